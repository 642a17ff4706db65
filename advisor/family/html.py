"""family.html: the key outputs plotted against the axes, the outcome map and the summary
tables, in one self-contained page (matplotlib SVG inline; imported only on this path).

Drawn from the summary alone: its document, and what it kept while the rows went by (the
outcome of every variant, the rows at the points the plots show, :func:`plot_points`)."""

import html
import io
from collections.abc import Iterator
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np

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


def _svg(fig: Any) -> str:
    buf = io.StringIO()
    fig.savefig(buf, format="svg", bbox_inches="tight")
    import matplotlib.pyplot as plt

    plt.close(fig)
    text = buf.getvalue()
    return text[text.index("<svg") :]


def _label(v: Any) -> str:
    return f"{v:g}" if isinstance(v, float) else str(v)


def _mpl(text: str) -> str:
    """User text as matplotlib draws it literally: a ``$`` would start mathtext (and a
    broken formula in a member's name would stop the page)."""
    return text.replace("$", r"\$")


def _sample(n: int, k: int) -> list[int]:
    if n <= k:
        return list(range(n))
    return sorted({round(i * (n - 1) / (k - 1)) for i in range(k)})


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


def _other_axis(member: Member, ax_i: int) -> int | None:
    """The axis whose values make the lines of a plot against axis ``ax_i``."""
    axes = member.axes
    return next((j for j in range(len(axes)) if j != ax_i and len(axes[j].values) > 1), None)


