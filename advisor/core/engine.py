"""The engine: requirements in, an explained design (the Report) out.

One entry point, :func:`advise`, used by the batch command and the terminal wizard alike.
"""

from pathlib import Path

from advisor import __version__
from advisor.core import registry
from advisor.core.cite import Cite, cited_ids, note, text
from advisor.core.errors import InfeasibleError
from advisor.core.ignored import ignored
from advisor.core.reading import Requirements
from advisor.core.report import DecisionOut, Report, ReportHeader, SourceOut, check_out, margin_text
from advisor.core.rulebook import Trace
from catalogs import load_catalogs


def advise(req: Requirements, catalog_dir: Path | None = None) -> Report:
    """Choose and size the drive for ``req``.

    Raises :class:`advisor.core.errors.InputError` for an input the catalogs cannot serve (an
    unknown thread, a broken user catalog) and :class:`advisor.core.errors.InfeasibleError` when
    no design satisfies the requirement. With an ``[uncertainty]`` table the report carries
    the design's probability of passing (:mod:`advisor.uncertainty`, imported only then).
    """
    cat = load_catalogs(catalog_dir)
    if getattr(req, "uncertainty", None) is None:
        return advise_with(req, cat)
    from advisor.uncertainty import apply, replaced

    nominal = advise_with(replaced(req, uncertainty=None), cat)
    return apply(
        req, cat, nominal.replace(requirements=req.model_dump(exclude_none=True)), advise_with
    )


def advise_with(req: Requirements, cat) -> Report:
    """:func:`advise` with the catalogs given (the robust choice runs the rules on a catalog
    narrowed to one candidate)."""
    trace = Trace()
    # the registry imports only this application's pipeline: the linear path stays numpy-free
    design, checks, warnings = registry.pipeline(req.application.kind)(req, cat, trace)
    failed = [c for c in checks if not c.passed]
    if failed:  # the rules should never let this happen; if they do, it is not a design
        raise InfeasibleError(
            "no feasible design: the chosen parts fail checks",
            [
                f"{c.name}: {c.value:.4g}"
                + (f" × service factor {c.factor:g}" if getattr(c, "factor", None) else "")
                + f" against {c.limit:.4g} {c.unit} (margin {margin_text(c.margin)})"
                for c in failed
            ],
            checks=finite_checks(checks),
            nearest=_nearest(design),
        )
    checks = finite_checks(checks)
    short = cat.short_names()
    # a check may give its basis as plain words (a toy application does): no source then
    checks = [
        c if isinstance(c.source, Cite) else c._replace(source=note(c.source)) for c in checks
    ]
    ids = cited_ids([*(d.source.ids for d in trace.decisions), *(c.source.ids for c in checks)])
    unknown = [i for i in ids if i not in cat.bibliography]
    if unknown:  # a rule or a check cites what the bibliography lacks: a bug, not an input
        raise KeyError(f"sources {unknown} are not in the bibliography")
    return Report.make(
        report=ReportHeader.make(
            advisor_version=__version__,
            application=req.application.kind,
            title=req.application.title,
            status="feasible",
        ),
        requirements=req.model_dump(exclude_none=True),
        design=design,
        checks=[check_out(c, short) for c in checks],
        warnings=[*ignored(req), *warnings],
        decisions=[
            DecisionOut.make(
                id=d.id,
                title=d.title,
                decision=d.decision,
                rationale=d.rationale,
                source=text(d.source, short),
                sources=d.source.ids,
                inputs=_tomlable(d.inputs),
            )
            for d in trace.decisions
        ],
        sources=[SourceOut.make(**cat.bibliography[i]) for i in ids],
    )


def _nearest(design) -> str | None:
    """The design that failed its checks, in the words of its parts (for the report of an
    infeasible run); None where it has none to give."""
    try:
        from advisor.core.report import plain_data

        parts = plain_data(design)
    except (TypeError, ValueError):
        return None
    if not isinstance(parts, dict):
        return None
    names = [
        f"{k} {v.get('model') or v.get('designation') or v.get('thread') or ''}".strip()
        for k, v in parts.items()
        if isinstance(v, dict)
    ]
    return ", ".join(names) or None


def _tomlable(inputs: dict) -> dict:
    """Decision inputs as TOML can hold them (no None, plain numbers and strings)."""
    out = {}
    for k, v in inputs.items():
        if v is None:
            continue
        if isinstance(v, list | tuple):
            v = [x for x in v if x is not None]
        out[str(k)] = v
    return out


def finite_checks(checks: list) -> list:
    """The checks a report can state: a check of a value that is zero (no load on that part)
    has an infinite margin. It is no check at all, and a report never states an infinite
    number."""
    return [c for c in checks if c.margin - c.margin == 0.0]
