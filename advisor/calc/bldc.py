"""PM brushless motor with concentrated windings: pole/slot sets and losses against speed.

References
----------
[1] Seed 000 (000_e109c3d4c17eaf1c.txt): eq. (1) pole/slot relation; (4) ohmic losses fall
    with the square of the total reduction; (5) iron losses; (9)–(10) the frequency of
    minimum total loss; the worked example (74 mm stator, 500 Hz, 230 W vs 518 W).
[2] Winding factor of tooth-coil windings: k_w = k_p·k_d with k_p = |sin(π·p/z)| and, for k
    adjacent coils of alternating polarity per phase group, k_d = sin(k·γ/2)/(k·sin(γ/2)),
    γ = π − 2π·p/z (e.g. Meier, «Theoretical design of surface-mounted PM machines with
    non-overlapping windings», 2008). Known values: 12s/10p 0.933, 9s/8p 0.945, 12s/8p 0.866.
"""

import functools
import itertools
import math
from typing import NamedTuple


class PoleSlot(NamedTuple):
    slots: int
    poles: int
    teeth_per_group: int
    winding_factor: float

    @property
    def pole_pairs(self) -> int:
        return self.poles // 2


def winding_factor(slots: int, pole_pairs: int, teeth_per_group: int) -> float:
    """Fundamental winding factor of a tooth-coil winding [2].

    Parameters
    ----------
    slots : int
        Stator teeth (slots) z [-]
    pole_pairs : int
        Rotor pole pairs p [-]
    teeth_per_group : int
        Adjacent teeth of one phase group k [-]

    Returns
    -------
    float
        Fundamental winding factor k_w = k_p·k_d [-]

    Notes
    -----
    For tooth-coil (concentrated) windings with alternating coil polarity within a group.

    Examples
    --------
    >>> round(winding_factor(12, 5, 2), 3), round(winding_factor(9, 4, 3), 3)
    (0.933, 0.945)
    """
    alpha = 2.0 * math.pi * pole_pairs / slots  # electrical angle between adjacent teeth
    kp = abs(math.sin(alpha / 2.0))
    k = teeth_per_group
    gamma = math.pi - alpha
    kd = 1.0 if k == 1 else abs(math.sin(k * gamma / 2.0) / (k * math.sin(gamma / 2.0)))
    return kp * kd


