"""The linear actuator advice: induction motor + sliding screw–nut (seed 001).

Orchestration only: the rules in ``rules/`` choose, the functions in ``advisor/calc`` compute.
:func:`advise_linear` reads as its steps; the joint choice of thread and motor is in
:mod:`.choice`, the motor's plan in :mod:`.motor`, the duty cycle in :mod:`.duty`, the
screw's whirling, thrust-bearing and nut checks in :mod:`.screw_checks`, and the report
tables built from the evaluations in :mod:`.tables`.
"""

import math
from collections.abc import Callable, Iterable
from typing import NamedTuple

from advisor.applications.linear.choice import catalog_parts, choice_options, thread_screens
from advisor.applications.linear.holding import holding_checks
from advisor.applications.linear.motor import MotorPlan, motor_evaluation, plan_motor
from advisor.applications.linear.no_drive import power_reasons
from advisor.applications.linear.report import LinearDesignOut
from advisor.applications.linear.screw_checks import screw_checks
from advisor.applications.linear.tables import motor_out, screw_out
from advisor.calc.induction import synchronous_speed_rpm
from advisor.calc.one_way import NO_DEVICE, Passage, size
from advisor.calc.screw import WHIRL_ALLOWED_SHARE
from advisor.calc.service_factor import service_factor
from advisor.calc.sizing import (
    Check,
    MotorEvaluation,
    ScrewDemand,
    ScrewMaterial,
    ThreadEvaluation,
    ThreadScreen,
    ThrustFace,
)
from advisor.core.cite import cite
from advisor.core.errors import InfeasibleError, InputError
from advisor.core.ignored import IGNORED_PREFIX
from advisor.core.reading import Requirements
from advisor.core.report import margin_text
from advisor.core.rulebook import Trace
from advisor.duty.report import DutyOut
from catalogs import Catalogs
from catalogs.threads import ThreadProfile
from rules import induction as induction_rules
from rules import screw as screw_rules


def _material(
    req: Requirements, cat: Catalogs, trace: Trace
) -> tuple[ScrewMaterial, tuple[float, float]]:
    s = req.screw
    pair = cat.pair(s.material_pair)
    lo, hi = pair.friction_range(s.lubrication)
    f = trace.apply(
        screw_rules.friction_coefficient,
        s.friction_coefficient,
        s.material_pair,
        s.lubrication,
        lo,
        hi,
    )
    steel = cat.steel(s.screw_steel)
    m = cat.materials
    return (
        ScrewMaterial(
            friction_coefficient=f,
            friction_low=min(lo, f),
            allowable_pressure_Pa=pair.allowable_pressure_MPa * 1e6,
            yield_strength_Pa=steel.yield_strength_MPa * 1e6,
            elastic_modulus_Pa=steel.elastic_modulus_MPa * 1e6,
            yield_safety_factor=m.strength.yield_safety_factor,
            nut_height_ratio_min=m.nut.height_ratio_min,
            nut_height_ratio_max=m.nut.height_ratio_max,
            nut_max_turns=m.nut.max_turns,
        ),
        (lo, hi),
    )


def thrust_face(req: Requirements, cat: Catalogs) -> ThrustFace | None:
    """The thrust face of ``[screw.thrust]``; None where it is unknown."""
    t = req.screw.thrust
    if t.kind == "collar":
        return ThrustFace("collar", t.friction_coefficient, t.mean_diameter_mm * 1e-3)
    if t.kind == "bearing":
        b = cat.bearing(t.bearing)
        if b is None:
            known = ", ".join(sorted(x.designation for x in cat.bearings))
            raise InputError(
                f"screw.thrust.bearing = {t.bearing!r}: not a bearing of the catalog ({known})"
            )
        k = cat.bearing_friction[b.friction]
        return ThrustFace(
            "bearing", bearing=b, constants=k, viscosity_mm2_s=t.lubricant_viscosity_mm2_s
        )
    return None


