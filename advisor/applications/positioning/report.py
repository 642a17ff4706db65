"""Report tables of the positioning drive (imported only on that path)."""

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
    if t == nominal:
        return f"{t:.4g} s"
    return f"{t:.4g} s with its estimated inertia {INERTIA_BAND * 100:.0f} % higher"


def headline(report) -> str:
    """The design in a few words: motor, ratio, move time; with a required move time, that
    time and the fastest motor beside the chosen one (MO-05); with a duty cycle, the cycle's
    ratio, the single move's beside it, labelled so."""
    motion = report.design.motion
    motor, ratio, time_s = design_ratio(report)
    text = f"motor {motor}, i = {ratio:.4g}, {time_s:.4g} s ({motion.profile_actual})"
    if motion.required_move_time_s is not None:
        text += f", required ≤ {motion.required_move_time_s:.4g} s"
        if motion.fastest_motor is not None and motion.fastest_motor != motor:
            text += f" (fastest: motor {motion.fastest_motor}, {_fastest_time(motion)})"
    if report.design.duty is not None and (motor, ratio) != (motion.motor, motion.optimal_ratio):
        single = "fastest move" if motion.required_move_time_s is None else "the move's choice"
        text += (
            f" for the duty cycle; {single} without the cycle: motor {motion.motor}, "
            f"i = {motion.optimal_ratio:.4g}, {motion.move_time_s:.4g} s"
        )
    return text
