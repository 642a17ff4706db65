"""Report tables of the linear actuator (imported only on the linear path)."""

from advisor.core.report import ReportTable
from advisor.duty.report import DutyOut
from advisor.one_way.report import OneWayOut


class NutOut(ReportTable):
    height_mm: float
    turns: float
    turns_basis: str | None = None  # stated where the emergency stop's force lengthens the nut
    height_ratio: float
    bearing_pressure_MPa: float
    allowable_pressure_MPa: float
    # wear and heat at the motor's working speed
    sliding_speed_m_s: float | None = None
    safe_pressure_MPa: float | None = None  # Shigley, Table 8-4, at the sliding speed
    safe_pressure_basis: str | None = None
    pv_MPa_m_s: float | None = None
    friction_power_W: float | None = None
    mean_friction_power_W: float | None = None
    mean_friction_basis: str | None = None
    temperature_rise_K: float | None = None
    allowed_temperature_rise_K: float | None = None
    heat_model: str | None = None


class ThrustOut(ReportTable):
    """The face that takes the axial force and its friction torque."""

    kind: str
    model: str
    torque_Nm: float
    drive_torque_Nm: float  # thread + thrust face: what the motor moves
    efficiency: float  # F·L / (2π·(T_thread + T_thrust))
    # a rolling bearing's basic rating life (ISO 281) under f_B·F: reported, not checked
    equivalent_load_N: float | None = None
    life_L10_Mrev: float | None = None
    life_L10_h: float | None = None
    life_speed_rpm: float | None = None  # the mean screw speed L10h is counted at
    life_basis: str | None = None


class BucklingOut(ReportTable):
    formula: str
    why: str | None = None  # why Euler or Johnson: the slenderness against the transition
    end_fixity: str
    effective_length_factor: float
    slenderness: float
    critical_load_N: float
    safety_factor_required: float


class ScrewOut(ReportTable):
    thread: str  # the profile (GOST 24737-81): Tr14x2
    designation: str  # with its starts (GOST 24739-81): Tr14x8(P2); as thread for one start
    imposed: bool
    advisor_choice: str | None = None
    nominal_diameter_mm: float
    pitch_mm: float
    preferred_pitch: bool
    starts: int
    lead_mm: float
    d2_mm: float
    d3_mm: float
    D1_mm: float
    D2_mm: float
    D4_mm: float
    ac_mm: float
    H1_mm: float
    h3_mm: float
    material_pair: str
    lubrication: str
    screw_steel: str
    friction_model: str
    friction_coefficient: float
    friction_range: list[float]
    lead_angle_deg: float
    friction_angle_deg: float
    torque_Nm: float
    torque_standard_Nm: float
    torque_paper_Nm: float
    efficiency: float
    back_driving_efficiency: float
    back_driving: str  # the sign of back_driving_efficiency in words
    self_locking: bool
    self_locking_at_low_friction: bool
    linear_speed_m_s: float
    revolutions: float
    speed_rpm: float
    output_power_W: float
    nut: NutOut
    buckling: BucklingOut
    thrust: ThrustOut | None = None
    critical_speed_rpm: float | None = None
    service_factor: float | None = None


class CurveOut(ReportTable):
    slip: list[float]
    speed_rpm: list[float]
    torque_Nm: list[float]


class MotorCandidateOut(ReportTable):
    role: str
    rated_power_kW: float
    model: str | None = None
    in_catalog: bool
    rated_speed_rpm: float | None = None
    rated_torque_Nm: float | None = None
    max_torque_Nm: float | None = None
    starting_torque_Nm: float | None = None
    critical_slip: float | None = None
    kloss_epsilon: float | None = None
    working_speed_rpm: float | None = None
    torque_at_required_speed_Nm: float | None = None
    rated_torque_margin: float | None = None
    starting_torque_margin: float | None = None
    breakdown_torque_margin: float | None = None
    travel_time_s: float | None = None
    suitable: bool
    problems: list[str] = []
    curve: CurveOut | None = None


