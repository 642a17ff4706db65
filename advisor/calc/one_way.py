"""One-way (irreversible) mechanisms that hold a load with the motor off (seed 004).

Each function sizes one device for a torque M (N·m) at its shaft and returns its outer
diameter, length, mass, moment of inertia (about its own shaft), efficiency while driving and
electrical power drawn while driving. SI inside; millimetres only where the seed's formulas
are written in them (they say so).
"""

import math
from typing import NamedTuple

STEEL_DENSITY = 7800.0  # kg/m³, seed 004
COPPER_RESISTIVITY = 1.75e-8  # Ω·m at 20 °C
MU0 = 4e-7 * math.pi


class Device(NamedTuple):
    type: str
    torque_Nm: float
    outer_diameter_mm: float
    length_mm: float
    mass_kg: float
    inertia_kgm2: float
    efficiency: float
    power_W: float
    basis: str  # what the figures rest on


# ------------------------------------------------------------------ roller clutch
ROLLER_FILL = 0.8  # k_з of the mass formula (seed 004)


class RollerGeometry(NamedTuple):
    roller_diameter_mm: float
    outer_diameter_mm: float
    length_mm: float
    support_height_mm: float  # c of eq. (9)
    star_radius_mm: float  # R of eq. (8)
    star_mass_kg: float
    roller_mass_kg: float
    star_inertia_kgm2: float
    roller_inertia_kgm2: float


def roller_geometry(torque_Nm: float, rollers: int, wedge_angle_deg: float) -> RollerGeometry:
    """Geometry, masses and inertias of a roller irreversible clutch.

        d_p = 0.583·∛(M/z)  (M in N·mm, d in mm),   D = 12·d_p,   L = 1.5·d_p,
        c = d_p·(7·cos α − 1)/2,   R = c + d_p/2,
        m_star = ρ·π·R²·L,   m_roller = ρ·π·(d_p/2)²·L,
        J_star = m_star·R²/2,   J_roller = m_roller·R²

    Parameters
    ----------
    torque_Nm : float
        Torque the clutch carries [N·m], > 0
    rollers : int
        Number of rollers z [-], 3 … 12
    wedge_angle_deg : float
        Wedging angle α [°], 6 … 10 in the seed

    Returns
    -------
    RollerGeometry
        Roller diameter d_p, outer diameter D, length L, support height c and star radius R
        [mm]; star and roller masses [kg]; their inertias about the clutch axis [kg·m²]

    Notes
    -----
    The OCR of eq. (1) lost the cube root; the later (M/z)^(5/3) laws of the seed need it.

    References
    ----------
    Seed 004, eqs. (1)–(9).

    Examples
    --------
    >>> g = roller_geometry(2.0, 6, 8.0)
    >>> round(g.roller_diameter_mm, 3), round(g.outer_diameter_mm, 2)
    (4.042, 48.51)
    """
    dp = 0.583 * (torque_Nm * 1e3 / rollers) ** (1.0 / 3.0)
    big_d, length = 12.0 * dp, 1.5 * dp
    c = dp * (7.0 * math.cos(math.radians(wedge_angle_deg)) - 1.0) / 2.0
    r_star = c + dp / 2.0
    rho = STEEL_DENSITY
    r_m, l_m, rp_m = r_star * 1e-3, length * 1e-3, dp / 2.0 * 1e-3
    m_star = rho * math.pi * r_m**2 * l_m  # (6)
    m_roll = rho * math.pi * rp_m**2 * l_m  # (7)
    return RollerGeometry(
        dp,
        big_d,
        length,
        c,
        r_star,
        m_star,
        m_roll,
        m_star * r_m**2 / 2.0,  # (4)
        m_roll * r_m**2,  # (5)
    )


