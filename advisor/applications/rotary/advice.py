"""The rotary actuator advice: PM brushless motor + wave-gear reducer with rolling bodies
(seed 000). Orchestration only: rules choose, ``advisor/calc`` computes."""

import functools
import math
from typing import NamedTuple

import numpy as np

from advisor.applications.rotary import motor as bm
from advisor.applications.rotary.report import (
    BldcMotorOut,
    Fig1Out,
    GearboxOut,
    GearboxSummaryOut,
    LossesOut,
    ParetoOut,
    ParetoPointOut,
    PoleSlotOut,
    RotaryDesignOut,
    SpeedCandidateOut,
    StageOut,
    SteelOut,
    SweepOut,
)
from advisor.calc import bldc
from advisor.calc import reducer as rd
from advisor.calc import wavegear as wg
from advisor.calc.checks import Check
from advisor.calc.service_factor import service_factor
from advisor.core.cite import Cite, note
from advisor.core.errors import InfeasibleError, InputError
from advisor.core.reading import Requirements
from advisor.core.rulebook import Trace
from catalogs import Catalogs
from rules import bldc as bl_rules
from rules import wavegear as wg_rules

SEED_000 = wg_rules.SEED_000
MAX_ROWS = int(rd.ROW_GRID.max())
FIG1_ROWS = [2, 3, 4, 6, 8, 10, 12]
#: At most this many designs of the Pareto front in the report, evenly spaced along it.
PARETO_POINTS = 16
#: The envelope checks rest on the requirement itself, not on a published source.
ENVELOPE = note("the requirement's [envelope]")


def _ratio_hint(output_rpm: float, speeds_rpm: list[float]) -> str:
    """The total ratios a reducer makes (one stage's minimum for a bore, seed 000 eq. (14); four
    stages of 20 × 12 × 12 × the stage maximum) and the speeds that reach them."""
    q_min = rd.STAGE_RATIO_MIN
    q_max = wg_rules.Q_OUT_PREFERRED * wg_rules.Q_NEXT**2 * rd.STAGE_RATIO_MAX
    lo, hi = min(speeds_rpm), max(speeds_rpm)
    return (
        f"one to four wave-gear stages make q_Σ = {q_min:g} … {q_max:.6g} (one stage at least "
        f"{q_min:g} for a bore, eq. (14)): motor.candidate_speeds_rpm "
        f"{q_min * output_rpm:.4g} … {q_max * output_rpm:.4g} rpm, or rotary.speed_rpm "
        f"{lo / q_max:.4g} … {hi / q_min:.4g} rpm"
    )


def _steel(req: Requirements, cat: Catalogs, ref=None):
    ref = ref if ref is not None else req.motor.reference  # type: ignore[union-attr]
    steel = cat.electrical_steel(ref.steel_grade, ref.steel_thickness_mm)
    if steel is None:
        known = ", ".join(s.name for s in cat.electrical_steels)
        raise InputError(
            f"motor.reference.steel_grade = {ref.steel_grade!r} at steel_thickness_mm = "
            f"{ref.steel_thickness_mm:g}: not in the electrical steel catalog "
            f"(GOST 21427.2-83: {known})"
        )
    return steel


def device_efficiency(req: Requirements) -> float:
    """The driving efficiency of the holding device the requirement asks for, known before the
    frame, the speed and the reducer are chosen (seed 004): the motor gives 1/η_d times the
    torque wherever the device sits, so every loss the choices weigh includes it. 'auto'
    chooses between the two clutches (OW-02), both of η = 1."""
    if not req.application.hold_without_power or req.one_way.type == "auto":
        return 1.0
    from advisor.calc import one_way as ow

    return ow.passage(req.one_way.type).efficiency


def reducer_output_torque(req: Requirements) -> float:
    """The torque the reducer's output stage delivers at the rated point: the load's, or with
    a holding device at the output (between the load and the reducer) the device's input
    torque, M_out/η_d (seed 004): the stages are sized for it."""
    torque = req.rotary.torque_Nm
    if req.application.hold_without_power and req.one_way.location == "output_side":
        return torque / device_efficiency(req)
    return torque


