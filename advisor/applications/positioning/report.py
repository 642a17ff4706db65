"""Report tables of the positioning drive (imported only on that path)."""

from advisor.core.report import _Out
from advisor.duty.report import DutyOut


class MotionCandidateOut(_Out):
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


class CurveOut(_Out):
    ratio: list[float]
    move_time_s: list[float]


class MotionOut(_Out):
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
    candidates: list[MotionCandidateOut]
    curve: CurveOut


class PositioningDesignOut(_Out):
    motion: MotionOut
    duty: DutyOut | None = None


def headline(report) -> str:
    """The design in a few words: motor, ratio, move time."""
    mo = report.design.motion
    return (
        f"motor {mo.motor}, i = {mo.optimal_ratio:.4g}, {mo.move_time_s:.4g} s "
        f"({mo.profile_actual})"
    )