def roller_clutch(torque_Nm: float, rollers: int = 6, wedge_angle_deg: float = 8.0) -> Device:
    """A roller irreversible clutch sized for a torque.

        m = π·D²/4·L·ρ·k_з,   J = J_star + z·J_roller   (geometry by :func:`roller_geometry`)

    Parameters
    ----------
    torque_Nm : float
        Torque the clutch carries [N·m], > 0
    rollers : int, optional
        Number of rollers z [-], 3 … 12
    wedge_angle_deg : float, optional
        Wedging angle α [°], 6 … 10 in the seed

    Returns
    -------
    Device
        Outer diameter and length [mm], mass [kg] (k_з = ROLLER_FILL), inertia [kg·m²];
        efficiency 1 and power 0: it transmits the torque without slip and draws nothing

    References
    ----------
    Seed 004, eqs. (1)–(9), (3).

    Examples
    --------
    >>> d = roller_clutch(2.0)
    >>> round(d.mass_kg, 4), round(d.inertia_kgm2 * 1e6, 3)
    (0.0699, 3.577)
    """
    g = roller_geometry(torque_Nm, rollers, wedge_angle_deg)
    d_m, l_m = g.outer_diameter_mm * 1e-3, g.length_mm * 1e-3
    mass = math.pi * d_m**2 / 4.0 * l_m * STEEL_DENSITY * ROLLER_FILL
    return Device(
        "roller_clutch",
        torque_Nm,
        g.outer_diameter_mm,
        g.length_mm,
        mass,
        g.star_inertia_kgm2 + rollers * g.roller_inertia_kgm2,
        1.0,
        0.0,
        f"seed 004 eqs. (1)–(9), {rollers} rollers, wedging angle {wedge_angle_deg:g}°",
    )


def roller_collapsed_inertia(torque_Nm: float, rollers: int) -> tuple[float, float]:
    """The seed's collapsed inertia coefficients, kept only as a cross-check.

        J_star = 0.95·ρ·π·(M/z)^(5/3),   J_roller = 15.63·ρ·π·(M/z)^(5/3)
        (M in N·mm, lengths in mm, ρ in kg/mm³ → kg·mm²)

    Parameters
    ----------
    torque_Nm : float
        Torque the clutch carries [N·m], > 0
    rollers : int
        Number of rollers z [-]

    Returns
    -------
    tuple[float, float]
        J_star and J_roller [kg·m²]

    Notes
    -----
    They do not follow from the seed's own geometry (4)–(9), which
    :func:`roller_geometry` computes; the advice never uses them.

    References
    ----------
    Seed 004, eqs. (12), (13).

    Examples
    --------
    >>> j_star, j_roller = roller_collapsed_inertia(2.0, 6)
    >>> round(j_roller / j_star, 2)
    16.45
    """
    k = STEEL_DENSITY * 1e-9 * math.pi * (torque_Nm * 1e3 / rollers) ** (5.0 / 3.0) * 1e-6
    return 0.95 * k, 15.63 * k


# ------------------------------------------------------------------ electromagnetic clutch
class EmClutchDesign(NamedTuple):
    """Proportions of an electromagnetic friction clutch (assumptions, stated in the report)."""

    current_density_A_mm2: float = 3.0
    air_gap_mm: float = 0.3  # δ, both gaps together
    friction: float = 0.3  # f_тр of dry friction surfaces
    reserve: float = 1.5  # k_з, torque reserve
    saturation_T: float = 1.2  # flux density the pole area is sized to
    diameters_mm: tuple[float, ...] = (80.0, 100.0, 120.0, 140.0)  # the seed's fig. 9 range
    friction_radius_share: float = 0.35  # mean friction/coil radius as a share of D
    friction_surfaces: int = 2  # the armature clamped between two faces
    pole_area_share: float = 0.25  # pole area as a share of π·D²/4
    length_share: float = 0.4  # axial length as a share of D
    fill: float = 0.6  # steel and copper fill of the envelope
    armature_share: float = 0.06  # armature disc thickness as a share of D


EM_CLUTCH = EmClutchDesign()


