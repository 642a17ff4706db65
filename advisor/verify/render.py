"""The verification report: plain text for the terminal, self-contained HTML for the file an
auditor keeps. Both say the same things: one line per quantity (published, computed,
relative deviation, tolerance, verdict, source), then the departures with their reasons,
the notes, and the cases whose published numbers could not be checked against the source's
own text."""

import html
import math
from typing import Any

from advisor.verify.runner import Case, Outcome, Quantity

#: The columns of the quantity table.
COLUMNS = (
    "case",
    "quantity",
    "published",
    "computed",
    "deviation",
    "tolerance",
    "verdict",
    "source",
)


def _num(x: Any) -> str:
    if x is None:
        return "—"
    if isinstance(x, bool) or isinstance(x, str):
        return str(x)
    if isinstance(x, int | float):
        if not math.isfinite(x):
            return str(x)
        return f"{x:.6g}"
    return str(x)


def _with_unit(x: Any, unit: str) -> str:
    text = _num(x)
    return f"{text} {unit}" if unit and x is not None else text


def tolerance_text(q: Quantity) -> str:
    if isinstance(q.published, str):
        return "exact text"
    parts = []
    if q.tolerance:
        parts.append(f"±{q.tolerance * 100:.3g} %")
    if q.abs_tolerance:
        parts.append(f"±{_num(q.abs_tolerance)} {q.unit}".rstrip())
    bound = {"<=": "at most ", ">=": "at least "}.get(q.relation, "")
    if not parts:
        return f"{bound}the value" if bound else "exact"
    return bound + " or ".join(parts)


def deviation_text(o: Outcome) -> str:
    return "—" if o.deviation is None else f"{o.deviation * 100:+.3g} %"


def source_text(case: Case, short: dict[str, str]) -> str:
    return f"{short.get(case.source, case.source)}, {case.where}"


def rows(outcomes: list[Outcome], short: dict[str, str]) -> list[tuple[str, ...]]:
    """The quantity table, one row per quantity, in :data:`COLUMNS` order."""
    out = []
    for o in outcomes:
        q = o.quantity
        published = ("≤ " if q.relation == "<=" else "≥ " if q.relation == ">=" else "") + (
            _with_unit(q.published, q.unit)
        )
        computed = _with_unit(o.computed, q.unit) if o.verdict != "ERROR" else o.error
        out.append(
            (
                o.case.id,
                q.name,
                published,
                computed,
                deviation_text(o),
                tolerance_text(q),
                o.verdict,
                source_text(o.case, short),
            )
        )
    return out


def departures(outcomes: list[Outcome]) -> list[Outcome]:
    return [o for o in outcomes if o.verdict == "departure"]


def notes(outcomes: list[Outcome]) -> list[Outcome]:
    return [o for o in outcomes if o.quantity.note]


def unconfirmed(outcomes: list[Outcome]) -> list[Case]:
    """Cases whose published numbers were not checked against the source's own text."""
    seen: dict[str, Case] = {}
    for o in outcomes:
        if o.case.checked.upper().startswith("NOT"):
            seen.setdefault(o.case.id, o.case)
    return list(seen.values())


def summary(outcomes: list[Outcome]) -> str:
    count = {v: sum(o.verdict == v for o in outcomes) for v in ("pass", "departure")}
    bad = [o for o in outcomes if not o.ok]
    cases = len({o.case.id for o in outcomes})
    head = (
        f"{len(outcomes)} quantities of {cases} cases: {count['pass']} within tolerance, "
        f"{count['departure']} stated departures"
    )
    if bad:
        return f"{head}, {len(bad)} NOT VERIFIED"
    return f"{head}: verified"


def _table(header: tuple[str, ...], body: list[tuple[str, ...]]) -> list[str]:
    widths = [max(len(r[i]) for r in (header, *body)) for i in range(len(header))]
    # the source column is last and free: no padding, the line ends where its text ends
    fmt = "  ".join(f"{{:<{w}}}" for w in widths[:-1]) + "  {}"
    return [fmt.format(*r).rstrip() for r in (header, *body)]


