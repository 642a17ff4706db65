"""An infeasible run reports (issue 28, item 2): exit 3 still, and with -o or a datasheet
format a report with status = "infeasible" that says why, the failing checks with their
numbers, the nearest design and what would make it feasible."""

import tomllib
from html.parser import HTMLParser

import pytest
from helpers import EXAMPLES

from advisor.calc.checks import Check
from advisor.cli import main
from advisor.core.cite import cite
from advisor.core.errors import ExitCode, InfeasibleError
from advisor.core.reading import read_requirements
from advisor.core.report import to_toml
from advisor.infeasible import infeasible_report, shortfall
from advisor.summary import summary_lines

# not among the examples every test runs (those are feasible): in a folder of its own
EXAMPLE = EXAMPLES / "infeasible" / "screw_buckles.toml"


def test_the_example_exits_3_and_writes_its_report(tmp_path, capsys):
    out = tmp_path / "r.toml"
    assert main(["--batch", str(EXAMPLE), "-o", str(out)]) == ExitCode.INFEASIBLE
    io = capsys.readouterr()
    assert "(infeasible)" in io.out and "no feasible design" in io.err
    doc = tomllib.loads(out.read_text(encoding="utf-8"))
    assert doc["report"]["status"] == "infeasible"
    assert doc["requirements"]["linear"]["force_N"] == 5e6
    d = doc["design"]
    assert d["summary"].startswith("no feasible design")
    # the nearest candidate, the largest thread, and the check it misses by most: buckling
    assert any(r.startswith("Tr100x20: buckling between supports") for r in d["reasons"])


def test_without_output_the_report_goes_to_stdout(tmp_path, capsys):
    """As a design's TOML does, and as --format json and md already did: the report saying
    why is on stdout, the reasons on stderr, exit 3 (`advisor --batch f.toml > r.toml` wrote
    an empty r.toml)."""
    assert main(["--batch", str(EXAMPLE)]) == ExitCode.INFEASIBLE
    io = capsys.readouterr()
    assert "no feasible design" in io.err
    assert tomllib.loads(io.out)["report"]["status"] == "infeasible"
    out = tmp_path / "r.toml"
    assert main(["--batch", str(EXAMPLE), "-o", str(out)]) == ExitCode.INFEASIBLE
    assert io.out == out.read_text(encoding="utf-8")


@pytest.mark.parametrize("fmt", ["md", "html"])
def test_its_datasheet_renders(tmp_path, capsys, fmt):
    pytest.importorskip("matplotlib")
    out = tmp_path / f"r.{fmt}"
    assert main(["--batch", str(EXAMPLE), "-o", str(out)]) == ExitCode.INFEASIBLE
    capsys.readouterr()
    text = out.read_text(encoding="utf-8")
    assert "infeasible" in text and "Tr100x20" in text
    if fmt == "html":
        ids: list[str] = []

        class P(HTMLParser):
            def handle_starttag(self, tag, attrs):
                if tag == "section":
                    ids.append(dict(attrs)["id"])

        P().feed(text)
        assert ids[:3] == ["header", "summary", "required"]


def test_a_design_that_fails_its_checks_says_what_it_would_take():
    req = read_requirements(EXAMPLES / "linear_screw_actuator.toml")
    ok = Check("travel_time", "travel time", 4.3, 5.0, "s", 5.0 / 4.3, cite("GOST-12139-84"))
    # 15 turns where 10 are allowed: margin 10/15; 50 % more capacity or a third less demand
    bad = Check("nut_turns", "engaged nut turns", 15.0, 10.0, "", 10.0 / 15.0, cite("GOST"))
    exc = InfeasibleError(
        "no feasible design: the chosen parts fail checks",
        ["engaged nut turns: 15 against 10"],
        checks=[ok, bad],
        nearest="screw Tr16x2, motor 4A71B4",
    )
    report = infeasible_report(req, exc)
    assert report.report.status == "infeasible"
    assert [c.passed for c in report.checks] == [True, False]
    assert report.design.to_be_feasible == [
        "engaged nut turns: 15 against the limit 10 (margin 0.667): 50 % more capacity, "
        "or 33 % less demand"
    ]
    assert 'status = "infeasible"' in to_toml(report)
    lines = summary_lines(report, EXAMPLE)
    assert "nearest         screw Tr16x2, motor 4A71B4" in lines  # aligned to "to be feasible"
    assert any(line.startswith("to be feasible") for line in lines)


