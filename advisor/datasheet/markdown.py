"""The datasheet as Markdown, for wikis: the HTML's sections without the plots.

Every text that goes in is escaped, ours and the user's alike (a title, a motor model of a
user catalog, a candidate's name are the user's), as the HTML datasheet escapes its text:
a title must not become a heading, a link, an image or raw HTML in somebody's wiki. The
rules are CommonMark's (https://spec.commonmark.org/0.31.2/) and GitHub's table extension:

- a backslash before ASCII punctuation makes it literal (§2.4): ``\\ ` * _ [ ] # | ~ $``
  are escaped wherever they stand, and ``(`` after ``]`` (a ``](`` would open a link
  destination); with ``[`` escaped no link or image can open (``![img](…)``);
- ``<``, ``>`` and ``&`` are written as entity references (§2.5): no raw HTML (§4.6, §6.6)
  and no autolink ``<javascript:…>`` can form, and ``\\<`` would still read as ``<script``;
- a line break would start a new block (a heading, a list, a quote): line breaks and tabs
  become spaces; other control characters and bidirectional overrides are shown escaped
  (``\\x1b``), as the terminal shows them;
- text that begins a block (a list item, a paragraph) has a leading ``-``, ``+``, ``=`` or
  ``1.`` escaped (a list, a thematic break, a setext underline) and no leading spaces (an
  indented code block, §4.4);
- in a table cell ``|`` is escaped (GFM tables, example 200).
"""

import re

from advisor.datasheet.content import (
    Block,
    Probability,
    Sheet,
    Table,
    no_checks,
    nothing_to_show,
)

MARK = {
    "fails": "✗ FAILS",
    "tight": "⚠ tight",
    "passes": "✓",
    "none": "no check",
    "unreached": "not reached",
}

#: Characters of a utilisation bar: ten cells, each a tenth of the capacity.
BAR_CELLS = 10

#: Headings stop at level 6 (CommonMark §4.2: ``#######`` is a paragraph), as in the HTML.
DEEPEST = 6

#: Characters that start or end Markdown syntax anywhere in a line (CommonMark §6, GFM
#: strikethrough ``~``, table ``|``, and ``$`` of the math wikis render).
_SPECIAL = re.compile(r"([\\`*_\[\]#|~$])")
#: Characters that break a line (``str.splitlines``' set) and the tab (indentation).
_BREAKS = re.compile("[\n\r\t\v\f\x1c\x1d\x1e\x85\u2028\u2029]")
_LEADING = re.compile(r"^([-+=]|\d{1,9}(?=[.)]))")


def text(value: object) -> str:
    r"""User or report text as literal Markdown inline text, on one line.

    >>> text("# Title\n![img](http://x/y.png) <iframe src=x> a_b | c & d")
    '\\# Title !\\[img\\]\\(http://x/y.png) &lt;iframe src=x&gt; a\\_b \\| c &amp; d'
    """
    from advisor.core.io_safety import printable

    s = _BREAKS.sub(" ", str(value))
    s = printable(s, newlines=False)  # the controls left (ESC, NUL…) shown as \x1b, bidi too
    s = s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
    s = _SPECIAL.sub(r"\\\1", s)
    return s.replace("\\](", "\\]\\(")


def lead(value: object) -> str:
    r"""Text that begins a block (a paragraph, a list item): also no list, thematic break,
    setext underline or indented code at its start.

    >>> lead("  - item"), lead("1. first"), lead("=== x"), lead("2024 was")
    ('\\- item', '1\\. first', '\\=== x', '2024 was')
    """
    s = text(value).lstrip(" ")
    m = _LEADING.match(s)
    if m is None:
        return s
    if m.group().isdigit():
        return f"{m.group()}\\{s[m.end() :]}"
    return f"\\{s}"


def strong(value: object) -> str:
    """Bold text; nothing for empty text (``****`` alone is a thematic break)."""
    s = text(value).strip()
    return f"**{s}**" if s else ""


def _cell(value: object) -> str:
    return text(value).strip()


def _heading(level: int, title: object) -> str:
    return f"{'#' * min(level, DEEPEST)} {lead(title).strip()}"


def _table(columns: list[str], rows: list[list[str]]) -> list[str]:
    out = ["| " + " | ".join(_cell(c) for c in columns) + " |", "|" + "---|" * len(columns)]
    out += ["| " + " | ".join(_cell(c) for c in r) + " |" for r in rows]
    return [*out, ""]


def _block(b: Block, level: int) -> list[str]:
    out = [_heading(level, b.title), ""]
    if b.rows:
        out += _table(["", "value", "unit"], [[k, v, u] for k, v, u in b.rows])
    for t in b.tables:
        out += _tables(t, level + 1)
    for p in b.parts:
        out += _block(p, level + 1)
    return out


def _tables(t: Table, level: int) -> list[str]:
    return [_heading(level, t.title), "", *_table(t.columns, t.rows)]


def _items(lines: list[str]) -> list[str]:
    return [f"- {lead(w)}" for w in lines] or ["None."]


def bar(utilisation: float) -> str:
    """A utilisation as ten cells, full ones for each tenth of the capacity used.

    >>> bar(0.54), bar(1.3)
    ('█████░░░░░', '██████████')
    """
    full = round(min(max(utilisation, 0.0), 1.0) * BAR_CELLS)
    return "█" * full + "░" * (BAR_CELLS - full)