@functools.cache  # a table of constants: the same for every frame
def pole_slot_combinations(phases: int = 3, max_slots: int = 36) -> tuple[PoleSlot, ...]:
    """Feasible sets of eq. (1), 2p = z/(m·k)·(k·m ± 1), seed 000.

    z must hold a whole number of phase groups of k teeth (z divisible by m·k), 2p must be
    even, and the winding must be balanced (z / gcd(z, p) divisible by m).

    Parameters
    ----------
    phases : int, optional
        Phases m [-]
    max_slots : int, optional
        Most teeth z enumerated [-]

    Returns
    -------
    tuple of PoleSlot
        Slots, poles, teeth per group and winding factor, by poles then slots
    """
    out = []
    for z in range(phases, max_slots + 1, phases):
        for k in range(1, z // phases + 1):
            if z % (phases * k):
                continue
            groups = z // (phases * k)
            for sign in (+1, -1):
                two_p = groups * (k * phases + sign)
                if two_p <= 0 or two_p % 2 or two_p == z:
                    continue
                p = two_p // 2
                if (z // math.gcd(z, p)) % phases:
                    continue
                out.append(PoleSlot(z, two_p, k, winding_factor(z, p, k)))
    return tuple(sorted(set(out), key=lambda c: (c.poles, c.slots)))


def flux_frequency_Hz(speed_rpm: float, pole_pairs: int) -> float:
    """f = n·p/60. Seed 000: 5000 rpm, p = 6 → 500 Hz.

    Parameters
    ----------
    speed_rpm : float
        Motor speed n [rpm]
    pole_pairs : int
        Pole pairs p (the electrical reduction) [-]

    Returns
    -------
    float
        Flux frequency in the stator f [Hz]

    Examples
    --------
    >>> flux_frequency_Hz(5000, 6)
    500.0
    """
    return speed_rpm * pole_pairs / 60.0


def stator_steel_mass(
    area_mm2: float, stack_length_mm: float, fill: float, density_kg_m3: float
) -> float:
    """m = ρ·S·l·k_з. Seed 000: 7.8 g/cm³ × 12 cm² × 5 cm × 0.85 ≈ 0.4 kg.

    Parameters
    ----------
    area_mm2 : float
        Steel cross-section of the stator S [mm²]
    stack_length_mm : float
        Stack length l [mm]
    fill : float
        Stacking factor k_з [-]
    density_kg_m3 : float
        Steel density ρ [kg/m³]

    Returns
    -------
    float
        Stator steel mass m [kg]

    Examples
    --------
    >>> round(stator_steel_mass(1200, 50, 0.85, 7800), 4)
    0.3978
    """
    return density_kg_m3 * area_mm2 * 1e-6 * stack_length_mm * 1e-3 * fill


def iron_specific_loss_quadratic(p15_50_W_kg: float, frequency_Hz: float) -> float:
    """Specific iron loss at 1.5 T scaled with the square of frequency — seed 000's
    simplification of eq. (5) (hysteresis neglected, the excess term taken ∝ f²):
    P = P1.5/50·(f/50)². Seed 000: 2.5 W/kg at 500 Hz → 250 W/kg.

    Parameters
    ----------
    p15_50_W_kg : float
        Catalog loss of the steel at 1.5 T, 50 Hz P1.5/50 [W/kg]
    frequency_Hz : float
        Flux frequency f [Hz]

    Returns
    -------
    float
        Specific iron loss at 1.5 T [W/kg]

    Notes
    -----
    The seed's simplification; it overstates the loss below 50 Hz and where hysteresis
    dominates. The three-term :func:`fit_eq5` is the fuller model.

    Examples
    --------
    >>> iron_specific_loss_quadratic(2.5, 500)
    250.0
    """
    return p15_50_W_kg * (frequency_Hz / 50.0) ** 2


class SteinmetzTerms(NamedTuple):
    """Coefficients of eq. (5) with C_dc = 1: P = K_h·f·B² + K_c·(f·B)² + K_e·(f·B)^1.5."""

    k_h: float
    k_c: float
    k_e: float

    def specific_loss(self, frequency_Hz: float, induction_T: float) -> float:
        fb = frequency_Hz * induction_T
        return self.k_h * frequency_Hz * induction_T**2 + self.k_c * fb**2 + self.k_e * fb**1.5


def fit_eq5(p10_50: float, p15_50: float, p10_400: float) -> SteinmetzTerms:
    """Fit the three terms of seed 000 eq. (5) to the three catalog losses of a steel
    (P1.0/50, P1.5/50, P1.0/400), solving the 3×3 linear system exactly.

    Parameters
    ----------
    p10_50 : float
        Catalog loss at 1.0 T, 50 Hz [W/kg]
    p15_50 : float
        Catalog loss at 1.5 T, 50 Hz [W/kg]
    p10_400 : float
        Catalog loss at 1.0 T, 400 Hz [W/kg]

    Returns
    -------
    SteinmetzTerms
        K_h [W/(kg·Hz·T²)], K_c [W/(kg·(Hz·T)²)], K_e [W/(kg·(Hz·T)^1.5)] with C_dc = 1

    Notes
    -----
    Exact through the three points; between 50 and 400 Hz and 1.0…1.5 T an interpolation,
    beyond them an extrapolation of eq. (5).

    Examples
    --------
    >>> t = fit_eq5(1.0, 2.5, 17.0)
    >>> round(t.specific_loss(50, 1.5), 6), round(t.specific_loss(400, 1.0), 6)
    (2.5, 17.0)
    """
    rows = [(50.0, 1.0, p10_50), (50.0, 1.5, p15_50), (400.0, 1.0, p10_400)]
    a = [[f * b * b, (f * b) ** 2, (f * b) ** 1.5] for f, b, _ in rows]
    y = [p for _, _, p in rows]
    return SteinmetzTerms(*_solve3(a, y))


def _solve3(a: list[list[float]], y: list[float]) -> list[float]:
    """Cramer's rule for a 3×3 system (no numpy needed for three unknowns)."""

    def det(m: list[list[float]]) -> float:
        return (
            m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
        )

    d = det(a)
    out = []
    for col in range(3):
        m = [row[:] for row in a]
        for r in range(3):
            m[r][col] = y[r]
        out.append(det(m) / d)
    return out


def ohmic_loss(
    reference_loss_W: float, reference_speed_rpm: float, speed_rpm: float, load_ratio: float = 1.0
) -> float:
    """Copper loss of the same stator rewound for another speed, seed 000 eq. (4):
    n times the speed with n times fewer turns of n times the cross-section gives the same
    power at the same current with 1/n² of the loss. ``load_ratio`` = required torque over
    the torque the rewound motor gives at the reference current (loss ∝ current²).

    Seed 000: 70 W at 5000 rpm → 17.5 W at 10000 rpm (the paper rounds to 18 W).

    Parameters
    ----------
    reference_loss_W : float
        Copper loss of the reference winding P_1 [W]
    reference_speed_rpm : float
        Speed of the reference winding n_1 [rpm]
    speed_rpm : float
        Speed of the rewound motor n_2 [rpm]
    load_ratio : float, optional
        Required torque over the rewound motor's torque at the reference current [-]

    Returns
    -------
    float
        Copper loss of the rewound motor P_2 [W]

    Examples
    --------
    >>> round(ohmic_loss(2 * 1.14 * 5.5**2, 5000, 10000), 2)
    17.24
    """
    return reference_loss_W * (reference_speed_rpm / speed_rpm) ** 2 * load_ratio**2


def ohmic_loss_at_torque(
    reference_loss_W: float, reference_torque_Nm: float, torque_Nm: float
) -> float:
    """Copper loss of the frame at a torque, whatever its winding.

    Rewinding the same frame for another speed at the same voltage scales the turns and the
    torque constant as 1/n and the resistance as 1/n², so the current at a torque grows as n
    and I²·R does not change: the loss depends on the torque alone, P = P_ref·(M/M_ref)².
    With the motor torque of a reducer, M ∝ 1/n, this is seed 000's eq. (4), P1/P2 = n², and
    eq. (9), P_om ∝ 1/f².

    Seed 000: 2 · 1.14 Ω · 5.5² A² = 68.97 W at 2.0 N·m; the 10000 rpm motor at 1.0 N·m
    (two parallels, R/4, same 5.5 A) loses a quarter of that.

    Parameters
    ----------
    reference_loss_W : float
        Copper loss at the reference torque P_ref [W]
    reference_torque_Nm : float
        Reference torque M_ref [N·m]
    torque_Nm : float
        Motor torque M [N·m]

    Returns
    -------
    float
        Copper loss P [W]

    Notes
    -----
    The same frame and supply voltage, the winding rewound; temperature effects on the
    resistance neglected.

    Examples
    --------
    >>> ohmic_loss_at_torque(68.97, 2.0, 1.0)
    17.2425
    """
    return reference_loss_W * (torque_Nm / reference_torque_Nm) ** 2


def rewound_current_A(
    reference_current_A: float,
    reference_torque_Nm: float,
    reference_speed_rpm: float,
    torque_Nm: float,
    speed_rpm: float,
) -> float:
    """Phase current of the frame rewound for ``speed_rpm`` at a torque: the torque constant
    falls as 1/n, so I = I_ref·(M/M_ref)·(n/n_ref). A drive-sizing figure, not the frame's
    limit (that is thermal: see :func:`ohmic_loss_at_torque`).

    Seed 000: 1.0 N·m at 10000 rpm needs the reference 5.5 A (2.0 N·m at 5000 rpm).

    Parameters
    ----------
    reference_current_A : float
        Phase current at the reference point I_ref [A]
    reference_torque_Nm : float
        Reference torque M_ref [N·m]
    reference_speed_rpm : float
        Reference speed n_ref [rpm]
    torque_Nm : float
        Motor torque M [N·m]
    speed_rpm : float
        Speed the frame is wound for n [rpm]

    Returns
    -------
    float
        Phase current I [A]

    Notes
    -----
    Seed 000, eq. (4): a winding for n times the speed has n times fewer turns.

    Examples
    --------
    >>> rewound_current_A(5.5, 2.0, 5000, 1.0, 10000)
    5.5
    """
    return (
        reference_current_A * (torque_Nm / reference_torque_Nm) * (speed_rpm / reference_speed_rpm)
    )


def magnet_loss(points: list[tuple[float, float]], speed_rpm: float) -> float:
    """Eddy-current loss in the magnets at a speed, from the reference design's values.

    Between two given points the loss follows the power law through them (log–log
    interpolation); beyond the given points it grows with the square of speed, seed 000's
    stated assumption. The seed's own FEM values (60 W at 5000 rpm, 100 W at 10000 rpm) grow
    as n^0.74, not n², which is why they are data here and not a law. A loss of 0 W (magnets
    that are segmented finely enough, or none at all) has no power law through it: between a
    zero and its neighbour the loss is interpolated linearly, and beyond a zero it stays 0.

    Parameters
    ----------
    points : list of (float, float)
        (speed [rpm], magnet loss [W]) of the reference design
    speed_rpm : float
        Motor speed n [rpm]

    Returns
    -------
    float
        Eddy-current loss in the magnets [W]

    Examples
    --------
    >>> magnet_loss([(5000, 60), (10000, 100)], 10000), magnet_loss([(5000, 60)], 10000)
    (100.0, 240.0)
    >>> magnet_loss([(5000, 0), (10000, 100)], 7500), magnet_loss([(5000, 0.0)], 10000)
    (50.0, 0.0)
    """
    pts = sorted(points)
    if len(pts) == 1 or speed_rpm <= pts[0][0]:
        n0, p0 = pts[0]
        return p0 * (speed_rpm / n0) ** 2
    if speed_rpm >= pts[-1][0]:
        n0, p0 = pts[-1]
        return p0 * (speed_rpm / n0) ** 2
    for (n0, p0), (n1, p1) in itertools.pairwise(pts):
        if n0 <= speed_rpm <= n1:
            if p0 <= 0.0 or p1 <= 0.0:
                return p0 + (p1 - p0) * (speed_rpm - n0) / (n1 - n0)
            e = math.log(p1 / p0) / math.log(n1 / n0)
            return p0 * (speed_rpm / n0) ** e
    raise AssertionError("unreachable")


def optimum_frequency_Hz(ohmic_W: float, core_W: float, frequency_Hz: float) -> float:
    """Frequency of minimum total loss, f* = (K_ом/K_маг)^0.25, seed 000 eq. (10), with
    K_ом = P_ом·f² (eq. 9) and K_маг = P_M/f² taken at one operating point. At f* the ohmic
    and the core losses are equal.

    Parameters
    ----------
    ohmic_W : float
        Ohmic loss P_ом at the operating point [W]
    core_W : float
        Iron and magnet loss P_M at the operating point [W]
    frequency_Hz : float
        Flux frequency of the operating point f [Hz]

    Returns
    -------
    float
        Frequency of least total loss f* [Hz]

    Notes
    -----
    Holds while P_ом ∝ 1/f² (a reducer's motor torque ∝ 1/n at one efficiency) and
    P_M ∝ f² (the quadratic iron model).

    Examples
    --------
    >>> round(optimum_frequency_Hz(68.97, 160.0, 500.0), 1)
    405.1
    """
    k_om = ohmic_W * frequency_Hz**2
    k_mag = core_W / frequency_Hz**2
    return (k_om / k_mag) ** 0.25


# ---------------------------------------------------------------- a frame series by similarity
#: Exponents of the scaling laws under geometric similarity (every length × l*, the same
#: materials, the same flux density B* = 1 and the same winding temperature rise θ* = 1),
#: for the preliminary design of electromechanical actuators [3], [4], [5]:
#:
#: - continuous torque T* = J*·l*⁴ with the current density J* = l*^-0.5 (Joule losses carried
#:   by convection over a surface ∝ l*², θ* = 1): T* = l*^3.5 [3] (§ brushless motor), [5];
#: - rated (maximum) speed Ω* = l*^-1 (the same peripheral speed, i.e. the same centrifugal
#:   stress in the rotor) [3]; SizingLab's VEGA notebook writes W* = T*^(-1/3.5) [6];
#: - stator steel area ∝ l*², stack length ∝ l*, steel mass ∝ l*³ (seed 000's m = ρ·S·l·k);
#: - phase resistance R* = T*^(-5/3.5)·K_T*² [6] with the winding for the same bus voltage at
#:   the rated speed (K_T·Ω = const, K_T* = l*): R* = l*^-3, current I* = T*/K_T* = l*^2.5, so
#:   the Joule loss at the rated torque R*·I*² = l*² (the θ* = 1 premise of the torque law);
#: - magnet eddy losses ∝ the magnet volume l*³ at the same frequency: the classical loss
#:   density σ·(π·f·B·w)²/6 of a conducting plate of width w is kept by segmenting the magnets
#:   into pieces of the reference's width (whole magnets, w ∝ l*, would give l*⁵);
#: - rotor inertia J* = l*⁵ = T*^(5/3.5), mass M* = l*³ = T*^(3/3.5) [3], [5], [6];
#: - thermal time constant τ* = R_th*·C_th* = l*^-2·l*³ = l* (convection) [5];
#: - outer dimensions (stator diameter, stack length) ∝ l*.
#:
#: [3] M. Budinger, J. Liscouët, F. Hospital, J.-C. Maré, «Estimation models for the
#:     preliminary design of electromechanical actuators», Proc. IMechE Part G 226 (3),
#:     243–259, 2012. [4] M. Budinger, J.-C. Passieux, C. Gogu, A. Fraj, «Scaling-law-based
#:     metamodels for the sizing of mechatronic systems», Mechatronics 24 (7), 775–787, 2014.
#:     [5] M. Budinger, S. Delbecq, «Sizing and optimization of mechatronic systems», course,
#:     lecture 2 «Scaling laws» (INSA/ISAE Toulouse, SizingLab/sizing_course). [6] SizingLab,
#:     VEGA TVC EMA notebook «Sizing procedure and optimization with OpenMDAO» (motor:
#:     M ∝ T^(3/3.5), J ∝ T^(5/3.5), W ∝ T^(-1/3.5)); FAST-UAV motor estimation models
#:     (R ∝ T^(-5/3.5)·K_T²).
SCALING_EXPONENTS: dict[str, float] = {
    "torque_Nm": 3.5,
    "speed_rpm": -1.0,
    "stator_outer_diameter_mm": 1.0,
    "stack_length_mm": 1.0,
    "stator_steel_area_mm2": 2.0,
    "phase_resistance_ohm": -3.0,
    "current_A": 2.5,
    "magnet_loss_W": 3.0,
    "rotor_inertia_kgm2": 5.0,
    "mass_kg": 3.0,
    "thermal_time_constant_s": 1.0,
}

#: The law a scaled row states, in words.
SCALING_LAW = (
    "geometric similarity from seed 000's reference frame (Budinger et al. 2012, 2014): "
    "T ∝ l^3.5, n ∝ l^-1, steel area ∝ l², stack ∝ l, R ∝ l^-3, I ∝ l^2.5, magnet losses "
    "∝ l³, J ∝ l⁵, mass ∝ l³, τ_th ∝ l"
)


def length_scale_for_torque(torque_Nm: float, reference_torque_Nm: float) -> float:
    """l* of the frame that gives ``torque_Nm`` continuously, T* = l*^3.5 [3].

    Parameters
    ----------
    torque_Nm : float
        Continuous torque wanted T [N·m]
    reference_torque_Nm : float
        Continuous torque of the reference frame [N·m]

    Returns
    -------
    float
        Length scale l* [-]

    Notes
    -----
    Geometric similarity, the same materials, flux density and winding temperature rise.

    Examples
    --------
    >>> round(length_scale_for_torque(2 * 2**3.5, 2.0), 9)
    2.0
    """
    return (torque_Nm / reference_torque_Nm) ** (1.0 / SCALING_EXPONENTS["torque_Nm"])


def scaled(quantity: str, reference_value: float, length_scale: float) -> float:
    """A quantity of the frame l* times the reference's, by its law (:data:`SCALING_EXPONENTS`).

    The 2.0 N·m reference at twice its size: 2·2^3.5 = 22.6 N·m, its rotor 2⁵ = 32 times the
    inertia, its rated speed halved.

    Parameters
    ----------
    quantity : str
        A key of :data:`SCALING_EXPONENTS`
    reference_value : float
        The reference frame's value, in its unit
    length_scale : float
        Length scale l* [-]

    Returns
    -------
    float
        The scaled frame's value, in the reference's unit

    Examples
    --------
    >>> round(scaled("torque_Nm", 2.0, 2.0), 3), scaled("rotor_inertia_kgm2", 1.0, 2.0)
    (22.627, 32.0)
    >>> scaled("speed_rpm", 5000.0, 2.0)
    2500.0
    """
    return reference_value * length_scale ** SCALING_EXPONENTS[quantity]


def thermal_time_constant_s(limit_W: float, rise_K: float, heat_capacity_J_K: float) -> float:
    """τ = R_th·C_th of a first-order body whose limit losses give the allowed rise:
    R_th = Δθ/P. 228.4 W for 105 K and 1191 J/K: 547.6 s.

    Parameters
    ----------
    limit_W : float
        Losses that give the allowed rise P [W]
    rise_K : float
        Allowed temperature rise Δθ [K]
    heat_capacity_J_K : float
        Heat capacity of the body C_th [J/K]

    Returns
    -------
    float
        Thermal time constant τ [s]

    Examples
    --------
    >>> round(thermal_time_constant_s(228.42, 105.0, 2.5949 * 459.0), 1)
    547.5
    """
    return rise_K / limit_W * heat_capacity_J_K
