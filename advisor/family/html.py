"""family.html: the key outputs plotted against the axes, the outcome map and the summary
tables, in one self-contained page (inline SVG drawn by :mod:`advisor.family.svg`).

Drawn from the summary alone: its document, and what it kept while the rows went by (the
outcome of every variant, the rows at the points the plots show, :func:`plot_points`)."""

from collections.abc import Iterator
from pathlib import Path
from typing import Any, NamedTuple

from advisor.family import svg
from advisor.family.outputs import NUMERIC
from advisor.family.spec import Family, Member
from advisor.family.summary import Picture

MAX_LINES = 6  # lines per plot (values of a second axis); more are sampled evenly
STATUS_COLOURS = {
    "design": "#4c9a2a",
    "infeasible": "#e0a030",
    "invalid": "#c0392b",
    "internal_error": "#6c3483",
}
_label = svg.label


def _numeric_axis(a: Any) -> bool:
    return all(isinstance(v, int | float) and not isinstance(v, bool) for v in a.values)


def _local(member: Member, coords: list[int]) -> int:
    """The number within the member of the variant at ``coords`` (last axis fastest)."""
    local = 0
    for a, k in zip(member.axes, coords, strict=True):
        local = local * len(a.values) + k
    return local


def _grid_value(picture: Picture, local: int, col: str) -> float:
    text = picture.points[local].get(col, "")
    return float(text) if text else float("nan")


class Line(NamedTuple):
    value: int | None  # index of the other axis's value on this line (None: one axis only)
    variants: list[int]  # the member's variants along the plotted axis, in its order


class Plot(NamedTuple):
    axis: int  # the axis along x
    other: int | None  # the axis whose values make the lines
    lines: list[Line]


def _other_axis(member: Member, ax_i: int) -> int | None:
    """The axis whose values make the lines of a plot against axis ``ax_i``."""
    axes = member.axes
    return next((j for j in range(len(axes)) if j != ax_i and len(axes[j].values) > 1), None)


