"""A report as the wizard shows it: rich renderables per component, and the data of each
application's plot. Pure functions of the report (no textual), so they are tested directly."""

from typing import Any, NamedTuple

from rich.console import Group
from rich.table import Table
from rich.text import Text

from advisor.many import headline


def _kv(title: str, rows: list[tuple[str, Any]]) -> Table:
    t = Table(title=title, title_justify="left", show_header=False, box=None, pad_edge=False)
    t.add_column(style="bold", no_wrap=True)
    t.add_column()
    for k, v in rows:
        t.add_row(k, _fmt(v))
    return t


def _fmt(v: Any) -> str:
    if isinstance(v, bool):
        return "yes" if v else "no"
    if isinstance(v, float):
        return f"{v:.4g}"
    return str(v)


def summary(report) -> Group:
    worst = min(report.checks, key=lambda c: c.margin) if report.checks else None
    lines = [
        Text(report.report.title or report.report.application, style="bold"),
        Text(headline(report)),
        Text(f"status: {report.report.status}, {len(report.checks)} checks passed"),
    ]
    if worst is not None:
        lines.append(Text(f"lowest margin: {worst.name} — {worst.margin:.3f}"))
    for w in report.warnings:
        lines.append(Text(f"⚠ {w}", style="yellow"))
    return Group(*lines)


def components(report) -> Group:
    d = report.design
    app = report.report.application
    parts: list[Any] = []
    if app == "linear":
        s, m = d.screw, d.motor
        parts.append(
            _kv(
                "Screw",
                [
                    ("thread", s.thread + (" (imposed)" if s.imposed else "")),
                    *([("starts", f"{s.starts} (lead {s.lead_mm:g} mm)")] if s.starts > 1 else []),
                    ("speed", f"{s.speed_rpm:.0f} rpm"),
                    ("torque", f"{s.torque_Nm:.4g} N·m ({s.friction_model})"),
                    ("efficiency", s.efficiency),
                    ("self-locking", s.self_locking),
                ],
            )
        )
        parts.append(
            _kv(
                "Motor",
                [
                    ("model", m.model),
                    ("rated power", f"{m.rated_power_kW:g} kW"),
                    ("pole pairs", m.pole_pairs),
                    ("working speed", f"{m.working_speed_rpm:.0f} rpm"),
                    ("travel time", f"{m.travel_time_s:.3g} s"),
                ],
            )
        )
    elif app == "rotary":
        m, g = d.motor, d.gearbox
        parts.append(
            _kv(
                "Motor",
                [
                    ("speed", f"{m.speed_rpm:g} rpm"),
                    ("torque", f"{m.torque_Nm:.4g} N·m at {m.current_A:.3g} A"),
                    ("losses", f"{m.losses_W.total:.0f} W"),
                ],
            )
        )
        t = Table(title="Reducer stages (motor side first)", title_justify="left")
        for col in ("stage", "q", "rows", "torque N·m", "Ø mm", "length mm", "mass kg"):
            t.add_column(col, justify="right")
        for st in g.stages:
            t.add_row(
                str(st.position),
                f"{st.ratio:.4g}",
                str(st.rows),
                f"{st.torque_Nm:.4g}",
                f"{st.outer_diameter_mm:.4g}",
                f"{st.length_mm:.4g}",
                f"{st.mass_kg:.3g}",
            )
        parts.append(t)
    elif app == "positioning":
        mo = d.motion
        t = Table(title="Candidate motors", title_justify="left")
        for col in ("motor", "optimal ratio", "estimate", "move time s", "profile"):
            t.add_column(col, justify="right")
        for c in mo.candidates:
            t.add_row(
                c.name,
                f"{c.optimal_ratio:.4g}",
                f"{c.estimated_ratio:.4g}",
                f"{c.move_time_s:.4g}",
                c.profile,
            )
        parts.append(t)
    elif app == "spinning_rotor":
        r = d.rotor
        parts.append(
            _kv(
                "Rotor",
                [
                    ("gyroscopic moment", f"{r.gyroscopic_moment_Nm:.4g} N·m"),
                    ("preload", f"{r.preload_N:.4g} N"),
                    (
                        "steady power",
                        f"{r.steady_power_W.without_reaction:.4g} → "
                        f"{r.steady_power_W.with_reaction:.4g} W with the reaction",
                    ),
                    ("required torque", f"{r.required_torque_Nm:.4g} N·m"),
                    ("run-up", f"{r.run_up_time_s:.3g} s"),
                ],
            )
        )
        b = r.bearing
        parts.append(
            _kv(
                "Bearings",
                [
                    ("bearing", f"{b.designation} {b.d_mm:g}×{b.D_mm:g}×{b.B_mm:g} mm"),
                    ("friction (eq. 4)", f"{r.bearing_friction_Nm.with_reaction:.3g} N·m"),
                    ("life L10h", f"{r.bearing_life_h:.3g} h"),
                    ("static safety", b.static_safety),
                ],
            )
        )
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
        parts.append(_kv("One-way device", rows))
    return Group(*parts)


