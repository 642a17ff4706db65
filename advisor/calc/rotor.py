"""Drive of an idling high-speed rotor under gyroscopic load (seed 002).

SI units throughout: N, m, rad/s, kg. The bearing friction follows eq. (4) with a rolling
friction coefficient λ (a length); the run-up follows the motion equation (5).

Numbers of the seed's example (7000 CD pair, h = 10 mm) are reproduced in
``tests/test_golden_seed002.py``.
"""

import functools
import math
from dataclasses import dataclass
from typing import NamedTuple

from advisor.calc.roots import brent

G = 9.80665
BALL_DENSITY_kg_m3 = 7850.0
#: F_H ≈ 1.58·F_r·tan β: the recommended axial preload of a pair (seed 002, after eq. (4)).
PRELOAD_FACTOR = 1.58


class BallSet(NamedTuple):
    """The geometry eq. (4) needs, in metres and radians."""

    pitch_radius_m: float  # r of eq. (3): ball centre to the axis
    ball_diameter_m: float  # D_ш
    balls: int  # z
    contact_angle_rad: float  # β

    @property
    def inner_raceway_radius_m(self) -> float:
        """r_B of eq. (4)."""
        return self.pitch_radius_m - self.ball_diameter_m / 2.0


class Loads(NamedTuple):
    """Forces on one bearing, N."""

    radial_N: float
    axial_N: float  # preload included
    centrifugal_N: float  # per ball


class FrictionParts(NamedTuple):
    """The three terms of eq. (4) for one bearing, N·m."""

    radial_Nm: float
    axial_Nm: float
    centrifugal_Nm: float

    @property
    def total_Nm(self) -> float:
        return self.radial_Nm + self.axial_Nm + self.centrifugal_Nm


def gyroscopic_moment(angular_momentum: float, slew_rate: float, axis_angle_rad: float) -> float:
    """M = H·Ω·sin α (seed 002, the equation before (1))."""
    return angular_momentum * slew_rate * math.sin(axis_angle_rad)


def reaction_forces(
    moment: float, pitch_radius: float, plane_to_cg: float, phase_rad: float = 0.0
) -> tuple[float, float]:
    """Axial and radial components of the gyroscopic reaction on a ball (seed 002, eq. (3)).

    ``phase_rad`` is ωt of eq. (3); the design value is at ωt = 0, where the ball lies in the
    plane normal to the moment.

    >>> fa, fr = reaction_forces(10.0, 0.0066, 0.010)
    >>> round(fa, 1), round(fr, 1)
    (459.7, 696.6)
    """
    c = math.cos(phase_rad)
    den = pitch_radius**2 * c * c + plane_to_cg**2
    return moment * pitch_radius * c * c / den, moment * plane_to_cg * c / den


def preload(radial_force: float, contact_angle_rad: float) -> float:
    """Axial preload F_H ≈ 1.58·F_r·tan β, F_r with every radial component (seed 002)."""
    return PRELOAD_FACTOR * radial_force * math.tan(contact_angle_rad)


def ball_mass(ball_diameter: float, density: float = BALL_DENSITY_kg_m3) -> float:
    return density * math.pi / 6.0 * ball_diameter**3


def cage_speed(shaft_speed: float, balls: BallSet) -> float:
    """Orbit speed of the balls with the inner ring turning, rad/s (rolling kinematics)."""
    gamma = balls.ball_diameter_m * math.cos(balls.contact_angle_rad) / (2 * balls.pitch_radius_m)
    return 0.5 * shaft_speed * (1.0 - gamma)


def centrifugal_force(shaft_speed: float, balls: BallSet) -> float:
    """F_ц on one ball, N: m_ball·ω_c²·r."""
    wc = cage_speed(shaft_speed, balls)
    return ball_mass(balls.ball_diameter_m) * wc * wc * balls.pitch_radius_m


