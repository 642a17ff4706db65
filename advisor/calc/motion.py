"""Gear ratio for the fastest point-to-point move (seed 003, Trofimuk 1965).

A motor (speed ω0, inertia J0, starting/braking torque M_λ) moves a load (inertia J_p,
resisting torque M_p) through a path α [rad] of the load shaft via a reducer of ratio i.
SI units throughout: rad, rad/s, kg·m², N·m, s.

References
----------
[1] Seed 003 (003_9e41cc3901572aaa.txt): eqs. (1)–(4) move time of a trapezoidal speed graph,
    (6)–(7) the optimum, (8)–(9a) the graphical method i = K·∛A with K = ∛(1/(1 − μ²)²)
    (the OCR prints (I − μ²); it is (1 − μ²), from i⁴(1 − m²/i²)²), (10)–(11) and figs. 4–5
    the intersection of the curves (the method's answer), (12)–(13) engineering units.
"""

import math
from dataclasses import dataclass
from typing import NamedTuple

from advisor.calc.roots import bisect, golden_min

G = 9.80665  # kgf → N, for the engineering units of (12), (13)

#: The ratios searched: a step-up gear of 1000 to a reducer of 10⁶. An optimum outside means
#: a load negligible (or overwhelming) against the motor; it is clamped and reported.
RATIO_MIN = 1e-3
RATIO_MAX = 1e6


class Drive(NamedTuple):
    speed_rad_s: float  # ω0
    inertia_kgm2: float  # J0 (motor and coupling)
    accel_torque_Nm: float  # M_λ, starting and braking
    load_inertia_kgm2: float  # J_p
    load_torque_Nm: float  # M_p

    @property
    def inertia_ratio(self) -> float:
        """I = J_p/J0."""
        return self.load_inertia_kgm2 / self.inertia_kgm2

    @property
    def torque_ratio(self) -> float:
        """m = M_p/M_λ; a ratio must exceed m for the motor to move the load."""
        return self.load_torque_Nm / self.accel_torque_Nm


def transient_time(d: Drive, i: float) -> float:
    """Time spent starting and stopping at ratio i (the two transients of a trapezoidal graph).

        t_j = 2·ω0·J0/M_λ · (i² + I)/(i² − m²),   I = J_p/J0,  m = M_p/M_λ

    Parameters
    ----------
    d : Drive
        Motor speed ω0 [rad/s], motor inertia J0 [kg·m²], starting and braking torque M_λ
        [N·m], load inertia J_p [kg·m²] and load torque M_p [N·m]
    i : float
        Reducer ratio, motor speed over load speed [-], > m = M_p/M_λ

    Returns
    -------
    float
        Start plus stop time t_j [s]

    Notes
    -----
    The motor accelerates with M_λ against M_p/i and brakes with M_λ helped by M_p/i on
    J0 + J_p/i². Valid for i > m (at i ≤ m the motor cannot move the load and t_j is not
    physical).

    References
    ----------
    Seed 003, eq. (3).

    Examples
    --------
    Motor A of seed 003 (150 rad/s, 0.01 kg·m², 20 N·m) on 5 kg·m² and 100 N·m at i = 12:

    >>> round(transient_time(Drive(150.0, 0.01, 20.0, 5.0, 100.0), 12.0), 4)
    0.8118
    """
    m, big_i = d.torque_ratio, d.inertia_ratio
    return (
        2.0 * d.speed_rad_s * d.inertia_kgm2 / d.accel_torque_Nm * (i * i + big_i) / (i * i - m * m)
    )


