"""The linear actuator advice: induction motor + sliding screw–nut (seed 001).

Orchestration only: the rules in ``rules/`` choose, the functions in ``advisor/calc`` compute.
"""

import math
from bisect import bisect_left
from collections.abc import Callable, Iterable
from typing import NamedTuple

from advisor.applications.linear.report import (
    BucklingOut,
    CurveOut,
    InductionMotorOut,
    LinearDesignOut,
    MotorCandidateOut,
    NutOut,
    ScrewOut,
    ThrustOut,
    back_driving_words,
)
from advisor.calc import one_way as one_way_calc
from advisor.calc import screw as screw_calc
from advisor.calc.induction import synchronous_speed_rpm
from advisor.calc.one_way import NO_DEVICE, Passage
from advisor.calc.screw import (
    END_FIXITY_FACTOR,
    NUT_ALLOWED_RISE_K,
    NUT_FILM_COEFFICIENT,
    NUT_OUTER_DIAMETER_RATIO,
    WHIRL_ALLOWED_SHARE,
    WHIRL_EIGENVALUE,
)
from advisor.calc.service_factor import ServiceFactor, service_factor
from advisor.calc.sizing import (
    STEEL_DENSITY_KG_M3,
    Check,
    MotorEvaluation,
    MotorFit,
    ScrewDemand,
    ScrewMaterial,
    ThreadEvaluation,
    ThreadGeometry,
    ThreadScreen,
    ThrustFace,
    drive_working_speed,
    evaluate_motor,
    fit_motor,
    thread_geometry,
)
from advisor.core.cite import cite, text
from advisor.core.errors import InfeasibleError, InputError
from advisor.core.reading import Requirements
from advisor.core.rulebook import Trace
from advisor.duty.report import DutyOut
from catalogs import Catalogs
from catalogs.rows import InductionMotor
from catalogs.threads import ThreadProfile
from rules import induction as induction_rules
from rules import screw as screw_rules


class MotorLine(NamedTuple):
    """The catalog's motors of one pole count, in order of rated power, fitted, with the
    running maximum along the line of the smaller of rated and starting torque (``reach``)."""

    pole_pairs: int
    fits: list[MotorFit]
    reach: list[float]


def motor_line(pole_pairs: int, fits: list[MotorFit]) -> MotorLine:
    """A motor line with its reach (see :func:`drive_options`)."""
    reach, top = [], -math.inf
    for fit in fits:
        top = max(top, min(fit.rated_torque_Nm, fit.starting_torque_Nm))
        reach.append(top)
    return MotorLine(pole_pairs, fits, reach)


class CatalogParts(NamedTuple):
    """What the linear advice derives from a catalog alone, whatever the requirement."""

    threads: list[ThreadGeometry]  # of cat.threads, in order
    fits: dict[int, list[MotorFit]]  # by pole pairs, lines in order of rated power
    lines: list[MotorLine]


#: Catalog parts by ``id`` of the catalog, with the catalog itself kept alive beside them so
#: that its id cannot be reused by another catalog (a user catalog directory is another one).
_PARTS: dict[int, tuple[Catalogs, CatalogParts]] = {}
_PARTS_MAX = 8


def catalog_parts(cat: Catalogs) -> CatalogParts:
    """The thread geometries and fitted motor lines of ``cat``, computed once per catalog:
    they do not depend on the requirement."""
    held = _PARTS.get(id(cat))
    if held is not None and held[0] is cat:
        return held[1]
    fits = {pp: [fit_motor(m) for m in cat.motors_with_poles(2 * pp)] for pp in (1, 2, 3, 4)}
    fits = {pp: line for pp, line in fits.items() if line}
    parts = CatalogParts(
        [thread_geometry(t) for t in cat.threads],
        fits,
        [motor_line(pp, line) for pp, line in fits.items()],
    )
    if len(_PARTS) >= _PARTS_MAX:
        _PARTS.clear()
    _PARTS[id(cat)] = (cat, parts)
    return parts


class MotorPlan(NamedTuple):
    pole_pairs: int
    required_power_kW: float  # load torque × required screw speed
    band_kW: list[float]
    evaluations: dict[float, MotorEvaluation | None]  # by rated power; None: not in catalog
    selected: InductionMotor


STARTS_FREE = (1, 2, 3, 4)


