"""The report of an infeasible run: exit 3 still, and with ``-o`` (or a datasheet format) a
report with ``status = "infeasible"`` a reviewer can read: the requirement, why no design
satisfies it, the failing checks with their numbers, the nearest design where the advice got
that far, and what would make it feasible (each limit missed and by how much).

The design table of such a report is :class:`InfeasibleOut`: the application's own design
table needs a design, which an infeasible run does not have.
"""

from typing import Any

from advisor import __version__
from advisor.core.errors import InfeasibleError
from advisor.core.report import Report, ReportHeader, ReportTable, margin_text


class InfeasibleOut(ReportTable):
    """Why there is no design: the advice's summary, its reasons, the nearest candidate
    and, per failing check, what it would take."""

    summary: str
    reasons: list[str] = []  # noqa: RUF012  (an ReportTable copies its defaults, see report.py)
    nearest: str | None = None
    to_be_feasible: list[str] = []  # noqa: RUF012


def shortfall(name: str, value: float, limit: float, unit: str, margin: float) -> str:
    """What a failing check misses, in words: the limit, the value, and by how much.

    The margin is capacity over demand (≥ 1 passes), so the capacity must grow by a factor
    1/margin, or the demand fall by a factor margin.

    >>> shortfall("nut turns", 15.0, 10.0, "", 0.6667)
    'nut turns: 15 against the limit 10 (margin 0.667): 50 % more capacity, or 33 % less demand'
    """
    more = (1.0 / margin - 1.0) * 100.0 if margin > 0 else float("inf")
    less = (1.0 - margin) * 100.0
    unit = f" {unit}" if unit else ""
    return (
        f"{name}: {value:.4g}{unit} against the limit {limit:.4g}{unit} "
        f"(margin {margin_text(margin)}): "
        f"{more:.0f} % more capacity, or {less:.0f} % less demand"
    )


def infeasible_report(req: Any, exc: InfeasibleError) -> Report:
    """The report of a requirement no design satisfies (``status = "infeasible"``)."""
    from advisor.core.report import check_out

    # the ids as they are: the catalogs' short names are not loaded again for this
    checks = [check_out(c, {}) for c in exc.checks]
    failing = [c for c in checks if not c.passed]
    return Report.make(
        report=ReportHeader.make(
            advisor_version=__version__,
            application=req.application.kind,
            title=req.application.title,
            status="infeasible",
        ),
        requirements=req.model_dump(exclude_none=True),
        design=InfeasibleOut.make(
            summary=exc.summary,
            reasons=list(exc.reasons),
            nearest=exc.nearest,
            to_be_feasible=[shortfall(c.name, c.value, c.limit, c.unit, c.margin) for c in failing],
        ),
        checks=checks,
        warnings=[],  # the reasons are the design table's: said once
        decisions=[],
    )


def is_infeasible(report: Any) -> bool:
    return getattr(report.report, "status", "") == "infeasible"


def summary_rows(report: Report) -> list[tuple[str, str]]:
    """The rows of the short summary (and the datasheet's) for an infeasible report."""
    d = report.design
    rows = [("design", f"none: {d.summary}")]
    if d.nearest:
        rows.append(("nearest", d.nearest))
    rows += [("to be feasible", t) for t in d.to_be_feasible]
    if not d.to_be_feasible:
        rows += [("why", r) for r in d.reasons]
    return rows