def _review(s: Sheet) -> list[str]:
    """The first page: what a review reads and signs."""
    out = ["## Required and achieved", ""]
    out += _table(
        ["requirement", "required", "covered by", "achieved (value against limit)", "margin", ""],
        [
            [
                r.label,
                f"{r.value} {r.unit}".strip(),
                r.check + (f" (and {r.more} more)" if r.more else ""),
                r.achieved,
                r.margin,
                MARK[r.status],
            ]
            for r in s.required
        ],
    )
    if s.at_default:
        out += [
            f"{s.at_default} further requirements are at their defaults; the Requirements "
            "section lists every value.",
            "",
        ]
    out += ["## Utilisation", ""]
    if s.bars:
        out += ["Demand over capacity of each check (1 / margin).", ""]
        out += _table(
            ["check", "utilisation", "", ""],
            [
                [b.name, bar(b.utilisation), f"{b.utilisation * 100:.0f} %", MARK[b.status]]
                for b in s.bars
            ],
        )
    else:
        out += [no_checks(s.status), ""]
    out += ["## Load cycle", ""]
    if s.cycle is None:
        out += [r"This design has no duty cycle: its requirement has no \[duty\] table.", ""]
    else:
        out += _table(s.cycle.columns, s.cycle.rows)
        out += [lead(s.cycle.note), ""]
    out += ["## Parts", ""]
    out += (
        _table(["component", "designation", "rating", "dimensions", "mass", "source"], s.parts)
        if s.parts
        else ["No parts: this design names no component.", ""]
    )
    return out


def _probability(p: Probability | None, absent: str) -> list[str]:
    """P(pass) of the design and of each check, and the tornado charts' data as tables: each
    input's ρ with a bar of ten cells either side of zero (``absent``: what to say where
    there is none)."""
    out = ["## Probability of passing", ""]
    if p is None:
        return [*out, absent.replace("[", r"\[").replace("]", r"\]"), ""]
    out += [lead(p.statement), ""]
    out += _tables(p.inputs, 3)
    out += _tables(p.checks, 3)
    for n in p.notes:
        out += [lead(n), ""]
    for t in p.tornadoes:
        out += [_heading(3, f"Tornado chart: drivers of {t.check_name}"), ""]
        out += [lead(t.probability), ""]
        out += _table(
            ["input", "ρ", "−1 … 0 … +1"],
            [[b.label, f"{b.rho:+.2f}", tornado_bar(b.rho)] for b in t.bars],
        )
    return out


def tornado_bar(rho: float) -> str:
    """A rank correlation as a bar of ten cells either side of zero.

    >>> tornado_bar(-0.87)
    '░█████████│░░░░░░░░░░'
    >>> tornado_bar(0.46)
    '░░░░░░░░░░│█████░░░░░'
    """
    cells = round(min(abs(rho), 1.0) * BAR_CELLS)
    left = "░" * (BAR_CELLS - cells) + "█" * cells if rho < 0 else "░" * BAR_CELLS
    right = "█" * cells + "░" * (BAR_CELLS - cells) if rho > 0 else "░" * BAR_CELLS
    return f"{left}│{right}"


def _checks(s: Sheet) -> list[str]:
    """The checks' table, or one line where there is none (no bare header)."""
    if not s.checks:
        return [no_checks(s.status), ""]
    return _table(
        ["", "check", "value", "limit", "unit", "margin", "source"],
        [
            [MARK[c.status], f"{c.id} {c.name}", c.value, c.limit, c.unit, c.margin, c.source]
            for c in s.checks
        ],
    )


def render(s: Sheet) -> str:
    out = [_heading(1, s.title), ""]
    out += [f"Drive Advisor {text(s.version)} — {text(s.application)}, {text(s.status)}", ""]
    out += ["## Document", ""]
    out += _table(["", ""], [[k, v] for k, v in s.project])
    out += ["## Summary", "", strong(s.headline), ""]
    out += _table(["", ""], [[k, v] for k, v in s.summary])
    out += _review(s)
    out += ["## Warnings", "", *_items(s.warnings)]
    out += ["", "## Components", ""]
    for b in s.components:
        out += _block(b, 3)
    if not s.components:
        out += [nothing_to_show("component", s.status), ""]
    out += ["## Checks", ""]
    out += _checks(s)
    out += _probability(s.probability, s.no_probability)
    out += ["## Decisions", ""]
    for d in s.decisions:
        out += [f"{_heading(3, d.id)} — {text(d.title).strip()}", ""]
        out += [strong(d.decision), "", lead(d.rationale), ""]
        out += [f"*Source:* {text(d.source)}", ""]
        if d.inputs:
            out += [f"*Inputs:* {text(d.inputs)}", ""]
    if not s.decisions:
        out += [nothing_to_show("decision", s.status), ""]
    out += ["## Requirements (SI)", ""]
    for b in s.requirements:
        out += _block(b, 3)
    out += ["## References", "", *_items(s.references)]
    out += ["", "Plots: see the HTML datasheet (`--format html`).", ""]
    return "\n".join(out)