def text_report(outcomes: list[Outcome], short: dict[str, str]) -> str:
    """The terminal report."""
    lines = ["Verification of the Drive Advisor against published examples", ""]
    lines += _table(COLUMNS, rows(outcomes, short))
    dep = departures(outcomes)
    if dep:
        lines += ["", "Departures (the advisor computes otherwise on purpose):"]
        for o in dep:
            d = o.quantity.departure
            assert d is not None
            where = f" [see {d.doc}]" if d.doc else ""
            lines.append(
                f"- {o.case.id} / {o.quantity.name}: published {_num(o.quantity.published)}, "
                f"the advisor {_num(o.computed)} (stated {_num(d.expected)}): {d.reason}{where}"
            )
    for o in notes(outcomes):
        lines.append(f"- note, {o.case.id} / {o.quantity.name}: {o.quantity.note}")
    gaps = unconfirmed(outcomes)
    if gaps:
        lines += ["", "Published values not checked against the source's own text:"]
        lines += [f"- {c.id}: {c.checked}" for c in gaps]
    lines += ["", summary(outcomes)]
    return "\n".join(lines) + "\n"


_CSS = """
body{font-family:sans-serif;margin:2em;color:#222}
table{border-collapse:collapse;font-size:0.9em}
th,td{border:1px solid #bbb;padding:0.25em 0.5em;text-align:left;vertical-align:top}
th{background:#eee} td.num{text-align:right;white-space:nowrap}
.pass{background:#e6f4e6} .departure{background:#fff4d6}
.FAIL,.ERROR{background:#f8d7d7;font-weight:bold}
"""


def html_report(outcomes: list[Outcome], short: dict[str, str], cases: list[Case]) -> str:
    """A self-contained HTML document (no script, no external file); every text escaped."""
    e = html.escape
    out = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8">',
        "<title>Drive Advisor — verification report</title>",
        f"<style>{_CSS}</style></head><body>",
        "<h1>Drive Advisor — verification report</h1>",
        f"<p><strong>{e(summary(outcomes))}</strong></p>",
        "<p>Every quantity below is a number printed in the source named beside it, computed "
        "again by the advisor's own calculation functions (or by the whole advisor from the "
        "example's requirement). A stated departure is the advisor computing otherwise on "
        "purpose; it is verified against the value the departure states.</p>",
        "<h2>Quantities</h2>",
        "<table><tr>" + "".join(f"<th>{e(c)}</th>" for c in COLUMNS) + "</tr>",
    ]
    numeric = {2, 3, 4}
    for o, r in zip(outcomes, rows(outcomes, short), strict=True):
        cells = []
        for i, cell in enumerate(r):
            cls = ' class="num"' if i in numeric else ""
            if COLUMNS[i] == "verdict":
                cls = f' class="{e(o.verdict)}"'
            cells.append(f"<td{cls}>{e(cell)}</td>")
        out.append("<tr>" + "".join(cells) + "</tr>")
    out.append("</table>")
    dep = departures(outcomes)
    if dep:
        out.append("<h2>Departures</h2><ul>")
        for o in dep:
            d = o.quantity.departure
            assert d is not None
            doc = f" (see {e(d.doc)})" if d.doc else ""
            out.append(
                f"<li><strong>{e(o.case.id)}</strong>, {e(o.quantity.name)}: published "
                f"{e(_num(o.quantity.published))}, the advisor {e(_num(o.computed))}: "
                f"{e(d.reason)}{doc}</li>"
            )
        out.append("</ul>")
    n = notes(outcomes)
    if n:
        out.append("<h2>Notes</h2><ul>")
        out += [f"<li>{e(o.case.id)}: {e(o.quantity.note)}</li>" for o in n]
        out.append("</ul>")
    out.append("<h2>Cases and how their numbers were checked</h2><table>")
    out.append("<tr><th>case</th><th>title</th><th>source</th><th>checked</th></tr>")
    ran = {o.case.id for o in outcomes}
    for c in cases:
        if c.id in ran:
            out.append(
                f"<tr><td>{e(c.id)}</td><td>{e(c.title)}</td>"
                f"<td>{e(source_text(c, short))}</td><td>{e(c.checked)}</td></tr>"
            )
    out.append("</table></body></html>")
    return "\n".join(out) + "\n"
