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


# ------------------------------------------------------------------ hostile data and targets
#: One direct calculation: seed 002's 4453 rad/s is 4453·30/π = 42523.2 rpm.
ONE_CASE = """[[case]]
id = "c1"
title = "t"
source = "s"
where = "w"
checked = "c"
kind = "calc"
function = "seed002_speed"
inputs = { speed_rad_s = 4453 }

[[case.quantity]]
name = "n"
key = "speed_rpm"
published = 42523
unit = "rpm"
tolerance = 0.001
"""


def _data(tmp_path: Path, text: str, name: str = "data.toml") -> Path:
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


def test_a_one_case_set_verifies(tmp_path, capsys):
    p = _data(tmp_path, ONE_CASE)
    assert main(["verify", "--data", str(p)]) == 0
    line = next(ln for ln in capsys.readouterr().out.splitlines() if ln.startswith("c1 "))
    assert "42523" in line and "pass" in line


def test_output_onto_the_data_itself_is_refused(tmp_path, capsys):
    p = _data(tmp_path, ONE_CASE)
    for target in (p, tmp_path / "." / "data.toml"):
        assert main(["verify", "--data", str(p), "-o", str(target)]) == 2
        out, err = capsys.readouterr()
        assert out == ""
        assert err.count("\n") == 1 and "is the verification data itself" in err
    assert p.read_text(encoding="utf-8") == ONE_CASE
    link = tmp_path / "link.toml"
    link.symlink_to(p)
    assert main(["verify", "--data", str(p), "-o", str(link)]) == 2
    assert p.read_text(encoding="utf-8") == ONE_CASE


def test_output_into_a_missing_folder_or_a_directory_is_one_line(tmp_path, capsys):
    p = _data(tmp_path, ONE_CASE)
    for target in (tmp_path / "nodir" / "x.txt", tmp_path):
        assert main(["verify", "--data", str(p), "-o", str(target)]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and str(target) in err
    assert sorted(x.name for x in tmp_path.iterdir()) == ["data.toml"]


def test_output_is_written_atomically_and_said(tmp_path, capsys):
    p = _data(tmp_path, ONE_CASE)
    out = tmp_path / "v.txt"
    out.write_text("old", encoding="utf-8")
    out.chmod(0o640)
    assert main(["verify", "--data", str(p), "-o", str(out)]) == 0
    text = out.read_text(encoding="utf-8")
    assert "c1 " in text and text.rstrip().endswith("verified")
    assert out.stat().st_mode & 0o777 == 0o640  # an existing file keeps its mode
    assert sorted(x.name for x in tmp_path.iterdir()) == ["data.toml", "v.txt"]  # no temp left
    assert capsys.readouterr().out.endswith(f"(report: {out})\n")


QUANTITY = ONE_CASE.split("[[case.quantity]]\n", 1)[1]


@pytest.mark.parametrize(
    ("text", "says"),
    [
        ("case = 5\n", "case must be an array of tables, not a number"),
        ("case = [1]\n", "case[0] must be a table, not a number"),
        (ONE_CASE.split("[[case.quantity]]")[0] + "quantity = 5\n", "case c1: quantity must be"),
        (ONE_CASE.split("[[case.quantity]]")[0], "case c1: quantity is missing"),
        (
            ONE_CASE.replace("published = 42523", 'published = [1, 2]\nrelation = "<="'),
            "case c1: quantity[0]: published must be a finite number or text, not an array",
        ),
        (
            ONE_CASE.replace("published = 42523", 'published = "x"\nrelation = "<="'),
            "case c1: quantity 'n': published must be a number with relation '<='",
        ),
        (ONE_CASE.replace("published = 42523", "published = nan"), "published must be a finite"),
        (ONE_CASE.replace("tolerance = 0.001", "tolerance = -1"), "tolerance must be a finite"),
        (ONE_CASE.replace("tolerance = 0.001", ""), "quantity 'n': tolerance (or abs_tolerance)"),
        (ONE_CASE.replace('key = "speed_rpm"', ""), "quantity 'n': path (or key) is missing"),
        (ONE_CASE.replace('unit = "rpm"', 'unit = "rpm"\nrelation = ">="'), None),  # a bound
        (ONE_CASE.replace('unit = "rpm"', 'unit = "rpm"\nrelation = "<"'), "relation '<' is not"),
        (ONE_CASE.replace('name = "n"', "name = 5"), "quantity[0]: name must be text"),
        (ONE_CASE.replace('function = "seed002_speed"', 'function = "__init__"'), "'__init__'"),
        (ONE_CASE.replace('function = "seed002_speed"', ""), "case c1: function is missing"),
        (ONE_CASE.replace('kind = "calc"', 'kind = "x"'), "case c1: kind 'x' is not"),
        (ONE_CASE.replace('kind = "calc"', 'kind = "requirement"'), "requirement is missing"),
        (ONE_CASE.replace('id = "c1"', ""), "case[0]: id is missing"),
        (ONE_CASE.replace('title = "t"', "title = 5"), "case c1: title must be text, not a"),
        (ONE_CASE.replace("inputs = {", "inputs = 5\nx = {"), "case c1: inputs must be a table"),
        (ONE_CASE + "departure = 5\n", "quantity[0]: departure must be a table"),
        (ONE_CASE + "[case.quantity.departure]\nexpected = 1\n", "departure: reason is missing"),
        (ONE_CASE + ONE_CASE, "case id 'c1' is not unique"),
    ],
)
def test_malformed_data_is_one_line_naming_file_case_and_key(tmp_path, capsys, text, says):
    p = _data(tmp_path, text)
    code = main(["verify", "--data", str(p), "--list"])
    out, err = capsys.readouterr()
    if says is None:
        assert code == 0 and out == "c1  t\n"
        return
    assert code == 2 and out == ""
    assert err.startswith(f"advisor: {p}: ") and err.count("\n") == 1
    assert says in err


@pytest.mark.parametrize(
    "text", ["", "[application]\nkind = 'rotary'\n", (ROOT / "examples" / "gyro_compensator.toml")]
)
def test_a_file_without_cases_is_refused(tmp_path, capsys, text):
    p = text if isinstance(text, Path) else _data(tmp_path, text)
    assert main(["verify", "--data", str(p)]) == 2
    assert (
        capsys.readouterr().err == f"advisor: no verification cases in {p} (no [[case]] tables)\n"
    )


def test_broken_toml_and_missing_data_name_the_file(tmp_path, capsys):
    p = _data(tmp_path, "[[case]\n")
    assert main(["verify", "--data", str(p)]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"advisor: {p}: broken TOML: ") and err.count("\n") == 1
    assert main(["verify", "--data", str(tmp_path / "none.toml")]) == 2
    err = capsys.readouterr().err
    assert err == f"advisor: verification data {tmp_path / 'none.toml'}: no such file\n"
