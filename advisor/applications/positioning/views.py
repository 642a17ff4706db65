"""How the wizard shows a positioning-drive report: its components and its plots."""

from typing import Any

from rich.table import Table

from advisor.core.io_safety import plain
from advisor.tui.views import PlotData


def components(report) -> list[Any]:
    d = report.design
    parts: list[Any] = []
    motion = d.motion
    t = Table(title="Candidate motors", title_justify="left")
    cols = ("motor", "optimal ratio", "estimate", "first step", "move time s", "profile")
    for col in cols:
        t.add_column(col, justify="right")
    for c in motion.candidates:
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
    """Move time against ratio for every candidate motor (seed 003, eqs. (1)–(4)), each at
    its own optimum marked, the chosen one named first."""
    d = report.design
    series: list[tuple[str, list[float], list[float]]] = [
        (f"{d.motion.motor} (chosen)", d.motion.curve.ratio, d.motion.curve.move_time_s)
    ]
    series += [
        (c.name, *_curve(report, c)) for c in d.motion.candidates if c.name != d.motion.motor
    ]
    series += [
        (f"optimum of {c.name}", [c.optimal_ratio], [c.move_time_s]) for c in d.motion.candidates
    ]
    main = PlotData("Move time against ratio", "ratio i", "move time, s", series)
    from advisor.duty.views import plots as duty_plots

    return [main, *duty_plots(getattr(d, "duty", None))]


def _curve(report, c) -> tuple[list[float], list[float]]:
    """The move time of candidate ``c`` over the ratios of the chosen motor's curve widened
    to take in ``c``'s own optimum (ratios the motor cannot move the load at left out)."""
    from advisor.calc.motion import Drive, move_time

    pos = report.requirements["positioning"]
    drive = Drive(
        c.speed_rad_s,
        c.inertia_kgm2,
        c.accel_torque_Nm,
        pos["load_inertia_kgm2"],
        pos["load_torque_Nm"],
    )
    ratios = report.design.motion.curve.ratio
    lo = min(min(ratios), c.optimal_ratio / 3)
    hi = max(max(ratios), c.optimal_ratio * 3)
    n = 60
    grid = [lo * (hi / lo) ** (k / (n - 1)) for k in range(n)]
    xs, ys = [], []
    for i in grid:
        if i <= drive.torque_ratio * 1.001:
            continue
        xs.append(i)
        ys.append(move_time(drive, pos["travel_rad"], i)[0])
    return xs, ys


def compare(report) -> list[Any]:
    """The candidate motors, each at its own optimal ratio (seed 003)."""
    from advisor.tui.compare import Option, Section, decision, mark, table

    motion = report.design.motion
    t = table("motor", "ω0 rad/s", "J0 kg·m²", "M_λ N·m", "ratio", "move time s", "graph")
    rows = report.requirements["positioning"].get("motors", [])
    options = []
    for c in sorted(motion.candidates, key=lambda c: c.move_time_s):
        chosen = c.name == motion.motor
        t.add_row(
            mark(chosen, c.name),
            f"{c.speed_rad_s:.4g}",
            f"{c.inertia_kgm2:.4g}",
            f"{c.accel_torque_Nm:.4g}",
            f"{c.optimal_ratio:.4g}",
            f"{c.move_time_s:.4g}",
            c.profile,
        )
        row = next((r for r in rows if r.get("name") == c.name), None)
        if not chosen and row is not None:
            patch = ((("positioning", "motors"), [dict(row)]),)
            options.append(Option(f"Use {c.name}", patch))
    return [
        Section(
            "Candidate motors",
            t,
            decision(report, "MO-02") or decision(report, "MO-05"),
            tuple(options),
            "“Use” keeps that motor alone in the requirement's list of motors.",
        )
    ]
