"""The chosen screw's own checks beyond its strength: the whirling speed, the thrust
bearing's static load (and its rating life, reported), and the nut's wear and heat at the
motor's working speed."""

import math
from typing import NamedTuple

from advisor.calc import screw as screw_calc
from advisor.calc.screw import (
    NUT_ALLOWED_RISE_K,
    NUT_FILM_COEFFICIENT,
    NUT_OUTER_DIAMETER_RATIO,
    WHIRL_ALLOWED_SHARE,
    WHIRL_EIGENVALUE,
)
from advisor.calc.service_factor import ServiceFactor
from advisor.calc.sizing import (
    STEEL_DENSITY_KG_M3,
    Check,
    MotorEvaluation,
    ThreadEvaluation,
    ThrustFace,
    factored_check,
    stop_force_words,
)
from advisor.core.cite import cite
from advisor.core.reading import Requirements
from catalogs import Catalogs
from catalogs.threads import ThreadProfile


class NutHeat(NamedTuple):
    """The nut's wear and heat: flank sliding speed, Shigley's safe pressure at
    it, p·v, and the steady temperature rise from the mean friction power."""

    sliding_speed_m_s: float
    safe_pressure_Pa: float
    safe_pressure_row: str
    pv_MPa_m_s: float
    friction_power_W: float
    mean_friction_power_W: float
    mean_basis: str
    surface_m2: float
    temperature_rise_K: float


def _mean_friction_power(req: Requirements, ev: ThreadEvaluation, power_W: float):
    """The thread's friction power averaged over the cycle: the friction work of the duty's
    moves (input work of the screw torque less the work done on the load) times the cycles
    per hour; an IEC duty type by its cyclic duration factor; no duty: continuous running
    (the worst case), said so."""
    duty = req.duty
    if duty is None:
        return power_W, "no [duty]: continuous running assumed (give a duty for the mean)"
    if getattr(duty, "segments", None):
        from advisor.applications.linear.duty import screw_torque

        lead = ev.thread.pitch_mm * 1e-3 * ev.starts
        work = 0.0
        for seg in duty.segments:
            if seg.kind != "move":
                continue
            force = req.linear.force_N if seg.force_N is None else seg.force_N
            angle = 2.0 * math.pi * seg.distance_m / lead
            done = force * seg.distance_m * (1.0 if seg.direction == "against" else -1.0)
            work += max(screw_torque(ev, force, seg.direction, thrust=False) * angle - done, 0.0)
        return (
            work * duty.cycles_per_hour / 3600.0,
            f"duty segments: {work:.4g} J of thread friction a cycle × "
            f"{duty.cycles_per_hour:g} cycles/h",
        )
    share = _running_share(duty)
    return power_W * share, f"duty {duty.duty_type}, running share {share:g}"


def _running_share(duty) -> float:
    """The share of the time an IEC duty type runs the screw [-]."""
    # the running share the duty type has: its cdf where it uses one (S3 to S6); S1, S2 and S7
    # run throughout, S9 and S10 taken at the rated load throughout (the larger side)
    from advisor.core.ignored import DUTY_KEYS_USED

    uses_cdf = duty.duty_type in DUTY_KEYS_USED["cyclic_duration_factor"]
    return duty.cyclic_duration_factor if uses_cdf and duty.cyclic_duration_factor else 1.0


class ThrustLife(NamedTuple):
    """The thrust bearing's basic rating life (ISO 281) under the factored axial force."""

    equivalent_load_N: float
    life_Mrev: float
    life_h: float | None  # None where the duty never turns the screw
    speed_rpm: float
    basis: str


def _mean_screw_speed(req: Requirements, ev: ThreadEvaluation, n_work: float):
    """The screw's speed averaged over the time [rpm], as the nut's mean friction power takes
    its running share: the duty's moves (revolutions a cycle × cycles per hour); an IEC duty
    type by its running share; no duty: continuous running at the working speed (the worst
    case), said so."""
    duty = req.duty
    if duty is None:
        return n_work, "no [duty]: continuous running at the working speed assumed"
    if getattr(duty, "segments", None):
        lead = ev.thread.pitch_mm * 1e-3 * ev.starts
        revs = sum(s.distance_m / lead for s in duty.segments if s.kind == "move")
        return (
            revs * duty.cycles_per_hour / 60.0,
            f"duty segments: {revs:.4g} screw revolutions a cycle × "
            f"{duty.cycles_per_hour:g} cycles/h",
        )
    share = _running_share(duty)
    return n_work * share, f"duty {duty.duty_type}: working speed × running share {share:g}"


