"""The wave-gear reducer of the rotary advice (seed 000): the rules' design (WG-02, WG-03),
the design space it stands against (sweep, optima, Pareto front: WG-04, WG-05), the one
adopted (WG-06), its checks and its report table."""

import functools
from typing import NamedTuple

import numpy as np

from advisor.applications.rotary.candidates import (
    MAX_ROWS,
    Envelope,
    optimum,
    rows_needed,
)
from advisor.applications.rotary.report import (
    Fig1Out,
    GearboxOut,
    GearboxSummaryOut,
    ParetoOut,
    ParetoPointOut,
    StageOut,
    SweepOut,
)
from advisor.calc import reducer, wavegear
from advisor.calc.checks import Check
from advisor.core.cite import note
from advisor.core.errors import InfeasibleError
from advisor.core.rulebook import Trace
from rules import wavegear as wavegear_rules

SEED_000 = wavegear_rules.SEED_000
FIG1_ROWS = [2, 3, 4, 6, 8, 10, 12]
#: At most this many designs of the Pareto front in the report, evenly spaced along it.
PARETO_POINTS = 16
#: The envelope checks rest on the requirement itself, not on a published source.
ENVELOPE = note("the requirement's [envelope]")


class ReducerChoice(NamedTuple):
    """The reducer adopted at a total ratio and the design space it was weighed against."""

    design: reducer.Reducer
    taken: str  # "rules" | "lightest" | "slimmest"
    optimum: reducer.Reducer  # the lightest within the envelope
    slimmest: reducer.Reducer
    space: reducer.SweepResult
    pareto: ParetoOut
    warnings: list[str]


def choose_reducer(
    q_total: float, gearbox, env: Envelope, params: reducer.ReducerParams, trace: Trace
) -> ReducerChoice:
    """WG-02 and WG-03 give the rules' design; the design space its lightest and slimmest;
    WG-06 takes one of these where the rules' design does not stand; WG-04 or WG-05 say
    where the adopted one stands. An infeasible error when nothing of the space fits."""
    split = trace.apply(
        wavegear_rules.split_ratio, q_total, reducer.STAGE_RATIO_MIN, reducer.STAGE_RATIO_MAX
    )
    needed = rows_needed(params.torque_Nm, env.max_outer_diameter_mm, split, params)
    rows = trace.apply(wavegear_rules.choose_rows, len(split), needed, MAX_ROWS)
    space = reducer.sweep(q_total, params)
    lightest = optimum(space, q_total, "mass", params, env)
    slimmest = optimum(space, q_total, "diameter", params, env)
    if lightest is None or slimmest is None:
        raise no_reducer(space, params.torque_Nm, env)
    rule_design = reducer.evaluate(split, rows, params) if rows else None
    options = wavegear_rules.ReducerOptions(
        gearbox.choice,
        rule_design,
        lightest,
        slimmest,
        env.max_outer_diameter_mm,
        env.max_length_mm,
    )
    design, taken, warnings = adopt(options, trace)
    if taken == "rules":
        warnings += trace.apply(
            wavegear_rules.compare_with_optimum,
            design.mass_kg,
            lightest.mass_kg,
            design.outer_diameter_mm,
            slimmest.outer_diameter_mm,
        )
    front = pareto(space, design, params, env, trace, taken, gearbox.choice)
    return ReducerChoice(design, taken, lightest, slimmest, space, front, warnings)


