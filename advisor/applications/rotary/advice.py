"""The rotary actuator advice: PM brushless motor + wave-gear reducer with rolling bodies
(seed 000). Orchestration only: rules choose, ``advisor/calc`` computes.

:func:`advise_rotary` reads as its steps: the frame (BL-03) and its candidate speeds, the
speed (BL-02), the reducer at its ratio (:mod:`.gearbox`), the working point behind the
reducer adopted, then the holding device, the duty cycle and a reviewer's checks."""

import math
from typing import Any, NamedTuple

from advisor.applications.rotary import motor
from advisor.applications.rotary.candidates import (
    Envelope,
    FrameModel,
    SpeedCandidate,
    adopted_stages,
    device_efficiency,
    frame_model,
    loss_curve,
    reducer_output_torque,
    speed_candidate,
    stage_count,
)
from advisor.applications.rotary.gearbox import (
    ReducerChoice,
    choose_reducer,
    envelope_checks,
    gearbox_out,
    stage_checks,
)
from advisor.applications.rotary.report import (
    BldcMotorOut,
    LossCurveOut,
    LossesOut,
    PoleSlotOut,
    RotaryDesignOut,
    SpeedCandidateOut,
    SteelOut,
)
from advisor.calc import bldc, reducer, wavegear
from advisor.calc.checks import Check
from advisor.calc.service_factor import ServiceFactor, service_factor
from advisor.core.cite import Cite
from advisor.core.errors import InfeasibleError
from advisor.core.reading import Requirements
from advisor.core.rulebook import Trace
from catalogs import Catalogs
from rules import bldc as bldc_rules
from rules import wavegear as wavegear_rules

__all__ = ["advise_rotary", "device_efficiency", "reducer_output_torque"]

SEED_000 = wavegear_rules.SEED_000


def _ratio_hint(output_rpm: float, speeds_rpm: list[float]) -> str:
    """The total ratios a reducer makes (one stage's minimum for a bore, seed 000 eq. (14); four
    stages of 20 × 12 × 12 × the stage maximum) and the speeds that reach them."""
    q_min = reducer.STAGE_RATIO_MIN
    q_max = wavegear_rules.Q_OUT_PREFERRED * wavegear_rules.Q_NEXT**2 * reducer.STAGE_RATIO_MAX
    lo, hi = min(speeds_rpm), max(speeds_rpm)
    return (
        f"one to four wave-gear stages make q_Σ = {q_min:g} … {q_max:.6g} (one stage at least "
        f"{q_min:g} for a bore, eq. (14)): motor.candidate_speeds_rpm "
        f"{q_min * output_rpm:.4g} … {q_max * output_rpm:.4g} rpm, or rotary.speed_rpm "
        f"{lo / q_max:.4g} … {hi / q_min:.4g} rpm"
    )


def _device_note(req: Requirements) -> str:
    """Why the motor torque above includes the holding device, in words (or '' without)."""
    eta_d = device_efficiency(req)
    if eta_d == 1.0:
        return ""
    kind = req.one_way.type.replace("_", " ")
    return (
        f"the torque includes the {kind}'s driving loss (η = {eta_d:.3g}: the motor gives "
        f"{1 / eta_d:.3g}× the torque, seed 004); a clutch (one_way.type = 'roller_clutch' or "
        "'em_clutch') drives with η = 1"
    )


def _too_lossy(
    cands: list[SpeedCandidate],
    limit: float,
    basis: str,
    n_opt: float,
    choice: str,
    device_note: str = "",
) -> InfeasibleError:
    """No candidate within the frame's limit; where the requirement takes the space's
    reducer, its efficiency may be the cause, and the other choices are named."""
    exc = motor.too_lossy(cands, limit, basis, n_opt)
    if device_note:  # the holding device's driving loss is part of the motor's torque
        exc = InfeasibleError(exc.summary, [*exc.reasons, device_note])
    if choice == "rules":
        return exc
    other = "lightest" if choice == "slimmest" else "slimmest"
    etas = ", ".join(sorted({f"{c.gearbox_efficiency:.3g}" for c in cands}))
    return InfeasibleError(
        exc.summary,
        [
            *exc.reasons,
            f"gearbox.choice = {choice!r} takes a reducer of η = {etas}: 'rules' or "
            f"{other!r} may leave the motor within its limit",
        ],
    )


