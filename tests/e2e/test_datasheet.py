"""The datasheet (issue 17): one self-contained HTML file per report with every section and
every plot the report has data for, the same without plots as Markdown, the report as JSON;
matplotlib only on the HTML path, deterministic SVG."""

import json
import subprocess
import sys
import tomllib
from html.parser import HTMLParser
from pathlib import Path

import pytest
from helpers import EXAMPLES

from advisor.applications.rotary.plots import reducer_space
from advisor.cli import main
from advisor.core.engine import advise
from advisor.core.reading import read_requirements
from advisor.core.report import nest_curves, plain, to_toml
from advisor.datasheet import render
from advisor.datasheet.content import TIGHT_MARGIN, number, sheet
from advisor.datasheet.html import SECTIONS
from advisor.datasheet.plots import duty, plots

pytest.importorskip("matplotlib")

#: The plots each example's report has data for.
PLOTS = {
    "linear_screw_actuator.toml": ["motor-envelope", "motor-torque-speed"],
    "rudder_actuator.toml": [
        "motor-envelope",
        "motor-losses",
        "reducer-design-space",
        "reducer-fig1",
    ],
    "valve_actuator_hold.toml": [
        "motor-envelope",
        "motor-losses",
        "reducer-design-space",
        "reducer-fig1",
    ],
    "positioning_drive.toml": ["motor-envelope", "move-time-ratio"],
    "gyro_compensator.toml": ["run-up", "slew"],
    "rudder_actuator_duty.toml": [
        "motor-envelope",
        "motor-losses",
        "reducer-design-space",
        "reducer-fig1",
        "duty",
        "duty-speed",
        "duty-thermal",
    ],
}


class Page(HTMLParser):
    """What a reader finds in the page: sections, figures with their SVG, check rows,
    decisions, and anything that would load from outside the file."""

    def __init__(self) -> None:
        super().__init__()
        self.sections: list[str] = []
        self.figures: dict[str, int] = {}  # figure id → <path> elements in its <svg>
        self.check_rows: list[str] = []  # class of every row of the checks table
        self.decisions: list[str] = []
        self.external: list[str] = []
        self._figure: str | None = None
        self._section: str | None = None
        self._svg_open = False

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "section":
            self._section = a["id"]
            self.sections.append(a["id"])
        elif tag == "figure":
            self._figure = a["id"]
            self.figures[a["id"]] = 0
        elif tag == "svg" and self._figure:
            self._svg_open = True
        elif tag == "path" and self._svg_open:
            self.figures[self._figure] += 1
        elif tag == "tr" and self._section == "checks" and "class" in a:
            self.check_rows.append(a["class"])
        elif tag == "div" and a.get("class") == "decision":
            self.decisions.append(a["id"].removeprefix("decision-"))
        for k in ("src", "href"):
            if k in a and not str(a[k]).startswith("#"):
                self.external.append(a[k])
        if tag in ("script", "link", "img", "iframe"):
            self.external.append(tag)

    def handle_endtag(self, tag):
        if tag == "figure":
            self._figure = None
        elif tag == "svg":
            self._svg_open = False


@pytest.fixture(scope="module")
def reports():
    return {name: advise(read_requirements(EXAMPLES / name)) for name in PLOTS}


@pytest.mark.parametrize("name", sorted(PLOTS))
def test_html_has_every_section_and_every_plot(reports, name):
    report = reports[name]
    page = Page()
    page.feed(render(report, "html"))
    assert page.sections == [sid for sid, _ in SECTIONS]
    assert list(page.figures) == [f"plot-{p}" for p in PLOTS[name]]
    assert all(n > 3 for n in page.figures.values()), page.figures  # drawn, not empty
    assert len(page.check_rows) == len(report.checks)
    assert page.decisions == [d.id for d in report.decisions]
    assert page.external == []  # self-contained


