"""summary.toml: counts, where the discrete choices change along each axis, the infeasible
region, and the span of the key numbers over the range.

Built in one pass over the rows, which are streamed (from designs.csv, row by row): a study
of a million variants is never held in memory. What a member keeps while the rows go by is
one small code per variant and discrete column (a byte while there are fewer than 256
distinct values), the extremes of each key number, the axis values of each group of
variants without a design, and, for family.html, the key numbers at the points its plots
show.
"""

import csv
import re
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np

from advisor.family.outputs import DISCRETE, NUMERIC
from advisor.family.spec import Family, Member

STATUSES = ("design", "infeasible", "invalid", "internal_error")
#: The columns whose changes along the axes the summary reports, in its order.
CHANGING = ("status", *DISCRETE)
_NUMBER = re.compile(r"[-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?", re.IGNORECASE)

Row = dict[str, str]


def iter_rows(path: Path) -> Iterator[Row]:
    """The rows of designs.csv one at a time, each text as the study had it (without the
    quote that keeps a spreadsheet from reading it as a formula)."""
    from advisor.family.chunks import uncell

    with path.open(encoding="utf-8", newline="") as fh:
        rows = csv.reader(fh)
        head = [uncell(h) for h in next(rows, [])]
        for r in rows:
            yield dict(zip(head, map(uncell, r), strict=True))


def read_rows(path: Path) -> list[Row]:
    """Every row of designs.csv in a list (for small studies and tests; the command
    streams them with :func:`iter_rows`)."""
    return list(iter_rows(path))


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


class Codes:
    """A column of texts, one per variant, kept as integer codes in the order first seen
    (one byte a variant while there are fewer than 256 distinct texts)."""

    def __init__(self, size: int) -> None:
        self.index: dict[str, int] = {}
        self.codes = np.zeros(size, dtype=np.uint8)

    def set(self, i: int, text: str) -> None:
        code = self.index.get(text)
        if code is None:
            code = self.index[text] = len(self.index)
            if code > np.iinfo(self.codes.dtype).max:
                self.codes = self.codes.astype(np.uint16 if code <= 0xFFFF else np.int64)
        self.codes[i] = code

    def sorted(self) -> tuple[np.ndarray, np.ndarray]:
        """The distinct texts sorted, and each variant's code into them: what
        ``np.unique(texts, return_inverse=True)`` gives."""
        uniq = sorted(self.index)
        remap = np.empty(max(len(uniq), 1), dtype=self.codes.dtype)  # a byte a variant, still
        for new, text in enumerate(uniq):
            remap[self.index[text]] = new
        return np.array(uniq, dtype=str), remap[self.codes]


def changes(member: Member, values: list[str]) -> list[dict[str, Any]]:
    """Where ``values`` (one per variant of the member, in order) change along each axis.

    One entry per (axis, place, from, to): ``between`` the two neighbouring axis values,
    on how many ``lines`` (combinations of the other axes) of how many. Blank values
    (variants without a design) are not changes of a choice; the status says where those are.
    """
    column = Codes(len(values))
    for i, v in enumerate(values):
        column.set(i, v)
    return coded_changes(member, *column.sorted())


def coded_changes(member: Member, uniq: np.ndarray, codes: np.ndarray) -> list[dict[str, Any]]:
    """:func:`changes` of a column given as its sorted distinct texts and the codes."""
    shape = tuple(len(a.values) for a in member.axes)
    grid = codes.reshape(shape)
    blank = np.flatnonzero(uniq == "")
    out = []
    for ax, a in enumerate(member.axes):
        n = shape[ax]
        if n < 2:
            continue
        lo = np.take(grid, range(n - 1), axis=ax)
        hi = np.take(grid, range(1, n), axis=ax)
        mask = lo != hi
        if blank.size:
            mask &= (lo != blank[0]) & (hi != blank[0])
        if not mask.any():
            continue
        place = np.nonzero(mask)[ax]  # the index along the axis of each change, in order
        triples = np.stack([place, lo[mask], hi[mask]], axis=1)
        found, counts = np.unique(triples, axis=0, return_counts=True)
        lines = grid.size // n
        for (k, f, t), c in zip(found.tolist(), counts.tolist(), strict=True):
            out.append(
                {
                    "axis": a.key,
                    "between": [a.values[k], a.values[k + 1]],
                    "from": _value(str(uniq[f])),
                    "to": _value(str(uniq[t])),
                    "lines": c,
                    "of_lines": lines,
                }
            )
    return out