def friction_moment(loads: Loads, balls: BallSet, rolling_friction_m: float) -> FrictionParts:
    """Friction moment of one bearing by eq. (4) of seed 002.

    M = 1.4·F_r·λ·(1 + 2r_B/D) + F_a·λ/sin β·(2r_B/D + cos β) + z·F_ц·λ/cos β·r_B/D
    """
    lam, d = rolling_friction_m, balls.ball_diameter_m
    rb, beta = balls.inner_raceway_radius_m, balls.contact_angle_rad
    return FrictionParts(
        1.4 * loads.radial_N * lam * (1.0 + 2.0 * rb / d),
        loads.axial_N * lam / math.sin(beta) * (2.0 * rb / d + math.cos(beta)),
        balls.balls * loads.centrifugal_N * lam / math.cos(beta) * rb / d,
    )


def bearing_loads(
    rotor_weight_share: float, moment: float, balls: BallSet, plane_to_cg: float, speed: float
) -> Loads:
    """Loads on one bearing: its share of the weight plus the gyroscopic reaction at ωt = 0,
    with the preload sized on all radial components (seed 002)."""
    f_ax, f_rad = reaction_forces(moment, balls.pitch_radius_m, plane_to_cg)
    radial = rotor_weight_share + f_rad
    return Loads(
        radial,
        preload(radial, balls.contact_angle_rad) + f_ax,
        centrifugal_force(speed, balls),
    )


# ------------------------------------------------------------------ aerodynamic drag
class CupGeometry(NamedTuple):
    """Rotor cup of eq. (5): outer and inner radii and lengths, m; air density and viscosity."""

    outer_radius_m: float
    outer_length_m: float
    inner_radius_m: float
    inner_length_m: float
    air_density_kg_m3: float
    air_viscosity_m2_s: float


def aero_torque_cup(speed: float, cup: CupGeometry) -> float:
    """Aerodynamic drag torque of the cup, N·m (seed 002, last term of eq. (5)).

    1.06·π·ρ·ω²·(R_o⁴·l_o + R_i⁴·l_i + 0.4·R_o⁵)·√(ν/(ω·R_o²))
    """
    if speed <= 0.0:
        return 0.0
    ro = cup.outer_radius_m
    shape = ro**4 * cup.outer_length_m + cup.inner_radius_m**4 * cup.inner_length_m + 0.4 * ro**5
    return (
        1.06
        * math.pi
        * cup.air_density_kg_m3
        * speed**2
        * shape
        * math.sqrt(cup.air_viscosity_m2_s / (speed * ro * ro))
    )


def aero_coefficient(cup: CupGeometry) -> float:
    """k of M_aero = k·ω^1.5: eq. (5)'s torque grows with ω² · ω^-½."""
    return aero_torque_cup(1.0, cup)


def aero_coefficient_from_loss(loss_W: float, speed: float) -> float:
    """k from a known aerodynamic loss at one speed: P = k·ω^2.5 (same law as eq. (5))."""
    return loss_W / speed**2.5


# ------------------------------------------------------------------ the motion equation (5)
class Rotor(NamedTuple):
    """Everything the motion equation (5) needs; forces per bearing, torques in N·m."""

    inertia_kgm2: float
    bearings: int
    balls: BallSet
    rolling_friction_m: float
    weight_share_N: float  # radial weight on one bearing
    plane_to_cg_m: float
    aero_k: float  # M_aero = aero_k·ω^1.5
    slew_per_speed: float  # M_gyro = slew_per_speed·ω (H = J·ω, Ω·sin α fixed)


def resisting_torque(rotor: Rotor, speed: float, slewing: bool) -> float:
    """Bearing friction of all bearings plus aerodynamic drag at ``speed`` (eq. (5)), term by
    term from the loads; :func:`resistance` gives the same as a polynomial in ω."""
    moment = rotor.slew_per_speed * speed if slewing else 0.0
    loads = bearing_loads(rotor.weight_share_N, moment, rotor.balls, rotor.plane_to_cg_m, speed)
    bearing = friction_moment(loads, rotor.balls, rotor.rolling_friction_m).total_Nm
    return rotor.bearings * bearing + rotor.aero_k * max(speed, 0.0) ** 1.5