def thrust_bearing_life(
    req: Requirements, ev: ThreadEvaluation, n_work: float
) -> ThrustLife | None:
    """The rolling thrust bearing's basic rating life: P = X·F_r + Y·F_a with F_a = f_B·F
    (F_r = 0), L10 = (C/P)³ millions of revolutions, L10h = 10⁶·L10/(60·n̄) at the screw's
    mean speed n̄ (ISO 281:2007, eq. (1) and table 3); None without a rolling bearing.

    Every duty segment's force is at most linear.force_N, so the life at it is the shorter
    side of the one at the duty's own forces."""
    from advisor.calc.bearing_life import equivalent_load, hours_from_Mrev, rating_life_Mrev

    if ev.thrust is None or ev.thrust.kind != "bearing":
        return None
    b = ev.thrust.bearing
    axial = ev.service_factor * req.linear.force_N
    p = equivalent_load(b, 0.0, axial)
    life = rating_life_Mrev(b.C_kN * 1e3, p.load_N)
    speed, words = _mean_screw_speed(req, ev, n_work)
    kind = "deep groove" if b.type == "deep_groove" else f"angular contact {b.contact_angle_deg:g}°"
    basis = (
        f"P = Y·F_a = {p.Y:.4g} × {axial:g} N (F_a = f_B·F, F_r = 0; Y of ISO 281 table 3, "
        f"{kind}), L10 = (C/P)³ with C = {b.C_kN:g} kN; "
        f"L10h at the mean screw speed ({words}), hours of service"
    )
    return ThrustLife(
        p.load_N, life, hours_from_Mrev(life, speed) if speed > 0 else None, speed, basis
    )


def nut_heat(req: Requirements, ev: ThreadEvaluation, speed_rpm: float) -> NutHeat:
    """Sliding speed, safe pressure, p·v and temperature rise of the chosen nut at the
    motor's working speed."""
    t = ev.thread
    v = screw_calc.flank_sliding_speed(t.d2_mm * 1e-3, speed_rpm, ev.lead_angle_rad)
    nut = "bronze" if "bronze" in req.screw.material_pair else "cast_iron"
    if req.screw.material_pair == "steel_steel":
        safe, row = 0.0, "steel–steel: not in Shigley's Table 8-4 (no safe value for a moving nut)"
    else:
        safe, row = screw_calc.shigley_bearing_pressure(nut, v)
    power = screw_calc.friction_power(ev.torque_Nm, speed_rpm, ev.efficiency)
    mean, basis = _mean_friction_power(req, ev, power)
    area = screw_calc.nut_surface(t.d_mm * 1e-3, ev.nut_height_mm * 1e-3)
    return NutHeat(
        v,
        safe,
        row,
        ev.nut_pressure_Pa / 1e6 * v,
        power,
        mean,
        basis,
        area,
        screw_calc.nut_temperature_rise(mean, area),
    )


def whirling_speed_rpm(req: Requirements, thread: ThreadProfile, cat: Catalogs) -> float:
    """The first whirling speed of the screw's core between its supports  [rpm]."""
    lin = req.linear
    steel = cat.steel(req.screw.screw_steel)
    return screw_calc.critical_speed_rpm(
        thread.d3_mm * 1e-3,
        lin.support_span_m,
        lin.end_fixity,
        steel.elastic_modulus_MPa * 1e6,
        STEEL_DENSITY_KG_M3,
    )


def _whirl_check(req: Requirements, ev: ThreadEvaluation, n_work: float, cat: Catalogs) -> Check:
    """The screw's working speed against the allowed share of its whirling speed."""
    lin = req.linear
    n_cr = whirling_speed_rpm(req, ev.thread, cat)
    allowed = WHIRL_ALLOWED_SHARE * n_cr
    return Check(
        "critical_speed",
        f"screw speed against {WHIRL_ALLOWED_SHARE:g} of its whirling speed "
        f"({lin.end_fixity}, βL = {WHIRL_EIGENVALUE[lin.end_fixity]:.5g}, core d3)",
        n_work,
        allowed,
        "rpm",
        allowed / n_work,
        cite("blevins", "table 8-1").with_note(
            f"n_cr = {n_cr:.5g} rpm; {WHIRL_ALLOWED_SHARE:g}·n_cr, screw makers' rule"
        ),
    )