@dataclass
class Region:
    """Variants without a design that share a kind of reason, and the axis values (by
    index) at which they occur."""

    status: str
    example: str
    at: list[set[int]]
    variants: int = 0

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
class Picture:
    """What family.html draws of a member: the outcome of every variant (its index in
    :data:`STATUSES`, in the member's order) and the rows at the points its plots show."""

    status: np.ndarray
    points: dict[int, Row]


@dataclass
class Tally:
    """One member's summary, built a row at a time (rows in the member's order)."""

    member: Member
    first_variant: int
    keep: frozenset[int] = frozenset()  # the local numbers whose rows the page plots
    counts: dict[str, int] = field(default_factory=lambda: dict.fromkeys(STATUSES, 0))
    spans: dict[str, list[tuple[float, int]]] = field(default_factory=dict)
    columns: dict[str, Codes] = field(init=False)
    regions: dict[tuple[str, str], Region] = field(default_factory=dict)
    points: dict[int, Row] = field(default_factory=dict)

    def __post_init__(self) -> None:
        self.columns = {c: Codes(self.member.size) for c in CHANGING}

    def add(self, local: int, row: Row) -> None:
        status = row["status"]
        self.counts[status] = self.counts.get(status, 0) + 1
        for col, codes in self.columns.items():
            codes.set(local, row[col])
        if local in self.keep:
            self.points[local] = row
        self._add_numbers(row)  # blank but for designs
        if status != "design":
            self._add_region(local, status, row["reason"])

    def _add_numbers(self, row: Row) -> None:
        variant = int(row["variant"])
        for col in NUMERIC:
            if row.get(col):
                p = (float(row[col]), variant)
                span = self.spans.get(col)
                if span is None:
                    self.spans[col] = [p, p]
                elif p < span[0]:  # as min() over the rows: the first of equal ones
                    span[0] = p
                elif p > span[1]:
                    span[1] = p

    def _add_region(self, local: int, status: str, reason: str) -> None:
        key = (status, _NUMBER.sub("#", reason))
        g = self.regions.get(key)
        if g is None:
            g = self.regions[key] = Region(status, reason, [set() for _ in self.member.axes])
        g.variants += 1
        for s, k in zip(g.at, self.member.coords(local), strict=True):
            s.add(k)

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
            ch += [{"output": col, **c} for c in coded_changes(m, *self.columns[col].sorted())]
        groups = sorted(self.regions.values(), key=lambda g: -g.variants)  # stable: first seen
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
        uniq, codes = self.columns["status"].sorted()
        lut = np.array([STATUSES.index(str(u)) for u in uniq] or [0], dtype=np.uint8)
        return Picture(lut[codes], self.points)


class Summary(NamedTuple):
    doc: dict[str, Any]  # the summary document (TOML data)
    pictures: list[Picture]  # per member, what family.html draws


def build_summary(
    family: Family,
    rows: Iterable[Row],
    extra: dict[str, Any],
    keep: list[set[int]] | None = None,
) -> Summary:
    """The summary of a study from its rows in variant order (a stream is enough);
    ``keep[n]`` names the rows of member ``n`` that family.html plots."""
    tallies, start = [], 0
    for n, m in enumerate(family.members):
        tallies.append(Tally(m, start, frozenset(keep[n]) if keep else frozenset()))
        start += m.size
    ends = np.cumsum([m.size for m in family.members])
    n, first = 0, 0
    for i, row in enumerate(rows):
        while i >= ends[n]:
            first = int(ends[n])
            n += 1
        tallies[n].add(i - first, row)
    total = {s: sum(t.counts.get(s, 0) for t in tallies) for s in STATUSES}
    doc: dict[str, Any] = {
        "family": {"name": family.name, "source": family.source, "variants": family.size, **extra},
        "counts": total,
        "members": [t.entry() for t in tallies],
    }
    return Summary(doc, [t.picture() for t in tallies])


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