class Resistance(NamedTuple):
    """M_res(ω) = a0 + a1·ω + a2·ω² + k·ω^1.5, N·m (eq. (5) with eq. (4)).

    Every load of eq. (4) is a polynomial in ω: the weight is constant, the gyroscopic
    reaction (H = J·ω) and the preload it raises are linear, the centrifugal force is
    quadratic; eq. (4) is linear in the loads, and the aerodynamic term is k·ω^1.5.
    """

    a0: float
    a1: float
    a2: float
    k: float

    def __call__(self, speed):
        """The torque at ``speed`` (a float or a numpy array, ≥ 0)."""
        return self.a0 + speed * (self.a1 + self.a2 * speed) + self.k * speed * speed**0.5

    def at_root(self, v):
        """The torque at ω = v² (v a float or a numpy array): a polynomial in v."""
        v2 = v * v
        return self.a0 + v2 * (self.a1 + self.a2 * v2) + self.k * v2 * v

    def drop(self, speed: float, u):
        """M_res(speed) − M_res(speed − u) for 0 ≤ u ≤ speed (u a float or a numpy array),
        without the cancellation of the plain difference: ω^1.5 − (ω − u)^1.5 =
        u·(3ω² − 3ωu + u²)/(ω^1.5 + (ω − u)^1.5)."""
        rest = speed - u
        cubes = u * (3.0 * speed * (speed - u) + u * u)
        return u * (self.a1 + self.a2 * (speed + rest)) + self.k * cubes / (
            speed * speed**0.5 + rest * rest**0.5
        )

    def slope(self, speed: float) -> float:
        """dM_res/dω at ``speed``."""
        return self.a1 + 2.0 * self.a2 * speed + 1.5 * self.k * math.sqrt(speed)


def resistance(rotor: Rotor, slewing: bool) -> Resistance:
    """The coefficients of :class:`Resistance` for ``rotor``, with or without the slew."""
    n, balls, lam = rotor.bearings, rotor.balls, rotor.rolling_friction_m
    # the loads at ω = 0, the part proportional to ω (the reaction to a moment of
    # slew_per_speed, with its preload) and the part proportional to ω² (centrifugal)
    still = bearing_loads(rotor.weight_share_N, 0.0, balls, rotor.plane_to_cg_m, 0.0)
    per_speed = (
        bearing_loads(0.0, rotor.slew_per_speed, balls, rotor.plane_to_cg_m, 0.0)
        if slewing
        else Loads(0.0, 0.0, 0.0)
    )
    per_speed2 = Loads(0.0, 0.0, centrifugal_force(1.0, balls))
    return Resistance(
        n * friction_moment(still, balls, lam).total_Nm,
        n * friction_moment(per_speed, balls, lam).total_Nm,
        n * friction_moment(per_speed2, balls, lam).total_Nm,
        rotor.aero_k,
    )


@dataclass(frozen=True, slots=True)
class GyroscopicLoads:
    """One bearing's loads and eq. (4) friction without and with the gyroscopic reaction."""

    moment_Nm: float  # M = H·Ω·sin α
    reaction_axial_N: float  # eq. (3) at ωt = 0
    reaction_radial_N: float
    calm: Loads  # without the reaction
    slewing: Loads  # with it
    friction_calm: FrictionParts
    friction_slewing: FrictionParts

    @property
    def preload_N(self) -> float:
        """The preload sized with the reaction (the axial load less the reaction's part)."""
        return self.slewing.axial_N - self.reaction_axial_N


def gyroscopic_loads(rotor: Rotor, moment: float, speed: float) -> GyroscopicLoads:
    """Loads and friction of one bearing at ``speed``, without and with the gyroscopic moment
    ``moment`` (seed 002, eqs. (3), (4))."""
    balls, h, share = rotor.balls, rotor.plane_to_cg_m, rotor.weight_share_N
    f_ax, f_rad = reaction_forces(moment, balls.pitch_radius_m, h)
    calm = bearing_loads(share, 0.0, balls, h, speed)
    slewing = bearing_loads(share, moment, balls, h, speed)
    return GyroscopicLoads(
        moment,
        f_ax,
        f_rad,
        calm,
        slewing,
        friction_moment(calm, balls, rotor.rolling_friction_m),
        friction_moment(slewing, balls, rotor.rolling_friction_m),
    )


