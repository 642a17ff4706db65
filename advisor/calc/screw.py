"""Sliding screw–nut (trapezoidal thread): kinematics, torque, efficiency and strength.

All functions take SI units (m, N, s, Pa) and return SI units.

References
----------
[1] Seed 001: Ivanov, Kolesnik, Koloshenko, «Обеспечение эксплуатационной совместимости
    асинхронных двигателей с линейным перемещением исполнительного элемента»
    (001_085658f38eaaea54.txt).
[2] GOST 24737-81 / ISO 2904: basic profile of trapezoidal threads (flank angle α = 30°).
[3] Ivanov M. N., «Детали машин» (textbook), power screws: combined core stress, nut bearing
    pressure, nut height ratio ψ_H = H/d2.
[4] Euler and Johnson column formulas (any strength-of-materials text, e.g. Shigley,
    «Mechanical Engineering Design», ch. 4: columns with central loading).
"""

import math
from typing import Literal

FrictionModel = Literal["standard", "paper"]

#: Flank angle of the trapezoidal thread, GOST 24737-81 [2].
TRAPEZOIDAL_FLANK_ANGLE_RAD = math.radians(30.0)

#: Effective-length factors μ (L_eff = μ·L) for the end fixities of a column [4].
END_FIXITY_FACTOR: dict[str, float] = {
    "fixed-fixed": 0.5,
    "fixed-pinned": 0.7,
    "pinned-pinned": 1.0,
    "fixed-free": 2.0,
}


def linear_speed(stroke_m: float, travel_time_s: float) -> float:
    """Linear speed of the rod, v = l / t  [m/s]. Seed 001, eq. for v.

    >>> linear_speed(0.2, 5.0)
    0.04
    """
    return stroke_m / travel_time_s


def revolutions(stroke_m: float, pitch_m: float, starts: int = 1) -> float:
    """Screw revolutions over the stroke, N = l / (P·n_starts). Seed 001 (N = l·10³/P, l in m,
    P in mm, for one start).

    >>> round(revolutions(0.2, 0.002), 9)
    100.0
    """
    return stroke_m / (pitch_m * starts)


def screw_speed_rpm(revs: float, travel_time_s: float) -> float:
    """Screw speed that makes the stroke in the given time, n = 60·N / t  [rpm]. Seed 001.

    >>> screw_speed_rpm(100.0, 5.0)
    1200.0
    """
    return 60.0 * revs / travel_time_s


def lead_angle(pitch_m: float, d2_m: float, starts: int = 1) -> float:
    """Lead angle ψ: tan ψ = P·n / (π·d2)  [rad]. Seed 001."""
    return math.atan(pitch_m * starts / (math.pi * d2_m))


def friction_angle(f: float, model: FrictionModel, psi_rad: float) -> float:
    """Reduced friction angle φ' of the thread  [rad].

    ``standard``: tan φ' = f / cos(α/2), α = 30° — the reduced friction of an inclined flank
    (Ivanov [3]; DOMAIN.md). ``paper``: tan φ = f / cos(ψ/2) as printed in seed 001, where the
    half lead angle stands in place of the half flank angle (a slip, kept to reproduce the
    paper's 5.085 N·m).
    """
    if model == "standard":
        return math.atan(f / math.cos(TRAPEZOIDAL_FLANK_ANGLE_RAD / 2))
    if model == "paper":
        return math.atan(f / math.cos(psi_rad / 2))
    raise ValueError(f"unknown friction model {model!r}")


def thread_torque(
    force_N: float,
    d2_m: float,
    pitch_m: float,
    f: float,
    model: FrictionModel = "standard",
    starts: int = 1,
) -> float:
    """Torque to drive the nut against the axial force, M = F·d2/2·tan(ψ + φ)  [N·m].

    Seed 001, eq. (1). The worked example of seed 001 (Tr16x2, F = 3500 N, f = 0.15, one
    start, the paper's friction formula) gives 5.085 N·m:

    >>> round(thread_torque(3500, 0.015, 0.002, 0.15, "paper"), 3)
    5.085
    >>> round(thread_torque(3500, 0.015, 0.002, 0.15, "standard"), 3)
    5.225
    """
    psi = lead_angle(pitch_m, d2_m, starts)
    return torque_from_angles(force_N, d2_m, psi, friction_angle(f, model, psi))


def torque_from_angles(force_N: float, d2_m: float, psi_rad: float, phi_rad: float) -> float:
    """M = F·d2/2·tan(ψ + φ') of seed 001, eq. (1), from angles already computed  [N·m]."""
    return force_N * d2_m / 2.0 * math.tan(psi_rad + phi_rad)


