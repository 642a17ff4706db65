"""The datasheet as one self-contained HTML file: inline CSS, plots as inline SVG, no
script, no link to anything outside it (it can be mailed or attached to a review)."""

from html import escape

from advisor.datasheet.content import Block, Sheet, Table
from advisor.datasheet.plots import Plot, svg

#: The sections, in order: their ids are what a reader (and the test) finds.
SECTIONS = (
    ("summary", "Summary"),
    ("warnings", "Warnings"),
    ("components", "Components"),
    ("checks", "Checks"),
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
@media print { section { break-inside: avoid-page; } }
"""

MARK = {"fails": "✗ fails", "tight": "⚠ tight", "passes": "✓"}


def _e(text: object) -> str:
    return escape(str(text))


def _num_cell(text: str) -> str:
    numeric = text.replace(".", "", 1).replace("-", "", 1).replace("e", "").replace("+", "")
    cls = ' class="num"' if numeric.isdigit() else ""
    return f"<td{cls}>{_e(text)}</td>"


def _table(t: Table, level: int) -> str:
    head = "".join(f"<th>{_e(c)}</th>" for c in t.columns)
    rows = "".join("<tr>" + "".join(_num_cell(c) for c in r) + "</tr>" for r in t.rows)
    return f"<h{level}>{_e(t.title)}</h{level}><table><tr>{head}</tr>{rows}</table>"


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


def render(s: Sheet, plots: list[Plot]) -> str:
    body: dict[str, str] = {}
    summary = "".join(f"<tr><th>{_e(k)}</th><td>{_e(v)}</td></tr>" for k, v in s.summary)
    body["summary"] = f'<p class="headline">{_e(s.headline)}</p><table>{summary}</table>'
    body["warnings"] = "".join(f'<p class="warning">{_e(w)}</p>' for w in s.warnings) or (
        "<p>None.</p>"
    )
    body["components"] = "\n".join(_block(b, 3) for b in s.components)
    rows = "".join(
        f'<tr class="{c.status}"><td class="mark-{c.status}">{_e(MARK[c.status])}</td>'
        f"<td>{_e(c.id)}</td><td>{_e(c.name)}</td>{_num_cell(c.value)}{_num_cell(c.limit)}"
        f"<td>{_e(c.unit)}</td>{_num_cell(c.margin)}<td>{_e(c.source)}</td></tr>"
        for c in s.checks
    )
    body["checks"] = (
        "<p>The margin is the limit over the value (or the value over the limit, whichever "
        "way the check passes): at least 1 passes; below 1.1 it is marked tight.</p>"
        "<table><tr><th></th><th>id</th><th>check</th><th>value</th><th>limit</th>"
        f"<th>unit</th><th>margin</th><th>source</th></tr>{rows}</table>"
    )
    body["plots"] = "\n".join(_figure(p, i) for i, p in enumerate(plots, 1)) or (
        "<p>This report has no curves to plot.</p>"
    )
    body["decisions"] = "\n".join(
        f'<div class="decision" id="decision-{_e(d.id)}"><h3>{_e(d.id)} — {_e(d.title)}</h3>'
        f'<p class="what">{_e(d.decision)}</p><p>{_e(d.rationale)}</p>'
        f'<p class="src">Source: {_e(d.source)}</p>'
        + (f'<p class="src">Inputs: {_e(d.inputs)}</p>' if d.inputs else "")
        + "</div>"
        for d in s.decisions
    )
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