@dataclass(frozen=True, slots=True)
class SteadyTorques:
    """The torque that holds the rotor at speed: all bearings' friction plus the drag."""

    aero_Nm: float
    calm_Nm: float  # without the gyroscopic reaction
    slewing_Nm: float  # with it


def steady_torques(rotor: Rotor, loads: GyroscopicLoads, speed: float) -> SteadyTorques:
    """The resisting torque of eq. (5) at ``speed``, without and with the reaction."""
    aero = rotor.aero_k * speed**1.5
    return SteadyTorques(
        aero,
        rotor.bearings * loads.friction_calm.total_Nm + aero,
        rotor.bearings * loads.friction_slewing.total_Nm + aero,
    )


# ------------------------------------------------------------------ quadrature of eq. (5)
#: Gauss–Legendre nodes per panel. The integrands below are analytic with their nearest
#: singularity at least a panel's width away, so 16 nodes give about 1e-15 (the error falls
#: like ρ^-32 with ρ ≥ 3 for every panel used here).
GL_NODES = 16
#: Width of a panel in s = ln(ω − ω'): the integrand's poles lie π off the real axis there.
LOG_PANEL = 2.0


@functools.cache
def _gauss_legendre() -> tuple:
    import numpy as np

    x, w = np.polynomial.legendre.leggauss(GL_NODES)
    return x, w


@functools.cache
def _unit_panels(panels: int, first: float = 0.0) -> tuple:
    """Nodes and weights on [0, 1] of ``panels`` Gauss–Legendre panels, flat: equal panels, or
    with ``first`` > 0 a first panel [0, first] and one more up to 1. Read only."""
    import numpy as np

    x, w = _gauss_legendre()
    edges = np.array([0.0, first, 1.0]) if first else np.linspace(0.0, 1.0, panels + 1)
    half = 0.5 * np.diff(edges)[:, None]
    nodes, weights = (
        (0.5 * (edges[:-1] + edges[1:])[:, None] + half * x).ravel(),
        (half * w).ravel(),
    )
    nodes.flags.writeable = weights.flags.writeable = False
    return nodes, weights


def _segments(lo, hi):
    """Nodes and weights of one Gauss–Legendre panel on each [lo[i], hi[i]] (arrays)."""
    x, w = _gauss_legendre()
    half = 0.5 * (hi - lo)[:, None]
    return 0.5 * (hi + lo)[:, None] + half * x, half * w


def _time_between(res: Resistance, j: float, drive_torque: float, w0, w1):
    """∫ J dω/(M − M_res(ω)) from each w0[i] to w1[i] (numpy arrays of speeds ≥ 0), in
    v = √ω, where M_res is a polynomial: J·2v dv/(M − M_res(v²))."""
    import numpy as np

    v, wt = _segments(np.sqrt(w0), np.sqrt(w1))
    return (wt * (2.0 * j) * v / (drive_torque - res.at_root(v))).sum(axis=1)


def _run_up_integral(res: Resistance, j: float, drive_torque: float, speed: float) -> float:
    """t = ∫₀^ω J dω'/(M − M_res(ω')) with M > M_res(ω): see :func:`run_up_time`."""
    import numpy as np

    delta = drive_torque - res(speed)
    half = 0.5 * speed
    # lower half in v = √ω' on two panels, [0, ½√(ω/2)] and up to √(ω/2): the integrand
    # varies by at most a factor of two there
    top = math.sqrt(half)
    nodes, weights = _unit_panels(2, 0.5)
    v = top * nodes
    lower = float(np.dot(weights, v / (drive_torque - res.at_root(v)))) * 2.0 * j * top
    slope = res.slope(speed)
    sliver = speed * 1e-3 if slope <= 0.0 else min(speed * 1e-3, 1e-6 * delta / slope)
    # upper half in s = ln(ω − ω'): J·e^s/(M − M_res(ω − e^s)), smooth however small δ is;
    # M − M_res(ω − u) taken as δ + (M_res(ω) − M_res(ω − u)) against cancellation
    s0, s1 = math.log(sliver), math.log(half)
    nodes, weights = _unit_panels(max(1, math.ceil((s1 - s0) / LOG_PANEL)))
    u = np.exp(s0 + (s1 - s0) * nodes)
    upper = float(np.dot(weights, u / (delta + res.drop(speed, u)))) * j * (s1 - s0)
    # the last sliver, where M − M_res ≈ δ + slope·(ω − ω'), in closed form
    last = j * sliver / delta if slope <= 0.0 else j / slope * math.log1p(slope * sliver / delta)
    return lower + upper + last


