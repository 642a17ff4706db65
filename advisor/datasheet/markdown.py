"""The datasheet as Markdown, for wikis: the HTML's sections without the plots."""

from advisor.datasheet.content import Block, Sheet, Table

MARK = {"fails": "✗ FAILS", "tight": "⚠ tight", "passes": "✓"}


def _esc(text: str) -> str:
    return str(text).replace("|", "\\|").replace("\n", " ")


def _table(columns: list[str], rows: list[list[str]]) -> list[str]:
    out = ["| " + " | ".join(_esc(c) for c in columns) + " |", "|" + "---|" * len(columns)]
    out += ["| " + " | ".join(_esc(c) for c in r) + " |" for r in rows]
    return [*out, ""]


def _block(b: Block, level: int) -> list[str]:
    out = [f"{'#' * level} {b.title}", ""]
    if b.rows:
        out += _table(["", "value", "unit"], [[k, v, u] for k, v, u in b.rows])
    for t in b.tables:
        out += _tables(t, level + 1)
    for p in b.parts:
        out += _block(p, level + 1)
    return out


def _tables(t: Table, level: int) -> list[str]:
    return [f"{'#' * level} {t.title}", "", *_table(t.columns, t.rows)]


def render(s: Sheet) -> str:
    out = [f"# {s.title}", "", f"Drive Advisor {s.version} — {s.application}, {s.status}", ""]
    out += ["## Summary", "", f"**{s.headline}**", ""]
    out += _table(["", ""], [[k, v] for k, v in s.summary])
    out += ["## Warnings", ""]
    out += [f"- {w}" for w in s.warnings] or ["None."]
    out += ["", "## Components", ""]
    for b in s.components:
        out += _block(b, 3)
    out += ["## Checks", ""]
    out += _table(
        ["", "check", "value", "limit", "unit", "margin", "source"],
        [
            [MARK[c.status], f"{c.id} {c.name}", c.value, c.limit, c.unit, c.margin, c.source]
            for c in s.checks
        ],
    )
    out += ["## Decisions", ""]
    for d in s.decisions:
        out += [f"### {d.id} — {d.title}", "", f"**{d.decision}**", "", d.rationale, ""]
        out += [f"*Source:* {d.source}", ""]
        if d.inputs:
            out += [f"*Inputs:* {d.inputs}", ""]
    out += ["## Requirements (SI)", ""]
    for b in s.requirements:
        out += _block(b, 3)
    out += ["## References", ""]
    out += [f"- {r}" for r in s.references] or ["None."]
    out += ["", "Plots: see the HTML datasheet (`--format html`).", ""]
    return "\n".join(out)
