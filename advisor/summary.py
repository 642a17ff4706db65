"""A short human summary of a report, printed as plain text after ``advisor --batch -o``.

Plain text, not rich: the summary is a handful of lines, and importing and rendering rich
would cost more than the whole advice on the batch path. User and catalog text
(title, path, names, messages) is shown with its control characters escaped.
"""

import sys
from pathlib import Path
from typing import TextIO

from advisor.core.io_safety import printable
from advisor.core.report import Report, margin_text


def summary_lines(report: Report, path: Path) -> list[str]:
    """The summary: a heading, where the report went, the design's rows (names aligned) with
    the lowest check margin, then the warnings."""
    from advisor.core.registry import summary_rows

    head = printable(str(report.report.title or report.report.application), newlines=False)
    where = printable(str(path), newlines=False)
    if report.report.status == "infeasible":  # no design: why, and what it would take
        from advisor.infeasible import summary_rows as infeasible_rows

        given = infeasible_rows(report)
    else:
        given = summary_rows(report)
    rows = [
        (printable(name, newlines=False), printable(text, newlines=False)) for name, text in given
    ]
    if report.checks:
        worst = min(report.checks, key=lambda c: c.margin)
        rows.append(("lowest margin", printable(f"{worst.name}: {margin_text(worst.margin)}")))
    else:
        rows.append(("lowest margin", "none: no check applies to this design"))
    width = max(len(name) for name, _ in rows)
    return [
        f"Drive Advisor — {head}",
        f"report written to {where}  ({report.report.status})",
        *(f"{name:<{width}}  {text}" for name, text in rows),
        *(f"warning: {printable(w)}" for w in report.warnings),
    ]


def print_summary(report: Report, path: Path, file: TextIO | None = None) -> None:
    out = file or sys.stdout
    out.write("".join(line + "\n" for line in summary_lines(report, path)))
