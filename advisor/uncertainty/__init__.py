"""The probability that a design passes, and what drives it.

With an ``[uncertainty]`` table the chosen design is held fixed and every check is evaluated
over Latin hypercube samples of the inputs known only as a distribution (vectorised with
numpy: the application's margin model, its registry entry's ``uncertainty`` module, gives
the margins as functions of the inputs). The report's ``[uncertainty]`` section gives
P(pass) of each check and of the design with a 95 % Wilson interval and the inputs that
drive each margin (Spearman's ρ); with ``target`` the advisor takes, among the candidates it
already considers and in its own order, the first (the lightest) whose P(pass) reaches the
target, and says what the nominal rule chose.

An application without a margin model refuses ``[uncertainty]`` with one line (exit 2).
Nothing here is imported on a run without the table.
"""

from typing import Any

from advisor.core import registry
from advisor.core.errors import InfeasibleError, InputError

#: How many candidates the robust choice evaluates at most, in the advisor's order.
MAX_CANDIDATES = 40


def replaced(table: Any, **update: Any) -> Any:
    """A copy of a validated requirement table with some keys changed: a pydantic model or
    a record of the compiled validator (:mod:`advisor.core.compiled_validator`) alike."""
    if hasattr(table, "model_copy"):
        return table.model_copy(update=update)
    from advisor.core.compiled_validator import make_record

    values = {k: table.__dict__[k] for k in table._fields}
    return make_record(table._model, {**values, **update}, set(table.model_fields_set))


def distributions(req: Any, cat: Any, nominal: dict[str, float]) -> list:
    """The inputs' laws: the table's, and the defaults the application's model gives for what
    its data marks uncertain (``default_inputs``: the linear screw's friction, for one)."""
    from advisor.uncertainty.sampling import Distribution

    out = []
    given = {d.name for d in req.uncertainty.inputs}
    for d in req.uncertainty.inputs:
        if d.name not in nominal:
            raise InputError(
                f"uncertainty.inputs: {d.name} does not apply to this design "
                f"(it applies: {', '.join(nominal)})"
            )
        x0 = nominal[d.name]
        out.append(
            Distribution(
                d.name,
                d.distribution,
                x0,
                d.low,
                d.high,
                d.sd,
                x0 if d.mean is None and d.distribution == "normal" else d.mean,
                x0 if d.mode is None and d.distribution == "triangular" else d.mode,
            )
        )
    out += margin_model(req.application.kind).default_inputs(req, cat, nominal, given)
    for d in out:
        if d.kind != "normal" and not (d.low <= d.nominal <= d.high):
            raise InputError(
                f"uncertainty.inputs: {d.name} = {d.nominal:g} (nominal) lies outside "
                f"{d.low:g} … {d.high:g}: the range must contain the design's value"
            )
    return out


def _label(report: Any) -> str:
    """The design in the words of its application's model (``design_label``)."""
    return margin_model(report.report.application).design_label(report)


def margin_model(kind: str) -> Any:
    """The module of an application's margin model (``margin_model``, ``default_inputs``,
    ``design_label``, ``candidates``, ``restricted``); an InputError where the application has
    none."""
    model = registry.application(kind).uncertainty
    if model is None:
        available = [a.kind for a in registry.applications() if a.uncertainty is not None]
        raise InputError(
            f"[uncertainty]: not available for application.kind = {kind!r} yet "
            f"(available: {', '.join(available)})"
        )
    return registry.load(model)


def check_probabilities(report: Any, results: list, varied: set[str]) -> list:
    """P(pass) of each of the report's checks the model evaluates, with the drivers among the
    varied inputs (in the report's order of checks)."""
    from advisor.uncertainty.report import CheckProbabilityOut, DriverOut

    by_id = {r.id: r for r in results}
    out = []
    for c in report.checks:
        r = by_id.get(c.id)
        if r is None:
            continue
        drivers = [
            DriverOut.make(input=k, rank_correlation=rho) for k, rho in r.drivers if k in varied
        ]
        modelled = any(abs(d.rank_correlation) > 0 for d in drivers)
        if not modelled:  # a constant margin has no rank correlation (not a ρ of 0)
            drivers = []
        out.append(
            CheckProbabilityOut.make(
                id=c.id,
                name=c.name,
                nominal_margin=c.margin,
                modelled=modelled,
                p_pass=r.probability.p,
                p_pass_low=r.probability.low,
                p_pass_high=r.probability.high,
                margin_p05=r.margin_p05,
                margin_p50=r.margin_p50,
                drivers=drivers,
            )
        )
    return out


def inputs_out(dists: list) -> list:
    """The report's rows of the sampled inputs' laws."""
    from advisor.uncertainty.report import InputOut

    return [
        InputOut.make(
            name=d.name,
            distribution=d.kind,
            nominal=d.nominal,
            basis=d.basis,
            low=d.low,
            high=d.high,
            sd=d.sd,
            mean=d.mean,
            mode=d.mode,
        )
        for d in dists
    ]


