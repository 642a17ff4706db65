"""Run every benchmark, write benchmarks/results/all.json and the table in benchmarks/README.md.

    python benchmarks/run_all.py [--quick]

Comparisons are paired: the two commands compared run back to back, A B A B …, and each pair
gives one ratio; the table shows the median ratio with its interquartile range (IQR) and its
range over the pairs, so load that comes and goes cannot favour one side. The cold batch is
timed on stdout, with ``-o`` and as a first run without the catalog cache (see
``cold_batch.py``), in wall time and in CPU time (user + system, which does not count the
time spent waiting for a core on a loaded machine). The sweep counts only the configurations
it computed (see ``sweep.py``). ``goals.py`` adds the cold figures beyond the batch (a file
with unit strings, the HTML datasheet against matplotlib's import, numpy's BLAS threads);
``tui_latency.py`` the wizard's (a key at the first paint among them); and every
``family_*.py`` that defines ``run_all(quick) -> list[tuple[str, str, str]]`` (measurement,
case, figure) the family studies' rows.
"""

import argparse
import importlib
import json
import os
import platform
import shutil
import statistics
import sys
import tempfile
import time
from pathlib import Path

import goals
import tui_latency
from _results import ROOT, examples, save
from cold_batch import advisor_cmd, cold, spread, timed

BEGIN, END = "<!-- results:begin -->", "<!-- results:end -->"


def warm(n: int) -> dict:
    """In-process read + advise + TOML per example, imports and catalogs already loaded."""
    from advisor.core.engine import advise
    from advisor.core.reading import read_requirements
    from advisor.core.report import to_toml

    out = {}
    for ex in examples():
        to_toml(advise(read_requirements(ex)))
        ts, cpu = [], []
        for _ in range(n):
            t0, c0 = time.perf_counter(), time.process_time()
            to_toml(advise(read_requirements(ex)))
            ts.append(1e3 * (time.perf_counter() - t0))
            cpu.append(1e3 * (time.process_time() - c0))
        out[ex.name] = {**spread(ts), "cpu": spread(cpu)}
    return out


def sweep(n: int) -> dict:
    """The design-space sweep, counted honestly: only combinations within the stage-ratio
    limits are built, and both the configurations computed and the feasible ones (every
    stage within the common diameter) are reported, with the optimum against a fine brute
    force (tests/brute_reducer.py)."""
    sys.path.insert(0, str(ROOT / "tests"))
    from brute_reducer import lightest

    from advisor.calc import reducer

    p = reducer.ReducerParams(1620.0, 1.0, 0.9, 7800.0, 0.75)
    out = {}
    for q in (100.0, 1000.0, 2000.0, 10000.0):
        reducer.sweep(q, p)
        ts = []
        for _ in range(n):
            t0 = time.perf_counter()
            r = reducer.sweep(q, p)
            ts.append(time.perf_counter() - t0)
        med = statistics.median(ts)
        out[f"q={q:g}"] = {
            "configurations": r.evaluated,
            "feasible": r.feasible,
            "median_ms": 1e3 * med,
            "configs_per_s": r.evaluated / med,
            "feasible_per_s": r.feasible / med,
            "mass_ratio_vs_fine_grid": float(r.mass_kg[reducer.best(r, "mass")] / lightest(q, p)),
        }
    return out


def many(pairs: int, files: int) -> dict:
    """``-j 1`` and ``-j 2`` on the same ``files`` requirement files (the examples in turn),
    paired: the speed-up is ``-j 1`` time over ``-j 2`` time, pair by pair."""
    adv = advisor_cmd()
    j1, j2, j1_cpu, j2_cpu, speedup = [], [], [], [], []
    with tempfile.TemporaryDirectory() as tmp:
        src = Path(tmp) / "reqs"
        src.mkdir()
        exs = examples()
        for i in range(files):
            shutil.copy(exs[i % len(exs)], src / f"req{i:03d}.toml")

        def run(jobs: int, k: int) -> tuple[float, float]:
            dest = Path(tmp) / f"out{jobs}-{k}"
            return timed([*adv, "--batch", str(src), "--out-dir", str(dest), "-j", str(jobs)])

        run(1, -1)
        for k in range(pairs):
            if k % 2 == 0:
                a, b = run(1, k), run(2, k)
            else:
                b, a = run(2, k), run(1, k)
            j1.append(a[0])
            j2.append(b[0])
            j1_cpu.append(a[1])
            j2_cpu.append(b[1])
            speedup.append(a[0] / b[0])
    return {
        "files": files,
        "pairs": pairs,
        "j1_s": spread(j1),
        "j2_s": spread(j2),
        "j1_cpu_s": spread(j1_cpu),
        "j2_cpu_s": spread(j2_cpu),
        "speedup": spread(speedup),
    }


