"""The candidate motor speeds of the rotary advice (seed 000): at each, the frame rewound for
it, behind the reducer the design would adopt at its ratio, with its losses; and the reducer
the design adopts at a total ratio (the rules' design, or WG-06's choice from the space)."""

import functools
import math
from typing import Any, NamedTuple

from advisor.applications.rotary.motor import Losses, losses_at, specific_iron_loss
from advisor.calc import bldc, reducer, wavegear
from advisor.core.errors import InputError
from advisor.core.reading import Requirements
from catalogs import Catalogs
from rules import wavegear as wavegear_rules

MAX_ROWS = int(reducer.ROW_GRID.max())


class Envelope(NamedTuple):
    max_outer_diameter_mm: float | None
    max_length_mm: float | None


class FrameModel(NamedTuple):
    """A frame's iron-loss model: the frame, its steel (catalog row), the steel's mass [kg]
    and the fitted terms of eq. (5)."""

    ref: Any
    steel: Any
    steel_mass_kg: float
    terms: Any


class SpeedCandidate(NamedTuple):
    """One candidate motor speed (seed 000): the frame rewound for it behind the reducer the
    design would adopt at its ratio. The first fields are the report's candidate table's."""

    speed_rpm: float
    electrical_frequency_Hz: float
    total_ratio: float
    stages: int  # 0: no reducer of the rules realises the ratio
    gearbox_efficiency: float
    torque_Nm: float
    current_A: float
    losses_W: Losses
    iron_loss_three_term_W: float
    split: list[float] | None  # WG-02's ratios, output first
    specific_loss_W_kg: float
    specific_loss_three_term_W_kg: float


def steel_for(req: Requirements, cat: Catalogs, ref=None):
    """The catalog row of the frame's electrical steel; an input error naming the catalog's
    grades when it holds none of that grade and thickness."""
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


def frame_model(req: Requirements, cat: Catalogs, ref) -> FrameModel:
    """The frame's steel, its mass and the terms of eq. (5) fitted to the steel's losses."""
    steel = steel_for(req, cat, ref)
    steel_mass = bldc.stator_steel_mass(
        ref.stator_steel_area_mm2, ref.stack_length_mm, ref.stacking_factor, ref.steel_density_kg_m3
    )
    terms = bldc.fit_eq5(steel.p10_50_W_kg, steel.p15_50_W_kg, steel.p10_400_W_kg)
    return FrameModel(ref, steel, steel_mass, terms)


def device_efficiency(req: Requirements) -> float:
    """The driving efficiency of the holding device the requirement asks for, known before the
    frame, the speed and the reducer are chosen (seed 004): the motor gives 1/η_d times the
    torque wherever the device sits, so every loss the choices weigh includes it. 'auto'
    chooses between the two clutches (OW-02), both of η = 1."""
    if not req.application.hold_without_power or req.one_way.type == "auto":
        return 1.0
    from advisor.calc import one_way

    return one_way.passage(req.one_way.type).efficiency


def output_stage_torque(req: Requirements, torque_Nm: float) -> float:
    """The torque the reducer's output stage delivers for a torque at the load: the torque
    itself, or with a holding device at the output (between the load and the reducer) the
    device's input torque, M/η_d (seed 004)."""
    if req.application.hold_without_power and req.one_way.location == "output_side":
        return torque_Nm / device_efficiency(req)
    return torque_Nm


def reducer_output_torque(req: Requirements) -> float:
    """The torque the reducer's output stage delivers at the rated point
    (:func:`output_stage_torque` of ``rotary.torque_Nm``): the stages are sized for it."""
    return output_stage_torque(req, req.rotary.torque_Nm)


def speed_candidate(
    n: float, req: Requirements, model: FrameModel, params: reducer.ReducerParams
) -> SpeedCandidate:
    """Losses and drive figures of the frame rewound for speed ``n``, behind the reducer the
    design would adopt at its ratio (:func:`stage_count`): the efficiency the speed choice
    (BL-02) weighs is the one the design then has."""
    rot = req.rotary
    ref = model.ref
    q_total = n / rot.speed_rpm
    split = wavegear_rules.split_of(
        q_total, reducer.STAGE_RATIO_MIN, reducer.STAGE_RATIO_MAX
    ).ratios
    stages = stage_count(q_total, split, req, params) if split else 0
    eta = params.stage_efficiency**stages if stages else math.nan
    # the holding device's driving loss is the motor's too: it gives 1/η_d times the torque
    torque = rot.torque_Nm / (q_total * eta * device_efficiency(req)) if stages else math.nan
    f = bldc.flux_frequency_Hz(n, ref.pole_pairs)
    spec, spec_three = specific_iron_loss(ref, model.steel, model.terms, f)
    return SpeedCandidate(
        speed_rpm=n,
        electrical_frequency_Hz=f,
        total_ratio=q_total,
        stages=stages,
        gearbox_efficiency=eta,
        torque_Nm=torque,
        # the winding rewound for n: current ∝ torque·n (seed 000, eq. (4)); reported only
        current_A=bldc.rewound_current_A(ref.current_A, ref.torque_Nm, ref.speed_rpm, torque, n),
        losses_W=losses_at(ref, model.steel_mass_kg * spec, n, torque),
        iron_loss_three_term_W=model.steel_mass_kg * spec_three,
        split=split,
        specific_loss_W_kg=spec,
        specific_loss_three_term_W_kg=spec_three,
    )


