"""What the wizard asks, step by step, for each application. Nothing is restated here: the
applications come from the registry, and each question (label, unit, help, step, default,
valid range, optional or not) from its field in the application's requirement model (see
:mod:`advisor.core.questions`). Pure data and functions; no textual here, so the tests can
use it cheaply."""

import math
import re
from functools import cache
from typing import Any

from advisor.core import registry
from advisor.core.questions import Question, fixed_values, wizard_questions

STEPS = ("Application", *registry.DEFAULT_STEPS, "Review")
#: The steps that ask the model's fields, and the review.
ASKED = tuple(range(1, len(STEPS) - 1))
REVIEW = len(STEPS) - 1


class Field(Question):
    """A question as the wizard shows it: a widget id and a dotted path."""

    __slots__ = ()

    @property
    def id(self) -> str:
        return "f-" + "-".join(self.path).replace("_", "-")

    @property
    def dotted(self) -> str:
        return ".".join(self.path)

    @property
    def shown_default(self) -> str:
        """What an empty box stands for: the model's default, or an example of a value."""
        if self.optional and self.default not in (None, [], ""):
            return f"default {to_text(self, self.default)}"
        if self.example is not None:
            return f"e.g. {self.example}"
        return ""


def titles() -> dict[str, str]:
    """The applications the wizard offers, kind → title, in registration order."""
    return {a.kind: a.title for a in registry.applications()}


def _by_step(qs: Any) -> dict[int, tuple[Field, ...]]:
    out: dict[int, list[Field]] = {}
    for q in qs:
        f = Field(*q)
        out.setdefault(f.step, []).append(f)
    return {step: tuple(fs) for step, fs in out.items()}


@cache
def _fields(model: Any) -> dict[int, tuple[Field, ...]]:
    return _by_step(wizard_questions(model))


@cache
def _compiled_fields(kind: str) -> dict[int, tuple[Field, ...]]:
    from advisor.core.requirement_spec import QUESTIONS

    return _by_step(QUESTIONS[kind])


def fields_for(kind: str, step: int) -> tuple[Field, ...]:
    from advisor.core.compiled_validator import compiled

    if compiled(kind):  # the shipped applications: their questions compiled, no pydantic
        return _compiled_fields(kind).get(step, ())
    return _fields(registry.requirements_model(kind)).get(step, ())


def steps_for(kind: str | None) -> list[tuple[int, str]]:
    """The steps the wizard walks for ``kind``: (step number, name), the application's own
    names for its asking steps, a step with no question skipped (no "nothing to set")."""
    if kind is None:
        return list(enumerate(STEPS))
    names = registry.application(kind).steps
    middle = [(s, names[s - 1]) for s in ASKED if fields_for(kind, s)]
    return [(0, STEPS[0]), *middle, (REVIEW, STEPS[REVIEW])]


def all_fields(kind: str) -> list[Field]:
    return [f for step in ASKED for f in fields_for(kind, step)]


def starting_doc(kind: str) -> dict[str, Any]:
    """A new requirement of ``kind``: the fields that allow one value only (the motor kind)
    filled in; everything else empty, so that the model's defaults apply."""
    doc: dict[str, Any] = {}
    for path, value in starting_doc_values(kind).items():
        put(doc, path, value)
    return doc


def starting_doc_values(kind: str) -> dict[tuple[str, ...], str]:
    """The fields that allow one value only, by path."""
    from advisor.core.compiled_validator import compiled

    if compiled(kind):
        from advisor.core.requirement_spec import FIXED

        return dict(FIXED[kind])
    return fixed_values(registry.requirements_model(kind))


@cache
def title_field() -> Field:
    """The report title, asked with the application (step 0; compiled with the models)."""
    from advisor.core.requirement_spec import TITLE

    return Field(*TITLE)


def row_note(kind: str, step: int) -> str:
    """A word on the rows of a list of tables asked in this step (candidate motors)."""
    rows = {f.row[:-1] for f in fields_for(kind, step) if f.row is not None}
    return " ".join(
        f"Rows of {'.'.join(r)} may stay empty; a row once started needs every value."
        for r in sorted(rows)
    )


# ------------------------------------------------------------------ the draft document
def get(doc: dict, path: tuple[str, ...]) -> Any:
    node: Any = doc
    for key in path:
        if isinstance(node, list):
            i = int(key)
            node = node[i] if i < len(node) else None
        elif isinstance(node, dict):
            node = node.get(key)
        else:
            return None
        if node is None:
            return None
    return node