def _iqr(s: dict, fmt: str = ".2f") -> str:
    return f"IQR {s['q1']:{fmt}}–{s['q3']:{fmt}}, range {s['min']:{fmt}}–{s['max']:{fmt}}"


def table(res: dict) -> str:
    rows = [
        "| measurement | case | median (spread over the pairs or runs) |",
        "| --- | --- | --- |",
    ]
    for name, per_path in res["cold_batch"].items():
        for path, r in per_path.items():
            w, c = r["ratio"], r["cpu_ratio"]
            rows.append(
                f"| cold `advisor --batch` ({path}) / import floor | {name} | "
                f"**{w['median']:.2f} ×** wall ({_iqr(w)}); **{c['median']:.2f} ×** CPU "
                f"({_iqr(c)}); {r['batch_ms']['median']:.0f} ms vs "
                f"{r['floor_ms']['median']:.0f} ms wall |"
            )
            pw, pc = r["pydantic_floor_ratio"], r["pydantic_floor_cpu_ratio"]
            rows.append(
                f"| cold `advisor --batch` ({path}) / pydantic floor | {name} | "
                f"**{pw['median']:.2f} ×** wall ({_iqr(pw)}); **{pc['median']:.2f} ×** CPU "
                f"({_iqr(pc)}) |"
            )
    for name, r in res["warm_advice"].items():
        rows.append(
            f"| warm advice (read + advise + TOML) | {name} | {r['median']:.2f} ms wall "
            f"({_iqr(r)} ms); {r['cpu']['median']:.2f} ms CPU ({_iqr(r['cpu'])} ms) |"
        )
    for name, r in res["sweep"].items():
        rows.append(
            f"| design-space sweep | {name}: {r['configurations']:,} computed, "
            f"{r['feasible']:,} feasible | {r['median_ms']:.2f} ms, "
            f"{r['configs_per_s'] / 1e6:.2f} M computed/s, "
            f"{r['feasible_per_s'] / 1e6:.2f} M feasible/s; optimum mass / "
            f"fine brute force = {r['mass_ratio_vs_fine_grid']:.4f} |"
        )
    m = res["many"]
    rows.append(
        f"| many files, `-j 1` / `-j 2` | {m['files']} files, {m['pairs']} pairs | "
        f"**{m['speedup']['median']:.2f} ×** faster with `-j 2` ({_iqr(m['speedup'])}); "
        f"{m['j1_s']['median']:.2f} s vs {m['j2_s']['median']:.2f} s wall, "
        f"{m['j1_cpu_s']['median']:.2f} s vs {m['j2_cpu_s']['median']:.2f} s CPU |"
    )
    rows += goal_rows(res)
    for name, r in res["tui_latency"].items():
        rows.append(
            f"| wizard in a pty: start → first screen painted | {name} | "
            f"{r['first_screen_ms']:.0f} ms (a textual app painting one Static, run just "
            f"before: {r['floor_first_screen_ms']:.0f} ms) |"
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


def _ratio(r: dict, what: str) -> str:
    w, c = r["ratio"], r["cpu_ratio"]
    return (
        f"**{c['median']:.2f} ×** CPU ({_iqr(c)}); {w['median']:.2f} × wall ({_iqr(w)}); "
        f"{r['b_cpu_ms']['median']:.0f} ms vs {r['a_cpu_ms']['median']:.0f} ms CPU {what}"
    )


def goal_rows(res: dict) -> list[str]:
    """The rows of ``goals.py``, the wizard's first key and the family studies."""
    rows = []
    for name, r in res["unit_strings"].items():
        rows.append(
            f"| cold batch of a file with unit strings / import floor | {name} (two keys as "
            f"unit strings) | {_ratio(r['vs_floor'], '(file vs floor)')} |"
        )
        rows.append(
            f"| the same / the file in plain numbers | {name} | "
            f"{_ratio(r['vs_plain'], '(unit strings vs numbers)')} |"
        )
    for name, r in res["html"].items():
        rows.append(
            f"| HTML datasheet (`--format html -o`) / matplotlib's import | {name} | "
            f"{_ratio(r, '(datasheet vs import)')} |"
        )
    rows.append(
        "| numpy's BLAS threads: the CLI's one thread / a pool of every core "
        f"(`OPENBLAS_NUM_THREADS` set) | rudder_actuator.toml | "
        f"{_ratio(res['blas_threads'], '(one thread vs pool)')} |"
    )
    for name, r in res.get("first_key", {}).items():
        t = r["this"]
        lo, hi = t["at_paint_range_ms"]
        rows.append(
            f"| wizard in a pty: a key (F1) at the first paint → answered | {name} | "
            f"{t['at_paint_median_ms']:.0f} ms median (range {lo:.0f}–{hi:.0f}); the screen "
            f"settled: {t['settled_median_ms']:.0f} ms |"
        )
    for name, family_rows in res.get("family", {}).items():
        rows += [f"| {m} | {case} ({name}) | {fig} |" for m, case, fig in family_rows]
    return rows


def family(quick: bool) -> dict:
    """The rows of every ``family_*.py`` that defines ``run_all(quick)``."""
    out = {}
    for path in sorted((ROOT / "benchmarks").glob("family_*.py")):
        module = importlib.import_module(path.stem)
        if hasattr(module, "run_all"):
            out[path.stem] = module.run_all(quick)
    return out


def first_key(runs: int) -> dict:
    """A key at the wizard's first paint (when ``tui_latency.py`` measures it)."""
    if not hasattr(tui_latency, "first_keys"):
        return {}
    chosen = ("rudder_actuator.toml", "linear_screw_actuator.toml")
    return {ex.name: tui_latency.first_keys(ex, runs) for ex in examples() if ex.name in chosen}


def commit() -> str:
    """The commit measured (``+`` when the work tree has changes)."""
    import subprocess

    def git(*args: str) -> str:
        r = subprocess.run(["git", *args], cwd=ROOT, capture_output=True, text=True)
        return r.stdout.strip()

    head = git("rev-parse", "--short", "HEAD") or "unknown"
    return head + ("+" if git("status", "--porcelain", "--untracked-files=no") else "")


def machine() -> str:
    load = ", ".join(f"{x:.1f}" for x in os.getloadavg())
    return (
        f"{platform.machine()}, {os.cpu_count()} CPUs, {platform.system()} "
        f"{platform.release()}, Python {platform.python_version()}; load average {load}"
    )


def main() -> None:
    from advisor.cli import one_blas_thread

    one_blas_thread()  # as the command does, before numpy: an idle BLAS pool counts in CPU
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true", help="fewer repeats")
    quick = ap.parse_args().quick
    res = {"machine_before": machine(), "commit": commit()}
    res["cold_batch"] = cold(7 if quick else 21)
    res["warm_advice"] = warm(20 if quick else 100)
    res["sweep"] = sweep(5 if quick else 20)
    res["many"] = many(1 if quick else 3, 400)
    res["unit_strings"] = goals.unit_strings(7 if quick else 21)
    res["html"] = goals.html(5 if quick else 15)
    res["blas_threads"] = goals.blas_threads(7 if quick else 21)
    res["tui_latency"] = tui_latency.tui_latency(5 if quick else 15)
    res["first_key"] = first_key(5 if quick else 15)
    res["family"] = family(quick)
    res["machine_after"] = machine()
    res["date"] = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    save("all", res)
    text = table(res)
    print(text)
    readme = ROOT / "benchmarks" / "README.md"
    body = readme.read_text(encoding="utf-8")
    if BEGIN in body and END in body:
        head, rest = body.split(BEGIN, 1)
        tail = rest.split(END, 1)[1]
        stamp = (
            f"\n_{res['date']}, commit {res['commit']}, "
            f"`python benchmarks/run_all.py{' --quick' if quick else ''}`; "
            f"machine: {res['machine_before']} (before) / "
            f"{res['machine_after'].rsplit('; ', 1)[1]} (after)_\n\n"
        )
        readme.write_text(head + BEGIN + stamp + text + "\n" + END + tail, encoding="utf-8")
    print(json.dumps({k: res[k] for k in ("date", "machine_before", "machine_after")}))


if __name__ == "__main__":
    main()