def _candidate(
    n: float, req: Requirements, steel, steel_mass: float, terms, params, ref=None
) -> dict:
    """Losses and drive figures of the reference motor rewound for speed ``n``, behind the
    reducer the design would adopt at its ratio (:func:`_stage_count`): the efficiency the
    speed choice (BL-02) weighs is the one the design then has."""
    rot = req.rotary
    mot = req.motor
    assert rot is not None and mot.kind == "bldc"
    ref = ref if ref is not None else mot.reference
    q_total = n / rot.speed_rpm
    split = wg_rules.split_ratio(q_total, rd.STAGE_RATIO_MIN, rd.STAGE_RATIO_MAX).value
    stages = _stage_count(q_total, split, req, params) if split else 0
    eta = params.stage_efficiency**stages if stages else math.nan
    # the holding device's driving loss is the motor's too: it gives 1/η_d times the torque
    torque = rot.torque_Nm / (q_total * eta * device_efficiency(req)) if stages else math.nan
    f = bldc.flux_frequency_Hz(n, ref.pole_pairs)
    spec, spec_three = bm.specific_iron_loss(ref, steel, terms, f)
    return {
        "speed_rpm": n,
        "frequency_Hz": f,
        "q_total": q_total,
        "split": split,
        "stages": stages,
        "eta": eta,
        "torque_Nm": torque,
        # the winding rewound for n: current ∝ torque·n (seed 000, eq. (4)); reported only
        "current_A": bldc.rewound_current_A(ref.current_A, ref.torque_Nm, ref.speed_rpm, torque, n),
        "losses": bm.losses_at(ref, steel_mass * spec, n, torque),
        "iron_three_term_W": steel_mass * spec_three,
        "spec": spec,
        "spec_three": spec_three,
    }


def _rows_needed(
    torque_Nm: float, d_max: float | None, split: list[float], params: rd.ReducerParams
) -> float | None:
    """The rows the envelope diameter asks of the output stage (seed 000, the inequality
    after eq. (19)); None without a diameter limit."""
    if not d_max:
        return None
    return float(wg.rows_for_diameter(torque_Nm, split[0], d_max, params.k_rb))


def _stage_count(q_total: float, split: list[float], req: Requirements, params) -> int:
    """See :func:`_adopted_stages`: the same, from a requirement."""
    env = req.envelope
    return _adopted_stages(
        q_total,
        tuple(split),
        params.torque_Nm,
        req.gearbox.choice,
        env.max_outer_diameter_mm,
        env.max_length_mm,
        params,
    )


@functools.lru_cache(maxsize=64)
def _adopted_stages(
    q_total: float,
    split: tuple[float, ...],
    torque_Nm: float,
    choice: str,
    d_max: float | None,
    l_max: float | None,
    params,
) -> int:
    """The stage count of the reducer the design adopts at ``q_total``: the rules' split
    (WG-02) where its design fits the envelope and gearbox.choice is "rules"; otherwise the
    design space's lightest (or slimmest) within the envelope, as :func:`advise_rotary`
    adopts. The rules' count where the space has none that fits (the advice then says so)."""
    env = _Envelope(d_max, l_max)
    split = list(split)
    rule_design = None
    if choice == "rules":
        needed = _rows_needed(torque_Nm, d_max, split, params)
        rows = wg_rules.choose_rows(len(split), needed, MAX_ROWS).value
        rule_design = rd.evaluate(split, rows, params) if rows else None
    taken = wg_rules.space_choice(choice, rule_design, d_max, l_max)
    if taken is None:
        return len(split)
    space = rd.sweep(q_total, params)
    best = _optimum(space, q_total, "diameter" if taken == "slimmest" else "mass", params, env)
    return len(best.stages) if best is not None else len(split)


def _adopt(options: wg_rules.ReducerOptions, trace: Trace) -> tuple[rd.Reducer, str, list[str]]:
    """The reducer the design adopts: the rule design, or the one of the design space that
    WG-06 takes (and says why, where the requirement asked the rules)."""
    taken = wg_rules.space_choice(
        options.asked, options.rules, options.max_outer_diameter_mm, options.max_length_mm
    )
    if taken is None:
        assert options.rules is not None
        return options.rules, "rules", []
    warnings = []
    if options.asked == "rules":
        design = options.rules
        why = (
            "the envelope diameter needs more rows than the design space holds"
            if design is None
            else f"the rule design ({design.outer_diameter_mm:.4g} mm × "
            f"{design.length_mm:.4g} mm) does not fit the envelope"
        )
        warnings.append(
            f"{why}; the lightest reducer of the design space that fits is used instead"
        )
    return trace.apply(wg_rules.taken_from_space, options), taken, warnings


class _Envelope(NamedTuple):
    max_outer_diameter_mm: float | None
    max_length_mm: float | None


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
    cands: list[dict], limit: float, basis: str, n_opt: float, choice: str, device_note: str = ""
) -> InfeasibleError:
    """No candidate within the frame's limit; where the requirement takes the space's
    reducer, its efficiency may be the cause, and the other choices are named."""
    exc = bm.too_lossy(cands, limit, basis, n_opt)
    if device_note:  # the holding device's driving loss is part of the motor's torque
        exc = InfeasibleError(exc.summary, [*exc.reasons, device_note])
    if choice == "rules":
        return exc
    other = "lightest" if choice == "slimmest" else "slimmest"
    etas = ", ".join(sorted({f"{c['eta']:.3g}" for c in cands}))
    return InfeasibleError(
        exc.summary,
        [
            *exc.reasons,
            f"gearbox.choice = {choice!r} takes a reducer of η = {etas}: 'rules' or "
            f"{other!r} may leave the motor within its limit",
        ],
    )


