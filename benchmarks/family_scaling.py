"""Family studies on Dask: variants per second at 1, 2, … workers, and the cost model.

    python benchmarks/family_scaling.py [--quick]

Measures, on this machine:
- t_v, the advice of one variant in a worker (run_chunk in-process, no Dask), for the rotary
  valve family of examples/family_valve_actuators.toml (finer torque steps) and a cheap
  positioning family;
- t_task, the scheduler's round trip for one task (empty tasks on one worker);
- t_chunk, the client's serial work per chunk (receive, write the chunk's CSV with fsync);
- t_join, the client's serial work per variant at the end (designs.csv, summary);
- the wall time of real studies on a LocalCluster of 1, 2, … worker processes;
and prints the cost model's prediction for 10⁶ variants on 64 workers. Writes
benchmarks/results/family.json.
"""

import argparse
import os
import statistics
import tempfile
import time
import tomllib
from pathlib import Path

from _results import ROOT, save

from advisor.family.chunks import run_chunk
from advisor.family.spec import parse_family
from advisor.family.study import join_chunks, run_study
from advisor.family.summary import read_rows, summarize


def valve_family(steps: int):
    path = ROOT / "examples" / "family_valve_actuators.toml"
    doc = tomllib.loads(path.read_text())
    doc["family"]["axes"]["rotary.torque_Nm"]["steps"] = steps
    return parse_family(doc, path)


def positioning_family(steps: int):
    path = ROOT / "examples" / "positioning_drive.toml"
    doc = tomllib.loads(path.read_text())
    doc["family"] = {
        "name": "positioning",
        "axes": {
            "positioning.travel_rad": {"from": 1, "to": 100, "steps": steps, "scale": "log"},
            "positioning.load_inertia_kgm2": [0.5, 1, 2, 5, 10],
        },
    }
    return parse_family(doc, path)


def per_variant_s(family, n: int) -> float:
    run_chunk(family, 0, 0, min(5, family.size), None, False)  # warm imports and caches
    r = run_chunk(family, 0, 0, min(n, family.size), None, False)
    return r.seconds / len(r.rows)


def noop() -> None:
    return None


def task_round_trip_s(client, n: int) -> float:
    client.gather(client.map(noop, range(20), pure=False))
    t0 = time.perf_counter()
    client.gather(client.map(noop, range(n), pure=False))
    return (time.perf_counter() - t0) / n


def study_wall_s(family, client, chunk: int) -> tuple[float, float]:
    with tempfile.TemporaryDirectory() as d:
        t0 = time.perf_counter()
        res = run_study(family, Path(d), client, chunk)
        t1 = time.perf_counter()
        join_chunks(family, Path(d), chunk)
        summarize(family, read_rows(Path(d) / "designs.csv"), {})
        t2 = time.perf_counter()
    assert res.computed == res.chunks
    return t1 - t0, t2 - t1


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    import logging

    from dask.distributed import Client, LocalCluster

    steps = 20 if args.quick else 60
    valve = valve_family(steps)
    pos = positioning_family(200 if args.quick else 800)
    out: dict = {"cores": os.cpu_count()}
    out["t_v_rotary_ms"] = 1e3 * per_variant_s(valve, 60)
    out["t_v_positioning_ms"] = 1e3 * per_variant_s(pos, 400)
    scaling = {}
    for workers in sorted({1, 2, os.cpu_count() or 1}):
        t0 = time.perf_counter()
        cluster = LocalCluster(
            n_workers=workers,
            threads_per_worker=1,
            processes=True,
            dashboard_address=None,
            silence_logs=logging.ERROR,
        )
        client = Client(cluster)
        start_s = time.perf_counter() - t0
        if workers == 1:
            out["t_task_ms"] = 1e3 * statistics.median(
                task_round_trip_s(client, 200) for _ in range(3)
            )
            # cheap variants in chunks of 1: the per-chunk cost dominates
            wall1, _ = study_wall_s(pos, client, 1) if args.quick else study_wall_s(pos, client, 2)
            chunks = pos.size // (1 if args.quick else 2)
            out["t_chunk_ms"] = 1e3 * (wall1 - pos.size * out["t_v_positioning_ms"] / 1e3) / chunks
        chunk = max(1, valve.size // (4 * workers))
        study_wall_s(valve, client, chunk)  # warm the workers' imports
        wall, join = study_wall_s(valve, client, chunk)
        scaling[workers] = {
            "cluster_start_s": start_s,
            "variants": valve.size,
            "chunk_size": chunk,
            "wall_s": wall,
            "variants_per_s": valve.size / wall,
            "join_and_summary_s": join,
        }
        client.close()
        cluster.close()
    out["scaling"] = scaling
    out["t_join_us"] = 1e6 * scaling[1]["join_and_summary_s"] / valve.size
    out["prediction"] = predict(out)
    save("family", out)
    print_table(out)


def predict(m: dict, n: float = 1e6, workers: int = 64) -> dict:
    """T(c) = n·t_v/W + (n/c)·t_c/W (parallel) or (n/c)·(t_task + t_chunk) (serial at the
    scheduler and client), whichever is larger, + c·t_v (the last chunk's tail) + n·t_join."""
    t_v = m["t_v_rotary_ms"] / 1e3
    t_serial = (m["t_task_ms"] + m["t_chunk_ms"]) / 1e3
    best = None
    table = {}
    for c in (10, 20, 50, 100, 200, 500, 1000, 2000, 5000):
        chunks = n / c
        compute = n * t_v / workers
        serial = chunks * t_serial
        tail = c * t_v
        total = max(compute, serial) + tail + n * m["t_join_us"] / 1e6
        table[c] = total
        if chunks >= 8 * workers and (best is None or total < table[best]):
            best = c
    return {"variants": n, "workers": workers, "total_s_by_chunk": table, "recommended": best}


def print_table(m: dict) -> None:
    print(f"t_v rotary {m['t_v_rotary_ms']:.1f} ms, positioning {m['t_v_positioning_ms']:.2f} ms")
    print(f"t_task {m['t_task_ms']:.2f} ms, t_chunk {m['t_chunk_ms']:.2f} ms, t_join {m['t_join_us']:.0f} µs")
    for w, s in m["scaling"].items():
        print(
            f"{w} workers: {s['variants']} variants in {s['wall_s']:.1f} s = "
            f"{s['variants_per_s']:.1f} variants/s (chunks of {s['chunk_size']}; cluster start "
            f"{s['cluster_start_s']:.1f} s; join + summary {s['join_and_summary_s']:.2f} s)"
        )
    p = m["prediction"]
    for c, t in p["total_s_by_chunk"].items():
        print(f"  1e6 variants on 64 workers, chunks of {c}: {t:.0f} s")
    print(f"  recommended chunk size: {p['recommended']}")


if __name__ == "__main__":
    main()