def _loss_optimum_Hz(at_ref: SpeedCandidate, req: Requirements, params, pole_pairs: int) -> float:
    """Seed 000, eq. (10), with K_om read at ``at_ref`` behind the efficiency of the reducer
    the design adopts near the optimum: eq. (10) holds one η for every speed, while the
    adopted stage count (hence η) steps with the ratio. From the reference point's η, the
    optimum is found, the η adopted at its ratio taken, and the ohmic loss rescaled to it
    (P_om ∝ (M/(q·η))², eq. (9)) until the stage count stays (at most four rounds)."""
    losses = at_ref.losses_W
    core = losses.iron + losses.magnets
    ohmic, eta, f_ref = losses.ohmic, at_ref.gearbox_efficiency, at_ref.electrical_frequency_Hz
    if core <= 0.0:  # a catalog motor states no core losses: no optimum, loss falls with n
        return math.inf
    f_opt = bldc.optimum_frequency_Hz(ohmic, core, f_ref)
    for _ in range(4):
        n = f_opt * 60.0 / pole_pairs
        q = n / req.rotary.speed_rpm
        split = wavegear_rules.split_of(q, reducer.STAGE_RATIO_MIN, reducer.STAGE_RATIO_MAX)
        if not split.ratios:
            break
        adopted = params.stage_efficiency ** stage_count(q, split.ratios, req, params)
        if adopted == eta:
            break
        ohmic, eta = ohmic * (eta / adopted) ** 2, adopted
        f_opt = bldc.optimum_frequency_Hz(ohmic, core, f_ref)
    return f_opt


class _Fit(NamedTuple):
    """A frame tried for the requirement: its candidates, limit and what passes."""

    model: FrameModel
    reducible: list[SpeedCandidate]
    passing: list[SpeedCandidate]
    limit: float
    basis: str
    f_opt: float
    n_opt: float
    frame_for: Any
    error: InfeasibleError | None


def _reducible(
    req: Requirements, model: FrameModel, params, speeds: list[float]
) -> list[SpeedCandidate]:
    """The candidate speeds whose ratio a wave-gear reducer makes; exit 3 when none does."""
    cands = [speed_candidate(n, req, model, params) for n in speeds]
    reducible = [c for c in cands if c.split]
    if not reducible:
        raise InfeasibleError(
            "no feasible design: no candidate speed gives a ratio a wave-gear reducer can make",
            [
                *(f"{c.speed_rpm:g} rpm → q_Σ = {c.total_ratio:.4g}" for c in cands),
                _ratio_hint(req.rotary.speed_rpm, [c.speed_rpm for c in cands]),
            ],
        )
    return reducible


def _optimum_at_reference(req, model: FrameModel, params, reducible) -> float:
    """Eq. (10) at the reference speed, with the losses of the model in use; where no reducer
    makes the reference speed's ratio, at the candidate nearest to it (K_om and K_mag are
    the constants of eqs. (9) and (5), read at any operating point), never nan."""
    ref = model.ref
    at_ref = speed_candidate(ref.speed_rpm, req, model, params)
    if not at_ref.split:
        at_ref = min(reducible, key=lambda c: abs(math.log(c.speed_rpm / ref.speed_rpm)))
    return _loss_optimum_Hz(at_ref, req, params, ref.pole_pairs)