def line_option(
    ev: ThreadScreen, line: MotorLine, max_power_kW: float = math.inf
) -> screw_rules.DriveOption | None:
    """The smallest motor of ``line`` that drives the thread of ``ev`` directly, as a drive
    option; ``None`` when none does (or none of at most ``max_power_kW``: the line is in
    order of rated power, so the search stops at the first motor above it).

    A motor whose rated or starting torque is below the screw torque cannot drive it (the
    first test of :func:`drive_working_speed`); the line's reach is the running maximum of
    the smaller of the two, and a bisection on it skips those motors at once instead of
    testing them one by one (the joint choice screens every thread, so this runs often)."""
    torque, fits = ev.motor_torque_Nm, line.fits
    for i in range(bisect_left(line.reach, torque), len(fits)):
        fit = fits[i]
        if fit.motor.rated_power_kW > max_power_kW:
            return None
        n = drive_working_speed(fit, torque, ev.speed_rpm)
        if n is None or n > ev.max_speed_rpm:  # too slow, or above the whirling limit
            continue
        m, thread = fit.motor, ev.thread
        return screw_rules.DriveOption(  # positional, in the order of its fields (faster)
            ev.name,  # thread
            thread.d_mm,
            thread.pitch_mm,
            ev.starts,
            ev.self_locking_at_low_friction,
            ev.torque_Nm,  # screw_torque_Nm
            m.model,
            line.pole_pairs,
            m.rated_power_kW,
            fit.rated_torque_Nm,
            60.0 * ev.revolutions / n,  # travel_time_s
        )
    return None


def drive_options(
    screens: list[ThreadScreen], lines: list[MotorLine]
) -> list[screw_rules.DriveOption]:
    """Every (thread, starts) that passes its checks, with the smallest motor of each pole
    count that drives it directly (:func:`line_option`)."""
    out = []
    for ev in screens:
        if ev.passed:
            for line in lines:
                option = line_option(ev, line)
                if option is not None:
                    out.append(option)
    return out


def first_drive_option(
    screens: list[ThreadScreen], lines: list[MotorLine], hold: bool
) -> screw_rules.DriveOption | None:
    """The option of :func:`drive_options` that comes first in the order of
    :func:`rules.screw.drive_order` (the first of equals, as ``min`` takes it), found
    without building most of the others.

    Exact: the order compares the holding flag, then the motor's rated power, first. The
    option of a thread on a line uses a motor at or after the line's bisection index, and a
    line is in order of rated power, so that motor's rated power is at least the one at the
    index. A (thread, line) whose flag and least possible rated power already compare above
    the best option found cannot come first, and is skipped; with the same flag, the search
    along the line stops above the best one's rated power for the same reason. Every other
    option is built by :func:`line_option` and compared by the full order, in the order of
    :func:`drive_options`, a later one replacing the best only when it comes strictly
    first."""
    best, best_key = None, None
    for ev in screens:
        if not ev.passed:
            continue
        flag = not ev.self_locking_at_low_friction if hold else False
        for line in lines:
            i = bisect_left(line.reach, ev.motor_torque_Nm)
            if i == len(line.fits):
                continue  # no motor of the line drives it
            cap = math.inf
            if best_key is not None:
                if (flag, line.fits[i].motor.rated_power_kW) > (best_key[0], best_key[1][0]):
                    continue
                if flag == best_key[0]:
                    cap = best_key[1][0]
            option = line_option(ev, line, cap)
            if option is None:
                continue
            key = screw_rules.drive_order(option, hold)
            if best_key is None or key < best_key:
                best, best_key = option, key
    return best


def choice_options(
    screens: list[ThreadScreen], lines: list[MotorLine], imposed: str | None, hold: bool
) -> list[screw_rules.DriveOption]:
    """The drive options the joint choice (rule SCR-04) reads. With the thread free, all of
    them (it counts them and ranks them all). With a thread imposed, the imposed thread's
    options, and of the others only the one the advisor would choose itself
    (:func:`first_drive_option`): the rule ranks, counts and lists the imposed thread's
    options only, and names the best of all as the advisor's own choice."""
    if imposed is None:
        return drive_options(screens, lines)
    options = drive_options([ev for ev in screens if ev.name == imposed], lines)
    own = first_drive_option(screens, lines, hold)
    if own is not None and own.thread != imposed:
        options.append(own)
    return options


