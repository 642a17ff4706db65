"""The datasheet as one self-contained HTML file: inline CSS, plots as inline SVG, no
script, no link to anything outside it (it can be mailed or attached to a review)."""

from html import escape

from advisor.core.io_safety import printable
from advisor.datasheet.content import (
    Bar,
    Block,
    Probability,
    Required,
    Sheet,
    Table,
    no_checks,
    nothing_to_show,
)
from advisor.datasheet.plots import Plot, svg, tornado_svg

#: The sections, in order: their ids are what a reader (and the test) finds.
SECTIONS = (
    ("header", "Document"),
    ("summary", "Summary"),
    ("required", "Required and achieved"),
    ("utilisation", "Utilisation"),
    ("load-cycle", "Load cycle"),
    ("parts", "Parts"),
    ("warnings", "Warnings"),
    ("components", "Components"),
    ("checks", "Checks"),
    ("uncertainty", "Probability of passing"),
    ("plots", "Plots"),
    ("decisions", "Decisions"),
    ("requirements", "Requirements (SI)"),
    ("references", "References"),
)

CSS = """
body { font-family: -apple-system, "Segoe UI", "DejaVu Sans", sans-serif; max-width: 60rem;
  margin: 2rem auto; padding: 0 1rem; color: #222; line-height: 1.4; }
h1 { margin-bottom: 0.2rem; } .sub { color: #666; margin-top: 0; }
.headline { font-size: 1.2rem; font-weight: bold; }
table { border-collapse: collapse; margin: 0.5rem 0 1rem; font-size: 0.9rem; }
th, td { border-bottom: 1px solid #ddd; padding: 0.2rem 0.6rem; text-align: left;
  vertical-align: top; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
tr.fails td { background: #fdd; } tr.tight td { background: #fff3cd; }
.mark-fails { color: #b00; font-weight: bold; } .mark-tight { color: #a60; font-weight: bold; }
.warning { background: #fff3cd; padding: 0.3rem 0.6rem; margin: 0.3rem 0; }
.decision { border-left: 3px solid #8ab; padding-left: 0.8rem; margin: 0.8rem 0; }
.decision .what { font-weight: bold; } .src { color: #555; font-size: 0.85rem; }
figure { margin: 1rem 0; } figure svg { max-width: 100%; height: auto; }
h3 { margin-bottom: 0.2rem; } h4 { margin: 0.6rem 0 0.1rem; }
td, th { overflow-wrap: break-word; }
.scroll { overflow-x: auto; max-width: 100%; }
table.many { font-size: 0.75rem; } table.many th, table.many td { padding: 0.15rem 0.3rem; }
td.mark, td[class^="mark-"] { white-space: nowrap; }
table.wide { width: 100%; }
#header table { width: 100%; border: 1px solid #444; }
#header th { width: 22%; background: #f2f2f2; }
#header td { height: 1.3rem; }
.bar { position: relative; height: 0.9rem; width: 12rem; border: 1px solid #444;
  background: #fff; }
.bar .fill { height: 100%; background: #555; }
.bar.tight .fill { background: repeating-linear-gradient(45deg, #555 0 3px, #fff 3px 5px); }
.bar.fails .fill { background: #000; }
.note { color: #555; font-size: 0.85rem; }
section#summary { break-after: auto; }
@page { size: A4; margin: 15mm; }
@media print { body { margin: 0; max-width: none; } section { break-inside: auto; }
  #required { break-after: page; } tr, figure { break-inside: avoid; } }
"""

MARK = {
    "fails": "✗ fails",
    "tight": "⚠ tight",
    "passes": "✓",
    "none": "no check",
    "unreached": "not reached",
}


def _e(text: object) -> str:
    """Text for the page: HTML-escaped, and control and bidi characters shown escaped (a NUL
    is invalid in HTML; a right-to-left override would reorder a header's fields)."""
    return escape(printable(str(text), newlines=False))


def _num_cell(text: str) -> str:
    numeric = text.replace(".", "", 1).replace("-", "", 1).replace("e", "").replace("+", "")
    cls = ' class="num"' if numeric.isdigit() else ""
    return f"<td{cls}>{_e(text)}</td>"


def _table(t: Table, level: int) -> str:
    head = "".join(f"<th>{_e(c)}</th>" for c in t.columns)
    rows = "".join("<tr>" + "".join(_num_cell(c) for c in r) + "</tr>" for r in t.rows)
    cls = ' class="many"' if len(t.columns) > 6 else ""  # fits an A4 page in small print
    return (
        f'<h{level}>{_e(t.title)}</h{level}><div class="scroll"><table{cls}><tr>{head}</tr>'
        f"{rows}</table></div>"
    )


