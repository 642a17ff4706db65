"""The plots of family.html as inline SVG, drawn here: line panels and the outcome map.

A page of a few plots takes milliseconds this way; through matplotlib it took about a
second of CPU (its import, then a layout and a drawing of every figure), more than
advising the 60 variants of the example. Every text is escaped: a member's name is shown,
never read as markup.
"""

import math
from collections.abc import Sequence
from html import escape
from typing import NamedTuple

from advisor.core.io_safety import printable

#: The colours of the lines, one per value of the other axis (matplotlib's first six).
LINE_COLOURS = ("#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b")
PANEL_W, PANEL_H = 320, 220  # px
LEFT, RIGHT, TOP, BOTTOM = 56, 12, 24, 44  # margins of the plotting area, px
MAX_CELLS = 160  # cells per side of the outcome map; more are sampled evenly
FONT = "font-family='sans-serif' font-size='11'"


def page_text(text: object) -> str:
    """Text for the page: HTML-escaped, and control and bidi characters shown escaped (as
    the HTML datasheet does: a NUL is invalid in HTML, an ESC or BEL in a member's name must
    not reach the page raw)."""
    return escape(printable(str(text), newlines=False))


def label(v: object) -> str:
    return f"{v:g}" if isinstance(v, float) else str(v)


def nice_ticks(lo: float, hi: float, count: int = 5) -> list[float]:
    """About ``count`` round values (1, 2 or 5 × 10^k apart) from ``lo`` to ``hi``.

    >>> nice_ticks(0.0, 1.0), nice_ticks(3.0, 3.0)
    ([0.0, 0.2, 0.4, 0.6, 0.8, 1.0], [3.0])
    """
    if not hi > lo:
        return [lo]
    raw = (hi - lo) / count
    mag = 10 ** math.floor(math.log10(raw))
    step = next(m * mag for m in (1, 2, 5, 10) if m * mag >= raw)
    first = math.ceil(lo / step - 1e-9)
    return [round(k * step, 12) for k in range(first, math.floor(hi / step + 1e-9) + 1)]


def log_ticks(lo: float, hi: float) -> list[float]:
    """The powers of ten from ``lo`` to ``hi``; 1, 2 and 5 × 10^k where that gives too few.

    >>> log_ticks(1.0, 1000.0), log_ticks(100.0, 2000.0)
    ([1.0, 10.0, 100.0, 1000.0], [100.0, 200.0, 500.0, 1000.0, 2000.0])
    """
    decades = range(math.floor(math.log10(lo)), math.ceil(math.log10(hi)) + 1)
    for mantissas in ((1,), (1, 2, 5), (1, 2, 3, 5, 7)):
        ticks = [m * 10.0**d for d in decades for m in mantissas]
        ticks = [t for t in ticks if lo * (1 - 1e-9) <= t <= hi * (1 + 1e-9)]
        if len(ticks) >= 3:
            return ticks
    return [lo, hi]


class Scale(NamedTuple):
    """Data from ``lo`` to ``hi`` (logarithmic or not) onto pixels from ``p0`` to ``p1``."""

    lo: float
    hi: float
    log: bool
    p0: float
    p1: float

    def __call__(self, v: float) -> float:
        f = math.log10 if self.log else float
        span = f(self.hi) - f(self.lo)
        t = (f(v) - f(self.lo)) / span if span else 0.5
        return self.p0 + t * (self.p1 - self.p0)


def y_range(series: Sequence[Sequence[float]]) -> tuple[float, float]:
    """The finite values of every line, with a margin of 5 % (a flat line gets ±5 %)."""
    ys = [y for s in series for y in s if math.isfinite(y)]
    if not ys:
        return 0.0, 1.0
    lo, hi = min(ys), max(ys)
    pad = (hi - lo) * 0.05 or abs(lo) * 0.05 or 1.0
    return lo - pad, hi + pad


def _text(x: float, y: float, text: str, anchor: str = "middle", extra: str = "") -> str:
    at = f"x='{x:.1f}' y='{y:.1f}' text-anchor='{anchor}' {FONT} {extra}"
    return f"<text {at}>{page_text(text)}</text>"


def _polylines(xs: Sequence[float], ys: Sequence[float], sx: Scale, sy: Scale, colour: str) -> str:
    """A line through the points, broken where a value is missing (no design), with dots."""
    out, run = [], []
    for x, y in [*zip(xs, ys, strict=True), (math.nan, math.nan)]:
        if math.isfinite(y) and math.isfinite(x):
            run.append(f"{sx(x):.1f},{sy(y):.1f}")
            out.append(f"<circle cx='{sx(x):.1f}' cy='{sy(y):.1f}' r='2' fill='{colour}'/>")
        elif run:
            out.append(
                f"<polyline points='{' '.join(run)}' fill='none' stroke='{colour}' "
                "stroke-width='1.5'/>"
            )
            run = []
    return "".join(out)


class XAxis(NamedTuple):
    values: list[float]  # the positions of the points (the axis values, or 0, 1, … for text)
    log: bool
    names: list[str] | None  # the tick labels of a text axis, one per value
    title: str


