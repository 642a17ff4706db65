"""Samples of the uncertain inputs: a Latin hypercube (McKay, Beckman & Conover 1979) in the
unit cube by :class:`scipy.stats.qmc.LatinHypercube`, mapped through each input's inverse
distribution function. The inputs are taken independent; the same seed gives the same
samples."""

from typing import NamedTuple

import numpy as np


class Distribution(NamedTuple):
    """One input's law, with its parameters resolved (a default mean or mode is the nominal
    value); ``unit`` as the input's key names it."""

    name: str
    kind: str  # "uniform", "normal", "triangular"
    nominal: float
    low: float | None = None
    high: float | None = None
    sd: float | None = None
    mean: float | None = None
    mode: float | None = None
    basis: str = "given"

    def describe(self) -> str:
        if self.kind == "uniform":
            return f"uniform {self.low:g} … {self.high:g}"
        if self.kind == "normal":
            return f"normal, mean {self.mean:g}, σ {self.sd:g}"
        return f"triangular {self.low:g} … {self.mode:g} … {self.high:g}"


def unit_cube(n: int, d: int, seed: int) -> np.ndarray:
    """``n`` Latin hypercube points in (0, 1)^d: each input's range cut into n equal strata,
    one point in each, the strata paired at random."""
    from scipy.stats import qmc

    return qmc.LatinHypercube(d=d, rng=np.random.default_rng(seed)).random(n)


def inverse_cdf(u: np.ndarray, dist: Distribution) -> np.ndarray:
    """The input's values at probabilities ``u`` (its quantile function).

    >>> inverse_cdf(np.array([0.0, 0.5, 1.0]), Distribution("x", "uniform", 1, 0.0, 2.0))
    array([0., 1., 2.])
    >>> d = Distribution("x", "triangular", 1, low=0.0, high=2.0, mode=1.0)
    >>> inverse_cdf(np.array([0.125, 0.5, 0.875]), d)
    array([0.5, 1. , 1.5])
    """
    if dist.kind == "uniform":
        return dist.low + u * (dist.high - dist.low)
    if dist.kind == "normal":
        from scipy.special import ndtri

        return dist.mean + dist.sd * ndtri(u)
    a, b, c = dist.low, dist.high, dist.mode
    f = (c - a) / (b - a)  # the CDF at the mode
    left = a + np.sqrt(u * (b - a) * (c - a))
    right = b - np.sqrt((1.0 - u) * (b - a) * (b - c))
    return np.where(u < f, left, right)


def sample(dists: list[Distribution], n: int, seed: int) -> dict[str, np.ndarray]:
    """``n`` joint samples of the inputs, by name."""
    u = unit_cube(n, len(dists), seed)
    return {d.name: inverse_cdf(u[:, i], d) for i, d in enumerate(dists)}