def _fit(req: Requirements, cat: Catalogs, ref, params, data, speeds: list[float]) -> _Fit:
    """Seed 000's model with the frame ``ref``'s numbers: its candidates, its limit (its own
    losses at its own rated point), and the speeds that pass the point check and the duty."""
    model = frame_model(req, cat, ref)
    reducible = _reducible(req, model, params, speeds)
    f_opt = _optimum_at_reference(req, model, params, reducible)
    n_opt = f_opt * 60.0 / ref.pole_pairs
    # the frame's limit is thermal: a speed is a candidate only if its losses are carried
    limit, basis = motor.loss_limit(req.motor, model.steel, model.steel_mass_kg, model.terms, ref)
    frame_for = None

    def fit(passing: list[SpeedCandidate], error: InfeasibleError | None = None) -> _Fit:
        return _Fit(model, reducible, passing, limit, basis, f_opt, n_opt, frame_for, error)

    within = [c for c in reducible if bldc_rules.within_limit(c.losses_W.total, limit)]
    if getattr(ref, "kind", "") == "catalog":  # no core-loss data above the rated speed
        within = [c for c in within if c.speed_rpm <= ref.speed_rpm * (1 + 1e-9)]
        if not within and reducible:
            return fit([], motor.above_rated(reducible, ref))
    if not within:
        note = _device_note(req)
        return fit([], _too_lossy(reducible, limit, basis, n_opt, req.gearbox.choice, note))
    if req.duty is None:
        return fit(within)
    from advisor.applications.rotary.duty import frames, passing_speeds

    # only the speeds whose motor passes the cycle
    frame_for = frames(ref, model.steel, model.steel_mass_kg, model.terms, limit, data)
    offered = reducible if getattr(ref, "kind", "") != "catalog" else within
    try:
        passing = passing_speeds(
            req,
            offered,
            frame_for,
            lambda c: _holder(req, c.total_ratio, c.gearbox_efficiency),
            limit,
        )
    except InfeasibleError as exc:
        return fit([], exc)
    return fit(passing)


def _best_words(fit: _Fit) -> str:
    """The numbers of a tried frame's least lossy candidate, for BL-03."""
    best = min(fit.reducible, key=lambda c: c.losses_W.total)
    if (
        fit.error is not None
        and fit.passing == []
        and bldc_rules.within_limit(best.losses_W.total, fit.limit)
    ):
        return fit.error.reasons[0] if fit.error.reasons else fit.error.summary
    return (
        f"at {best.speed_rpm:g} rpm ({best.torque_Nm:.4g} N·m of the motor) losses "
        f"{best.losses_W.total:.4g} W against its limit {fit.limit:.4g} W"
    )


def _choose_frame(req: Requirements, cat: Catalogs, params, speeds, trace: Trace):
    """The frame the design takes (BL-03 over the series and a catalog's motors, or the one
    the requirement imposes) and its fit; exit 3 naming the largest's reason when none fits."""
    from advisor.applications.rotary import frames

    choice = frames.frame_choice(req.motor, cat)
    if choice.imposed is not None:
        ref = choice.imposed[0]
        data = frames.imposed_data(req, choice, cat)
        fit = _fit(req, cat, ref, params, data, speeds)
        if fit.error is not None:
            raise fit.error
        return fit, data, choice
    tried: list = []
    for frame in choice.series:
        data = frames.frame_data(req, frame)
        fit = _fit(req, cat, frame, params, data, speeds)
        if fit.error is None:
            best = min(fit.passing, key=lambda c: c.losses_W.total)
            why = (
                f"at {best.speed_rpm:g} rpm it loses {best.losses_W.total:.4g} W of its "
                f"{fit.limit:.4g} W"
            )
            tried.append(frames.tried_row(frame, True, why))
            trace.apply(bldc_rules.choose_frame, tried[-2:] if len(tried) > 1 else tried)
            return fit, data, choice._replace(tried=tuple(tried))
        tried.append(frames.tried_row(frame, False, _best_words(fit)))
    raise _no_frame(tried[-1], fit)