def run_up_time(rotor: Rotor, drive_torque: float, speed: float, slewing: bool = False) -> float:
    """Time to reach ``speed`` from rest at a constant drive torque, s; inf if it never does.

    Eq. (5) is separable: t = ∫₀^ω J dω / (M − M_res(ω)) (the tests compare it with
    solve_ivp). The resistance rises with speed, so the integrand peaks at the top, where it
    nears 1/δ, δ = M − M_res(ω): the upper half is integrated in s = ln(ω − ω'), in which it is
    smooth however small δ is, and the last sliver (M − M_res ≈ δ + slope·(ω − ω') there) in
    closed form; the lower half in v = √ω', where M_res is a polynomial. Both by
    Gauss–Legendre panels, vectorised.
    """
    res = resistance(rotor, slewing)
    if drive_torque - res(speed) <= 0.0:
        return math.inf
    return _run_up_integral(res, rotor.inertia_kgm2, drive_torque, speed)


def torque_for_run_up(rotor: Rotor, speed: float, time_s: float, slewing: bool = False) -> float:
    """The constant drive torque that reaches ``speed`` in ``time_s`` (root finding on eq. (5)).

    The time grows like ln(1/(M − M_res(ω))) as the torque nears the resistance at speed, so
    the root is sought in x = ln(M − M_res(ω)), where the time is a smooth function.
    """
    res, j = resistance(rotor, slewing), rotor.inertia_kgm2
    resist = res(speed)

    def excess(x: float) -> float:
        return _run_up_integral(res, j, resist + math.exp(x), speed) - time_s

    lo = math.log(resist * 1e-12 + 1e-300)
    if excess(lo) <= 0.0:
        # the time allows a torque within 1e-12 of the resistance at speed: that is the answer
        return resist + math.exp(lo)
    hi = math.log(max(resist, 2.0 * j * speed / time_s))
    while excess(hi) > 0.0:
        hi += math.log(2.0)
    x = brent(excess, lo, hi, xtol=1e-12)
    for _ in range(60):  # land on the side that meets the time
        if excess(x) <= 0.0:
            break
        x += 1e-9 * max(1.0, abs(x))
    return resist + math.exp(x)


def _segment_time(rotor: Rotor, drive_torque: float, w0: float, w1: float, slewing: bool) -> float:
    """∫ J dω/(M − M_res(ω)) from w0 to w1 (eq. (5)); positive for a run-up (w1 > w0, M above
    the resistance) and for a run-down (w1 < w0, M below it)."""
    import numpy as np

    res = resistance(rotor, slewing)
    return float(
        _time_between(res, rotor.inertia_kgm2, drive_torque, np.array([w0]), np.array([w1]))[0]
    )


def _cumulative_times(res: Resistance, j: float, drive_torque: float, speeds: list[float]):
    """Times at ``speeds`` from the first, each piece by :func:`_time_between`."""
    import numpy as np

    w = np.asarray(speeds, dtype=float)
    pieces = _time_between(res, j, drive_torque, w[:-1], w[1:])
    return [0.0, *np.cumsum(pieces).tolist()]


