"""Rules of the wave-gear reducer with rolling bodies (seed 000)."""

import math
from typing import NamedTuple

from advisor.calc.reducer import Reducer, fits
from advisor.calc.wavegear import outer_diameter, rolling_body_diameter
from advisor.core.cite import cite
from advisor.core.rulebook import Finding, rule

SEED_000 = cite("seed-000")
TEXTBOOK = cite("textbook-2010", "fig. 1.72, cited by seed 000")

#: The output ratio the seed prefers, and its range (minimum outer diameter).
Q_OUT_PREFERRED = 20.0
Q_OUT_RANGE = (12.0, 20.0)
#: The ratio the seed gives the stage next to the output in a three-stage reducer.
Q_NEXT = 12.0


@rule("WG-01", "Type of reducer", SEED_000)
def reducer_type(torque_Nm: float) -> Finding[str]:
    return Finding(
        "wave gear with rolling bodies",
        "A reducer of wave gear stages with rolling bodies (ВПТК) in series.",
        "Seed 000, after its textbook [3]: of the mechanical transmissions compared by volume "
        "per unit of load torque against ratio, wave gears with rolling bodies are the smallest "
        "and lightest for the large ratios of an actuator.",
        {"torque_Nm": torque_Nm},
    )


def _output_diameter_factor(q: float, rows: int = 3) -> float:
    """D/∛M of a stage of ratio q with balls, seed 000, eqs. (13) and (16) at M = 1 N·m (the
    comparison of two ratios does not depend on the torque or the rolling body)."""
    return float(outer_diameter(q, rolling_body_diameter(1.0, q, rows)))


#: Relative tolerance of the stage ratio limits (rounding and typing, not engineering).
RATIO_REL_TOL = 1e-6


class Split(NamedTuple):
    """WG-02's split of a total ratio and the case of the seed's rules that gave it (the
    rule's words follow the case): ``below`` one stage's minimum, ``one`` stage, ``between``
    20 and 12·q_min (``one``/``two`` the options weighed and their D/∛M), ``two`` stages,
    ``more`` stages, ``above`` four stages."""

    ratios: list[float] | None
    case: str
    options: tuple[list[float] | None, list[float] | None, float, float] | None = None


def split_of(total_ratio: float, q_min: float, q_max: float) -> Split:
    """WG-02's split without its words: :func:`split_ratio` narrates it; the candidate speeds
    and the loss curve ask it for tens of speeds an advice."""
    q = total_ratio
    lo, hi = Q_OUT_RANGE
    # a ratio within RATIO_REL_TOL of a stage limit is at the limit: a speed typed as a round
    # number (6400 rpm to 5 rpm: q = 20 × 64) must not change the stage count when rounding
    # moves it by 1e-15, nor by a 1e-9 change of the requirement (a knife edge)
    at_least_min = q_min * (1 - RATIO_REL_TOL)
    at_most_max = q_max * (1 + RATIO_REL_TOL)
    if q < at_least_min:
        return Split(None, "below")
    if q <= hi:
        return Split([q], "one")
    if q < lo * q_min:
        one = [q] if q <= at_most_max else None
        two = [q / q_min, q_min] if q / q_min >= at_least_min else None
        d_one = _output_diameter_factor(q) if one else math.inf
        d_two = _output_diameter_factor(q / q_min) if two else math.inf
        return Split(one if d_one <= d_two else two, "between", (one, two, d_one, d_two))
    if q <= Q_OUT_PREFERRED * at_most_max:
        q_out = Q_OUT_PREFERRED if q / Q_OUT_PREFERRED >= at_least_min else q / q_min
        return Split([q_out, q / q_out], "two")
    for n in (3, 4):
        rest = q / (Q_OUT_PREFERRED * Q_NEXT ** (n - 2))
        if rest <= at_most_max:
            mids = [Q_NEXT] * (n - 2)
            if rest < at_least_min:  # lower the next stage to keep the input stage
                mids[0] = Q_NEXT * rest / q_min
                rest = q_min
            return Split([Q_OUT_PREFERRED, *mids, rest], "more")
    return Split(None, "above")


