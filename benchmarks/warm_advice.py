"""Warm in-process time of one advice per example (imports and catalogs already loaded).

python benchmarks/warm_advice.py [-n 200]
"""

import argparse
import json
import statistics
import time
from pathlib import Path

from advisor.engine import advise
from advisor.models import read_requirements
from advisor.report import to_toml

ROOT = Path(__file__).resolve().parent.parent


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("-n", type=int, default=200)
    n = ap.parse_args().n
    results = {}
    for example in sorted((ROOT / "examples").glob("*.toml")):
        req = read_requirements(example)
        to_toml(advise(req))  # warm: imports, catalog cache, first-call costs
        times = []
        for _ in range(n):
            t0 = time.perf_counter()
            to_toml(advise(read_requirements(example)))
            times.append(time.perf_counter() - t0)
        med = statistics.median(times)
        results[example.name] = {"median_ms": med * 1e3, "runs": n}
        print(f"{example.name:32s} warm advice (read + advise + TOML) {med * 1e3:6.2f} ms")
    out = ROOT / "benchmarks" / "results"
    out.mkdir(exist_ok=True)
    (out / "warm_advice.json").write_text(json.dumps(results, indent=2) + "\n")


if __name__ == "__main__":
    main()