def _x_ticks(xa: XAxis, sx: Scale, bottom: float) -> list[str]:
    if xa.names is not None:
        ticks = list(zip(xa.values, xa.names, strict=True))
    elif xa.log:
        ticks = [(t, label(t)) for t in log_ticks(sx.lo, sx.hi)]
    else:
        ticks = [(t, label(t)) for t in nice_ticks(sx.lo, sx.hi)]
    out = []
    for t, name in ticks:
        x = sx(t)
        out.append(f"<line x1='{x:.1f}' y1='{TOP}' x2='{x:.1f}' y2='{bottom}' stroke='#e4e4e4'/>")
        if xa.names is None:
            out.append(_text(x, bottom + 14, name))
        else:  # names slanted, as they may be long
            turn = f"transform='rotate(-30 {x:.1f} {bottom + 12:.1f})'"
            out.append(_text(x, bottom + 12, name, "end", turn))
    return out


def bottom_margin(xa: XAxis) -> int:
    """Room under the plotting area for the tick labels and the axis title."""
    if xa.names is None:
        return BOTTOM
    return BOTTOM + min(90, 3 * max(len(n) for n in xa.names))


def line_panel(title: str, xa: XAxis, series: Sequence[Sequence[float]]) -> str:
    """One panel: each series against the x axis, in the colours of :data:`LINE_COLOURS`."""
    height = PANEL_H - BOTTOM + bottom_margin(xa)
    right, bottom = PANEL_W - RIGHT, PANEL_H - BOTTOM
    lo, hi = min(xa.values), max(xa.values)
    if lo == hi:
        lo, hi = (lo / 2, hi * 2) if xa.log else (lo - 1, hi + 1)
    sx = Scale(lo, hi, xa.log, LEFT, right)
    sy = Scale(*y_range(series), False, bottom, TOP)
    parts = [f"<svg xmlns='http://www.w3.org/2000/svg' width='{PANEL_W}' height='{height}'>"]
    parts += _x_ticks(xa, sx, bottom)
    for t in nice_ticks(sy.lo, sy.hi):
        y = sy(t)
        parts.append(f"<line x1='{LEFT}' y1='{y:.1f}' x2='{right}' y2='{y:.1f}' stroke='#e4e4e4'/>")
        parts.append(_text(LEFT - 4, y + 4, label(t), "end"))
    parts.append(
        f"<rect x='{LEFT}' y='{TOP}' width='{right - LEFT}' height='{bottom - TOP}' "
        "fill='none' stroke='#555'/>"
    )
    for k, ys in enumerate(series):
        parts.append(_polylines(xa.values, ys, sx, sy, LINE_COLOURS[k % len(LINE_COLOURS)]))
    parts.append(_text((LEFT + right) / 2, 15, title, extra="font-weight='bold'"))
    parts.append(_text((LEFT + right) / 2, height - 8, xa.title))
    parts.append("</svg>")
    return "".join(parts)


def sample(n: int, k: int) -> list[int]:
    """At most ``k`` indices of ``n``, evenly spread, the first and the last included."""
    if n <= k:
        return list(range(n))
    return sorted({round(i * (n - 1) / (k - 1)) for i in range(k)})


def map_panel(
    grid: Sequence[Sequence[int]],
    colours: Sequence[str],
    x_names: Sequence[str],
    y_names: Sequence[str] | None,
    titles: tuple[str, str],
) -> str:
    """The outcome map: ``grid[row][column]`` an index into ``colours``, the first row at
    the bottom; at most :data:`MAX_CELLS` rows and columns (sampled evenly)."""
    rows, cols = sample(len(grid), MAX_CELLS), sample(len(grid[0]), MAX_CELLS)
    cell = max(4.0, min(48.0, 640 / max(len(cols), 1)))
    ch = max(4.0, min(28.0, 360 / max(len(rows), 1)))
    left, top = 84, 8
    w, h = left + cell * len(cols) + 10, top + ch * len(rows) + 58
    parts = [f"<svg xmlns='http://www.w3.org/2000/svg' width='{w:.0f}' height='{h:.0f}'>"]
    for r, i in enumerate(rows):
        y = top + ch * (len(rows) - 1 - r)
        for c, j in enumerate(cols):
            parts.append(
                f"<rect x='{left + cell * c:.1f}' y='{y:.1f}' width='{cell:.1f}' "
                f"height='{ch:.1f}' fill='{colours[grid[i][j]]}'/>"
            )
    bottom = top + ch * len(rows)
    # as many tick labels as fit: about 90 px a label across, 16 px up
    for c in sample(len(cols), max(2, int(cell * len(cols) // 90))):
        x = left + cell * (c + 0.5)
        parts.append(_text(x, bottom + 14, x_names[cols[c]]))
    for r in sample(len(rows), max(2, int(ch * len(rows) // 16))) if y_names is not None else []:
        y = top + ch * (len(rows) - 1 - r + 0.5)
        parts.append(_text(left - 4, y + 4, y_names[rows[r]], "end"))
    parts.append(_text(left + cell * len(cols) / 2, bottom + 32, titles[0]))
    if titles[1]:
        y = top + ch * len(rows) / 2
        parts.append(_text(12, y, titles[1], extra=f"transform='rotate(-90 12 {y:.1f})'"))
    parts.append("</svg>")
    return "".join(parts)


def legend(items: Sequence[tuple[str, str]]) -> str:
    """A row of colour swatches and their names (HTML)."""
    return (
        "<p class='legend'>"
        + "".join(
            f"<span><i style='background:{colour}'></i>{page_text(name)}</span>"
            for name, colour in items
        )
        + "</p>"
    )