def _loss_optimum_Hz(at_ref: dict, req: Requirements, params, pole_pairs: int) -> float:
    """Seed 000, eq. (10), with K_om read at ``at_ref`` behind the efficiency of the reducer
    the design adopts near the optimum: eq. (10) holds one η for every speed, while the
    adopted stage count (hence η) steps with the ratio. From the reference point's η, the
    optimum is found, the η adopted at its ratio taken, and the ohmic loss rescaled to it
    (P_om ∝ (M/(q·η))², eq. (9)) until the stage count stays (at most four rounds)."""
    core = at_ref["losses"]["iron"] + at_ref["losses"]["magnets"]
    ohmic, eta, f_ref = at_ref["losses"]["ohmic"], at_ref["eta"], at_ref["frequency_Hz"]
    if core <= 0.0:  # a catalog motor states no core losses: no optimum, loss falls with n
        return math.inf
    f_opt = bldc.optimum_frequency_Hz(ohmic, core, f_ref)
    for _ in range(4):
        n = f_opt * 60.0 / pole_pairs
        q = n / req.rotary.speed_rpm
        split = wg_rules.split_ratio(q, rd.STAGE_RATIO_MIN, rd.STAGE_RATIO_MAX).value
        if not split:
            break
        adopted = params.stage_efficiency ** _stage_count(q, split, req, params)
        if adopted == eta:
            break
        ohmic, eta = ohmic * (eta / adopted) ** 2, adopted
        f_opt = bldc.optimum_frequency_Hz(ohmic, core, f_ref)
    return f_opt


class _Fit(NamedTuple):
    """A frame tried for the requirement: its candidates, limit and what passes."""

    ref: object
    steel: object
    steel_mass: float
    terms: object
    reducible: list[dict]
    passing: list[dict]
    limit: float
    basis: str
    f_opt: float
    n_opt: float
    frame_for: object
    error: InfeasibleError | None


def _fit(req: Requirements, cat: Catalogs, ref, params, data, speeds: list[float]) -> _Fit:
    """Seed 000's model with the frame ``ref``'s numbers: its candidates, its limit (its own
    losses at its own rated point), and the speeds that pass the point check and the duty."""
    mot, gb = req.motor, req.gearbox
    steel = _steel(req, cat, ref)
    steel_mass = bldc.stator_steel_mass(
        ref.stator_steel_area_mm2, ref.stack_length_mm, ref.stacking_factor, ref.steel_density_kg_m3
    )
    terms = bldc.fit_eq5(steel.p10_50_W_kg, steel.p15_50_W_kg, steel.p10_400_W_kg)
    cands = [_candidate(n, req, steel, steel_mass, terms, params, ref) for n in speeds]
    reducible = [c for c in cands if c["split"]]
    if not reducible:
        raise InfeasibleError(
            "no feasible design: no candidate speed gives a ratio a wave-gear reducer can make",
            [
                *(f"{c['speed_rpm']:g} rpm → q_Σ = {c['q_total']:.4g}" for c in cands),
                _ratio_hint(req.rotary.speed_rpm, [c["speed_rpm"] for c in cands]),
            ],
        )
    # eq. (10) at the reference speed, with the losses of the model in use; where no reducer
    # makes the reference speed's ratio, at the candidate nearest to it (K_om and K_mag are
    # the constants of eqs. (9) and (5), read at any operating point), never nan
    at_ref = _candidate(ref.speed_rpm, req, steel, steel_mass, terms, params, ref)
    if not at_ref["split"]:
        at_ref = min(reducible, key=lambda c: abs(math.log(c["speed_rpm"] / ref.speed_rpm)))
    f_opt = _loss_optimum_Hz(at_ref, req, params, ref.pole_pairs)
    n_opt = f_opt * 60.0 / ref.pole_pairs
    # the frame's limit is thermal: a speed is a candidate only if its losses are carried
    limit, basis = bm.loss_limit(mot, steel, steel_mass, terms, ref)
    frame_for = None

    def fit(passing: list[dict], error: InfeasibleError | None = None) -> _Fit:
        args = (ref, steel, steel_mass, terms, reducible, passing, limit, basis, f_opt, n_opt)
        return _Fit(*args, frame_for, error)

    within = [c for c in reducible if bl_rules.within_limit(c["losses"]["total"], limit)]
    if getattr(ref, "kind", "") == "catalog":  # no core-loss data above the rated speed
        within = [c for c in within if c["speed_rpm"] <= ref.speed_rpm * (1 + 1e-9)]
        if not within and reducible:
            return fit([], bm.above_rated(reducible, ref))
    if not within:
        return fit([], _too_lossy(reducible, limit, basis, n_opt, gb.choice, _device_note(req)))
    if req.duty is None:
        return fit(within)
    from advisor.applications.rotary import (
        duty as dr,  # only the speeds whose motor passes the cycle
    )

    frame_for = dr.frames(ref, steel, steel_mass, terms, limit, data)
    offered = reducible if getattr(ref, "kind", "") != "catalog" else within
    try:
        passing = dr.passing_speeds(
            req, offered, frame_for, lambda c: _holder(req, c["q_total"], c["eta"]), limit
        )
    except InfeasibleError as exc:
        return fit([], exc)
    return fit(passing)