def _no_frame(last, fit: _Fit) -> InfeasibleError:
    """No frame of the series carries the load: the largest's reason (``last``: its
    :class:`~advisor.applications.rotary.frames.FrameTried`)."""
    return InfeasibleError(
        "no feasible design: no motor frame of the series carries the load",
        [
            f"the largest, {last.name} ({last.torque_Nm:.4g} N·m continuous, "
            f"{last.mass_kg:.3g} kg): {last.why}",
            fit.error.summary if fit.error is not None else "",
            "give a catalog motor (bldc_motors.toml in --catalog-dir), motor.max_losses_W "
            "with motor.frame for a better cooling, more candidate speeds, or a lower "
            "rotary.torque_Nm",
        ],
    )


def _reducer_params(req: Requirements, sf: ServiceFactor) -> reducer.ReducerParams:
    """The stages are sized (eq. (16)) for the output torque times the service factor: every
    strength check of the reducer then holds f_B·demand within its capacity."""
    gb = req.gearbox
    return reducer.ReducerParams(
        torque_Nm=reducer_output_torque(req) * sf.value,
        k_rb=wavegear.ROLLING_BODY_FACTOR[gb.rolling_body],
        stage_efficiency=gb.stage_efficiency,
        density_kg_m3=gb.density_kg_m3,
        fill_factor=gb.fill_factor,
    )


def _offered(req: Requirements, fit: _Fit) -> list[SpeedCandidate]:
    """BL-02 weighs every reducible speed (those over the limit shown, not chosen); with a
    cycle those that pass it and those over the limit (shown, not chosen, as without one: a
    speed within the limit that fails the cycle is not offered); with a catalog motor only
    those that pass (and lie within its rated speed)."""
    if getattr(fit.model.ref, "kind", "") == "catalog":
        return fit.passing
    if req.duty is None:
        return fit.reducible
    passing = {c.speed_rpm for c in fit.passing}
    return [
        c
        for c in fit.reducible
        if c.speed_rpm in passing or not bldc_rules.within_limit(c.losses_W.total, fit.limit)
    ]


def _choose_speed(req: Requirements, fit: _Fit, trace: Trace) -> SpeedCandidate:
    """BL-02: the candidate speed the design takes."""
    offered = _offered(req, fit)
    speed = trace.apply(
        bldc_rules.choose_speed,
        {c.speed_rpm: c.losses_W.total for c in offered},
        fit.n_opt,
        fit.model.ref.pole_pairs,
        fit.limit,
        fit.basis,
        {c.speed_rpm: c.current_A for c in offered},
    )
    return next(c for c in offered if c.speed_rpm == speed)


def _working_point(
    req: Requirements, fit: _Fit, chosen: SpeedCandidate, design: reducer.Reducer
) -> SpeedCandidate:
    """The chosen speed behind the reducer actually adopted: the motor torque follows its
    efficiency and the holding device's driving efficiency; exit 3 over the frame's limit."""
    ref, speed = fit.model.ref, chosen.speed_rpm
    torque = req.rotary.torque_Nm / (
        design.total_ratio * design.efficiency * device_efficiency(req)
    )
    working = chosen._replace(
        total_ratio=design.total_ratio,
        gearbox_efficiency=design.efficiency,
        torque_Nm=torque,
        current_A=bldc.rewound_current_A(
            ref.current_A, ref.torque_Nm, ref.speed_rpm, torque, speed
        ),
        losses_W=motor.losses_at(ref, chosen.losses_W.iron, speed, torque),
    )
    if not bldc_rules.within_limit(working.losses_W.total, fit.limit):
        note = _device_note(req)
        raise _too_lossy([working], fit.limit, fit.basis, fit.n_opt, req.gearbox.choice, note)
    return working


