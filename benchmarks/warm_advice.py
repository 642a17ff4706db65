"""Warm in-process time of one advice per example (imports and catalogs already loaded).

python benchmarks/warm_advice.py [-n 200]
"""

import argparse
import statistics
import time

from _results import examples, save

from advisor.core.engine import advise
from advisor.core.reading import read_requirements
from advisor.core.report import to_toml


def main() -> None:
    from advisor.cli import one_blas_thread

    one_blas_thread()  # as the command does, before numpy: an idle BLAS pool counts in CPU
    ap = argparse.ArgumentParser()
    ap.add_argument("-n", type=int, default=200)
    n = ap.parse_args().n
    results = {}
    for example in examples():
        req = read_requirements(example)
        to_toml(advise(req))  # warm: imports, catalog cache, first-call costs
        times, parts = [], {"read": [], "advise": [], "toml": []}
        for _ in range(n):
            t0 = time.perf_counter()
            r = read_requirements(example)
            t1 = time.perf_counter()
            report = advise(r)
            t2 = time.perf_counter()
            to_toml(report)
            t3 = time.perf_counter()
            times.append(t3 - t0)
            for part, t in zip(parts, (t1 - t0, t2 - t1, t3 - t2), strict=True):
                parts[part].append(t)
        med = statistics.median(times)
        each = {part: statistics.median(ts) * 1e3 for part, ts in parts.items()}
        results[example.name] = {"median_ms": med * 1e3, "runs": n, "parts_median_ms": each}
        line = (
            f"{example.name:32s} warm advice (read + advise + TOML) {med * 1e3:6.2f} ms "
            f"(medians: read {each['read']:.2f}, advise {each['advise']:.2f}, "
            f"TOML {each['toml']:.2f})"
        )
        if req.application.kind == "rotary":  # the sweep, counted honestly (issue 16)
            sweep = advise(req).design.gearbox.sweep
            results[example.name]["sweep_configurations"] = sweep.configurations
            results[example.name]["sweep_feasible"] = sweep.feasible
            line += f" (sweep: {sweep.configurations:,} computed, {sweep.feasible:,} feasible)"
        print(line)
    save("warm_advice", results)


if __name__ == "__main__":
    main()
