"""The rotary design-space sweep alone, counted honestly (issue 16): configurations
computed (every one within the stage-ratio limits) and feasible, per second.

python benchmarks/sweep.py [-n 50]
"""

import argparse

from _results import save
from run_all import sweep


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("-n", type=int, default=50)
    res = sweep(ap.parse_args().n)
    for name, r in res.items():
        print(
            f"{name:10s} {r['configurations']:7,} computed {r['feasible']:7,} feasible "
            f"{r['median_ms']:7.2f} ms {r['feasible_per_s'] / 1e6:6.2f} M feasible/s "
            f"optimum/brute force {r['mass_ratio_vs_fine_grid']:.4f}"
        )
    save("sweep", res)


if __name__ == "__main__":
    main()