def em_clutch_power(
    torque_Nm: float, diameter_mm: float, p: EmClutchDesign = EM_CLUTCH
) -> tuple[float, float]:
    """Power an electromagnetic friction clutch draws to transmit a torque, and the flux
    density in its poles.

        F = k_з·M/(f·r·n),   Φ = √(2·F·μ0·S),   Iw = Φ·δ/(μ0·S),
        P = ρ·2π·r·(Iw)·j = 2π·j·ρ·δ·√(2·k_з·M·r/(n·f·μ0·S)),   B = √(2·F·μ0/S)

    Parameters
    ----------
    torque_Nm : float
        Torque transmitted M [N·m], > 0
    diameter_mm : float
        Outer diameter of the clutch D [mm]; the friction radius r and the pole area S
        follow from it by the proportions of ``p``
    p : EmClutchDesign, optional
        Current density j, air gap δ, friction f, reserve k_з, surfaces n and proportions

    Returns
    -------
    tuple[float, float]
        Power drawn P [W] and flux density in the poles B [T]

    Notes
    -----
    Valid while B stays below saturation (``p.saturation_T``); the seed writes n = 1, the
    armature clamped between two faces gives n = 2.

    References
    ----------
    Seed 004, eqs. (14)–(19).

    Examples
    --------
    >>> power, b = em_clutch_power(2.0, 80.0)
    >>> round(power, 3), round(b, 3)
    (1.318, 0.598)
    """
    d = diameter_mm * 1e-3
    r = p.friction_radius_share * d
    s = p.pole_area_share * math.pi * d * d / 4.0
    j = p.current_density_A_mm2 * 1e6
    power = (
        2.0
        * math.pi
        * j
        * COPPER_RESISTIVITY
        * p.air_gap_mm
        * 1e-3
        * math.sqrt(2.0 * p.reserve * torque_Nm * r / (p.friction_surfaces * p.friction * MU0 * s))
    )
    force = p.reserve * torque_Nm / (p.friction_surfaces * p.friction * r)
    flux_density = math.sqrt(2.0 * force * MU0 / s)
    return power, flux_density


def em_clutch(torque_Nm: float, p: EmClutchDesign = EM_CLUTCH) -> Device | None:
    """The smallest electromagnetic clutch of the seed's range that carries a torque.

    Tries the diameters of ``p`` (80 … 140 mm, the seed's fig. 9) in order and keeps the first
    whose poles stay below saturation; power by :func:`em_clutch_power`, mass
    π·D²/4·L·ρ·fill, inertia that of the armature disc, m_disc·D²/8.

    Parameters
    ----------
    torque_Nm : float
        Torque transmitted [N·m], > 0
    p : EmClutchDesign, optional
        The clutch's proportions (assumptions, stated in the device's basis)

    Returns
    -------
    Device or None
        The clutch: diameter and length [mm], mass [kg], inertia [kg·m²], efficiency 1,
        power drawn [W]; None when even the largest saturates

    References
    ----------
    Seed 004, eqs. (14)–(19), fig. 9.

    Examples
    --------
    >>> em_clutch(2.0).outer_diameter_mm, em_clutch(500.0)
    (80.0, None)
    """
    for dia in p.diameters_mm:
        power, b = em_clutch_power(torque_Nm, dia, p)
        if b <= p.saturation_T:
            d = dia * 1e-3
            length = p.length_share * d
            mass = math.pi * d * d / 4.0 * length * STEEL_DENSITY * p.fill
            disc = math.pi * d * d / 4.0 * p.armature_share * d * STEEL_DENSITY
            return Device(
                "em_clutch",
                torque_Nm,
                dia,
                length * 1e3,
                mass,
                disc * d * d / 8.0,  # the armature disc turns with the shaft
                1.0,
                power,
                f"seed 004 eqs. (14)–(19), D = {dia:g} mm, j = {p.current_density_A_mm2:g} "
                f"A/mm², δ = {p.air_gap_mm:g} mm, f = {p.friction:g}, k_з = {p.reserve:g}, "
                f"B = {b:.2f} T; mass and inertia from assumed proportions; a clutch-brake: "
                "energised it couples the motor (drawing power_W while the drive moves), "
                "de-energised a spring presses the armature against a fixed face and holds the "
                "load (no power in holds)",
            )
    return None


