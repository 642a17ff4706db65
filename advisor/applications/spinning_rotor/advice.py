"""The spinning-rotor drive advice (seed 002): bearing and aerodynamic losses with and
without the gyroscopic reaction, and the drive torque that reaches speed in time.
Orchestration only: the steps are in :mod:`.steps`, the report tables in :mod:`.tables`."""

import math

from advisor.applications.spinning_rotor.report import RotorDesignOut
from advisor.applications.spinning_rotor.steps import (
    RPM,
    BearingRating,
    RunUp,
    bearing_rating,
    chosen_bearing,
    designation_runs,
    rotor_model,
    run_up,
    slew_duration,
)
from advisor.applications.spinning_rotor.tables import bearing_out, rotor_out
from advisor.calc.checks import Check
from advisor.calc.rotor import gyroscopic_loads, gyroscopic_moment, slew_loss, steady_torques
from advisor.core.cite import cite
from advisor.core.reading import Requirements
from advisor.core.report import round_sig
from advisor.core.rulebook import Trace
from catalogs import Catalogs
from catalogs.rows import Bearing
from rules.rotor import SEED_002, design_loads, friction_model

__all__ = ["advise_spinning_rotor", "designation_runs"]


def _checks(
    req: Requirements,
    cat: Catalogs,
    b: Bearing,
    rating: BearingRating,
    drive: RunUp,
    steady_Nm: float,
) -> list[Check]:
    """The bearing's speed, static safety and (where required) life; the drive holds speed
    under the gyroscopic load."""
    r = req.rotor
    # in rpm to 12 significant digits: the limit is a catalog figure in rpm, and a speed
    # given as that figure ("40000 rpm", or its rad/s) comes back from rad/s a few units in
    # the last place above it (22000 rpm: 22000.000000000004), refused at its own limit
    n_rpm = round_sig(r.speed_rad_s * RPM, 12)
    required, s0 = drive.required_torque_Nm, rating.static_safety
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
            steady_Nm,
            "N·m",
            # RO-02 takes torques within 1e-9 as equal (the same sum, rounded differently)
            1.0 if abs(required / steady_Nm - 1.0) < 1e-9 else required / steady_Nm,
            SEED_002.at("eq. (5)"),
        ),
    ]
    if r.required_life_h is not None:
        checks.append(
            Check(
                "bearing_life",
                "basic rating life L10h of each bearing under the gyroscopic load",
                rating.life_h,
                r.required_life_h,
                "h",
                rating.life_h / r.required_life_h,
                cite("iso-281", "eq. (1)"),
            )
        )
    return checks


def _and(items: list[str]) -> str:
    return ", ".join(items[:-1]) + " and " + items[-1] if len(items) > 1 else items[0]


def rating_outputs(b: Bearing) -> list[str]:
    """What rests on the row's estimated ratings: C is the life's; C0 the static safety's, the
    life's where X/Y are read at Fa/C0 (deep groove, by f0·Fa/C0, and 15° angular contact) and
    the deep-groove SKF friction's; f0 the deep-groove X/Y, so the life's."""
    est = set(b.estimated)
    reads_c0 = b.type == "deep_groove" or b.contact_angle_deg < 20.0
    life = "C_kN" in est or "f0" in est or ("C0_kN" in est and reads_c0)
    static = "C0_kN" in est
    skf = "C0_kN" in est and b.type == "deep_groove"
    names = ("the life", "the static safety", "the SKF friction")
    return [n for n, on in zip(names, (life, static, skf), strict=True) if on]


def estimate_warning(b: Bearing) -> str:
    """The warning for a row with estimated fields: which, and what rests on each. The ball set
    is eq. (4)'s (r_B/D_w, z, the ball mass), so the steady power and the drive torque; the
    pitch diameter is also r of eq. (3), the reaction behind every load; the ratings are the
    life's, the static safety's and (deep groove) the SKF friction's."""
    est = set(b.estimated)
    clauses = [
        f"bearing {b.designation}: {', '.join(b.estimated)} estimated (see the catalog "
        "file for how)"
    ]
    if est & {"pitch_diameter_mm", "ball_diameter_mm", "ball_count"}:
        clauses.append(
            "the eq. (4) friction rests on the ball set, and with it the steady power and "
            "the drive torque"
        )
    if "pitch_diameter_mm" in est:
        clauses.append(
            "the pitch diameter is also r of eq. (3), so the reaction and through it the "
            "life, the static safety and the SKF friction"
        )
    ratings = rating_outputs(b)
    if ratings:
        fields = [f for f in b.estimated if f in ("C_kN", "C0_kN", "f0")]
        verb = "rests" if len(ratings) == 1 else "rest"
        clauses.append(f"{_and(ratings)} {verb} on {_and(fields)}")
    if est & {"ball_diameter_mm", "ball_count"}:
        # eq. (4): the load terms go as 1 + 2·r_B/D_w = 2r/D_w, the centrifugal one as
        # z·D_w³·r_B/D_w with z ∝ 1/D_w, i.e. about as D_w
        clauses.append(
            "a ball larger than the real one lowers eq. (4)'s load terms and raises its "
            "centrifugal term, so whether the estimate errs low (unsafe) depends on the speed"
        )
    return "; ".join(clauses)


def _warnings(req: Requirements, b: Bearing, angle: float) -> list[str]:
    """Estimated catalog values the result rests on; a contact angle other than the
    catalog's."""
    r = req.rotor
    warnings = []
    if b.estimated:
        warnings.append(estimate_warning(b))
    if r.contact_angle_deg is not None and b.contact_angle_deg and angle != b.contact_angle_deg:
        warnings.append(
            f"contact angle {angle:g}° given instead of the catalog's {b.contact_angle_deg:g}°"
        )
    return warnings


def advise_spinning_rotor(req: Requirements, cat: Catalogs, trace: Trace):
    """The bearing; the rotor's model (RO-03); the gyroscopic loads (RO-01); the steady
    torques; the drive torque and run-up (RO-02); a sustained slew at the design's drive torque
    and with a drive sized on the steady power without the reaction; the bearing's rating.
    Returns the design's tables, its checks and its warnings."""
    r = req.rotor
    w = r.speed_rad_s
    b, angle = chosen_bearing(req, cat)
    trace.apply(friction_model, r.rolling_friction_mm)
    rotor = rotor_model(req, b, angle)
    moment = gyroscopic_moment(
        r.angular_momentum, r.slew_rate_rad_s, math.radians(r.axis_angle_deg)
    )
    loads = gyroscopic_loads(rotor, moment, w)
    trace.apply(
        design_loads,
        moment,
        loads.reaction_axial_N,
        loads.reaction_radial_N,
        loads.preload_N,
        rotor.weight_share_N,
    )
    steady = steady_torques(rotor, loads, w)
    drive = run_up(req, rotor, steady, trace)
    duration = slew_duration(req)
    # the design's drive (at least the steady torque with the reaction: it keeps the speed), and
    # seed 002's fig. 4: a drive sized on the steady power without the reaction, saturated
    slews = (
        slew_loss(rotor, drive.required_torque_Nm, w, duration),
        slew_loss(rotor, steady.calm_Nm, w, duration),
    )
    rating = bearing_rating(req, cat, b, loads)
    checks = _checks(req, cat, b, rating, drive, steady.slewing_Nm)
    bearing = bearing_out(b, angle, w * RPM, loads, rating, cat)
    out = rotor_out(req, loads, steady, drive, bearing, rating, slews)
    return RotorDesignOut.make(rotor=out), checks, _warnings(req, b, angle)
