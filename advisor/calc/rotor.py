"""Drive of an idling high-speed rotor under gyroscopic load (seed 002).

SI units throughout: N, m, rad/s, kg. The bearing friction follows eq. (4) with a rolling
friction coefficient λ (a length); the run-up follows the motion equation (5).

Numbers of the seed's example (7000 CD pair, h = 10 mm) are reproduced in
``tests/golden/test_golden_seed002.py``.
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
    """The gyroscopic moment on a rotor whose housing turns.

        M = H·Ω·sin α

    Parameters
    ----------
    angular_momentum : float
        Kinetic moment of the rotor H = J·ω [kg·m²/s]
    slew_rate : float
        Angular velocity of the housing Ω [rad/s]
    axis_angle_rad : float
        Angle α between H and Ω [rad]

    Returns
    -------
    float
        Gyroscopic moment M [N·m]

    References
    ----------
    Seed 002, the equation before (1).

    Examples
    --------
    The seed's rotor, H = 1.814 kg·m²/s, slewed at 0.0765 rad/s about a normal axis:

    >>> round(gyroscopic_moment(1.814, 0.0765, math.pi / 2), 4)
    0.1388
    """
    return angular_momentum * slew_rate * math.sin(axis_angle_rad)


def reaction_forces(
    moment: float, pitch_radius: float, plane_to_cg: float, phase_rad: float = 0.0
) -> tuple[float, float]:
    """Axial and radial components of the gyroscopic reaction on a ball.

        F_ax = M·r·cos²ωt/(r²·cos²ωt + h²),   F_rad = M·h·cos ωt/(r²·cos²ωt + h²)

    Parameters
    ----------
    moment : float
        Gyroscopic moment M [N·m]
    pitch_radius : float
        Ball centre to the axis r [m]
    plane_to_cg : float
        Ball plane to the rotor's centre of mass h [m]
    phase_rad : float
        ωt of eq. (3) [rad]; the design value is at ωt = 0, where the ball lies in the plane
        normal to the moment and the force is largest

    Returns
    -------
    tuple[float, float]
        Axial and radial reaction [N]; it does not depend on the number of balls

    References
    ----------
    Seed 002, eq. (3).

    >>> fa, fr = reaction_forces(10.0, 0.0066, 0.010)
    >>> round(fa, 1), round(fr, 1)
    (459.7, 696.6)
    """
    c = math.cos(phase_rad)
    den = pitch_radius**2 * c * c + plane_to_cg**2
    return moment * pitch_radius * c * c / den, moment * plane_to_cg * c / den


def preload(radial_force: float, contact_angle_rad: float) -> float:
    """The recommended axial preload of an angular-contact pair.

        F_H ≈ 1.58·F_r·tan β

    Parameters
    ----------
    radial_force : float
        Radial load F_r with every radial component (weight and reaction) [N]
    contact_angle_rad : float
        Contact angle β [rad]

    Returns
    -------
    float
        Axial preload F_H [N]

    References
    ----------
    Seed 002, after eq. (4), and its conclusion 2 (the preload set with all radial loads).

    >>> round(preload(10.0, math.radians(15.0)), 3)
    4.234
    """
    return PRELOAD_FACTOR * radial_force * math.tan(contact_angle_rad)


def ball_mass(ball_diameter: float, density: float = BALL_DENSITY_kg_m3) -> float:
    """Mass of one steel ball.

        m = ρ·π/6·D³

    Parameters
    ----------
    ball_diameter : float
        Ball diameter D [m]
    density : float
        Ball density ρ [kg/m³]; bearing steel 7850 by default

    Returns
    -------
    float
        Ball mass [kg]

    References
    ----------
    Seed 002, the centrifugal term of eq. (4).

    >>> round(ball_mass(0.00476) * 1e3, 3)
    0.443
    """
    return density * math.pi / 6.0 * ball_diameter**3


def cage_speed(shaft_speed: float, balls: BallSet) -> float:
    """Orbit speed of the balls with the inner ring turning (rolling kinematics).

        ω_c = ω/2·(1 − D·cos β/(2r))

    Parameters
    ----------
    shaft_speed : float
        Speed of the inner ring ω [rad/s]
    balls : BallSet
        Pitch radius r [m], ball diameter D [m], number of balls z [-], contact angle β [rad]

    Returns
    -------
    float
        Cage speed ω_c [rad/s]

    References
    ----------
    Seed 002, the centrifugal term of eq. (4) (the kinematics of a rolling bearing).

    >>> b = BallSet(0.0066, 0.00476, 8, math.radians(15.0))
    >>> round(cage_speed(4453.0, b), 1)
    1451.0
    """
    gamma = balls.ball_diameter_m * math.cos(balls.contact_angle_rad) / (2 * balls.pitch_radius_m)
    return 0.5 * shaft_speed * (1.0 - gamma)


def centrifugal_force(shaft_speed: float, balls: BallSet) -> float:
    """Centrifugal force on one ball orbiting at the cage speed.

        F_ц = m_ball·ω_c²·r

    Parameters
    ----------
    shaft_speed : float
        Speed of the inner ring ω [rad/s]
    balls : BallSet
        Pitch radius r [m], ball diameter D [m], number of balls z [-], contact angle β [rad]

    Returns
    -------
    float
        Centrifugal force per ball F_ц [N]

    References
    ----------
    Seed 002, eq. (4).

    >>> b = BallSet(0.0066, 0.00476, 8, math.radians(15.0))
    >>> round(centrifugal_force(4453.0, b), 2)
    6.16
    """
    wc = cage_speed(shaft_speed, balls)
    return ball_mass(balls.ball_diameter_m) * wc * wc * balls.pitch_radius_m


def friction_moment(loads: Loads, balls: BallSet, rolling_friction_m: float) -> FrictionParts:
    """Friction moment of one bearing: radial, axial and centrifugal terms.

        M = 1.4·F_r·λ·(1 + 2r_B/D) + F_a·λ/sin β·(2r_B/D + cos β) + z·F_ц·λ/cos β·r_B/D

    Parameters
    ----------
    loads : Loads
        Radial load F_r [N], axial load F_a with the preload [N], centrifugal force per ball [N]
    balls : BallSet
        Pitch radius r [m], ball diameter D [m], number of balls z [-], contact angle β [rad]
    rolling_friction_m : float
        Rolling friction coefficient λ [m] (a length; 0.028 mm fits the seed's table)

    Returns
    -------
    FrictionParts
        The three terms [N·m]; ``total_Nm`` their sum

    Notes
    -----
    r_B = r − D/2 is the inner raceway radius. Valid for angular-contact balls (β > 0); the
    seed's table has the centrifugal row at half the printed equation
    (``tests/golden/test_golden_seed002.py``); the printed equation is kept.

    References
    ----------
    Seed 002, eq. (4).

    Examples
    --------
    The seed's 7000 CD (8 balls of 4.76 mm at r = 6.6 mm, β = 15°) without the reaction: the
    radial row of its table, 2.96e-4 N·m:

    >>> b = BallSet(0.0066, 0.00476, 8, math.radians(15.0))
    >>> loads = bearing_loads(0.56 * G / 2, 0.0, b, 0.010, 4453.0)
    >>> round(friction_moment(loads, b, 0.028e-3).radial_Nm * 1e4, 2)
    2.97
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
    """Loads on one bearing: its share of the weight plus the gyroscopic reaction at ωt = 0, with
    the preload sized on all radial components.

        F_r = G_share + F_rad,   F_a = F_H(F_r) + F_ax,   F_ц at the speed

    Parameters
    ----------
    rotor_weight_share : float
        The rotor's weight carried by this bearing [N]
    moment : float
        Gyroscopic moment M [N·m]
    balls : BallSet
        Pitch radius r [m], ball diameter D [m], number of balls z [-], contact angle β [rad]
    plane_to_cg : float
        Ball plane to the centre of mass h [m]
    speed : float
        Rotor speed ω [rad/s], ≥ 0

    Returns
    -------
    Loads
        Radial [N], axial with the preload [N] and centrifugal per ball [N]

    References
    ----------
    Seed 002, eq. (3) and the preload after eq. (4).

    >>> b = BallSet(0.0066, 0.00476, 8, math.radians(15.0))
    >>> [round(x, 3) for x in bearing_loads(0.56 * G / 2, 0.1388, b, 0.010, 4453.0)]
    [12.414, 11.637, 6.16]
    """
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
    """Aerodynamic drag torque of the rotor cup.

        M_aero = 1.06·π·ρ·ω²·(R_o⁴·l_o + R_i⁴·l_i + 0.4·R_o⁵)·√(ν/(ω·R_o²))

    Parameters
    ----------
    speed : float
        Rotor speed ω [rad/s]; 0 or less gives 0
    cup : CupGeometry
        Outer and inner radii and lengths [m], gas density ρ [kg/m³], kinematic viscosity
        ν [m²/s]

    Returns
    -------
    float
        Drag torque [N·m]

    Notes
    -----
    A laminar boundary-layer law (torque ∝ ω^1.5); the seed gives no range of validity.

    References
    ----------
    Seed 002, the last term of eq. (5).

    >>> cup = CupGeometry(0.02, 0.03, 0.01, 0.02, 1.204, 1.516e-5)
    >>> round(aero_torque_cup(4453.0, cup) * 1e3, 4)
    1.4566
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
    """The coefficient k of M_aero = k·ω^1.5 for a cup (eq. (5)'s torque grows with ω²·ω^−½).

    Parameters
    ----------
    cup : CupGeometry
        Outer and inner radii and lengths [m], gas density [kg/m³], kinematic viscosity [m²/s]

    Returns
    -------
    float
        k [N·m·s^1.5], the drag torque at 1 rad/s

    References
    ----------
    Seed 002, eq. (5).

    >>> cup = CupGeometry(0.02, 0.03, 0.01, 0.02, 1.204, 1.516e-5)
    >>> round(aero_coefficient(cup) * 4453.0**1.5, 7) == round(aero_torque_cup(4453.0, cup), 7)
    True
    """
    return aero_torque_cup(1.0, cup)


def aero_coefficient_from_loss(loss_W: float, speed: float) -> float:
    """The coefficient k of M_aero = k·ω^1.5 from a known aerodynamic loss at one speed.

        k = P/ω^2.5   (P = M·ω = k·ω^2.5, the law of eq. (5))

    Parameters
    ----------
    loss_W : float
        Aerodynamic loss P at the speed [W]
    speed : float
        That speed ω [rad/s], > 0

    Returns
    -------
    float
        k [N·m·s^1.5]

    References
    ----------
    Seed 002, eq. (5) and its table (32.15 W at 4453 rad/s).

    >>> round(aero_coefficient_from_loss(32.15, 4453.0) * 4453.0**2.5, 2)
    32.15
    """
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

    @property
    def couple_share(self) -> float:
        """The share 1/⌊n/2⌋ of a support's gyroscopic reaction one bearing carries [-].

        Seed 002's eq. (3) is the force of one contact answering the whole moment, F = M/R
        (fig. 1, "a rotor … in a bearing"), and its example loads each bearing of its pair
        with it: each support takes F(M), so the pair carries 2·M, twice what equilibrium
        needs for one bearing a side (kept as the seed's: conservative). With n bearings, n/2
        a side (duplex sets), the bearings of a support share its force: each takes
        F(M)/(n/2) = F(2·M/n), eq. (3) being linear in M. An
        odd n puts ⌊n/2⌋ on one side, whose bearings then carry F/⌊n/2⌋ each; every bearing
        is taken at that (the larger) share, so the friction of the other side's is
        overstated, never understated. The weight is shared by all n (``weight_share_N``)."""
        return 1.0 / (self.bearings // 2)


def resisting_torque(rotor: Rotor, speed: float, slewing: bool) -> float:
    """Bearing friction of all bearings plus aerodynamic drag at a speed, term by term from the
    loads.

        M_res(ω) = n·M_bearing(ω) + k·ω^1.5

    Parameters
    ----------
    rotor : Rotor
        Inertia J [kg·m²], bearings, ball set, rolling friction λ [m], weight per bearing [N],
        ball plane to centre of mass h [m], drag coefficient k [N·m·s^1.5], and the gyroscopic
        moment per unit of speed J·Ω·sin α [N·m·s]
    speed : float
        Rotor speed ω [rad/s], ≥ 0
    slewing : bool
        With the gyroscopic reaction of a sustained slew (M = J·ω·Ω·sin α) or without

    Returns
    -------
    float
        Resisting torque [N·m]; :func:`resistance` gives the same as a polynomial in ω

    References
    ----------
    Seed 002, eqs. (4), (5).

    >>> b = BallSet(0.0066, 0.00476, 8, math.radians(15.0))
    >>> j = 1.814 / 4453.0
    >>> r = Rotor(j, 2, b, 0.028e-3, 0.56 * G / 2, 0.01, 32.15 / 4453.0**2.5, j * 0.0765)
    >>> round(resisting_torque(r, 4453.0, True), 5)
    0.01935
    """
    moment = rotor.slew_per_speed * speed * rotor.couple_share if slewing else 0.0
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
    """The coefficients of the resisting torque as a polynomial in ω (:class:`Resistance`).

        M_res(ω) = a0 + a1·ω + a2·ω² + k·ω^1.5

    Parameters
    ----------
    rotor : Rotor
        Inertia J [kg·m²], bearings, ball set, rolling friction λ [m], weight per bearing [N],
        ball plane to centre of mass h [m], drag coefficient k [N·m·s^1.5], and the gyroscopic
        moment per unit of speed J·Ω·sin α [N·m·s]
    slewing : bool
        With the gyroscopic reaction of a sustained slew or without

    Returns
    -------
    Resistance
        a0 [N·m], a1 [N·m·s], a2 [N·m·s²], k [N·m·s^1.5]

    Notes
    -----
    The weight is constant, the reaction (H = J·ω) and the preload it raises are linear in ω,
    the centrifugal force is quadratic; eq. (4) is linear in the loads.

    References
    ----------
    Seed 002, eqs. (4), (5).

    >>> b = BallSet(0.0066, 0.00476, 8, math.radians(15.0))
    >>> j = 1.814 / 4453.0
    >>> r = Rotor(j, 2, b, 0.028e-3, 0.56 * G / 2, 0.01, 32.15 / 4453.0**2.5, j * 0.0765)
    >>> round(resistance(r, True)(4453.0), 5)
    0.01935
    """
    n, balls, lam = rotor.bearings, rotor.balls, rotor.rolling_friction_m
    # the loads at ω = 0, the part proportional to ω (the reaction to a moment of
    # slew_per_speed, with its preload) and the part proportional to ω² (centrifugal)
    still = bearing_loads(rotor.weight_share_N, 0.0, balls, rotor.plane_to_cg_m, 0.0)
    per_speed = (
        bearing_loads(
            0.0, rotor.slew_per_speed * rotor.couple_share, balls, rotor.plane_to_cg_m, 0.0
        )
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
    """Loads and friction of one bearing at a speed, without and with the gyroscopic moment.

    Parameters
    ----------
    rotor : Rotor
        Inertia J [kg·m²], bearings, ball set, rolling friction λ [m], weight per bearing [N],
        ball plane to centre of mass h [m], drag coefficient k [N·m·s^1.5], and the gyroscopic
        moment per unit of speed J·Ω·sin α [N·m·s]
    moment : float
        Gyroscopic moment M = H·Ω·sin α [N·m] on the rotor; one bearing answers
        M/⌊n/2⌋ of it (:attr:`Rotor.couple_share`)
    speed : float
        Rotor speed ω [rad/s], ≥ 0

    Returns
    -------
    GyroscopicLoads
        The moment M [N·m], one bearing's axial and radial reaction [N] (eq. (3) for
        M/⌊n/2⌋), the loads without and with it
        (:func:`bearing_loads`) and their friction (:func:`friction_moment`) [N·m]

    References
    ----------
    Seed 002, eqs. (3), (4).

    Examples
    --------
    The seed's table: 12.8e-4 → 54.5e-4 N·m per bearing with the reaction (this model
    19.1e-4 → 60.6e-4: the centrifugal row of the printed eq. (4) is twice the table's):

    >>> b = BallSet(0.0066, 0.00476, 8, math.radians(15.0))
    >>> j = 1.814 / 4453.0
    >>> r = Rotor(j, 2, b, 0.028e-3, 0.56 * G / 2, 0.01, 32.15 / 4453.0**2.5, j * 0.0765)
    >>> g = gyroscopic_loads(r, 0.1388, 4453.0)
    >>> round(g.friction_calm.total_Nm * 1e4, 1), round(g.friction_slewing.total_Nm * 1e4, 1)
    (19.1, 60.6)
    """
    balls, h, share = rotor.balls, rotor.plane_to_cg_m, rotor.weight_share_N
    # one bearing answers its share of a support's force: eq. (3) is each support's (the
    # seed's reading, 2·M over a pair), ⌊n/2⌋ bearings a support
    m_one = moment * rotor.couple_share
    f_ax, f_rad = reaction_forces(m_one, balls.pitch_radius_m, h)
    calm = bearing_loads(share, 0.0, balls, h, speed)
    slewing = bearing_loads(share, m_one, balls, h, speed)
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
    """The torque that holds the rotor at speed: all bearings' friction plus the aerodynamic drag,
    without and with the gyroscopic reaction.

        M_steady = n·M_bearing + k·ω^1.5

    Parameters
    ----------
    rotor : Rotor
        Inertia J [kg·m²], bearings, ball set, rolling friction λ [m], weight per bearing [N],
        ball plane to centre of mass h [m], drag coefficient k [N·m·s^1.5], and the gyroscopic
        moment per unit of speed J·Ω·sin α [N·m·s]
    loads : GyroscopicLoads
        One bearing's friction without and with the reaction [N·m]
    speed : float
        Rotor speed ω [rad/s], ≥ 0

    Returns
    -------
    SteadyTorques
        Drag [N·m], steady torque without and with the reaction [N·m]

    References
    ----------
    Seed 002, eq. (5) at steady speed and its table (required power 43.59 → 80.69 W).

    >>> b = BallSet(0.0066, 0.00476, 8, math.radians(15.0))
    >>> j = 1.814 / 4453.0
    >>> r = Rotor(j, 2, b, 0.028e-3, 0.56 * G / 2, 0.01, 32.15 / 4453.0**2.5, j * 0.0765)
    >>> s = steady_torques(r, gyroscopic_loads(r, 0.1388, 4453.0), 4453.0)
    >>> round(s.calm_Nm * 4453.0, 1), round(s.slewing_Nm * 4453.0, 1)
    (49.2, 86.2)
    """
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
    """Time to reach a speed from rest at a constant drive torque.

        t = ∫₀^ω J dω'/(M − M_res(ω'))

    Parameters
    ----------
    rotor : Rotor
        Inertia J [kg·m²], bearings, ball set, rolling friction λ [m], weight per bearing [N],
        ball plane to centre of mass h [m], drag coefficient k [N·m·s^1.5], and the gyroscopic
        moment per unit of speed J·Ω·sin α [N·m·s]
    drive_torque : float
        Constant drive torque M [N·m]
    speed : float
        Rotor speed ω [rad/s], ≥ 0
    slewing : bool
        With the gyroscopic reaction during the run-up (the housing slewing) or without

    Returns
    -------
    float
        Run-up time [s]; inf where M does not exceed M_res at the speed

    Notes
    -----
    Eq. (5) is separable (the tests compare the quadrature with solve_ivp). The resistance rises
    with speed, so the integrand peaks at the top, where it nears 1/δ, δ = M − M_res(ω): the
    upper half is integrated in s = ln(ω − ω'), in which it is smooth however small δ is, and the
    last sliver (M − M_res ≈ δ + slope·(ω − ω') there) in closed form; the lower half in v = √ω',
    where M_res is a polynomial. Both by Gauss–Legendre panels, vectorised.

    References
    ----------
    Seed 002, eq. (5); the seed's example needs about 0.066 N·m for 30 s.

    >>> b = BallSet(0.0066, 0.00476, 8, math.radians(15.0))
    >>> j = 1.814 / 4453.0
    >>> r = Rotor(j, 2, b, 0.028e-3, 0.56 * G / 2, 0.01, 32.15 / 4453.0**2.5, j * 0.0765)
    >>> round(run_up_time(r, 0.066, 4453.0), 1)
    29.8
    """
    res = resistance(rotor, slewing)
    if drive_torque - res(speed) <= 0.0:
        return math.inf
    return _run_up_integral(res, rotor.inertia_kgm2, drive_torque, speed)


def torque_for_run_up(rotor: Rotor, speed: float, time_s: float, slewing: bool = False) -> float:
    """The constant drive torque that reaches a speed from rest in a given time.

        find M:  ∫₀^ω J dω'/(M − M_res(ω')) = t

    Parameters
    ----------
    rotor : Rotor
        Inertia J [kg·m²], bearings, ball set, rolling friction λ [m], weight per bearing [N],
        ball plane to centre of mass h [m], drag coefficient k [N·m·s^1.5], and the gyroscopic
        moment per unit of speed J·Ω·sin α [N·m·s]
    speed : float
        Rotor speed ω [rad/s], ≥ 0
    time_s : float
        Required run-up time [s], > 0
    slewing : bool
        With the gyroscopic reaction during the run-up or without

    Returns
    -------
    float
        Drive torque M [N·m]; its run-up takes no longer than ``time_s``

    Notes
    -----
    The time grows like ln(1/(M − M_res(ω))) as the torque nears the resistance at speed, so the
    root is sought in x = ln(M − M_res(ω)), where the time is a smooth function (Brent's method).
    Where even a torque within 1e-12 of the resistance meets the time, that torque is returned.

    References
    ----------
    Seed 002, eq. (5) and conclusion 4 (the readiness time sizes the drive): 30 s needs about
    0.066 N·m.

    >>> b = BallSet(0.0066, 0.00476, 8, math.radians(15.0))
    >>> j = 1.814 / 4453.0
    >>> r = Rotor(j, 2, b, 0.028e-3, 0.56 * G / 2, 0.01, 32.15 / 4453.0**2.5, j * 0.0765)
    >>> round(torque_for_run_up(r, 4453.0, 30.0), 4)
    0.0656
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
    """Speed against time from rest to a speed at a constant torque.

    Parameters
    ----------
    rotor : Rotor
        Inertia J [kg·m²], bearings, ball set, rolling friction λ [m], weight per bearing [N],
        ball plane to centre of mass h [m], drag coefficient k [N·m·s^1.5], and the gyroscopic
        moment per unit of speed J·Ω·sin α [N·m·s]
    drive_torque : float
        Constant drive torque M [N·m]
    speed : float
        Rotor speed ω [rad/s], ≥ 0
    points : int
        Number of speeds on the curve, evenly spaced from 0 [-]

    Returns
    -------
    tuple[list[float], list[float]]
        Times [s] and speeds [rad/s]; the last time is :func:`run_up_time`'s

    Notes
    -----
    The equation is separable, so the curve is its exact solution t(ω) at ``points`` speeds,
    integrated piece by piece (tests compare it with solve_ivp's integration in time). Raises
    ValueError where the torque does not exceed the resistance at the speed.

    References
    ----------
    Seed 002, eq. (5).

    >>> b = BallSet(0.0066, 0.00476, 8, math.radians(15.0))
    >>> j = 1.814 / 4453.0
    >>> r = Rotor(j, 2, b, 0.028e-3, 0.56 * G / 2, 0.01, 32.15 / 4453.0**2.5, j * 0.0765)
    >>> t, w = run_up_curve(r, 0.066, 4453.0)
    >>> len(t), round(t[-1], 1), w[-1]
    (41, 29.8, 4453.0)
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
    """Speed against time under a sustained slew with the drive at its limit (the stabiliser
    saturated): eq. (5) with the gyroscopic term, H = J·ω falling with ω.

        J·dω/dt = M − M_res(ω) with the reaction,  from ω0 down towards the balance speed

    Parameters
    ----------
    rotor : Rotor
        Inertia J [kg·m²], bearings, ball set, rolling friction λ [m], weight per bearing [N],
        ball plane to centre of mass h [m], drag coefficient k [N·m·s^1.5], and the gyroscopic
        moment per unit of speed J·Ω·sin α [N·m·s]
    drive_torque : float
        Constant drive torque M [N·m]
    speed : float
        Rotor speed ω [rad/s], ≥ 0
    points : int
        Number of points on the curve [-]

    Returns
    -------
    tuple[list[float], list[float], float]
        Times [s] and speeds [rad/s] down to within 0.1 % of the speed where the rotor settles,
        and that balance speed [rad/s]

    Notes
    -----
    Where the torque lacking is within 1e-9 of the resistance the slew costs nothing measurable:
    one point, the speed itself.

    References
    ----------
    Seed 002, eq. (5).

    >>> b = BallSet(0.0066, 0.00476, 8, math.radians(15.0))
    >>> j = 1.814 / 4453.0
    >>> r = Rotor(j, 2, b, 0.028e-3, 0.56 * G / 2, 0.01, 32.15 / 4453.0**2.5, j * 0.0765)
    >>> t, w, settle = slew_response(r, resisting_torque(r, 4453.0, False), 4453.0)
    >>> round(settle)
    2784
    """
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
    """The speed a slew of a given duration leaves, from the curve of :func:`slew_response`.

    Parameters
    ----------
    times : list[float]
        Times of the slew curve [s]
    speeds : list[float]
        Speeds of the slew curve [rad/s]
    rotor : Rotor
        Inertia J [kg·m²], bearings, ball set, rolling friction λ [m], weight per bearing [N],
        ball plane to centre of mass h [m], drag coefficient k [N·m·s^1.5], and the gyroscopic
        moment per unit of speed J·Ω·sin α [N·m·s]
    drive_torque : float
        Constant drive torque M [N·m]
    duration_s : float
        Duration of the slew [s]

    Returns
    -------
    float
        Speed at the end of the slew [rad/s]; found between the curve's points by Brent's method
        on the time integral of eq. (5)

    References
    ----------
    Seed 002, eq. (5).

    >>> b = BallSet(0.0066, 0.00476, 8, math.radians(15.0))
    >>> j = 1.814 / 4453.0
    >>> r = Rotor(j, 2, b, 0.028e-3, 0.56 * G / 2, 0.01, 32.15 / 4453.0**2.5, j * 0.0765)
    >>> m = resisting_torque(r, 4453.0, False)
    >>> t, w, _ = slew_response(r, m, 4453.0)
    >>> round(speed_after(t, w, r, m, 2.0), 1)
    4412.8
    """
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
    """The speed at which the resistance equals the drive torque: where the rotor settles with the
    drive at its limit.

        M_res(ω_b) = M,   0 ≤ ω_b ≤ ω

    Parameters
    ----------
    rotor : Rotor
        Inertia J [kg·m²], bearings, ball set, rolling friction λ [m], weight per bearing [N],
        ball plane to centre of mass h [m], drag coefficient k [N·m·s^1.5], and the gyroscopic
        moment per unit of speed J·Ω·sin α [N·m·s]
    drive_torque : float
        Constant drive torque M [N·m]
    speed : float
        Rotor speed ω [rad/s], ≥ 0
    slewing : bool
        With the gyroscopic reaction or without

    Returns
    -------
    float
        Balance speed ω_b [rad/s]; ``speed`` where the torque holds it, 0 where it holds none

    References
    ----------
    Seed 002, eq. (5).

    >>> b = BallSet(0.0066, 0.00476, 8, math.radians(15.0))
    >>> j = 1.814 / 4453.0
    >>> r = Rotor(j, 2, b, 0.028e-3, 0.56 * G / 2, 0.01, 32.15 / 4453.0**2.5, j * 0.0765)
    >>> round(balance_speed(r, resisting_torque(r, 4453.0, False), 4453.0, True))
    2784
    """
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
    """The speed curve under a sustained slew at a constant drive torque, and the speed a slew of a
    given duration leaves (:func:`slew_response`, :func:`speed_after`).

    Parameters
    ----------
    rotor : Rotor
        Inertia J [kg·m²], bearings, ball set, rolling friction λ [m], weight per bearing [N],
        ball plane to centre of mass h [m], drag coefficient k [N·m·s^1.5], and the gyroscopic
        moment per unit of speed J·Ω·sin α [N·m·s]
    drive_torque : float
        Constant drive torque M [N·m]
    speed : float
        Rotor speed ω [rad/s], ≥ 0
    duration_s : float
        Duration of one slew [s]; 0: no slew

    Returns
    -------
    SlewLoss
        The torque [N·m], the duration [s], the curve (times [s], speeds [rad/s]), the balance
        speed [rad/s] and the speed after the slew [rad/s]

    References
    ----------
    Seed 002, eq. (5).

    >>> b = BallSet(0.0066, 0.00476, 8, math.radians(15.0))
    >>> j = 1.814 / 4453.0
    >>> r = Rotor(j, 2, b, 0.028e-3, 0.56 * G / 2, 0.01, 32.15 / 4453.0**2.5, j * 0.0765)
    >>> m = resisting_torque(r, 4453.0, False)
    >>> round(slew_loss(r, m, 4453.0, 2.0).speed_after_rad_s, 1)
    4412.8
    """
    times, speeds, balance = slew_response(rotor, drive_torque, speed)
    after = speed_after(times, speeds, rotor, drive_torque, duration_s)
    return SlewLoss(drive_torque, duration_s, times, speeds, balance, after)
