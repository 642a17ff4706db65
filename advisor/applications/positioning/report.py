"""Report tables of the positioning drive (imported only on that path)."""

from advisor.applications.positioning.stated import stated_up
from advisor.core.report import ReportTable
from advisor.duty.report import DutyOut
from rules.motion import INERTIA_BAND


class MotionCandidateOut(ReportTable):
    name: str
    speed_rad_s: float
    inertia_kgm2: float
    accel_torque_Nm: float
    optimal_ratio: float
    estimated_ratio: float
    estimated_ratio_first_step: float
    first_step_moves_load: bool
    move_time_s: float
    profile: str


class CurveOut(ReportTable):
    ratio: list[float]
    move_time_s: list[float]


class MotionOut(ReportTable):
    motor: str
    optimal_ratio: float
    estimated_ratio: float
    estimated_ratio_first_step: float
    first_step_moves_load: bool
    ratio_i0: float
    k_factor: float
    coefficient_A: float
    move_time_s: float
    transient_time_s: float
    profile_assumed: str
    profile_actual: str
    inertia_ratio: float
    torque_ratio: float
    #: with a required move time: the time, and the fastest motor beside the
    #: smallest that meets it (decision MO-05)
    required_move_time_s: float | None = None
    fastest_motor: str | None = None
    fastest_move_time_s: float | None = None
    candidates: list[MotionCandidateOut]
    curve: CurveOut


class PositioningDesignOut(ReportTable):
    motion: MotionOut
    duty: DutyOut | None = None


def design_ratio(report) -> tuple[str, float, float]:
    """The motor, ratio and move time of the drive to build: the duty cycle's where the
    requirement has one (the fastest ratio may fail the cycle), else the fastest move's."""
    motion, duty = report.design.motion, report.design.duty
    if duty is not None:
        return duty.motor, duty.ratio, duty.move_time_s
    return motion.motor, motion.optimal_ratio, motion.move_time_s


def _fastest_time(motion) -> str:
    """The fastest motor's time as the required time is judged: where its inertia is an
    estimate counted higher (MO-05), said so."""
    t = motion.fastest_move_time_s
    nominal = next(c.move_time_s for c in motion.candidates if c.name == motion.fastest_motor)
    if t == stated_up(nominal):  # the stated time is rounded up (stated_up): a given inertia
        return f"{t:.4g} s"
    return f"{t:.4g} s with its estimated inertia {INERTIA_BAND * 100:.0f} % higher"


def _fastest(report, motor: str) -> str:
    """The fastest motor beside the chosen one where a time is required: with a cycle the
    fastest that passes it (MO-06: its move at its cycle's ratio), else the single move's
    (MO-05); empty where it is the chosen motor or none is stated."""
    motion, duty = report.design.motion, report.design.duty
    if duty is not None:
        if duty.fastest_motor is None or duty.fastest_motor == motor:
            return ""
        return (
            f" (fastest that passes the cycle: motor {duty.fastest_motor}, "
            f"{duty.fastest_move_time_s:.4g} s)"
        )
    if motion.fastest_motor is None or motion.fastest_motor == motor:
        return ""
    return f" (fastest: motor {motion.fastest_motor}, {_fastest_time(motion)})"


def headline(report) -> str:
    """The design in a few words: motor, ratio, move time; with a required move time, that
    time and the fastest motor beside the chosen one (MO-05, or with a duty cycle the fastest
    that passes it); with a duty cycle, the cycle's ratio, the single move's beside it,
    labelled so."""
    motion, duty = report.design.motion, report.design.duty
    motor, ratio, time_s = design_ratio(report)
    how = motion.profile_actual
    if duty is not None and duty.motor_inertia_kgm2 is not None:
        how += f", its estimated inertia {INERTIA_BAND * 100:.0f} % higher"
    text = f"motor {motor}, i = {ratio:.4g}, {time_s:.4g} s ({how})"
    if motion.required_move_time_s is not None:
        text += f", required ≤ {motion.required_move_time_s:.4g} s" + _fastest(report, motor)
    if duty is not None and (motor, ratio) != (motion.motor, motion.optimal_ratio):
        single = "fastest move" if motion.required_move_time_s is None else "the move's choice"
        text += (
            f" for the duty cycle; {single} without the cycle: motor {motion.motor}, "
            f"i = {motion.optimal_ratio:.4g}, {motion.move_time_s:.4g} s"
        )
    return text
