"""A report as the wizard shows it: rich renderables per component, and the data of each
application's plot. Pure functions of the report (no textual), so they are tested directly."""

from typing import Any, NamedTuple

from rich.console import Group
from rich.table import Table
from rich.text import Text

from advisor.core import registry
from advisor.core.io_safety import plain
from advisor.core.registry import headline
from advisor.core.report import margin_text


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


def plural(n: int, word: str) -> str:
    """``1 check``, ``2 checks``."""
    return f"{n} {word}" if n == 1 else f"{n} {word}s"


def holding(report) -> str | None:
    """How the drive holds the load with the motor off, in a line (None: not asked)."""
    req = getattr(report, "requirements", None)
    app = req.get("application", {}) if isinstance(req, dict) else {}
    one_way = getattr(report.design, "one_way", None)
    if one_way is None:
        if app.get("hold_without_power", False):
            return "holding: asked, but the design has no one-way device"
        return None
    where = f" at the {one_way.location}" if one_way.location not in ("", "none") else ""
    if one_way.type == "none":
        return f"holding: none needed{where} ({one_way.basis})" if one_way.basis else None
    mass = f", {one_way.mass_kg:.3g} kg" if one_way.mass_kg is not None else ""
    return f"holding: {one_way.type.replace('_', ' ')}{where}, {one_way.torque_Nm:.4g} N·m{mass}"


def summary(report, previous=None) -> Group:
    worst = min(report.checks, key=lambda c: c.margin) if report.checks else None
    passed = sum(c.passed for c in report.checks)
    lines = [
        plain(report.report.title or report.report.application, "bold"),
        plain(headline(report)),
        Text(f"status: {report.report.status}, {plural(passed, 'check')} passed"),
    ]
    hold = holding(report)
    if hold:
        lines.append(plain(hold))
    if worst is not None:
        lines.append(plain(f"lowest margin: {worst.name} — {margin_text(worst.margin)}"))
    lines.extend(plain(line) for line in probability_lines(report))
    for w in report.warnings:
        lines.append(plain(f"⚠ {w}", "yellow"))
    changed = changes(previous, report) if previous is not None else []
    if changed:
        lines.append(Text("\nChanged since the previous result:", style="bold"))
        lines.extend(plain(f" • {c}") for c in changed)
    return Group(*lines)


def _rho(x: float) -> str:
    return f"{x:+.2f}".replace("-", "−")


def probability_lines(report) -> list[str]:
    """P(pass) of the design, its least probable check with what drives it, and the robust
    choice, in words; nothing without an ``[uncertainty]`` table."""
    u = getattr(report, "uncertainty", None)
    if u is None:
        return []
    from advisor.uncertainty.drivers import labels_of, least_probable

    conf = f"{u.confidence * 100:g} %"
    lines = [
        f"P(pass): {u.p_pass:.4f} ({conf} interval {u.p_pass_low:.4f} … {u.p_pass_high:.4f}, "
        f"{u.samples} samples, every check in the same sample)"
    ]
    t = least_probable(u, labels_of(report.report.application))
    if t is not None:
        drivers = ", ".join(f"{b.label} (ρ {_rho(b.rho)})" for b in t.bars)
        lines.append(f"least probable: {t.check_name}, P(pass) {t.p_pass:.4f}; driven by {drivers}")
    r = u.robust
    if r is not None:
        lines.append(
            f"robust choice (P(pass) ≥ {r.target:g}): {r.chosen}, P {r.chosen_p_pass:.4f}; "
            f"the nominal rule's {r.nominal_choice}, P {r.nominal_p_pass:.4f}"
        )
    return lines


def changes(before, after) -> list[str]:
    """What differs between two results, in words: the same lines as ``advisor diff``
    (requirement values, components, decisions, checks whose margin moved, warnings)."""
    from advisor.diff import changes_between

    return changes_between(before, after)


def infeasible(exc) -> Text:
    """An infeasible requirement in words: "No feasible design" once, then why."""
    head = exc.summary
    lowered = head.lower()
    for prefix in ("no feasible design: ", "no feasible design"):
        if lowered.startswith(prefix):
            head = head[len(prefix) :]
            break
    text = Text("No feasible design", style="bold")
    if head:
        text.append_text(plain(f": {head}"))
    for r in exc.reasons:
        text.append_text(plain(f"\n • {r}"))
    # the same as the infeasible report and the batch summary: the nearest design, and for
    # each failing check how far it misses
    from advisor.infeasible import shortfall

    nearest = getattr(exc, "nearest", None)
    if nearest:
        text.append_text(plain(f"\nNearest: {nearest}"))
    for c in getattr(exc, "checks", []):
        if not c.passed:
            text.append_text(
                plain(
                    "\nTo be feasible: "
                    + shortfall(c.name, c.value, c.limit, c.unit, c.margin, c.id)
                )
            )
    return text


def components(report) -> Group:
    """The application's own components (from its registered views), then the one-way
    device where the design has one."""
    d = report.design
    app_views = registry.views(report.report.application)
    parts: list[Any] = list(app_views.components(report)) if app_views is not None else []
    one_way = getattr(d, "one_way", None)
    if one_way is not None:
        parts.extend(one_way_parts(one_way))
    return Group(*parts)


