"""Cold `advisor --batch` on each example against the bare import of its dependencies.

Runs the two commands interleaved (so background noise hits both alike), N times each, and
prints medians and their ratio; writes benchmarks/results/cold_batch.json.

    python benchmarks/cold_batch.py [-n 21]
"""

import argparse
import shutil
import statistics
import subprocess
import sys
import time

from _results import examples, save

FLOOR = [sys.executable, "-c", "import numpy, scipy, pydantic, tomli_w"]


def wall(cmd: list[str]) -> float:
    t0 = time.perf_counter()
    subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    return time.perf_counter() - t0


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("-n", type=int, default=21)
    n = ap.parse_args().n
    results = {}
    for example in examples():
        exe = shutil.which("advisor")
        cmd = [exe] if exe else [sys.executable, "-m", "advisor"]
        batch = [*cmd, "--batch", str(example)]
        wall(batch), wall(FLOOR)  # warm the OS file cache
        floor, run = [], []
        for _ in range(n):
            floor.append(wall(FLOOR))
            run.append(wall(batch))
        f, r = statistics.median(floor), statistics.median(run)
        results[example.name] = {"floor_s": f, "batch_s": r, "ratio": r / f, "runs": n}
        line = f"{example.name:32s} floor {f * 1e3:6.1f} ms  batch {r * 1e3:6.1f} ms"
        print(f"{line}  ratio {r / f:.2f}")
    save("cold_batch", results)


if __name__ == "__main__":
    main()