def _bearing_static_check(
    id: str, name: str, bearing, force_N: float, sf: ServiceFactor, note: str = ""
) -> Check:
    """A thrust bearing's static equivalent load P0 under an axial force against its C0,
    stated as the factored load under a service factor (so that C0/value is the margin)."""
    from advisor.calc.bearing_life import static_safety

    c0 = bearing.C0_kN * 1e3
    p0 = c0 / static_safety(bearing, 0.0, force_N)
    source = cite("iso-76").with_note(f"P0 = max(F_r, X0·F_r + Y0·F_a){note}")
    if sf.value != 1.0:
        return factored_check(id, name, p0, c0, "N", source, sf.value)
    return Check(id, name, p0, c0, "N", c0 / p0, source)


def _thrust_checks(
    ev: ThreadEvaluation,
    thrust: ThrustFace | None,
    force_N: float,
    sf: ServiceFactor,
    stop_force_N: float | None = None,
) -> tuple[list[Check], list[str]]:
    """The thrust bearing's static load against C0 as a check, again at the emergency stop's
    momentary force where one is given (at max(F, F_stop), a static load as C0 is); the
    thrust face left out, or a bearing wider than the core, as warnings."""
    if thrust is None:
        return [], [
            "the motor margin excludes thrust friction: no [screw.thrust] face is given, so "
            "the torque is the thread's alone; a collar adds F·f_c·d_c/2 (Shigley, eq. (8-6))"
        ]
    if thrust.kind != "bearing":
        return [], []
    b = thrust.bearing
    what = "static equivalent load against C0"
    name = f"thrust bearing {b.designation}: {what}"
    checks = [_bearing_static_check("thrust_bearing_static", name, b, force_N, sf)]
    if stop_force_N:
        at = stop_force_words(force_N, stop_force_N)
        checks.append(
            _bearing_static_check(
                "thrust_bearing_static_emergency_stop",
                f"thrust bearing {b.designation} at {at}: {what}",
                b,
                max(force_N, stop_force_N),
                sf,
                "; momentary force",
            )
        )
    warnings = []
    if b.d_mm > ev.thread.d3_mm:
        warnings.append(
            f"the thrust bearing {b.designation} (bore {b.d_mm:g} mm) needs a journal "
            f"wider than the core of {ev.thread.name} (d3 = {ev.thread.d3_mm:g} mm): "
            "the screw end must be upset or the bearing smaller"
        )
    return checks, warnings


def _nut_warnings(ev: ThreadEvaluation, heat: NutHeat) -> list[str]:
    """The nut's wear (flank pressure above Shigley's safe one at its sliding speed) and
    heat (steady rise above the allowed one), where they need a word."""
    warnings = []
    pressure_MPa = ev.nut_pressure_Pa / 1e6
    if pressure_MPa > heat.safe_pressure_Pa / 1e6:
        warnings.append(
            f"the nut wears fast: its flank pressure {pressure_MPa:.3g} MPa at a sliding "
            f"speed of {heat.sliding_speed_m_s:.3g} m/s ({heat.sliding_speed_m_s * 60:.3g} "
            f"m/min; p·v = {heat.pv_MPa_m_s:.3g} MPa·m/s) is above the safe "
            f"{heat.safe_pressure_Pa / 1e6:.3g} MPa of Shigley's Table 8-4 "
            f"({heat.safe_pressure_row}); a slower screw (a reduction stage), a longer nut "
            "or a ball screw"
        )
    if heat.temperature_rise_K > NUT_ALLOWED_RISE_K:
        warnings.append(
            f"the nut overheats: {heat.mean_friction_power_W:.3g} W of thread friction on "
            f"average ({heat.mean_basis}) through its {heat.surface_m2 * 1e4:.3g} cm² surface "
            f"gives a steady rise of {heat.temperature_rise_K:.3g} K, above the "
            f"{NUT_ALLOWED_RISE_K:g} K allowed (natural convection, "
            f"h = {NUT_FILM_COEFFICIENT:g} W/(m²·K), nut body "
            f"{NUT_OUTER_DIAMETER_RATIO:g}·d; the screw's own cooling neglected)"
        )
    return warnings


def screw_checks(
    req: Requirements,
    ev: ThreadEvaluation,
    sel: MotorEvaluation,
    thrust: ThrustFace | None,
    sf: ServiceFactor,
    cat: Catalogs,
) -> tuple[list[Check], list[str]]:
    """The whirling speed and the thrust bearing's static load as checks; the thrust face
    left out, and the nut's wear and heat, as warnings where they need a word."""
    n_work = sel.working_speed_rpm or ev.speed_rpm
    lin = req.linear
    checks, warnings = _thrust_checks(ev, thrust, lin.force_N, sf, lin.emergency_stop_force_N)
    warnings += _nut_warnings(ev, nut_heat(req, ev, n_work))
    return [_whirl_check(req, ev, n_work, cat), *checks], warnings
