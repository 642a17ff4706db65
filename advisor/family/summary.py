"""summary.toml: counts, where the discrete choices change along each axis, the infeasible
region, and the span of the key numbers over the range."""

import csv
import re
from pathlib import Path
from typing import Any

import numpy as np

from advisor.family.outputs import DISCRETE, NUMERIC
from advisor.family.spec import Family, Member

STATUSES = ("design", "infeasible", "invalid", "internal_error")
_NUMBER = re.compile(r"[-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?", re.IGNORECASE)


def read_rows(path: Path) -> list[dict[str, str]]:
    """The rows of designs.csv, each text as the study had it (without the quote that
    keeps a spreadsheet from reading it as a formula)."""
    from advisor.family.chunks import uncell

    with path.open(encoding="utf-8", newline="") as fh:
        rd = csv.reader(fh)
        head = [uncell(h) for h in next(rd, [])]
        return [dict(zip(head, map(uncell, r), strict=True)) for r in rd]


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


def changes(member: Member, values: list[str]) -> list[dict[str, Any]]:
    """Where ``values`` (one per variant of the member, in order) change along each axis.

    One entry per (axis, place, from, to): ``between`` the two neighbouring axis values,
    on how many ``lines`` (combinations of the other axes) of how many. Blank values
    (variants without a design) are not changes of a choice; the status says where those are.
    """
    shape = tuple(len(a.values) for a in member.axes)
    uniq, codes = np.unique(np.asarray(values, dtype=object).astype(str), return_inverse=True)
    grid = codes.reshape(shape)
    blank = np.flatnonzero(uniq == "")
    out = []
    for ax, a in enumerate(member.axes):
        n = shape[ax]
        if n < 2:
            continue
        lo = np.take(grid, range(n - 1), axis=ax)
        hi = np.take(grid, range(1, n), axis=ax)
        place = np.indices(lo.shape)[ax]
        mask = lo != hi
        if blank.size:
            mask &= (lo != blank[0]) & (hi != blank[0])
        if not mask.any():
            continue
        triples = np.stack([place[mask], lo[mask], hi[mask]], axis=1)
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


def regions(member: Member, rows: list[dict[str, str]]) -> list[dict[str, Any]]:
    """The variants without a design, grouped by the kind of reason (numbers masked), with
    the axis values at which each group occurs."""
    groups: dict[tuple[str, str], dict[str, Any]] = {}
    shape = tuple(len(a.values) for a in member.axes)
    for i, r in enumerate(rows):
        if r["status"] == "design":
            continue
        key = (r["status"], _NUMBER.sub("#", r["reason"]))
        g = groups.setdefault(
            key, {"status": r["status"], "variants": 0, "example": r["reason"], "at": []}
        )
        g["variants"] += 1
        g["at"].append(i)
    out = []
    for g in sorted(groups.values(), key=lambda g: -g["variants"]):
        coords = np.unravel_index(np.asarray(g.pop("at")), shape)
        g["axes"] = {
            a.key: [a.values[k] for k in sorted(set(c.tolist()))]
            for a, c in zip(member.axes, coords, strict=True)
        }
        out.append(g)
    return out


def spans(rows: list[dict[str, str]]) -> dict[str, Any]:
    """Smallest and largest of each key number over the designs, and where."""
    out: dict[str, Any] = {}
    for col in NUMERIC:
        pts = [(float(r[col]), int(r["variant"])) for r in rows if r.get(col)]
        if pts:
            lo, hi = min(pts), max(pts)
            out[col] = {"min": lo[0], "min_variant": lo[1], "max": hi[0], "max_variant": hi[1]}
    return out


def counts(rows: list[dict[str, str]]) -> dict[str, int]:
    return {s: sum(r["status"] == s for r in rows) for s in STATUSES}


def summarize(family: Family, rows: list[dict[str, str]], extra: dict[str, Any]) -> dict:
    """The summary document (TOML data)."""
    doc: dict[str, Any] = {
        "family": {"name": family.name, "source": family.source, "variants": family.size, **extra},
        "counts": counts(rows),
        "members": [],
    }
    start = 0
    for m in family.members:
        mine = rows[start : start + m.size]
        start += m.size
        ch = []
        for col in ("status", *DISCRETE):
            for c in changes(m, [r[col] for r in mine]):
                ch.append({"output": col, **c})
        doc["members"].append(
            {
                "name": m.name,
                "application": m.application,
                "variants": m.size,
                "first_variant": int(mine[0]["variant"]) if mine else 0,
                "axes": {a.key: {"scale": a.scale, "values": list(a.values)} for a in m.axes},
                "counts": counts(mine),
                "outputs": spans(mine),
                "changes": ch,
                "without_design": regions(m, mine),
            }
        )
    return doc


def write_summary(path: Path, doc: dict[str, Any]) -> None:
    import tomli_w

    from advisor.family.adapter import write_atomic

    write_atomic(path, tomli_w.dumps(doc))
