"""How the wizard shows a positioning-drive report: its components and its plots."""

from typing import Any

from rich.table import Table

from advisor.io_safety import plain
from advisor.tui.views import PlotData


def components(report) -> list[Any]:
    d = report.design
    parts: list[Any] = []
    mo = d.motion
    t = Table(title="Candidate motors", title_justify="left")
    cols = ("motor", "optimal ratio", "estimate", "first step", "move time s", "profile")
    for col in cols:
        t.add_column(col, justify="right")
    for c in mo.candidates:
        t.add_row(
            plain(c.name),  # named by the user: data, never markup
            f"{c.optimal_ratio:.4g}",
            f"{c.estimated_ratio:.4g}",
            f"{c.estimated_ratio_first_step:.4g}" + ("" if c.first_step_moves_load else " < m"),
            f"{c.move_time_s:.4g}",
            plain(c.profile),
        )
    parts.append(t)
    return parts


def plots(report) -> list[PlotData]:
    d = report.design
    main = PlotData(
        "Move time against ratio",
        "ratio i",
        "move time, s",
        [(d.motion.motor, d.motion.curve.ratio, d.motion.curve.move_time_s)],
    )
    from advisor.duty.views import plots as duty_plots

    return [main, *duty_plots(getattr(d, "duty", None))]