def transient_path(d: Drive, i: float) -> float:
    """Path of the load shaft covered while starting and stopping at ratio i.

        α_j = ω_p·t_j/2,   ω_p = ω0/i

    Parameters
    ----------
    d : Drive
        Motor speed ω0 [rad/s], motor inertia J0 [kg·m²], starting and braking torque M_λ
        [N·m], load inertia J_p [kg·m²] and load torque M_p [N·m]
    i : float
        Reducer ratio, motor speed over load speed [-], > m = M_p/M_λ

    Returns
    -------
    float
        Path of the two transients α_j [rad] at the load shaft

    Notes
    -----
    A move longer than α_j reaches ω0 and is trapezoidal; a shorter one is triangular. Valid for
    i > m.

    References
    ----------
    Seed 003, eqs. (3)–(4).

    >>> round(transient_path(Drive(150.0, 0.01, 20.0, 5.0, 100.0), 12.0), 4)
    5.0735
    """
    return d.speed_rad_s / i * transient_time(d, i) / 2.0


def move_time_trapezoidal(d: Drive, path_rad: float, i: float) -> float:
    """Time of a move with a trapezoidal speed graph (start, run at ω0, stop).

        t_Σ = α·i/ω0 + ω0·J0/M_λ · (i² + I)/(i² − m²)

    Parameters
    ----------
    d : Drive
        Motor speed ω0 [rad/s], motor inertia J0 [kg·m²], starting and braking torque M_λ
        [N·m], load inertia J_p [kg·m²] and load torque M_p [N·m]
    path_rad : float
        Path of the load shaft α [rad], > 0
    i : float
        Reducer ratio, motor speed over load speed [-], > m = M_p/M_λ

    Returns
    -------
    float
        Move time t_Σ [s]

    Notes
    -----
    Valid while the motor reaches ω0, i.e. α ≥ α_j (:func:`transient_path`), and for i > m.

    References
    ----------
    Seed 003, eq. (4).

    >>> round(move_time_trapezoidal(Drive(150.0, 0.01, 20.0, 5.0, 100.0), 10.0, 12.0), 4)
    1.2059
    """
    return path_rad * i / d.speed_rad_s + transient_time(d, i) / 2.0


def move_time_triangular(d: Drive, path_rad: float, i: float) -> float:
    """Time of a move with a triangular speed graph: the motor accelerates with M_λ − M_p/i and
    brakes with M_λ + M_p/i over the whole path and never reaches ω0.

        θ = α·i = v²/(2a₁) + v²/(2a₂),  t = v/a₁ + v/a₂  ⇒  t = √(2θ·(1/a₁ + 1/a₂)),
        a₁,₂ = (M_λ ∓ M_p/i)/(J0 + J_p/i²)

    Parameters
    ----------
    d : Drive
        Motor speed ω0 [rad/s], motor inertia J0 [kg·m²], starting and braking torque M_λ
        [N·m], load inertia J_p [kg·m²] and load torque M_p [N·m]
    path_rad : float
        Path of the load shaft α [rad], > 0
    i : float
        Reducer ratio, motor speed over load speed [-], > m = M_p/M_λ

    Returns
    -------
    float
        Move time t [s]

    Notes
    -----
    Valid while the peak speed (:func:`triangular_peak_speed`) stays within ω0, i.e. α ≤ α_j,
    and for i > m.

    References
    ----------
    The phases of seed 003, eq. (3), without the run at ω0.

    >>> round(move_time_triangular(Drive(150.0, 0.01, 20.0, 5.0, 100.0), 0.2, 24.4126), 4)
    0.1369
    """
    j = d.inertia_kgm2 + d.load_inertia_kgm2 / (i * i)
    a1 = (d.accel_torque_Nm - d.load_torque_Nm / i) / j
    a2 = (d.accel_torque_Nm + d.load_torque_Nm / i) / j
    return math.sqrt(2.0 * path_rad * i * (1.0 / a1 + 1.0 / a2))