def test_failing_and_tight_checks_are_marked(reports):
    report = reports["linear_screw_actuator.toml"]
    # the 4A71B4 carries 5.152 N·m against the screw's 5.085: margin 1.013 < 1.1
    page = Page()
    page.feed(render(report, "html"))
    tight = [c.id for c in report.checks if c.margin < TIGHT_MARGIN]
    assert tight == ["motor_rated_torque"]
    assert page.check_rows.count("tight") == 1 and "fails" not in page.check_rows
    doc = plain(report)
    doc["checks"][0].update(passed=False, margin=0.8)
    s = sheet(doc, "h", [])
    assert [c.status for c in s.checks][:1] == ["fails"]
    n = len(report.checks)
    assert s.summary[-1] == (
        "checks",
        f"{n} checks: {n - 1} pass (1 with a margin below 1.1), 1 fail",
    )


def test_decisions_carry_full_references(reports):
    html = render(reports["rudder_actuator.toml"], "html")
    assert "000_e109c3d4c17eaf1c.txt" not in html  # the seed file became a reference
    assert "Baranov et al. (seed 000), eqs. (13), (16)" in html
    # the references section is the report's own bibliography ([[sources]])
    assert "Baranov M. V., Borisov M. V." in html and "GOST 21427.2-83" in html


def test_self_locking_is_said_in_words(reports):
    md = render(reports["linear_screw_actuator.toml"], "md")
    assert "self-locking: a back-driving efficiency of -2.52 (≤ 0) means the load cannot" in md


def test_html_is_deterministic(reports):
    report = reports["gyro_compensator.toml"]
    first = render(report, "html")
    assert render(report, "html") == first
    assert "dc:date" not in first and "Matplotlib v" not in first


def test_markdown_has_the_sections_without_plots(reports):
    md = render(reports["rudder_actuator.toml"], "md")
    for head in ("## Summary", "## Warnings", "## Components", "## Checks", "## Decisions"):
        assert head in md
    assert "<svg" not in md
    assert "| ⚠ tight |" in md or "| ✓ |" in md
    # the reducer stages as a table with units in the headers
    assert "| position | ratio | rows | torque, N·m |" in md


def test_json_is_the_toml_document(reports):
    report = reports["positioning_drive.toml"]
    as_json = json.loads(render(report, "json"))
    assert as_json == tomllib.loads(to_toml(report))
    assert list(as_json)[-1] == "curves"
    assert (
        nest_curves(as_json)["design"]["motion"]["curve"]
        == plain(report)["design"]["motion"]["curve"]
    )


def test_numbers_read_as_engineers_write_them():
    assert number(0.219099) == "0.2191"
    assert number(1200.0) == "1200"
    assert number(-2.51905) == "-2.519"


def test_the_duty_plot_steps_through_the_phases(reports):
    doc = plain(reports["rudder_actuator_duty.toml"])
    d = duty(doc)
    phases = doc["design"]["duty"]["phases"]
    torque = d.lines[0]
    assert torque.y[:-1] == [p["torque_Nm"] for p in phases]
    assert torque.x[-1] == pytest.approx(sum(p["time_s"] for p in phases))
    assert torque.x[-1] == pytest.approx(doc["design"]["duty"]["cycle_time_s"])
    assert [y for y, _ in d.hlines] == [
        doc["design"]["duty"]["rms_torque_Nm"],
        doc["design"]["duty"]["peak_torque_limit_Nm"],
    ]


def test_pareto_front_and_duty_when_the_report_has_them():
    doc = {
        "report": {"application": "rotary"},
        "requirements": {"envelope": {"max_outer_diameter_mm": 180.0}},
        "design": {
            "gearbox": {
                "mass_kg": 5.6,
                "outer_diameter_mm": 156.0,
                "optimum": {"mass_kg": 2.0, "outer_diameter_mm": 114.0},
                "pareto": {
                    "points": [
                        {"mass_kg": 2.0, "outer_diameter_mm": 114.0},
                        {"mass_kg": 3.0, "outer_diameter_mm": 95.0},
                    ]
                },
            },
            "duty": {
                "segments": [
                    {"duration_s": 2.0, "torque_Nm": 10.0},
                    {"duration_s": 3.0, "torque_Nm": -4.0},
                ]
            },
        },
    }
    space = reducer_space(doc)
    front = space.lines[0]
    assert front.label.startswith("Pareto front") and front.x == [95.0, 114.0]
    assert space.vlines == [(180.0, "envelope Ø180 mm")]
    d = duty(doc)
    assert d.lines[0].x == [0.0, 2.0, 5.0] and d.lines[0].y == [10.0, -4.0, -4.0]
    assert [p.id for p in plots(doc)] == ["reducer-design-space", "duty"]
    # absent: no plot, no error
    del doc["design"]["gearbox"]["pareto"], doc["design"]["duty"]
    assert not reducer_space(doc).lines[0].label.startswith("Pareto")
    assert duty(doc) is None