def test_shortfall_by_hand():
    # buckling: 5 MN against 3138 N: margin 6.276e-4; 5e6 / 3138 = 1593.37 times the capacity;
    # the demand must fall by 1 − 6.276e-4 = 99.937 %, not to nothing ("100 %")
    text = shortfall("buckling", 5e6, 3138.0, "N", 3138.0 / 5e6)
    assert text.startswith("buckling: 5e+06 N against the limit 3138 N (margin 0.001): ")
    assert "159237 % more capacity" in text and "99.94 % less demand" in text
    # a margin a hair below 1 (1 − 8.6e-13) misses by 8.6e-11 %, not "0 %"
    tiny = shortfall("speed", 1.0, 1.0, "rpm", 1.0 - 8.6e-13)
    assert "8.6e-11 % more capacity, or 8.6e-11 % less demand" in tiny


def test_a_life_shortfall_is_said_in_the_load_and_the_rating():
    """L10h ∝ (C/P)³ (ISO 281:2007, eq. (1), ball bearings): a life of 0.004776 h against
    1000 h (margin 4.776e-6) needs P lower by 1 − (4.776e-6)^(1/3) = 1 − 0.016840 = 98.3 %,
    or C higher by 1/0.016840 − 1 = 58.38 → 5838 %; not "100 % less demand" (a required life
    of nothing). Other checks keep the capacity/demand wording."""
    m = 0.004776 / 1000.0
    text = shortfall("basic rating life L10h", 0.004776, 1000.0, "h", m, "bearing_life")
    assert text.endswith("the load P lower by 98 %, or the rating C higher by 5838 %")
    assert "less demand" not in text
    same = shortfall("output bearing L10h", 500.0, 1000.0, "h", 0.5, "output_bearing_life")
    assert same.endswith("the load P lower by 21 %, or the rating C higher by 26 %")
    other = shortfall("static safety", 0.5, 1.0, "", 0.5, "bearing_static")
    assert other.endswith("100 % more capacity, or 50 % less demand")


def test_many_files_write_the_infeasible_report_beside_the_designs(tmp_path, capsys):
    """--out-dir: the infeasible file gets its report with its status, as -o gives it; the
    feasible one its design; the run's exit code is the worst, 3."""
    out = tmp_path / "out"
    ok = EXAMPLES / "linear_screw_actuator.toml"
    assert main(["--batch", str(EXAMPLE), str(ok), "--out-dir", str(out)]) == 3
    bad = tomllib.loads((out / "screw_buckles.report.toml").read_text(encoding="utf-8"))
    assert bad["report"]["status"] == "infeasible"
    assert bad["design"]["summary"].startswith("no feasible design")
    good = tomllib.loads((out / "linear_screw_actuator.report.toml").read_text(encoding="utf-8"))
    assert good["report"].get("status", "feasible") != "infeasible"
    assert "screw_buckles.toml" in capsys.readouterr().out


def test_the_wizard_says_what_the_report_says():
    """The wizard's summary of an infeasible requirement names the nearest design and how
    far each failing check misses, in the report's own words: 15 turns against 10 needs
    10/15 → 50 % more capacity or 33 % less demand."""
    from advisor.tui.views import infeasible

    check = Check("nut_turns", "engaged nut turns", 15.0, 10.0, "", 10.0 / 15.0, cite("seed-001"))
    exc = InfeasibleError(
        "no feasible design: the chosen parts fail checks",
        ["nut turns: 15 against 10"],
        checks=[check],
        nearest="Tr16x2 + 4A71B4",
    )
    text = infeasible(exc).plain
    assert "Nearest: Tr16x2 + 4A71B4" in text
    assert shortfall(check.name, 15.0, 10.0, "", check.margin) in text
    assert "50 % more capacity, or 33 % less demand" in text


def test_an_infeasible_report_keeps_a_checks_service_factor():
    """A failing strength check under f_B = 1.5 (3500 N × 1.5 against 3707 N: margin
    3707/5250 = 0.706) keeps its factor in the infeasible report, as in a design's."""
    req = read_requirements(EXAMPLE)
    check = Check(
        "buckling", "buckling", 3500.0, 3707.0, "N", 3707.0 / 5250.0, cite("seed-001"), 1.5
    )
    exc = InfeasibleError("no feasible design: the chosen parts fail checks", ["x"], checks=[check])
    out = infeasible_report(req, exc).checks[0]
    assert out.factor == 1.5 and out.margin == pytest.approx(0.706, abs=5e-4)
    assert out.sources == ["seed-001"]
