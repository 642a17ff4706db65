"""Report tables of the spinning-rotor drive (imported only on that path)."""

from advisor.core.report import ReportTable


class PairOut(ReportTable):
    without_reaction: float
    with_reaction: float


class FrictionTermsOut(ReportTable):
    radial_Nm: float
    axial_Nm: float
    centrifugal_Nm: float


class FrictionPartsOut(ReportTable):
    without_reaction: FrictionTermsOut
    with_reaction: FrictionTermsOut


class LoadsOut(ReportTable):
    radial_N: float
    axial_N: float
    centrifugal_per_ball_N: float


class BearingOut(ReportTable):
    designation: str
    type: str
    d_mm: float
    D_mm: float
    B_mm: float
    contact_angle_deg: float
    ball_count: int
    ball_diameter_mm: float
    pitch_diameter_mm: float
    C_kN: float
    C0_kN: float
    limiting_speed_rpm: float
    speed_rpm: float
    loads_without_reaction: LoadsOut
    loads_with_reaction: LoadsOut
    equivalent_load_N: float
    factor_X: float
    factor_Y: float
    static_safety: float
    source: list[str]
    estimated: list[str]


class CurveOut(ReportTable):
    time_s: list[float]
    speed_rad_s: list[float]


class SlewOut(ReportTable):
    basis: str  # what the drive torque is
    drive_torque_Nm: float
    duration_s: float
    speed_after_slew_rad_s: float
    speed_drop_pct: float
    balance_speed_rad_s: float
    # absent where the drive holds the speed (the curve would be the one point)
    curve: CurveOut | None = None


class RotorOut(ReportTable):
    inertia_kgm2: float
    angular_momentum_kgm2_s: float
    speed_rad_s: float
    speed_rpm: float
    gyroscopic_moment_Nm: float
    reaction_axial_N: float
    reaction_radial_N: float
    preload_N: float
    preload_without_reaction_N: float
    bearing_friction_Nm: PairOut
    bearing_friction_terms: FrictionPartsOut
    bearing_loss_W: PairOut
    skf_friction_Nm: PairOut
    aero_loss_W: float
    aero_torque_Nm: float
    steady_torque_Nm: PairOut
    steady_power_W: PairOut
    run_up_torque_Nm: float
    required_torque_Nm: float
    run_up_time_s: float
    # absent when the steady torque only equals the resistance at speed (no slew): the rotor
    # then approaches the speed without ever reaching it
    run_up_time_at_steady_torque_s: float | None = None
    bearing_life_h: float  # each bearing's L10h
    bearing_set_life_h: float  # the set's: 10 % of sets lose a bearing (e = 10/9)
    bearing: BearingOut
    slew: SlewOut  # at the design's drive torque
    # seed 002's fig. 4: a drive limited to the steady torque without the reaction
    slew_if_sized_without_reaction: SlewOut
    run_up: CurveOut


class RotorDesignOut(ReportTable):
    rotor: RotorOut


def headline(report) -> str:
    """The design in a few words: drive torque, run-up, power, bearing life."""
    r = report.design.rotor
    return (
        f"{r.required_torque_Nm:.4g} N·m drive, run-up {r.run_up_time_s:.3g} s, "
        f"{r.steady_power_W.with_reaction:.4g} W with the gyroscopic load, "
        f"{r.bearing.designation} L10h {r.bearing_life_h:.3g} h"
    )