class InductionMotorOut(ReportTable):
    kind: str
    supply_frequency_Hz: float
    speed_rpm: float
    pole_pairs: int
    synchronous_speed_rpm: float
    required_torque_Nm: float
    required_power_kW: float
    rated_power_kW: float
    model: str
    rated_speed_rpm: float
    rated_torque_Nm: float
    working_speed_rpm: float
    working_slip: float
    working_power_kW: float
    travel_time_s: float
    efficiency_pct: float
    cos_phi: float
    starting_current_ratio: float
    inertia_kgm2: float
    mass_kg: float
    estimated: list[str]
    source: str
    candidates: list[MotorCandidateOut]


class LinearDesignOut(ReportTable):
    screw: ScrewOut
    motor: InductionMotorOut
    one_way: "OneWayOut | None" = None
    duty: DutyOut | None = None


def headline(report) -> str:
    """The design in a few words: thread (with its starts when more than one), motor, pole
    pairs."""
    s, m = report.design.screw, report.design.motor
    starts = f" ({s.starts} starts)" if s.starts > 1 else ""
    return f"{s.thread}{starts}, {m.model} {m.rated_power_kW:g} kW, p = {m.pole_pairs}"


def _torque_words(s) -> str:
    """The torque and efficiency that drive the screw: the thread's, and where a thrust face
    is given the drive torque with the face's friction and the efficiency with it (what the
    motor drives), the thread's alone beside it."""
    model = f"{s.friction_model}; standard {s.torque_standard_Nm:.3f}"
    if s.thrust is None:
        return f"{s.torque_Nm:.3f} N·m ({model}), η = {s.efficiency:.3f}"
    t = s.thrust
    face = "collar" if t.kind == "collar" else "thrust bearing"
    return (
        f"{t.drive_torque_Nm:.3f} N·m with the {face}'s {t.torque_Nm:.3f} N·m (thread "
        f"{s.torque_Nm:.3f}, {model}), η = {t.efficiency:.3f} with the {face} (thread "
        f"{s.efficiency:.3f})"
    )


def summary_rows(report) -> list[tuple[str, str]]:
    """The screw and the motor, one line each, for the summary after ``--batch -o``."""
    s, m = report.design.screw, report.design.motor
    return [
        (
            "screw",
            f"{s.thread}{' (imposed)' if s.imposed else ''}"
            f"{f', {s.starts} starts, lead {s.lead_mm:g} mm' if s.starts > 1 else ''}, "
            f"{s.speed_rpm:.0f} rpm, {_torque_words(s)}, "
            f"{'self-locking' if s.self_locking else 'not self-locking'}",
        ),
        (
            "motor",
            f"{m.model}, {m.rated_power_kW:g} kW, {2 * m.pole_pairs} poles (p = {m.pole_pairs}), "
            f"runs at {m.working_speed_rpm:.0f} rpm, stroke in {m.travel_time_s:.2f} s",
        ),
    ]


def back_driving_words(eta_back: float, self_locking: bool, at_low_friction: bool) -> str:
    """What the back-driving efficiency η' = tan(ψ − φ')/tan ψ means (Ivanov [3]): a
    negative one is no efficiency but a self-locking screw.

    >>> back_driving_words(0.35, False, False)[:40]
    'not self-locking: the load drives the sc'
    """
    if not self_locking:
        return (
            f"not self-locking: the load drives the screw back with an efficiency of "
            f"{eta_back:.3g}; holding without power needs a brake or a one-way device"
        )
    words = (
        f"self-locking: a back-driving efficiency of {eta_back:.3g} (≤ 0) means the load "
        f"cannot turn the screw; it holds without power"
    )
    if not at_low_friction:
        words += ", but not at the low end of the friction range: do not rely on it alone"
    return words
