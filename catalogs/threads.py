"""Basic profile of single-start metric trapezoidal threads, GOST 24737-81 (= ISO 2904).

Formulas of the standard (all in mm):
    H1 = 0.5·P            working depth
    ac                    crest clearance: 0.15 (P = 1.5), 0.25 (P = 2…5), 0.5 (P = 6…12),
                          1.0 (P = 14…44)
    h3 = H4 = 0.5·P + ac  thread depth of screw and nut
    d2 = D2 = d − 0.5·P   pitch diameters
    d3 = d − 2·h3         minor diameter of the screw
    D1 = d − P            minor diameter of the nut
    D4 = d + 2·ac         major diameter of the nut
"""

from typing import NamedTuple


def crest_clearance_mm(pitch_mm: float) -> float:
    """ac of GOST 24737-81 for a pitch.

    >>> [crest_clearance_mm(p) for p in (1.5, 2, 5, 6, 12, 14, 20)]
    [0.15, 0.25, 0.25, 0.5, 0.5, 1.0, 1.0]
    """
    if pitch_mm <= 1.5:
        return 0.15
    if pitch_mm <= 5:
        return 0.25
    if pitch_mm <= 12:
        return 0.5
    return 1.0


class ThreadProfile(NamedTuple):
    """One diameter–pitch combination with its GOST 24737-81 dimensions (mm)."""

    d_mm: float
    pitch_mm: float
    preferred: bool
    series: int
    ac_mm: float
    H1_mm: float
    h3_mm: float
    d2_mm: float
    d3_mm: float
    D1_mm: float
    D2_mm: float
    D4_mm: float

    @property
    def name(self) -> str:
        return f"Tr{self.d_mm:g}x{self.pitch_mm:g}"


def trapezoidal_profile(
    d_mm: float, pitch_mm: float, *, preferred: bool = False, series: int = 1
) -> ThreadProfile:
    """Profile dimensions of Tr d×P by GOST 24737-81.

    >>> t = trapezoidal_profile(16, 2)
    >>> t.name, t.d2_mm, t.d3_mm, t.D1_mm, t.D2_mm, t.D4_mm
    ('Tr16x2', 15.0, 13.5, 14.0, 15.0, 16.5)
    """
    d_mm, pitch_mm = float(d_mm), float(pitch_mm)
    ac = crest_clearance_mm(pitch_mm)
    h3 = 0.5 * pitch_mm + ac
    return ThreadProfile(
        d_mm=d_mm,
        pitch_mm=pitch_mm,
        preferred=preferred,
        series=series,
        ac_mm=ac,
        H1_mm=0.5 * pitch_mm,
        h3_mm=h3,
        d2_mm=d_mm - 0.5 * pitch_mm,
        d3_mm=d_mm - 2.0 * h3,
        D1_mm=d_mm - pitch_mm,
        D2_mm=d_mm - 0.5 * pitch_mm,
        D4_mm=d_mm + 2.0 * ac,
    )