def triangular_peak_speed(d: Drive, path_rad: float, i: float) -> float:
    """Motor speed reached at the middle of a triangular move.

        v = √(2θ·a₁a₂/(a₁ + a₂)),  θ = α·i,  a₁,₂ = (M_λ ∓ M_p/i)/(J0 + J_p/i²)

    Parameters
    ----------
    d : Drive
        Motor speed ω0 [rad/s], motor inertia J0 [kg·m²], starting and braking torque M_λ
        [N·m], load inertia J_p [kg·m²] and load torque M_p [N·m]
    path_rad : float
        Path of the load shaft α [rad], > 0
    i : float
        Reducer ratio, motor speed over load speed [-], > m = M_p/M_λ

    Returns
    -------
    float
        Peak motor speed v [rad/s]; the triangular law holds while v ≤ ω0

    References
    ----------
    The phases of seed 003, eq. (3).

    >>> round(triangular_peak_speed(Drive(150.0, 0.01, 20.0, 5.0, 100.0), 0.2, 24.4126), 2)
    71.33
    """
    j = d.inertia_kgm2 + d.load_inertia_kgm2 / (i * i)
    a1 = (d.accel_torque_Nm - d.load_torque_Nm / i) / j
    a2 = (d.accel_torque_Nm + d.load_torque_Nm / i) / j
    return math.sqrt(2.0 * path_rad * i * a1 * a2 / (a1 + a2))


def move_time(d: Drive, path_rad: float, i: float) -> tuple[float, str]:
    """The move time that actually happens at ratio i, and which speed graph it is: trapezoidal
    where the path covers the transients (α ≥ α_j), triangular otherwise.

    Parameters
    ----------
    d : Drive
        Motor speed ω0 [rad/s], motor inertia J0 [kg·m²], starting and braking torque M_λ
        [N·m], load inertia J_p [kg·m²] and load torque M_p [N·m]
    path_rad : float
        Path of the load shaft α [rad], > 0
    i : float
        Reducer ratio, motor speed over load speed [-], > m = M_p/M_λ

    Returns
    -------
    tuple[float, str]
        Move time [s] and the graph, ``"trapezoidal"`` or ``"triangular"``

    References
    ----------
    Seed 003, eqs. (3)–(4); :func:`move_time_triangular`.

    >>> t, graph = move_time(Drive(150.0, 0.01, 20.0, 5.0, 100.0), 10.0, 12.0)
    >>> round(t, 4), graph
    (1.2059, 'trapezoidal')
    """
    if path_rad >= transient_path(d, i):
        return move_time_trapezoidal(d, path_rad, i), "trapezoidal"
    return move_time_triangular(d, path_rad, i), "triangular"


def coefficient_a(d: Drive, path_rad: float) -> float:
    """The coefficient A of the optimum condition A·i/(i² − m²)² = 1.

        A = 2·ω0²·J0·(m² + I)/(α·M_λ)

    Parameters
    ----------
    d : Drive
        Motor speed ω0 [rad/s], motor inertia J0 [kg·m²], starting and braking torque M_λ
        [N·m], load inertia J_p [kg·m²] and load torque M_p [N·m]
    path_rad : float
        Path of the load shaft α [rad], > 0

    Returns
    -------
    float
        A [-] (dimensionless; i ≈ ∛A without load torque)

    References
    ----------
    Seed 003, eq. (7).

    >>> coefficient_a(Drive(150.0, 0.01, 20.0, 5.0, 100.0), 10.0)
    1181.25
    """
    m, big_i = d.torque_ratio, d.inertia_ratio
    return (
        2.0 * d.speed_rad_s**2 * d.inertia_kgm2 * (m * m + big_i) / (path_rad * d.accel_torque_Nm)
    )