def put(doc: dict, path: tuple[str, ...], value: Any) -> None:
    """Set (or, with None, remove) a value; lists of tables grow as needed."""
    node: Any = doc
    for i, key in enumerate(path[:-1]):
        nxt = path[i + 1]
        if isinstance(node, list):
            k = int(key)
            while len(node) <= k:
                node.append({})
            node = node[k]
            continue
        if key not in node or node[key] is None:
            if value is None:
                return
            node[key] = [] if nxt.isdigit() else {}
        node = node[key]
    last = path[-1]
    if isinstance(node, list):
        k = int(last)
        while len(node) <= k:
            node.append({})
        node[k] = value
    elif value is None:
        node.pop(last, None)
    else:
        node[last] = value


def prune(doc: Any) -> Any:
    """The draft without empty tables and without blank rows of arrays of tables."""
    if isinstance(doc, dict):
        out = {k: prune(v) for k, v in doc.items()}
        return {k: v for k, v in out.items() if v not in ({}, [], None)}
    if isinstance(doc, list):
        items = [prune(v) for v in doc]
        return [v for v in items if v not in ({}, None)]
    return doc


def to_text(field: Field, value: Any) -> str:
    if value is None:
        return ""
    if field.kind == "floats" and isinstance(value, list):
        # a quantity from a file ("3000 rpm") is shown as written, as it would be typed
        return ", ".join(_item_text(v) for v in value)
    if isinstance(value, float):
        return f"{value:g}"
    # text from a file is shown with its control and bidi characters escaped (\x1b): a box
    # that printed them raw would let a title clear or retitle the terminal
    from advisor.core.io_safety import printable

    return printable(str(value), newlines=False)


def _item_text(value: Any) -> str:
    if not isinstance(value, str):
        return f"{value:g}"
    from advisor.core.io_safety import printable

    text = printable(value, newlines=False)
    # quoted where a bare item would read otherwise: a comma or semicolon would split it, and
    # a number in quotes is text to a file ("3000", refused: a unit is missing)
    bare = text.strip(" \t")
    if not bare or any(c in text for c in ',;"') or _PLAIN.fullmatch(bare):
        return '"' + text.replace('"', '""') + '"'
    return text


#: A plain number as the grammar of :mod:`advisor.core.units` writes one: ASCII digits, no
#: ``_`` separators (``float`` would take ``1_000`` and full-width ``１６２０``, a file not).
_PLAIN = re.compile(r"[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?", re.ASCII)
_WHOLE = re.compile(r"[+-]?[0-9]+", re.ASCII)
#: One item of a list box: in double quotes, as a file writes a string (``"3,5 rpm"`` stays
#: one item; a quote inside is doubled), or bare up to the next comma or semicolon.
#: A whole number, a comma and a number with its unit, no space between: "3,5 rpm" typed in
#: a list is a decimal comma, not the items 3 and 5 rpm.
_DECIMAL_COMMA = re.compile(r"[+-]?[0-9]+,[0-9][^,;]*", re.ASCII)
_ITEM = re.compile(r'[ \t]*(?:"((?:[^"]|"")*)"[ \t]*|([^,;"][^,;]*)?)(?:[,;]|$)')


def _number(field: Field, text: str) -> float:
    """A number, or a quantity with a unit ("5 kN") in the field's unit, as a requirement
    file takes it (:mod:`advisor.core.units`: a strict grammar, so any text typed so far is
    a value or a :class:`~advisor.core.units.UnitError` worded for the user)."""
    if _PLAIN.fullmatch(text.strip(" \t")):
        return float(text)
    from advisor.core.units import to_unit

    return to_unit(text, field.unit)  # UnitError is a ValueError, worded for the user


def parse_text(field: Field, text: str) -> tuple[Any, str | None]:
    """The value of a field's text, or None with a message written for the user."""
    text = text.strip()
    if not text:
        # an empty row of a list of tables is no row; a started one the engine checks whole
        return None, None if field.optional or field.row is not None else "required"
    if field.kind == "str":
        return text, None
    if field.kind == "int":
        if _WHOLE.fullmatch(text):
            return int(text), None
        return None, f"{text!r} is not a whole number (digits 0-9 only)"
    if field.kind == "floats":
        return _parse_list(field, text)
    try:  # "1,5" is refused as a file refuses it: the grammar has no decimal comma
        value = _number(field, text)
    except ValueError as exc:
        return None, f"{text!r}: {exc}"
    if not math.isfinite(value):
        return None, "must be a finite number"
    return value, None


