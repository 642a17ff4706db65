"""Run every benchmark, write benchmarks/results/all.json and the table in benchmarks/README.md.

    python benchmarks/run_all.py [--quick]

Medians over repeated runs; ratios are measured within the same run (the machine is noisy).
"""

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from _results import ROOT, examples, save
from tui_latency import tui_latency

FLOOR = [sys.executable, "-c", "import numpy, scipy, pydantic, tomli_w"]
ADVISOR = (
    [shutil.which("advisor")] if shutil.which("advisor") else [sys.executable, "-m", "advisor"]
)
BEGIN, END = "<!-- results:begin -->", "<!-- results:end -->"


def wall(cmd: list[str]) -> float:
    t0 = time.perf_counter()
    subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    return time.perf_counter() - t0


def cold(n: int) -> dict:
    out = {}
    for ex in examples():
        batch = [*ADVISOR, "--batch", str(ex)]
        wall(batch), wall(FLOOR)
        f, b = [], []
        for _ in range(n):
            f.append(wall(FLOOR))
            b.append(wall(batch))
        out[ex.name] = {
            "floor_ms": 1e3 * statistics.median(f),
            "batch_ms": 1e3 * statistics.median(b),
        }
        out[ex.name]["ratio"] = out[ex.name]["batch_ms"] / out[ex.name]["floor_ms"]
    return out


def warm(n: int) -> dict:
    from advisor.core.engine import advise
    from advisor.core.report import to_toml
    from advisor.core.requirements import read_requirements

    out = {}
    for ex in examples():
        to_toml(advise(read_requirements(ex)))
        ts = []
        for _ in range(n):
            t0 = time.perf_counter()
            to_toml(advise(read_requirements(ex)))
            ts.append(time.perf_counter() - t0)
        out[ex.name] = {"median_ms": 1e3 * statistics.median(ts)}
    return out


def sweep(n: int) -> dict:
    """The design-space sweep, counted honestly: only combinations within the stage-ratio
    limits are built, and both the configurations computed and the feasible ones (every
    stage within the common diameter) are reported, with the optimum against a fine brute
    force (tests/brute_reducer.py)."""
    sys.path.insert(0, str(ROOT / "tests"))
    from brute_reducer import lightest

    from advisor.calc import reducer as rd

    p = rd.ReducerParams(1620.0, 1.0, 0.9, 7800.0, 0.75)
    out = {}
    for q in (100.0, 1000.0, 2000.0, 10000.0):
        rd.sweep(q, p)
        ts = []
        for _ in range(n):
            t0 = time.perf_counter()
            r = rd.sweep(q, p)
            ts.append(time.perf_counter() - t0)
        med = statistics.median(ts)
        out[f"q={q:g}"] = {
            "configurations": r.evaluated,
            "feasible": r.feasible,
            "median_ms": 1e3 * med,
            "configs_per_s": r.evaluated / med,
            "feasible_per_s": r.feasible / med,
            "mass_ratio_vs_fine_grid": float(r.mass_kg[rd.best(r, "mass")] / lightest(q, p)),
        }
    return out


def many(repeats: int, files: int) -> dict:
    out = {}
    with tempfile.TemporaryDirectory() as tmp:
        src = Path(tmp) / "reqs"
        src.mkdir()
        exs = examples()
        for i in range(files):
            shutil.copy(exs[i % len(exs)], src / f"req{i:03d}.toml")
        for jobs in (1, 2):
            ts = []
            for r in range(repeats):
                dest = Path(tmp) / f"out{jobs}-{r}"
                ts.append(
                    wall([*ADVISOR, "--batch", str(src), "--out-dir", str(dest), "-j", str(jobs)])
                )
            med = statistics.median(ts)
            out[f"-j {jobs}"] = {"files": files, "median_s": med, "requirements_per_s": files / med}
    return out


def table(res: dict) -> str:
    rows = ["| measurement | case | median |", "| --- | --- | --- |"]
    for name, r in res["cold_batch"].items():
        rows.append(
            f"| cold `advisor --batch` vs import floor | {name} | {r['batch_ms']:.0f} ms vs "
            f"{r['floor_ms']:.0f} ms = **{r['ratio']:.2f} ×** |"
        )
    for name, r in res["warm_advice"].items():
        rows.append(f"| warm advice (read + advise + TOML) | {name} | {r['median_ms']:.2f} ms |")
    for name, r in res["sweep"].items():
        rows.append(
            f"| design-space sweep | {name}: {r['configurations']:,} computed, "
            f"{r['feasible']:,} feasible | {r['median_ms']:.2f} ms, "
            f"{r['feasible_per_s'] / 1e6:.2f} M feasible/s; optimum mass / "
            f"fine brute force = {r['mass_ratio_vs_fine_grid']:.4f} |"
        )
    for name, r in res["many"].items():
        rows.append(
            f"| many files, `{name}` | {r['files']} files | {r['median_s']:.2f} s, "
            f"{r['requirements_per_s']:.1f} requirements/s |"
        )
    for name, r in res["tui_latency"].items():
        rows.append(
            f"| wizard in a pty: start → first screen painted | {name} | "
            f"{r['first_screen_ms']:.0f} ms |"
        )
        rows.append(
            f"| wizard in a pty: first ctrl+r → results painted | {name} | "
            f"{r['first_compute_ms']:.0f} ms |"
        )
        rows.append(
            f"| wizard in a pty: edit, ctrl+r → results painted | {name} | "
            f"{r['median_ms']:.0f} ms (max {r['max_ms']:.0f} ms) |"
        )
    return "\n".join(rows)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true", help="fewer repeats")
    quick = ap.parse_args().quick
    res = {
        "cold_batch": cold(7 if quick else 21),
        "warm_advice": warm(20 if quick else 100),
        "sweep": sweep(5 if quick else 20),
        "many": many(1 if quick else 3, 20 if quick else 60),
        "tui_latency": tui_latency(5 if quick else 15),
        "load_average": os.getloadavg()[0],
        "python": sys.version.split()[0],
        "date": time.strftime("%Y-%m-%d"),
    }
    save("all", res)
    text = table(res)
    print(text)
    readme = ROOT / "benchmarks" / "README.md"
    body = readme.read_text(encoding="utf-8")
    if BEGIN in body and END in body:
        head, rest = body.split(BEGIN, 1)
        tail = rest.split(END, 1)[1]
        stamp = (
            f"\n_{res['date']}, Python {res['python']}, `python benchmarks/run_all.py`, load "
            f"average {res['load_average']:.1f} on {os.cpu_count()} CPUs at the end_\n\n"
        )
        readme.write_text(head + BEGIN + stamp + text + "\n" + END + tail, encoding="utf-8")
    print(json.dumps({k: v for k, v in res.items() if k in ("python", "date")}))


if __name__ == "__main__":
    main()