@rule("WG-02", "Stage count and split of the ratio", SEED_000 + TEXTBOOK)
def split_ratio(total_ratio: float, q_min: float, q_max: float) -> Finding[list[float] | None]:
    """Output stage q_out = 20 (12…20 gives the smallest outer diameter), the stage next to
    it 12, the remainder to the input stage; the fewest stages whose ratios stay within the
    per-stage limits. Ratios are listed from the output towards the motor.

    Where the seed's rules cannot all hold, the decision says which gave way: below
    q_Σ = 12 one stage is all there is (q_out < 12); between 20 and 12·q_min (≈ 78) neither
    one stage (q_out = q_Σ > 20) nor two (q_out = q_Σ/q_min < 12) keeps q_out within 12…20,
    and the option with the smaller outer diameter (eqs. (13), (16), three rows) is taken,
    the reason the seed gives for its 12…20. The split is :func:`split_of`'s."""
    q = total_ratio
    lo, hi = Q_OUT_RANGE
    split, case, options = split_of(q, q_min, q_max)
    if case == "below":
        return Finding(
            None,
            f"No reducer: the total ratio {q:.4g} is below one stage's minimum {q_min:g}.",
            "Eq. (14) leaves no bore below q ≈ 6.45.",
        )
    if case == "one":
        if q >= lo:
            return Finding(
                split,
                f"One stage, q = {q:.4g}.",
                "The whole ratio fits one output stage.",
                {"ratios": split},
            )
        return Finding(
            split,
            f"One stage, q = {q:.4g}: the rule q_out = {lo:g}…{hi:g} gives way.",
            f"q_Σ = {q:.4g} is below {lo:g}, so one stage carries the whole ratio and its "
            f"q_out lies below the seed's {lo:g}…{hi:g}; a second stage would need a ratio "
            f"below the minimum {q_min:g} (eq. (14)).",
            {"ratios": split},
        )
    if case == "between":
        assert options is not None
        return _between(q, q_min, split, *options)
    if case == "two":
        assert split is not None
        return _two(q, q_min, q_max, split)
    if case == "more":
        assert split is not None
        return _more(q, q_min, split)
    return Finding(
        None,
        f"No reducer of up to four stages reaches q_Σ = {q:.4g}.",
        f"Four stages give at most 20 × 12² × {q_max:g}.",
    )


def _between(
    q: float,
    q_min: float,
    split: list[float] | None,
    one: list[float] | None,
    two: list[float] | None,
    d_one: float,
    d_two: float,
) -> Finding[list[float] | None]:
    """WG-02's words where q_Σ lies between 20 and 12·q_min: no split keeps q_out within
    12…20, the option with the smaller outer diameter is taken."""
    lo, hi = Q_OUT_RANGE
    if d_one <= d_two:  # as split_of decides
        decision = f"One stage, q = {q:.4g}: the rule q_out = {lo:g}…{hi:g} gives way."
    else:
        decision = (
            f"Two stages: q_out = {q / q_min:.4g}, q1 = {q_min:g}: the rule "
            f"q_out = {lo:g}…{hi:g} gives way."
        )
    alternatives = []
    if one:
        alternatives.append(f"one stage (q_out = {q:.4g} > {hi:g}): D = {d_one:.4g}·∛M")
    if two:
        alternatives.append(
            f"two stages with the input stage at its minimum {q_min:g} "
            f"(q_out = {q / q_min:.4g} < {lo:g}): D = {d_two:.4g}·∛M"
        )
    return Finding(
        split,
        decision,
        f"q_Σ = {q:.4g} lies between {hi:g} and {lo:g} × {q_min:g} = {lo * q_min:.4g}: "
        f"no split keeps q_out within {lo:g}…{hi:g} and every stage at or above "
        f"{q_min:g} (eq. (14)). The seed keeps q_out within {lo:g}…{hi:g} for the "
        "smallest outer diameter, so the option with the smaller outer diameter "
        "(eqs. (13), (16), three rows at the output) is taken: " + "; ".join(alternatives) + ".",
        {
            "ratios": split,
            "outer_diameter_per_cbrt_torque": {
                k: v for k, v in (("one", d_one), ("two", d_two)) if math.isfinite(v)
            },
        },
    )


def _two(q: float, q_min: float, q_max: float, split: list[float]) -> Finding[list[float] | None]:
    """WG-02's words for two stages: q_out = 20 (or what keeps the input stage at its
    minimum), the remainder to the input stage."""
    lo, hi = Q_OUT_RANGE
    q_out, q_in = split
    why = (
        f"q_Σ = {q:.4g} needs two stages: the output stage takes q_out = {q_out:.4g} "
        f"(seed 000: {lo:g}…{hi:g} gives the smallest outer diameter, 20 preferred), the "
        f"input stage the remaining {q_in:.4g} (within {q_min:g}…{q_max:g})."
    )
    return Finding(
        split,
        f"Two stages: q_out = {q_out:.4g}, q1 = {q_in:.4g}.",
        why,
        {"ratios": split},
    )