# ------------------------------------------------------------------ self-locking worm
def worm_efficiency(lead_angle_rad: float, friction_angle_rad: float) -> tuple[float, float]:
    """Driving and back-driven efficiency of a worm pair.

        η = tan γ/tan(γ + φ),   η' = tan(γ − φ)/tan γ

    Parameters
    ----------
    lead_angle_rad : float
        Lead angle of the worm γ [rad], 0 … π/2
    friction_angle_rad : float
        Friction angle φ = atan f [rad]

    Returns
    -------
    tuple[float, float]
        Driving efficiency η [-] and back-driven efficiency η' [-]; η' ≤ 0 (γ ≤ φ): the pair
        is self-locking

    References
    ----------
    Seed 004 (aviation practice: γ < 0.5·φ).

    Examples
    --------
    >>> phi = math.atan(0.1)
    >>> round(worm_efficiency(0.5 * phi, phi)[0], 3)
    0.331
    """
    g, f = lead_angle_rad, friction_angle_rad
    return math.tan(g) / math.tan(g + f), math.tan(g - f) / math.tan(g)


class WormDesign(NamedTuple):
    ratio: float = 40.0  # the seed: best efficiency with self-locking up to q = 40 per stage
    friction: float = 0.1  # reduced friction coefficient, steel worm on bronze wheel
    lead_share: float = 0.5  # γ = 0.5·φ, the aviation margin of the seed
    allowable_contact_MPa: float = 200.0  # tin bronze wheel
    load_factor: float = 1.2


WORM = WormDesign()


def _solid_disc(diameter_mm: float, width_mm: float) -> tuple[float, float]:
    """Mass [kg] and inertia about its axis [kg·m²] of a solid steel disc: ρ·π·d²/4·b, m·d²/8."""
    d, b = diameter_mm * 1e-3, width_mm * 1e-3
    mass = STEEL_DENSITY * math.pi * d * d / 4.0 * b
    return mass, mass * d * d / 8.0


def worm(torque_Nm: float, p: WormDesign = WORM) -> Device:
    """A single-start self-locking worm pair taking a torque on the worm shaft.

        η = tan γ/tan(γ + φ),   γ = lead_share·φ,   q0 = 1/tan γ,
        a = (z2/q0 + 1)·∛((170/((z2/q0)·[σ_H]))²·T2·K)   (a in mm, T2 in N·mm, [σ_H] in MPa)

    Parameters
    ----------
    torque_Nm : float
        Torque on the worm shaft [N·m], > 0
    p : WormDesign, optional
        Ratio z2, friction f, lead share, allowable contact stress [σ_H] [MPa], load factor K

    Returns
    -------
    Device
        Wheel tip diameter and overall length [mm], mass of worm and wheel [kg], inertia at
        the worm shaft J_worm + J_wheel/z2² [kg·m²], driving efficiency η, power 0

    References
    ----------
    Seed 004 (efficiency); the centre distance of worm gears of Chernavsky et al. (ref. [4]
    of the seed); worm and wheel as solid steel discs.

    Examples
    --------
    >>> d = worm(2.0)
    >>> round(d.efficiency, 3), round(d.outer_diameter_mm, 1)
    (0.331, 75.1)
    """
    phi = math.atan(p.friction)
    gamma = p.lead_share * phi
    eta, _ = worm_efficiency(gamma, phi)
    q0 = 1.0 / math.tan(gamma)
    z2 = p.ratio
    t2 = torque_Nm * p.ratio * eta * 1e3
    a = (z2 / q0 + 1.0) * (
        (170.0 / (z2 / q0 * p.allowable_contact_MPa)) ** 2 * t2 * p.load_factor
    ) ** (1.0 / 3.0)
    m = 2.0 * a / (z2 + q0)
    d2, da2 = m * z2, m * (z2 + 2.0)
    d1 = m * q0
    b2 = 0.75 * (d1 + 2.0 * m)
    l1 = (11.0 + 0.06 * z2) * m
    m_wheel, j_wheel = _solid_disc(d2, b2)
    m_worm, j_worm = _solid_disc(d1, l1)
    return Device(
        "worm",
        torque_Nm,
        da2,
        b2 + d1 + 2.0 * m,
        m_wheel + m_worm,
        j_worm + j_wheel / z2**2,
        eta,
        0.0,
        f"single start, q = {z2:g}, f = {p.friction:g}, γ = {math.degrees(gamma):.2f}° = "
        f"{p.lead_share:g}·φ, q0 = {q0:.1f}, a = {a:.1f} mm, m = {m:.2f} mm",
    )


