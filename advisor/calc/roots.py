"""A bracketing root finder for the batch path.

scipy.optimize.brentq would do, but importing scipy.optimize costs about 0.3 s, more than the
whole budget of a cold batch run (1.3 x the bare import of numpy, scipy, pydantic, tomli_w).
The functions solved here are smooth and monotone on their bracket, so bisection to machine
precision (about 60 halvings) is exact enough and costs microseconds.
"""

import math
from collections.abc import Callable


def bisect(f: Callable[[float], float], lo: float, hi: float, *, xtol: float = 1e-13) -> float:
    """Root of ``f`` in [lo, hi] by bisection.

        halve [lo, hi] keeping the sign change until hi − lo < xtol·max(1, |x|)

    Parameters
    ----------
    f : Callable[[float], float]
        A continuous function, in whatever units the caller's x and f(x) carry
    lo : float
        Lower end of the bracket [units of x]
    hi : float
        Upper end of the bracket [units of x]; f(lo) and f(hi) must differ in sign
    xtol : float
        Relative width at which to stop [-]; 1e-13 by default

    Returns
    -------
    float
        A root x [units of x]; lo or hi where f is zero there

    Notes
    -----
    Raises ValueError without a sign change. At most 200 halvings; about 60 reach machine
    precision on a bracket of order one. Robust on any continuous f; slower than :func:`brent`.

    References
    ----------
    Any numerical analysis text, e.g. Press et al., *Numerical Recipes*, 3rd ed., §9.1.

    Examples
    --------
    >>> round(bisect(lambda x: x * x - 2.0, 0.0, 2.0), 12)
    1.414213562373
    """
    flo, fhi = f(lo), f(hi)
    if flo == 0.0:
        return lo
    if fhi == 0.0:
        return hi
    if (flo > 0) == (fhi > 0):
        raise ValueError(f"no sign change on [{lo}, {hi}]: f = {flo}, {fhi}")
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        fmid = f(mid)
        if fmid == 0.0 or hi - lo < xtol * max(1.0, abs(mid)):
            return mid
        if (fmid > 0) == (flo > 0):
            lo, flo = mid, fmid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def brent(f: Callable[[float], float], lo: float, hi: float, *, xtol: float = 1e-13) -> float:
    """Root of ``f`` in [lo, hi] by Brent's method: inverse quadratic interpolation and secant
    steps, safeguarded by bisection.

    Parameters
    ----------
    f : Callable[[float], float]
        A continuous function, in whatever units the caller's x and f(x) carry
    lo : float
        Lower end of the bracket [units of x]
    hi : float
        Upper end of the bracket [units of x]; f(lo) and f(hi) must differ in sign
    xtol : float
        Relative width at which to stop [-]: the bracket shrinks to xtol·max(1, |x|)

    Returns
    -------
    float
        A root x [units of x]

    Notes
    -----
    Raises ValueError without a sign change. About ten evaluations for a smooth ``f`` where
    bisection takes sixty; at most 200 steps.

    References
    ----------
    R. P. Brent, *Algorithms for Minimization without Derivatives*, 1973, ch. 4.

    >>> round(brent(lambda x: x * x - 2.0, 0.0, 2.0), 12)
    1.414213562373
    """
    a, b = lo, hi
    fa, fb = f(a), f(b)
    if fa == 0.0:
        return a
    if fb == 0.0:
        return b
    if (fa > 0) == (fb > 0):
        raise ValueError(f"no sign change on [{lo}, {hi}]: f = {fa}, {fb}")
    c, fc = b, fb
    d = e = b - a
    for _ in range(200):
        if (fb > 0) == (fc > 0):  # keep the root between b and c
            c, fc = a, fa
            d = e = b - a
        if abs(fc) < abs(fb):  # b is the best estimate so far
            a, b, c = b, c, b
            fa, fb, fc = fb, fc, fb
        tol = 0.5 * xtol * max(1.0, abs(b)) + 2.0 * _EPS * abs(b)
        m = 0.5 * (c - b)
        if abs(m) <= tol or fb == 0.0:
            return b
        d, e = _brent_step((a, b, c), (fa, fb, fc), m, tol, d, e)
        a, fa = b, fb
        b += d if abs(d) > tol else (tol if m > 0 else -tol)
        fb = f(b)
    return b


def _brent_step(
    x: tuple[float, float, float],
    fx: tuple[float, float, float],
    m: float,
    tol: float,
    d: float,
    e: float,
) -> tuple[float, float]:
    """The next step of :func:`brent` from b and the step before it, (d, e): an inverse
    quadratic interpolation through a, b, c (a secant where a = c) where it stays inside the
    bracket and shrinks faster than the step before last; otherwise bisection, (m, m)."""
    a, b, c = x
    fa, fb, fc = fx
    if not (abs(e) >= tol and abs(fa) > abs(fb)):
        return m, m
    s = fb / fa
    if a == c:  # secant
        p, q = 2.0 * m * s, 1.0 - s
    else:  # inverse quadratic interpolation
        q, r = fa / fc, fb / fc
        p = s * (2.0 * m * q * (q - r) - (b - a) * (r - 1.0))
        q = (q - 1.0) * (r - 1.0) * (s - 1.0)
    if p > 0.0:
        q = -q
    p = abs(p)
    if 2.0 * p < min(3.0 * m * q - abs(tol * q), abs(e * q)):
        return p / q, d
    return m, m  # the interpolation strays: bisect


_EPS = 2.220446049250313e-16


def golden_min(
    f: Callable[[float], float], a: float, b: float, *, iterations: int = 200, xtol: float = 0.0
) -> float:
    """The minimum of a unimodal ``f`` on [a, b] by golden-section search.

        c = b − φ·(b − a),  e = a + φ·(b − a),  φ = (√5 − 1)/2; keep the side of the smaller value

    Parameters
    ----------
    f : Callable[[float], float]
        A unimodal function on [a, b], in whatever units the caller's x and f(x) carry
    a : float
        Lower end of the interval [units of x]
    b : float
        Upper end of the interval [units of x]
    iterations : int
        Most steps [-]; each shrinks the bracket by φ ≈ 0.618
    xtol : float
        Absolute bracket width at which to stop [units of x]; 0: run every iteration

    Returns
    -------
    float
        The middle of the last bracket [units of x]

    Notes
    -----
    On a function with more than one minimum in [a, b] it finds one of them, not necessarily the
    least.

    References
    ----------
    J. Kiefer, "Sequential minimax search for a maximum", Proc. AMS 4 (1953) 502–506.

    Examples
    --------
    >>> round(golden_min(lambda x: (x - 2.0) ** 2, 0.0, 5.0), 9)
    2.0
    """
    phi = (math.sqrt(5.0) - 1.0) / 2.0
    c, e = b - phi * (b - a), a + phi * (b - a)
    fc, fe = f(c), f(e)
    for _ in range(iterations):
        if fc < fe:
            b, e, fe = e, c, fc
            c = b - phi * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, e, fe
            e = a + phi * (b - a)
            fe = f(e)
        if b - a < xtol:
            break
    return (a + b) / 2.0