def _more(q: float, q_min: float, split: list[float]) -> Finding[list[float] | None]:
    """WG-02's words for three or four stages: q_out = 20, the next stage 12 (lowered where
    the input stage would fall below its minimum), the remainder to the input stage."""
    n = len(split)
    rest = q / (Q_OUT_PREFERRED * Q_NEXT ** (n - 2))
    gave_way = ""
    if rest < q_min * (1 - RATIO_REL_TOL):  # as split_of decides
        gave_way = (
            f" The remainder {rest:.4g} is below the minimum {q_min:g} (eq. (14)), so "
            f"the seed's {Q_NEXT:g} for the stage next to the output gives way: it "
            f"takes {split[1]:.4g} and the input stage {q_min:g}."
        )
    names = ", ".join(f"{x:.4g}" for x in split)
    return Finding(
        split,
        f"{n} stages: q = {names} (output first).",
        f"q_Σ = {q:.4g} exceeds what {n - 1} stages give; seed 000 takes "
        f"q_out = 20, the next stage {Q_NEXT:g} and gives the remainder to the input "
        f"stage." + gave_way,
        {"ratios": split},
    )


@rule("WG-03", "Rows of rolling bodies", SEED_000)
def choose_rows(
    stages: int,
    needed_for_envelope: float | None,
    max_rows: int,
) -> Finding[list[int] | None]:
    """Three rows at the output, two in the other stages (seed 000, conclusion 2); more rows
    at the output where the envelope diameter demands (the n_p ≥ … inequality)."""
    rows_out = 3
    why = (
        "Seed 000: the output stage holds most of the volume and mass; three rows of rolling "
        "bodies give the smallest reducer, and the intermediate stages take two."
    )
    if needed_for_envelope is not None and needed_for_envelope > rows_out:
        rows_out = math.ceil(needed_for_envelope - 1e-9)
        if rows_out > max_rows:
            return Finding(
                None,
                f"The envelope diameter needs {needed_for_envelope:.1f} rows at the output, "
                f"more than {max_rows}.",
                "By the n_p ≥ … inequality of seed 000 the rows grow with the cube of the "
                "diameter shortfall.",
            )
        why += (
            f" The envelope diameter needs n_p ≥ {needed_for_envelope:.2f} at the output "
            f"(seed 000, inequality after eq. (19)): {rows_out} rows."
        )
    rows = [rows_out] + [2] * (stages - 1)
    return Finding(rows, f"Rows (output first): {rows}.", why, {"rows": rows, "max_rows": max_rows})


@rule("WG-04", "Rule design against the computed optimum", SEED_000)
def compare_with_optimum(
    rule_mass_kg: float,
    opt_mass_kg: float,
    rule_diameter_mm: float,
    min_diameter_mm: float,
    tolerance: float = 0.05,
) -> Finding[list[str]]:
    warnings = []
    if rule_mass_kg > opt_mass_kg * (1 + tolerance):
        warnings.append(
            f"the rule-based reducer ({rule_mass_kg:.3g} kg) is "
            f"{rule_mass_kg / opt_mass_kg - 1:.0%} heavier than the lightest in the design "
            f"space ({opt_mass_kg:.3g} kg): by eqs. (13)–(19) alone mass keeps falling with "
            "more rows and a higher output ratio"
        )
    if rule_diameter_mm > min_diameter_mm * (1 + tolerance):
        warnings.append(
            f"the rule-based outer diameter ({rule_diameter_mm:.4g} mm) is "
            f"{rule_diameter_mm / min_diameter_mm - 1:.0%} above the smallest in the design "
            f"space ({min_diameter_mm:.4g} mm): with (13)+(16) alone the diameter is flat for "
            "q ≈ 8…16 with its minimum near q ≈ 9; the seed's 12…20 comes from its fuller model"
        )
    decision = (
        "The rule design is within 5 % of the computed optimum."
        if not warnings
        else "The rule design is kept (the seed's practice); the optimum is shown beside it."
    )
    return Finding(
        warnings,
        decision,
        "The seed's heuristics (q_out = 20, three rows) come from the authors' fuller model and "
        "experience; the sweep uses only eqs. (13)–(19). Both are reported so the engineer can "
        "judge; differences above 5 % are flagged.",
        {
            "tolerance": tolerance,
            "rule_mass_kg": rule_mass_kg,
            "opt_mass_kg": opt_mass_kg,
            "rule_diameter_mm": rule_diameter_mm,
            "min_diameter_mm": min_diameter_mm,
        },
    )


