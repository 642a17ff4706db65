"""``advisor verify`` (issue 30, part 1): the verification set runs in CI through these tests,
a broken published value is caught (exit 1), a departure is verified too, the data agrees with
the golden tests and the docs, and the HTML report escapes what it prints."""

import re
import tomllib
from pathlib import Path

import pytest
from helpers import ROOT

from advisor.cli import main
from advisor.verify.runner import (
    Departure,
    Quantity,
    data_path,
    judge,
    load_cases,
    lookup,
    run_case,
    within,
)

CASES = load_cases()


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_every_case_verifies(case):
    outcomes = run_case(case)
    bad = [(o.quantity.name, o.computed, o.verdict, o.error) for o in outcomes if not o.ok]
    assert bad == []


def test_the_command_exits_0_and_prints_one_line_per_quantity(capsys):
    assert main(["verify"]) == 0
    out = capsys.readouterr().out
    n = sum(len(c.quantities) for c in CASES)
    table = [ln for ln in out.splitlines() if any(ln.startswith(c.id + " ") for c in CASES)]
    assert len(table) == n
    assert "Departures" in out and "seed004-worm" in out
    assert out.rstrip().endswith("verified")
    # the worm erratum is a stated departure, with its reason
    worm = next(ln for ln in table if "γ = 0.5·φ" in ln)
    assert "≤ 0.25" in worm and "0.33112" in worm and "departure" in worm


def _broken(tmp_path: Path, old: str, new: str) -> Path:
    text = data_path().read_text(encoding="utf-8")
    assert old in text
    p = tmp_path / "cases.toml"
    p.write_text(text.replace(old, new, 1), encoding="utf-8")
    return p


def test_a_broken_published_value_exits_1(tmp_path, capsys):
    # SKF's L10 = 169 million revolutions, changed to 179: not within ±0.5, no departure
    p = _broken(tmp_path, "published = 169\n", "published = 179\n")
    assert main(["verify", "skf-6309", "--data", str(p)]) == 1
    out = capsys.readouterr().out
    line = next(ln for ln in out.splitlines() if "L10 " in ln or "rating life L10 " in ln)
    assert "FAIL" in line and "179 Mrev" in line and "169.112 Mrev" in line
    assert "NOT VERIFIED" in out


def test_a_departure_that_the_advisor_does_not_compute_fails(tmp_path):
    # seed 004's worm: the stated departure is 0.331; state 0.30 instead and the case fails
    p = _broken(tmp_path, "expected = 0.331\n", "expected = 0.30\n")
    assert main(["verify", "seed004-worm", "--data", str(p)]) == 1


def test_one_case_and_unknown_case(capsys):
    assert main(["verify", "honpine-fsg25"]) == 0
    out = capsys.readouterr().out
    assert "89 N·m" in out and "89.3868 N·m" in out and "1 cases" in out
    assert main(["verify", "no-such-case"]) == 2
    assert "no case 'no-such-case'" in capsys.readouterr().err


def test_html_report_is_self_contained_and_escaped(tmp_path, capsys):
    p = _broken(
        tmp_path,
        'title = "Honpine, FSG-25: average load torque of a load cycle"',
        'title = "<script>alert(1)</script> & FSG-25"',
    )
    out = tmp_path / "verification.html"
    assert main(["verify", "--data", str(p), "--format", "html", "-o", str(out)]) == 0
    text = out.read_text(encoding="utf-8")
    assert "<script>" not in text and "&lt;script&gt;alert(1)&lt;/script&gt; &amp; FSG-25" in text
    assert "<link" not in text and "src=" not in text  # nothing outside the file
    assert text.count('class="departure"') == sum(
        1 for c in CASES for q in c.quantities if q.departure
    )
    assert "verified" in capsys.readouterr().out


def test_html_needs_an_output_file(capsys):
    assert main(["verify", "--format", "html"]) == 2
    assert "-o" in capsys.readouterr().err


def _forms(x) -> set[str]:
    """How a number can be written in a test: 5.085, 5000, 2.0, 2.96e-4, 13.5e-4."""
    if isinstance(x, str):
        return {x}
    out = {f"{x:g}", repr(float(x)), str(x)}
    if float(x).is_integer():
        out.add(str(int(x)))
    for e in range(-6, 0):
        out.add(f"{x / 10**e:g}e{e}")
    return out


def test_published_values_agree_with_the_golden_tests():
    """The golden tests and the verification data state the same published numbers: every
    value a case takes as published (and reproduces) appears in the golden test it names."""
    missing = []
    for c in CASES:
        if not c.golden:
            continue
        src = (ROOT / c.golden).read_text(encoding="utf-8")
        for q in c.quantities:
            if q.departure is not None:
                continue  # the departures are checked against the docs below
            pattern = "|".join(
                r"(?<![\d.])" + re.escape(f) + r"(?![\d])" for f in _forms(q.published)
            )
            if not re.search(pattern, src):
                missing.append((c.id, q.name, q.published))
    assert missing == []


def test_every_departure_is_stated_in_the_docs():
    """Each departure names a file of the docs and the bold heading of its item there."""
    named = set()
    for c in CASES:
        for q in c.quantities:
            if q.departure is None:
                continue
            assert q.departure.reason and q.departure.doc, (c.id, q.name)
            path, heading = q.departure.doc.split(": ", 1)
            doc = ROOT / path
            assert doc.is_file(), (c.id, path)
            assert f"**{heading}" in doc.read_text(encoding="utf-8"), (c.id, heading)
            named.add(path)
    assert named == {"docs/reference/departures.md"}


def test_every_case_cites_the_bibliography():
    bib = tomllib.loads((ROOT / "catalogs" / "bibliography.toml").read_text(encoding="utf-8"))
    ids = {s["id"] for s in bib["source"]}
    assert {c.source for c in CASES} <= ids
    assert all(c.where and c.checked for c in CASES)


def test_tolerances_and_bounds():
    assert within(101.0, 100.0, 0.01, None)
    assert not within(101.1, 100.0, 0.01, None)
    assert within(100.4, 100.0, None, 0.5)
    assert within(1.3, 2.0, 0.0, None, "<=") and not within(2.1, 2.0, 0.0, None, "<=")
    assert within(2.1, 2.0, 0.0, None, ">=") and not within(1.9, 2.0, 0.0, None, ">=")
    assert within("II", "II", None, None) and not within("III", "II", None, None)
    assert not within(float("nan"), 1.0, 1.0, None)
    case = CASES[0]
    q = Quantity("x", 100.0, "W", "k", tolerance=0.01, departure=Departure(120.0, 0.001, None, "r"))
    assert judge(case, q, 100.5).verdict == "pass"
    assert judge(case, q, 120.05).verdict == "departure"
    assert judge(case, q, 110.0).verdict == "FAIL"
    assert judge(case, q, KeyError("gone")).verdict == "ERROR"


def test_report_paths():
    tree = {"a": {"b": [{"id": "x", "v": 1}, {"id": "y", "v": 2}]}, "n": [{"s": 10.0, "t": 3}]}
    assert lookup(tree, "a.b[id=y].v") == 2
    assert lookup(tree, "n[s=10].t") == 3
    with pytest.raises(KeyError):
        lookup(tree, "a.c")
    with pytest.raises(KeyError):
        lookup(tree, "a.b[id=z].v")