def run_up_curve(
    rotor: Rotor, drive_torque: float, speed: float, points: int = 41
) -> tuple[list[float], list[float]]:
    """Speed against time from rest to ``speed`` at a constant torque (eq. (5)).

    The equation is separable, so the curve is its exact solution t(ω) at ``points`` speeds,
    integrated piece by piece; the last piece is :func:`run_up_time`'s (tests compare the
    curve with solve_ivp's integration in time).
    """
    total = run_up_time(rotor, drive_torque, speed)
    if not math.isfinite(total):
        raise ValueError("the drive torque does not exceed the resistance at the target speed")
    speeds = [speed * k / (points - 1) for k in range(points)]
    times = _cumulative_times(
        resistance(rotor, False), rotor.inertia_kgm2, drive_torque, speeds[:-1]
    )
    times.append(max(total, times[-1]))
    return times, speeds


def slew_response(
    rotor: Rotor, drive_torque: float, speed: float, points: int = 41
) -> tuple[list[float], list[float], float]:
    """Speed against time under a sustained slew from ``speed`` with the drive at its limit
    ``drive_torque`` (the stabiliser saturated): eq. (5) with the gyroscopic term, H = J·ω
    falling with ω. Returns the curve down to within 0.1 % of the speed where the rotor
    settles, and that speed."""
    res = resistance(rotor, True)
    if res(speed) - drive_torque <= 1e-9 * drive_torque:
        # the slew costs nothing measurable: the torque it lacks is within rounding of the
        # resistance (where the balance speed itself would be rounding noise)
        return [0.0], [speed], speed
    settle = balance_speed(rotor, drive_torque, speed, True)
    if speed - settle <= 1e-9 * speed:
        return [0.0], [speed], settle
    drop = speed - settle
    speeds = [speed - drop * (1.0 - 10.0 ** (-3.0 * k / (points - 1))) for k in range(points)]
    times = _cumulative_times(res, rotor.inertia_kgm2, drive_torque, speeds)
    return times, speeds, settle


def speed_after(
    times: list[float], speeds: list[float], rotor: Rotor, drive_torque: float, duration_s: float
) -> float:
    """The speed a slew of ``duration_s`` leaves, from the curve of :func:`slew_response`."""
    if duration_s <= 0.0 or len(times) == 1:
        return speeds[0]
    if duration_s >= times[-1]:
        return speeds[-1]
    k = next(i for i, t in enumerate(times) if t >= duration_s)
    w_hi, t_hi = speeds[k - 1], times[k - 1]
    return brent(
        lambda w: t_hi + _segment_time(rotor, drive_torque, w_hi, w, True) - duration_s,
        speeds[k],
        w_hi,
        xtol=1e-12 * speeds[0] / max(1.0, speeds[0]),
    )


def balance_speed(rotor: Rotor, drive_torque: float, speed: float, slewing: bool) -> float:
    """The speed at which the resistance equals the drive torque (≤ ``speed``): where the rotor
    settles with the drive at its limit."""
    res = resistance(rotor, slewing)

    def excess(w: float) -> float:
        return drive_torque - res(w)

    if excess(speed) >= 0.0:
        return speed
    if excess(0.0) <= 0.0:
        return 0.0
    return brent(excess, 0.0, speed, xtol=1e-9 * speed / max(1.0, speed))


@dataclass(frozen=True, slots=True)
class SlewLoss:
    """Speed lost in a sustained slew with the drive saturated (eq. (5) with the reaction)."""

    drive_torque_Nm: float
    duration_s: float
    time_s: list[float]  # the curve down to the balance speed
    speed_rad_s: list[float]
    balance_speed_rad_s: float
    speed_after_rad_s: float


def slew_loss(rotor: Rotor, drive_torque: float, speed: float, duration_s: float) -> SlewLoss:
    """The speed curve under a sustained slew from ``speed`` at ``drive_torque``, and the speed
    a slew of ``duration_s`` leaves (:func:`slew_response`, :func:`speed_after`)."""
    times, speeds, balance = slew_response(rotor, drive_torque, speed)
    after = speed_after(times, speeds, rotor, drive_torque, duration_s)
    return SlewLoss(drive_torque, duration_s, times, speeds, balance, after)