def evaluate(req: Any, report: Any, cat: Any) -> Any:
    """The ``[uncertainty]`` section of ``report``'s design under ``req``'s distributions."""
    from advisor.uncertainty.analysis import check_results
    from advisor.uncertainty.report import UncertaintyOut
    from advisor.uncertainty.sampling import sample

    u = req.uncertainty
    margins_of, nominal = margin_model(req.application.kind).margin_model(req, report, cat)
    dists = distributions(req, cat, nominal)
    x = sample(dists, u.samples, u.seed)
    results, every = check_results(margins_of(x), x)
    modelled = {r.id for r in results}
    return UncertaintyOut.make(
        method="Latin hypercube sampling (scipy.stats.qmc), inputs independent; P(pass) with "
        "Wilson's 95 % score interval; drivers by Spearman's rank correlation",
        samples=u.samples,
        seed=u.seed,
        confidence=0.95,
        design=_label(report),
        p_pass=every.p,
        p_pass_low=every.low,
        p_pass_high=every.high,
        inputs=inputs_out(dists),
        checks=check_probabilities(report, results, {d.name for d in dists}),
        not_modelled=[c.id for c in report.checks if c.id not in modelled],
    )


def apply(req: Any, cat: Any, report: Any, advise_with: Any) -> Any:
    """``report`` with its ``[uncertainty]`` section; with ``target``, the report of the first
    candidate in the advisor's order whose P(pass) reaches it (``advise_with(req, cat)`` runs
    the rules on a requirement and catalog), with decision UQ-01 saying what the nominal rule
    chose and its P(pass)."""
    margin_model(req.application.kind)  # refused before any sampling where there is none
    section = evaluate(req, report, cat)
    target = req.uncertainty.target
    if target is None:
        return report.replace(uncertainty=section)
    return _robust(req, cat, report, section, advise_with)


def _robust(req: Any, cat: Any, nominal: Any, section: Any, advise_with: Any) -> Any:
    from advisor.uncertainty.report import CandidateOut, RobustOut

    target = req.uncertainty.target
    model = margin_model(req.application.kind)
    tried: list[Any] = []
    chosen, chosen_section = None, None
    if section.p_pass_low >= target:
        chosen, chosen_section = nominal, section
    else:
        for option in model.candidates(req, cat)[:MAX_CANDIDATES]:
            req2, cat2 = model.restricted(req, cat, option)
            try:
                rep = advise_with(req2, cat2)
            except InfeasibleError:
                continue
            if _label(rep) == section.design:
                continue  # the nominal design itself
            sec = evaluate(req, rep, cat)
            tried.append(
                CandidateOut.make(
                    label=sec.design,
                    p_pass=sec.p_pass,
                    p_pass_low=sec.p_pass_low,
                    p_pass_high=sec.p_pass_high,
                )
            )
            if sec.p_pass_low >= target:
                chosen, chosen_section = rep, sec
                break
    if chosen is None:
        best = sorted(tried, key=lambda c: -c.p_pass)[:3]
        raise InfeasibleError(
            f"no feasible design: no candidate passes every check with probability "
            f"{target:g} (uncertainty.target); the nominal {section.design} passes with "
            f"{section.p_pass:.4f}",
            [f"{c.label}: P(pass) {c.p_pass:.4f}" for c in best],
        )
    robust = RobustOut.make(
        target=target,
        nominal_choice=section.design,
        nominal_p_pass=section.p_pass,
        chosen=chosen_section.design,
        chosen_p_pass=chosen_section.p_pass,
        candidates=tried,
    )
    return _with_decision(
        req, cat, chosen.replace(uncertainty=chosen_section.replace(robust=robust)), robust
    )


def _with_decision(req: Any, cat: Any, report: Any, robust: Any) -> Any:
    """Decision UQ-01 and its sources in the report; the requirement as the user gave it."""
    from advisor.core.report import DecisionOut, SourceOut

    same = robust.chosen == robust.nominal_choice
    decision = (
        f"Keep {robust.chosen}: it passes every check with P = {robust.chosen_p_pass:.4f}, "
        f"at least the target {robust.target:g} (lower 95 % bound)."
        if same
        else f"Choose {robust.chosen} (P(pass) = {robust.chosen_p_pass:.4f}) instead of the "
        f"nominal rule's {robust.nominal_choice} (P(pass) = {robust.nominal_p_pass:.4f}): "
        f"the first candidate in the advisor's order that reaches {robust.target:g}."
    )
    ids = ["mckay-1979", "wilson-1927"]
    d = DecisionOut.make(
        id="UQ-01",
        title="Robust choice under the stated uncertainty",
        decision=decision,
        rationale="A margin above 1 at nominal inputs can be lucky: the inputs known only as "
        "ranges are sampled (Latin hypercube), the candidates the rules rank are taken in "
        "their order (smallest motor, then lightest screw), and the first whose probability "
        "of passing every check reaches the target, by the lower bound of its 95 % Wilson "
        "interval, is chosen.",
        source="McKay, Beckman, Conover (1979); Wilson (1927)",
        sources=ids,
        inputs={
            "target": robust.target,
            "nominal": robust.nominal_choice,
            "nominal_p_pass": robust.nominal_p_pass,
            "chosen_p_pass": robust.chosen_p_pass,
            "candidates_evaluated": len(robust.candidates),
        },
    )
    have = {s.id for s in report.sources}
    extra = [SourceOut.make(**cat.bibliography[i]) for i in ids if i not in have]
    return report.replace(
        decisions=[*report.decisions, d],
        sources=[*report.sources, *extra],
        requirements=req.model_dump(exclude_none=True),
    )