def _one_way(
    req: Requirements,
    trace: Trace,
    ev: ThreadEvaluation,
    thread: str,
    friction_low: float,
    drive_torque: float,
    motor_power_W: float,
):
    """Seed 004 for a screw drive: no device when the screw holds with margin, otherwise one
    at the motor side carrying the torque that drives the screw (thread and thrust face) — at
    the rated force or, if larger, at the emergency stop's momentary force, times the service
    factor; the check that it holds the load with the power off states the smaller torque
    the load gives it back through the screw (:mod:`advisor.applications.linear.holding`).
    Its power share is over the motor's mechanical
    power at the working point, ``motor_power_W``."""
    from advisor.one_way.advice import choose_device
    from advisor.one_way.report import OneWayOut
    from rules import one_way as ow_rules

    holds = trace.apply(ow_rules.screw_holds, ev.self_locking_at_low_friction, thread, friction_low)
    if holds:
        return OneWayOut.make(
            type="none",
            location="none",
            torque_Nm=ev.torque_Nm,
            basis=f"{thread} is self-locking over the whole friction range of the pair",
        ), _unused_device(req, thread, friction_low)
    lin, f_b = req.linear, service_factor(getattr(req, "design", None)).value
    force = max(lin.force_N, lin.emergency_stop_force_N or 0.0)
    sized = device_torque(req, drive_torque)
    device, warnings = choose_device(req.one_way, sized, sized, motor_power_W, trace)
    if force != lin.force_N or f_b != 1.0:
        what = "the emergency stop's" if force != lin.force_N else "the rated"
        device = device.replace(
            basis=f"{device.basis}; sized for {what} {force:g} N × f_B = {f_b:g}"
        )
    warnings.insert(
        0,
        f"{thread} is not self-locking at the low end of the friction range (f = "
        f"{friction_low:g}): {ow_rules.with_article(device.type)} at the motor side holds the load",
    )
    return device.replace(output_side=None), warnings


def _unused_device(req: Requirements, thread: str, friction_low: float) -> list[str]:
    """A [one_way] table given while the screw holds by itself is said as ignored, as one
    given with hold_without_power = false is: the table chooses the device where one is
    needed, and a device in series with a self-locking screw would only cost its efficiency
    (the worm's 0.33), mass and power (OW-03; seed 004 judges self-locking gears not
    rational)."""
    if "one_way" not in req.model_fields_set:
        return []
    return [
        f"{IGNORED_PREFIX}the [one_way] table (type = {req.one_way.type!r}), because "
        f"{thread} is self-locking over the whole friction range of the pair (down to f = "
        f"{friction_low:g}): the screw holds the load and no device is chosen (OW-03)"
    ]


def device_torque(req: Requirements, drive_torque_Nm: float) -> float:
    """The torque a holding device at the motor side is sized for: the torque that drives
    the screw (thread and thrust face) at the rated force or, if larger, at the emergency
    stop's momentary force, times the service factor f_B (the screw's torques grow with the
    force)."""
    lin, f_b = req.linear, service_factor(getattr(req, "design", None)).value
    force = max(lin.force_N, lin.emergency_stop_force_N or 0.0)
    return drive_torque_Nm * force / lin.force_N * f_b


def screw_demand(
    req: Requirements, cat: Catalogs, trace: Trace
) -> tuple[ScrewDemand, tuple[float, float]]:
    """What the requirement asks of every thread (rules SCR-01 to SCR-03 decide the
    transmission, the friction coefficient and its model) and the pair's friction range."""
    lin, s = req.linear, req.screw
    trace.apply(screw_rules.transmission_type, lin.force_N)
    material, f_range = _material(req, cat, trace)
    model = trace.apply(screw_rules.friction_model, s.friction_model)
    demand = ScrewDemand(
        force_N=lin.force_N,
        stroke_m=lin.stroke_m,
        travel_time_s=lin.travel_time_s,
        span_m=lin.support_span_m,
        end_fixity=lin.end_fixity,
        buckling_safety_factor=lin.buckling_safety_factor,
        friction_model=model,
        material=material,
        thrust=thrust_face(req, cat),
        service_factor=service_factor(getattr(req, "design", None)).value,
        stop_force_N=lin.emergency_stop_force_N or 0.0,
    )
    return demand, f_range


def _thread_in_catalog(thread: str | None, cat: Catalogs) -> None:
    """An imposed thread must be one of the standard's; the nearest two are named."""
    if thread is None or cat.thread(thread) is not None:
        return
    d = float(thread[2:].split("x")[0])
    near = sorted({t.d_mm for t in cat.threads}, key=lambda x: abs(x - d))[:2]
    nearest = ", ".join(t.name for t in cat.threads if t.d_mm in near)
    raise InputError(
        f"screw.thread = {thread!r}: not a thread of GOST 24738-81 "
        f"(Tr8 … Tr100 with the pitches the standard gives); nearest: {nearest}"
    )