def one_way_parts(one_way) -> list[Any]:
    """The holding device: what it is, where it sits, why, and what else would hold."""
    if one_way.type == "none":
        return [kv("One-way device", [("none", one_way.basis or "holding not asked")])]
    rows: list[tuple[str, Any]] = [
        ("type", one_way.type.replace("_", " ")),
        ("where", one_way.location),
        ("torque held", f"{one_way.torque_Nm:.4g} N·m"),
    ]
    if one_way.mass_kg is not None:
        rows += [
            ("size", f"Ø{one_way.outer_diameter_mm:.3g} × {one_way.length_mm:.3g} mm"),
            ("mass", f"{one_way.mass_kg:.3g} kg"),
            ("power drawn", f"{one_way.power_W:.3g} W"),
        ]
    if one_way.basis:
        rows.append(("basis", one_way.basis))
    parts: list[Any] = [kv("One-way device (holds the load with the motor off)", rows)]
    other_side = one_way.output_side or getattr(one_way, "motor_side", None)
    others = [*([other_side] if other_side else []), *one_way.alternatives]
    if others:
        t = Table(title="…and what else would hold it", title_justify="left")
        for col in ("type", "where", "torque N·m", "Ø×L mm", "mass kg", "power W"):
            t.add_column(col, justify="left" if col in ("type", "where") else "right")
        t.add_row(
            "▶ " + one_way.type.replace("_", " ") + " (chosen)",
            one_way.location,
            f"{one_way.torque_Nm:.4g}",
            f"{one_way.outer_diameter_mm or 0:.3g}×{one_way.length_mm or 0:.3g}",
            f"{one_way.mass_kg or 0:.3g}",
            f"{one_way.power_W or 0:.3g}",
        )
        for o in others:
            t.add_row(
                o.type.replace("_", " "),
                o.location,
                f"{o.torque_Nm:.4g}",
                f"{o.outer_diameter_mm:.3g}×{o.length_mm:.3g}",
                f"{o.mass_kg:.3g}",
                f"{o.power_W:.3g}",
            )
        parts.append(t)
    return parts


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
    """The checks; with an ``[uncertainty]`` table, each one's P(pass) too."""
    u = getattr(report, "uncertainty", None)
    p_pass = {c.id: c.p_pass for c in u.checks} if u is not None else None
    t = Table(expand=True)
    cols = ("check", "value", "limit", "margin", *(("P(pass)",) if p_pass is not None else ()))
    for col in (*cols, ""):
        t.add_column(col, justify="left" if col == "check" else "right")
    for c in report.checks:
        p = [] if p_pass is None else [f"{p_pass[c.id]:.4f}" if c.id in p_pass else "—"]
        t.add_row(
            Text.assemble(plain(c.name), "\n", plain(c.source, "dim")),
            f"{c.value:.4g} {c.unit}".strip(),
            f"{c.limit:.4g} {c.unit}".strip(),
            margin_text(c.margin),
            *p,
            "ok" if c.passed else "FAIL",
        )
    return t


#: One marker per series, told apart without colour (NO_COLOR): curves take the first
#: markers, single points (a working point, an optimum) the solid shapes.
MARKERS = ("•", "+", "x", "o", "*", "=", "#", "~")
POINT_MARKERS = ("◆", "■", "▲", "★", "●", "▼")


def markers(data: "PlotData") -> list[str]:
    """The marker of each series of a plot, in order."""
    out, curves, points = [], 0, 0
    for _label, xs, _ys in data.series:
        if len(xs) == 1:
            out.append(POINT_MARKERS[points % len(POINT_MARKERS)])
            points += 1
        else:
            out.append(MARKERS[curves % len(MARKERS)])
            curves += 1
    return out


def legend(data: "PlotData") -> str:
    """The legend under the plot, never over the curves: marker, then name (a bar plot:
    what its bars measure)."""
    if data.bars:
        return (
            "bar: Spearman's ρ of the input with the margin, −1 … 1 "
            "(< 0: a rise of the input lowers the margin)"
        )
    return "   ".join(
        f"{m} {label}" for m, (label, _, _) in zip(markers(data), data.series, strict=True)
    )


class PlotData(NamedTuple):
    title: str
    xlabel: str
    ylabel: str
    series: list[tuple[str, list[float], list[float]]]
    #: a horizontal bar plot instead of curves: (label, value) from the top bar down
    bars: tuple[tuple[str, float], ...] = ()


def drivers_plot(report) -> PlotData | None:
    """The tornado chart of the design's least probable check: one bar per
    input, its Spearman ρ with the margin, the largest |ρ| on top; None without an
    ``[uncertainty]`` table or where no check has drivers."""
    u = getattr(report, "uncertainty", None)
    if u is None:
        return None
    from advisor.uncertainty.drivers import labels_of, least_probable

    t = least_probable(u, labels_of(report.report.application))
    if t is None:
        return None
    return PlotData(
        f"Drivers of {t.check_name}: {t.probability}",
        "rank correlation ρ with the margin",
        "input",
        [],
        tuple((b.label, b.rho) for b in t.bars),
    )


def plots(report) -> list[PlotData]:
    """Every plot of an application, as its registered views draw them, then the drivers of
    the least probable check where the report has an ``[uncertainty]`` table."""
    app_views = registry.views(report.report.application)
    out = list(app_views.plots(report)) if app_views is not None else []
    drivers = drivers_plot(report)
    return [*out, drivers] if drivers is not None else out


def compare(report) -> list[Any]:
    """The comparison sections of an application (see :mod:`advisor.tui.compare`); none
    where its views have no ``compare``."""
    app_views = registry.views(report.report.application)
    fn = getattr(app_views, "compare", None)
    return list(fn(report)) if fn is not None else []
