"""The report of an infeasible run: exit 3 still, and with ``-o`` (or a datasheet format) a
report with ``status = "infeasible"`` a reviewer can read: the requirement, why no design
satisfies it, the failing checks with their numbers, the nearest design where the advice got
that far, and what would make it feasible (each limit missed and by how much).

The design table of such a report is :class:`InfeasibleOut`: the application's own design
table needs a design, which an infeasible run does not have.
"""

import math
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


#: The life law of the life checks, L ∝ (C/P)^p (ISO 281:2007, eq. (1); ball bearings p = 3):
#: for these the demand to cut is the load, not the required life.
LIFE_EXPONENTS = {"bearing_life": 3.0, "output_bearing_life": 3.0}


def percent(x: float) -> str:
    """A percentage in whole numbers, but never a nonzero one shown as 0 nor one short of 100
    as 100: those get the digits that tell them apart (99.9995, 8.6e-11)."""
    if 0.5 <= x < 99.5 or x >= 100.0 or x == 0.0:
        return f"{x:.0f}"
    if x < 0.5:
        return f"{x:.2g}"
    return f"{x:.{max(1, math.ceil(-math.log10(100.0 - x)))}f}"


def shortfall(
    name: str, value: float, limit: float, unit: str, margin: float, check_id: str = ""
) -> str:
    """What a failing check misses, in words: the limit, the value, and by how much.

    The margin is capacity over demand (≥ 1 passes), so the capacity must grow by a factor
    1/margin, or the demand fall by a factor margin. A life check (:data:`LIFE_EXPONENTS`)
    says it in the load and the rating instead, L ∝ (C/P)^p: P lower by 1 − margin^(1/p), or
    C higher by margin^(−1/p) − 1.

    >>> shortfall("nut turns", 15.0, 10.0, "", 0.6667)
    'nut turns: 15 against the limit 10 (margin 0.667): 50 % more capacity, or 33 % less demand'
    >>> shortfall("L10h", 500.0, 1000.0, "h", 0.5, "bearing_life").split("): ")[1]
    'the load P lower by 21 %, or the rating C higher by 26 %'
    """
    unit = f" {unit}" if unit else ""
    head = (
        f"{name}: {value:.4g}{unit} against the limit {limit:.4g}{unit} "
        f"(margin {margin_text(margin)}): "
    )
    p = LIFE_EXPONENTS.get(check_id)
    if p is not None and margin > 0:
        lower = (1.0 - margin ** (1.0 / p)) * 100.0
        higher = (margin ** (-1.0 / p) - 1.0) * 100.0
        return (
            f"{head}the load P lower by {percent(lower)} %, "
            f"or the rating C higher by {percent(higher)} %"
        )
    more = (1.0 / margin - 1.0) * 100.0 if margin > 0 else float("inf")
    less = (1.0 - margin) * 100.0
    return f"{head}{percent(more)} % more capacity, or {percent(less)} % less demand"


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
            to_be_feasible=[
                shortfall(c.name, c.value, c.limit, c.unit, c.margin, c.id) for c in failing
            ],
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