def _imposed_thread_passes(
    screens: list[ThreadScreen], imposed: str | None, demand: ScrewDemand
) -> None:
    """An imposed thread that fails its checks with every number of starts ends the advice
    with the failed checks of the starts that fail fewest."""
    if imposed is None:
        return
    mine = [screen for screen in screens if screen.name == imposed]
    if any(screen.passed for screen in mine):
        return
    ev = min((demand.evaluate(x.thread, x.starts) for x in mine), key=lambda e: len(e.failed))
    raise InfeasibleError(
        f"no feasible design: the imposed thread {imposed} fails its checks",
        [_describe(c) for c in ev.failed],
    )


def _pole_options(
    options: list[screw_rules.DriveOption],
    pole_pairs: Iterable[int],
    imposed: str | None,
    hold: bool,
    frequency_Hz: float,
) -> list[induction_rules.PoleOption]:
    """The best drive option of each pole count (of the imposed thread, if one is), as rule
    IM-01 compares them."""
    firsts: dict[int, tuple[tuple, screw_rules.DriveOption]] = {}
    order = screw_rules.drive_order_key(hold)
    for o in options:  # each option's order once; a later one only if strictly first, as min
        if imposed is None or o.thread == imposed:
            key, held = order(o), firsts.get(o.pole_pairs)
            if held is None or key < held[0]:
                firsts[o.pole_pairs] = (key, o)
    out = []
    for pp in pole_pairs:
        best = firsts[pp][1] if pp in firsts else None
        out.append(
            induction_rules.PoleOption(
                pp,
                synchronous_speed_rpm(frequency_Hz, pp),
                best.label if best else None,
                best.motor_model if best else None,
                best.rated_power_kW if best else None,
                best.travel_time_s if best else None,
            )
        )
    return out


class Drive(NamedTuple):
    """The chosen screw as the motor sees it: the torque that moves the load (thread and
    thrust face), the same at the motor (through the one-way device's η), the device in
    the chain where one holds the load, and the motor's plan; the device's own inertia, which
    turns with the rotor (0 without a device)."""

    screw: ThreadEvaluation
    at_motor: ThreadEvaluation
    passage: Passage | None
    plan: MotorPlan
    device_inertia_kgm2: float = 0.0


def _drive(
    req: Requirements, ev: ThreadEvaluation, motor_model: str, cat: Catalogs, trace: Trace
) -> Drive:
    """The torque the chosen motor gives, and its plan (rules IM-02, IM-03). The one-way
    device is chosen at the torque it is sized for, as :func:`_one_way` sizes it, so that
    the device in the chain is the one reported, with its inertia."""
    passage, j_device = None, 0.0  # the one-way device in the chain, where one holds the load
    if req.application.hold_without_power and not ev.self_locking_at_low_friction:
        from advisor.one_way.advice import device_passage

        sized = device_torque(req, ev.drive_torque_Nm)
        passage = device_passage(req.one_way, sized, sized)
        device = size(passage.type, sized, req.one_way.rollers)
        j_device = device.inertia_kgm2 if device is not None else 0.0
    # the torque that moves the load: the thread's and the thrust face's; the motor drives
    # the screw through the device: it gives that torque over the device's η
    drive = ev._replace(torque_Nm=ev.drive_torque_Nm, thrust_torque_Nm=0.0)
    at_motor = (
        drive if passage is None else drive._replace(torque_Nm=drive.torque_Nm / passage.efficiency)
    )
    motor = next(m for m in cat.motors if m.model == motor_model)
    plan = plan_motor(at_motor, motor, cat, trace)
    return Drive(drive, at_motor, passage, plan, j_device)