def advise_rotary(req: Requirements, cat: Catalogs, trace: Trace):
    """The rotary actuator's design, its checks and its warnings (seed 000)."""
    assert req.rotary is not None and req.motor.kind == "bldc"
    # shared within one advice (a candidate at the reference speed), not across advices: a
    # repeated advice (the warm benchmark) computes everything again
    adopted_stages.cache_clear()
    trace.apply(bldc_rules.motor_type)
    trace.apply(wavegear_rules.reducer_type, req.rotary.torque_Nm)
    sf = service_factor(req.design)
    params = _reducer_params(req, sf)
    speeds = sorted(set(req.motor.candidate_speeds_rpm))
    fit, data, choice = _choose_frame(req, cat, params, speeds, trace)
    chosen = _choose_speed(req, fit, trace)
    env = Envelope(req.envelope.max_outer_diameter_mm, req.envelope.max_length_mm)
    gear = _reducer_for_cycle(req, fit, chosen, env, (params, sf), trace)
    working = _working_point(req, fit, chosen, gear.design)
    steel_cite = cat.cite_rows(cat.steel_sources, fit.model.steel.source)
    checks = [
        *envelope_checks(gear.design, env),
        *stage_checks(gear.design),
        _losses_check(working, fit, steel_cite),
    ]
    from advisor.applications.rotary.frames import frame_out

    listed = _offered(req, fit) if req.duty is not None else fit.reducible
    curve = loss_curve(req, fit.model, params, [c.speed_rpm for c in listed], fit.limit)
    motor_out = _motor_out(working, listed, fit).replace(
        frame=frame_out(choice, fit.model.ref, data),
        loss_curve=LossCurveOut.make(**curve._asdict()),
    )
    gearbox = gearbox_out(gear, chosen.total_ratio, req.gearbox.rolling_body, params.k_rb)
    rest = _beyond_the_point(req, cat, trace, gear, working, fit, steel_cite, sf)
    design_out = RotaryDesignOut.make(
        motor=motor_out,
        gearbox=gearbox,
        one_way=rest.one_way,
        duty=rest.duty,
        reducer_load=rest.reducer_load,
        output_bearing=rest.output_bearing,
        regeneration=rest.regeneration,
    )
    return design_out, checks + rest.checks, gear.warnings + rest.warnings


def _reducer_for_cycle(
    req: Requirements,
    fit: _Fit,
    chosen: SpeedCandidate,
    env: Envelope,
    sizing: tuple[reducer.ReducerParams, ServiceFactor],
    trace: Trace,
) -> ReducerChoice:
    """The reducer at the chosen ratio, its stages sized by eq. (16) for the rated output
    torque or, with a [duty] that asks more of them, for the cycle: its cube-mean torque T_av
    and its repeated peak T_rep within 98/39 × T_N (WG-07; × f_B). The cycle is found at the
    ratio and efficiency of the reducer adopted, so the reducer is chosen again while a stage
    count changing η lifts it (at most four passes, until the stage torque no longer grows)."""
    params, sf = sizing
    if req.duty is None:
        return choose_reducer(chosen.total_ratio, req.gearbox, env, params, trace)
    from advisor.applications.rotary.duty import output_loads
    from advisor.calc import load_spectrum

    speed, frame = chosen.speed_rpm, fit.frame_for(chosen.speed_rpm)
    q, eta = chosen.total_ratio, chosen.gearbox_efficiency
    sized, basis = params, None
    for _ in range(4):
        loads = output_loads(req, q, eta, speed, frame, _holder(req, q, eta))
        t_av = load_spectrum.cube_mean_torque(loads)
        t_rep = load_spectrum.repeated_peak_torque(loads)
        need = max(t_av * sf.value, t_rep * sf.value / load_spectrum.REPEATED_PEAK_FACTOR)
        while load_spectrum.REPEATED_PEAK_FACTOR * need < t_rep * sf.value:
            need = math.nextafter(need, math.inf)  # sized for its peak: never a bit short of it
        if need <= sized.torque_Nm:
            break
        sized, basis = params._replace(torque_Nm=need), (t_av, t_rep, q, eta)
        design = choose_reducer(chosen.total_ratio, req.gearbox, env, sized, Trace()).design
        q, eta = design.total_ratio, design.efficiency
    if basis is not None:
        rated = reducer_output_torque(req)
        trace.apply(wavegear_rules.size_for_cycle, rated, *basis[:2], sf.value, *basis[2:])
    return choose_reducer(chosen.total_ratio, req.gearbox, env, sized, trace)