def _best_words(fit: _Fit) -> str:
    """The numbers of a tried frame's least lossy candidate, for BL-03."""
    best = min(fit.reducible, key=lambda c: c["losses"]["total"])
    if (
        fit.error is not None
        and fit.passing == []
        and bl_rules.within_limit(best["losses"]["total"], fit.limit)
    ):
        return fit.error.reasons[0] if fit.error.reasons else fit.error.summary
    return (
        f"at {best['speed_rpm']:g} rpm ({best['torque_Nm']:.4g} N·m of the motor) losses "
        f"{best['losses']['total']:.4g} W against its limit {fit.limit:.4g} W"
    )


def _choose_frame(req: Requirements, cat: Catalogs, params, speeds, trace: Trace):
    """The frame the design takes (BL-03 over the series and a catalog's motors, or the one
    the requirement imposes) and its fit; exit 3 naming the largest's reason when none fits."""
    from advisor.applications.rotary import frames as fr

    choice = fr.frame_choice(req.motor, cat)
    if choice.imposed is not None:
        ref = choice.imposed[0]
        data = fr.imposed_data(req, choice, cat)
        fit = _fit(req, cat, ref, params, data, speeds)
        if fit.error is not None:
            raise fit.error
        return fit, data, choice
    tried: list[dict] = []
    for frame in choice.series:
        data = fr.frame_data(req, frame)
        fit = _fit(req, cat, frame, params, data, speeds)
        tried.append(fr.tried_row(frame, fit.error is None, ""))
        if fit.error is None:
            best = min(fit.passing, key=lambda c: c["losses"]["total"])
            tried[-1]["why"] = (
                f"at {best['speed_rpm']:g} rpm it loses {best['losses']['total']:.4g} W of its "
                f"{fit.limit:.4g} W"
            )
            trace.apply(bl_rules.choose_frame, tried[-2:] if len(tried) > 1 else tried)
            return fit, data, choice._replace(tried=tuple(tried))
        tried[-1]["why"] = _best_words(fit)
    last = tried[-1]
    raise InfeasibleError(
        "no feasible design: no motor frame of the series carries the load",
        [
            f"the largest, {last['name']} ({last['torque_Nm']:.4g} N·m continuous, "
            f"{last['mass_kg']:.3g} kg): {last['why']}",
            fit.error.summary if fit.error is not None else "",
            "give a catalog motor (bldc_motors.toml in --catalog-dir), motor.max_losses_W "
            "with motor.frame for a better cooling, more candidate speeds, or a lower "
            "rotary.torque_Nm",
        ],
    )


