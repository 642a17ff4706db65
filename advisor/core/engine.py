"""The engine: requirements in, an explained design (the Report) out.

One entry point, :func:`advise`, used by the batch command and the terminal wizard alike.
"""

from pathlib import Path

from advisor import __version__
from advisor.core import registry
from advisor.core.errors import InfeasibleError
from advisor.core.report import CheckOut, DecisionOut, Report, ReportHeader
from advisor.core.requirements import Requirements
from advisor.core.rulebook import Trace
from advisor.ignored import ignored
from catalogs import load_catalogs


def advise(req: Requirements, catalog_dir: Path | None = None) -> Report:
    """Choose and size the drive for ``req``.

    Raises :class:`advisor.core.errors.InputError` for an input the catalogs cannot serve (an
    unknown thread, a broken user catalog) and :class:`advisor.core.errors.InfeasibleError` when
    no design satisfies the requirement.
    """
    cat = load_catalogs(catalog_dir)
    trace = Trace()
    # the registry imports only this application's pipeline: the linear path stays numpy-free
    design, checks, warnings = registry.pipeline(req.application.kind)(req, cat, trace)
    failed = [c for c in checks if not c.passed]
    if failed:  # the rules should never let this happen; if they do, it is not a design
        raise InfeasibleError(
            "no feasible design: the chosen parts fail checks",
            [
                f"{c.name}: {c.value:.4g} against {c.limit:.4g} {c.unit} (margin {c.margin:.3f})"
                for c in failed
            ],
        )
    return Report.make(
        report=ReportHeader.make(
            advisor_version=__version__,
            application=req.application.kind,
            title=req.application.title,
            status="feasible",
        ),
        requirements=req.model_dump(exclude_none=True),
        design=design,
        checks=[
            CheckOut.make(
                id=c.id,
                name=c.name,
                value=c.value,
                limit=c.limit,
                unit=c.unit,
                margin=c.margin,
                passed=c.passed,
                source=c.source,
            )
            for c in checks
        ],
        warnings=[*ignored(req), *warnings],
        decisions=[
            DecisionOut.make(
                id=d.id,
                title=d.title,
                decision=d.decision,
                rationale=d.rationale,
                source=d.source,
                inputs=_tomlable(d.inputs),
            )
            for d in trace.decisions
        ],
    )


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
