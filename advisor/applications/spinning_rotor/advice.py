"""The spinning-rotor drive advice (seed 002): bearing and aerodynamic losses with and
without the gyroscopic reaction, and the drive torque that reaches speed in time.
Orchestration only."""

import math

from advisor.applications.spinning_rotor.report import (
    BearingOut,
    CurveOut,
    FrictionPartsOut,
    FrictionTermsOut,
    LoadsOut,
    PairOut,
    RotorDesignOut,
    RotorOut,
    SlewOut,
)
from advisor.calc import bearing_life as bl
from advisor.calc import rotor as ro
from advisor.calc.checks import Check
from advisor.core.cite import cite, text
from advisor.core.errors import InputError
from advisor.core.reading import Requirements
from advisor.core.rulebook import Trace
from catalogs import Catalogs
from catalogs.rows import Bearing
from rules import rotor as rules

MM = 1e-3
RPM = 30.0 / math.pi


def designation_runs(designations: list[str]) -> str:
    """The catalog's designations in few words: consecutive numbers of one series as a run,
    ``6200 … 6210``, ``7200 … 7210 BECBP``; others as they are, in catalog order."""
    runs: list[list] = []  # [first, last, number, suffix]
    for des in designations:
        head, _, suffix = des.partition(" ")
        if head.isdigit() and runs and runs[-1][2] is not None:
            first, _, number, last_suffix = runs[-1]
            if suffix == last_suffix and int(head) == number + 1 and len(head) == len(first):
                runs[-1][1:3] = [head, int(head)]
                continue
        runs.append([head, head, int(head) if head.isdigit() else None, suffix])
    parts = [
        f + (f" … {la}" if la != f else "") + (f" {sx}" if sx else "") for f, la, _, sx in runs
    ]
    return ", ".join(parts)


def _bearing(req: Requirements, cat: Catalogs) -> tuple[Bearing, float]:
    r = req.rotor
    b = cat.bearing(r.bearing)
    if b is None:
        known = designation_runs([x.designation for x in cat.bearings])
        raise InputError(
            f"rotor.bearing = {r.bearing!r}: not in the bearing catalog; known: {known}"
        )
    angle = r.contact_angle_deg if r.contact_angle_deg is not None else b.contact_angle_deg
    if angle == 0:
        raise InputError(
            f"rotor.contact_angle_deg is missing: {b.designation} is a deep-groove bearing, and "
            "eq. (4) needs the operating contact angle β it takes under the preload "
            "(typically 10…15°)"
        )
    return b, angle


def _aero_k(req: Requirements) -> float:
    a, w = req.rotor.aero, req.rotor.speed_rad_s
    if a.loss_W is not None:
        return ro.aero_coefficient_from_loss(a.loss_W, w)
    return ro.aero_coefficient(
        ro.CupGeometry(
            a.outer_radius_mm * MM,
            a.outer_length_mm * MM,
            a.inner_radius_mm * MM,
            a.inner_length_mm * MM,
            a.air_density_kg_m3,
            a.air_viscosity_m2_s,
        )
    )


def _loads_out(loads: ro.Loads) -> LoadsOut:
    return LoadsOut.make(
        radial_N=loads.radial_N, axial_N=loads.axial_N, centrifugal_per_ball_N=loads.centrifugal_N
    )


def _terms_out(parts: ro.FrictionParts) -> FrictionTermsOut:
    return FrictionTermsOut.make(
        radial_Nm=parts.radial_Nm, axial_Nm=parts.axial_Nm, centrifugal_Nm=parts.centrifugal_Nm
    )


