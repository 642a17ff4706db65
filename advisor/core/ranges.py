"""Ranges in words, free of pydantic: the prose of a requirement field's valid range, made
from its constraint (:func:`range_prose`, so that the range is declared once), and the ranges
the constraints cannot state alone (used by the ``requirement_checks`` modules of the
applications and the duty)."""

import math

#: Units written with an SI prefix in a range (``1 mm … 20 m``, ``1 N … 5 MN``); every other
#: limit is a plain number or a power of ten (``1 … 10⁵ N·m``), as the error message's "must be
#: ≥ 0.01" gives it, the unit after the range's upper end.
PREFIXED_UNITS = ("N", "m")
#: Units a range writes otherwise than a key's suffix names them.
PROSE_UNITS = {"deg": "°"}
_PREFIXES = ((1e6, "M"), (1e3, "k"), (1.0, ""), (1e-3, "m"), (1e-6, "µ"))
_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def number_prose(x: float) -> str:
    """A limit as the prose of a range writes it: plain from 0.01 to below 10⁴ (``0.05``,
    ``2000``) except 10³ itself, else a power of ten (``10⁻³``, ``10³``, ``2·10⁵``).

    >>> [number_prose(x) for x in (0, 0.05, 2000, 1e3, 1e-3, 2e5)]
    ['0', '0.05', '2000', '10³', '10⁻³', '2·10⁵']
    """
    if x == 0 or (1e-2 <= abs(x) < 1e4 and abs(x) != 1e3):
        return f"{x:g}"
    exponent = math.floor(math.log10(abs(x)))
    mantissa = float(f"{x / 10.0**exponent:.6g}")
    power = "10" + str(exponent).translate(_SUPERSCRIPT)
    return power if mantissa == 1 else f"{mantissa:g}·{power}"


def _limit(x: float, unit: str) -> str:
    """One end of a range: with the SI prefix that leaves 1 to 999 before it (``5e6`` N →
    ``5 MN``) where the unit takes one, else :func:`number_prose` (without its unit)."""
    if x != 0 and unit in PREFIXED_UNITS:
        for scale, prefix in _PREFIXES:
            if abs(x) >= scale * (1 - 1e-12):
                return f"{x / scale:.6g} {prefix}{unit}"
    return number_prose(x)


def range_prose(
    unit: str = "",
    *,
    ge: float | None = None,
    gt: float | None = None,
    le: float | None = None,
    lt: float | None = None,
) -> str:
    """The valid range of a number in words, from its constraint: ``1 … 10⁵ N·m``,
    ``1 mm … 20 m`` (see :data:`PREFIXED_UNITS`), ``> 0 … 2000 mm`` (an open end), ``≥ 1``
    (no upper end).

    >>> range_prose("N·m", ge=1, le=1e5), range_prose("N", ge=1, le=5e6)
    ('1 … 10⁵ N·m', '1 N … 5 MN')
    >>> range_prose("mm", gt=0, le=2000), range_prose("", gt=0, lt=1)
    ('> 0 … 2000 mm', '> 0 … < 1')
    >>> range_prose("deg", ge=0, le=180)
    '0 … 180°'
    """
    lo, hi = (ge if gt is None else gt), (le if lt is None else lt)
    low = None if lo is None else ("" if gt is None else "> ") + _limit(lo, unit)
    high = None if hi is None else ("" if lt is None else "< ") + _limit(hi, unit)
    if low is not None and high is not None:
        words = f"{low} … {high}"
    elif low is not None:
        words = low if gt is not None else "≥ " + low
    elif high is not None:
        words = high if lt is not None else "≤ " + high
    else:
        return ""
    if not unit or words.endswith(unit):  # the upper end names it already
        return words
    shown = PROSE_UNITS.get(unit)
    return words + (shown if shown else f" {unit}")


def zero_or_from(v: float | None, least: float, upto: str) -> float | None:
    """``v`` if it is None, 0 (no such load) or at least ``least``; below that, a ValueError
    worded "must be 0 or from {least} to {upto}" (``upto``: the upper limit with its unit)."""
    if v is not None and 0 < v < least:
        raise ValueError(f"must be 0 or from {least:g} to {upto}")
    return v
