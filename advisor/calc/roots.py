"""A bracketing root finder for the batch path.

scipy.optimize.brentq would do, but importing scipy.optimize costs about 0.3 s, more than the
whole budget of a cold batch run (1.3 x the bare import of numpy, scipy, pydantic, tomli_w).
The functions solved here are smooth and monotone on their bracket, so bisection to machine
precision (about 60 halvings) is exact enough and costs microseconds.
"""

from collections.abc import Callable


def bisect(f: Callable[[float], float], lo: float, hi: float, *, xtol: float = 1e-13) -> float:
    """Root of ``f`` in ``[lo, hi]``; ``f(lo)`` and ``f(hi)`` must differ in sign.

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