def plan_motor(
    ev: ThreadEvaluation, motor: InductionMotor, cat: Catalogs, frequency_Hz: float, trace: Trace
) -> MotorPlan:
    """The chosen motor's pole pairs, its rated-power band and the evaluated neighbours."""
    pp = motor.pole_pairs
    # the band shows one motor per rated power; the chosen one must be the one at its power
    # (a user catalog may hold another motor of the same rating and poles)
    line = {m.rated_power_kW: m for m in cat.motors_with_poles(2 * pp)}
    line[motor.rated_power_kW] = motor

    def evaluate(power: float) -> MotorEvaluation | None:
        m = line.get(power)
        return None if m is None else evaluate_motor(m, ev.torque_Nm, ev.speed_rpm, ev.revolutions)

    sel = evaluate(motor.rated_power_kW)
    assert sel is not None and sel.working_speed_rpm is not None
    series = cat.power_series(2 * pp)  # a user motor may be off the GOST series
    p_req_kW = ev.torque_Nm * ev.speed_rpm * math.pi / 30.0 / 1e3
    p_work_kW = ev.torque_Nm * sel.working_speed_rpm * math.pi / 30.0 / 1e3
    band = trace.apply(
        induction_rules.rated_power_band, p_req_kW, p_work_kW, motor.rated_power_kW, series
    )
    evaluations = {power: evaluate(power) for power in band}
    # IM-03 looks at the line from the lower neighbour up to the chosen motor: the joint
    # choice took the first one that drives the screw, so the rule must agree with it.
    options = []
    for m in sorted(line.values(), key=lambda m: m.rated_power_kW):
        if m.rated_power_kW < band[0] or m.rated_power_kW > motor.rated_power_kW:
            continue
        e = evaluations.get(m.rated_power_kW) or evaluate(m.rated_power_kW)
        assert e is not None
        options.append(
            induction_rules.MotorOption(
                m.rated_power_kW, m.model, tuple(e.problems), e.rated_torque_margin
            )
        )
    model = trace.apply(induction_rules.choose_motor, options)
    assert model == motor.model, (model, motor.model)
    return MotorPlan(pp, p_req_kW, band, evaluations, motor)


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


def _device_efficiency(req: Requirements) -> float:
    """The driving efficiency of the one-way device the requirement asks for, known before
    the thread and the motor are chosen: the motor's choice must see it. 'auto' chooses
    between the two clutches (OW-02), both of η = 1."""
    kind = req.one_way.type
    return 1.0 if kind == "auto" else one_way_calc.passage(kind).efficiency


def _through_device(screens: list[ThreadScreen], efficiency: float) -> list[ThreadScreen]:
    """The screens with the device's efficiency on every thread that needs the device (one
    not self-locking at the low end of its friction range): their motor gives 1/η times the
    screw torque."""
    if efficiency == 1.0:
        return screens
    return [
        screen._replace(device_efficiency=efficiency)
        if not screen.self_locking_at_low_friction
        else screen
        for screen in screens
    ]


def _one_way(req, trace: Trace, ev, thread: str, friction_low: float, drive_torque: float):
    """Seed 004 for a screw drive: no device when the screw holds with margin, otherwise one
    at the motor side carrying the torque that drives the screw (thread and thrust face) — at
    the rated force or, if larger, at the emergency stop's momentary force, times the service
    factor: the device holds the stop by its sizing (a check of it against the same torque
    could only state a margin of 1.000)."""
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
        ), []
    lin, f_b = req.linear, service_factor(getattr(req, "design", None)).value
    stop = lin.emergency_stop_force_N
    force = max(lin.force_N, stop or 0.0)
    sized = drive_torque * force / lin.force_N * f_b  # the screw's torques grow with the force
    power = drive_torque * ev.speed_rpm * math.pi / 30.0
    device, warnings = choose_device(req.one_way, sized, sized, power, trace)
    if force != lin.force_N or f_b != 1.0:
        what = "the emergency stop's" if force != lin.force_N else "the rated"
        device = device.replace(
            basis=f"{device.basis}; sized for {what} {force:g} N × f_B = {f_b:g}"
        )
    warnings.insert(
        0,
        f"{thread} is not self-locking at the low end of the friction range (f = "
        f"{friction_low:g}): a {device.type.replace('_', ' ')} at the motor side holds the load",
    )
    return device.replace(output_side=None), warnings


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
    pool = [o for o in options if imposed is None or o.thread == imposed]
    out = []
    for pp in pole_pairs:
        best = min(
            (o for o in pool if o.pole_pairs == pp),
            key=lambda o: screw_rules.drive_order(o, hold),
            default=None,
        )
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
    the chain where one holds the load, and the motor's plan."""

    screw: ThreadEvaluation
    at_motor: ThreadEvaluation
    passage: Passage | None
    plan: MotorPlan