def optimal_ratio_trapezoidal(d: Drive, path_rad: float) -> float:
    """The ratio of the fastest trapezoidal move: the exact root of A·i/(i² − m²)² = 1 on i > m.

        (i² − m²)²/i = A

    Parameters
    ----------
    d : Drive
        Motor speed ω0 [rad/s], motor inertia J0 [kg·m²], starting and braking torque M_λ
        [N·m], load inertia J_p [kg·m²] and load torque M_p [N·m]
    path_rad : float
        Path of the load shaft α [rad], > 0

    Returns
    -------
    float
        Optimal ratio i [-], clamped to RATIO_MIN … RATIO_MAX

    Notes
    -----
    (i² − m²)²/i is strictly increasing for i > m (its derivative is (i² − m²)(3i² + m²)/i²),
    so the root is unique; it is bracketed and found by bisection. Where the time rises over the
    whole range the smallest ratio searched is returned. Valid for the trapezoidal law only
    (α ≥ α_j at the result; :func:`move_time` tells).

    References
    ----------
    Seed 003, eqs. (6)–(7).

    >>> round(optimal_ratio_trapezoidal(Drive(150.0, 0.01, 20.0, 5.0, 100.0), 10.0), 4)
    12.0031
    """
    a, m = coefficient_a(d, path_rad), d.torque_ratio

    def h(i: float) -> float:
        return (i * i - m * m) ** 2 / i - a

    lo = max(m * (1.0 + 1e-12), RATIO_MIN)
    if h(lo) >= 0:  # the time rises over the whole range: the smallest ratio is fastest
        return lo
    if h(RATIO_MAX) <= 0:
        return RATIO_MAX
    return bisect(h, lo, RATIO_MAX)


def k_factor(mu: float) -> float:
    """The factor K of the seed's graphical method, i = K·∛A.

        K = ∛(1/(1 − μ²)²),  μ = m/i

    Parameters
    ----------
    mu : float
        μ = m/i [-], 0 ≤ μ < 1

    Returns
    -------
    float
        K [-]; 1 … 1.35 for μ = 0 … 0.6, the range of the seed's chart

    Notes
    -----
    The OCR of the seed prints (I − μ²); it is (1 − μ²), from i⁴·(1 − m²/i²)².

    References
    ----------
    Seed 003, eq. (9a).

    >>> round(k_factor(0.0), 3), round(k_factor(0.6), 3)
    (1.0, 1.346)
    """
    return (1.0 / (1.0 - mu * mu) ** 2) ** (1.0 / 3.0)


def graphical_estimate(d: Drive, path_rad: float) -> tuple[float, float, float]:
    """The first step of the seed's graphical method: K read at μ0 = m/∛A.

        i0 = ∛A,  μ0 = m/i0,  i ≈ K(μ0)·i0

    Parameters
    ----------
    d : Drive
        Motor speed ω0 [rad/s], motor inertia J0 [kg·m²], starting and braking torque M_λ
        [N·m], load inertia J_p [kg·m²] and load torque M_p [N·m]
    path_rad : float
        Path of the load shaft α [rad], > 0

    Returns
    -------
    tuple[float, float, float]
        ``(first_step, i0, K(μ0))``: the first-step ratio [-], ∛A [-] and K [-]

    Notes
    -----
    It is not the method's answer (that is the intersection of the curves,
    :func:`graphical_fixed_point`). Where μ0 ≥ 1, i.e. i0 ≤ m, K(μ0) is read off the chart's range
    (μ = 0…0.6) and the first step can fall below m, a ratio at which the motor cannot move the
    load; :func:`first_step_moves_load` tells.

    References
    ----------
    Seed 003, eqs. (8)–(9a), fig. 5.

    >>> [round(x, 4) for x in graphical_estimate(Drive(150.0, 0.01, 20.0, 5.0, 100.0), 10.0)]
    [12.5152, 10.5709, 1.1839]
    """
    i0 = coefficient_a(d, path_rad) ** (1.0 / 3.0)
    k = k_factor(d.torque_ratio / i0)
    return k * i0, i0, k


