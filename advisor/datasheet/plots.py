"""The datasheet's plots: which ones a report has (pure, from its plain data) and each drawn
as an SVG with matplotlib, imported here only (``pip install 'drive-advisor[report]'``).
The plots every report may have (the motor's envelope, the duty cycle) are here; each
application's own are in its package, named by its registry entry (``plots``).

The SVG is deterministic, so that two datasheets of the same input diff clean: no date, no
creator, ids salted per plot (``svg.hashsalt``) instead of random, text kept as text.
"""

import io
import itertools
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any


@dataclass
class Line:
    label: str
    x: list[float]
    y: list[float]
    style: str = "line"  # line | points | marker | steps


@dataclass
class Plot:
    id: str
    title: str
    xlabel: str
    ylabel: str
    lines: list[Line]
    vlines: list[tuple[float, str]] = field(default_factory=list)
    hlines: list[tuple[float, str]] = field(default_factory=list)
    logx: bool = False


#: The grey levels and dash patterns of successive lines: a plot printed in grey still tells
#: its lines apart (with the legend's labels).
MARKERS = ("o", "s", "^", "D", "v", "P", "X", "*")
DASHES = ("-", "--", "-.", ":", (0, (5, 1, 1, 1, 1, 1)), (0, (1, 1)))


def at(doc: Any, *path: str) -> Any:
    """The value at ``path`` in a report's plain data, None where a key is missing."""
    for p in path:
        if not isinstance(doc, dict) or p not in doc:
            return None
        doc = doc[p]
    return doc


def table_at(doc: Any, *path: str) -> dict:
    """The table at ``path``, empty where there is none (or a value of another type there:
    an application's ``design.motor`` may be the motor's name)."""
    found = at(doc, *path)
    return found if isinstance(found, dict) else {}


def duty(doc: dict) -> Plot | None:
    """Motor torque against time over the duty cycle, where the report has one: its phases
    (each ``time_s`` or ``duration_s`` long at ``torque_Nm``) as steps, or arrays
    (``time_s`` and ``…_Nm``); the RMS torque and the peak limit as lines."""
    d = at(doc, "design", "duty")
    if not isinstance(d, dict):
        return None
    phases = next(
        (
            v
            for v in d.values()
            if isinstance(v, list) and v and all(isinstance(x, dict) for x in v)
        ),
        None,
    )
    lines: list[Line] = []
    if isinstance(d.get("time_s"), list):
        for k, v in d.items():
            if k.endswith("_Nm") and isinstance(v, list) and len(v) == len(d["time_s"]):
                lines.append(Line(k.removesuffix("_Nm").replace("_", " "), d["time_s"], v, "steps"))
    elif phases and all(("duration_s" in s or "time_s" in s) and "torque_Nm" in s for s in phases):
        t, xs, ys = 0.0, [], []
        for s in phases:
            xs.append(t)
            ys.append(s["torque_Nm"])
            t += s.get("duration_s", s.get("time_s", 0.0))
        xs.append(t)
        ys.append(phases[-1]["torque_Nm"])
        lines.append(Line("motor torque", xs, ys, "steps"))
    if not lines:
        return None
    hlines = []
    rms = next((v for k, v in d.items() if "rms" in k and isinstance(v, int | float)), None)
    if rms is not None:
        hlines.append((rms, f"RMS {rms:.4g} N·m"))
    limit = d.get("peak_torque_limit_Nm")
    if isinstance(limit, int | float):
        hlines.append((limit, f"peak limit {limit:.4g} N·m"))
    return Plot(
        "duty", "Duty cycle: torque against time", "time, s", "torque, N·m", lines, [], hlines
    )


def duty_thermal(doc: dict) -> Plot | None:
    """The winding's temperature rise over repeated duty cycles (S2: its one run from cold)
    against its limit."""
    th = at(doc, "design", "duty", "thermal")
    if not isinstance(th, dict) or not th.get("time_s") or not th.get("rise_K"):
        return None
    lim = th.get("limit_rise_K")
    single = at(doc, "design", "duty", "duty_type") == "S2"
    over = "one S2 run from cold" if single else "repeated cycles"
    return Plot(
        "duty-thermal",
        f"Winding temperature rise over {over}",
        "time, s",
        "rise, K",
        [Line("rise", th["time_s"], th["rise_K"])],
        [],
        [(lim, f"limit {lim:g} K")] if isinstance(lim, int | float) else [],
    )


