"""Basic rating life (ISO 281) and the SKF friction model of a ball bearing.

Loads in N, speeds in rpm, dimensions in mm, moments in N·mm inside the SKF formulas (as the
catalogue writes them) and N·m at the interface.
"""

import itertools
import math
from typing import NamedTuple

from catalogs.rows import Bearing, FrictionConstants

# ISO 281:2007, table 3, single-row angular contact ball bearings, α = 15°:
# i·F_a/C0 → (e, Y) with X = 0.44 when F_a/F_r > e.
_AC15 = (
    (0.015, 0.38, 1.47),
    (0.029, 0.40, 1.40),
    (0.058, 0.43, 1.30),
    (0.087, 0.46, 1.23),
    (0.12, 0.47, 1.19),
    (0.17, 0.50, 1.12),
    (0.29, 0.55, 1.02),
    (0.44, 0.56, 1.00),
    (0.58, 0.56, 1.00),
)
# Deep groove (radial contact) ball bearings, normal clearance: f0·F_a/C0 → (e, Y), X = 0.56.
_DG = (
    (0.172, 0.19, 2.30),
    (0.345, 0.22, 1.99),
    (0.689, 0.26, 1.71),
    (1.03, 0.28, 1.55),
    (1.38, 0.30, 1.45),
    (2.07, 0.34, 1.31),
    (3.45, 0.38, 1.15),
    (5.17, 0.42, 1.04),
    (6.89, 0.44, 1.00),
)
# Single-row angular contact at larger angles: constant e, X, Y (ISO 281, table 3).
_AC_FIXED = {25.0: (0.68, 0.41, 0.87), 40.0: (1.14, 0.35, 0.57)}


def _interp(table, x: float) -> tuple[float, float]:
    if x <= table[0][0]:
        return table[0][1], table[0][2]
    for (x0, e0, y0), (x1, e1, y1) in itertools.pairwise(table):
        if x <= x1:
            t = (x - x0) / (x1 - x0)
            return e0 + t * (e1 - e0), y0 + t * (y1 - y0)
    return table[-1][1], table[-1][2]


class Equivalent(NamedTuple):
    load_N: float
    e: float
    X: float
    Y: float


def equivalent_load(b: Bearing, radial_N: float, axial_N: float) -> Equivalent:
    """Dynamic equivalent load P = X·F_r + Y·F_a (ISO 281:2007, 6.1).

    Parameters
    ----------
    b : Bearing
        Catalog row: C, C0 [kN], type, contact angle [°], f0
    radial_N : float
        Radial load F_r [N]
    axial_N : float
        Axial load F_a [N]

    Returns
    -------
    Equivalent
        Equivalent load P [N], the limit e and the factors X, Y [-]

    Notes
    -----
    Single-row deep-groove (normal clearance) and angular-contact ball bearings, ISO 281:2007,
    table 3.
    """
    c0 = b.C0_kN * 1e3
    if b.type == "deep_groove":
        e, y = _interp(_DG, (b.f0 or 0.0) * axial_N / c0)
        x = 0.56
    else:
        angle = b.contact_angle_deg
        nearest = min([15.0, *_AC_FIXED], key=lambda a: abs(a - angle))
        if nearest == 15.0:
            e, y = _interp(_AC15, axial_N / c0)
            x = 0.44
        else:
            e, x, y = _AC_FIXED[nearest]
    if radial_N > 0 and axial_N / radial_N <= e:
        return Equivalent(radial_N, e, 1.0, 0.0)
    return Equivalent(x * radial_N + y * axial_N, e, x, y)


def rating_life_h(b: Bearing, load_N: float, speed_rpm: float) -> float:
    """L10h = 10⁶/(60·n)·(C/P)³ for ball bearings (ISO 281:2007, eq. (1)).

    Parameters
    ----------
    b : Bearing
        Catalog row: C, C0 [kN], type, contact angle [°], f0
    load_N : float
        Dynamic equivalent load P [N]
    speed_rpm : float
        Speed n [rpm]

    Returns
    -------
    float
        Basic rating life L10h [h]; infinite without load
    """
    if load_N <= 0:
        return math.inf
    return 1e6 / (60.0 * speed_rpm) * (b.C_kN * 1e3 / load_N) ** 3