def first_step_moves_load(d: Drive, first_step: float) -> bool:
    """Whether a ratio exceeds m = M_p/M_λ, the least ratio at which the motor moves the load.

    Parameters
    ----------
    d : Drive
        Motor speed ω0 [rad/s], motor inertia J0 [kg·m²], starting and braking torque M_λ
        [N·m], load inertia J_p [kg·m²] and load torque M_p [N·m]
    first_step : float
        The ratio to test [-]

    Returns
    -------
    bool
        True where first_step > m

    References
    ----------
    Seed 003, eq. (3) (the acceleration M_λ − M_p/i must be positive).

    >>> first_step_moves_load(Drive(150.0, 0.01, 20.0, 5.0, 100.0), 4.0)
    False
    """
    return first_step > d.torque_ratio


class FixedPoint(NamedTuple):
    ratio: float  # i = K1·i0
    k: float  # K1
    mu: float  # μ1 = m/i


def graphical_fixed_point(d: Drive, path_rad: float) -> FixedPoint:
    """The answer of the seed's graphical method: the intersection of K = φ(μ) (eq. (9a)) and
    μ = f(μ0, K) (eqs. (10), (10a)), read in figs. 4 and 5 to ΔK/2 = 1 %; here exactly.

    With i = K·i0 and m = μ0·i0 the curve f is μ = μ0/K, and φ is K = (1 − μ²)^(−2/3). At the
    intersection K^(3/2)·(1 − μ0²/K²) = 1, i.e. with x = √K

        x⁴ − x − μ0² = 0,

    whose left side rises for x ≥ 1 (derivative 4x³ − 1 > 0) from −μ0² at x = 1 to
    (1 + μ0)⁴ − 1 − μ0 − μ0² ≥ 0 at x = 1 + μ0: one root, bracketed and found by bisection
    (on y = x − 1, to keep the precision of a small μ0).

    Parameters
    ----------
    d : Drive
        Motor speed ω0 [rad/s], motor inertia J0 [kg·m²], starting and braking torque M_λ
        [N·m], load inertia J_p [kg·m²] and load torque M_p [N·m]
    path_rad : float
        Path of the load shaft α [rad], > 0

    Returns
    -------
    FixedPoint
        ``ratio`` i = K1·i0 [-], ``k`` K1 [-], ``mu`` μ1 = m/i [-]

    Notes
    -----
    It is the optimum of eq. (6): i³·(1 − μ²)² = A is (i² − m²)²/i = A, so it equals
    :func:`optimal_ratio_trapezoidal` (a test checks it to 1e-12).

    References
    ----------
    Seed 003, eqs. (8)–(11), figs. 4–5.

    >>> round(graphical_fixed_point(Drive(150.0, 0.01, 20.0, 5.0, 100.0), 10.0).ratio, 4)
    12.0031
    """
    i0 = coefficient_a(d, path_rad) ** (1.0 / 3.0)
    mu0 = d.torque_ratio / i0
    mu0_sq = mu0 * mu0
    # solved for y = x − 1 ≥ 0, as y·(x³ + x² + x) = μ0², which keeps its precision when
    # μ0 is small (then y ≈ μ0²/3 and x itself would round to 1)
    y = bisect(
        lambda y: y * ((1.0 + y) ** 3 + (1.0 + y) ** 2 + (1.0 + y)) - mu0_sq,
        0.0,
        mu0,
        xtol=1e-16 * min(1.0, mu0_sq),
    )
    k = (1.0 + y) ** 2
    return FixedPoint(k * i0, k, mu0 / k)


