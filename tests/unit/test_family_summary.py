"""The family summary merged from chunk parts: the same document whatever the order the
chunks arrive in, the changes of a choice found as a walk over every pair of neighbours
finds them, and no numpy on the way."""

import itertools
import random
import subprocess
import sys
import tomllib

import pytest
from helpers import EXAMPLES

from advisor.family.spec import parse_family
from advisor.family.summary import (
    READ,
    Column,
    SummaryBuilder,
    build_summary,
    changes,
    encode,
)

SHAPE = (5, 3, 4)


@pytest.fixture(scope="module")
def family(tmp_path_factory):
    """Two members: a positioning one of 5 × 3 × 4 variants, and a one-axis one of 7."""
    doc = tomllib.loads((EXAMPLES / "positioning_drive.toml").read_text(encoding="utf-8"))
    base = str(EXAMPLES / "positioning_drive.toml")
    doc = {
        "family": {
            "name": "parts",
            "members": [
                {
                    "name": "grid",
                    "base": base,
                    "axes": {
                        "positioning.travel_rad": [1, 2, 3, 4, 5],
                        "positioning.load_inertia_kgm2": [1, 2, 3],
                        "positioning.load_torque_Nm": [10, 20, 30, 40],
                    },
                },
                {"name": "line", "base": base, "axes": {"positioning.travel_rad": [*range(1, 8)]}},
            ],
        }
    }
    return parse_family(doc, tmp_path_factory.mktemp("fam") / "f.toml")


def random_rows(n: int, seed: int) -> list[dict[str, str]]:
    """Rows as designs.csv gives them back: designs with numbers and choices, the others
    blank with a reason that carries a number."""
    rng = random.Random(seed)
    rows = []
    for i in range(n):
        status = rng.choice(["design", "design", "design", "infeasible", "invalid"])
        row = dict.fromkeys(READ, "")
        row.update(variant=str(i), status=status)
        if status == "design":
            row.update(motor=rng.choice(["M1", "M2", "M3"]), pole_pairs=rng.choice(["2", "4"]))
            row.update(mass_kg=str(rng.choice([1.5, 2.0, 2.5, 3.0])), ratio=str(rng.random()))
        else:
            row["reason"] = f"{status}: margin {rng.randint(1, 9)} below 1"
        rows.append(row)
    return rows


def merged(family, rows, order: list[int], size: int, keep) -> tuple:
    """The summary merged from chunks of ``size`` rows tallied apart, in ``order``."""
    builder = SummaryBuilder(family, keep)
    for n in order:
        chunk = [[r[c] for c in READ] for r in rows[n * size : (n + 1) * size]]
        builder.add_rows(n * size, chunk)  # tally_rows, then the rows the page plots
    return builder.finish({"workers": 2})


def test_the_order_of_the_chunks_changes_nothing(family):
    rows = random_rows(family.size, seed=1)
    keep = [{0, 5, 17, 59}, {3, 6}]
    whole = build_summary(family, rows, {"workers": 2}, keep)
    for size, seed in ((7, 2), (1, 3), (60, 4), (67, 5)):
        order = list(range(-(-family.size // size)))
        random.Random(seed).shuffle(order)
        doc, pictures = merged(family, rows, order, size, keep)
        assert doc == whole.doc
        assert pictures == whole.pictures
    assert whole.doc["members"][0]["without_design"]  # the regions were exercised
    assert whole.pictures[0].points[17]["status"] == rows[17]["status"]


def brute_changes(member, values: list[str]) -> list[tuple]:
    """Every pair of neighbours along every axis, counted: (axis, k, from, to, lines)."""
    shape = [len(a.values) for a in member.axes]
    out = []
    for ax, a in enumerate(member.axes):
        found: dict[tuple[int, str, str], int] = {}
        for coords in itertools.product(*map(range, shape)):
            if coords[ax] == shape[ax] - 1:
                continue
            nxt = list(coords)
            nxt[ax] += 1
            f, t = values[flat(coords, shape)], values[flat(nxt, shape)]
            if f != t and "" not in (f, t):
                found[coords[ax], f, t] = found.get((coords[ax], f, t), 0) + 1
        out += [(a.key, *key, c) for key, c in sorted(found.items())]
    return out


def flat(coords, shape) -> int:
    i = 0
    for c, n in zip(coords, shape, strict=True):
        i = i * n + c
    return i


@pytest.mark.parametrize("kinds", [2, 3, 300])
def test_changes_are_every_pair_of_neighbours_that_differ(family, kinds):
    member = family.members[0]
    rng = random.Random(kinds)
    texts = ["", *(f"m{k:03d}" for k in range(kinds))]
    values = [rng.choice(texts) for _ in range(member.size)]
    found = [
        (
            c["axis"],
            member.axes[[a.key for a in member.axes].index(c["axis"])].values.index(
                c["between"][0]
            ),
            *(str(c[k]) for k in ("from", "to")),
            c["lines"],
        )
        for c in changes(member, values)
    ]
    assert found == brute_changes(member, values)


def test_a_column_of_many_texts_keeps_its_codes():
    column = Column(600)
    column.put(0, *encode([f"a{i}" for i in range(200)]))
    column.put(200, *encode([f"b{i}" for i in range(400)]))  # past 256 texts: wider codes
    assert len(column.index) == 600
    assert [column.texts()[c] for c in column.codes[:3]] == ["a0", "a1", "a2"]
    assert [column.texts()[c] for c in column.codes[-2:]] == ["b398", "b399"]


def test_the_summary_and_the_page_import_no_numpy(family):
    code = (
        "import sys\n"
        "from advisor.family import cli, html, study, summary\n"
        "print('numpy' in sys.modules)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"