# ------------------------------------------------------------------ inverse-profile gear
class InverseGearDesign(NamedTuple):
    teeth: int = 20
    yield_MPa: float = 400.0  # σ_t of the seed
    width_modules: float = 10.0  # b = (8…15)·m
    pair_efficiency: float = 0.45  # a self-braking pair drives with η < 0.5 (estimate)


INVERSE_GEAR = InverseGearDesign()


def inverse_gear(torque_Nm: float, p: InverseGearDesign = INVERSE_GEAR) -> Device:
    """A cylindrical gear with a braking (inverse) profile sized for a torque.

        m = ∛(M/(σ_t·z))  (M in N·mm, σ_t in MPa → m in mm),   d = m·z,   b = (8 … 15)·m,
        mass = π·d²/4·b·ρ,   J = mass·d²/8

    Parameters
    ----------
    torque_Nm : float
        Torque the gear carries [N·m], > 0
    p : InverseGearDesign, optional
        Teeth z, σ_t [MPa], width in modules, estimated driving efficiency

    Returns
    -------
    Device
        Pitch diameter d and width b [mm], mass [kg], inertia [kg·m²], driving efficiency
        (estimated, below 0.5 when self-braking), power 0

    References
    ----------
    Seed 004 (σ_t = 400 MPa, b = (8 … 15)·m).

    Examples
    --------
    >>> round(inverse_gear(2.0).outer_diameter_mm, 2)
    12.6
    """
    module = (torque_Nm * 1e3 / (p.yield_MPa * p.teeth)) ** (1.0 / 3.0)
    d = module * p.teeth
    b = p.width_modules * module
    mass = math.pi * (d * 1e-3) ** 2 / 4.0 * b * 1e-3 * STEEL_DENSITY
    return Device(
        "inverse_gear",
        torque_Nm,
        d,
        b,
        mass,
        mass * (d * 1e-3) ** 2 / 8.0,
        p.pair_efficiency,
        0.0,
        f"z = {p.teeth}, σ_t = {p.yield_MPa:g} MPa, b = {p.width_modules:g}·m, m = {module:.2f} "
        f"mm; forward efficiency {p.pair_efficiency:g} estimated (below 0.5 when self-braking)",
    )


def size(kind: str, torque_Nm: float, rollers: int = 6) -> Device | None:
    """One device of a given type sized for a torque.

    Parameters
    ----------
    kind : str
        One of :data:`TYPES`: roller_clutch, em_clutch, worm, inverse_gear
    torque_Nm : float
        Torque the device carries where it sits [N·m], > 0
    rollers : int, optional
        Rollers of a roller clutch [-]

    Returns
    -------
    Device or None
        The device (see :func:`roller_clutch`, :func:`em_clutch`, :func:`worm`,
        :func:`inverse_gear`); None for an electromagnetic clutch that saturates

    References
    ----------
    Seed 004.

    Examples
    --------
    >>> size("roller_clutch", 2.0).type
    'roller_clutch'
    """
    if kind == "roller_clutch":
        return roller_clutch(torque_Nm, rollers)
    if kind == "em_clutch":
        return em_clutch(torque_Nm)
    if kind == "worm":
        return worm(torque_Nm)
    return inverse_gear(torque_Nm)


