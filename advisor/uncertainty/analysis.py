"""What the samples say: the probability that each check passes and that all pass together,
with a confidence interval, and which inputs drive each check's margin.

- P(pass) is the share of samples whose margin is at least 1; its interval is Wilson's score
  interval (Wilson 1927), which stays inside 0 … 1 and is honest near 0 and 1, where a design
  that passes almost always sits. Latin hypercube sampling is at least as precise as simple
  random sampling for these means (McKay et al. 1979), so the binomial interval is
  conservative.
- A driver is an input whose rank correlation (Spearman's ρ) with the check's margin is large:
  the sign says whether more of the input raises (+) or lowers (−) the margin. Rank
  correlation needs no linearity, only a monotone effect, which every modelled margin has.
"""

import math
from typing import NamedTuple

import numpy as np

#: Two-sided 95 % normal quantile.
Z95 = 1.959963984540054


class Interval(NamedTuple):
    p: float
    low: float
    high: float


def wilson(successes: int, n: int, z: float = Z95) -> Interval:
    """Wilson's score interval of a binomial proportion.

    >>> [round(x, 4) for x in wilson(95, 100)]
    [0.95, 0.8883, 0.9785]
    >>> wilson(100, 100).high
    1.0
    """
    p = successes / n
    denom = 1.0 + z * z / n
    centre = (p + z * z / (2 * n)) / denom
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / denom
    # at the ends the interval reaches the end exactly (rounding would leave 1e-17)
    low = 0.0 if successes == 0 else max(0.0, centre - half)
    high = 1.0 if successes == n else min(1.0, centre + half)
    return Interval(p, low, high)


def _ranks(x: np.ndarray) -> np.ndarray:
    """Ranks of ``x`` along its last axis (ties broken by order: continuous inputs have
    none; a constant array is handled by the caller)."""
    order = np.argsort(x, axis=-1, kind="stable")
    ranks = np.empty_like(order, dtype=float)
    np.put_along_axis(ranks, order, np.arange(x.shape[-1], dtype=float)[None, :], axis=-1)
    return ranks


def rank_correlations(inputs: np.ndarray, margin: np.ndarray) -> np.ndarray:
    """Spearman's ρ of a margin with each row of ``inputs`` (shape d × n); 0 where the
    margin or an input does not vary."""
    if np.ptp(margin) == 0.0:
        return np.zeros(inputs.shape[0])
    rx = _ranks(inputs)
    ry = _ranks(margin[None, :])[0]
    rx -= rx.mean(axis=1, keepdims=True)
    ry -= ry.mean()
    num = rx @ ry
    den = np.sqrt((rx * rx).sum(axis=1) * (ry @ ry))
    with np.errstate(invalid="ignore", divide="ignore"):
        rho = np.where(den > 0, num / den, 0.0)
    return rho


class CheckResult(NamedTuple):
    id: str
    probability: Interval
    margin_p05: float
    margin_p50: float
    drivers: list[tuple[str, float]]  # (input, ρ), largest |ρ| first


def check_results(
    margins: dict[str, np.ndarray], samples: dict[str, np.ndarray]
) -> tuple[list[CheckResult], Interval]:
    """Every check's P(pass), margin percentiles and drivers, and P(all pass)."""
    names = list(samples)
    x = np.vstack([samples[k] for k in names]) if names else np.zeros((0, 1))
    n = next(iter(margins.values())).shape[0]
    every = np.ones(n, dtype=bool)
    out = []
    for cid, m in margins.items():
        ok = m >= 1.0
        every &= ok
        rho = rank_correlations(x, m) if names else np.zeros(0)
        drivers = sorted(zip(names, (float(r) for r in rho), strict=True), key=lambda t: -abs(t[1]))
        p05, p50 = np.percentile(m, [5.0, 50.0])
        out.append(CheckResult(cid, wilson(int(ok.sum()), n), float(p05), float(p50), drivers))
    return out, wilson(int(every.sum()), n)