def _size_for_duty(
    req: Requirements, ev: ThreadEvaluation, chain: Drive, cat: Catalogs, trace: Trace
) -> tuple[Drive, DutyOut | None, list[Check], list[str]]:
    """The motor sized for the duty cycle, where one is given: the drive with the cycle's
    motor, the duty table, its checks and its warnings."""
    if req.duty is None:
        return chain, None, [], []
    from advisor.applications.linear.duty import advise_duty

    holder = "screw" if ev.self_locking_at_low_friction else None
    holder = holder or ("one_way" if req.application.hold_without_power else None)
    plan = chain.plan
    duty, motor, checks, warnings = advise_duty(
        req,
        chain.screw,
        plan.selected,
        cat,
        holder,
        trace,
        chain.passage or NO_DEVICE,
        chain.device_inertia_kgm2,
    )
    if motor is not plan.selected:
        power = motor.rated_power_kW
        evaluations = {**plan.evaluations, power: motor_evaluation(motor, chain.at_motor)}
        chain = chain._replace(plan=plan._replace(selected=motor, evaluations=evaluations))
    return chain, duty, checks, warnings


def _motor_checks(
    chain: Drive, sel: MotorEvaluation, thrust: ThrustFace | None, cat: Catalogs, time_s: float
) -> list[Check]:
    """The motor's rated and starting torque against the torque it gives, and the travel
    time at its working speed."""
    screw_load = "the screw torque" if thrust is None else "the screw and thrust-face torque"
    passage, torque = chain.passage, chain.at_motor.torque_Nm
    demand = (
        screw_load
        if passage is None or passage.efficiency == 1.0
        else f"{screw_load} through the {passage.type.replace('_', ' ')} "
        f"(η {passage.efficiency:.3g})"
    )
    rated = cite("gost-12139-84", "rated powers") + screw_rules.SEED_001
    starting = cat.cite_rows(cat.motor_sources, chain.plan.selected.source)
    return [
        Check(
            "motor_rated_torque",
            f"motor rated torque against {demand}",
            torque,
            sel.rated_torque_Nm,
            "N·m",
            sel.rated_torque_margin,
            rated,
        ),
        Check(
            "motor_starting_torque",
            f"motor starting torque against {demand}",
            torque,
            sel.starting_torque_Nm,
            "N·m",
            sel.starting_torque_margin,
            starting.with_note("catalog starting torque ratio"),
        ),
        Check(
            "travel_time",
            "travel time at the motor's working speed",
            sel.travel_time_s or math.inf,
            time_s,
            "s",
            time_s / (sel.travel_time_s or math.inf),
            screw_rules.SEED_001,
        ),
    ]


def _choose_drive(
    req: Requirements, cat: Catalogs, demand: ScrewDemand, trace: Trace
) -> tuple[screw_rules.DriveOption, list[ThreadScreen], list[screw_rules.DriveOption]]:
    """The joint choice of thread, starts and motor (rule SCR-04) from the screen of every
    thread; the screens and the options it read."""
    s, hold = req.screw, req.application.hold_without_power
    screens = thread_screens(req, cat, demand)
    options = choice_options(screens, catalog_parts(cat).lines, s.thread, hold)
    _imposed_thread_passes(screens, s.thread, demand)
    chosen = trace.apply(screw_rules.choose_drive, options, hold, s.thread, s.starts)
    if chosen is None:
        raise _no_drive(screens, s.thread, cat, demand.force_N, demand.evaluate)
    return chosen, screens, options


def _holding_device(
    req: Requirements,
    ev: ThreadEvaluation,
    thread: str,
    chain: Drive,
    demand: ScrewDemand,
    trace: Trace,
    sel: MotorEvaluation,
):
    """The one-way device of a drive that must hold its load (seed 004), sized for the
    torque that passes it: the screw's (thread and thrust face), the motor's before the
    device's own loss; its power share over the motor's mechanical power at the working
    point, M·ω of the motor (as ``working_power_kW``)."""
    eta_d = chain.passage.efficiency if chain.passage is not None else 1.0
    torque = chain.at_motor.torque_Nm * eta_d
    speed_rpm = sel.working_speed_rpm or 0.0
    power_W = chain.at_motor.torque_Nm * speed_rpm * math.pi / 30.0
    return _one_way(req, trace, ev, thread, demand.material.friction_low, torque, power_W)


def _paper_friction_warning(ev: ThreadEvaluation) -> str:
    """The paper's friction formula in use: the standard one's torque beside it."""
    return (
        "friction_model = 'paper' uses seed 001's f/cos(ψ/2); the standard f/cos(α/2) "
        f"gives {ev.torque_standard_Nm:.4g} N·m instead of {ev.torque_paper_Nm:.4g} N·m."
    )