def plot_lines(member: Member) -> Iterator[Plot]:
    """For each axis of two values or more: the lines of its plots (one per sampled value of
    the other axis; the remaining axes at their middle value)."""
    mid = [len(a.values) // 2 for a in member.axes]
    for ax_i, a in enumerate(member.axes):
        if len(a.values) < 2:
            continue
        other = _other_axis(member, ax_i)
        n = len(member.axes[other].values) if other is not None else 0
        sampled: list[int | None] = list(svg.sample(n, MAX_LINES)) if other is not None else [None]
        lines = []
        for li in sampled:
            coords = list(mid)
            if li is not None and other is not None:
                coords[other] = li
            along = []
            for k in range(len(a.values)):
                coords[ax_i] = k
                along.append(_local(member, coords))
            lines.append(Line(li, along))
        yield Plot(ax_i, other, lines)


def plot_points(member: Member) -> set[int]:
    """The member's variants whose key numbers the plots show (the summary keeps their rows)."""
    return {v for plot in plot_lines(member) for line in plot.lines for v in line.variants}


def _rest(member: Member, shown: tuple[int | None, ...]) -> str:
    """`` (key = value, …)``: the axes not shown, at their middle value."""
    rest = [
        f"{b.key} = {_label(b.values[len(b.values) // 2])}"
        for j, b in enumerate(member.axes)
        if j not in shown
    ]
    return f" ({', '.join(rest)})" if rest else ""


def _figure(title: str, legend: str, panels: list[str]) -> str:
    return f"<div class='fig'><h4>{svg.page_text(title)}</h4>{legend}{''.join(panels)}</div>"


def axis_figure(member: Member, picture: Picture, cols: list[str], plot: Plot) -> str:
    """The key numbers ``cols`` against one axis, one panel each, one line per value of the
    other axis (its legend above the panels)."""
    a = member.axes[plot.axis]
    numeric = _numeric_axis(a)
    xa = svg.XAxis(
        list(a.values) if numeric else list(range(len(a.values))),
        a.scale == "log",
        None if numeric else [_label(v) for v in a.values],
        a.key,
    )
    panels = [
        svg.line_panel(
            col, xa, [[_grid_value(picture, v, col) for v in line.variants] for line in plot.lines]
        )
        for col in cols
    ]
    legend = ""
    if plot.other is not None:
        b = member.axes[plot.other]
        legend = svg.legend(
            [
                (f"{b.key} = {_label(b.values[line.value])}", svg.LINE_COLOURS[k])
                for k, line in enumerate(plot.lines)
                if line.value is not None
            ]
        )
    title = f"{member.name}: key outputs against {a.key}" + _rest(member, (plot.axis, plot.other))
    return _figure(title, legend, panels)


def output_plots(member: Member, picture: Picture, cols: list[str]) -> list[str]:
    """For each axis: the key numbers ``cols`` against it, one line per value of another
    axis, the remaining axes at their middle value. A gap is a variant without a design."""
    if not cols:
        return []
    return [axis_figure(member, picture, cols, plot) for plot in plot_lines(member)]


def _status_grid(member: Member, picture: Picture) -> list[list[int]]:
    """The outcome (index into STATUS_COLOURS) over the first two axes, the others at their
    middle value: one row per value of the second axis."""
    axes = member.axes
    if len(axes) == 1:
        return [list(picture.status)]
    mid = [len(a.values) // 2 for a in axes]
    return [
        [picture.status[_local(member, [i, j, *mid[2:]])] for i in range(len(axes[0].values))]
        for j in range(len(axes[1].values))
    ]


def status_map(member: Member, picture: Picture) -> str | None:
    """The outcome of every variant over the first two axes (others at their middle)."""
    axes = member.axes
    if not axes:
        return None
    a0, a1 = axes[0], axes[1] if len(axes) > 1 else None
    panel = svg.map_panel(
        _status_grid(member, picture),
        list(STATUS_COLOURS.values()),
        [_label(v) for v in a0.values],
        [_label(v) for v in a1.values] if a1 is not None else None,
        (a0.key, a1.key if a1 is not None else ""),
    )
    title = f"{member.name}: outcome of each variant" + _rest(member, (0, 1))
    return _figure(title, svg.legend(list(STATUS_COLOURS.items())), [panel])


def _table(head: list[str], body: list[list[Any]]) -> str:
    th = "".join(f"<th>{svg.page_text(h)}</th>" for h in head)
    trs = "".join(
        "<tr>" + "".join(f"<td>{svg.page_text(_label(c))}</td>" for c in r) + "</tr>" for r in body
    )
    return f"<table><tr>{th}</tr>{trs}</table>"


CSS = """body{font-family:sans-serif;max-width:1300px;margin:1em auto;padding:0 1em;color:#222}
table{border-collapse:collapse;margin:.5em 0 1.5em}td,th{border:1px solid #ccc;padding:2px 8px;
font-size:13px;text-align:left}th{background:#eee}svg{max-width:100%;height:auto}
.fig{margin:1em 0}.fig h4{margin:.3em 0;font-weight:normal}.legend{margin:.2em 0;font-size:12px}
.legend span{margin-right:1.2em}.legend i{display:inline-block;width:10px;height:10px;
margin-right:4px}"""


def _changes_table(md: dict[str, Any]) -> str:
    return _table(
        ["output", "along", "between", "from", "to", "lines"],
        [
            [
                ch["output"],
                ch["axis"],
                " – ".join(_label(b) for b in ch["between"]),
                ch["from"],
                ch["to"],
                f"{ch['lines']} of {ch['of_lines']}",
            ]
            for ch in md["changes"]
        ],
    )


def _without_design_table(md: dict[str, Any]) -> str:
    return _table(
        ["status", "variants", "example reason", "at axis values"],
        [
            [
                g["status"],
                g["variants"],
                g["example"],
                "; ".join(f"{k}: {', '.join(_label(x) for x in v)}" for k, v in g["axes"].items()),
            ]
            for g in md["without_design"]
        ],
    )


def member_section(m: Member, md: dict[str, Any], picture: Picture) -> list[str]:
    """A member's part of the page: its axes, the outcome map, the plots and the tables."""
    parts = [
        f"<h2>{svg.page_text(m.name)} ({svg.page_text(m.application)}), {m.size} variants</h2>",
        _table(
            ["axis", "scale", "values"],
            [
                [k, v["scale"], ", ".join(_label(x) for x in v["values"])]
                for k, v in md["axes"].items()
            ],
        ),
    ]
    sm = status_map(m, picture)
    if sm:
        parts.append(sm)
    # the numbers some variant has (its span is in the summary)
    parts += output_plots(m, picture, [c for c in NUMERIC if c in md["outputs"]])
    if md["changes"]:
        parts += ["<h3>Where the choices change</h3>", _changes_table(md)]
    if md["without_design"]:
        parts += ["<h3>Variants without a design</h3>", _without_design_table(md)]
    return parts


def render(family: Family, doc: dict[str, Any], pictures: list[Picture]) -> str:
    """The page, from the summary document and what the summary kept for the plots."""
    c = doc["counts"]
    parts = [
        f"<!doctype html><html><head><meta charset='utf-8'><title>{svg.page_text(family.name)}"
        f"</title><style>{CSS}</style></head><body>",
        f"<h1>{svg.page_text(family.name)}</h1>",
        f"<p>{family.size} variants from <code>{svg.page_text(family.source)}</code>: "
        f"{c['design']} designs, {c['infeasible']} infeasible, {c['invalid']} invalid"
        + (f", {c['internal_error']} internal errors" if c["internal_error"] else "")
        + ". Every row of <code>designs.csv</code> is what <code>advisor --batch</code> gives "
        "for that variant alone.</p>",
    ]
    for m, md, pic in zip(family.members, doc["members"], pictures, strict=True):
        parts += member_section(m, md, pic)
    parts.append("</body></html>\n")
    return "\n".join(parts)


def write_html(path: Path, family: Family, doc: dict[str, Any], pictures: list[Picture]) -> None:
    from advisor.family.adapter import write_atomic

    write_atomic(path, render(family, doc, pictures))