def advise_rotary(req: Requirements, cat: Catalogs, trace: Trace):
    rot, mot, env, gb = req.rotary, req.motor, req.envelope, req.gearbox
    assert rot is not None and mot.kind == "bldc"
    # shared within one advice (a candidate at the reference speed), not across advices: a
    # repeated advice (the warm benchmark) computes everything again
    _adopted_stages.cache_clear()
    trace.apply(bl_rules.motor_type)
    trace.apply(wg_rules.reducer_type, rot.torque_Nm)

    # the stages are sized (eq. (16)) for the output torque times the service factor: every
    # strength check of the reducer then holds f_B·demand within its capacity (issue 26)
    sf = service_factor(req.design)
    params = rd.ReducerParams(
        torque_Nm=reducer_output_torque(req) * sf.value,
        k_rb=wg.ROLLING_BODY_FACTOR[gb.rolling_body],
        stage_efficiency=gb.stage_efficiency,
        density_kg_m3=gb.density_kg_m3,
        fill_factor=gb.fill_factor,
    )
    speeds = sorted(set(mot.candidate_speeds_rpm))
    fit, data, choice = _choose_frame(req, cat, params, speeds, trace)
    ref, steel, steel_mass = fit.ref, fit.steel, fit.steel_mass
    reducible, limit, basis = fit.passing, fit.limit, fit.basis
    f_opt, n_opt, frame_for = fit.f_opt, fit.n_opt, fit.frame_for
    # BL-02 weighs every reducible speed (those over the limit shown, not chosen), or, with a
    # cycle or a catalog motor, only those that pass it (or lie within its rated speed)
    catalog = getattr(ref, "kind", "") == "catalog"
    offered = fit.passing if req.duty is not None or catalog else fit.reducible
    speed = trace.apply(
        bl_rules.choose_speed,
        {c["speed_rpm"]: c["losses"]["total"] for c in offered},
        n_opt,
        ref.pole_pairs,
        limit,
        basis,
        {c["speed_rpm"]: c["current_A"] for c in offered},
    )
    chosen = next(c for c in offered if c["speed_rpm"] == speed)
    reducible = fit.reducible if req.duty is None else fit.passing

    # ---- reducer
    q_total = chosen["q_total"]
    split = trace.apply(wg_rules.split_ratio, q_total, rd.STAGE_RATIO_MIN, rd.STAGE_RATIO_MAX)
    needed = _rows_needed(params.torque_Nm, env.max_outer_diameter_mm, split, params)
    rows = trace.apply(wg_rules.choose_rows, len(split), needed, MAX_ROWS)
    space = rd.sweep(q_total, params)
    optimum = _optimum(space, q_total, "mass", params, env)
    slimmest = _optimum(space, q_total, "diameter", params, env)
    if optimum is None or slimmest is None:
        raise _no_reducer(space, params.torque_Nm, env)
    rule_design = rd.evaluate(split, rows, params) if rows else None
    options = wg_rules.ReducerOptions(
        gb.choice, rule_design, optimum, slimmest, env.max_outer_diameter_mm, env.max_length_mm
    )
    design, taken, warnings = _adopt(options, trace)
    if taken == "rules":
        warnings += trace.apply(
            wg_rules.compare_with_optimum,
            design.mass_kg,
            optimum.mass_kg,
            design.outer_diameter_mm,
            slimmest.outer_diameter_mm,
        )
    pareto = _pareto(space, design, params, env, trace, taken, gb.choice)

    # the motor torque follows the reducer actually adopted (its efficiency) and the holding
    # device's driving efficiency
    motor_torque = rot.torque_Nm / (design.total_ratio * design.efficiency * device_efficiency(req))
    working = {
        **chosen,
        "q_total": design.total_ratio,
        "eta": design.efficiency,
        "torque_Nm": motor_torque,
        "current_A": bldc.rewound_current_A(
            ref.current_A, ref.torque_Nm, ref.speed_rpm, motor_torque, speed
        ),
        "losses": bm.losses_at(ref, chosen["losses"]["iron"], speed, motor_torque),
    }
    if not bl_rules.within_limit(working["losses"]["total"], limit):
        raise _too_lossy([working], limit, basis, n_opt, gb.choice, _device_note(req))
    steel_cite = cat.cite_rows(cat.steel_sources, steel.source)
    checks = _checks(design, env, working["losses"]["total"], limit, basis, steel_cite)
    motor = _motor_out(working, reducible, ref, steel, steel_mass, f_opt, n_opt, limit, basis)
    from advisor.applications.rotary import frames as fr

    motor = motor.replace(frame=fr.frame_out(choice, ref, data))
    gearbox = GearboxOut.make(
        kind="wave gear with rolling bodies",
        layout="equal-diameter",
        rolling_body=gb.rolling_body,
        **_summary_fields(design),
        optimum=GearboxSummaryOut.make(**_summary_fields(optimum)),
        optimum_min_diameter=GearboxSummaryOut.make(**_summary_fields(slimmest)),
        sweep=SweepOut.make(
            configurations=space.evaluated,
            feasible=space.feasible,
            stage_counts=[int(n) for n in rd.stage_count_bounds(q_total)],
            objective_mass="least mass within the envelope",
            objective_diameter="least outer diameter within the envelope",
        ),
        pareto=pareto,
        fig1=_fig1(params.k_rb),
    )
    one_way = None
    if req.application.hold_without_power:
        one_way, dev_checks, dev_warnings = _one_way(
            req, trace, design, working, limit, basis, steel_cite, ref
        )
        checks += dev_checks
        warnings += dev_warnings
    duty = None
    if req.duty is not None:
        from advisor.applications.rotary import duty as dr

        holder = _holder(req, design.total_ratio, design.efficiency)
        duty, duty_checks, duty_warnings = dr.advise_duty(
            req, design.total_ratio, design.efficiency, speed, frame_for(speed), holder, trace
        )
        checks += duty_checks
        warnings += duty_warnings
    extra = _reviewer_checks(req, cat, design, speed, frame_for if req.duty else None, sf)
    checks += extra.checks
    warnings += extra.warnings
    design_out = RotaryDesignOut.make(
        motor=motor,
        gearbox=gearbox,
        one_way=one_way,
        duty=duty,
        reducer_load=extra.reducer_load,
        output_bearing=extra.output_bearing,
        regeneration=extra.regeneration,
    )
    return design_out, checks, warnings