def test_the_design_space_of_the_rudder_shows_its_pareto_front(reports):
    doc = plain(reports["rudder_actuator.toml"])
    pareto = doc["design"]["gearbox"]["pareto"]  # columns, lightest first
    space = reducer_space(doc)
    labels = [line.label for line in space.lines]
    assert (
        labels[0]
        == f"Pareto front (mass, diameter, length, efficiency): {len(pareto['mass_kg'])} of {pareto['front_size']} designs"
    )
    assert sorted(space.lines[0].y) == sorted(pareto["mass_kg"])
    assert labels[1:] == [
        "least mass in the design space",
        "least diameter in the design space",
        "the rule's design (adopted)",
        "lightest design that dominates the rule's",
    ]
    g = doc["design"]["gearbox"]
    assert space.lines[3].x == [g["outer_diameter_mm"]] and space.lines[3].y == [g["mass_kg"]]


def test_cli_writes_the_datasheet(tmp_path, capsys):
    out = tmp_path / "design.html"
    assert (
        main(
            [
                "--batch",
                str(EXAMPLES / "linear_screw_actuator.toml"),
                "--format",
                "html",
                "-o",
                str(out),
            ]
        )
        == 0
    )
    assert "report written to" in capsys.readouterr().out
    assert out.read_text(encoding="utf-8").startswith("<!DOCTYPE html>")
    # -o with a known suffix and no --format: the suffix decides
    md = tmp_path / "design.md"
    assert main(["--batch", str(EXAMPLES / "linear_screw_actuator.toml"), "-o", str(md)]) == 0
    assert md.read_text(encoding="utf-8").startswith("# ")
    capsys.readouterr()
    # stdout stays TOML by default
    assert main(["--batch", str(EXAMPLES / "linear_screw_actuator.toml")]) == 0
    assert tomllib.loads(capsys.readouterr().out)["report"]["format"] == 1


def test_cli_refuses_a_datasheet_for_many_files(tmp_path, capsys):
    assert main(["--batch", str(EXAMPLES), "--out-dir", str(tmp_path), "--format", "html"]) == 2
    assert capsys.readouterr().err == (
        "advisor: --format html takes one input; with --out-dir the reports are TOML\n"
    )


def _run(code: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)


def test_matplotlib_only_on_the_html_path(tmp_path):
    src = str(EXAMPLES / "rudder_actuator.toml")
    out = tmp_path / "design."
    code = (
        "import sys\n"
        "from advisor.cli import main\n"
        "for fmt in ('toml', 'json', 'md'):\n"
        f"    assert main(['--batch', {src!r}, '--format', fmt, '-o', {str(out)!r} + fmt]) == 0\n"
        "print('MPL', 'matplotlib' in sys.modules)\n"
        f"assert main(['--batch', {src!r}, '--format', 'html', '-o', {str(out)!r} + 'html']) == 0\n"
        "print('MPL', 'matplotlib' in sys.modules)\n"
    )
    r = _run(code)
    assert r.returncode == 0, r.stderr
    assert [line for line in r.stdout.splitlines() if line.startswith("MPL")] == [
        "MPL False",
        "MPL True",
    ]


def test_html_without_matplotlib_is_one_line_exit_2(tmp_path):
    src = str(EXAMPLES / "linear_screw_actuator.toml")
    out = tmp_path / "d.html"
    code = (
        "import sys\n"
        "sys.modules['matplotlib'] = None  # as if it were not installed\n"
        "from advisor.cli import main\n"
        f"sys.exit(main(['--batch', {src!r}, '--format', 'html', '-o', {str(out)!r}]))\n"
    )
    r = _run(code)
    assert r.returncode == 2
    assert r.stderr == (
        "advisor: --format html draws its plots with matplotlib, which is not installed: "
        "pip install 'drive-advisor[report]'\n"
    )
    assert not Path(out).exists()