def _block(b: Block, level: int) -> str:
    out = [f"<h{level}>{_e(b.title)}</h{level}>"]
    if b.rows:
        out.append("<table>")
        for k, v, u in b.rows:
            out.append(f"<tr><th>{_e(k)}</th>{_num_cell(v)}<td>{_e(u)}</td></tr>")
        out.append("</table>")
    out += [_table(t, min(level + 1, 6)) for t in b.tables]
    out += [_block(p, min(level + 1, 6)) for p in b.parts]
    return "\n".join(out)


def _figure(p: Plot, index: int) -> str:
    return (
        f'<figure id="plot-{p.id}">{svg(p, f"drive-advisor-{index}-{p.id}")}'
        f"<figcaption>{_e(p.title)}</figcaption></figure>"
    )


def _probability(p: Probability | None, absent: str) -> str:
    """P(pass) of the design and of each check, and the tornado chart of the drivers of the
    least probable checks (``absent``: what to say where there is none)."""
    if p is None:
        return f"<p>{_e(absent)}</p>"
    out = [f"<p>{_e(p.statement)}</p>", _table(p.inputs, 3), _table(p.checks, 3)]
    out += [f'<p class="note">{_e(n)}</p>' for n in p.notes]
    for i, t in enumerate(p.tornadoes, 1):
        out.append(
            f'<h3 id="drivers-{_e(t.check_id)}">Tornado chart: drivers of {_e(t.check_name)}</h3>'
            f'<figure id="tornado-{_e(t.check_id)}" data-check="{_e(t.check_id)}">'
            f"{tornado_svg(t, f'drive-advisor-tornado-{i}-{t.check_id}')}"
            f"<figcaption>{_e(t.check_name)}: {_e(t.probability)}; bars by |ρ|, largest "
            "first</figcaption></figure>"
        )
    return "\n".join(out)


def _header(s: Sheet) -> str:
    cells = list(s.project)
    rows = "".join(
        f"<tr><th>{_e(a)}</th><td>{_e(b)}</td><th>{_e(c)}</th><td>{_e(d)}</td></tr>"
        for (a, b), (c, d) in zip(cells[::2], [*cells[1::2], ("", "")], strict=False)
    )
    return f"<table>{rows}</table>"


def _required(rows: list[Required], at_default: int) -> str:
    out = [
        '<table class="wide"><tr><th>requirement</th><th>required</th><th>covered by</th>'
        "<th>achieved (value against limit)</th><th>margin</th><th></th></tr>"
    ]
    for r in rows:
        more = f" (and {r.more} more)" if r.more else ""
        mark = MARK.get(r.status, "—")
        out.append(
            f'<tr class="{r.status}" data-path="{_e(r.path)}"><th>{_e(r.label)}</th>'
            f"<td>{_e(f'{r.value} {r.unit}'.strip())}</td><td>{_e(r.check + more)}</td>"
            f"<td>{_e(r.achieved)}</td>{_num_cell(r.margin)}"
            f'<td class="mark-{r.status}">{_e(mark)}</td></tr>'
        )
    out.append("</table>")
    if at_default:
        out.append(
            f'<p class="note">{at_default} further requirements are at their defaults; '
            "the Requirements section lists every value.</p>"
        )
    return "".join(out)


def _bars(bars: list[Bar]) -> str:
    rows = []
    for b in bars:
        width = min(b.utilisation, 1.0) * 100
        rows.append(
            f'<tr class="{b.status}"><td>{_e(b.name)}</td>'
            f'<td><div class="bar {b.status}" role="meter" aria-valuenow="{b.utilisation:.3f}">'
            f'<div class="fill" style="width: {width:.1f}%"></div></div></td>'
            f"{_num_cell(f'{b.utilisation * 100:.0f} %')}"
            f'<td class="mark-{b.status}">{_e(MARK[b.status])}</td></tr>'
        )
    return (
        '<p class="note">Demand over capacity of each check (1 / margin): a full bar is a check '
        "at its limit; hatched, tight (margin below 1.1); black, failing.</p>"
        f'<table class="wide">{"".join(rows)}</table>'
    )


def _cycle(s: Sheet) -> str:
    if s.cycle is None:
        return "<p>This design has no duty cycle: its requirement has no [duty] table.</p>"
    head = "".join(f"<th>{_e(c)}</th>" for c in s.cycle.columns)
    rows = "".join("<tr>" + "".join(_num_cell(c) for c in r) + "</tr>" for r in s.cycle.rows)
    return (
        f'<table class="wide"><tr>{head}</tr>{rows}</table><p class="note">{_e(s.cycle.note)}</p>'
    )


