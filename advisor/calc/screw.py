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
    """Linear speed of the rod that makes the stroke in the travel time.

    v = l / t

    Parameters
    ----------
    stroke_m : float
        Stroke l [m]
    travel_time_s : float
        Time to travel the stroke t [s]

    Returns
    -------
    speed_m_s : float
        Linear speed v [m/s]

    Notes
    -----
    A constant speed over the stroke: the starting and stopping ramps are neglected, as in
    the seed.

    Examples
    --------
    Seed 001's worked example, 0.2 m in 5 s:

    >>> linear_speed(0.2, 5.0)
    0.04

    References
    ----------
    Seed 001, the speed v = l/t of its worked example.
    """
    return stroke_m / travel_time_s


def revolutions(stroke_m: float, pitch_m: float, starts: int = 1) -> float:
    """Screw revolutions over the stroke.

    N = l / (P·n_s)

    Parameters
    ----------
    stroke_m : float
        Stroke l [m]
    pitch_m : float
        Thread pitch P [m]
    starts : int, optional
        Number of thread starts n_s [-]

    Returns
    -------
    revolutions : float
        Revolutions N of the screw over the stroke [-]

    Notes
    -----
    The seed writes N = l·10³/P with l in m and P in mm, for one start; the lead is P·n_s.

    Examples
    --------
    >>> round(revolutions(0.2, 0.002), 9)
    100.0

    References
    ----------
    Seed 001, N = l·10³/P.
    """
    return stroke_m / (pitch_m * starts)


def screw_speed_rpm(revs: float, travel_time_s: float) -> float:
    """Screw speed that makes the stroke in the travel time.

    n = 60·N / t

    Parameters
    ----------
    revs : float
        Revolutions of the screw over the stroke N [-]
    travel_time_s : float
        Time to travel the stroke t [s]

    Returns
    -------
    speed_rpm : float
        Screw speed n [rpm]

    Examples
    --------
    Seed 001's worked example, 100 revolutions in 5 s:

    >>> screw_speed_rpm(100.0, 5.0)
    1200.0

    References
    ----------
    Seed 001, n = 60·N/t.
    """
    return 60.0 * revs / travel_time_s


def lead_angle(pitch_m: float, d2_m: float, starts: int = 1) -> float:
    """Lead angle of the thread on its pitch diameter.

    tan ψ = P·n_s / (π·d2)

    Parameters
    ----------
    pitch_m : float
        Thread pitch P [m]
    d2_m : float
        Pitch diameter d2 [m]
    starts : int, optional
        Number of thread starts n_s [-]

    Returns
    -------
    psi_rad : float
        Lead angle ψ [rad]

    Examples
    --------
    Tr16x2, one start: ψ = atan(2/(π·15)) = 2.43°:

    >>> round(math.degrees(lead_angle(0.002, 0.015)), 2)
    2.43

    References
    ----------
    Seed 001, tan ψ of eq. (1).
    """
    return math.atan(pitch_m * starts / (math.pi * d2_m))