def triangular_ratio(d: Drive) -> float:
    """Ratio of the fastest triangular move, counting the load torque (closed form).

    Over the whole path α the motor accelerates with a₁ = (M_λ − M_p/i)/J and brakes with
    a₂ = (M_λ + M_p/i)/J, J = J0 + J_p/i² (the phases of seed 003, eq. (3)). With θ = α·i the
    motor's path, θ = v²/(2a₁) + v²/(2a₂) and t = v/a₁ + v/a₂ give t² = 2θ·(1/a₁ + 1/a₂), and

        1/a₁ + 1/a₂ = J·2M_λ/(M_λ² − M_p²/i²),
        t² = (4α·J0/M_λ) · i·(i² + I)/(i² − m²),   I = J_p/J0, m = M_p/M_λ.

    So t is least where F(i) = i·(i² + I)/(i² − m²) is. F' = 0 gives
    (3i² + I)(i² − m²) − 2i²(i² + I) = 0, i.e. i⁴ − (3m² + I)·i² − I·m² = 0, a quadratic
    in u = i² with one positive root:

        i² = [(3m² + I) + √((3m² + I)² + 4·I·m²)] / 2.

    Parameters
    ----------
    d : Drive
        Motor speed ω0 [rad/s], motor inertia J0 [kg·m²], starting and braking torque M_λ
        [N·m], load inertia J_p [kg·m²] and load torque M_p [N·m]

    Returns
    -------
    float
        Optimal ratio of the triangular law [-], clamped to RATIO_MIN … RATIO_MAX

    Notes
    -----
    Without load torque (m = 0) this is the inertia match i = √I; without load inertia (I = 0)
    it is i = √3·m. The root always exceeds m (i² ≥ 3m²), so the motor moves the load. It does
    not depend on the path; valid while the move stays triangular (peak speed ≤ ω0).

    References
    ----------
    Derived here from the phases of seed 003, eq. (3).

    >>> round(triangular_ratio(Drive(150.0, 0.01, 20.0, 5.0, 100.0)), 4)
    24.4126
    """
    m2, big_i = d.torque_ratio**2, d.inertia_ratio
    b = 3.0 * m2 + big_i
    u = 0.5 * (b + math.sqrt(b * b + 4.0 * big_i * m2))
    return min(max(math.sqrt(u), RATIO_MIN), RATIO_MAX)


def optimal_ratio_triangular(d: Drive, path_rad: float) -> float:
    """The ratio of the fastest triangular move, found numerically: the minimum of
    :func:`move_time_triangular` over i > m.

    Parameters
    ----------
    d : Drive
        Motor speed ω0 [rad/s], motor inertia J0 [kg·m²], starting and braking torque M_λ
        [N·m], load inertia J_p [kg·m²] and load torque M_p [N·m]
    path_rad : float
        Path of the load shaft α [rad], > 0

    Returns
    -------
    float
        Optimal ratio [-] within max(m·(1 + 1e-9), RATIO_MIN) … RATIO_MAX

    Notes
    -----
    Golden-section search on log i; the law is unimodal (it grows without bound as i → m and as
    i → ∞). It agrees with the closed form :func:`triangular_ratio`, which a test checks.

    References
    ----------
    The phases of seed 003, eq. (3).

    >>> round(optimal_ratio_triangular(Drive(150.0, 0.01, 20.0, 5.0, 100.0), 0.2), 4)
    24.4126
    """
    m = d.torque_ratio
    lo = math.log(max(m * (1.0 + 1e-9), RATIO_MIN))
    hi = math.log(RATIO_MAX)
    f = lambda x: move_time_triangular(d, path_rad, math.exp(x))  # noqa: E731
    return math.exp(golden_min(f, lo, hi, iterations=200, xtol=1e-12))


def coefficient_a_engineering(
    n_rpm: float,
    gd2_kgfm2: float,
    accel_torque_kgfm: float,
    revolutions: float,
    m: float,
    big_i: float,
    constant: float = 3600.0 * G / math.pi,
) -> float:
    """The coefficient A in the seed's engineering units.

        A = n²·GD²/(C·M_λ·S)·(m² + I),   C = 3600·g/π ≈ 11238

    Parameters
    ----------
    n_rpm : float
        Motor speed n [rpm]
    gd2_kgfm2 : float
        Flywheel moment of the motor GD² [kgf·m²] (numerically 4·J0 in kg·m²)
    accel_torque_kgfm : float
        Starting and braking torque M_λ [kgf·m]
    revolutions : float
        Path of the load shaft S [revolutions]
    m : float
        M_p/M_λ [-]
    big_i : float
        I = J_p/J0 [-]
    constant : float
        C [-]; the paper prints 11320

    Returns
    -------
    float
        A [-], the same as :func:`coefficient_a` in SI with C = 3600·g/π

    Notes
    -----
    From (7), C = 3600·g/π = 11238; the paper prints 11320 (0.73 % off; its eq. (13) uses the
    consistent 375 = 120·g/π).

    References
    ----------
    Seed 003, eq. (12).

    >>> round(coefficient_a_engineering(1432.39, 0.04, 2.0394, 1.59155, 5.0, 500.0), 1)
    1181.3
    """
    return n_rpm**2 * gd2_kgfm2 / (constant * accel_torque_kgfm * revolutions) * (m * m + big_i)


