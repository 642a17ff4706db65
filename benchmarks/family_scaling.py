"""Family studies on Dask: variants per second at 1, 2, … workers, and the cost model.

    python benchmarks/family_scaling.py [--quick] [--model-only]

Measures, on this machine:
- t_v, the advice of one variant in a worker (run_chunk in-process, no Dask), for the rotary
  valve family of examples/families/valve_actuators.toml (finer torque steps) and a cheap
  positioning family;
- t_task, the scheduler's round trip for one task (empty tasks on one worker);
- t_chunk, the client's serial work per chunk (receive, write the chunk's CSV with fsync);
- t_join, the client's serial work per variant at the end (designs.csv, summary);
- the wall time of real studies on a LocalCluster of 1, 2, … worker processes;
and prints the cost model's prediction for 10⁷ variants on 64 workers, after checking the
model against the studies it ran (the same formula, the measured t_v, t_chunk and t_join,
against each study's measured wall time). Writes benchmarks/results/family.json.
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
from advisor.family.summary import build_summary, iter_rows


def valve_family(steps: int):
    path = ROOT / "examples" / "families" / "valve_actuators.toml"
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


def per_variant_s(family, n: int) -> tuple[float, float]:
    """(wall, CPU) seconds per variant; on a shared machine the CPU time is what a core of
    its own would take."""
    run_chunk(family, 0, 0, min(5, family.size), None, False)  # warm imports and caches
    c0 = time.process_time()
    r = run_chunk(family, 0, 0, min(n, family.size), None, False)
    return r.seconds / len(r.rows), (time.process_time() - c0) / len(r.rows)


def noop(_: int) -> None:
    return None


def task_round_trip_s(client, n: int) -> tuple[float, float]:
    """(wall, CPU of this process) per empty task: the local scheduler runs in this process,
    so its CPU time is the scheduler's and the client's serial work."""
    client.gather(client.map(noop, range(20), pure=False))
    t0, c0 = time.perf_counter(), time.process_time()
    client.gather(client.map(noop, range(n), pure=False))
    return (time.perf_counter() - t0) / n, (time.process_time() - c0) / n


def study_wall_s(family, client, chunk: int) -> tuple[float, float, float, float]:
    """(wall of the study, CPU of this process during it, wall of join + summary, the
    workers' time advising, summed over the chunks)."""
    with tempfile.TemporaryDirectory() as d:
        t0, c0 = time.perf_counter(), time.process_time()
        res = run_study(family, Path(d), client, chunk)
        t1, c1 = time.perf_counter(), time.process_time()
        join_chunks(family, Path(d), chunk)
        build_summary(family, iter_rows(Path(d) / "designs.csv"), {})
        t2 = time.perf_counter()
    assert res.computed == res.chunks
    return t1 - t0, c1 - c0, t2 - t1, res.advise_seconds


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--model-only", action="store_true", help="recompute from results/family.json")
    args = ap.parse_args()
    if args.model_only:
        import json

        m = json.loads((ROOT / "benchmarks" / "results" / "family.json").read_text())
        m["scaling"] = {int(k): v for k, v in m["scaling"].items()}
        m["check"] = check_model(m)
        m["prediction"] = predict(m)
    else:
        m = measure(args.quick)
    save("family", m)
    print_table(m)


def run_all(quick: bool) -> list[tuple[str, str, str]]:
    """The rows of ``run_all.py``'s table: the model's terms, its check, its prediction."""
    m = measure(quick)
    save("family", m)
    p = m["prediction"]
    rows = [
        (
            "family cost model: terms (Dask)",
            "valve family, rotary",
            f"t_v {m['t_v_rotary_ms']:.1f} ms CPU a variant, t_chunk {m['t_chunk_ms']:.2f} ms "
            f"CPU a chunk (client + scheduler), t_join {m['t_join_us']:.0f} µs a variant",
        )
    ]
    for w, c in m["check"].items():
        rows.append(
            (
                "family cost model: measured / predicted wall",
                f"{w} Dask workers, {m['scaling'][w]['variants']} variants",
                f"**{c['measured_over_predicted']:.2f} ×** ({c['measured_s']:.1f} s vs "
                f"{c['predicted_s']:.1f} s; load {m['scaling'][w]['load_average']:.1f})",
            )
        )
    best = p["by_chunk_size"][p["recommended"]] if p["recommended"] else None
    rows.append(
        (
            "family cost model: 10⁷ variants on 64 workers",
            f"chunks of {p['recommended']}",
            f"{best['total_s'] / 60:.0f} min (advice {p['compute_s'] / 60:.0f} min, serial "
            f"{best['serial_s'] / 60:.1f} min, join + summary {p['join_s'] / 60:.1f} min)"
            if best
            else "no chunk size meets the rules",
        )
    )
    return rows


def measure(quick: bool) -> dict:
    """Every term of the model, the studies at 1, 2, … workers, the check and the prediction."""
    import logging

    from dask.distributed import Client, LocalCluster

    steps = 20 if quick else 60
    valve = valve_family(steps)
    pos = positioning_family(200 if quick else 800)
    out: dict = {"cores": os.cpu_count(), "load_average_before": os.getloadavg()[0]}
    wall_v, cpu_v = per_variant_s(valve, 60)
    out["t_v_rotary_wall_ms"], out["t_v_rotary_ms"] = 1e3 * wall_v, 1e3 * cpu_v
    wall_p, cpu_p = per_variant_s(pos, 400)
    out["t_v_positioning_wall_ms"], out["t_v_positioning_ms"] = 1e3 * wall_p, 1e3 * cpu_p
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
            trips = [task_round_trip_s(client, 200) for _ in range(3)]
            out["t_task_wall_ms"] = 1e3 * statistics.median(t[0] for t in trips)
            out["t_task_ms"] = 1e3 * statistics.median(t[1] for t in trips)
            # cheap variants in chunks of 1: the client's and scheduler's work per chunk
            # (receive, write the chunk with fsync, bookkeeping) is this process's CPU time
            small = positioning_family(100)
            _, cpu1, _, _ = study_wall_s(small, client, 1)
            out["t_chunk_ms"] = 1e3 * cpu1 / small.size
            # join + summary per variant, on enough variants that fixed costs do not count
            _, _, join, _ = study_wall_s(pos, client, 200)
            out["t_join_us"] = 1e6 * join / pos.size
            out["join_variants"] = pos.size
        chunk = max(1, valve.size // (4 * workers))
        study_wall_s(valve, client, chunk)  # warm the workers' imports
        wall, _, join, advise_s = study_wall_s(valve, client, chunk)
        scaling[workers] = {
            "load_average": os.getloadavg()[0],
            "cluster_start_s": start_s,
            "variants": valve.size,
            "chunk_size": chunk,
            "wall_s": wall,
            "variants_per_s": valve.size / wall,
            "join_and_summary_s": join,
            "t_v_in_workers_ms": 1e3 * advise_s / valve.size,
        }
        client.close()
        cluster.close()
    out["scaling"] = scaling
    out["check"] = check_model(out)
    out["prediction"] = predict(out)
    return out


def model_s(
    n: float, workers: int, chunk: float, t_v: float, t_chunk: float, t_join: float
) -> float:
    """T = max(n·t_v/W, (n/c)·t_chunk) + c·t_v + n·t_join: the workers' advice in parallel,
    unless the client and scheduler (serial, t_chunk per chunk, which includes the task's
    round trip) are the slower; then the last chunk's tail; then the client's join and
    summary (serial, per variant)."""
    return max(n * t_v / workers, (n / chunk) * t_chunk) + chunk * t_v + n * t_join


def check_model(m: dict) -> dict:
    """The model against each study run here: its wall time predicted from t_v (as the
    study's workers measured it, wall time per variant: on a shared machine a worker gets
    less than a core), t_chunk and the chunk size, over the measured wall time."""
    out = {}
    for w, s in m["scaling"].items():
        t_v = s.get("t_v_in_workers_ms", m["t_v_rotary_wall_ms"]) / 1e3
        # the study's wall time is measured before the join: t_join does not count here
        pred = model_s(s["variants"], w, s["chunk_size"], t_v, m["t_chunk_ms"] / 1e3, 0.0)
        out[w] = {
            "predicted_s": pred,
            "measured_s": s["wall_s"],
            "measured_over_predicted": s["wall_s"] / pred,
        }
    return out


def predict(m: dict, n: float = 1e7, workers: int = 64) -> dict:
    """The model (:func:`model_s`) for ``n`` variants on ``workers`` workers, by chunk size.

    The recommended chunk size is the fastest that leaves every worker at least 8 chunks
    (load balance, cheap retries) and keeps the serial work under a quarter of the parallel
    work (headroom: the scheduler must never become the bottleneck)."""
    t_v = m["t_v_rotary_ms"] / 1e3
    t_serial = m["t_chunk_ms"] / 1e3
    t_join = m["t_join_us"] / 1e6
    compute = n * t_v / workers
    best = None
    table = {}
    for c in (10, 20, 50, 100, 200, 500, 1000, 2000, 5000):
        chunks = n / c
        serial = chunks * t_serial
        total = model_s(n, workers, c, t_v, t_serial, t_join)
        table[c] = {"total_s": total, "serial_s": serial, "chunks_per_worker": chunks / workers}
        ok = chunks >= 8 * workers and serial <= 0.25 * compute
        if ok and (best is None or total < table[best]["total_s"]):
            best = c
    return {
        "variants": n,
        "workers": workers,
        "compute_s": compute,
        "join_s": n * t_join,
        "by_chunk_size": table,
        "recommended": best,
    }


def print_table(m: dict) -> None:
    print(
        f"load average {m['load_average_before']:.1f}; t_v rotary {m['t_v_rotary_ms']:.1f} ms CPU "
        f"({m['t_v_rotary_wall_ms']:.1f} wall), positioning {m['t_v_positioning_ms']:.2f} ms CPU "
        f"({m['t_v_positioning_wall_ms']:.2f} wall)"
    )
    print(
        f"t_task {m['t_task_ms']:.2f} ms CPU ({m['t_task_wall_ms']:.2f} wall), t_chunk "
        f"{m['t_chunk_ms']:.2f} ms CPU, t_join {m['t_join_us']:.0f} µs"
    )
    for w, s in m["scaling"].items():
        print(
            f"{w} workers: {s['variants']} variants in {s['wall_s']:.1f} s = "
            f"{s['variants_per_s']:.1f} variants/s (chunks of {s['chunk_size']}; cluster start "
            f"{s['cluster_start_s']:.1f} s; join + summary {s['join_and_summary_s']:.2f} s; "
            f"load {s['load_average']:.1f})"
        )
    for w, c in m.get("check", {}).items():
        print(
            f"model check, {w} workers: predicted {c['predicted_s']:.1f} s, measured "
            f"{c['measured_s']:.1f} s ({c['measured_over_predicted']:.2f}×)"
        )
    p = m["prediction"]
    print(
        f"  {p['variants']:.0e} variants on {p['workers']} workers: advice alone "
        f"{p['compute_s']:.0f} s, join + summary {p['join_s']:.0f} s"
    )
    for c, t in p["by_chunk_size"].items():
        print(
            f"  chunks of {c}: {t['total_s']:.0f} s (serial {t['serial_s']:.0f} s, "
            f"{t['chunks_per_worker']:.0f} chunks per worker)"
        )
    print(f"  recommended chunk size: {p['recommended']}")


if __name__ == "__main__":
    main()
