"""A short human summary of a report, printed with rich after ``advisor --batch -o``."""

from pathlib import Path

from rich.console import Console
from rich.table import Table
from rich.text import Text

from advisor.core.report import Report
from advisor.io_safety import plain


def print_summary(report: Report, path: Path, console: Console | None = None) -> None:
    console = console or Console()
    from advisor.core.registry import summary_rows

    # user and catalog text (title, path, names, messages) is data: plain Text, never markup
    console.print(
        Text.assemble(
            ("Drive Advisor", "bold"),
            " — ",
            plain(report.report.title or report.report.application),
        )
    )
    console.print(
        Text.assemble("report written to ", plain(path, "cyan"), f"  ({report.report.status})")
    )
    t = Table(show_header=False, box=None, pad_edge=False)
    t.add_column(style="bold")
    t.add_column()
    for name, text in summary_rows(report):
        t.add_row(plain(name), plain(text))
    if report.checks:
        worst = min(report.checks, key=lambda c: c.margin)
        t.add_row("lowest margin", plain(f"{worst.name}: {worst.margin:.3f}"))
    else:
        t.add_row("lowest margin", "none: no check applies to this design")
    console.print(t)
    for w in report.warnings:
        console.print(Text.assemble(("warning:", "yellow"), " ", plain(w)))
