"""The steps of the spinning-rotor advice (seed 002), each returning a typed record: the
bearing, the rotor's model, the drive torque and run-up, the bearing's rating."""

import math
from dataclasses import dataclass

from advisor.calc.bearing_life import (
    Equivalent,
    SkfFriction,
    equivalent_load,
    rating_life_h,
    skf_friction,
    static_safety,
)
from advisor.calc.rotor import (
    BallSet,
    CupGeometry,
    G,
    GyroscopicLoads,
    Rotor,
    SteadyTorques,
    aero_coefficient,
    aero_coefficient_from_loss,
    run_up_curve,
    run_up_time,
    torque_for_run_up,
)
from advisor.core.errors import InputError
from advisor.core.reading import Requirements
from advisor.core.rulebook import Trace
from catalogs import Catalogs
from catalogs.rows import Bearing
from rules.rotor import drive_torque

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


def chosen_bearing(req: Requirements, cat: Catalogs) -> tuple[Bearing, float]:
    """The catalog's row of rotor.bearing and its operating contact angle, degrees."""
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


def aero_k(req: Requirements) -> float:
    """k of M_aero = k·ω^1.5: from a known loss at speed, or from the cup's geometry."""
    a, w = req.rotor.aero, req.rotor.speed_rad_s
    if a.loss_W is not None:
        return aero_coefficient_from_loss(a.loss_W, w)
    return aero_coefficient(
        CupGeometry(
            a.outer_radius_mm * MM,
            a.outer_length_mm * MM,
            a.inner_radius_mm * MM,
            a.inner_length_mm * MM,
            a.air_density_kg_m3,
            a.air_viscosity_m2_s,
        )
    )


def rotor_model(req: Requirements, b: Bearing, angle_deg: float) -> Rotor:
    """Everything the motion equation (5) needs, in SI. The bearings share the weight, n
    ways, and seed 002's eq. (3) reaction, the full force on each support as in the seed's
    example, ⌊n/2⌋ bearings a support (:attr:`advisor.calc.rotor.Rotor.couple_share`)."""
    r = req.rotor
    return Rotor(
        inertia_kgm2=r.inertia,
        bearings=r.bearing_count,
        balls=BallSet(
            b.pitch_radius_mm * MM, b.ball_diameter_mm * MM, b.ball_count, math.radians(angle_deg)
        ),
        rolling_friction_m=r.rolling_friction_mm * MM,
        weight_share_N=r.mass_kg * G / r.bearing_count,
        plane_to_cg_m=r.ball_plane_to_cg_mm * MM,
        aero_k=aero_k(req),
        slew_per_speed=r.inertia * r.slew_rate_rad_s * math.sin(math.radians(r.axis_angle_deg)),
    )


@dataclass(frozen=True, slots=True)
class RunUp:
    """The drive torque (RO-02) and the run-up it gives."""

    run_up_torque_Nm: float  # the torque that reaches speed in the required time
    required_torque_Nm: float  # the larger of that and the steady torque with the reaction
    time_s: float  # the run-up at the required torque
    time_at_steady_torque_s: float | None  # at the steady torque; None: never quite reached
    curve_time_s: list[float]
    curve_speed_rad_s: list[float]


def run_up(req: Requirements, rotor: Rotor, steady: SteadyTorques, trace: Trace) -> RunUp:
    """RO-02: the drive torque, the larger of the run-up's in the required time and the steady
    torque with the reaction; the run-up time and curve at it."""
    r = req.rotor
    w = r.speed_rad_s
    run_up_torque = torque_for_run_up(rotor, w, r.run_up_time_s)
    required = trace.apply(drive_torque, run_up_torque, steady.slewing_Nm, r.run_up_time_s)
    times, speeds = run_up_curve(rotor, required, w)
    return RunUp(
        run_up_torque,
        required,
        run_up_time(rotor, required, w),
        time_at_steady_torque(rotor, steady, w),
        times,
        speeds,
    )


#: Below this excess over the resistance at speed, relative to it, the steady torque is taken as
#: the resistance itself. Its two routes (term by term, and the polynomial the run-up integrates)
#: differ by a few units of the last place (~1e-16), and the time near the top grows like
#: J/(dM_res/dω)·ln(1/excess): for the seed's rotor a rounding excess of 1.5e-16 gives 4244 s,
#: a true one of 1e-12 gives 3245 s. The same floor as :func:`torque_for_run_up`'s.
SAME_TORQUE_REL = 1e-12


def time_at_steady_torque(rotor: Rotor, steady: SteadyTorques, speed: float) -> float | None:
    """The run-up time at the steady torque with the reaction, s; None where that torque does
    not exceed the resistance of the run-up (without the reaction) at speed: with no slew the
    two are the same torque and the rotor never quite reaches the speed.

    The decision compares the two steady torques, both summed term by term from the same loads
    (the run-up's resistance at speed is the steady torque without the reaction), so rounding of
    the polynomial :func:`advisor.calc.rotor.run_up_time` integrates cannot decide it."""
    if steady.slewing_Nm - steady.calm_Nm <= SAME_TORQUE_REL * steady.calm_Nm:
        return None
    t = run_up_time(rotor, steady.slewing_Nm, speed)
    return t if math.isfinite(t) else None


def slew_duration(req: Requirements) -> float:
    """How long one slew lasts, s (none without a slew rate)."""
    r = req.rotor
    return math.radians(r.slew_angle_deg) / r.slew_rate_rad_s if r.slew_rate_rad_s else 0.0


@dataclass(frozen=True, slots=True)
class BearingRating:
    """The bearing under the gyroscopic load: SKF friction, equivalent load, life, safety."""

    skf_calm: SkfFriction
    skf_slewing: SkfFriction
    equivalent: Equivalent
    life_h: float
    static_safety: float


def bearing_rating(
    req: Requirements, cat: Catalogs, b: Bearing, loads: GyroscopicLoads
) -> BearingRating:
    """The SKF friction without and with the reaction, and the ISO 281 life and ISO 76 static
    safety under it."""
    r = req.rotor
    n_rpm = r.speed_rad_s * RPM
    k = cat.bearing_friction[b.friction]
    nu = r.lubricant_viscosity_mm2_s
    calm, slewing = loads.calm, loads.slewing
    eq = equivalent_load(b, slewing.radial_N, slewing.axial_N)
    return BearingRating(
        skf_friction(b, k, calm.radial_N, calm.axial_N, n_rpm, nu),
        skf_friction(b, k, slewing.radial_N, slewing.axial_N, n_rpm, nu),
        eq,
        rating_life_h(b, eq.load_N, n_rpm),
        static_safety(b, slewing.radial_N, slewing.axial_N),
    )
