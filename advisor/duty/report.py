"""Report tables of a duty cycle: ``[design.duty]`` and its ``phases``."""

from advisor.calc.duty import Phase
from advisor.core.report import ReportTable

RPM = 30.0 / 3.141592653589793


class PhaseOut(ReportTable):
    name: str
    time_s: float
    speed_rpm: float  # the highest speed in the phase; a ramp runs from/to it linearly
    speed_start_rpm: float
    speed_end_rpm: float
    torque_Nm: float
    energy_J: float


class ThermalOut(ReportTable):
    """A first-order thermal model of the motor over repeated cycles (S2: its one run from
    cold)."""

    time_constant_s: float
    time_constant_basis: str
    resistance_K_W: float
    steady_rise_K: float  # at the cycle-averaged losses
    peak_rise_K: float  # the highest rise within a settled cycle (S2: at the run's end)
    limit_rise_K: float  # the rise at the frame's limit
    time_s: list[float]
    rise_K: list[float]


class DutyOut(ReportTable):
    motor: str
    ratio: float
    cycle_time_s: float
    move_time_s: float
    peak_torque_Nm: float
    peak_torque_limit_Nm: float
    rms_torque_Nm: float
    thermal_utilisation: float
    thermal_basis: str
    inertia_ratio: float
    motor_inertia_kgm2: float | None = None  # the rotor inertia the cycle used
    motor_inertia_basis: str | None = None  # where it came from
    inertia_ratio_guideline: float
    energy_per_cycle_J: float
    regenerated_per_cycle_J: float
    mean_speed_rpm: float
    cycles_per_hour: float | None = None
    duty_type: str
    held_by: str | None = None  # what holds the load at rest and against back-driving
    regenerated_to: str | None = None  # where the energy given back goes
    mean_starting_torque_Nm: float | None = None  # an induction motor's mean start torque
    rated_torque_Nm: float | None = None
    min_rms_ratio: float | None = None
    min_rms_torque_Nm: float | None = None
    standstill_cooling_factor: float | None = None
    starts_per_hour: float | None = None
    allowed_starts_per_hour: float | None = None
    no_load_starts_per_hour: float | None = None
    inertia_factor: float | None = None
    #: positioning with a required time: the fastest motor that passes the cycle (MO-06)
    fastest_motor: str | None = None
    fastest_move_time_s: float | None = None
    losses_W: dict[str, float] | None = None
    loss_limit_W: float | None = None
    thermal: ThermalOut | None = None
    phases: list[PhaseOut]


def phases_out(phases: list[Phase]) -> list[PhaseOut]:
    return [
        PhaseOut.make(
            name=p.name,
            time_s=p.time_s,
            speed_rpm=max(abs(p.speed_start_rad_s), abs(p.speed_end_rad_s)) * RPM,
            speed_start_rpm=p.speed_start_rad_s * RPM,
            speed_end_rpm=p.speed_end_rad_s * RPM,
            torque_Nm=p.torque_Nm,
            energy_J=p.energy_J,
        )
        for p in phases
    ]