#: Weibull slope of ball-bearing fatigue (Lundberg–Palmgren; SKF General Catalogue, system life).
BALL_WEIBULL_SLOPE = 10.0 / 9.0


def set_life_h(life_h: float, bearings: int, slope: float = BALL_WEIBULL_SLOPE) -> float:
    """The L10 life of a set of equal bearings at equal loads: the time by which 10 % of such
    sets have lost a bearing.

        L_set = (Σ L_i^(−e))^(−1/e) = L·n^(−1/e)

    Parameters
    ----------
    life_h : float
        L10h of one bearing [h]
    bearings : int
        Bearings in the set, n [-], ≥ 1
    slope : float
        Weibull slope e [-]; 10/9 for ball bearings

    Returns
    -------
    float
        L10h of the set [h]; a pair of ball bearings 0.536·L

    References
    ----------
    SKF General Catalogue, system life; Lundberg–Palmgren.

    >>> round(set_life_h(1000.0, 2), 1)
    535.9
    """
    return life_h * bearings ** (-1.0 / slope)


def static_safety(b: Bearing, radial_N: float, axial_N: float) -> float:
    """s0 = C0/P0 with P0 = max(F_r, 0.5·F_r + 0.46·F_a) for 15° angular contact, 0.6/0.5 for
    deep groove (ISO 76 / SKF catalogue).

    Parameters
    ----------
    b : Bearing
        Catalog row: C, C0 [kN], type, contact angle [°], f0
    radial_N : float
        Radial load F_r [N]
    axial_N : float
        Axial load F_a [N]

    Returns
    -------
    float
        Static safety s0 = C0/P0 [-]; infinite without load
    """
    if b.type == "deep_groove":
        p0 = max(radial_N, 0.6 * radial_N + 0.5 * axial_N)
    else:
        y0 = 0.46 if b.contact_angle_deg < 20 else 0.38 if b.contact_angle_deg < 30 else 0.26
        p0 = max(radial_N, 0.5 * radial_N + y0 * axial_N)
    return math.inf if p0 <= 0 else b.C0_kN * 1e3 / p0


class SkfFriction(NamedTuple):
    rolling_Nm: float
    sliding_Nm: float
    shear_heating_factor: float

    @property
    def total_Nm(self) -> float:
        return self.rolling_Nm + self.sliding_Nm


#: SKF friction model, sliding friction in a full film of mineral oil, and with the additive
#: boundary film (SKF General Catalogue, 'Трение').
MU_EHL = 0.05
MU_BL = 0.15


def skf_friction(
    b: Bearing,
    k: FrictionConstants,
    radial_N: float,
    axial_N: float,
    speed_rpm: float,
    viscosity_mm2_s: float,
) -> SkfFriction:
    """Rolling and sliding moments of the SKF model, M = φ_ish·M_rr + M_sl (no seals, no
    oil-bath drag; the kinematic-starvation factor φ_rs is taken as 1, which errs high).

    Parameters
    ----------
    b : Bearing
        Catalog row: d, D [mm], C0 [kN], type
    k : FrictionConstants
        The SKF model's constants R1…R3, S1…S3 of the bearing's series
    radial_N : float
        Radial load F_r [N]
    axial_N : float
        Axial load F_a [N]
    speed_rpm : float
        Speed n [rpm]
    viscosity_mm2_s : float
        Lubricant's kinematic viscosity at the operating temperature ν [mm²/s]

    Returns
    -------
    SkfFriction
        Rolling and sliding moments [N·m] and the shear heating factor φ_ish [-]

    Notes
    -----
    SKF General Catalogue, the SKF model of frictional moment; dimensions in mm and moments in
    N·mm inside the formulas.
    """
    n, nu = speed_rpm, viscosity_mm2_s
    dm = 0.5 * (b.d_mm + b.D_mm)
    fr, fa = radial_N, axial_N
    if b.type == "deep_groove":
        if fa > 0:
            alpha_f = math.radians(24.6 * (fa / (b.C0_kN * 1e3)) ** 0.24)
            g_rr = k.R1 * dm**1.96 * (fr + k.R2 / math.sin(alpha_f) * fa) ** 0.54
            g_sl = (
                k.S1 * dm**-0.145 * (fr**5 + k.S2 * dm**1.5 / math.sin(alpha_f) * fa**4) ** (1 / 3)
            )
        else:
            g_rr = k.R1 * dm**1.96 * fr**0.54
            g_sl = k.S1 * dm**-0.26 * fr ** (5 / 3)
    else:
        fg_rr = k.R3 * dm**4 * n * n
        fg_sl = k.S3 * dm**4 * n * n
        g_rr = k.R1 * dm**1.97 * (fr + fg_rr + k.R2 * fa) ** 0.54
        g_sl = k.S1 * dm**0.26 * ((fr + fg_sl) ** (4 / 3) + k.S2 * fa ** (4 / 3))
    m_rr = g_rr * (nu * n) ** 0.6
    phi_bl = 1.0 / math.exp(min(2.6e-8 * (n * nu) ** 1.4 * dm, 700.0))
    mu_sl = phi_bl * MU_BL + (1.0 - phi_bl) * MU_EHL
    phi_ish = 1.0 / (1.0 + 1.84e-9 * (n * dm) ** 1.28 * nu**0.64)
    return SkfFriction(phi_ish * m_rr * 1e-3, mu_sl * g_sl * 1e-3, phi_ish)