def _drive(
    req: Requirements, ev: ThreadEvaluation, motor_model: str, cat: Catalogs, trace: Trace
) -> Drive:
    """The torque the chosen motor gives, and its plan (rules IM-02, IM-03)."""
    passage = None  # the one-way device in the chain, where one holds the load
    if req.application.hold_without_power and not ev.self_locking_at_low_friction:
        from advisor.one_way.advice import device_passage

        passage = device_passage(req.one_way, ev.torque_Nm, ev.torque_Nm)
    # the torque that moves the load: the thread's and the thrust face's; the motor drives
    # the screw through the device: it gives that torque over the device's η
    drive = ev._replace(torque_Nm=ev.drive_torque_Nm, thrust_torque_Nm=0.0)
    at_motor = (
        drive if passage is None else drive._replace(torque_Nm=drive.torque_Nm / passage.efficiency)
    )
    motor = next(m for m in cat.motors if m.model == motor_model)
    plan = plan_motor(at_motor, motor, cat, req.motor.supply_frequency_Hz, trace)
    return Drive(drive, at_motor, passage, plan)


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
        req, chain.screw, plan.selected, cat, holder, trace, chain.passage or NO_DEVICE
    )
    if motor is not plan.selected:
        power = motor.rated_power_kW
        evaluations = {**plan.evaluations, power: _eval_motor(motor, chain.at_motor)}
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


def thread_screens(req: Requirements, cat: Catalogs, demand: ScrewDemand) -> list[ThreadScreen]:
    """Every thread of the catalog with every number of starts allowed, screened under the
    demand; where the load must hold, through the one-way device on every thread that needs
    one."""
    s = req.screw
    starts_options = (s.starts,) if s.starts is not None else STARTS_FREE
    device_eta = _device_efficiency(req) if req.application.hold_without_power else 1.0
    return _through_device(demand.screen(catalog_parts(cat).threads, starts_options), device_eta)


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
    one_way = None
    if hold:
        # the torque that passes the device: the screw's (thread and thrust face), the
        # motor's before the device's own loss
        eta_d = chain.passage.efficiency if chain.passage is not None else 1.0
        low = demand.material.friction_low
        torque = chain.at_motor.torque_Nm * eta_d
        one_way, device_warnings = _one_way(req, trace, ev, chosen.label, low, torque)
        warnings += device_warnings
    if s.friction_model == "paper":
        warnings.append(
            "friction_model = 'paper' uses seed 001's f/cos(ψ/2); the standard f/cos(α/2) "
            f"gives {ev.torque_standard_Nm:.4g} N·m instead of {ev.torque_paper_Nm:.4g} N·m."
        )
    advisor_choice = trace.find("SCR-04").inputs.get("advisor_choice")
    plan = chain.plan
    sel = plan.evaluations[plan.selected.rated_power_kW]
    assert sel is not None
    design = LinearDesignOut.make(
        screw=_screw_out(ev, req, demand.material, f_range, advisor_choice, sel, cat),
        motor=_motor_out(plan, chain.at_motor, cat, freq),
        one_way=one_way,
        duty=duty,
    )
    checks = [*ev.checks, *_motor_checks(chain, sel, demand.thrust, cat, lin.travel_time_s)]
    if sel.travel_time_s and sel.travel_time_s < FAST_SHARE * lin.travel_time_s:
        warnings.append(_too_fast(chain.at_motor, sel, plan, screens, cat, lin.travel_time_s))
    sf = service_factor(getattr(req, "design", None))
    screw_checks, screw_warnings = _screw_checks(req, ev, sel, demand.thrust, sf, cat)
    return design, checks + screw_checks + duty_checks, warnings + screw_warnings


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
    share = 1.0 if duty.duty_type in ("S1",) else (duty.cyclic_duration_factor or 1.0)
    return power_W * share, f"duty {duty.duty_type}, running share {share:g}"


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