TYPES = ("roller_clutch", "em_clutch", "worm", "inverse_gear")


# ------------------------------------------------------------------ torque through a device
class Passage(NamedTuple):
    """How a holding device at the motor side passes torque between the motor and the load.

    ``efficiency``: driving (the motor gives 1/η times the torque the device passes on).
    ``back_drivable``: whether a load that drives (a torque with the motion) can turn the
    motor through it; the electromagnetic clutch, energised, transmits both ways. A
    self-locking device does not: the motor must drive the load down itself, with
    ``lowering_factor`` times the load's torque, and nothing is regenerated."""

    type: str
    efficiency: float
    back_drivable: bool
    lowering_factor: float
    basis: str


def worm_lowering_factor(p: WormDesign = WORM) -> float:
    """The worm torque that lowers a load, per unit of the load's torque at the worm.

        k = −η' = −tan(γ − φ)/tan γ

    Parameters
    ----------
    p : WormDesign, optional
        Friction f and lead share of the worm

    Returns
    -------
    float
        Lowering factor k [-], ≥ 0 for a self-locking pair (1 at γ = φ/2)

    References
    ----------
    Seed 004, back-driven efficiency of a worm pair.

    Examples
    --------
    >>> round(worm_lowering_factor(), 6)
    1.0
    """
    phi = math.atan(p.friction)
    _, back = worm_efficiency(p.lead_share * phi, phi)
    return -back


def self_braking_lowering_factor(efficiency: float) -> float:
    """The torque that lowers a load through a self-braking pair known only by its driving
    efficiency, per unit of the load's torque.

        η = γ/(γ + φ),   η' = (γ − φ)/γ = 2 − 1/η,   k = −η' = 1/η − 2   (small angles)

    Parameters
    ----------
    efficiency : float
        Driving efficiency η [-], 0 … 1

    Returns
    -------
    float
        Lowering factor k [-], 0 at η ≥ 0.5 (the edge of self-locking)

    References
    ----------
    Seed 004, self-braking gears (small-angle friction model).

    Examples
    --------
    >>> round(self_braking_lowering_factor(0.45), 4)
    0.2222
    """
    return max(0.0, 1.0 / efficiency - 2.0)


def passage(kind: str) -> Passage:
    """How a device of seed 004 passes torque as a part of the chain.

    The roller clutch passes rotation only from its input to its output (the rollers wedge
    when the output drives): self-locking, its release taking only the rollers' friction,
    neglected (lowering factor 0). The worm and the braking-profile gear are self-locking
    gears (:func:`worm_lowering_factor`, :func:`self_braking_lowering_factor`); the
    energised electromagnetic clutch passes torque both ways. The advisor takes it as a
    clutch-brake: seed 004's fig. 4 clutch engages when energised, and de-energised a spring
    presses its armature against a fixed face, which holds the load with no power.

    Parameters
    ----------
    kind : str
        One of :data:`TYPES`

    Returns
    -------
    Passage
        Driving efficiency [-], whether a driving load turns the motor, lowering factor [-]

    References
    ----------
    Seed 004.

    Examples
    --------
    >>> passage("em_clutch").back_drivable, passage("worm").back_drivable
    (True, False)
    """
    if kind == "roller_clutch":
        return Passage(kind, 1.0, False, 0.0, "seed 004: the rollers wedge when the load drives")
    if kind == "em_clutch":
        return Passage(kind, 1.0, True, 0.0, "seed 004: an energised clutch passes both ways")
    if kind == "worm":
        d = worm(1.0)
        return Passage(
            kind,
            d.efficiency,
            False,
            worm_lowering_factor(),
            "seed 004: tan γ/tan(γ + φ) driving, tan(γ − φ)/tan γ ≤ 0 back-driven",
        )
    if kind == "inverse_gear":
        eta = INVERSE_GEAR.pair_efficiency
        return Passage(
            kind,
            eta,
            False,
            self_braking_lowering_factor(eta),
            f"seed 004: self-braking, η {eta:g} estimated; lowering factor 1/η − 2 "
            "(small-angle friction model)",
        )
    raise ValueError(f"unknown one-way device {kind!r}")


