"""summary.toml: counts, where the discrete choices change along each axis, the infeasible
region, and the span of the key numbers over the range.

Built from partial summaries, never from a list of rows: a worker tallies its chunk's rows
while it holds them (:func:`tally_rows`, a :class:`Part` per member the chunk touches) and
the command merges the parts as the chunks arrive, in any order (:class:`SummaryBuilder`);
a chunk written by an earlier run of a resumed study is tallied from its file. A study of a
million variants is never held in memory, and designs.csv is never read back. What the
command keeps while the chunks go by is one small code per variant and discrete column (a
byte while there are at most 256 distinct values), the extremes of each key number, the axis
values of each group of variants without a design, and, for family.html, the key numbers at
the points its plots show. Plain Python: the command imports no numpy for it.
"""

import csv
import io
import math
import re
from array import array
from bisect import bisect_left
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass
from itertools import islice
from operator import itemgetter
from pathlib import Path
from typing import Any, NamedTuple

from advisor.family.cells import HEAD, TAIL, uncell
from advisor.family.outputs import COLUMNS, DISCRETE, NUMERIC
from advisor.family.spec import Family, Member

STATUSES = ("design", "infeasible", "invalid", "internal_error")
#: The columns whose changes along the axes the summary reports, in its order.
CHANGING = ("status", *DISCRETE)
#: The columns of designs.csv the summary reads, in the order of a row it is given (texts
#: as the study had them, without the quote that keeps a spreadsheet from a formula).
READ = ("status", "reason", *DISCRETE, *NUMERIC)
_CHANGING_AT = tuple(READ.index(c) for c in CHANGING)
_NUMERIC_AT = tuple(READ.index(c) for c in NUMERIC)
_NUMBER = re.compile(r"[-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?", re.IGNORECASE)
#: Rows tallied at a time when a summary is built from a stream of rows.
BATCH = 4096

Row = dict[str, str]
#: A code per variant: a byte each while there are at most 256 distinct texts.
Codes = bytes | bytearray | array
#: (value, variant): the smallest and largest of a key number, and where
Span = tuple[tuple[float, int], tuple[float, int]]


def iter_rows(path: Path) -> Iterator[Row]:
    """The rows of designs.csv one at a time, each text as the study had it (without the
    quote that keeps a spreadsheet from reading it as a formula)."""
    with path.open(encoding="utf-8", newline="") as fh:
        rows = csv.reader(fh)
        head = [uncell(h) for h in next(rows, [])]
        for r in rows:
            yield dict(zip(head, map(uncell, r), strict=True))


def read_rows(path: Path) -> list[Row]:
    """Every row of designs.csv in a list (for small studies and tests; the command never
    reads designs.csv back)."""
    return list(iter_rows(path))


def read_positions(family: Family) -> Callable[[Sequence[str]], tuple[str, ...]]:
    """What picks the cells the summary reads (:data:`READ`, in its order) from a row of
    designs.csv (:func:`advisor.family.cells.columns`: head, axes, tail, key outputs)."""
    tail = len(HEAD) + len(family.axis_keys())
    at = {c: tail + i for i, c in enumerate((*TAIL, *COLUMNS))}
    return itemgetter(*(at[c] for c in READ))


def read_cells(row: Sequence[str], pick: Callable[[Sequence[str]], tuple[str, ...]]) -> list[str]:
    """The texts the summary reads of a row of cells (``pick``: :func:`read_positions`);
    only a cell that starts with a quote can be a neutralised one."""
    return [uncell(t) if t.startswith("'") else t for t in pick(row)]


def _value(text: str) -> Any:
    """A CSV cell back as TOML wants it: whole numbers as int, other numbers as float."""
    try:
        return int(text)
    except ValueError:
        pass
    try:
        return float(text)
    except ValueError:
        return text


