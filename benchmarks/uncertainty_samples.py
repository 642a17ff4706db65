"""Warm time of the probability of passing (issue 30): 10⁴ Latin hypercube samples of the
linear example's inputs, every check evaluated over them with numpy, the design held fixed.
The requirement is examples/uncertainty/linear_screw_robust.toml without its target (the
robust choice runs the rules once per candidate and is timed apart).

Method: the nominal advice and a first evaluation warm the imports (scipy.stats.qmc costs
about 0.6 s cold) and the caches; then the median of -n evaluations.

python benchmarks/uncertainty_samples.py [-n 20]
"""

import argparse
import statistics
import time

from _results import ROOT, save

from advisor.core.engine import advise, advise_with
from advisor.core.reading import read_requirements
from advisor.uncertainty import evaluate, replaced
from catalogs import load_catalogs

EXAMPLE = ROOT / "examples" / "uncertainty" / "linear_screw_robust.toml"


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("-n", type=int, default=20)
    n = ap.parse_args().n
    req = read_requirements(EXAMPLE)
    fixed = replaced(req, uncertainty=replaced(req.uncertainty, target=None))
    cat = load_catalogs()
    nominal = advise_with(replaced(req, uncertainty=None), cat)
    evaluate(fixed, nominal, cat)  # warm
    times = []
    for _ in range(n):
        t0 = time.perf_counter()
        evaluate(fixed, nominal, cat)
        times.append(time.perf_counter() - t0)
    t0 = time.perf_counter()
    advise(req)  # the robust choice, warm
    robust = time.perf_counter() - t0
    results = {
        "samples": req.uncertainty.samples,
        "evaluate_median_ms": statistics.median(times) * 1e3,
        "evaluate_max_ms": max(times) * 1e3,
        "robust_choice_ms": robust * 1e3,
        "runs": n,
    }
    print(
        f"{results['samples']} samples: {results['evaluate_median_ms']:.1f} ms median "
        f"(max {results['evaluate_max_ms']:.1f} ms); robust choice {robust * 1e3:.0f} ms"
    )
    save("uncertainty_samples", results)


if __name__ == "__main__":
    main()
