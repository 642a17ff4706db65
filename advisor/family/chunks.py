"""One task of a family study: advise a block of variants in one process.

:func:`run_chunk` is what a Dask worker runs; it takes the family (small: bases and axes)
and a range of variant numbers, builds each variant itself, and returns the CSV rows (and,
when asked, the report texts). The scheduler never sees a task per variant.
"""

import csv
import io
import json
import time
from typing import Any, NamedTuple

from advisor.core.io_safety import printable
from advisor.family.adapter import advise_one
from advisor.family.outputs import COLUMNS, key_outputs
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


def report_name(index: int) -> str:
    return f"v{index:07d}.report.toml"


class ChunkResult(NamedTuple):
    number: int
    rows: list[list[str]]
    reports: list[tuple[str, str]]  # (file name, report TOML) when asked for
    seconds: float  # time spent advising, for the cost model


class MemberCells(NamedTuple):
    """A member's cells that every one of its rows repeats, written once per chunk."""

    head: tuple[str, str]  # its name and application
    #: per axis key of the family: this member's axis number and its values as cells
    #: (None: not an axis of this member, a blank cell)
    axes: list[tuple[int, list[str]] | None]


def member_cells(family: Family) -> list[MemberCells]:
    keys = family.axis_keys()
    out = []
    for m in family.members:
        pos = {a.key: i for i, a in enumerate(m.axes)}
        axes = [
            (pos[k], [cell(v) for v in m.axes[pos[k]].values]) if k in pos else None for k in keys
        ]
        out.append(MemberCells((cell(m.name), cell(m.application)), axes))
    return out


def run_chunk(
    family: Family, number: int, start: int, stop: int, catalog_dir: str | None, reports: bool
) -> ChunkResult:
    """Advise variants ``start`` … ``stop - 1``."""
    t0 = time.perf_counter()
    cells = member_cells(family)
    blank = [""] * len(COLUMNS)
    rows, texts = [], []
    for index in range(start, stop):
        n, local = family.locate(index)
        member = family.members[n]
        coords = member.coords(local)
        o = advise_one(member.requirement(coords), catalog_dir, with_text=reports)
        mc = cells[n]
        outputs = key_outputs(o.report) if o.report is not None else None
        rows.append(
            [
                str(index),
                *mc.head,
                *("" if ax is None else ax[1][coords[ax[0]]] for ax in mc.axes),
                o.status,
                str(int(o.exit_code)),
                cell(o.reason),
                *(blank if outputs is None else [cell(outputs.get(c)) for c in COLUMNS]),
            ]
        )
        if o.text is not None:
            texts.append((report_name(index), o.text))
    return ChunkResult(number, rows, texts, time.perf_counter() - t0)


def rows_csv(rows: list[list[str]], header: list[str] | None = None) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    if header is not None:
        w.writerow(header)
    w.writerows(rows)
    return buf.getvalue()