def duty_speed(doc: dict) -> Plot | None:
    """Motor speed against time over the duty cycle: each phase from its start speed to its
    end speed (a ramp is a straight line: constant acceleration within a phase)."""
    from advisor.datasheet.review import phases_of

    phases = phases_of(doc)
    if not phases or not all("speed_start_rpm" in p and "speed_end_rpm" in p for p in phases):
        return None
    t, xs, ys = 0.0, [], []
    for p in phases:
        xs += [t, t + p.get("time_s", p.get("duration_s", 0.0))]
        ys += [p["speed_start_rpm"], p["speed_end_rpm"]]
        t = xs[-1]
    return Plot(
        "duty-speed",
        "Duty cycle: motor speed against time",
        "time, s",
        "speed, rpm",
        [Line("motor speed", xs, ys)],
    )


def _mean_speed(phase: dict) -> float | None:
    """Where a phase sits on the speed axis: a ramp (its start and end speeds given) at its
    mean speed, where its torque acts on average; a steady phase at its speed. At its top
    speed a starting torque would stand outside the motor's M(n), which it never meets."""
    from advisor.datasheet.review import speed_rpm

    if "speed_start_rpm" in phase and "speed_end_rpm" in phase:
        return (abs(phase["speed_start_rpm"]) + abs(phase["speed_end_rpm"])) / 2.0
    n = speed_rpm(phase)
    return None if n is None else abs(n)


def envelope(doc: dict) -> Plot | None:
    """The motor's continuous and peak torque–speed envelope with the operating points the
    report states: each phase of the cycle (at its speed, the magnitude of its torque), the
    RMS torque at the mean speed and the peak torque; without a cycle, the working point.
    The limits and the working point are the application's (its datasheet module's
    ``motor_limits(doc)`` → (continuous lines, peak lines) and ``working_point(doc)`` →
    (rpm, N·m)); an application without ``motor_limits`` has no envelope."""
    from advisor.datasheet.review import phases_of

    hooks = application_hooks(doc)
    limits = hooks.motor_limits(doc) if hasattr(hooks, "motor_limits") else None
    if limits is None:
        return None
    cont, peak = limits
    lines = [*cont, *peak]
    phases = phases_of(doc) or []
    pts = [(_mean_speed(p), abs(p["torque_Nm"])) for p in phases if _mean_speed(p) is not None]
    if pts:
        label = "phases of the cycle (a ramp at its mean speed)"
        lines.append(Line(label, [x for x, _ in pts], [y for _, y in pts], "points"))
    d = table_at(doc, "design", "duty")
    rms, n_mean = d.get("rms_torque_Nm"), d.get("mean_speed_rpm")
    if isinstance(rms, int | float) and isinstance(n_mean, int | float):
        lines.append(Line(f"RMS {rms:.4g} N·m at the mean speed", [n_mean], [rms], "marker"))
    m_pk = d.get("peak_torque_Nm")
    if isinstance(m_pk, int | float) and pts:
        n_pk = max(pts, key=lambda p: p[1])[0]
        lines.append(Line(f"peak {m_pk:.4g} N·m", [n_pk], [m_pk], "marker"))
    point = hooks.working_point(doc) if hasattr(hooks, "working_point") else None
    if not phases and point is not None:
        n, m = point
        lines.append(Line(f"working point {n:.4g} rpm, {m:.4g} N·m", [n], [m], "marker"))
    return Plot(
        "motor-envelope",
        "Motor torque–speed envelope and operating points",
        "motor speed, rpm",
        "torque, N·m",
        lines,
    )


#: The plots every application's report may have, around its own (its registry entry's
#: ``plots``): the motor's envelope first, the duty cycle's last.
FIRST = (envelope,)
LAST = (duty, duty_speed, duty_thermal)


def application_hooks(doc: dict) -> Any:
    """The datasheet module of the report's application (its registry entry's ``plots``):
    ``DATASHEET_PLOTS``, and where it has them ``motor_limits`` and ``working_point``. None
    for a kind the registry does not know (a report file of an application removed since)."""
    from advisor.core import registry

    kind = at(doc, "report", "application")
    return registry.datasheet(kind) if kind in registry.kinds() else None


def plots(doc: dict) -> list[Plot]:
    """Every plot the report has data for, in a fixed order."""
    own = getattr(application_hooks(doc), "DATASHEET_PLOTS", ())
    funcs: tuple[Callable[[dict], Plot | None], ...] = (*FIRST, *own, *LAST)
    return [p for p in (f(doc) for f in funcs) if p is not None]


def _style(salt: str) -> dict[str, Any]:
    """matplotlib's settings of every datasheet plot: ids salted per plot, text as text."""
    return {
        "svg.hashsalt": salt,
        "svg.fonttype": "none",
        "font.family": "DejaVu Sans",
        "font.size": 9,
        "axes.grid": True,
        "grid.alpha": 0.3,
    }


def _svg_text(fig: Any) -> str:
    """A figure as an inline ``<svg>`` element: no date, no creator."""
    buf = io.StringIO()
    fig.savefig(buf, format="svg", metadata={"Date": None, "Creator": None})
    text = buf.getvalue()
    return text[text.index("<svg") :].strip()