class _Review(NamedTuple):
    reducer_load: object
    output_bearing: object
    regeneration: object
    checks: list[Check]
    warnings: list[str]


def _reviewer_checks(req, cat, design: rd.Reducer, speed: float, frame_for, sf) -> _Review:
    """Issue 26: the reducer under its load spectrum, the output bearing under an external
    load, and the regenerated energy of the duty cycle (:mod:`.loads`)."""
    from advisor.applications.rotary import loads

    q, eta = design.total_ratio, design.efficiency
    if req.duty is not None:
        from advisor.applications.rotary import duty as dr

        holder = _holder(req, q, eta)
        spectrum = dr.output_loads(req, q, eta, speed, frame_for(speed), holder)
        regeneration = loads.regeneration(
            dr.motor_phases(req, q, eta, speed, frame_for(speed), holder), req.drive
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
    from advisor.applications.rotary import duty as dr

    if not req.application.hold_without_power:
        return dr.NO_HOLDER
    from advisor.one_way.advice import device_passage

    at_output = req.one_way.location == "output_side"
    motor_side, output_side = _device_torques(req, q, eta)
    return dr.Holder(device_passage(req.one_way, motor_side, output_side, at_output), at_output)


def _device_torques(req: Requirements, q: float, eta: float) -> tuple[float, float]:
    """The torques the holding device is sized for, at the motor side and at the output: the
    output torque or, if larger, the emergency stop's momentary peak (issue 26, item 4), each
    times the service factor; M/(q·η) at the motor side (seed 004, OW-01)."""
    out = req.rotary.torque_Nm
    stop = req.rotary.emergency_stop_torque_Nm
    sized = max(out, stop or 0.0) * service_factor(req.design).value
    return sized / (q * eta), sized


def _one_way(
    req, trace, design: rd.Reducer, working: dict, limit: float, basis: str, steel_cite: Cite, ref
):
    """Seed 004: the holding device at the motor side (or at the output, where the requirement
    puts it), and what it asks of the motor: its driving loss raises the motor torque, hence
    the copper loss, at the same speed, wherever it sits (the motor gives 1/η_d times the
    torque either way)."""
    from advisor.one_way.advice import choose_device
    from rules import one_way as ow_rules

    q, eta = design.total_ratio, design.efficiency
    sized_motor, sized_output = _device_torques(req, q, eta)
    # the torque where the device sits (OW-01): the output torque or the emergency stop's,
    # whichever is larger, times the service factor; the decision states the device's torque
    trace.apply(ow_rules.placement, sized_output, q, eta, req.one_way.location)
    motor_torque, speed = working["torque_Nm"], working["speed_rpm"]
    power = motor_torque * speed * math.pi / 30.0
    at_output = req.one_way.location == "output_side"
    device, warnings = choose_device(
        req.one_way, sized_motor, sized_output, power, trace, at_output=at_output
    )
    device = device.replace(basis=device.basis + _sized_for(req))
    checks = []
    if device.efficiency < 1.0:
        # the motor torque (and so the losses the speed choice weighed) already includes the
        # device's 1/η_d: this check states that share of the losses by name
        with_device = bm.losses_at(ref, working["losses"]["iron"], speed, motor_torque)["total"]
        checks.append(
            bm.losses_check(
                "motor_losses_with_one_way",
                "motor losses with the one-way device's loss",
                with_device,
                limit,
                (ow_rules.SEED_004 + SEED_000.at("eq. (4)") + steel_cite).with_note(basis),
            )
        )
    return device, checks, warnings


def _sized_for(req: Requirements) -> str:
    """What the device is sized for, in words, where it is more than the output torque: it
    holds the emergency stop's momentary peak by its sizing (a check of it against the same
    torque could only state a margin of 1.000)."""
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


def _from_sweep(space: rd.SweepResult, i: int, params: rd.ReducerParams) -> rd.Reducer:
    ratios = space.ratios_out_to_in(i)
    return rd.evaluate(ratios, [int(space.rows_out[i])] + [2] * (len(ratios) - 1), params)


def _optimum(space, q_total, objective, params, env) -> rd.Reducer | None:
    """The best of the design space; within an envelope the optimum lies on it, between
    grid points, and the best grid point is polished (without one the boundary points the
    sweep adds hold the mass optimum)."""
    d_max, l_max = env.max_outer_diameter_mm, env.max_length_mm
    if d_max is None and l_max is None:
        i = rd.best(space, objective)
        return None if i is None else _from_sweep(space, i, params)
    found = rd.refine(q_total, params, space, objective, d_max, l_max)
    if found is None:
        return None
    ratios, rows = found
    return rd.evaluate(ratios, [rows] + [2] * (len(ratios) - 1), params)


def _pareto(space, design: rd.Reducer, params, env, trace, taken: str, asked: str) -> ParetoOut:
    """The non-dominated set of the design space (thinned) and where ``design`` stands."""
    d_max, l_max = env.max_outer_diameter_mm, env.max_length_mm
    eta = params.stage_efficiency
    front = rd.pareto(space, eta, d_max, l_max)
    shown = rd.thin(front, PARETO_POINTS)
    j = rd.dominator(space, design, d_max, l_max)
    point = _pareto_point(space, j, eta) if j is not None else None
    trace.apply(
        wg_rules.compare_with_front,
        int(front.size),
        int(shown.size),
        {
            "mass_kg": design.mass_kg,
            "outer_diameter_mm": design.outer_diameter_mm,
            "length_mm": design.length_mm,
            "stages": len(design.stages),
        },
        None if point is None else point.as_dict(),
        taken,
        asked,
    )
    return ParetoOut.make(
        objectives=["least mass", "least outer diameter", "least length", "highest efficiency"],
        front_size=int(front.size),
        adopted="on the front" if point is None else "dominated",
        dominated_by=point,
        stages=[int(space.stages[i]) for i in shown],
        ratios=[space.ratios_out_to_in(int(i)) for i in shown],
        rows_out=[int(space.rows_out[i]) for i in shown],
        mass_kg=[float(space.mass_kg[i]) for i in shown],
        outer_diameter_mm=[float(space.outer_diameter_mm[i]) for i in shown],
        length_mm=[float(space.length_mm[i]) for i in shown],
        efficiency=[eta ** int(space.stages[i]) for i in shown],
    )


def _pareto_point(space: rd.SweepResult, i: int, eta: float) -> ParetoPointOut:
    return ParetoPointOut.make(
        stages=int(space.stages[i]),
        ratios=space.ratios_out_to_in(i),
        rows_out=int(space.rows_out[i]),
        mass_kg=float(space.mass_kg[i]),
        outer_diameter_mm=float(space.outer_diameter_mm[i]),
        length_mm=float(space.length_mm[i]),
        efficiency=eta ** int(space.stages[i]),
    )


def _no_reducer(space: rd.SweepResult, torque: float, env) -> InfeasibleError:
    reasons = []
    if space.mass_kg.size == 0:
        reasons.append("no stage count of up to four realises the ratio within the stage limits")
    else:
        k = int(np.argmin(space.outer_diameter_mm))
        reasons.append(
            f"the smallest outer diameter in the design space for {torque:g} N·m is "
            f"{space.outer_diameter_mm[k]:.4g} mm ({int(space.rows_out[k])} rows, q_out = "
            f"{space.q_out[k]:g})"
            + (
                f" against the envelope's {env.max_outer_diameter_mm:g} mm"
                if env.max_outer_diameter_mm
                else ""
            )
        )
        if env.max_length_mm:
            ok_d = (
                space.outer_diameter_mm <= env.max_outer_diameter_mm
                if env.max_outer_diameter_mm
                else np.ones(space.mass_kg.size, bool)
            )
            if ok_d.any():
                reasons.append(
                    f"of those within the diameter the shortest is "
                    f"{space.length_mm[ok_d].min():.4g} mm against the envelope's "
                    f"{env.max_length_mm:g} mm"
                )
    return InfeasibleError(
        "no feasible design: no reducer in the design space fits the envelope", reasons
    )


def _checks(
    design: rd.Reducer, env, losses_W: float, limit_W: float, basis: str, steel_cite: Cite
) -> list[Check]:
    checks = []
    if env.max_outer_diameter_mm:
        checks.append(
            Check(
                "envelope_diameter",
                "reducer outer diameter within the envelope",
                design.outer_diameter_mm,
                env.max_outer_diameter_mm,
                "mm",
                env.max_outer_diameter_mm / design.outer_diameter_mm,
                ENVELOPE,
            )
        )
    if env.max_length_mm:
        checks.append(
            Check(
                "envelope_length",
                "reducer length within the envelope",
                design.length_mm,
                env.max_length_mm,
                "mm",
                env.max_length_mm / design.length_mm,
                ENVELOPE,
            )
        )
    for s in design.stages:
        checks.append(
            Check(
                f"bore_{s.position}",
                f"{s.position} stage ratio leaves a bore (eq. (14): "
                f"q > {wg.MIN_RATIO_FOR_BORE:.3g})",
                s.ratio,
                wg.MIN_RATIO_FOR_BORE,
                "",
                s.ratio / wg.MIN_RATIO_FOR_BORE,
                SEED_000.at("eq. (14)"),
            )
        )
        if s.position == "output":
            # the output stage sets the common diameter: checking it against itself would
            # always give margin 1 and hide the real lowest margin of the design
            continue
        checks.append(
            Check(
                f"fits_{s.position}",
                f"{s.position} stage's own outer diameter within the common one",
                s.own_outer_diameter_mm,
                s.outer_diameter_mm,
                "mm",
                s.outer_diameter_mm / s.own_outer_diameter_mm,
                SEED_000.at("eqs. (13), (16)"),
            )
        )
    checks.append(
        bm.losses_check(
            "motor_losses",
            "motor total losses against what the frame's cooling carries",
            losses_W,
            limit_W,
            (SEED_000.at("eqs. (4), (5), (9)") + steel_cite).with_note(basis),
        )
    )
    return checks


def _stages_out(r: rd.Reducer) -> list[StageOut]:
    return [
        StageOut.make(
            position=s.position,
            ratio=s.ratio,
            rows=s.rows,
            torque_Nm=s.torque_Nm,
            rolling_body_diameter_mm=s.rolling_body_diameter_mm,
            own_outer_diameter_mm=s.own_outer_diameter_mm,
            outer_diameter_mm=s.outer_diameter_mm,
            inner_diameter_mm=s.inner_diameter_mm,
            length_mm=s.length_mm,
            mass_kg=s.mass_kg,
        )
        for s in r.stages
    ]


def _summary_fields(r: rd.Reducer) -> dict:
    return {
        "total_ratio": r.total_ratio,
        "efficiency": r.efficiency,
        "outer_diameter_mm": r.outer_diameter_mm,
        "inner_diameter_mm": r.inner_diameter_mm,
        "length_mm": r.length_mm,
        "volume_cm3": r.volume_mm3 / 1e3,
        "mass_kg": r.mass_kg,
        "stages": _stages_out(r),
    }


def _fig1(k_rb: float) -> Fig1Out:
    """Seed 000, fig. 1: one stage's volume per unit load torque against q, per row count."""
    q = np.arange(7.0, 41.0)
    table = wg.volume_per_torque(q[None, :], np.array(FIG1_ROWS)[:, None], k_rb) / 1e3
    return Fig1Out.make(
        q=[float(x) for x in q],
        rows=FIG1_ROWS,
        volume_per_torque_cm3_per_Nm=[[float(x) for x in row] for row in table],
    )


def _losses(d: dict) -> LossesOut:
    return LossesOut.make(**{k: float(v) for k, v in d.items()})


def _motor_out(
    chosen, candidates, ref, steel, steel_mass, f_opt, n_opt, limit, basis
) -> BldcMotorOut:
    options = [c for c in bldc.pole_slot_combinations(3, 36) if c.pole_pairs == ref.pole_pairs]
    return BldcMotorOut.make(
        kind="bldc",
        speed_rpm=chosen["speed_rpm"],
        pole_pairs=ref.pole_pairs,
        electrical_frequency_Hz=chosen["frequency_Hz"],
        torque_Nm=chosen["torque_Nm"],
        current_A=chosen["current_A"],
        losses_W=_losses(chosen["losses"]),
        loss_limit_W=limit,
        loss_limit_basis=basis,
        optimum_frequency_Hz=f_opt if math.isfinite(f_opt) else None,
        optimum_speed_rpm=n_opt if math.isfinite(n_opt) else None,
        steel=SteelOut.make(
            grade=steel.grade,
            thickness_mm=steel.thickness_mm,
            equivalent=steel.equivalent,
            mass_kg=steel_mass,
            p15_50_W_kg=steel.p15_50_W_kg,
            specific_loss_W_kg=chosen["spec"],
            specific_loss_three_term_W_kg=chosen["spec_three"],
            iron_loss_model=ref.iron_loss_model,
            estimated=list(steel.estimated),
        ),
        candidates=[
            SpeedCandidateOut.make(
                speed_rpm=c["speed_rpm"],
                electrical_frequency_Hz=c["frequency_Hz"],
                total_ratio=c["q_total"],
                stages=c["stages"],
                gearbox_efficiency=c["eta"],
                torque_Nm=c["torque_Nm"],
                current_A=c["current_A"],
                within_loss_limit=bl_rules.within_limit(c["losses"]["total"], limit),
                losses_W=_losses(c["losses"]),
                iron_loss_three_term_W=c["iron_three_term_W"],
            )
            for c in candidates
        ],
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
