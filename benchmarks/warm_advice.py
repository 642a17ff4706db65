"""Warm in-process time of one advice per example (imports and catalogs already loaded).

python benchmarks/warm_advice.py [-n 200]
"""

import argparse
import statistics
import time

from _results import examples, save

from advisor.core.engine import advise
from advisor.core.report import to_toml
from advisor.core.requirements import read_requirements


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("-n", type=int, default=200)
    n = ap.parse_args().n
    results = {}
    for example in examples():
        req = read_requirements(example)
        to_toml(advise(req))  # warm: imports, catalog cache, first-call costs
        times = []
        for _ in range(n):
            t0 = time.perf_counter()
            to_toml(advise(read_requirements(example)))
            times.append(time.perf_counter() - t0)
        med = statistics.median(times)
        results[example.name] = {"median_ms": med * 1e3, "runs": n}
        line = f"{example.name:32s} warm advice (read + advise + TOML) {med * 1e3:6.2f} ms"
        if req.application.kind == "rotary":  # the sweep, counted honestly (issue 16)
            sweep = advise(req).design.gearbox.sweep
            results[example.name]["sweep_configurations"] = sweep.configurations
            results[example.name]["sweep_feasible"] = sweep.feasible
            line += f" (sweep: {sweep.configurations:,} computed, {sweep.feasible:,} feasible)"
        print(line)
    save("warm_advice", results)


if __name__ == "__main__":
    main()