def _whirling_speed_rpm(req: Requirements, thread: ThreadProfile, cat: Catalogs) -> float:
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
    n_cr = _whirling_speed_rpm(req, ev.thread, cat)
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


def _thrust_checks(
    ev: ThreadEvaluation, thrust: ThrustFace | None, force_N: float, sf: ServiceFactor
) -> tuple[list[Check], list[str]]:
    """The thrust bearing's static load against C0 as a check; the thrust face left out, or
    a bearing wider than the core, as warnings."""
    if thrust is None:
        return [], [
            "the motor margin excludes thrust friction: no [screw.thrust] face is given, so "
            "the torque is the thread's alone; a collar adds F·f_c·d_c/2 (Shigley, eq. (8-6))"
        ]
    if thrust.kind != "bearing":
        return [], []
    from advisor.calc.bearing_life import static_safety

    b = thrust.bearing
    c0 = b.C0_kN * 1e3
    p0 = c0 / static_safety(b, 0.0, force_N)
    factor = sf.value if sf.value != 1.0 else None
    check = Check(
        "thrust_bearing_static",
        f"thrust bearing {b.designation}: static equivalent load against C0",
        p0,
        c0,
        "N",
        c0 / ((factor or 1.0) * p0),
        cite("iso-76").with_note("P0 = max(F_r, X0·F_r + Y0·F_a)"),
        factor,
    )
    warnings = []
    if b.d_mm > ev.thread.d3_mm:
        warnings.append(
            f"the thrust bearing {b.designation} (bore {b.d_mm:g} mm) needs a journal "
            f"wider than the core of {ev.thread.name} (d3 = {ev.thread.d3_mm:g} mm): "
            "the screw end must be upset or the bearing smaller"
        )
    return [check], warnings


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


