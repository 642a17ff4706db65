"""A short human summary of a report, printed with rich after ``advisor --batch -o``."""

from pathlib import Path

from rich.console import Console
from rich.table import Table

from advisor.core.report import Report


def print_summary(report: Report, path: Path, console: Console | None = None) -> None:
    console = console or Console()
    from advisor.core.registry import summary_rows

    console.print(f"[bold]Drive Advisor[/] — {report.report.title or report.report.application}")
    console.print(f"report written to [cyan]{path}[/]  ({report.report.status})")
    t = Table(show_header=False, box=None, pad_edge=False)
    t.add_column(style="bold")
    t.add_column()
    for name, text in summary_rows(report):
        t.add_row(name, text)
    worst = min(report.checks, key=lambda c: c.margin)
    t.add_row("lowest margin", f"{worst.name}: {worst.margin:.3f}")
    console.print(t)
    for w in report.warnings:
        console.print(f"[yellow]warning:[/] {w}")