def advise_spinning_rotor(req: Requirements, cat: Catalogs, trace: Trace):
    r = req.rotor
    b, angle = _bearing(req, cat)
    w = r.speed_rad_s
    n_rpm = w * RPM
    balls = ro.BallSet(
        b.pitch_radius_mm * MM, b.ball_diameter_mm * MM, b.ball_count, math.radians(angle)
    )
    h = r.ball_plane_to_cg_mm * MM
    share = r.mass_kg * ro.G / r.bearing_count
    lam = r.rolling_friction_mm * MM
    trace.apply(rules.friction_model, r.rolling_friction_mm)

    moment = ro.gyroscopic_moment(
        r.angular_momentum, r.slew_rate_rad_s, math.radians(r.axis_angle_deg)
    )
    f_ax, f_rad = ro.reaction_forces(moment, balls.pitch_radius_m, h)
    calm = ro.bearing_loads(share, 0.0, balls, h, w)
    slewing = ro.bearing_loads(share, moment, balls, h, w)
    trace.apply(rules.design_loads, moment, f_ax, f_rad, slewing.axial_N - f_ax, share)
    fr_calm = ro.friction_moment(calm, balls, lam)
    fr_slew = ro.friction_moment(slewing, balls, lam)

    rotor = ro.Rotor(
        inertia_kgm2=r.inertia,
        bearings=r.bearing_count,
        balls=balls,
        rolling_friction_m=lam,
        weight_share_N=share,
        plane_to_cg_m=h,
        aero_k=_aero_k(req),
        slew_per_speed=r.inertia * r.slew_rate_rad_s * math.sin(math.radians(r.axis_angle_deg)),
    )
    aero_torque = rotor.aero_k * w**1.5
    steady_calm = r.bearing_count * fr_calm.total_Nm + aero_torque
    steady_slew = r.bearing_count * fr_slew.total_Nm + aero_torque

    run_up_torque = ro.torque_for_run_up(rotor, w, r.run_up_time_s)
    required = trace.apply(rules.drive_torque, run_up_torque, steady_slew, r.run_up_time_s)
    run_up_time = ro.run_up_time(rotor, required, w)
    at_steady = ro.run_up_time(rotor, steady_slew, w)

    times, speeds = ro.run_up_curve(rotor, required, w)
    # the drive sized on the steady power without the reaction, saturated during a slew
    duration = math.radians(r.slew_angle_deg) / r.slew_rate_rad_s if r.slew_rate_rad_s else 0.0
    s_times, s_speeds, balance = ro.slew_response(rotor, steady_calm, w)
    after = ro.speed_after(s_times, s_speeds, rotor, steady_calm, duration)

    skf_k = cat.bearing_friction[b.friction]
    skf_calm = bl.skf_friction(
        b, skf_k, calm.radial_N, calm.axial_N, n_rpm, r.lubricant_viscosity_mm2_s
    )
    skf_slew = bl.skf_friction(
        b, skf_k, slewing.radial_N, slewing.axial_N, n_rpm, r.lubricant_viscosity_mm2_s
    )
    eq = bl.equivalent_load(b, slewing.radial_N, slewing.axial_N)
    life = bl.rating_life_h(b, eq.load_N, n_rpm)
    s0 = bl.static_safety(b, slewing.radial_N, slewing.axial_N)

    checks = [
        Check(
            "bearing_speed",
            f"speed within the limiting speed of {b.designation}",
            n_rpm,
            b.limiting_speed_rpm,
            "rpm",
            b.limiting_speed_rpm / n_rpm,
            cat.cite_rows(cat.bearing_sources, b.source),
        ),
        Check(
            "bearing_static",
            "static safety s0 = C0/P0 under the gyroscopic load",
            s0,
            1.0,
            "",
            s0,
            cite("iso-76") + cite("skf-gc", "bearing tables"),
        ),
        Check(
            "drive_holds_speed",
            "drive torque over the resistance with the gyroscopic reaction at speed",
            required,
            steady_slew,
            "N·m",
            # RO-02 takes torques within 1e-9 as equal (the same sum, rounded differently)
            1.0 if abs(required / steady_slew - 1.0) < 1e-9 else required / steady_slew,
            rules.SEED_002.at("eq. (5)"),
        ),
    ]
    if r.required_life_h is not None:
        checks.append(
            Check(
                "bearing_life",
                "basic rating life L10h under the gyroscopic load",
                life,
                r.required_life_h,
                "h",
                life / r.required_life_h,
                cite("iso-281", "eq. (1)"),
            )
        )
    warnings = []
    if b.estimated:
        warnings.append(
            f"bearing {b.designation}: {', '.join(b.estimated)} estimated (see the catalog "
            "file for how); the life and the SKF friction rest on them"
        )
    if r.contact_angle_deg is not None and b.contact_angle_deg and angle != b.contact_angle_deg:
        warnings.append(
            f"contact angle {angle:g}° given instead of the catalog's {b.contact_angle_deg:g}°"
        )

    short = cat.short_names()
    out = RotorOut.make(
        inertia_kgm2=r.inertia,
        angular_momentum_kgm2_s=r.angular_momentum,
        speed_rad_s=w,
        speed_rpm=n_rpm,
        gyroscopic_moment_Nm=moment,
        reaction_axial_N=f_ax,
        reaction_radial_N=f_rad,
        preload_N=slewing.axial_N - f_ax,
        preload_without_reaction_N=calm.axial_N,
        bearing_friction_Nm=PairOut.make(
            without_reaction=fr_calm.total_Nm, with_reaction=fr_slew.total_Nm
        ),
        bearing_friction_terms=FrictionPartsOut.make(
            without_reaction=_terms_out(fr_calm), with_reaction=_terms_out(fr_slew)
        ),
        bearing_loss_W=PairOut.make(
            without_reaction=r.bearing_count * fr_calm.total_Nm * w,
            with_reaction=r.bearing_count * fr_slew.total_Nm * w,
        ),
        skf_friction_Nm=PairOut.make(
            without_reaction=skf_calm.total_Nm, with_reaction=skf_slew.total_Nm
        ),
        aero_loss_W=aero_torque * w,
        aero_torque_Nm=aero_torque,
        steady_torque_Nm=PairOut.make(without_reaction=steady_calm, with_reaction=steady_slew),
        steady_power_W=PairOut.make(
            without_reaction=steady_calm * w, with_reaction=steady_slew * w
        ),
        run_up_torque_Nm=run_up_torque,
        required_torque_Nm=required,
        run_up_time_s=run_up_time,
        run_up_time_at_steady_torque_s=at_steady if math.isfinite(at_steady) else None,
        bearing_life_h=life,
        bearing=BearingOut.make(
            designation=b.designation,
            type=b.type,
            d_mm=b.d_mm,
            D_mm=b.D_mm,
            B_mm=b.B_mm,
            contact_angle_deg=angle,
            ball_count=b.ball_count,
            ball_diameter_mm=b.ball_diameter_mm,
            pitch_diameter_mm=b.pitch_diameter_mm,
            C_kN=b.C_kN,
            C0_kN=b.C0_kN,
            limiting_speed_rpm=b.limiting_speed_rpm,
            speed_rpm=n_rpm,
            loads_without_reaction=_loads_out(calm),
            loads_with_reaction=_loads_out(slewing),
            equivalent_load_N=eq.load_N,
            factor_X=eq.X,
            factor_Y=eq.Y,
            static_safety=s0,
            source=[text(cat.cite_rows(cat.bearing_sources, s), short) for s in b.source],
            estimated=list(b.estimated),
        ),
        slew=SlewOut.make(
            drive_torque_Nm=steady_calm,
            duration_s=duration,
            speed_after_slew_rad_s=after,
            speed_drop_pct=100.0 * (1.0 - after / w),
            balance_speed_rad_s=balance,
            curve=CurveOut.make(time_s=s_times, speed_rad_s=s_speeds),
        ),
        run_up=CurveOut.make(time_s=times, speed_rad_s=speeds),
    )
    return RotorDesignOut.make(rotor=out), checks, warnings