def move_time_engineering(
    n_rpm: float,
    gd2_kgfm2: float,
    accel_torque_kgfm: float,
    revolutions: float,
    i: float,
    m: float,
    big_i: float,
) -> float:
    """The trapezoidal move time in the seed's engineering units.

        t_Σ = 60·S·i/n + n·GD²/(375·M_λ)·(i² + I)/(i² − m²),   375 = 120·g/π

    Parameters
    ----------
    n_rpm : float
        Motor speed n [rpm]
    gd2_kgfm2 : float
        Flywheel moment of the motor GD² [kgf·m²]
    accel_torque_kgfm : float
        Starting and braking torque M_λ [kgf·m]
    revolutions : float
        Path of the load shaft S [revolutions]
    i : float
        Reducer ratio [-], > m
    m : float
        M_p/M_λ [-]
    big_i : float
        I = J_p/J0 [-]

    Returns
    -------
    float
        Move time t_Σ [s], the same as :func:`move_time_trapezoidal`

    Notes
    -----
    The paper's first term reads 60·S/n; S turns of the load shaft are S·i turns of the motor,
    so the ratio belongs there, as in eq. (4). Valid where the move is trapezoidal.

    References
    ----------
    Seed 003, eq. (13).

    >>> round(move_time_engineering(1432.39, 0.04, 2.0394, 1.59155, 12.0, 5.0, 500.0), 3)
    1.206
    """
    return 60.0 * revolutions * i / n_rpm + n_rpm * gd2_kgfm2 / (
        120.0 * G / math.pi * accel_torque_kgfm
    ) * (i * i + big_i) / (i * i - m * m)


@dataclass(frozen=True, slots=True)
class RatioSolution:
    """A motor's fastest ratio (seed 003): the optimum under the time law asked for, then under
    the law that actually happens, with the seed's estimates beside it."""

    exact_ratio: float  # the optimum under the law asked for
    ratio: float  # the optimum under the law that happens
    estimated_ratio: float  # graphical fixed point (trapezoidal) or closed form (triangular)
    first_step: float  # K(μ0)·∛A, the graphical method's first step
    first_step_moves_load: bool  # whether that first step exceeds m
    ratio_i0: float  # i0 = ∛A
    k_factor: float  # K at the graphical fixed point
    move_time_s: float  # at ``ratio``
    profile: str  # the law that happens at ``ratio``


