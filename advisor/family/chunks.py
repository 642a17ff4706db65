"""One task of a family study: advise a block of variants in one process.

:func:`run_chunk` is what a Dask worker runs; it takes the family (small: bases and axes)
and a range of variant numbers, builds each variant itself, and returns the CSV rows (and,
when asked, the report texts). The scheduler never sees a task per variant.
"""

import csv
import io
import time
from collections.abc import Callable
from typing import Any, NamedTuple

from advisor.family.adapter import advise_one
from advisor.family.cells import cell
from advisor.family.outputs import COLUMNS, reader
from advisor.family.spec import Family
from advisor.family.summary import Part, read_cells, read_positions, tally_rows


def report_name(index: int) -> str:
    return f"v{index:07d}.report.toml"


class ChunkResult(NamedTuple):
    number: int
    rows: list[list[str]]
    reports: list[tuple[str, str]]  # (file name, report TOML) when asked for
    seconds: float  # the worker's time on the chunk (advice and tally), for the cost model
    #: the chunk's summary, tallied while its rows are at hand (the command merges them)
    parts: list[Part]


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
    readers: dict[str, Callable[[dict[str, Any]], dict[str, Any]]] = {}  # per application
    blank = [""] * len(COLUMNS)
    rows, texts = [], []
    for index in range(start, stop):
        n, local = family.locate(index)
        member = family.members[n]
        coords = member.coords(local)
        o = advise_one(member.requirement(coords), catalog_dir, with_text=reports)
        mc = cells[n]
        rows.append(
            [
                str(index),
                *mc.head,
                *("" if ax is None else ax[1][coords[ax[0]]] for ax in mc.axes),
                o.status,
                str(int(o.exit_code)),
                cell(o.reason),
                *(blank if o.report is None else output_cells(o.report, readers)),
            ]
        )
        if o.text is not None:
            texts.append((report_name(index), o.text))
    at = read_positions(family)
    parts = tally_rows(family, start, [read_cells(r, at) for r in rows])
    return ChunkResult(number, rows, texts, time.perf_counter() - t0, parts)


#: Where each key output's cell is among the output columns.
OUTPUT_AT = {c: i for i, c in enumerate(COLUMNS)}


def output_cells(report: dict[str, Any], readers: dict[str, Callable]) -> list[str]:
    """The key-output cells of a report's row, in :data:`advisor.family.outputs.COLUMNS`
    order (blank where the application gives none); ``readers``: the application's
    :func:`advisor.family.outputs.reader` by kind, looked up once a chunk."""
    kind = report["report"]["application"]
    read = readers.get(kind)
    if read is None:
        read = readers[kind] = reader(kind)
    cells = [""] * len(COLUMNS)
    for col, v in read(report).items():  # the few an application fills
        if v is not None and (i := OUTPUT_AT.get(col)) is not None:
            cells[i] = cell(v)
    return cells


def rows_csv(rows: list[list[str]], header: list[str] | None = None) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    if header is not None:
        w.writerow(header)
    w.writerows(rows)
    return buf.getvalue()