def rows_needed(
    torque_Nm: float, d_max: float | None, split: list[float], params: reducer.ReducerParams
) -> float | None:
    """The rows the envelope diameter asks of the output stage (seed 000, the inequality
    after eq. (19)); None without a diameter limit."""
    if not d_max:
        return None
    return float(wavegear.rows_for_diameter(torque_Nm, split[0], d_max, params.k_rb))


def stage_count(q_total: float, split: list[float], req: Requirements, params) -> int:
    """See :func:`adopted_stages`: the same, from a requirement."""
    env = req.envelope
    return adopted_stages(
        q_total,
        tuple(split),
        params.torque_Nm,
        req.gearbox.choice,
        env.max_outer_diameter_mm,
        env.max_length_mm,
        params,
    )


@functools.lru_cache(maxsize=64)
def adopted_stages(
    q_total: float,
    split: tuple[float, ...],
    torque_Nm: float,
    choice: str,
    d_max: float | None,
    l_max: float | None,
    params,
) -> int:
    """The stage count of the reducer the design adopts at ``q_total``: the rules' split
    (WG-02) where WG-06 lets the rule design stand; otherwise the design space's lightest
    (or slimmest) within the envelope, as the advice adopts. The rules' count where the
    space has none that fits (the advice then says so)."""
    if choice == "rules" and d_max is None and l_max is None:
        return len(split)  # without an envelope the rule design always fits: WG-06 is silent
    split_list = list(split)
    rule_design = None
    if choice == "rules":
        needed = rows_needed(torque_Nm, d_max, split_list, params)
        rows = wavegear_rules.choose_rows(len(split_list), needed, MAX_ROWS).value
        rule_design = reducer.evaluate(split_list, rows, params) if rows else None
    taken = wavegear_rules.space_choice(choice, rule_design, d_max, l_max)
    if taken is None:
        return len(split_list)
    space = reducer.sweep(q_total, params)
    objective = "diameter" if taken == "slimmest" else "mass"
    best = optimum(space, q_total, objective, params, Envelope(d_max, l_max))
    return len(best.stages) if best is not None else len(split_list)


def from_sweep(
    space: reducer.SweepResult, i: int, params: reducer.ReducerParams
) -> reducer.Reducer:
    """Configuration ``i`` of the design space as a reducer (two rows before the output)."""
    ratios = space.ratios_out_to_in(i)
    return reducer.evaluate(ratios, [int(space.rows_out[i])] + [2] * (len(ratios) - 1), params)


def optimum(
    space: reducer.SweepResult,
    q_total: float,
    objective: str,
    params: reducer.ReducerParams,
    env: Envelope,
) -> reducer.Reducer | None:
    """The best of the design space; within an envelope the optimum lies on it, between
    grid points, and the best grid point is polished (without one the boundary points the
    sweep adds hold the mass optimum)."""
    d_max, l_max = env.max_outer_diameter_mm, env.max_length_mm
    if d_max is None and l_max is None:
        i = reducer.best(space, objective)
        return None if i is None else from_sweep(space, i, params)
    found = reducer.refine(q_total, params, space, objective, d_max, l_max)
    if found is None:
        return None
    ratios, rows = found
    return reducer.evaluate(ratios, [rows] + [2] * (len(ratios) - 1), params)


#: Points of the loss curve between a quarter of the lowest candidate speed and twice the
#: highest (log-spaced), besides the candidates themselves.
CURVE_POINTS = 40


class LossCurve(NamedTuple):
    """The losses against speed [rpm, W], the frame's limit beside them [W], and a catalog
    motor's rated speed, above which it states no losses [rpm] (None for other frames)."""

    speed_rpm: list[float]
    ohmic_W: list[float]
    iron_W: list[float]
    magnets_W: list[float]
    total_W: list[float]
    limit_W: list[float]
    speed_limit_rpm: float | None


def curve_speeds(candidates_rpm: list[float], points: int = CURVE_POINTS) -> list[float]:
    """The candidate speeds and ``points`` log-spaced speeds from a quarter of the lowest to
    twice the highest, sorted."""
    lo, hi = min(candidates_rpm) / 4, max(candidates_rpm) * 2
    grid = (lo * (hi / lo) ** (k / (points - 1)) for k in range(points))
    return sorted({*candidates_rpm, *grid})


def loss_curve(
    req: Requirements,
    model: FrameModel,
    params: reducer.ReducerParams,
    candidates_rpm: list[float],
    limit_W: float,
) -> LossCurve:
    """The losses of the frame rewound for each speed of :func:`curve_speeds`, computed as
    the candidates are (:func:`speed_candidate`: seed 000, eqs. (4), (5), (9), behind the
    reducer the design would adopt at each ratio), so the curve passes through every
    candidate; the U of eq. (10) the speed choice rests on. A speed no reducer realises has
    no torque and no losses and is left out; a catalog motor's curve ends at its rated
    speed."""
    ref = model.ref
    speed_limit = ref.speed_rpm if getattr(ref, "kind", "") == "catalog" else None
    points = [
        c
        for c in (speed_candidate(n, req, model, params) for n in curve_speeds(candidates_rpm))
        if c.split and (speed_limit is None or c.speed_rpm <= speed_limit * (1 + 1e-9))
    ]
    return LossCurve(
        speed_rpm=[c.speed_rpm for c in points],
        ohmic_W=[c.losses_W.ohmic for c in points],
        iron_W=[c.losses_W.iron for c in points],
        magnets_W=[c.losses_W.magnets for c in points],
        total_W=[c.losses_W.total for c in points],
        limit_W=[limit_W] * len(points),
        speed_limit_rpm=speed_limit,
    )
