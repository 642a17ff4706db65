"""`advisor rules`: the rule table — every rule's id, title, what it decides and its sources —
printed from the registry of rules (:data:`advisor.core.rulebook.REGISTRY`), as a linter
lists its messages. ``--markdown`` writes the table that ``docs/reference/rules.md`` holds
(``python -m advisor.core.rules_table`` rewrites that file; a test keeps it current)."""

import argparse
import sys
from pathlib import Path
from typing import NamedTuple

DOC = Path(__file__).resolve().parents[2] / "docs" / "reference" / "rules.md"


class RuleRow(NamedTuple):
    id: str
    title: str
    decides: str  # the first line of the rule function's docstring, or its title
    sources: str  # bibliography ids, with the place cited where the rule names one


def rows() -> list[RuleRow]:
    """Every registered rule, every rule module loaded, in the order of their ids."""
    import rules

    registry = rules.load_all()
    out = []
    for rid in sorted(registry, key=_order):
        r = registry[rid]
        doc = " ".join((r.fn.__doc__ or "").strip().split("\n\n")[0].split())
        # a docstring that opens on the arguments ("rows: …", "``x``: …") says how, not what
        says_what = doc[:1].isupper() and ":" not in doc.split(" ", 1)[0]
        decides = doc if says_what else r.title
        sources = "; ".join(bib + (f", {where}" if where else "") for bib, where in r.source.refs)
        out.append(RuleRow(rid, r.title, decides, sources))
    return out


def _order(rid: str) -> tuple[str, int]:
    prefix, _, number = rid.partition("-")
    return prefix, int(number) if number.isdigit() else 0


def as_text(table: list[RuleRow]) -> str:
    width = max(len(r.id) for r in table)
    lines = [f"{r.id:<{width}}  {r.title}  [{r.sources}]" for r in table]
    return "\n".join([*lines, f"{len(table)} rules"]) + "\n"


def _cell(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def as_markdown(table: list[RuleRow]) -> str:
    head = [
        "# Rules",
        "",
        "Every rule the advisor applies, printed by `advisor rules --markdown` from the registry",
        "of rules (regenerate with `python -m advisor.core.rules_table`). Each decision of a",
        "report names its rule id; the sources are ids of the bibliography",
        "(`catalogs/bibliography.toml`).",
        "",
        "| id | title | what it decides | sources |",
        "|---|---|---|---|",
    ]
    body = [
        f"| {r.id} | {_cell(r.title)} | {_cell(r.decides)} | {_cell(r.sources)} |" for r in table
    ]
    return "\n".join([*head, *body, ""])


def main(argv: list[str]) -> int:
    p = argparse.ArgumentParser(prog="advisor rules", description=__doc__.split("\n\n")[0])
    p.add_argument("--markdown", action="store_true", help="the table as Markdown")
    try:
        args = p.parse_args(argv)
    except SystemExit as exc:
        return int(exc.code or 0)
    table = rows()
    sys.stdout.write(as_markdown(table) if args.markdown else as_text(table))
    return 0


if __name__ == "__main__":  # rewrite docs/reference/rules.md
    DOC.write_text(as_markdown(rows()), encoding="utf-8")
