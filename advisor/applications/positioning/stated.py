"""How the positioning advice states a figure that stands against a bound: a time the reader
may ask for must be one the advisor accepts, and a figure said to exceed a bound must be
written with the digits that show it does."""

import math
from decimal import ROUND_CEILING, Decimal

from advisor.core.report import round_sig

#: The report's precision (:func:`advisor.core.report.round_sig`).
DIGITS = 6


def _at_digits(x: float, digits: int, rounding: str) -> float:
    """x rounded at ``digits`` significant digits in the direction ``rounding``, from its exact
    binary value."""
    exponent = math.floor(math.log10(abs(x))) - digits + 1
    return float(Decimal(x).quantize(Decimal(1).scaleb(exponent), rounding=rounding))


def stated_up(x: float, digits: int = DIGITS) -> float:
    """A time stated as a bound the reader may ask for: x at the report's six significant
    digits, rounded up where the report's rounding would go below it, so that asking for the
    stated value is asking for no less than x (a move of 1.2058823 s is stated 1.20589 s, not
    1.20588 s, which it does not meet). The report writes it unchanged.

    >>> stated_up(1.2058822512), stated_up(0.16854363), stated_up(0.168544)
    (1.20589, 0.168544, 0.168544)
    """
    if x <= 0 or not math.isfinite(x):
        return x
    near = round_sig(x, digits)
    return near if near >= x else _at_digits(x, digits, ROUND_CEILING)


def shown_above(x: float, bound: float) -> str:
    """x (> bound) written with the fewest significant digits, four at least, that still show
    it above the bound: a move of 0.1685436 s against 0.1685 s is written 0.16854, not 0.1685
    (which reads as meeting it).

    >>> shown_above(0.1685436, 0.1685), shown_above(1.0228672, 0.9), shown_above(2.0, 3.0)
    ('0.16854', '1.023', '2')
    """
    if not (math.isfinite(x) and x > bound):
        return f"{x:.4g}"
    for digits in range(4, 18):
        shown = f"{x:.{digits}g}"
        if float(shown) > bound:
            return shown
    return repr(x)


def shown_apart(a: float, b: float) -> tuple[str, str]:
    """a and b written with the fewest significant digits, four at least, that tell them apart
    (equal figures the same at four): 1.022944 s against 1.022867 s is written 1.02294 against
    1.02287, not 1.023 against 1.023.

    >>> shown_apart(1.022944, 1.022867), shown_apart(0.2915, 0.2893), shown_apart(2.0, 2.0)
    (('1.02294', '1.02287'), ('0.2915', '0.2893'), ('2', '2'))
    """
    for digits in range(4, 18):
        x, y = f"{a:.{digits}g}", f"{b:.{digits}g}"
        if x != y or a == b:
            return x, y
    return repr(a), repr(b)