def decisions(report) -> Table:
    t = Table(expand=True)
    t.add_column("rule", no_wrap=True)
    t.add_column("decision and rationale", ratio=1)
    for d in report.decisions:
        t.add_row(
            f"{d.id}\n{d.title}",
            Text.assemble((d.decision, "bold"), "\n", d.rationale, "\n", (d.source, "dim")),
        )
    return t


def checks(report) -> Table:
    t = Table(expand=True)
    for col in ("check", "value", "limit", "margin", ""):
        t.add_column(col, justify="left" if col == "check" else "right")
    for c in report.checks:
        t.add_row(
            c.name,
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
    """Every plot of an application: the main one, and for the rotary actuator the seed's
    fig. 1 (reducer volume per unit torque against q for several row counts)."""
    out = [plot_data(report)]
    if report.report.application in ("rotary",):
        fig = report.design.gearbox.fig1
        out.append(
            PlotData(
                "Reducer stage volume per unit torque against q (seed 000, fig. 1)",
                "stage ratio q",
                "cm³ per N·m",
                [
                    (f"{n} rows", fig.q, vols)
                    for n, vols in zip(fig.rows, fig.volume_per_torque_cm3_per_Nm, strict=True)
                ],
            )
        )
    return out


def plot_data(report) -> PlotData:
    """What an engineer would rather look at than read, for each application."""
    d = report.design
    app = report.report.application
    if app == "linear":
        series = [
            (f"{c.model or c.role} {c.rated_power_kW:g} kW", c.curve.speed_rpm, c.curve.torque_Nm)
            for c in d.motor.candidates
            if getattr(c, "curve", None) is not None
        ]
        series.append(("screw torque", [d.motor.working_speed_rpm], [d.screw.torque_Nm]))
        return PlotData(
            "M(n) of the candidate motors and the working point",
            "speed, rpm",
            "torque, N·m",
            series,
        )
    if app == "rotary":
        cands = sorted(d.motor.candidates, key=lambda c: c.speed_rpm)
        speeds = [c.speed_rpm for c in cands]
        return PlotData(
            "Motor losses against speed",
            "motor speed, rpm",
            "loss, W",
            [
                ("ohmic", speeds, [c.losses_W.ohmic for c in cands]),
                ("iron", speeds, [c.losses_W.iron for c in cands]),
                ("magnets", speeds, [c.losses_W.magnets for c in cands]),
                ("total", speeds, [c.losses_W.total for c in cands]),
            ],
        )
    if app == "positioning":
        return PlotData(
            "Move time against ratio",
            "ratio i",
            "move time, s",
            [(d.motion.motor, d.motion.curve.ratio, d.motion.curve.move_time_s)],
        )
    r = d.rotor
    return PlotData(
        "Run-up of the rotor",
        "time, s",
        "speed, rad/s",
        [
            ("run-up", r.run_up.time_s, r.run_up.speed_rad_s),
            ("sustained slew", r.slew.curve.time_s, r.slew.curve.speed_rad_s),
        ],
    )
