"""``advisor diff A.toml B.toml``: what changed between two reports, in words and a table —
the requirement values, the components chosen, the decisions whose outcome changed, the
checks whose margin moved (both values), the warnings that came or went.

Exit codes as ``diff``'s: 0 the reports say the same, 1 they differ, 2 bad input (one line).
Pure functions of the reports' plain data (as read from their TOML), so the wizard's "what
changed since the previous result" can use the same code: :func:`changes_between`.
"""

import argparse
import math
import sys
from dataclasses import dataclass
from typing import Any

from advisor.core.errors import AdvisorError, ExitCode, InputError

#: A number that moved by less than this share of its size has not moved (the archive keeps
#: six significant digits; a margin at the fifth digit is noise).
REL_TOL = 5e-4


@dataclass(frozen=True)
class Change:
    what: str  # requirement | application | component | decision | check | warning | status
    item: str
    before: str
    after: str

    def words(self) -> str:
        head = f"{self.what} {self.item}" if self.item else self.what
        if not self.before:
            return f"{head}: new, {self.after}"
        if not self.after:
            return f"{head}: dropped (was {self.before})"
        return f"{head}: {self.before} → {self.after}"


def _flat(doc: Any, prefix: str = "") -> dict[str, Any]:
    if isinstance(doc, dict):
        out: dict[str, Any] = {}
        for k, v in doc.items():
            out.update(_flat(v, f"{prefix}.{k}" if prefix else str(k)))
        return out
    if isinstance(doc, list) and any(isinstance(v, dict) for v in doc):
        out = {}
        for i, v in enumerate(doc):
            out.update(_flat(v, f"{prefix}[{i + 1}]"))
        return out
    return {prefix: doc}


def _text(v: Any) -> str:
    from advisor.datasheet.content import number

    return "" if v is None else number(v)


def _moved(a: Any, b: Any) -> bool:
    if isinstance(a, int | float) and isinstance(b, int | float):
        if isinstance(a, bool) or isinstance(b, bool):
            return a != b
        return abs(a - b) > REL_TOL * max(abs(a), abs(b), 1e-12)
    return a != b


def _requirements(a: dict, b: dict) -> list[Change]:
    fa, fb = _flat(a.get("requirements", {})), _flat(b.get("requirements", {}))
    keys = [*fa, *(k for k in fb if k not in fa)]
    from advisor.datasheet.labels import split_key

    def said(v: Any, k: str) -> str:
        unit = split_key(k.rsplit(".", 1)[-1])[1]
        return "" if v is None else f"{_text(v)} {unit}".strip()

    return [
        Change("requirement", k, said(fa.get(k), k), said(fb.get(k), k))
        for k in keys
        if _moved(fa.get(k), fb.get(k))
    ]


def _components(a: dict, b: dict) -> list[Change]:
    from advisor.datasheet.review import parts

    def chosen(doc: dict) -> dict[str, str]:
        return {r[0]: ", ".join(x for x in (r[1], r[4]) if x) for r in parts(doc) if r[1] or r[4]}

    ca, cb = chosen(a), chosen(b)
    keys = [*ca, *(k for k in cb if k not in ca)]
    return [
        Change("component", k, ca.get(k, ""), cb.get(k, "")) for k in keys if ca.get(k) != cb.get(k)
    ]


def _decisions(a: dict, b: dict) -> list[Change]:
    da = {d["id"]: d["decision"] for d in a.get("decisions", [])}
    db = {d["id"]: d["decision"] for d in b.get("decisions", [])}
    keys = [*da, *(k for k in db if k not in da)]
    return [
        Change("decision", k, da.get(k, ""), db.get(k, "")) for k in keys if da.get(k) != db.get(k)
    ]


def _checks(a: dict, b: dict) -> list[Change]:
    def of(doc: dict) -> dict[str, dict]:
        return {c["id"]: c for c in doc.get("checks", [])}

    ca, cb = of(a), of(b)

    def said(c: dict | None) -> str:
        from advisor.core.report import margin_text

        if c is None:
            return ""
        shown = f"{_text(c['value'])} against {_text(c['limit'])} {c['unit']}".strip()
        return f"margin {margin_text(c['margin'])} ({shown})"

    out = []
    for k in [*ca, *(k for k in cb if k not in ca)]:
        x, y = ca.get(k), cb.get(k)
        if x is None or y is None or _moved(x["margin"], y["margin"]):
            out.append(Change("check", k, said(x), said(y)))
    return out


def _warnings(a: dict, b: dict) -> list[Change]:
    wa, wb = a.get("warnings", []), b.get("warnings", [])
    return [Change("warning", "", w, "") for w in wa if w not in wb] + [
        Change("warning", "", "", w) for w in wb if w not in wa
    ]