def _screw_checks(
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
    checks, warnings = _thrust_checks(ev, thrust, req.linear.force_N, sf)
    warnings += _nut_warnings(ev, nut_heat(req, ev, n_work))
    return [_whirl_check(req, ev, n_work, cat), *checks], warnings


def _eval_motor(motor: InductionMotor, ev: ThreadEvaluation) -> MotorEvaluation:
    return evaluate_motor(motor, ev.torque_Nm, ev.speed_rpm, ev.revolutions)


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
    text = (
        f"the motor makes the stroke in {sel.travel_time_s:.3g} s, much faster than the "
        f"{travel_time_s:g} s asked for: an induction motor on 50 Hz has no speed between its "
        "pole steps"
    )
    if lead_needed_mm < finest_lead:
        text += (
            f". No lead suits: even the slowest catalog motor ({slowest.rated_speed_rpm:g} rpm) "
            f"would need a lead of {lead_needed_mm:.3g} mm, and the finest that passes the "
            f"checks is {finest_lead:g} mm ({finest.thread.name})"
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
        f"(margin {c.margin:.3f})"
    )


def _remedy(force_N: float, failed: set[str]) -> str:
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
    biggest_kw = max(m.rated_power_kW for m in cat.motors)
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
        reachable = [ev for ev in passing if ev.speed_rpm <= fastest]
        least = min(ev.torque_Nm * ev.speed_rpm * math.pi / 30.0 / 1e3 for ev in reachable)
        reasons.append(
            f"the power needed ({least:.3g} kW or more at a reachable speed) exceeds what the "
            f"catalog's motors give (up to {biggest_kw:g} kW) at that speed"
        )
    return InfeasibleError(
        "no feasible design: no catalog motor can drive a thread that passes its checks",
        reasons,
    )


def _buckling_out(ev: ThreadEvaluation, req: Requirements, cat: Catalogs) -> BucklingOut:
    """The buckling table: the formula used and why (the slenderness against Johnson's
    transition), the end fixity and the critical load."""
    lin = req.linear
    steel = cat.steel(req.screw.screw_steel)
    transition = math.pi * math.sqrt(2.0 * steel.elastic_modulus_MPa / steel.yield_strength_MPa)
    why = (
        f"slenderness μL/i = {ev.slenderness:.4g} "
        f"{'≥' if ev.buckling_formula == 'Euler' else '<'} the transition "
        f"π·√(2E/σ_y) = {transition:.4g}: "
        + (
            "a slender column fails elastically (Euler)"
            if ev.buckling_formula == "Euler"
            else "an intermediate column yields before it buckles elastically (Johnson's parabola)"
        )
    )
    return BucklingOut.make(
        formula=ev.buckling_formula,
        why=why,
        end_fixity=lin.end_fixity,
        effective_length_factor=END_FIXITY_FACTOR[lin.end_fixity],
        slenderness=ev.slenderness,
        critical_load_N=ev.critical_load_N,
        safety_factor_required=lin.buckling_safety_factor,
    )


def _thrust_out(ev: ThreadEvaluation, force_N: float) -> ThrustOut | None:
    """The thrust face's table: its friction torque and the efficiency with it."""
    if ev.thrust is None:
        return None
    lead = ev.thread.pitch_mm * 1e-3 * ev.starts
    return ThrustOut.make(
        kind=ev.thrust.kind,
        model=ev.thrust.describe(),
        torque_Nm=ev.thrust_torque_Nm,
        drive_torque_Nm=ev.drive_torque_Nm,
        efficiency=screw_calc.thread_efficiency_with_thrust(
            force_N, lead, ev.torque_Nm, ev.thrust_torque_Nm
        ),
    )


def _nut_out(ev: ThreadEvaluation, material: ScrewMaterial, heat: NutHeat) -> NutOut:
    """The nut's table: its proportions, flank pressure, wear and heat."""
    return NutOut.make(
        height_mm=ev.nut_height_mm,
        turns=ev.nut_turns,
        height_ratio=ev.nut_height_mm / ev.thread.d2_mm,
        bearing_pressure_MPa=ev.nut_pressure_Pa / 1e6,
        allowable_pressure_MPa=material.allowable_pressure_Pa / 1e6,
        sliding_speed_m_s=heat.sliding_speed_m_s,
        safe_pressure_MPa=heat.safe_pressure_Pa / 1e6,
        safe_pressure_basis=f"Shigley, Table 8-4 (as recalled, not verified online): "
        f"{heat.safe_pressure_row}",
        pv_MPa_m_s=heat.pv_MPa_m_s,
        friction_power_W=heat.friction_power_W,
        mean_friction_power_W=heat.mean_friction_power_W,
        mean_friction_basis=heat.mean_basis,
        temperature_rise_K=heat.temperature_rise_K,
        allowed_temperature_rise_K=NUT_ALLOWED_RISE_K,
        heat_model=f"ΔT = P̄_f/(h·A), h = {NUT_FILM_COEFFICIENT:g} W/(m²·K) natural "
        f"convection, A = nut body of {NUT_OUTER_DIAMETER_RATIO:g}·d over its length "
        "and end faces; the screw's cooling neglected",
    )


def _screw_out(
    ev: ThreadEvaluation,
    req: Requirements,
    material: ScrewMaterial,
    f_range: tuple[float, float],
    advisor_choice: str | None,
    sel: MotorEvaluation,
    cat: Catalogs,
) -> ScrewOut:
    """The screw's table, from its evaluation at the motor's working speed."""
    t, lin, s = ev.thread, req.linear, req.screw
    assert lin is not None
    heat = nut_heat(req, ev, sel.working_speed_rpm or ev.speed_rpm)
    v = screw_calc.linear_speed(lin.stroke_m, lin.travel_time_s)
    return ScrewOut.make(
        thread=t.name,
        imposed=s.thread is not None,
        advisor_choice=advisor_choice,
        nominal_diameter_mm=t.d_mm,
        pitch_mm=t.pitch_mm,
        preferred_pitch=t.preferred,
        starts=ev.starts,
        lead_mm=t.pitch_mm * ev.starts,
        d2_mm=t.d2_mm,
        d3_mm=t.d3_mm,
        D1_mm=t.D1_mm,
        D2_mm=t.D2_mm,
        D4_mm=t.D4_mm,
        ac_mm=t.ac_mm,
        H1_mm=t.H1_mm,
        h3_mm=t.h3_mm,
        material_pair=s.material_pair,
        lubrication=s.lubrication,
        screw_steel=s.screw_steel,
        friction_model=ev.friction_model,
        friction_coefficient=material.friction_coefficient,
        friction_range=list(f_range),
        lead_angle_deg=math.degrees(ev.lead_angle_rad),
        friction_angle_deg=math.degrees(ev.friction_angle_rad),
        torque_Nm=ev.torque_Nm,
        torque_standard_Nm=ev.torque_standard_Nm,
        torque_paper_Nm=ev.torque_paper_Nm,
        efficiency=ev.efficiency,
        back_driving_efficiency=ev.back_driving_efficiency,
        back_driving=back_driving_words(
            ev.back_driving_efficiency, ev.self_locking, ev.self_locking_at_low_friction
        ),
        self_locking=ev.self_locking,
        self_locking_at_low_friction=ev.self_locking_at_low_friction,
        linear_speed_m_s=v,
        revolutions=ev.revolutions,
        speed_rpm=ev.speed_rpm,
        output_power_W=lin.force_N * v,
        nut=_nut_out(ev, material, heat),
        buckling=_buckling_out(ev, req, cat),
        thrust=_thrust_out(ev, lin.force_N),
        critical_speed_rpm=_whirling_speed_rpm(req, t, cat),
        service_factor=ev.service_factor if ev.service_factor != 1.0 else None,
    )


def _motor_out(
    plan: MotorPlan, ev: ThreadEvaluation, cat: Catalogs, freq: float
) -> InductionMotorOut:
    m = plan.selected
    assert m is not None and plan.pole_pairs is not None
    sel = plan.evaluations[m.rated_power_kW]
    assert sel is not None and sel.working_speed_rpm is not None and sel.working_slip is not None
    candidates = []
    for power in plan.band_kW:
        e = plan.evaluations.get(power)
        role = (
            "selected"
            if power == m.rated_power_kW
            else ("lower" if power < m.rated_power_kW else "higher")
        )
        candidates.append(_candidate_out(role, power, e))
    return InductionMotorOut.make(
        kind="induction",
        supply_frequency_Hz=freq,
        speed_rpm=ev.speed_rpm,
        pole_pairs=plan.pole_pairs,
        synchronous_speed_rpm=synchronous_speed_rpm(freq, plan.pole_pairs),
        required_torque_Nm=ev.torque_Nm,
        required_power_kW=plan.required_power_kW,
        rated_power_kW=m.rated_power_kW,
        model=m.model,
        rated_speed_rpm=m.rated_speed_rpm,
        rated_torque_Nm=m.rated_torque_Nm,
        working_speed_rpm=sel.working_speed_rpm,
        working_slip=sel.working_slip,
        working_power_kW=ev.torque_Nm * sel.working_speed_rpm * math.pi / 30.0 / 1e3,
        travel_time_s=sel.travel_time_s or math.inf,
        efficiency_pct=m.efficiency_pct,
        cos_phi=m.cos_phi,
        starting_current_ratio=m.starting_current_ratio,
        inertia_kgm2=m.inertia_kgm2,
        mass_kg=m.mass_kg,
        estimated=list(m.estimated),
        source=text(cat.cite_rows(cat.motor_sources, m.source), cat.short_names()),
        candidates=candidates,
    )


def _candidate_out(role: str, power: float, e: MotorEvaluation | None) -> MotorCandidateOut:
    if e is None:
        return MotorCandidateOut.make(
            role=role,
            rated_power_kW=power,
            in_catalog=False,
            suitable=False,
            problems=["no motor of this power and pole count in the catalog"],
        )
    n0 = e.motor.synchronous_speed_rpm
    return MotorCandidateOut.make(
        role=role,
        rated_power_kW=power,
        model=e.motor.model,
        in_catalog=True,
        rated_speed_rpm=e.motor.rated_speed_rpm,
        rated_torque_Nm=e.rated_torque_Nm,
        max_torque_Nm=e.max_torque_Nm,
        starting_torque_Nm=e.starting_torque_Nm,
        critical_slip=e.curve.critical_slip,
        kloss_epsilon=e.curve.epsilon,
        working_speed_rpm=e.working_speed_rpm,
        torque_at_required_speed_Nm=e.torque_at_required_speed_Nm,
        rated_torque_margin=e.rated_torque_margin,
        starting_torque_margin=e.starting_torque_margin,
        breakdown_torque_margin=e.breakdown_torque_margin,
        travel_time_s=e.travel_time_s,
        suitable=e.suitable,
        problems=e.problems,
        curve=CurveOut.make(
            slip=[float(x) for x in e.slips],
            speed_rpm=[float(n0 * (1.0 - x)) for x in e.slips],
            torque_Nm=[float(x) for x in e.torques_Nm],
        ),
    )