def advise_linear(
    req: Requirements, cat: Catalogs, trace: Trace
) -> tuple[LinearDesignOut, list[Check], list[str]]:
    """Seed 001's linear actuator: the thread and motor chosen together, the motor sized for
    the duty, the one-way device where the load must hold; the design, checks, warnings."""
    lin, s = req.linear, req.screw
    assert lin is not None  # guaranteed by Requirements validation
    hold = req.application.hold_without_power
    demand, f_range = screw_demand(req, cat, trace)
    _thread_in_catalog(s.thread, cat)
    chosen, screens, options = _choose_drive(req, cat, demand, trace)
    screen = next(x for x in screens if x.name == chosen.thread and x.starts == chosen.starts)
    ev = demand.evaluate(screen.thread, chosen.starts)
    trace.apply(
        screw_rules.holding, hold, ev.self_locking, ev.self_locking_at_low_friction, chosen.label
    )
    freq = req.motor.supply_frequency_Hz
    poles = _pole_options(options, catalog_parts(cat).fits, s.thread, hold, freq)
    trace.apply(induction_rules.choose_pole_pairs, chosen.pole_pairs, ev.speed_rpm, poles)
    chain = _drive(req, ev, chosen.motor_model, cat, trace)
    chain, duty, duty_checks, warnings = _size_for_duty(req, ev, chain, cat, trace)
    plan = chain.plan
    sel = plan.evaluations[plan.selected.rated_power_kW]
    assert sel is not None
    one_way, hold_checks = None, []
    if hold:
        one_way, device_warnings = _holding_device(req, ev, chosen.label, chain, demand, trace, sel)
        warnings += device_warnings
        friction_low = demand.material.friction_low
        hold_checks = holding_checks(req, ev, one_way, chosen.label, friction_low)
    if s.friction_model == "paper":
        warnings.append(_paper_friction_warning(ev))
    advisor_choice = trace.find("SCR-04").inputs.get("advisor_choice")
    design = LinearDesignOut.make(
        screw=screw_out(ev, req, demand.material, f_range, advisor_choice, sel, cat),
        motor=motor_out(plan, chain.at_motor, cat, freq),
        one_way=one_way,
        duty=duty,
    )
    checks = [*ev.checks, *_motor_checks(chain, sel, demand.thrust, cat, lin.travel_time_s)]
    if sel.travel_time_s and sel.travel_time_s < FAST_SHARE * lin.travel_time_s:
        warnings.append(_too_fast(chain.at_motor, sel, plan, screens, cat, lin.travel_time_s))
    sf = service_factor(getattr(req, "design", None))
    own_checks, own_warnings = screw_checks(req, ev, sel, demand.thrust, sf, cat)
    return design, checks + own_checks + duty_checks + hold_checks, warnings + own_warnings


#: A stroke made in less than this share of the time asked for is flagged.
FAST_SHARE = 0.7

#: Efficiency assumed for one spur reduction stage, in the saving a reducer would bring.
REDUCER_EFFICIENCY = 0.97


def _too_fast(
    ev: ThreadEvaluation,
    sel: MotorEvaluation,
    plan: MotorPlan,
    screens: list[ThreadScreen],
    cat: Catalogs,
    travel_time_s: float,
) -> str:
    """Say that the direct drive is much faster than asked, whether any lead would suit a
    motor speed step, and what a reduction stage would save."""
    assert sel.travel_time_s is not None and sel.working_speed_rpm is not None
    v_mm_s = ev.revolutions * ev.thread.pitch_mm * ev.starts / travel_time_s
    slowest = min(cat.motors, key=lambda m: m.rated_speed_rpm)
    lead_needed_mm = v_mm_s * 60.0 / slowest.rated_speed_rpm
    passing = [e for e in screens if e.passed]
    finest = min(passing, key=lambda e: e.thread.pitch_mm * e.starts)
    finest_lead = finest.thread.pitch_mm * finest.starts
    finest_name = screw_rules.thread_label(finest.thread.name, finest.starts)
    text = (
        f"the motor makes the stroke in {sel.travel_time_s:.3g} s, much faster than the "
        f"{travel_time_s:g} s asked for: an induction motor on 50 Hz has no speed between its "
        "pole steps"
    )
    if lead_needed_mm < finest_lead:
        text += (
            f". No lead suits: even the slowest catalog motor ({slowest.rated_speed_rpm:g} rpm) "
            f"would need a lead of {lead_needed_mm:.3g} mm, and the finest that passes the "
            f"checks is {finest_lead:g} mm ({finest_name})"
        )
    ratio = sel.working_speed_rpm / ev.speed_rpm
    need_kW = plan.required_power_kW / REDUCER_EFFICIENCY
    smaller = [m for m in cat.motors if m.rated_power_kW >= need_kW]
    if smaller:
        best = min(smaller, key=lambda m: (m.rated_power_kW, m.rated_torque_Nm))
        if best.rated_power_kW < plan.selected.rated_power_kW:
            text += (
                f". A reduction stage of about {ratio:.3g}:1 (η = {REDUCER_EFFICIENCY:g} "
                f"assumed) would let a {best.rated_power_kW:g} kW motor "
                f"({plan.required_power_kW / REDUCER_EFFICIENCY:.3g} kW needed) drive the "
                f"same screw instead of {plan.selected.rated_power_kW:g} kW"
            )
    return text + "."