def _parts(rows: list[list[str]]) -> str:
    if not rows:
        return "<p>No parts: this design names no component.</p>"
    head = "".join(
        f"<th>{c}</th>"
        for c in ("component", "designation", "rating", "dimensions", "mass", "source")
    )
    body = "".join("<tr>" + "".join(f"<td>{_e(c)}</td>" for c in r) + "</tr>" for r in rows)
    return f'<table class="wide"><tr>{head}</tr>{body}</table>'


def _checks(s: Sheet) -> str:
    """The checks' table, or one line where there is none (no bare header)."""
    if not s.checks:
        return f"<p>{_e(no_checks(s.status))}</p>"
    rows = "".join(
        f'<tr class="{c.status}"><td class="mark-{c.status}">{_e(MARK[c.status])}</td>'
        f"<td>{_e(c.id)}</td><td>{_e(c.name)}</td>{_num_cell(c.value)}{_num_cell(c.limit)}"
        f"<td>{_e(c.unit)}</td>{_num_cell(c.margin)}<td>{_e(c.source)}</td></tr>"
        for c in s.checks
    )
    return (
        "<p>The margin is the limit over the value (or the value over the limit, whichever "
        "way the check passes): at least 1 passes; below 1.1 it is marked tight.</p>"
        "<table><tr><th></th><th>id</th><th>check</th><th>value</th><th>limit</th>"
        f"<th>unit</th><th>margin</th><th>source</th></tr>{rows}</table>"
    )


def _decisions(s: Sheet) -> str:
    """Each decision with its reason, source and inputs, or one line where there is none."""
    return (
        "\n".join(
            f'<div class="decision" id="decision-{_e(d.id)}"><h3>{_e(d.id)} — {_e(d.title)}</h3>'
            f'<p class="what">{_e(d.decision)}</p><p>{_e(d.rationale)}</p>'
            f'<p class="src">Source: {_e(d.source)}</p>'
            + (f'<p class="src">Inputs: {_e(d.inputs)}</p>' if d.inputs else "")
            + "</div>"
            for d in s.decisions
        )
        or f"<p>{_e(nothing_to_show('decision', s.status))}</p>"
    )


def render(s: Sheet, plots: list[Plot]) -> str:
    body: dict[str, str] = {}
    body["header"] = _header(s)
    body["required"] = _required(s.required, s.at_default)
    body["utilisation"] = _bars(s.bars) if s.bars else f"<p>{_e(no_checks(s.status))}</p>"
    body["load-cycle"] = _cycle(s)
    body["parts"] = _parts(s.parts)
    summary = "".join(f"<tr><th>{_e(k)}</th><td>{_e(v)}</td></tr>" for k, v in s.summary)
    body["summary"] = f'<p class="headline">{_e(s.headline)}</p><table>{summary}</table>'
    body["warnings"] = "".join(f'<p class="warning">{_e(w)}</p>' for w in s.warnings) or (
        "<p>None.</p>"
    )
    body["components"] = "\n".join(_block(b, 3) for b in s.components) or (
        f"<p>{_e(nothing_to_show('component', s.status))}</p>"
    )
    body["checks"] = _checks(s)
    body["uncertainty"] = _probability(s.probability, s.no_probability)
    body["plots"] = "\n".join(_figure(p, i) for i, p in enumerate(plots, 1)) or (
        "<p>This report has no curves to plot.</p>"
    )
    body["decisions"] = _decisions(s)
    body["requirements"] = "\n".join(_block(b, 3) for b in s.requirements)
    body["references"] = (
        "<ol>" + "".join(f"<li>{_e(r)}</li>" for r in s.references) + "</ol>"
        if s.references
        else "<p>None.</p>"
    )
    sections = "\n".join(
        f'<section id="{sid}"><h2>{_e(title)}</h2>\n{body[sid]}\n</section>'
        for sid, title in SECTIONS
    )
    return (
        "<!DOCTYPE html>\n"
        f'<html lang="en"><head><meta charset="utf-8"><title>{_e(s.title)} — datasheet'
        f"</title><style>{CSS}</style></head><body>\n"
        f"<h1>{_e(s.title)}</h1>"
        f'<p class="sub">Drive Advisor {_e(s.version)} · {_e(s.application)} · '
        f"{_e(s.status)}</p>\n{sections}\n</body></html>\n"
    )