def differences(a: dict, b: dict) -> list[Change]:
    """Every change from report ``a`` to report ``b`` (plain data, as read from TOML)."""
    out: list[Change] = []
    ha, hb = a.get("report", {}), b.get("report", {})
    if ha.get("application") != hb.get("application"):
        out.append(
            Change("application", "", str(ha.get("application")), str(hb.get("application")))
        )
    if ha.get("status") != hb.get("status"):
        out.append(Change("status", "", str(ha.get("status")), str(hb.get("status"))))
    for part in (_requirements, _components, _decisions, _checks, _warnings):
        out += part(a, b)
    return out


def words(changes: list[Change]) -> list[str]:
    """The changes in words, one a line; a warning names itself."""
    out = []
    for c in changes:
        if c.what == "warning":
            out.append(f"new warning: {c.after}" if c.after else f"warning gone: {c.before}")
        else:
            out.append(c.words())
    return out


def changes_between(before: Any, after: Any) -> list[str]:
    """What changed between two results (Report objects), in words: what the wizard shows as
    "changed since the previous result" (the same lines as ``advisor diff``)."""
    from advisor.core.report import plain

    return words(differences(plain(before), plain(after)))


# ------------------------------------------------------------------------------ faces
COLUMNS = ("what", "item", "before", "after")


def as_text(changes: list[Change], a: str, b: str) -> str:
    if not changes:
        from advisor.core.io_safety import printable

        return printable(f"{a} and {b}: the same", newlines=False) + "\n"
    from advisor.core.io_safety import printable

    lines = [f"{a} → {b}: {len(changes)} changes", *(f"  {w}" for w in words(changes))]
    # report strings are data: an ESC or a bidi override is shown escaped, never obeyed
    return "\n".join(printable(x, newlines=False) for x in lines) + "\n"


def as_markdown(changes: list[Change], a: str, b: str) -> str:
    from advisor.datasheet.markdown import text

    out = [f"# Changes: {text(a)} → {text(b)}", ""]
    if not changes:
        return "\n".join([*out, "The reports say the same.", ""])
    out += [f"{len(changes)} changes.", ""]
    out += [f"- {text(w)}" for w in words(changes)] + [""]
    out += ["| " + " | ".join(COLUMNS) + " |", "|" + "---|" * len(COLUMNS)]
    out += [
        "| " + " | ".join(text(x).strip() for x in (c.what, c.item, c.before, c.after)) + " |"
        for c in changes
    ]
    return "\n".join([*out, ""])


def _html(x: str) -> str:
    """User text in HTML: control characters shown escaped (``\\x1b``; NUL is not allowed
    in HTML at all), then the markup characters escaped."""
    from html import escape

    from advisor.core.io_safety import printable

    return escape(printable(x, newlines=False))


#: The page's style sheet (a plain string: braces are CSS, not format fields).
CSS = (
    "body { font-family: sans-serif; max-width: 60rem; margin: 2rem auto; } "
    "td, th { border-bottom: 1px solid #ddd; padding: 0.2rem 0.5rem; text-align: left; "
    "vertical-align: top; } table { border-collapse: collapse; }"
)


def as_html(changes: list[Change], a: str, b: str) -> str:
    rows = "".join(
        "<tr>"
        + "".join(f"<td>{_html(x)}</td>" for x in (c.what, c.item, c.before, c.after))
        + "</tr>"
        for c in changes
    )
    items = "".join(f"<li>{_html(w)}</li>" for w in words(changes))
    head = "".join(f"<th>{x}</th>" for x in COLUMNS)
    body = (
        f"<p>{len(changes)} changes.</p><ul>{items}</ul><table><tr>{head}</tr>{rows}</table>"
        if changes
        else "<p>The reports say the same.</p>"
    )
    title = _html(f"Changes: {a} → {b}")
    return (
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
        f"<title>{title}</title><style>{CSS}</style></head><body><h1>{title}</h1>{body}"
        "</body></html>\n"
    )


def _kind(v: Any) -> str:
    if isinstance(v, bool):
        return "a boolean"
    if isinstance(v, int | float):
        return "a number"
    if isinstance(v, str):
        return "text"
    if isinstance(v, dict):
        return "a table"
    if isinstance(v, list):
        return "an array"
    return type(v).__name__  # a TOML date or time


def _is_number(v: Any) -> bool:
    return isinstance(v, int | float) and not isinstance(v, bool)


def _is_value(v: Any) -> bool:
    """A check's value or limit: a number, a flag or a word (what :func:`_text` shows)."""
    return isinstance(v, int | float | str)