def kept_text(field: Field, text: str) -> Any:
    """A refused field's text as a draft keeps it, in the form a loaded file shows again in
    the field with the same message: text in a number's place, and a list's items each as
    typed (a plain number as a number, anything else as text; a list that cannot be split
    into items, its whole text as one item).

    >>> kept_text(Field(("t",), "T", kind="float"), "1,5")
    '1,5'
    >>> kept_text(Field(("s",), "S", kind="floats"), '5000, "3,5 rpm"')
    [5000.0, '3,5 rpm']
    """
    text = text.strip()
    if field.kind != "floats":
        return text
    items = list_items(text)
    if items is None:
        return [text]
    plain = [not quoted and _PLAIN.fullmatch(item) for item, quoted in items]
    return [
        float(item) if bare and math.isfinite(float(item)) else item
        for (item, _), bare in zip(items, plain, strict=True)
    ]


def quantity(field: Field, text: str) -> float:
    """A string of a file (``"3000 rpm"``) in the field's unit, as the batch reads it: a
    :class:`~advisor.core.units.UnitError` in the batch's words when it is no quantity."""
    from advisor.core.units import to_unit

    return to_unit(text, field.unit)


def list_items(text: str) -> list[tuple[str, bool]] | None:
    """The items of a list box's text, each with whether it was quoted; None when a quote
    is not closed or text follows a closing quote. A decimal comma before a unit, ``3,5 rpm``
    with no space, is one item (refused as a file refuses it), not 3 and 5 rpm.

    >>> list_items('3000 rpm; "3,5 rpm",, 5000, 3,5 rpm')
    [('3000 rpm', False), ('3,5 rpm', True), ('5000', False), ('3,5 rpm', False)]
    """
    items: list[tuple[str, bool]] = []
    pos, bare_from = 0, -1  # where the previous bare item begins (-1: it was not bare)
    while pos < len(text):
        m = _ITEM.match(text, pos)
        if m is None:
            return None
        quoted, bare = m.group(1), m.group(2)
        if quoted is not None:
            items.append((quoted.replace('""', '"'), True))
        elif bare is not None and bare.strip():
            joined = text[bare_from : m.start(2) + len(bare.rstrip())] if bare_from >= 0 else ""
            if _DECIMAL_COMMA.fullmatch(joined) and not _PLAIN.fullmatch(bare.strip()):
                items[-1] = (joined, False)
            else:
                items.append((bare.strip(), False))
            bare_from = m.start(2)
            pos = m.end()
            continue
        bare_from, pos = -1, m.end()
    return items


def _parse_list(field: Field, text: str) -> tuple[list[float] | None, str | None]:
    """A list box's numbers; a refused item named by its place, in the batch's words (a
    quoted item is a string of a file: a quantity with its unit, read by the grammar)."""
    items = list_items(text)
    if items is None:
        return None, (
            f"{text!r}: numbers separated by commas, e.g. 5000, 10000 (an item in quotes, "
            '"3000 rpm", ends at its closing quote)'
        )
    values = []
    for k, (item, quoted) in enumerate(items, start=1):
        try:
            values.append(quantity(field, item) if quoted else _number(field, item))
        except ValueError as exc:
            from advisor.core.io_safety import show_repr

            return None, f"item {k} = {show_repr(item)}: {exc}"
    if not values or not all(math.isfinite(v) for v in values):
        return None, "numbers separated by commas, each finite"
    return values, None


def error_step(dotted: str, kind: str) -> int | None:
    """The step that asks about a path: its field's step, else the first step asking a field
    of the same table (``gearbox.colour`` → the step asking ``gearbox.*``); None for none."""
    parts = tuple(dotted.split("."))
    asked = [(s, f.path) for s in ASKED for f in fields_for(kind, s)]
    for k in range(len(parts), 0, -1):
        steps = [s for s, path in asked if path[:k] == parts[:k]]
        if steps:
            return min(steps)
    return None


def error_owner(line: str, kind: str, upto_step: int) -> str | None:
    """Which field (dotted path) an engine message belongs to, '' for the step as a whole,
    None when it concerns a later step only."""
    head = line.split(" ", 1)[0].split(":", 1)[0].split("=", 1)[0]
    head = head.replace("[", ".").replace("]", "")
    # list items are numbered from 1 in messages, from 0 in paths
    parts = head.split(".")
    parts = [str(int(p) - 1) if p.isdigit() else p for p in parts]
    dotted = ".".join(parts)
    step = error_step(dotted, kind)
    if step is None:  # nothing asked about it: the first step with questions takes it
        step = next((s for s in ASKED if fields_for(kind, s)), 1)
    if step > upto_step:
        return None
    if any(f.dotted == dotted for f in fields_for(kind, step)):
        return dotted
    return ""