def _losses_check(working: SpeedCandidate, fit: _Fit, steel_cite: Cite) -> Check:
    return motor.losses_check(
        "motor_losses",
        "motor total losses against what the frame's cooling carries",
        working.losses_W.total,
        fit.limit,
        (SEED_000.at("eqs. (4), (5), (9)") + steel_cite).with_note(fit.basis),
    )


class _Beyond(NamedTuple):
    """What the design asks beyond its working point: the holding device, the duty cycle and
    a reviewer's checks (load spectrum, output bearing, regenerated energy)."""

    one_way: Any
    duty: Any
    reducer_load: Any
    output_bearing: Any
    regeneration: Any
    checks: list[Check]
    warnings: list[str]


def _beyond_the_point(
    req, cat, trace: Trace, gear: ReducerChoice, working, fit: _Fit, steel_cite, sf
) -> _Beyond:
    """The holding device (seed 004), the duty cycle and a reviewer's checks, in that order."""
    design, speed = gear.design, working.speed_rpm
    checks: list[Check] = []
    warnings: list[str] = []
    one_way = None
    if req.application.hold_without_power:
        one_way, more, said = _one_way(req, trace, design, working, fit, steel_cite)
        checks += more
        warnings += said
    duty = None
    if req.duty is not None:
        from advisor.applications.rotary.duty import advise_duty

        holder = _holder(req, design.total_ratio, design.efficiency)
        duty, more, said = advise_duty(
            req, design.total_ratio, design.efficiency, speed, fit.frame_for(speed), holder, trace
        )
        checks += more
        warnings += said
    frame_for = fit.frame_for if req.duty else None
    extra = _reviewer_checks(req, cat, design, speed, frame_for, sf)
    return _Beyond(
        one_way,
        duty,
        extra.reducer_load,
        extra.output_bearing,
        extra.regeneration,
        checks + extra.checks,
        warnings + extra.warnings,
    )


class _Review(NamedTuple):
    reducer_load: Any
    output_bearing: Any
    regeneration: Any
    checks: list[Check]
    warnings: list[str]


def _reviewer_checks(req, cat, design: reducer.Reducer, speed: float, frame_for, sf) -> _Review:
    """The reducer under its load spectrum, the output bearing under an external load, and
    the regenerated energy of the duty cycle (:mod:`.loads`)."""
    from advisor.applications.rotary import loads

    q, eta = design.total_ratio, design.efficiency
    if req.duty is not None:
        from advisor.applications.rotary.duty import motor_phases, output_loads

        holder = _holder(req, q, eta)
        spectrum = output_loads(req, q, eta, speed, frame_for(speed), holder)
        regeneration = loads.regeneration(
            motor_phases(req, q, eta, speed, frame_for(speed), holder), req.drive
        )
        basis = "duty cycle"
    else:
        from advisor.calc.load_spectrum import Load

        # the torque the output stage delivers: through a device at the output, M/η_d
        spectrum = [Load(reducer_output_torque(req), req.rotary.speed_rpm, 1.0)]
        regeneration, basis = None, "working point (rotary.torque_Nm at rotary.speed_rpm)"
    rolling = req.gearbox.rolling_body
    reducer_load, checks, warnings = loads.reducer_load(req, design, spectrum, basis, sf, rolling)
    bearing = None
    if req.output_load is not None:
        bearing, more = loads.output_bearing(
            req, cat, design, reducer_load.mean_output_speed_rpm or req.rotary.speed_rpm, sf
        )
        checks += more
    return _Review(reducer_load, bearing, regeneration, checks, warnings)