def svg(plot: Plot, salt: str) -> str:
    """The plot as an inline ``<svg>`` element, byte for byte the same for the same data."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    with matplotlib.rc_context(_style(salt)):
        fig = Figure(figsize=(6.4, 3.8))
        ax = fig.add_subplot()
        # in grey, lines are told apart by their dash and points by their shape
        dashes, shapes = itertools.cycle(DASHES), itertools.cycle(MARKERS)
        for line in plot.lines:
            if line.style == "marker":
                ax.plot(
                    line.x,
                    line.y,
                    next(shapes),
                    markersize=8,
                    label=line.label,
                    zorder=5,
                    markeredgecolor="black",
                )
            elif line.style == "points":  # no curve between
                ax.plot(line.x, line.y, next(shapes), markersize=6, label=line.label, ls="none")
            elif line.style == "steps":
                ax.step(line.x, line.y, where="post", label=line.label, ls=next(dashes))
            else:
                ax.plot(line.x, line.y, label=line.label, ls=next(dashes))
        for x, label in plot.vlines:
            ax.axvline(x, linestyle="--", color="grey", linewidth=1, label=label)
        for y, label in plot.hlines:
            ax.axhline(y, linestyle=":", color="grey", linewidth=1, label=label)
        if plot.logx:
            from matplotlib.ticker import NullFormatter, ScalarFormatter

            ax.set_xscale("log")
            ax.xaxis.set_major_formatter(ScalarFormatter())
            ax.xaxis.set_minor_formatter(NullFormatter())
        ax.set_title(plot.title)
        ax.set_xlabel(plot.xlabel)
        ax.set_ylabel(plot.ylabel)
        ax.legend(fontsize=7)
        fig.tight_layout()
        return _svg_text(fig)


#: How the bars of a tornado chart are told apart in grey: an input whose rise lowers the
#: margin dark and solid, one that raises it light and hatched.
TORNADO_FILL = {
    "lowers": {"facecolor": "#444444", "hatch": ""},
    "raises": {"facecolor": "#dddddd", "hatch": "///"},
}


def tornado_svg(t: Any, salt: str) -> str:
    """A tornado chart (:class:`advisor.uncertainty.drivers.Tornado`) as an inline
    ``<svg>``: one horizontal bar per input, ρ from −1 to 1, the largest |ρ| on top, each bar
    an element with the id ``driver-<input>`` and its ρ written at its end; the check's
    P(pass) and interval in the title. Deterministic like :func:`svg`."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure
    from matplotlib.patches import Patch

    n = len(t.bars)
    with matplotlib.rc_context({**_style(salt), "hatch.linewidth": 0.8}):
        # constrained: the legend goes below the axes, never over a bar
        fig = Figure(figsize=(6.4, 1.9 + 0.42 * n), layout="constrained")
        ax = fig.add_subplot()
        ys = list(range(n))
        for y, b in zip(ys, t.bars, strict=True):
            fill = TORNADO_FILL["lowers" if b.rho < 0 else "raises"]
            (rect,) = ax.barh([y], [b.rho], height=0.6, edgecolor="black", linewidth=0.8, **fill)
            rect.set_gid(f"driver-{b.input}")
            # the value at the bar's end, outside it: readable on any fill
            ax.annotate(
                f"{b.rho:+.2f}".replace("-", "−"),  # the axis's minus sign
                (b.rho, y),
                xytext=(4 if b.rho >= 0 else -4, 0),
                textcoords="offset points",
                ha="left" if b.rho >= 0 else "right",
                va="center",
                fontsize=8,
            )
        ax.axvline(0.0, color="black", linewidth=0.8)
        ax.set_xlim(-1.35, 1.35)  # room for the value at the end of a full bar
        ax.set_xticks([-1.0, -0.5, 0.0, 0.5, 1.0])
        ax.set_ylim(n - 0.5, -0.5)  # the largest |ρ| on top
        ax.set_yticks(ys, [b.label for b in t.bars])
        ax.grid(axis="y", visible=False)
        ax.set_axisbelow(True)  # the grid behind the bars
        ax.set_xlabel("Spearman's rank correlation ρ of the input with the margin")
        ax.set_title(f"{t.check_name}\n{t.probability}", fontsize=9)
        fig.legend(
            handles=[
                Patch(
                    edgecolor="black", label="a rise lowers the margin", **TORNADO_FILL["lowers"]
                ),
                Patch(
                    edgecolor="black", label="a rise raises the margin", **TORNADO_FILL["raises"]
                ),
            ],
            fontsize=7,
            loc="outside lower center",
            ncols=2,
            frameon=False,
        )
        return _svg_text(fig)