def efficiency(psi_rad: float, phi_rad: float) -> float:
    """Efficiency of the screw driving the nut, η = tan ψ / tan(ψ + φ'). Ivanov [3]."""
    return math.tan(psi_rad) / math.tan(psi_rad + phi_rad)


def back_driving_efficiency(psi_rad: float, phi_rad: float) -> float:
    """Efficiency when the load drives the screw, η' = tan(ψ − φ') / tan ψ; ≤ 0 means the
    pair is self-locking. Ivanov [3]."""
    return math.tan(psi_rad - phi_rad) / math.tan(psi_rad)


def is_self_locking(psi_rad: float, phi_rad: float) -> bool:
    """A screw–nut holds its load without power when the lead angle is below the friction
    angle, ψ < φ'. Ivanov [3]."""
    return psi_rad < phi_rad


def core_equivalent_stress(force_N: float, torque_Nm: float, d3_m: float) -> float:
    """Von Mises stress in the screw core under axial force and torque  [Pa].

    σ = 4F/(π·d3²), τ = 16M/(π·d3³), σ_eq = √(σ² + 3τ²). Ivanov [3].

    Hand check for Tr16x2 at 3500 N and 5.085 N·m: σ = 24.45 MPa, τ = 10.53 MPa,
    σ_eq = √(24.45² + 3·10.53²) = 30.50 MPa.

    >>> round(core_equivalent_stress(3500, 5.085, 0.0135) / 1e6, 2)
    30.5
    """
    sigma = 4.0 * force_N / (math.pi * d3_m**2)
    tau = 16.0 * torque_Nm / (math.pi * d3_m**3)
    return math.sqrt(sigma**2 + 3.0 * tau**2)


def critical_buckling_load(
    d3_m: float,
    span_m: float,
    fixity: str,
    elastic_modulus_Pa: float,
    yield_strength_Pa: float,
) -> tuple[float, float, str]:
    """Critical axial load of the screw core as a column  [N].

    Returns ``(P_cr, slenderness, formula)``. The core is a round bar of diameter d3
    (radius of gyration i = d3/4), effective length μ·L with μ from :data:`END_FIXITY_FACTOR`.
    Euler above the transition slenderness λ_c = π·√(2E/σ_y), Johnson's parabola below it [4]:

    - Euler: P_cr = π²·E·I / (μL)²
    - Johnson: P_cr = A·(σ_y − (σ_y·λ / (2π))² / E)

    Hand check, Tr16x2 core (d3 = 13.5 mm) between pinned supports 0.4 m apart, steel 45
    (E = 210 GPa, σ_y = 355 MPa): λ = 400/3.375 = 118.5 > λ_c = 108.1, Euler:
    I = π·13.5⁴/64 = 1630.44 mm⁴, P_cr = π²·210000·1630.44/400² = 21120.5 N.

    >>> p, lam, how = critical_buckling_load(0.0135, 0.4, "pinned-pinned", 210e9, 355e6)
    >>> round(p, 1), round(lam, 1), how
    (21120.5, 118.5, 'Euler')
    """
    mu = END_FIXITY_FACTOR[fixity]
    area = math.pi * d3_m**2 / 4.0
    inertia = math.pi * d3_m**4 / 64.0
    slenderness = mu * span_m / (d3_m / 4.0)
    transition = math.pi * math.sqrt(2.0 * elastic_modulus_Pa / yield_strength_Pa)
    if slenderness >= transition:
        return math.pi**2 * elastic_modulus_Pa * inertia / (mu * span_m) ** 2, slenderness, "Euler"
    sigma_cr = yield_strength_Pa - (yield_strength_Pa * slenderness / (2.0 * math.pi)) ** 2 / (
        elastic_modulus_Pa
    )
    return area * sigma_cr, slenderness, "Johnson"


def nut_turns_required(
    force_N: float, d2_m: float, h1_m: float, allowable_pressure_Pa: float
) -> float:
    """Engaged turns so that the flank pressure stays within the allowable one, from
    p = F / (π·d2·H1·z) ≤ [p]  (H1 = working depth of the thread). Ivanov [3].

    >>> round(nut_turns_required(3500, 0.015, 0.001, 10e6), 3)
    7.427
    """
    return force_N / (math.pi * d2_m * h1_m * allowable_pressure_Pa)


def nut_bearing_pressure(force_N: float, d2_m: float, h1_m: float, turns: float) -> float:
    """Flank pressure in the nut, p = F / (π·d2·H1·z)  [Pa]. Ivanov [3].

    >>> round(nut_bearing_pressure(3500, 0.015, 0.001, 9.0) / 1e6, 3)
    8.252
    """
    return force_N / (math.pi * d2_m * h1_m * turns)