def _holder(req: Requirements, q: float, eta: float):
    """What holds the load in the duty cycle: the one-way device that would be chosen for
    this reducer (its passage of torque), or the motor with power on."""
    from advisor.applications.rotary.duty import NO_HOLDER, Holder

    if not req.application.hold_without_power:
        return NO_HOLDER
    from advisor.calc.one_way import size
    from advisor.one_way.advice import device_passage

    at_output = req.one_way.location == "output_side"
    motor_side, output_side = _device_torques(req, q, eta)
    passage = device_passage(req.one_way, motor_side, output_side, at_output)
    # the device OW-02 chooses, sized where it sits: its inertia turns in the cycle
    device = size(passage.type, output_side if at_output else motor_side, req.one_way.rollers)
    return Holder(passage, at_output, device.inertia_kgm2 if device is not None else 0.0)


def _device_torques(req: Requirements, q: float, eta: float) -> tuple[float, float]:
    """The torques the holding device is sized for, at the motor side and at the output: the
    output torque or, if larger, the emergency stop's momentary peak, each times the service
    factor; M/(q·η) at the motor side (seed 004, OW-01)."""
    out = req.rotary.torque_Nm
    stop = req.rotary.emergency_stop_torque_Nm
    sized = max(out, stop or 0.0) * service_factor(req.design).value
    return sized / (q * eta), sized


def _one_way(
    req, trace, design: reducer.Reducer, working: SpeedCandidate, fit: _Fit, steel_cite: Cite
):
    """Seed 004: the holding device at the motor side (or at the output, where the requirement
    puts it), and what it asks of the motor: its driving loss raises the motor torque, hence
    the copper loss, at the same speed, wherever it sits (the motor gives 1/η_d times the
    torque either way)."""
    from advisor.one_way.advice import choose_device
    from rules import one_way as one_way_rules

    q, eta = design.total_ratio, design.efficiency
    sized_motor, sized_output = _device_torques(req, q, eta)
    # the torque where the device sits (OW-01): the output torque or the emergency stop's,
    # whichever is larger, times the service factor; the decision states the device's torque
    trace.apply(one_way_rules.placement, sized_output, q, eta, req.one_way.location)
    motor_torque, speed = working.torque_Nm, working.speed_rpm
    power = motor_torque * speed * math.pi / 30.0
    at_output = req.one_way.location == "output_side"
    device, warnings = choose_device(
        req.one_way, sized_motor, sized_output, power, trace, at_output=at_output
    )
    device = device.replace(basis=device.basis + _sized_for(req))
    checks = _holding_checks(req, device, q, eta, at_output)
    if device.efficiency < 1.0:
        # the motor torque (and so the losses the speed choice weighed) already includes the
        # device's 1/η_d: this check states that share of the losses by name
        ref = fit.model.ref
        with_device = motor.losses_at(ref, working.losses_W.iron, speed, motor_torque).total
        source = one_way_rules.SEED_004 + SEED_000.at("eq. (4)") + steel_cite
        checks.append(
            motor.losses_check(
                "motor_losses_with_one_way",
                "motor losses with the one-way device's loss",
                with_device,
                fit.limit,
                source.with_note(fit.basis),
            )
        )
    return device, checks, warnings


def _holding_checks(req: Requirements, device, q: float, eta: float, at_output: bool):
    """The device holds the load with the power off (:mod:`advisor.one_way.holding`): the
    torque it is sized for against the one the standing load gives it — the output torque
    or, if larger, the emergency stop's, × f_B; at the motor side through the back-driven
    wave gear, M·η/q (its back-driven efficiency taken equal to its forward one, as in the
    duty cycle), so the margin is 1/η² there. At the output the load's torque is the one the
    device is sized for: a check of it could only state 1.000, so only a gear's self-locking
    is checked there."""
    from advisor.one_way.holding import device_checks, self_locking_check

    out, stop = req.rotary.torque_Nm, req.rotary.emergency_stop_torque_Nm
    held = max(out, stop or 0.0)
    what = "the emergency stop's" if held > out else "the output torque"
    f_b = service_factor(req.design).value
    if at_output:
        locking = self_locking_check(device.type)
        return [locking] if locking else []
    how = f"{what} {held:.4g} N·m back through the wave gear, M·η/q = {held:.4g}·{eta:.6g}/{q:.4g}"
    return device_checks(device.type, device.torque_Nm, held * eta / q, f_b, how)


