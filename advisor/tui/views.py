"""A report as the wizard shows it: rich renderables per component, and the data of each
application's plot. Pure functions of the report (no textual), so they are tested directly."""

from typing import Any, NamedTuple

from rich.console import Group
from rich.table import Table
from rich.text import Text

from advisor.core import registry
from advisor.core.registry import headline
from advisor.io_safety import plain


def kv(title: str, rows: list[tuple[str, Any]]) -> Table:
    t = Table(title=title, title_justify="left", show_header=False, box=None, pad_edge=False)
    t.add_column(style="bold", no_wrap=True)
    t.add_column()
    for k, v in rows:
        t.add_row(k, _fmt(v))
    return t


def _fmt(v: Any) -> Text:
    """A cell as plain text: names come from users and catalogs and are never markup."""
    if isinstance(v, bool):
        return plain("yes" if v else "no")
    if isinstance(v, float):
        return plain(f"{v:.4g}")
    return plain(v)


def summary(report) -> Group:
    worst = min(report.checks, key=lambda c: c.margin) if report.checks else None
    lines = [
        plain(report.report.title or report.report.application, "bold"),
        plain(headline(report)),
        Text(f"status: {report.report.status}, {len(report.checks)} checks passed"),
    ]
    if worst is not None:
        lines.append(plain(f"lowest margin: {worst.name} — {worst.margin:.3f}"))
    for w in report.warnings:
        lines.append(plain(f"⚠ {w}", "yellow"))
    return Group(*lines)


def components(report) -> Group:
    """The application's own components (from its registered views), then the one-way
    device where the design has one."""
    d = report.design
    app_views = registry.views(report.report.application)
    parts: list[Any] = list(app_views.components(report)) if app_views is not None else []
    one_way = getattr(d, "one_way", None)
    if one_way is not None:
        rows = [
            ("type", one_way.type),
            ("location", one_way.location),
            ("torque", f"{one_way.torque_Nm:.4g} N·m"),
        ]
        if one_way.mass_kg is not None:
            rows += [
                ("size", f"Ø{one_way.outer_diameter_mm:.3g} × {one_way.length_mm:.3g} mm"),
                ("mass", f"{one_way.mass_kg:.3g} kg"),
                ("power drawn", f"{one_way.power_W:.3g} W"),
            ]
        parts.append(kv("One-way device", rows))
    return Group(*parts)


def decisions(report) -> Table:
    t = Table(expand=True)
    t.add_column("rule", no_wrap=True)
    t.add_column("decision and rationale", ratio=1)
    for d in report.decisions:
        t.add_row(
            plain(f"{d.id}\n{d.title}"),
            Text.assemble(
                plain(d.decision, "bold"), "\n", plain(d.rationale), "\n", plain(d.source, "dim")
            ),
        )
    sources = getattr(report, "sources", [])
    if sources:  # the full references, once each, below the decisions that cite them
        t.add_row(
            plain("sources", "bold"),
            plain("\n".join(f"[{s.id}] {s.reference()}" for s in sources)),
        )
    return t


def checks(report) -> Table:
    t = Table(expand=True)
    for col in ("check", "value", "limit", "margin", ""):
        t.add_column(col, justify="left" if col == "check" else "right")
    for c in report.checks:
        t.add_row(
            Text.assemble(plain(c.name), "\n", plain(c.source, "dim")),
            f"{c.value:.4g} {c.unit}".strip(),
            f"{c.limit:.4g} {c.unit}".strip(),
            f"{c.margin:.3f}",
            "ok" if c.passed else "FAIL",
        )
    return t


class PlotData(NamedTuple):
    title: str
    xlabel: str
    ylabel: str
    series: list[tuple[str, list[float], list[float]]]


def plots(report) -> list[PlotData]:
    """Every plot of an application, as its registered views draw them (the rotary
    actuator adds the seed's fig. 1: reducer volume per unit torque against q)."""
    app_views = registry.views(report.report.application)
    return list(app_views.plots(report)) if app_views is not None else []