def friction_angle(f: float, model: FrictionModel, psi_rad: float) -> float:
    """Reduced friction angle of the thread's flanks.

    standard: tan φ' = f / cos(α/2), α = 30°
    paper:    tan φ  = f / cos(ψ/2)

    Parameters
    ----------
    f : float
        Friction coefficient of the screw–nut pair [-]
    model : str
        'standard' (the reduced friction of an inclined flank, Ivanov [3]) or 'paper' (the
        formula as printed in seed 001)
    psi_rad : float
        Lead angle ψ, used by the 'paper' model only [rad]

    Returns
    -------
    phi_rad : float
        Reduced friction angle φ' [rad]

    Notes
    -----
    The seed's cos(ψ/2) puts the half lead angle where the half flank angle belongs (a
    slip, kept to reproduce the paper's 5.085 N·m); the standard model is the default. α is
    the 30° flank angle of the trapezoidal thread of GOST 24737-81 [2].

    Examples
    --------
    >>> round(math.degrees(friction_angle(0.15, "standard", 0.0)), 3)
    8.827

    References
    ----------
    Seed 001, eq. (1); Ivanov [3]; GOST 24737-81 [2].
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
    """Torque to drive the nut against the axial force.

    M = F·d2/2 · tan(ψ + φ'),  tan ψ = P·n_s/(π·d2)

    Parameters
    ----------
    force_N : float
        Axial force on the nut F [N]
    d2_m : float
        Pitch diameter d2 [m]
    pitch_m : float
        Thread pitch P [m]
    f : float
        Friction coefficient of the pair [-]
    model : str, optional
        Reduced friction model, 'standard' or 'paper' (see :func:`friction_angle`)
    starts : int, optional
        Number of thread starts n_s [-]

    Returns
    -------
    torque_Nm : float
        Torque at the screw M [N·m]

    Notes
    -----
    The thread's torque alone; a thrust face adds its own friction torque
    (:func:`collar_torque`).

    Examples
    --------
    Seed 001's worked example (Tr16x2, F = 3500 N, f = 0.15, one start, the paper's
    friction formula) gives 5.085 N·m:

    >>> round(thread_torque(3500, 0.015, 0.002, 0.15, "paper"), 3)
    5.085
    >>> round(thread_torque(3500, 0.015, 0.002, 0.15, "standard"), 3)
    5.225

    References
    ----------
    Seed 001, eq. (1).
    """
    psi = lead_angle(pitch_m, d2_m, starts)
    return torque_from_angles(force_N, d2_m, psi, friction_angle(f, model, psi))


def torque_from_angles(force_N: float, d2_m: float, psi_rad: float, phi_rad: float) -> float:
    """Torque to drive the nut, from the lead and friction angles already computed.

    M = F·d2/2 · tan(ψ + φ')

    Parameters
    ----------
    force_N : float
        Axial force on the nut F [N]
    d2_m : float
        Pitch diameter d2 [m]
    psi_rad : float
        Lead angle ψ [rad]
    phi_rad : float
        Reduced friction angle φ' [rad]

    Returns
    -------
    torque_Nm : float
        Torque at the screw M [N·m]

    Examples
    --------
    >>> psi = lead_angle(0.002, 0.015)
    >>> round(torque_from_angles(3500, 0.015, psi, friction_angle(0.15, "standard", psi)), 3)
    5.225

    References
    ----------
    Seed 001, eq. (1).
    """
    return force_N * d2_m / 2.0 * math.tan(psi_rad + phi_rad)


def efficiency(psi_rad: float, phi_rad: float) -> float:
    """Efficiency of the screw driving the nut.

    η = tan ψ / tan(ψ + φ')

    Parameters
    ----------
    psi_rad : float
        Lead angle ψ [rad]
    phi_rad : float
        Reduced friction angle φ' [rad]

    Returns
    -------
    efficiency : float
        Efficiency of the thread, screw driving [-]

    Notes
    -----
    The thread alone, without the thrust face (:func:`thread_efficiency_with_thrust`).

    Examples
    --------
    Seed 001's Tr16x2 with the paper's friction (η = 0.219):

    >>> psi = lead_angle(0.002, 0.015)
    >>> round(efficiency(psi, friction_angle(0.15, "paper", psi)), 3)
    0.219

    References
    ----------
    Ivanov [3], power screws.
    """
    return math.tan(psi_rad) / math.tan(psi_rad + phi_rad)


def back_driving_efficiency(psi_rad: float, phi_rad: float) -> float:
    """Efficiency when the load drives the screw back.

    η' = tan(ψ − φ') / tan ψ

    Parameters
    ----------
    psi_rad : float
        Lead angle ψ [rad]
    phi_rad : float
        Reduced friction angle φ' [rad]

    Returns
    -------
    efficiency : float
        Back-driving efficiency η' [-]; 0 or less means the pair is self-locking

    Examples
    --------
    >>> back_driving_efficiency(0.05, 0.15) < 0
    True

    References
    ----------
    Ivanov [3], power screws.
    """
    return math.tan(psi_rad - phi_rad) / math.tan(psi_rad)


def is_self_locking(psi_rad: float, phi_rad: float) -> bool:
    """Whether a screw–nut holds its load without power.

    self-locking ⇔ ψ < φ'

    Parameters
    ----------
    psi_rad : float
        Lead angle ψ [rad]
    phi_rad : float
        Reduced friction angle φ' [rad]

    Returns
    -------
    self_locking : bool
        True when the load cannot turn the screw [-]

    Notes
    -----
    Judge it at the low end of the pair's friction range to rely on it: the friction
    coefficient of a lubricated pair varies.

    Examples
    --------
    >>> is_self_locking(0.042, 0.154)
    True

    References
    ----------
    Ivanov [3], power screws.
    """
    return psi_rad < phi_rad


def core_equivalent_stress(force_N: float, torque_Nm: float, d3_m: float) -> float:
    """Von Mises stress in the screw core under the axial force and the thread torque.

    σ = 4F/(π·d3²),  τ = 16M/(π·d3³),  σ_eq = √(σ² + 3τ²)

    Parameters
    ----------
    force_N : float
        Axial force F [N]
    torque_Nm : float
        Torque carried by the core M [N·m]
    d3_m : float
        Minor (core) diameter d3 [m]

    Returns
    -------
    stress_Pa : float
        Equivalent stress σ_eq [Pa]

    Notes
    -----
    The core is a round bar of the minor diameter; the thread's stress concentration is
    covered by the safety factor on the yield strength.

    Examples
    --------
    Tr16x2 at 3500 N and 5.085 N·m: σ = 24.45 MPa, τ = 10.53 MPa,
    σ_eq = √(24.45² + 3·10.53²) = 30.50 MPa:

    >>> round(core_equivalent_stress(3500, 5.085, 0.0135) / 1e6, 2)
    30.5

    References
    ----------
    Ivanov [3], power screws: combined core stress.
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
    """Critical axial load of the screw core as a column.

    Euler (λ ≥ λ_c):   P_cr = π²·E·I / (μL)²
    Johnson (λ < λ_c): P_cr = A·(σ_y − (σ_y·λ/(2π))² / E)
    λ = μL/i,  i = d3/4,  λ_c = π·√(2E/σ_y)

    Parameters
    ----------
    d3_m : float
        Minor (core) diameter d3 [m]
    span_m : float
        Length between the supports L [m]
    fixity : str
        End fixity, a key of :data:`END_FIXITY_FACTOR` (μ) [-]
    elastic_modulus_Pa : float
        Young's modulus of the screw steel E [Pa]
    yield_strength_Pa : float
        Yield strength of the screw steel σ_y [Pa]

    Returns
    -------
    critical_load_N : float
        Critical load P_cr [N]
    slenderness : float
        Slenderness ratio λ = μL/i [-]
    formula : str
        'Euler' or 'Johnson'

    Examples
    --------
    Tr16x2 core (d3 = 13.5 mm) between pinned supports 0.4 m apart, steel 45 (E = 210 GPa,
    σ_y = 355 MPa): λ = 400/3.375 = 118.5 > λ_c = 108.1, Euler:
    I = π·13.5⁴/64 = 1630.44 mm⁴, P_cr = π²·210000·1630.44/400² = 21120.5 N.

    >>> p, lam, how = critical_buckling_load(0.0135, 0.4, "pinned-pinned", 210e9, 355e6)
    >>> round(p, 1), round(lam, 1), how
    (21120.5, 118.5, 'Euler')

    References
    ----------
    Shigley [4], ch. 4: columns with central loading.
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
    """Engaged turns for the flank pressure to stay within the allowable one.

    z = F / (π·d2·H1·[p])

    Parameters
    ----------
    force_N : float
        Axial force F [N]
    d2_m : float
        Pitch diameter d2 [m]
    h1_m : float
        Working depth of the thread H1 [m]
    allowable_pressure_Pa : float
        Allowable flank pressure of the pair [p] [Pa]

    Returns
    -------
    turns : float
        Engaged turns z, not rounded [-]

    Examples
    --------
    >>> round(nut_turns_required(3500, 0.015, 0.001, 10e6), 3)
    7.427

    References
    ----------
    Ivanov [3], power screws: nut bearing pressure.
    """
    return force_N / (math.pi * d2_m * h1_m * allowable_pressure_Pa)


def nut_bearing_pressure(force_N: float, d2_m: float, h1_m: float, turns: float) -> float:
    """Flank pressure in the nut.

    p = F / (π·d2·H1·z)

    Parameters
    ----------
    force_N : float
        Axial force F [N]
    d2_m : float
        Pitch diameter d2 [m]
    h1_m : float
        Working depth of the thread H1 [m]
    turns : float
        Engaged turns z [-]

    Returns
    -------
    pressure_Pa : float
        Mean flank pressure p [Pa]

    Notes
    -----
    The load shared evenly by the turns, as the textbook sizing assumes.

    Examples
    --------
    >>> round(nut_bearing_pressure(3500, 0.015, 0.001, 9.0) / 1e6, 3)
    8.252

    References
    ----------
    Ivanov [3], power screws: nut bearing pressure.
    """
    return force_N / (math.pi * d2_m * h1_m * turns)


# ------------------------------------------------------------------ thrust face
def collar_torque(force_N: float, friction_coefficient: float, mean_diameter_m: float) -> float:
    """Friction torque of a plain thrust collar.

    T_c = F·f_c·d_c / 2

    Parameters
    ----------
    force_N : float
        Axial force on the collar F [N]
    friction_coefficient : float
        Friction coefficient of the collar f_c [-]
    mean_diameter_m : float
        Mean collar diameter d_c [m]

    Returns
    -------
    torque_Nm : float
        Friction torque of the collar T_c [N·m]

    Notes
    -----
    Bhandari, «Design of Machine Elements», §6.6, writes μc·W·R_m with R_m = (D_o + D_i)/4,
    the uniform-wear mean radius: the same number.

    Examples
    --------
    Bhandari, Ex. 6.6: W = 2 kN, μc = 0.12, collar 60/100 mm → d_c = 80 mm, 9.6 N·m:

    >>> round(collar_torque(2000, 0.12, 0.080), 6)
    9.6

    References
    ----------
    Shigley, «Mechanical Engineering Design», eq. (8-6).
    """
    return force_N * friction_coefficient * mean_diameter_m / 2.0


def thread_efficiency_with_thrust(
    force_N: float, lead_m: float, thread_torque_Nm: float, thrust_torque_Nm: float
) -> float:
    """Overall efficiency of the screw and its thrust face.

    η = F·L / (2π·(T_thread + T_thrust))

    Parameters
    ----------
    force_N : float
        Axial force F [N]
    lead_m : float
        Lead of the screw L = P·n_s [m]
    thread_torque_Nm : float
        Torque of the thread T_thread [N·m]
    thrust_torque_Nm : float
        Friction torque of the thrust face T_thrust [N·m]

    Returns
    -------
    efficiency : float
        Efficiency of screw and thrust face together [-]

    Examples
    --------
    Bhandari, Ex. 6.6: 2000·8 mm / (2π·19.684 N·m) = 0.1294:

    >>> round(thread_efficiency_with_thrust(2000, 0.008, 10.0841, 9.6), 4)
    0.1294

    References
    ----------
    Shigley, «Mechanical Engineering Design», eqs. (8-4), (8-6).
    """
    return force_N * lead_m / (2.0 * math.pi * (thread_torque_Nm + thrust_torque_Nm))


# ------------------------------------------------------------------ nut wear and heat
def flank_sliding_speed(d2_m: float, speed_rpm: float, psi_rad: float) -> float:
    """Sliding speed of the nut on the flanks, along the helix.

    v_s = π·d2·n / cos ψ

    Parameters
    ----------
    d2_m : float
        Pitch diameter d2 [m]
    speed_rpm : float
        Screw speed n [rpm]
    psi_rad : float
        Lead angle ψ [rad]

    Returns
    -------
    speed_m_s : float
        Sliding speed v_s [m/s]

    Examples
    --------
    Seed 001's Tr16x2 at 1200 rpm (ψ = 2.43°): π·0.015·20/cos ψ = 0.9433 m/s:

    >>> round(flank_sliding_speed(0.015, 1200, math.atan(0.002 / (math.pi * 0.015))), 4)
    0.9433

    References
    ----------
    Shigley, «Mechanical Engineering Design», Table 8-4 (its speeds are sliding speeds).
    """
    return math.pi * d2_m * speed_rpm / 60.0 / math.cos(psi_rad)


#: Safe bearing pressure of a screw–nut pair by sliding speed: Shigley, «Mechanical
#: Engineering Design», 9th/10th ed., Table 8-4 "Screw bearing pressure p_b" (from H. A.
#: Rothbart, «Mechanical Design Handbook»), rows (pair, upper sliding speed in m/min, low
#: and high end of the safe p_b in MPa). The SI rows convert the table's psi and ft/min
#: (2500–3500 psi low speed; 1600–2500 psi ≤ 10 fpm; 1800–2500 psi cast iron ≤ 8 fpm;
#: 800–1400 psi 20–40 fpm; 600–1000 psi cast iron 20–40 fpm; 150–240 psi ≥ 50 fpm).
#: Between the table's speed bands the lower band's value is kept (conservative), and the
#: low end of each range is used. The values could not be verified online (the search found
#: the neighbouring Tables 8-5 and 8-6 but not 8-4): they are the printed table as recalled
#: and are marked so in the report.
SHIGLEY_BEARING_PRESSURE: dict[str, tuple[tuple[float, float, float], ...]] = {
    # steel screw on a bronze nut: "low speed", ≤ 3 m/min, 6–12 m/min, ≥ 15 m/min
    "bronze": ((0.6, 17.2, 24.1), (3.0, 11.0, 17.2), (12.0, 5.5, 9.7), (math.inf, 1.0, 1.7)),
    # steel screw on a cast-iron nut: ≤ 2.4 m/min, 6–12 m/min (none given above)
    "cast_iron": ((2.4, 12.4, 17.2), (12.0, 4.1, 6.9)),
}


def shigley_bearing_pressure(nut: str, sliding_speed_m_s: float) -> tuple[float, str]:
    """The safe flank pressure of a screw–nut pair at a sliding speed, and its row.

    p_safe = the low end of the table's range in the speed band of v_s

    Parameters
    ----------
    nut : str
        Nut material, a key of :data:`SHIGLEY_BEARING_PRESSURE` ('bronze', 'cast_iron')
    sliding_speed_m_s : float
        Flank sliding speed v_s [m/s]

    Returns
    -------
    pressure_Pa : float
        Safe flank pressure [Pa]; 0 above the last speed band the table gives for the nut
    row : str
        The table's row in words

    Notes
    -----
    Between the table's speed bands the lower band's value is kept (conservative). Raises
    KeyError for a nut material the table lacks. The table's values could not be verified
    online: they are the printed table as recalled.

    Examples
    --------
    >>> shigley_bearing_pressure("bronze", 0.94)
    (1000000.0, 'steel–bronze, ≥ 15 m/min: 1–1.7 MPa')
    >>> shigley_bearing_pressure("bronze", 0.15)
    (5500000.0, 'steel–bronze, 6–12 m/min: 5.5–9.7 MPa')

    References
    ----------
    Shigley, «Mechanical Engineering Design», 9th/10th ed., Table 8-4 (from Rothbart,
    «Mechanical Design Handbook»).
    """
    v = sliding_speed_m_s * 60.0
    rows = SHIGLEY_BEARING_PRESSURE[nut]
    lower = 0.0
    for top, lo, hi in rows:
        if v <= top:
            band = (
                "low speed"
                if top < 1
                else f"≥ {lower:g} m/min"
                if top == math.inf
                else f"≤ {top:g} m/min"
                if lower < 1
                else f"{lower:g}–{top:g} m/min"
            )
            name = "bronze" if nut == "bronze" else "cast iron"
            return lo * 1e6, f"steel–{name}, {band}: {lo:g}–{hi:g} MPa"
        lower = 15.0 if top == 12.0 else (6.0 if top in (3.0, 2.4) else top)
    return 0.0, f"steel–{nut.replace('_', ' ')}: above {rows[-1][0]:g} m/min, no safe value"


#: Natural-convection film coefficient of the nut's outer surface in still air, W/(m²·K): the
#: middle of the 10–20 W/(m²·K) range usual for small bodies in air (e.g. Incropera, ch. 9).
NUT_FILM_COEFFICIENT = 15.0
#: Outer diameter of a nut body as a multiple of the thread's nominal diameter (the usual
#: flanged-nut proportion D_n ≈ 1.5·d; an assumption, stated in the report).
NUT_OUTER_DIAMETER_RATIO = 1.5
#: Allowed temperature rise of a lubricated bronze nut: 40 K over a 40 °C ambient keeps the
#: nut at 80 °C, the usual ceiling for mineral-oil and grease lubrication of sliding pairs.
#: A stated design rule, not a value of a verified table.
NUT_ALLOWED_RISE_K = 40.0


def friction_power(torque_Nm: float, speed_rpm: float, efficiency: float) -> float:
    """Power turned into heat in the thread.

    P_f = M·ω·(1 − η),  ω = π·n/30

    Parameters
    ----------
    torque_Nm : float
        Torque at the screw M [N·m]
    speed_rpm : float
        Screw speed n [rpm]
    efficiency : float
        Efficiency of the thread η [-]

    Returns
    -------
    power_W : float
        Friction power P_f [W]

    Examples
    --------
    Seed 001 (5.085 N·m, 1200 rpm, η 0.2191): 499 W:

    >>> round(friction_power(5.085, 1200, 0.2191))
    499

    References
    ----------
    Energy balance of the thread: input power less the power done on the load.
    """
    return torque_Nm * speed_rpm * math.pi / 30.0 * (1.0 - efficiency)


def nut_surface(d_m: float, nut_length_m: float) -> float:
    """Outer surface of the nut body that gives its heat to the air.

    A = π·D_n·l + 2·π/4·(D_n² − d²),  D_n = 1.5·d

    Parameters
    ----------
    d_m : float
        Nominal diameter of the thread d [m]
    nut_length_m : float
        Length of the nut l [m]

    Returns
    -------
    surface_m2 : float
        Cylinder and two annular end faces A [m²]

    Notes
    -----
    D_n = :data:`NUT_OUTER_DIAMETER_RATIO`·d, the usual flanged-nut proportion (an
    assumption, stated in the report).

    Examples
    --------
    Tr16 nut 18 mm long: D_n = 24 mm, π·24·18 + 2·π/4·(24² − 16²) = 1357.2 + 502.7 mm²:

    >>> round(nut_surface(0.016, 0.018) * 1e6)
    1860

    References
    ----------
    Geometry of the nut body.
    """
    dn = NUT_OUTER_DIAMETER_RATIO * d_m
    return math.pi * dn * nut_length_m + 2.0 * math.pi / 4.0 * (dn**2 - d_m**2)


def nut_temperature_rise(mean_power_W: float, surface_m2: float) -> float:
    """Steady temperature rise of the nut.

    ΔT = P̄_f / (h·A)

    Parameters
    ----------
    mean_power_W : float
        Friction power averaged over the cycle P̄_f [W]
    surface_m2 : float
        Outer surface of the nut A [m²]

    Returns
    -------
    rise_K : float
        Steady temperature rise ΔT [K]

    Notes
    -----
    Natural convection with h = :data:`NUT_FILM_COEFFICIENT`; heat carried away by the
    screw and the carriage is neglected, so the estimate errs high.

    Examples
    --------
    10 W through 1860 mm²: 10/(15·0.00186) = 358.4 K:

    >>> round(nut_temperature_rise(10.0, 0.00186), 1)
    358.4

    References
    ----------
    Incropera, «Fundamentals of Heat and Mass Transfer», ch. 9 (the film coefficient).
    """
    return mean_power_W / (NUT_FILM_COEFFICIENT * surface_m2)


# ------------------------------------------------------------------ whirling speed
#: Eigenvalue β·L of the first bending mode of a uniform shaft for the end fixities of
#: :data:`END_FIXITY_FACTOR` (Blevins, «Formulas for Natural Frequency and Mode Shape»,
#: table 8-1: clamped–free 1.87510, pinned–pinned π, clamped–pinned 3.92660,
#: clamped–clamped 4.73004).
WHIRL_EIGENVALUE: dict[str, float] = {
    "fixed-free": 1.87510,
    "pinned-pinned": math.pi,
    "fixed-pinned": 3.92660,
    "fixed-fixed": 4.73004,
}
#: Share of the critical speed a screw may run at (the usual 80 % rule of screw makers'
#: catalogues, e.g. THK and NSK ball-screw selection: permissible speed 0.8·n_cr).
WHIRL_ALLOWED_SHARE = 0.8


def critical_speed_rpm(
    d3_m: float, span_m: float, fixity: str, elastic_modulus_Pa: float, density_kg_m3: float
) -> float:
    """First whirling (critical) speed of the screw core between its supports.

    n_cr = (β·L)²/(2π·L²) · √(E·I/(ρ·A)) · 60,  √(I/A) = d3/4

    Parameters
    ----------
    d3_m : float
        Minor (core) diameter d3 [m]
    span_m : float
        Length between the supports L [m]
    fixity : str
        End fixity, a key of :data:`WHIRL_EIGENVALUE` (β·L) [-]
    elastic_modulus_Pa : float
        Young's modulus of the screw steel E [Pa]
    density_kg_m3 : float
        Density of the screw steel ρ [kg/m³]

    Returns
    -------
    speed_rpm : float
        Critical speed n_cr [rpm]

    Notes
    -----
    A uniform shaft of the core diameter; the screw may run at
    :data:`WHIRL_ALLOWED_SHARE` of it.

    Examples
    --------
    Tr16x2 core (d3 = 13.5 mm) pinned–pinned over 0.4 m, steel (E = 210 GPa,
    ρ = 7850 kg/m³): √(E/ρ) = 5172.2 m/s, d3/4 = 3.375 mm,
    ω = π²·5172.2·0.003375/0.16 = 1076.8 rad/s → 10 283 rpm.

    >>> round(critical_speed_rpm(0.0135, 0.4, "pinned-pinned", 210e9, 7850))
    10283

    References
    ----------
    Blevins, «Formulas for Natural Frequency and Mode Shape», table 8-1.
    """
    beta_l = WHIRL_EIGENVALUE[fixity]
    omega = beta_l**2 / span_m**2 * math.sqrt(elastic_modulus_Pa / density_kg_m3) * d3_m / 4.0
    return omega * 30.0 / math.pi