def plot_lines(member: Member) -> Iterator[tuple[int, int | None, list[Line]]]:
    """For each axis of two values or more: the axis, the other axis, and the lines of its
    plots (one per sampled value of the other axis; the remaining axes at their middle)."""
    mid = [len(a.values) // 2 for a in member.axes]
    for ax_i, a in enumerate(member.axes):
        if len(a.values) < 2:
            continue
        other = _other_axis(member, ax_i)
        sampled = (
            _sample(len(member.axes[other].values), MAX_LINES) if other is not None else [None]
        )
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
        yield ax_i, other, lines


def plot_points(member: Member) -> set[int]:
    """The member's variants whose key numbers the plots show (the summary keeps their rows)."""
    return {v for _, _, lines in plot_lines(member) for line in lines for v in line.variants}


def _plot_column(axp: Any, member: Member, picture: Picture, plot: tuple, col: str) -> None:
    """One subplot: ``col`` against the plot's axis, one line per value of the other axis."""
    ax_i, other, lines = plot
    a = member.axes[ax_i]
    xs = list(a.values) if _numeric_axis(a) else list(range(len(a.values)))
    for line in lines:
        ys = [_grid_value(picture, v, col) for v in line.variants]
        label = None
        if other is not None and line.value is not None:
            b = member.axes[other]
            label = _mpl(f"{b.key} = {_label(b.values[line.value])}")
        axp.plot(xs, ys, marker=".", label=label)
    if a.scale == "log":
        axp.set_xscale("log")
    if not _numeric_axis(a):
        axp.set_xticks(xs, [_mpl(_label(v)) for v in a.values], rotation=30)
    axp.set_xlabel(a.key)
    axp.set_title(col, fontsize=10)
    axp.grid(alpha=0.3)


def _axis_figure(member: Member, picture: Picture, cols: list[str], plot: tuple) -> str:
    """The key numbers against one axis, one subplot per number, as SVG."""
    import matplotlib.pyplot as plt

    ax_i, other, _ = plot
    ncol = min(3, len(cols))
    nrow = -(-len(cols) // ncol)
    fig, axs = plt.subplots(nrow, ncol, figsize=(4.2 * ncol, 3.0 * nrow), squeeze=False)
    for p, col in enumerate(cols):
        _plot_column(axs[p // ncol][p % ncol], member, picture, plot, col)
    for p in range(len(cols), nrow * ncol):
        axs[p // ncol][p % ncol].axis("off")
    if other is not None:
        axs[0][0].legend(fontsize=7)
    mid = [len(b.values) // 2 for b in member.axes]
    rest = [
        f"{b.key} = {_label(b.values[mid[j]])}"
        for j, b in enumerate(member.axes)
        if j not in (ax_i, other)
    ]
    title = f"{member.name}: key outputs against {member.axes[ax_i].key}"
    fig.suptitle(_mpl(title + (f" ({', '.join(rest)})" if rest else "")), fontsize=11)
    fig.tight_layout()
    return _svg(fig)


def output_plots(member: Member, picture: Picture, cols: list[str]) -> list[str]:
    """For each axis: the key numbers ``cols`` against it, one line per value of another
    axis, the remaining axes at their middle value. A gap is a variant without a design."""
    import matplotlib

    matplotlib.use("Agg")
    if not cols:
        return []
    return [_axis_figure(member, picture, cols, plot) for plot in plot_lines(member)]


def _status_grid(member: Member, picture: Picture) -> np.ndarray:
    """The outcome (index into STATUS_COLOURS) over the first two axes, the others at their
    middle value: one row per value of the second axis."""
    full = picture.status.reshape(tuple(len(a.values) for a in member.axes)).astype(np.int64)
    if len(member.axes) == 1:
        return full.reshape(1, -1)
    mid = [len(a.values) // 2 for a in member.axes]
    return full[(slice(None), slice(None), *mid[2:])].T


def status_map(member: Member, picture: Picture) -> str | None:
    """The outcome of every variant over the first two axes (others at their middle)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import ListedColormap

    axes = member.axes
    if not axes:
        return None
    grid = _status_grid(member, picture)
    a0, n1 = axes[0], grid.shape[0]
    fig, ax = plt.subplots(figsize=(min(12, 2 + 0.35 * len(a0.values)), min(8, 1.5 + 0.35 * n1)))
    ax.imshow(
        grid,
        cmap=ListedColormap(list(STATUS_COLOURS.values())),
        vmin=0,
        vmax=3,
        aspect="auto",
        origin="lower",
        interpolation="nearest",
    )
    _status_ticks(ax, member)
    fig.tight_layout()
    return _svg(fig)


def _status_ticks(ax: Any, member: Member) -> None:
    """The status map's ticks, legend and title."""
    from matplotlib.patches import Patch

    axes = member.axes
    a0 = axes[0]
    step0 = max(1, len(a0.values) // 12)
    ax.set_xticks(
        range(0, len(a0.values), step0),
        [_mpl(_label(v)) for v in a0.values[::step0]],
        rotation=45,
    )
    ax.set_xlabel(a0.key)
    if len(axes) > 1:
        a1 = axes[1]
        step1 = max(1, len(a1.values) // 12)
        ax.set_yticks(
            range(0, len(a1.values), step1), [_mpl(_label(v)) for v in a1.values[::step1]]
        )
        ax.set_ylabel(a1.key)
    else:
        ax.set_yticks([])
    ax.legend(
        handles=[Patch(color=c, label=s) for s, c in STATUS_COLOURS.items()],
        loc="upper left",
        bbox_to_anchor=(1.01, 1),
        fontsize=8,
    )
    mid = [len(a.values) // 2 for a in axes]
    rest = [f"{b.key} = {_label(b.values[mid[j]])}" for j, b in enumerate(axes) if j > 1]
    ax.set_title(
        _mpl(f"{member.name}: outcome of each variant" + (f" ({', '.join(rest)})" if rest else "")),
        fontsize=11,
    )


def _table(head: list[str], body: list[list[Any]]) -> str:
    th = "".join(f"<th>{html.escape(h)}</th>" for h in head)
    trs = "".join(
        "<tr>" + "".join(f"<td>{html.escape(_label(c))}</td>" for c in r) + "</tr>" for r in body
    )
    return f"<table><tr>{th}</tr>{trs}</table>"


CSS = """body{font-family:sans-serif;max-width:1300px;margin:1em auto;padding:0 1em;color:#222}
table{border-collapse:collapse;margin:.5em 0 1.5em}td,th{border:1px solid #ccc;padding:2px 8px;
font-size:13px;text-align:left}th{background:#eee}svg{max-width:100%;height:auto}"""


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
        f"<h2>{html.escape(m.name)} ({html.escape(m.application)}), {m.size} variants</h2>",
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
        f"<!doctype html><html><head><meta charset='utf-8'><title>{html.escape(family.name)}"
        f"</title><style>{CSS}</style></head><body>",
        f"<h1>{html.escape(family.name)}</h1>",
        f"<p>{family.size} variants from <code>{html.escape(family.source)}</code>: "
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
    import warnings

    from advisor.family.adapter import write_atomic

    # matplotlib warns when a long title leaves no room for tight_layout ("Tight layout not
    # applied"): the plot is drawn all the same, and the warning is not the user's business
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        text = render(family, doc, pictures)
    write_atomic(path, text)