#: What each array of tables diff reads must hold: key → (test, what it must be, required).
_ITEMS: dict[str, dict[str, tuple[Any, str, bool]]] = {
    "decisions": {
        "id": (lambda v: isinstance(v, str), "text", True),
        "decision": (lambda v: isinstance(v, str), "text", True),
    },
    "checks": {
        "id": (lambda v: isinstance(v, str), "text", True),
        "margin": (_is_number, "a number", True),
        "value": (_is_value, "a number or text", True),
        "limit": (_is_value, "a number or text", True),
        "unit": (lambda v: isinstance(v, str), "text", True),
    },
}


def _where(path: str, key: Any, in_list: bool) -> str:
    if in_list:
        return f"{path}[{key}]"
    return f"{path}.{key}" if path else str(key)


def non_finite(doc: Any, path: str = "") -> str | None:
    """The first number of ``doc`` that is nan or ±inf, as "key = value" (None if none).

    A report never holds nan or inf (docs/reference/report.md), and a comparison with one
    is never true: |nan − x| > tol is false, so such a file would read as "the same"."""
    if isinstance(doc, float) and not math.isfinite(doc):
        return f"{path} = {doc}"
    if not isinstance(doc, dict | list):
        return None
    items = doc.items() if isinstance(doc, dict) else enumerate(doc)
    for key, v in items:
        found = non_finite(v, _where(path, key, isinstance(doc, list)))
        if found is not None:
            return found
    return None


def shape_problem(doc: dict[str, Any]) -> str | None:
    """What makes ``doc`` not a report diff can read (None if nothing): the tables and arrays
    it reads, with their types, and no nan or inf anywhere, so a hand-edited or foreign file
    is refused in one line instead of failing half-way through the comparison or comparing
    as unchanged."""
    head = doc.get("report")
    if not isinstance(head, dict):
        return "[report] must be a table" if "report" in doc else "no [report] table"
    for key in ("application", "status"):
        if key not in head:
            return f"report.{key} is missing"
        if not isinstance(head[key], str):
            return f"report.{key} must be text, not {_kind(head[key])}"
    for key in ("requirements", "design"):
        if key in doc and not isinstance(doc[key], dict):
            return f"{key} must be a table, not {_kind(doc[key])}"
    for key, fields in _ITEMS.items():
        items = doc.get(key, [])
        if not isinstance(items, list):
            return f"{key} must be an array of tables, not {_kind(items)}"
        for i, item in enumerate(items):
            if not isinstance(item, dict):
                return f"{key}[{i}] must be a table, not {_kind(item)}"
            for name, (test, what, required) in fields.items():
                if name not in item:
                    if required:
                        return f"{key}[{i}].{name} is missing"
                elif not test(item[name]):
                    return f"{key}[{i}].{name} must be {what}, not {_kind(item[name])}"
    warnings = doc.get("warnings", [])
    if not isinstance(warnings, list):
        return f"warnings must be an array of text, not {_kind(warnings)}"
    for i, w in enumerate(warnings):
        if not isinstance(w, str):
            return f"warnings[{i}] must be text, not {_kind(w)}"
    found = non_finite(doc)
    if found is not None:
        return f"{found}: a report's numbers are finite (never nan or inf)"
    return None


def read_report(path: Any) -> dict:
    """A report file as plain data; an InputError (exit 2) for a file that is none."""
    from advisor.core.io_safety import read_toml, show

    doc = read_toml(path, wanted="a report file (written by advisor --batch -o)")
    head = doc.get("report")
    if not isinstance(head, dict) or "application" not in head:
        raise InputError(
            f"{show(str(path), 200)}: not a Drive Advisor report (no [report] table with "
            "application); give two reports written by advisor --batch -o"
        )
    problem = shape_problem(doc)
    if problem is not None:
        raise InputError(f"{show(str(path), 200)}: not a report of the advisor: {problem}")
    return doc


def main(argv: list[str]) -> int:
    p = argparse.ArgumentParser(
        prog="advisor diff",
        description="What changed between two reports. Exit 0 the same, 1 different, 2 bad input.",
    )
    p.add_argument("a", metavar="A.toml")
    p.add_argument("b", metavar="B.toml")
    p.add_argument("--format", choices=("text", "md", "html"), default="text")
    try:
        args = p.parse_args(argv)
    except SystemExit as exc:
        return int(exc.code or 0)
    try:
        a, b = read_report(args.a), read_report(args.b)
    except AdvisorError as exc:
        from advisor.core.io_safety import print_error

        print_error(str(exc).splitlines()[0] if str(exc) else "bad input")
        return ExitCode.INVALID_INPUT
    changes = differences(a, b)
    face = {"text": as_text, "md": as_markdown, "html": as_html}[args.format]
    sys.stdout.write(face(changes, args.a, args.b))
    return 1 if changes else ExitCode.OK