#: No device in the chain: torque passes unchanged both ways.
NO_DEVICE = Passage("none", 1.0, True, 0.0, "no device")


def motor_torque_through(p: Passage, torque_Nm: float) -> float:
    """The motor torque that gives a torque on the load side of a device.

        M_motor = T/η            (T ≥ 0, the motor drives)
        M_motor = T·η            (T < 0, a back-drivable device: the load drives the motor)
        M_motor = k·|T|          (T < 0, a self-locking device: the motor drives the load down)

    Parameters
    ----------
    p : Passage
        The device's efficiency η, back-drivability and lowering factor k
    torque_Nm : float
        Torque on the device's load side T [N·m], signed: > 0 with the motion

    Returns
    -------
    float
        Motor torque [N·m]; through a self-locking device nothing is regenerated

    References
    ----------
    Seed 004.

    Examples
    --------
    >>> w = passage("worm")
    >>> round(motor_torque_through(w, 10.0), 2), round(motor_torque_through(w, -10.0), 2)
    (30.2, 10.0)
    """
    if torque_Nm >= 0.0:
        return torque_Nm / p.efficiency
    if p.back_drivable:
        return torque_Nm * p.efficiency
    return p.lowering_factor * -torque_Nm


# ------------------------------------------------------------------ holding with the power off
def self_locking_ratio(kind: str) -> float | None:
    """The lead angle over the friction angle, γ/φ, of a self-locking gear of seed 004:
    below 1 the load cannot drive it back.

        worm:                 γ/φ = lead_share (γ = 0.5·φ, the aviation margin)
        braking-profile gear: η = γ/(γ + φ) (small angles)  ⇒  γ/φ = η/(1 − η)

    Parameters
    ----------
    kind : str
        One of :data:`TYPES`

    Returns
    -------
    float or None
        γ/φ [-]; None for the clutches, which hold by wedging rollers or a spring, not by
        a friction angle

    References
    ----------
    Seed 004 (self-locking worms and braking-profile gears; γ < 0.5·φ in aviation).

    Examples
    --------
    >>> self_locking_ratio("worm"), round(self_locking_ratio("inverse_gear"), 4)
    (0.5, 0.8182)
    """
    if kind == "worm":
        return WORM.lead_share
    if kind == "inverse_gear":
        eta = INVERSE_GEAR.pair_efficiency
        return eta / (1.0 - eta)
    return None


def screw_back_driving_torque(
    force_N: float, d2_m: float, lead_angle_rad: float, friction_angle_rad: float
) -> float:
    """The torque an axial load gives a sliding screw that is not self-locking: what a
    holding device at the screw's shaft must hold with the power off.

        T = F·d2/2·tan(ψ − φ')   (> 0 where ψ > φ': the load drives the screw back)

    Parameters
    ----------
    force_N : float
        Axial load F [N]
    d2_m : float
        Pitch diameter d2 [m]
    lead_angle_rad : float
        Lead angle ψ [rad]
    friction_angle_rad : float
        Reduced friction angle φ' [rad], at the low end of the friction range for a holding

    Returns
    -------
    float
        Back-driving torque T [N·m]; ≤ 0 for a self-locking screw (nothing to hold)

    References
    ----------
    Seed 001 (the thread torque with the load, F·d2/2·tan(φ' − ψ)); seed 004 (holding).

    Examples
    --------
    >>> round(screw_back_driving_torque(3500.0, 0.013, 0.097632, 0.051717), 3)
    1.045
    """
    return force_N * d2_m / 2.0 * math.tan(lead_angle_rad - friction_angle_rad)