def encode(texts: Sequence[str]) -> tuple[list[str], Codes]:
    """The distinct texts in the order first seen, and each text's index among them (a
    byte each while there are at most 256).

    >>> encode(["b", "a", "b"])
    (['b', 'a'], b'\\x00\\x01\\x00')
    """
    index = {t: i for i, t in enumerate(dict.fromkeys(texts))}
    codes = map(index.__getitem__, texts)
    return list(index), bytes(codes) if len(index) <= 256 else array("I", codes)


class Column:
    """A column of texts, one per variant of a member, kept as codes in the order first
    seen (a byte a variant while there are at most 256 distinct texts)."""

    def __init__(self, size: int) -> None:
        self.index: dict[str, int] = {}
        self.codes: bytearray | array = bytearray(size)

    def _code(self, text: str) -> int:
        code = self.index.get(text)
        if code is None:
            code = self.index[text] = len(self.index)
            if code == 256 and isinstance(self.codes, bytearray):
                self.codes = array("I", iter(self.codes))  # a bytearray itself: raw bytes
        return code

    def put(self, start: int, texts: list[str], codes: Codes) -> None:
        """The texts of the variants from local number ``start`` on, as :func:`encode`
        gives them."""
        lut = [self._code(t) for t in texts]
        stop = start + len(codes)
        if isinstance(self.codes, bytearray) and isinstance(codes, bytes):
            self.codes[start:stop] = codes.translate(bytes(lut).ljust(256, b"\0"))
        else:
            self.codes[start:stop] = array("I", map(lut.__getitem__, codes))

    def texts(self) -> list[str]:
        """The text of each code."""
        return list(self.index)


def differing(lo: Codes, hi: Codes) -> list[int]:
    """Where two code sequences of one length differ. Runs are compared whole and halved
    only where they differ, so that a few changes among many variants cost a few compares.

    >>> sorted(differing(b"aaaaxaaa" * 9, b"aaaaaaaa" * 9))
    [4, 12, 20, 28, 36, 44, 52, 60, 68]
    """
    out: list[int] = []
    todo = [(0, len(lo))]
    while todo:
        a, b = todo.pop()
        if lo[a:b] == hi[a:b]:
            continue
        if b - a <= 32:
            out += [i for i in range(a, b) if lo[i] != hi[i]]
        else:
            m = (a + b) // 2
            todo += [(a, m), (m, b)]
    return out