def _describe(c: Check) -> str:
    """A check in words; under a service factor the demand is stated with it, so that the
    margin reads as limit / (factor · value)."""
    unit = f" {c.unit}" if c.unit else ""
    factor = f" × service factor {c.factor:g}" if c.factor else ""
    return (
        f"{c.name}: {c.value:.4g}{unit}{factor} against the limit {c.limit:.4g}{unit} "
        f"(margin {margin_text(c.margin)})"
    )


def _remedy(force_N: float, failed_ids: set[str]) -> str:
    # a check at the emergency stop's force has the rated check's cures
    failed = {i.removesuffix("_emergency_stop") for i in failed_ids}
    cures = []
    if "buckling" in failed:
        cures.append("a shorter span between supports or stiffer end fixity")
    if "core_stress" in failed:
        cures.append("a stronger screw steel (40X)")
    if failed & {"nut_pressure", "nut_height", "nut_turns"}:
        cures.append("a nut material that allows a higher flank pressure")
    return f"a force of {force_N:g} N needs " + ", or ".join(cures)


def _no_drive(
    screens: list[ThreadScreen],
    imposed: str | None,
    cat: Catalogs,
    force_N: float,
    evaluate: Callable[[ThreadProfile, int], ThreadEvaluation],
) -> InfeasibleError:
    """Why no thread and motor could be chosen: the checks, or the motors."""
    pool = [ev for ev in screens if imposed is None or ev.name == imposed]
    passing = [ev for ev in pool if ev.passed]
    if not passing:
        # every thread fails a check: the largest one shows what limits the design
        big = max(pool, key=lambda e: (e.thread.d_mm, e.thread.pitch_mm, -e.starts))
        biggest = evaluate(big.thread, big.starts)
        return InfeasibleError(
            "no feasible design: no GOST 24738-81 thread (Tr8 … Tr100) passes every check",
            [f"{biggest.thread.name}: {_describe(c)}" for c in biggest.failed]
            + [_remedy(force_N, {c.id for c in biggest.failed})],
        )
    speeds = sorted(ev.speed_rpm for ev in passing)
    fastest = max(m.rated_speed_rpm for m in cat.motors)
    names = {ev.name for ev in passing}
    reasons = [
        f"{len(names)} threads pass the strength checks; they need {speeds[0]:.4g} … "
        f"{speeds[-1]:.4g} rpm at the screw"
    ]
    whirl = [ev for ev in passing if ev.speed_rpm > ev.max_speed_rpm]
    if whirl:
        reasons.append(
            f"{len(whirl)} of them would turn above {100 * WHIRL_ALLOWED_SHARE:g} % of their "
            "whirling speed: a shorter span, a stiffer end fixity or a coarser lead"
        )
    if speeds[0] > fastest:
        reasons.append(
            f"the fastest 50 Hz motor of the catalog runs at {fastest:g} rpm: allow a longer "
            "travel time or use more thread starts"
        )
    else:
        reasons += power_reasons(passing, cat)
    return InfeasibleError(
        "no feasible design: no catalog motor can drive a thread that passes its checks",
        reasons,
    )
