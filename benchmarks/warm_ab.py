"""Paired warm A/B: the warm advice of one example with this checkout's code against another
checkout's (a reference worktree of main), in two live processes that run batches in turn.

    git worktree add /tmp/ref main
    python benchmarks/warm_ab.py /tmp/ref [-e examples/linear_screw_actuator.toml] [-p 40] [-b 5]

Each pair is one batch of each side, back to back (A B, then B A, …); the ratio new/ref is
taken pair by pair, for read, advise, TOML and the whole, so that the machine's drifting
speed (up to 2× minute to minute here) and load that comes and goes touch both sides alike.
The medians of the two sides are shown beside the ratios, for scale only.
"""

import argparse
import os
import statistics
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PARTS = ("read", "advise", "toml", "whole")

CHILD = r"""
import statistics, sys, time
from pathlib import Path
from advisor.core.engine import advise
from advisor.core.report import to_toml
from advisor.core.reading import read_requirements
ex = Path(sys.argv[1])
for _ in range(3):
    to_toml(advise(read_requirements(ex)))
print("ready", flush=True)
for line in sys.stdin:
    times = [[], [], [], []]
    for _ in range(int(line)):
        t0 = time.perf_counter(); req = read_requirements(ex)
        t1 = time.perf_counter(); rep = advise(req)
        t2 = time.perf_counter(); to_toml(rep)
        t3 = time.perf_counter()
        for i, t in enumerate((t1 - t0, t2 - t1, t3 - t2, t3 - t0)):
            times[i].append(t * 1e3)
    print(*(statistics.median(t) for t in times), flush=True)
"""


def _child(root: Path, example: Path) -> subprocess.Popen:
    env = {**os.environ, "PYTHONPATH": str(root)}
    p = subprocess.Popen(
        [sys.executable, "-c", CHILD, str(example)],
        cwd=root,
        env=env,
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        text=True,
    )
    assert p.stdin is not None and p.stdout is not None
    if p.stdout.readline().strip() != "ready":
        raise SystemExit(f"the child in {root} did not start")
    return p


def _batch(p: subprocess.Popen, n: int) -> list[float]:
    assert p.stdin is not None and p.stdout is not None
    p.stdin.write(f"{n}\n")
    p.stdin.flush()
    return [float(x) for x in p.stdout.readline().split()]


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("ref", type=Path, help="the reference checkout (e.g. a worktree of main)")
    ap.add_argument(
        "-e", "--example", type=Path, default=Path("examples/linear_screw_actuator.toml")
    )
    ap.add_argument("-p", "--pairs", type=int, default=40)
    ap.add_argument("-b", "--batch", type=int, default=5, help="advices per side per pair")
    args = ap.parse_args()
    example = (ROOT / args.example).resolve()
    ref, new = _child(args.ref.resolve(), example), _child(ROOT, example)
    a_runs, b_runs, ratios = [], [], []
    for i in range(args.pairs):
        if i % 2:
            b = _batch(new, args.batch)
            a = _batch(ref, args.batch)
        else:
            a = _batch(ref, args.batch)
            b = _batch(new, args.batch)
        a_runs.append(a)
        b_runs.append(b)
        ratios.append([y / x for x, y in zip(a, b, strict=True)])
    for p in (ref, new):
        assert p.stdin is not None
        p.stdin.close()
        p.wait()
    print(f"{example.name}: {args.pairs} pairs of {args.batch} warm advices per side")
    for j, part in enumerate(PARTS):
        r = [x[j] for x in ratios]
        q1, _, q3 = statistics.quantiles(r, n=4)
        print(
            f"{part:7s} ref {statistics.median(x[j] for x in a_runs):6.3f} ms   "
            f"new {statistics.median(x[j] for x in b_runs):6.3f} ms   "
            f"new/ref {statistics.median(r):.3f} (IQR {q1:.3f}–{q3:.3f}, "
            f"range {min(r):.3f}–{max(r):.3f})"
        )


if __name__ == "__main__":
    main()