def _ratios(ratios: list[float]) -> str:
    return ", ".join(f"{x:.4g}" for x in ratios)


@rule("WG-05", "Rule design against the Pareto front of the design space", SEED_000)
def compare_with_front(
    front_size: int,
    shown: int,
    adopted: dict[str, float],
    dominating: dict[str, float] | None,
    taken: str = "rules",
    asked: str = "rules",
) -> Finding[str]:
    """Where the adopted reducer stands against the non-dominated set of the design space
    (mass, outer diameter, length, efficiency by eqs. (13)–(19)). ``adopted`` and
    ``dominating`` hold mass_kg, outer_diameter_mm, length_mm, stages and efficiency."""
    objectives = "least mass, outer diameter and length, highest efficiency"
    if dominating is None:
        return Finding(
            "on the front",
            f"The adopted reducer is on the Pareto front ({objectives}).",
            f"No configuration of the design space is at least as good in every objective and "
            f"better in one. The front holds {front_size} designs; {shown} are reported, "
            "evenly spaced along it.",
            {"front_size": front_size, "shown": shown, "adopted": adopted},
        )
    a, d = adopted, dominating
    return Finding(
        "dominated",
        f"The adopted reducer is dominated by q = {_ratios(d['ratios'])} (output first; rows "
        f"{int(d['rows_out'])} at the output): {d['mass_kg']:.4g} kg against "
        f"{a['mass_kg']:.4g} kg, "
        f"{d['outer_diameter_mm']:.4g} mm against {a['outer_diameter_mm']:.4g} mm outer "
        f"diameter, {d['length_mm']:.4g} mm against {a['length_mm']:.4g} mm length, "
        f"{int(d['stages'])} stages against {int(a['stages'])}; "
        + (
            "it is kept (the seed's practice)."
            if taken == "rules"
            else f"it is kept: the requirement takes the {taken} of the space (gearbox.choice)."
            if asked != "rules"
            else "it is kept: the rule design does not fit the envelope (WG-06)."
        ),
        "By eqs. (13)–(19) alone a design is at least as good in every objective "
        f"({objectives}) and better in one. The seed's rules (q_out = 12…20, three rows at "
        "the output) come from the authors' fuller model, which these equations do not hold; "
        f"the engineer judges. The front holds {front_size} designs; {shown} are reported, "
        "evenly spaced along it.",
        {"front_size": front_size, "shown": shown, "adopted": adopted, "dominating": dominating},
    )


class ReducerOptions(NamedTuple):
    """The reducers WG-06 chooses among: the rule design of WG-02 and WG-03 (None where the
    envelope asks more rows than the space holds), the lightest and the slimmest of the
    design space within the envelope, and what the requirement asks (gearbox.choice)."""

    asked: str
    rules: Reducer | None
    lightest: Reducer
    slimmest: Reducer
    max_outer_diameter_mm: float | None
    max_length_mm: float | None


def space_choice(
    asked: str,
    rule_design: Reducer | None,
    max_outer_diameter_mm: float | None,
    max_length_mm: float | None,
) -> str | None:
    """When WG-06 fires: the reducer of the design space the design takes ("lightest" or
    "slimmest"), or None where the rule design stands (the requirement asks the rules and
    their design fits the envelope)."""
    if asked == "rules" and rule_design is not None:
        if fits(rule_design, max_outer_diameter_mm, max_length_mm):
            return None
    return "slimmest" if asked == "slimmest" else "lightest"


def _rule_figures(o: ReducerOptions) -> dict[str, float] | None:
    """The rule design's figures WG-06 states beside the reducer it takes."""
    r = o.rules
    if r is None:
        return None
    return {
        "mass_kg": r.mass_kg,
        "outer_diameter_mm": r.outer_diameter_mm,
        "length_mm": r.length_mm,
        "stages": len(r.stages),
        "efficiency": r.efficiency,
        "fits": fits(r, o.max_outer_diameter_mm, o.max_length_mm),
    }


