"""The cells of designs.csv: its columns, and how a value is written into a cell and read
back (text a spreadsheet would evaluate is neutralised, and given back exactly)."""

import json
from typing import Any

from advisor.core.io_safety import printable
from advisor.family.outputs import COLUMNS
from advisor.family.spec import Family

HEAD = ("variant", "member", "application")
TAIL = ("status", "exit_code", "reason")


def columns(family: Family) -> list[str]:
    """The header of designs.csv: variant, member, application, axes, status, outputs."""
    return [*HEAD, *(cell(k) for k in family.axis_keys()), *TAIL, *COLUMNS]


#: A text cell starting with one of these is read as a formula by spreadsheets (OWASP,
#: "CSV Injection": = + - @, tab and carriage return).
FORMULA_START = ("=", "+", "-", "@", "\t", "\r")


def neutral(text: str) -> str:
    """Text as a spreadsheet shows it but never evaluates it: a cell that would start a
    formula gets a leading single quote (OWASP CSV injection guidance). Text that already
    starts with quotes before such a character gets one more, so :func:`uncell` gives every
    text back exactly.

    >>> neutral("=1+1"), neutral("@SUM(A1)"), neutral("-x"), neutral("bldc 3000 rpm")
    ("'=1+1", "'@SUM(A1)", "'-x", 'bldc 3000 rpm')
    """
    return "'" + text if text.lstrip("'").startswith(FORMULA_START) else text


def uncell(text: str) -> str:
    """The text of a cell written by :func:`cell` (the neutralising quote removed).

    >>> uncell("'=1+1"), uncell("''=x"), uncell("'quoted"), uncell("-5")
    ('=1+1', "'=x", "'quoted", '-5')
    """
    if text.startswith("'") and text.lstrip("'").startswith(FORMULA_START):
        return text[1:]
    return text


def cell(value: Any) -> str:
    """A CSV cell: blank for none, numbers as Python writes them (``-5`` stays a number),
    lists as JSON, text neutralised against spreadsheet formulas (:func:`neutral`)."""
    kind = type(value)
    if kind is str:  # the common cases first: a cell per column of every variant
        return neutral(printable(value, newlines=False))
    if kind is float or kind is int:
        return str(value)
    if value is None:
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int | float):
        return str(value)
    if isinstance(value, list | dict):
        return neutral(json.dumps(value))
    # a control character (a member named "a\x1b[2Jb") is written escaped: raw, it would
    # reach a terminal that shows the CSV, or end a row in a reader that splits lines
    return neutral(printable(str(value), newlines=False))