def adopt(
    options: wavegear_rules.ReducerOptions, trace: Trace
) -> tuple[reducer.Reducer, str, list[str]]:
    """The reducer the design adopts: the rule design, or the one of the design space that
    WG-06 takes (and says why, where the requirement asked the rules)."""
    taken = wavegear_rules.space_choice(
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
    return trace.apply(wavegear_rules.taken_from_space, options), taken, warnings


def pareto(
    space: reducer.SweepResult,
    design: reducer.Reducer,
    params: reducer.ReducerParams,
    env: Envelope,
    trace: Trace,
    taken: str,
    asked: str,
) -> ParetoOut:
    """The non-dominated set of the design space (thinned) and where ``design`` stands."""
    d_max, l_max = env.max_outer_diameter_mm, env.max_length_mm
    eta = params.stage_efficiency
    front = reducer.pareto(space, eta, d_max, l_max)
    shown = reducer.thin(front, PARETO_POINTS)
    j = reducer.dominator(space, design, d_max, l_max)
    point = pareto_point(space, j, eta) if j is not None else None
    adopted = {
        "mass_kg": design.mass_kg,
        "outer_diameter_mm": design.outer_diameter_mm,
        "length_mm": design.length_mm,
        "stages": len(design.stages),
    }
    dominating = None if point is None else point.as_dict()
    stages = space.stages[shown].tolist()
    trace.apply(
        wavegear_rules.compare_with_front,
        int(front.size),
        int(shown.size),
        adopted,
        dominating,
        taken,
        asked,
    )
    return ParetoOut.make(
        objectives=["least mass", "least outer diameter", "least length", "highest efficiency"],
        front_size=int(front.size),
        adopted="on the front" if point is None else "dominated",
        dominated_by=point,
        stages=stages,
        ratios=[space.ratios_out_to_in(i) for i in shown.tolist()],
        rows_out=space.rows_out[shown].tolist(),
        mass_kg=space.mass_kg[shown].tolist(),
        outer_diameter_mm=space.outer_diameter_mm[shown].tolist(),
        length_mm=space.length_mm[shown].tolist(),
        efficiency=[eta**n for n in stages],
    )


def pareto_point(space: reducer.SweepResult, i: int, eta: float) -> ParetoPointOut:
    """Configuration ``i`` of the design space as the report states a point of the front."""
    return ParetoPointOut.make(
        stages=int(space.stages[i]),
        ratios=space.ratios_out_to_in(i),
        rows_out=int(space.rows_out[i]),
        mass_kg=float(space.mass_kg[i]),
        outer_diameter_mm=float(space.outer_diameter_mm[i]),
        length_mm=float(space.length_mm[i]),
        efficiency=eta ** int(space.stages[i]),
    )


def no_reducer(space: reducer.SweepResult, torque: float, env: Envelope) -> InfeasibleError:
    """Nothing of the design space fits the envelope: the smallest diameter (and, within
    the diameter, the shortest length) the space holds, against the envelope's."""
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
            reasons += _shortest_within_diameter(space, env)
    return InfeasibleError(
        "no feasible design: no reducer in the design space fits the envelope", reasons
    )


def _shortest_within_diameter(space: reducer.SweepResult, env: Envelope) -> list[str]:
    ok_d = (
        space.outer_diameter_mm <= env.max_outer_diameter_mm
        if env.max_outer_diameter_mm
        else np.ones(space.mass_kg.size, bool)
    )
    if not ok_d.any():
        return []
    return [
        f"of those within the diameter the shortest is "
        f"{space.length_mm[ok_d].min():.4g} mm against the envelope's "
        f"{env.max_length_mm:g} mm"
    ]


def envelope_checks(design: reducer.Reducer, env: Envelope) -> list[Check]:
    """The reducer's outer diameter and length against the envelope's."""
    checks = []
    for id, name, value, limit in (
        (
            "envelope_diameter",
            "outer diameter",
            design.outer_diameter_mm,
            env.max_outer_diameter_mm,
        ),
        ("envelope_length", "length", design.length_mm, env.max_length_mm),
    ):
        if limit:
            checks.append(
                Check(
                    id,
                    f"reducer {name} within the envelope",
                    value,
                    limit,
                    "mm",
                    limit / value,
                    ENVELOPE,
                )
            )
    return checks


def stage_checks(design: reducer.Reducer) -> list[Check]:
    """Each stage leaves a bore (eq. (14)); each stage before the output fits the common
    diameter (eqs. (13), (16))."""
    checks = []
    bore = wavegear.MIN_RATIO_FOR_BORE
    for s in design.stages:
        checks.append(
            Check(
                f"bore_{s.position}",
                f"{s.position} stage ratio leaves a bore (eq. (14): q > {bore:.3g})",
                s.ratio,
                bore,
                "",
                s.ratio / bore,
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
    return checks


#: The fields a reducer's stage shares with the report's stage table.
_STAGE_FIELDS = tuple(f for f in StageOut.field_names if f in reducer.Stage._fields)


def summary_fields(r: reducer.Reducer) -> dict:
    """A reducer as the report's summary table states it (volume in cm³)."""
    return {
        "total_ratio": r.total_ratio,
        "efficiency": r.efficiency,
        "outer_diameter_mm": r.outer_diameter_mm,
        "inner_diameter_mm": r.inner_diameter_mm,
        "length_mm": r.length_mm,
        "volume_cm3": r.volume_mm3 / 1e3,
        "mass_kg": r.mass_kg,
        "stages": [StageOut.make(**{f: getattr(s, f) for f in _STAGE_FIELDS}) for s in r.stages],
    }


@functools.cache
def _fig1_curves(k_rb: float) -> tuple[tuple[float, ...], tuple[tuple[float, ...], ...]]:
    """Seed 000, fig. 1 (q, and W/M [cm³/(N·m)] per row count): the seed's figure for one
    rolling body, the same in every design, so computed once."""
    q = np.arange(7.0, 41.0)
    table = wavegear.volume_per_torque(q[None, :], np.array(FIG1_ROWS)[:, None], k_rb) / 1e3
    return tuple(float(x) for x in q), tuple(tuple(float(x) for x in row) for row in table)


def fig1(k_rb: float) -> Fig1Out:
    """Seed 000, fig. 1: one stage's volume per unit load torque against q, per row count."""
    q, table = _fig1_curves(k_rb)
    return Fig1Out.make(
        q=list(q),
        rows=FIG1_ROWS,
        volume_per_torque_cm3_per_Nm=[list(row) for row in table],
    )


def gearbox_out(
    choice: ReducerChoice, q_total: float, rolling_body: str, k_rb: float
) -> GearboxOut:
    """The report's gearbox table: the adopted reducer and, beside it, the design space."""
    space = choice.space
    return GearboxOut.make(
        kind="wave gear with rolling bodies",
        layout="equal-diameter",
        rolling_body=rolling_body,
        **summary_fields(choice.design),
        optimum=GearboxSummaryOut.make(**summary_fields(choice.optimum)),
        optimum_min_diameter=GearboxSummaryOut.make(**summary_fields(choice.slimmest)),
        sweep=SweepOut.make(
            configurations=space.evaluated,
            feasible=space.feasible,
            stage_counts=[int(n) for n in reducer.stage_count_bounds(q_total)],
            objective_mass="least mass within the envelope",
            objective_diameter="least outer diameter within the envelope",
        ),
        pareto=choice.pareto,
        fig1=fig1(k_rb),
    )