@rule("WG-06", "Reducer taken from the design space", SEED_000)
def taken_from_space(options: ReducerOptions) -> Finding[Reducer]:
    """The design takes the lightest or the slimmest configuration of the design space
    instead of the rule design of WG-02 and WG-03: because the requirement asks it
    (``gearbox.choice``), or because the rule design does not fit the envelope (or the
    envelope asks more rows than the space holds). Fires where :func:`space_choice` names
    a reducer of the space; returns that reducer."""
    asked = options.asked
    rule = _rule_figures(options)
    taken = space_choice(asked, options.rules, options.max_outer_diameter_mm, options.max_length_mm)
    if taken is None:
        raise ValueError("WG-06 fires only where the rule design does not stand (space_choice)")
    design = options.slimmest if taken == "slimmest" else options.lightest
    mass_kg, diameter_mm = design.mass_kg, design.outer_diameter_mm
    if rule is None:
        rules_give = "the rules give no design: the envelope asks more rows than the space holds"
    else:
        rules_give = (
            f"the rule design of WG-02 and WG-03 ({int(rule['stages'])} stages, "
            f"{rule['mass_kg']:.4g} kg, Ø {rule['outer_diameter_mm']:.4g} × "
            f"{rule['length_mm']:.4g} mm, η {rule['efficiency']:.3g})"
            + ("" if rule["fits"] else " does not fit the envelope")
            + (" is not used" if rule["fits"] else "")
        )
    why = (
        "as the requirement asks (gearbox.choice)"
        if asked != "rules"
        else "because the rule design cannot be used"
    )
    return Finding(
        design,
        f"The {taken} reducer of the design space, {why}: {mass_kg:.4g} kg at "
        f"Ø {diameter_mm:.4g} mm; {rules_give}.",
        "The seed's rules (WG-02, WG-03: q_out = 12…20, three rows at the output) are the "
        "default. The design space evaluates every stage count, ratio split and row count "
        "by eqs. (13)–(19) within the envelope; the design takes its "
        + (
            "least mass."
            if taken == "lightest"
            else "least outer diameter (of equal diameters, the least mass)."
        ),
        {
            "taken": taken,
            "asked": asked,
            "mass_kg": mass_kg,
            "outer_diameter_mm": diameter_mm,
            **({} if rule is None else {f"rule_{k}": v for k, v in rule.items()}),
        },
    )


@rule(
    "WG-07",
    "Stages sized for the duty's load spectrum",
    SEED_000.at("eq. (16)") + cite("honpine-harmonic", "step 2"),
)
def size_for_cycle(
    rated_Nm: float,
    mean_Nm: float,
    peak_Nm: float,
    service_factor: float,
    ratio: float,
    efficiency: float,
) -> Finding[float]:
    """The torque the stages are sized for by eq. (16): the rated output torque, or what the
    duty asks where it is more, the cube-mean torque T_av or the repeated peak T_rep over
    98/39, times the service factor f_B. Applied (and recorded) only where the duty asks more
    than the rated torque."""
    from advisor.calc.load_spectrum import REPEATED_PEAK_FACTOR

    by_peak = peak_Nm / REPEATED_PEAK_FACTOR
    sized = max(rated_Nm, mean_Nm, by_peak) * service_factor
    if mean_Nm >= by_peak:
        why = (
            f"the cycle's cube-mean torque T_av = {mean_Nm:.6g} N·m > the rated {rated_Nm:.6g} N·m"
        )
    else:
        why = (
            f"the cycle's repeated peak T_rep = {peak_Nm:.6g} N·m within 98/39 × T_N "
            f"(T_av = {mean_Nm:.6g} N·m, the rated {rated_Nm:.6g} N·m)"
        )
    return Finding(
        sized,
        f"The stages are sized for {why} (× f_B = {service_factor:g}: T_N = {sized:.6g} N·m at "
        f"the output stage; q = {ratio:.6g}, η = {efficiency:.4g}).",
        "A harmonic reducer is chosen for the load spectrum: its rated torque must carry the "
        "cycle's cube-mean torque T_av (Honpine, step 2), its repeated peak 98/39 × T_N. "
        "Sized at the rated torque alone, every start and stop of the cycle would lift T_av "
        "above it; eq. (16) sizes each stage for the larger torque (the stages before the "
        "output for its share), found at the ratio and efficiency of the reducer adopted.",
        {
            "rated_torque_Nm": rated_Nm,
            "mean_torque_Nm": mean_Nm,
            "repeated_peak_torque_Nm": peak_Nm,
            "service_factor": service_factor,
            "sizing_torque_Nm": sized,
            "ratio": ratio,
            "efficiency": efficiency,
        },
    )