def axis_changes(
    codes: Codes, shape: Sequence[int], ax: int, blank: int
) -> dict[tuple[int, int, int], int]:
    """``{(k, from, to): lines}``: how many lines (combinations of the other axes) go from
    code ``from`` at value ``k`` of axis ``ax`` to code ``to`` at value ``k + 1``; a blank
    (code ``blank``) on either side is not a change. ``codes``: the member's variants in
    order, last axis fastest."""
    n, stride = shape[ax], math.prod(shape[ax + 1 :])
    length = (n - 1) * stride  # the variants with a next value along the axis, per block
    found: dict[tuple[int, int, int], int] = {}
    for base in range(0, len(codes), n * stride):
        lo, hi = codes[base : base + length], codes[base + stride : base + stride + length]
        if lo == hi:  # the common case, without a call
            continue
        for i in differing(lo, hi):
            f, t = lo[i], hi[i]
            if f != blank and t != blank:
                key = (i // stride, f, t)
                found[key] = found.get(key, 0) + 1
    return found


def column_changes(member: Member, column: Column) -> list[dict[str, Any]]:
    """Where the texts of ``column`` change along each axis of the member (see
    :func:`changes`), in the order of (axis, place, from, to), texts sorted."""
    texts = column.texts()
    if len(texts) < 2:
        return []
    rank = [0] * len(texts)
    for r, code in enumerate(sorted(range(len(texts)), key=texts.__getitem__)):
        rank[code] = r
    blank = column.index.get("", -1)
    shape = [len(a.values) for a in member.axes]
    out = []
    for ax, a in enumerate(member.axes):
        if shape[ax] < 2:
            continue
        found = axis_changes(column.codes, shape, ax, blank)
        for k, f, t in sorted(found, key=lambda c: (c[0], rank[c[1]], rank[c[2]])):
            out.append(
                {
                    "axis": a.key,
                    "between": [a.values[k], a.values[k + 1]],
                    "from": _value(texts[f]),
                    "to": _value(texts[t]),
                    "lines": found[k, f, t],
                    "of_lines": member.size // shape[ax],
                }
            )
    return out


def changes(member: Member, values: list[str]) -> list[dict[str, Any]]:
    """Where ``values`` (one per variant of the member, in order) change along each axis.

    One entry per (axis, place, from, to): ``between`` the two neighbouring axis values,
    on how many ``lines`` (combinations of the other axes) of how many. Blank values
    (variants without a design) are not changes of a choice; the status says where those are.
    """
    column = Column(len(values))
    column.put(0, *encode(values))
    return column_changes(member, column)


@dataclass
class Region:
    """Variants without a design that share a kind of reason, and the axis values (by
    index) at which they occur; ``example``: the reason of the first of them (local
    number ``first``)."""

    status: str
    example: str
    at: list[set[int]]
    variants: int = 0
    first: int = 0

    def merge(self, other: "Region") -> None:
        """Add the variants of ``other`` (the same kind of reason, other variants)."""
        if other.first < self.first:
            self.example, self.first = other.example, other.first
        self.variants += other.variants
        for s, o in zip(self.at, other.at, strict=True):
            s |= o

    def entry(self, member: Member) -> dict[str, Any]:
        return {
            "status": self.status,
            "variants": self.variants,
            "example": self.example,
            "axes": {
                a.key: [a.values[k] for k in sorted(s)]
                for a, s in zip(member.axes, self.at, strict=True)
            },
        }


@dataclass(frozen=True, slots=True)
class Part:
    """One member's tally over consecutive variants of a chunk: what a worker sends back
    with the chunk's rows, and what the command merges."""

    member: int  # the member's number in the family
    start: int  # the local number (within the member) of the first variant
    counts: dict[str, int]
    spans: dict[str, Span]  # per key number with a value
    columns: dict[str, tuple[list[str], Codes]]  # per CHANGING column, as encode gives it
    regions: dict[tuple[str, str], Region]  # per (status, reason with its numbers as #)


def _spans(rows: Sequence[Sequence[str]], first_variant: int) -> dict[str, Span]:
    out = {}
    for col, i in zip(NUMERIC, _NUMERIC_AT, strict=True):
        values = [(float(r[i]), first_variant + j) for j, r in enumerate(rows) if r[i]]
        if values:
            out[col] = (min(values), max(values))
    return out


def _regions(member: Member, start: int, rows: Sequence[Sequence[str]]) -> dict:
    """The variants without a design among ``rows`` (from local number ``start``), grouped
    by status and reason (its numbers aside), in the order first seen."""
    out: dict[tuple[str, str], Region] = {}
    for j, row in enumerate(rows):
        status = row[0]
        if status == "design":
            continue
        reason = row[1]
        key = (status, _NUMBER.sub("#", reason))
        g = out.get(key)
        if g is None:
            g = out[key] = Region(status, reason, [set() for _ in member.axes], 0, start + j)
        g.variants += 1
        for s, k in zip(g.at, member.coords(start + j), strict=True):
            s.add(k)
    return out


def tally_part(
    family: Family, number: int, start: int, first_variant: int, rows: Sequence[Sequence[str]]
) -> Part:
    """The :class:`Part` of member ``number`` over ``rows`` (each the texts of :data:`READ`),
    its variants from local number ``start`` (variant ``first_variant`` of the family)."""
    counts: dict[str, int] = {}
    for row in rows:
        counts[row[0]] = counts.get(row[0], 0) + 1
    columns = {c: encode([r[i] for r in rows]) for c, i in zip(CHANGING, _CHANGING_AT, strict=True)}
    member = family.members[number]
    regions = _regions(member, start, rows)
    return Part(number, start, counts, _spans(rows, first_variant), columns, regions)


def tally_rows(family: Family, first_variant: int, rows: Sequence[Sequence[str]]) -> list[Part]:
    """The parts of consecutive variants from ``first_variant`` on, a part per member they
    touch; each row the texts of :data:`READ`."""
    parts, i = [], 0
    while i < len(rows):
        n, local = family.locate(first_variant + i)
        take = min(len(rows) - i, family.members[n].size - local)
        parts.append(tally_part(family, n, local, first_variant + i, rows[i : i + take]))
        i += take
    return parts


@dataclass(frozen=True, slots=True)
class Picture:
    """What family.html draws of a member: the outcome of every variant (its index in
    :data:`STATUSES`, a byte each, in the member's order) and, at the points its plots
    show, the row's texts of :data:`READ` by column."""

    status: bytes
    points: dict[int, Row]


class Tally:
    """One member's summary, merged from the parts of its variants (in any order)."""

    def __init__(self, member: Member, first_variant: int) -> None:
        self.member = member
        self.first_variant = first_variant
        self.counts = dict.fromkeys(STATUSES, 0)
        self.spans: dict[str, Span] = {}
        self.columns = {c: Column(member.size) for c in CHANGING}
        self.regions: dict[tuple[str, str], Region] = {}
        self.points: dict[int, Row] = {}  # the local numbers whose rows the page plots

    def merge(self, part: Part) -> None:
        for status, k in part.counts.items():
            self.counts[status] = self.counts.get(status, 0) + k
        for col, (lo, hi) in part.spans.items():  # (value, variant): the first of equal ones
            span = self.spans.get(col)
            self.spans[col] = (lo, hi) if span is None else (min(span[0], lo), max(span[1], hi))
        for col, (texts, codes) in part.columns.items():
            self.columns[col].put(part.start, texts, codes)
        for key, g in part.regions.items():
            mine = self.regions.get(key)
            if mine is None:
                self.regions[key] = g
            else:
                mine.merge(g)

    def outputs(self) -> dict[str, Any]:
        """Smallest and largest of each key number over the designs, and where."""
        out = {}
        for col in NUMERIC:
            if col in self.spans:
                (lo, lo_v), (hi, hi_v) = self.spans[col]
                out[col] = {"min": lo, "min_variant": lo_v, "max": hi, "max_variant": hi_v}
        return out

    def entry(self) -> dict[str, Any]:
        m = self.member
        ch = []
        for col in CHANGING:
            ch += [{"output": col, **c} for c in column_changes(m, self.columns[col])]
        # the largest groups first; of equal ones, the first seen along the variants
        groups = sorted(self.regions.values(), key=lambda g: (-g.variants, g.first))
        return {
            "name": m.name,
            "application": m.application,
            "variants": m.size,
            "first_variant": self.first_variant,
            "axes": {a.key: {"scale": a.scale, "values": list(a.values)} for a in m.axes},
            "counts": {s: self.counts.get(s, 0) for s in STATUSES},
            "outputs": self.outputs(),
            "changes": ch,
            "without_design": [g.entry(m) for g in groups],
        }

    def picture(self) -> Picture:
        column = self.columns["status"]
        lut = bytes(STATUSES.index(t) for t in column.texts()) or b"\0"
        return Picture(bytes(column.codes).translate(lut.ljust(256, b"\0")), self.points)


class Summary(NamedTuple):
    doc: dict[str, Any]  # the summary document (TOML data)
    pictures: list[Picture]  # per member, what family.html draws


class SummaryBuilder:
    """A study's summary, merged from its chunks as they arrive, in any order: the parts
    their workers tallied (:meth:`add_result`), or a chunk's file (:meth:`add_text`).
    ``keep[n]``: the local numbers of member ``n`` whose rows family.html plots."""

    def __init__(self, family: Family, keep: list[set[int]] | None = None) -> None:
        self.family = family
        self.tallies: list[Tally] = []
        kept, start = [], 0
        for n, m in enumerate(family.members):
            self.tallies.append(Tally(m, start))
            kept += [start + local for local in keep[n]] if keep else []
            start += m.size
        self.kept = sorted(kept)
        self.merged: set[int] = set()  # the chunks merged

    def add_parts(self, parts: Iterable[Part]) -> None:
        for p in parts:
            self.tallies[p.member].merge(p)

    def add_points(self, start: int, stop: int, row_of: Callable[[int], Sequence[str]]) -> None:
        """Keep the rows of variants ``start`` … ``stop - 1`` that family.html plots;
        ``row_of(variant)``: its texts of :data:`READ`."""
        for v in self.kept[bisect_left(self.kept, start) : bisect_left(self.kept, stop)]:
            n, local = self.family.locate(v)
            self.tallies[n].points[local] = dict(zip(READ, row_of(v), strict=True))

    def add_rows(self, start: int, rows: Sequence[Sequence[str]]) -> None:
        """Consecutive variants from ``start`` on, each row the texts of :data:`READ`."""
        self.add_parts(tally_rows(self.family, start, rows))
        self.add_points(start, start + len(rows), lambda v: rows[v - start])

    def add_result(
        self, number: int, start: int, cells: list[list[str]], parts: list[Part]
    ) -> None:
        """Chunk ``number`` (its first variant ``start``) as a worker gave it: its rows as
        designs.csv cells and the parts it tallied."""
        if number in self.merged:
            return
        self.merged.add(number)
        self.add_parts(parts)
        at = read_positions(self.family)
        self.add_points(start, start + len(cells), lambda v: read_cells(cells[v - start], at))

    def add_text(self, number: int, start: int, text: str) -> None:
        """Chunk ``number`` read from its file (written by an earlier run), unless merged."""
        if number in self.merged:
            return
        self.merged.add(number)
        at = read_positions(self.family)
        self.add_rows(start, [read_cells(r, at) for r in csv.reader(io.StringIO(text))])

    def finish(self, extra: dict[str, Any]) -> Summary:
        family, tallies = self.family, self.tallies
        total = {s: sum(t.counts.get(s, 0) for t in tallies) for s in STATUSES}
        doc: dict[str, Any] = {
            "family": {
                "name": family.name,
                "source": family.source,
                "variants": family.size,
                **extra,
            },
            "counts": total,
            "members": [t.entry() for t in tallies],
        }
        return Summary(doc, [t.picture() for t in tallies])


def build_summary(
    family: Family,
    rows: Iterable[Row],
    extra: dict[str, Any],
    keep: list[set[int]] | None = None,
) -> Summary:
    """The summary of a study from its rows in variant order (a stream is enough: they
    are tallied :data:`BATCH` at a time); ``keep[n]`` names the rows of member ``n`` that
    family.html plots."""
    builder = SummaryBuilder(family, keep)
    it, start = iter(rows), 0
    while batch := [[r.get(c, "") for c in READ] for r in islice(it, BATCH)]:
        builder.add_rows(start, batch)
        start += len(batch)
    return builder.finish(extra)


def summarize(family: Family, rows: Iterable[Row], extra: dict[str, Any]) -> dict:
    """The summary document (TOML data)."""
    return build_summary(family, rows, extra).doc


def summary_text(doc: dict[str, Any]) -> str:
    """summary.toml's text."""
    import tomli_w

    return tomli_w.dumps(doc)


def write_summary(path: Path, doc: dict[str, Any]) -> None:
    from advisor.family.adapter import write_atomic

    write_atomic(path, summary_text(doc))