def happening_profile(d: Drive, path_rad: float, asked: str, i: float) -> str:
    """The speed graph that happens at ratio i, the optimum of the ``asked`` law.

    Trapezoidal where the path covers the transients (α ≥ α_j); but a triangular optimum whose
    path would cover them only if the motor could pass ω0 stays triangular while its peak speed
    (:func:`triangular_peak_speed`) stays within ω0.

    Parameters
    ----------
    d : Drive
        Motor speed ω0 [rad/s], motor inertia J0 [kg·m²], starting and braking torque M_λ
        [N·m], load inertia J_p [kg·m²] and load torque M_p [N·m]
    path_rad : float
        Path of the load shaft α [rad], > 0
    asked : str
        The law the ratio was optimised for, ``"trapezoidal"`` or ``"triangular"``
    i : float
        Reducer ratio, motor speed over load speed [-], > m = M_p/M_λ

    Returns
    -------
    str
        ``"trapezoidal"`` or ``"triangular"``

    References
    ----------
    Seed 003, eqs. (3)–(4).

    >>> A = Drive(150.0, 0.01, 20.0, 5.0, 100.0)
    >>> happening_profile(A, 0.2, "trapezoidal", optimal_ratio_trapezoidal(A, 0.2))
    'triangular'
    """
    actual = "trapezoidal" if path_rad >= transient_path(d, i) else "triangular"
    if asked == "triangular" and actual == "trapezoidal":
        # the triangular optimum would pass ω0: the trapezoidal law governs
        if triangular_peak_speed(d, path_rad, i) <= d.speed_rad_s:
            actual = "triangular"
    return actual


def optimal_ratio(d: Drive, path_rad: float, profile: str) -> float:
    """The fastest ratio under the ``profile`` time law: :func:`optimal_ratio_trapezoidal` or
    :func:`optimal_ratio_triangular`.

    Parameters
    ----------
    d : Drive
        Motor speed ω0 [rad/s], motor inertia J0 [kg·m²], starting and braking torque M_λ
        [N·m], load inertia J_p [kg·m²] and load torque M_p [N·m]
    path_rad : float
        Path of the load shaft α [rad], > 0
    profile : str
        ``"trapezoidal"`` or ``"triangular"``

    Returns
    -------
    float
        Optimal ratio [-]

    References
    ----------
    Seed 003, eq. (6); the triangular law of :func:`move_time_triangular`.
    """
    if profile == "trapezoidal":
        return optimal_ratio_trapezoidal(d, path_rad)
    return optimal_ratio_triangular(d, path_rad)


def solve_ratio(d: Drive, path_rad: float, asked: str) -> RatioSolution:
    """A motor's fastest ratio: the optimum under the asked time law, then under the law that
    actually happens at it (re-optimised where they differ), with the seed's estimate for the
    asked law and the graphical method's first step beside it.

    Parameters
    ----------
    d : Drive
        Motor speed ω0 [rad/s], motor inertia J0 [kg·m²], starting and braking torque M_λ
        [N·m], load inertia J_p [kg·m²] and load torque M_p [N·m]
    path_rad : float
        Path of the load shaft α [rad], > 0
    asked : str
        The speed graph expected, ``"trapezoidal"`` or ``"triangular"``

    Returns
    -------
    RatioSolution
        The exact optimum of the asked law, the ratio of the law that happens [-], the estimate
        (graphical fixed point or closed form) [-], the first step [-] and whether it moves the
        load, i0 = ∛A [-], K at the fixed point [-], the move time [s] and the graph

    References
    ----------
    Seed 003, eqs. (3)–(11), step 8 of its procedure.

    >>> s = solve_ratio(Drive(150.0, 0.01, 20.0, 5.0, 100.0), 0.2, "trapezoidal")
    >>> round(s.exact_ratio, 2), round(s.ratio, 2), s.profile
    (39.37, 24.41, 'triangular')
    """
    first, i0, _ = graphical_estimate(d, path_rad)
    fp = graphical_fixed_point(d, path_rad)
    exact = optimal_ratio(d, path_rad, asked)
    estimate = fp.ratio if asked == "trapezoidal" else triangular_ratio(d)
    actual = happening_profile(d, path_rad, asked, exact)
    i = exact if actual == asked else optimal_ratio(d, path_rad, actual)
    t, happened = move_time(d, path_rad, i)
    return RatioSolution(
        exact_ratio=exact,
        ratio=i,
        estimated_ratio=estimate,
        first_step=first,
        first_step_moves_load=first_step_moves_load(d, first),
        ratio_i0=i0,
        k_factor=fp.k,
        move_time_s=t,
        profile=happened,
    )
