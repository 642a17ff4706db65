"""The spinning rotor's report tables, built from the typed records of the advice."""

from advisor.applications.spinning_rotor.report import (
    BearingOut,
    CurveOut,
    FrictionPartsOut,
    FrictionTermsOut,
    LoadsOut,
    PairOut,
    RotorOut,
    SlewOut,
)
from advisor.applications.spinning_rotor.steps import RPM, BearingRating, RunUp
from advisor.calc.bearing_life import set_life_h
from advisor.calc.rotor import FrictionParts, GyroscopicLoads, Loads, SlewLoss, SteadyTorques
from advisor.core.cite import text
from advisor.core.reading import Requirements
from catalogs import Catalogs
from catalogs.rows import Bearing


def loads_out(loads: Loads) -> LoadsOut:
    return LoadsOut.make(
        radial_N=loads.radial_N, axial_N=loads.axial_N, centrifugal_per_ball_N=loads.centrifugal_N
    )


def terms_out(parts: FrictionParts) -> FrictionTermsOut:
    return FrictionTermsOut.make(
        radial_Nm=parts.radial_Nm, axial_Nm=parts.axial_Nm, centrifugal_Nm=parts.centrifugal_Nm
    )


def bearing_out(
    b: Bearing,
    angle_deg: float,
    speed_rpm: float,
    loads: GyroscopicLoads,
    rating: BearingRating,
    cat: Catalogs,
) -> BearingOut:
    """The bearing's table: its catalog row, its loads, its equivalent load and safety."""
    short = cat.short_names()
    return BearingOut.make(
        designation=b.designation,
        type=b.type,
        d_mm=b.d_mm,
        D_mm=b.D_mm,
        B_mm=b.B_mm,
        contact_angle_deg=angle_deg,
        ball_count=b.ball_count,
        ball_diameter_mm=b.ball_diameter_mm,
        pitch_diameter_mm=b.pitch_diameter_mm,
        C_kN=b.C_kN,
        C0_kN=b.C0_kN,
        limiting_speed_rpm=b.limiting_speed_rpm,
        speed_rpm=speed_rpm,
        loads_without_reaction=loads_out(loads.calm),
        loads_with_reaction=loads_out(loads.slewing),
        equivalent_load_N=rating.equivalent.load_N,
        factor_X=rating.equivalent.X,
        factor_Y=rating.equivalent.Y,
        static_safety=rating.static_safety,
        source=[text(cat.cite_rows(cat.bearing_sources, s), short) for s in b.source],
        estimated=list(b.estimated),
    )


#: What drives each slew of the report (the design's first).
SLEW_BASIS = (
    "the design's drive torque (RO-02)",
    "a drive limited to the steady torque without the reaction (seed 002, fig. 4)",
)


def slew_out(slew: SlewLoss, speed: float, basis: str) -> SlewOut:
    """The speed lost in a sustained slew at a drive torque, and what that torque is."""
    return SlewOut.make(
        basis=basis,
        drive_torque_Nm=slew.drive_torque_Nm,
        duration_s=slew.duration_s,
        speed_after_slew_rad_s=slew.speed_after_rad_s,
        speed_drop_pct=100.0 * (1.0 - slew.speed_after_rad_s / speed),
        balance_speed_rad_s=slew.balance_speed_rad_s,
        curve=CurveOut.make(time_s=slew.time_s, speed_rad_s=slew.speed_rad_s)
        if len(slew.time_s) > 1
        else None,
    )


def pair(without: float, with_reaction: float) -> PairOut:
    return PairOut.make(without_reaction=without, with_reaction=with_reaction)


def rotor_out(
    req: Requirements,
    loads: GyroscopicLoads,
    steady: SteadyTorques,
    run_up: RunUp,
    bearing: BearingOut,
    rating: BearingRating,
    slews: tuple[SlewLoss, SlewLoss],
) -> RotorOut:
    """The rotor's table: loads, friction, losses, drive torque, run-up and the slew at the
    design's drive torque and at a drive sized without the reaction."""
    r = req.rotor
    w, n = r.speed_rad_s, r.bearing_count
    calm, slewing = loads.friction_calm.total_Nm, loads.friction_slewing.total_Nm
    return RotorOut.make(
        inertia_kgm2=r.inertia,
        angular_momentum_kgm2_s=r.angular_momentum,
        speed_rad_s=w,
        speed_rpm=w * RPM,
        gyroscopic_moment_Nm=loads.moment_Nm,
        reaction_axial_N=loads.reaction_axial_N,
        reaction_radial_N=loads.reaction_radial_N,
        preload_N=loads.preload_N,
        preload_without_reaction_N=loads.calm.axial_N,
        bearing_friction_Nm=pair(calm, slewing),
        bearing_friction_terms=FrictionPartsOut.make(
            without_reaction=terms_out(loads.friction_calm),
            with_reaction=terms_out(loads.friction_slewing),
        ),
        bearing_loss_W=pair(n * calm * w, n * slewing * w),
        skf_friction_Nm=pair(rating.skf_calm.total_Nm, rating.skf_slewing.total_Nm),
        aero_loss_W=steady.aero_Nm * w,
        aero_torque_Nm=steady.aero_Nm,
        steady_torque_Nm=pair(steady.calm_Nm, steady.slewing_Nm),
        steady_power_W=pair(steady.calm_Nm * w, steady.slewing_Nm * w),
        run_up_torque_Nm=run_up.run_up_torque_Nm,
        required_torque_Nm=run_up.required_torque_Nm,
        run_up_time_s=run_up.time_s,
        run_up_time_at_steady_torque_s=run_up.time_at_steady_torque_s,
        bearing_life_h=rating.life_h,
        bearing_set_life_h=set_life_h(rating.life_h, n),
        bearing=bearing,
        slew=slew_out(slews[0], w, SLEW_BASIS[0]),
        slew_if_sized_without_reaction=slew_out(slews[1], w, SLEW_BASIS[1]),
        run_up=CurveOut.make(time_s=run_up.curve_time_s, speed_rad_s=run_up.curve_speed_rad_s),
    )
