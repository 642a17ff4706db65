"""Report tables of the rotary application (imported only on the rotary path)."""

from advisor.core.report import ReportTable
from advisor.duty.report import DutyOut
from advisor.one_way.report import OneWayOut


class LossesOut(ReportTable):
    ohmic: float
    iron: float
    magnets: float
    total: float


class SpeedCandidateOut(ReportTable):
    speed_rpm: float
    electrical_frequency_Hz: float
    total_ratio: float
    stages: int
    gearbox_efficiency: float
    torque_Nm: float
    current_A: float
    within_loss_limit: bool
    losses_W: LossesOut
    iron_loss_three_term_W: float


class PoleSlotOut(ReportTable):
    slots: int
    poles: int
    teeth_per_group: int
    winding_factor: float


class SteelOut(ReportTable):
    grade: str
    thickness_mm: float
    equivalent: str
    mass_kg: float
    p15_50_W_kg: float
    specific_loss_W_kg: float
    specific_loss_three_term_W_kg: float
    iron_loss_model: str
    estimated: list[str]


class LossCurveOut(ReportTable):
    """The motor's losses against its speed, the frame rewound for each speed behind the
    reducer the design would adopt there (seed 000, eqs. (4), (5), (9)): the curve the speed
    choice (BL-02) rests on, through every candidate, with the frame's loss limit."""

    speed_rpm: list[float]
    ohmic_W: list[float]
    iron_W: list[float]
    magnets_W: list[float]
    total_W: list[float]
    limit_W: list[float]  # what the frame's cooling carries, at every speed
    # a catalog motor's rated speed: it states no losses above it, and the curve ends there
    speed_limit_rpm: float | None = None


class BldcMotorOut(ReportTable):
    kind: str
    speed_rpm: float
    pole_pairs: int
    electrical_frequency_Hz: float
    torque_Nm: float
    current_A: float
    losses_W: LossesOut
    loss_limit_W: float
    loss_limit_basis: str
    # seed 000's eq. (10); none for a catalog motor that states no core losses
    optimum_frequency_Hz: float | None = None
    optimum_speed_rpm: float | None = None
    steel: SteelOut
    candidates: list[SpeedCandidateOut]
    pole_slot_options: list[PoleSlotOut]
    frame: "FrameOut | None" = None
    loss_curve: LossCurveOut | None = None


class StageOut(ReportTable):
    position: str
    ratio: float
    rows: int
    torque_Nm: float
    rolling_body_diameter_mm: float
    own_outer_diameter_mm: float
    outer_diameter_mm: float
    inner_diameter_mm: float
    length_mm: float
    mass_kg: float


class GearboxSummaryOut(ReportTable):
    total_ratio: float
    efficiency: float
    outer_diameter_mm: float
    inner_diameter_mm: float
    length_mm: float
    volume_cm3: float
    mass_kg: float
    stages: list[StageOut]


class SweepOut(ReportTable):
    configurations: int  # built and computed: each realises the ratio within the stage limits
    feasible: int  # of those, the ones whose every stage fits the common diameter
    stage_counts: list[int]
    objective_mass: str
    objective_diameter: str


class Fig1Out(ReportTable):
    q: list[float]
    rows: list[int]
    volume_per_torque_cm3_per_Nm: list[list[float]]


class ParetoPointOut(ReportTable):
    stages: int
    ratios: list[float]  # output first
    rows_out: int
    mass_kg: float
    outer_diameter_mm: float
    length_mm: float
    efficiency: float


class ParetoOut(ReportTable):
    """The front as columns (one entry per design shown, lightest first), like ``fig1``."""

    objectives: list[str]
    front_size: int
    adopted: str  # "on the front" | "dominated"
    dominated_by: ParetoPointOut | None = None
    stages: list[int]
    ratios: list[list[float]]  # output first
    rows_out: list[int]
    mass_kg: list[float]
    outer_diameter_mm: list[float]
    length_mm: list[float]
    efficiency: list[float]


class GearboxOut(GearboxSummaryOut):
    """The adopted reducer (the summary fields) and, beside it, the design space."""

    kind: str
    layout: str
    rolling_body: str
    optimum: GearboxSummaryOut
    optimum_min_diameter: GearboxSummaryOut
    sweep: SweepOut
    pareto: ParetoOut
    fig1: Fig1Out