def _sized_for(req: Requirements) -> str:
    """What the device is sized for, in words, where it is more than the output torque: the
    emergency stop's momentary peak (the holding check, :func:`_holding_checks`, states the
    torque it holds against it)."""
    out, stop = req.rotary.torque_Nm, req.rotary.emergency_stop_torque_Nm
    f_b = service_factor(req.design).value
    if (stop is None or stop <= out) and f_b == 1.0:
        return ""
    what = (
        f"the emergency stop's {stop:.4g} N·m at the output (above the working {out:.4g} N·m)"
        if stop is not None and stop > out
        else f"the working {out:.4g} N·m at the output"
    )
    return f"; sized for {what} × f_B = {f_b:g}"


def _losses_out(losses: motor.Losses) -> LossesOut:
    return LossesOut.make(**{k: float(v) for k, v in losses._asdict().items()})


#: The fields a speed candidate shares with the report's candidate table.
_CANDIDATE_FIELDS = tuple(
    f for f in SpeedCandidateOut.field_names if f in SpeedCandidate._fields and f != "losses_W"
)


def _candidate_out(c: SpeedCandidate, limit_W: float) -> SpeedCandidateOut:
    return SpeedCandidateOut.make(
        **{f: getattr(c, f) for f in _CANDIDATE_FIELDS},
        within_loss_limit=bldc_rules.within_limit(c.losses_W.total, limit_W),
        losses_W=_losses_out(c.losses_W),
    )


def _steel_out(working: SpeedCandidate, model: FrameModel) -> SteelOut:
    steel = model.steel
    return SteelOut.make(
        grade=steel.grade,
        thickness_mm=steel.thickness_mm,
        equivalent=steel.equivalent,
        mass_kg=model.steel_mass_kg,
        p15_50_W_kg=steel.p15_50_W_kg,
        specific_loss_W_kg=working.specific_loss_W_kg,
        specific_loss_three_term_W_kg=working.specific_loss_three_term_W_kg,
        iron_loss_model=model.ref.iron_loss_model,
        estimated=list(steel.estimated),
    )


def _motor_out(
    working: SpeedCandidate, candidates: list[SpeedCandidate], fit: _Fit
) -> BldcMotorOut:
    """The report's motor table: the working point, the steel, every candidate speed and the
    pole/slot sets of the frame's pole pairs (eq. (1))."""
    ref = fit.model.ref
    options = [c for c in bldc.pole_slot_combinations(3, 36) if c.pole_pairs == ref.pole_pairs]
    return BldcMotorOut.make(
        kind="bldc",
        speed_rpm=working.speed_rpm,
        pole_pairs=ref.pole_pairs,
        electrical_frequency_Hz=working.electrical_frequency_Hz,
        torque_Nm=working.torque_Nm,
        current_A=working.current_A,
        losses_W=_losses_out(working.losses_W),
        loss_limit_W=fit.limit,
        loss_limit_basis=fit.basis,
        optimum_frequency_Hz=fit.f_opt if math.isfinite(fit.f_opt) else None,
        optimum_speed_rpm=fit.n_opt if math.isfinite(fit.n_opt) else None,
        steel=_steel_out(working, fit.model),
        candidates=[_candidate_out(c, fit.limit) for c in candidates],
        pole_slot_options=[
            PoleSlotOut.make(
                slots=o.slots,
                poles=o.poles,
                teeth_per_group=o.teeth_per_group,
                winding_factor=o.winding_factor,
            )
            for o in options
        ],
    )