def rating_life_Mrev(C_N: float, load_N: float, exponent: float = 3.0) -> float:
    """L10 = (C/P)^p  [millions of revolutions], p = 3 for ball bearings (ISO 281:2007,
    eq. (1)).

    SKF General Catalogue, calculation example 1: 6309, C = 55.3 kN, P = F_r = 10 kN →
    (5.53)³ = 169.1 million revolutions.

    Parameters
    ----------
    C_N : float
        Basic dynamic load rating C [N]
    load_N : float
        Dynamic equivalent load P [N]
    exponent : float, optional
        Life exponent p: 3 ball bearings, 10/3 roller bearings [-]

    Returns
    -------
    float
        Basic rating life L10 [millions of revolutions]; infinite without load

    Examples
    --------
    >>> round(rating_life_Mrev(55300.0, 10000.0), 1)
    169.1
    """
    if load_N <= 0:
        return math.inf
    return (C_N / load_N) ** exponent


def hours_from_Mrev(life_Mrev: float, speed_rpm: float) -> float:
    """L10h = 10⁶/(60·n)·L10  [h] (ISO 281:2007). SKF's example 1: 169 million revolutions at
    3000 r/min → 10⁶/(60·3000)·169 = 939 h, printed as 940 h.

    Parameters
    ----------
    life_Mrev : float
        Life L10 [millions of revolutions]
    speed_rpm : float
        Speed n [rpm]

    Returns
    -------
    float
        Life L10h [h]

    Examples
    --------
    >>> round(hours_from_Mrev(169.0, 3000.0))
    939
    """
    return 1e6 / (60.0 * speed_rpm) * life_Mrev


def pair_loads(
    radial_N: float, axial_N: float, moment_Nm: float, spacing_mm: float | None
) -> tuple[float, float]:
    """The radial and axial load on the most loaded output bearing: one bearing takes the
    forces as they are; a pair ``spacing_mm`` apart takes the radial force half each, the
    tilting moment as a couple ±M/a, and the axial force on the locating one (counted on the
    most loaded one: errs high).

    Parameters
    ----------
    radial_N : float
        Radial force at the output F_r [N]
    axial_N : float
        Axial force at the output F_a [N]
    moment_Nm : float
        Tilting moment M [N·m]
    spacing_mm : float or None
        Distance between the pair's bearings a [mm]; None: one bearing

    Returns
    -------
    tuple of float
        Radial and axial load on the most loaded bearing [N]

    Examples
    --------
    >>> pair_loads(10000.0, 0.0, 0.0, None)
    (10000.0, 0.0)
    >>> pair_loads(2000.0, 500.0, 100.0, 100.0)  # 1000 + 100/0.1
    (2000.0, 500.0)
    """
    if spacing_mm is None:
        return radial_N, axial_N
    return radial_N / 2.0 + moment_Nm / (spacing_mm * 1e-3), axial_N