class StageLifeOut(ReportTable):
    position: str
    rated_torque_Nm: float  # the torque eq. (16) sized the stage for
    mean_input_speed_rpm: float
    max_input_speed_rpm: float
    life_L50_h: float
    life_L10_h: float


class ReducerLoadOut(ReportTable):
    """The reducer under its load spectrum: figures at the output."""

    basis: str  # "duty cycle" | "working point"
    service_factor: float
    service_factor_basis: str
    mean_torque_Nm: float  # T_av, cube-mean weighted by revolutions
    mean_output_speed_rpm: float
    max_output_speed_rpm: float
    repeated_peak_torque_Nm: float
    momentary_peak_torque_Nm: float
    momentary_peak_basis: str
    rated_torque_Nm: float  # the output stage's sizing torque (eq. (16))
    average_torque_limit_Nm: float
    repeated_peak_limit_Nm: float
    momentary_peak_limit_Nm: float
    emergency_stop_time_s: float
    emergency_stops: int | None = None
    emergency_stops_allowed: float
    life_model: str
    required_life_h: float | None = None
    stages: list[StageLifeOut]
    phases_torque_Nm: list[float]
    phases_speed_rpm: list[float]
    phases_time_s: list[float]


class OutputBearingOut(ReportTable):
    designation: str
    chosen: str  # "given" | "automatic"
    arrangement: str
    radial_N: float  # on the most loaded bearing
    axial_N: float
    service_factor: float
    equivalent_load_N: float
    X: float
    Y: float
    C_kN: float
    C0_kN: float
    speed_rpm: float
    life_L10_Mrev: float
    life_L10_h: float
    required_life_h: float | None = None
    static_safety: float
    limiting_speed_rpm: float


class RegenerationOut(ReportTable):
    """Energy the motor gives back per cycle, and what absorbs it."""

    regenerated_per_cycle_J: float
    brakings_per_cycle: int
    largest_braking_J: float
    peak_power_W: float
    bus_voltage_V: float
    bus_max_voltage_V: float
    capacitance_for_largest_uF: float
    bus_capacitance_uF: float | None = None
    bus_energy_J: float
    resistor_needed: bool
    resistor_peak_power_W: float
    resistor_average_power_W: float
    resistor_max_ohm: float | None = None
    rule: str


class RotaryDesignOut(ReportTable):
    motor: BldcMotorOut
    gearbox: GearboxOut
    one_way: OneWayOut | None = None
    duty: DutyOut | None = None
    reducer_load: ReducerLoadOut | None = None
    output_bearing: OutputBearingOut | None = None
    regeneration: RegenerationOut | None = None


def headline(report) -> str:
    """The design in a few words: motor speed and losses, reducer stages, size, mass."""
    m, g = report.design.motor, report.design.gearbox
    return (
        f"{m.speed_rpm:g} rpm, {m.losses_W.total:.0f} W; {len(g.stages)} stages q = "
        f"{g.total_ratio:.4g}, Ø{g.outer_diameter_mm:.0f} mm, {g.mass_kg:.2f} kg"
    )


class FrameTriedOut(ReportTable):
    name: str
    kind: str  # "scaled" | "catalog"
    torque_Nm: float  # continuous, at the rated speed
    speed_rpm: float  # rated
    mass_kg: float
    outer_diameter_mm: float
    fits: bool
    why: str


class FrameOut(ReportTable):
    """The motor frame the design takes and which kind of data decided."""

    name: str
    kind: str  # "scaled" | "catalog" | "reference"
    choice: str  # "auto" | "imposed"
    data: str  # which kind of data decided: the law, a datasheet, the requirement
    torque_Nm: float  # continuous torque at the rated speed (the limit's point)
    speed_rpm: float
    outer_diameter_mm: float | None = None
    length_mm: float | None = None
    mass_kg: float | None = None
    rotor_inertia_kgm2: float | None = None
    thermal_time_constant_s: float | None = None
    length_scale: float | None = None
    law: str
    estimated: list[str]
    tried: list[FrameTriedOut]
    neighbours: list[FrameTriedOut]  # the next smaller and larger of the series (Compare)
