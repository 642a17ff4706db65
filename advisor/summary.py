"""A short human summary of a report, printed with rich after ``advisor --batch -o``."""

from pathlib import Path

from rich.console import Console
from rich.table import Table

from advisor.report import Report


def print_summary(report: Report, path: Path, console: Console | None = None) -> None:
    console = console or Console()
    from advisor.many import headline

    d = report.design
    console.print(f"[bold]Drive Advisor[/] — {report.report.title or report.report.application}")
    console.print(f"report written to [cyan]{path}[/]  ({report.report.status})")
    t = Table(show_header=False, box=None, pad_edge=False)
    t.add_column(style="bold")
    t.add_column()
    if report.report.application != "linear":
        t.add_row("design", headline(report))
    else:
        _linear_rows(t, d)
    worst = min(report.checks, key=lambda c: c.margin)
    t.add_row("lowest margin", f"{worst.name}: {worst.margin:.3f}")
    console.print(t)
    for w in report.warnings:
        console.print(f"[yellow]warning:[/] {w}")


def _linear_rows(t: Table, d) -> None:
    s, m = d.screw, d.motor
    t.add_row(
        "screw",
        f"{s.thread}{' (imposed)' if s.imposed else ''}"
        f"{f', {s.starts} starts, lead {s.lead_mm:g} mm' if s.starts > 1 else ''}, "
        f"{s.speed_rpm:.0f} rpm, "
        f"{s.torque_Nm:.3f} N·m ({s.friction_model}; standard {s.torque_standard_Nm:.3f}), "
        f"η = {s.efficiency:.3f}, {'self-locking' if s.self_locking else 'not self-locking'}",
    )
    t.add_row(
        "motor",
        f"{m.model}, {m.rated_power_kW:g} kW, {2 * m.pole_pairs} poles (p = {m.pole_pairs}), "
        f"runs at {m.working_speed_rpm:.0f} rpm, stroke in {m.travel_time_s:.2f} s",
    )
