"""family.html: the key outputs plotted against the axes, the outcome map and the summary
tables, in one self-contained page (matplotlib SVG inline; imported only on this path)."""

import html
import io
from pathlib import Path
from typing import Any

from advisor.family.outputs import NUMERIC
from advisor.family.spec import Family, Member

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


def _grid_value(rows: list[dict[str, str]], member: Member, coords: list[int], col: str) -> float:
    local = 0
    for a, k in zip(member.axes, coords, strict=True):
        local = local * len(a.values) + k
    text = rows[local].get(col, "")
    return float(text) if text else float("nan")


def output_plots(member: Member, rows: list[dict[str, str]]) -> list[str]:
    """For each axis: the key numbers against it, one line per value of another axis, the
    remaining axes at their middle value. A gap is a variant without a design."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    cols = [c for c in NUMERIC if any(r.get(c) for r in rows)]
    if not cols:
        return []
    mid = [len(a.values) // 2 for a in member.axes]
    out = []
    for ax_i, a in enumerate(member.axes):
        if len(a.values) < 2:
            continue
        other = next(
            (j for j in range(len(member.axes)) if j != ax_i and len(member.axes[j].values) > 1),
            None,
        )
        xs = list(a.values) if _numeric_axis(a) else list(range(len(a.values)))
        ncol = min(3, len(cols))
        nrow = -(-len(cols) // ncol)
        fig, axs = plt.subplots(nrow, ncol, figsize=(4.2 * ncol, 3.0 * nrow), squeeze=False)
        for p, col in enumerate(cols):
            axp = axs[p // ncol][p % ncol]
            line_idx = (
                _sample(len(member.axes[other].values), MAX_LINES) if other is not None else [None]
            )
            for li in line_idx:
                coords = list(mid)
                if other is not None:
                    coords[other] = li
                ys = []
                for k in range(len(a.values)):
                    coords[ax_i] = k
                    ys.append(_grid_value(rows, member, coords, col))
                label = (
                    _mpl(f"{member.axes[other].key} = {_label(member.axes[other].values[li])}")
                    if other is not None
                    else None
                )
                axp.plot(xs, ys, marker=".", label=label)
            if a.scale == "log":
                axp.set_xscale("log")
            if not _numeric_axis(a):
                axp.set_xticks(xs, [_mpl(_label(v)) for v in a.values], rotation=30)
            axp.set_xlabel(a.key)
            axp.set_title(col, fontsize=10)
            axp.grid(alpha=0.3)
        for p in range(len(cols), nrow * ncol):
            axs[p // ncol][p % ncol].axis("off")
        if other is not None:
            axs[0][0].legend(fontsize=7)
        rest = [
            f"{b.key} = {_label(b.values[mid[j]])}"
            for j, b in enumerate(member.axes)
            if j not in (ax_i, other)
        ]
        title = f"{member.name}: key outputs against {a.key}"
        fig.suptitle(_mpl(title + (f" ({', '.join(rest)})" if rest else "")), fontsize=11)
        fig.tight_layout()
        out.append(_svg(fig))
    return out


def status_map(member: Member, rows: list[dict[str, str]]) -> str | None:
    """The outcome of every variant over the first two axes (others at their middle)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import ListedColormap

    axes = member.axes
    if not axes:
        return None
    names = list(STATUS_COLOURS)
    mid = [len(a.values) // 2 for a in axes]
    a0 = axes[0]
    a1 = axes[1] if len(axes) > 1 else None
    n1 = len(a1.values) if a1 is not None else 1
    grid = []
    for k1 in range(n1):
        line = []
        for k0 in range(len(a0.values)):
            coords = list(mid)
            coords[0] = k0
            if a1 is not None:
                coords[1] = k1
            local = 0
            for a, k in zip(axes, coords, strict=True):
                local = local * len(a.values) + k
            line.append(names.index(rows[local]["status"]))
        grid.append(line)
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
    step0 = max(1, len(a0.values) // 12)
    ax.set_xticks(
        range(0, len(a0.values), step0),
        [_mpl(_label(v)) for v in a0.values[::step0]],
        rotation=45,
    )
    ax.set_xlabel(a0.key)
    if a1 is not None:
        step1 = max(1, n1 // 12)
        ax.set_yticks(range(0, n1, step1), [_mpl(_label(v)) for v in a1.values[::step1]])
        ax.set_ylabel(a1.key)
    else:
        ax.set_yticks([])
    from matplotlib.patches import Patch

    ax.legend(
        handles=[Patch(color=c, label=s) for s, c in STATUS_COLOURS.items()],
        loc="upper left",
        bbox_to_anchor=(1.01, 1),
        fontsize=8,
    )
    rest = [f"{b.key} = {_label(b.values[mid[j]])}" for j, b in enumerate(axes) if j > 1]
    ax.set_title(
        _mpl(f"{member.name}: outcome of each variant" + (f" ({', '.join(rest)})" if rest else "")),
        fontsize=11,
    )
    fig.tight_layout()
    return _svg(fig)


def _table(head: list[str], body: list[list[Any]]) -> str:
    th = "".join(f"<th>{html.escape(h)}</th>" for h in head)
    trs = "".join(
        "<tr>" + "".join(f"<td>{html.escape(_label(c))}</td>" for c in r) + "</tr>" for r in body
    )
    return f"<table><tr>{th}</tr>{trs}</table>"


CSS = """body{font-family:sans-serif;max-width:1300px;margin:1em auto;padding:0 1em;color:#222}
table{border-collapse:collapse;margin:.5em 0 1.5em}td,th{border:1px solid #ccc;padding:2px 8px;
font-size:13px;text-align:left}th{background:#eee}svg{max-width:100%;height:auto}"""


def render(family: Family, rows: list[dict[str, str]], doc: dict[str, Any]) -> str:
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
    start = 0
    for m, md in zip(family.members, doc["members"], strict=True):
        mine = rows[start : start + m.size]
        start += m.size
        parts.append(
            f"<h2>{html.escape(m.name)} ({html.escape(m.application)}), {m.size} variants</h2>"
        )
        parts.append(
            _table(
                ["axis", "scale", "values"],
                [
                    [k, v["scale"], ", ".join(_label(x) for x in v["values"])]
                    for k, v in md["axes"].items()
                ],
            )
        )
        sm = status_map(m, mine)
        if sm:
            parts.append(sm)
        parts += output_plots(m, mine)
        if md["changes"]:
            parts.append("<h3>Where the choices change</h3>")
            parts.append(
                _table(
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
            )
        if md["without_design"]:
            parts.append("<h3>Variants without a design</h3>")
            parts.append(
                _table(
                    ["status", "variants", "example reason", "at axis values"],
                    [
                        [
                            g["status"],
                            g["variants"],
                            g["example"],
                            "; ".join(
                                f"{k}: {', '.join(_label(x) for x in v)}"
                                for k, v in g["axes"].items()
                            ),
                        ]
                        for g in md["without_design"]
                    ],
                )
            )
    parts.append("</body></html>\n")
    return "\n".join(parts)


def write_html(path: Path, family: Family, rows: list[dict[str, str]], doc: dict[str, Any]) -> None:
    import warnings

    from advisor.family.adapter import write_atomic

    # matplotlib warns when a long title leaves no room for tight_layout ("Tight layout not
    # applied"): the plot is drawn all the same, and the warning is not the user's business
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        text = render(family, rows, doc)
    write_atomic(path, text)
