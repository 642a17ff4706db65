"""The datasheet as a review document (issue 28, item 1): the header from [project], every
requirement beside what the design achieves, the load cycle, the motor's envelope with the
operating points, a utilisation bar per check, the parts list; deterministic; the Markdown
kept as a golden file (``UPDATE_GOLDEN=1`` rewrites it)."""

import os
from html.parser import HTMLParser
from pathlib import Path

import pytest
from helpers import EXAMPLES

from advisor.core.engine import advise
from advisor.core.reading import parse_requirements, read_requirements
from advisor.datasheet import _sheet, render
from advisor.datasheet.labels import short_description, split_key
from advisor.datasheet.review import covering

pytest.importorskip("matplotlib")

NAMES = sorted(p.name for p in EXAMPLES.glob("*.toml"))
GOLDEN = Path(__file__).parents[1] / "golden" / "datasheet_gyro_compensator.md"


class Review(HTMLParser):
    """What a reviewer finds: the header cells, the required-vs-achieved rows (by the
    requirement's path), the load-cycle rows, the figures with their points, the bars."""

    def __init__(self) -> None:
        super().__init__()
        self.section: str | None = None
        self.header: list[str] = []
        self.required: list[str] = []
        self.cycle_rows = 0
        self.figures: dict[str, int] = {}
        self.bars: list[float] = []
        self._figure: str | None = None
        self._text = False

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "section":
            self.section = a["id"]
        elif tag == "th" and self.section == "header":
            self._text = True
        elif tag == "tr" and self.section == "required" and "data-path" in a:
            self.required.append(a["data-path"])
        elif tag == "tr" and self.section == "load-cycle":
            self.cycle_rows += 1
        elif tag == "figure":
            self._figure = a["id"]
            self.figures[self._figure] = 0
        elif tag == "use" and self._figure:  # a marker drawn: matplotlib <use>s its shape
            self.figures[self._figure] += 1
        elif tag == "div" and a.get("role") == "meter":
            self.bars.append(float(a["aria-valuenow"]))

    def handle_endtag(self, tag):
        if tag == "figure":
            self._figure = None
        elif tag == "th":
            self._text = False

    def handle_data(self, data):
        if self._text and data.strip():
            self.header.append(data.strip())


@pytest.fixture(scope="module")
def reports():
    return {name: advise(read_requirements(EXAMPLES / name)) for name in NAMES}


@pytest.mark.parametrize("name", NAMES)
def test_every_example_reads_as_a_review_document(reports, name):
    report = reports[name]
    html = render(report, "html")
    page = Review()
    page.feed(html)
    sheet, doc = _sheet(report)
    assert page.header[:3] == ["Project", "Document number", "Revision"]
    # one row per requirement field given (not at its default), in the file's order
    assert page.required == [r.path for r in sheet.required] and page.required
    assert all(r.check for r in sheet.required)
    # a utilisation bar per check: demand over capacity, 1 / margin
    assert page.bars == [round(1 / c.margin, 3) for c in report.checks]
    phases = doc["design"].get("duty", {}).get("phases")
    if phases:
        assert page.cycle_rows == len(phases) + 1  # the header row and one per phase
    envelope = page.figures.get("plot-motor-envelope")
    if "motion" in doc["design"] or "motor" in doc["design"]:
        assert envelope is not None
        if phases or "screw" in doc["design"] or "gearbox" in doc["design"]:
            assert envelope >= 1  # operating points drawn on it


def test_the_header_comes_from_the_project_table_never_the_clock(tmp_path):
    text = (EXAMPLES / "linear_screw_actuator.toml").read_text(encoding="utf-8")
    text += '\n[project]\nname = "Valve line 3"\ndocument_number = "DA-7"\ndate = "2024-02-29"\n'
    import tomllib

    report = advise(parse_requirements(tomllib.loads(text)))
    sheet, _ = _sheet(report)
    assert dict(sheet.project) == {
        "Project": "Valve line 3",
        "Document number": "DA-7",
        "Revision": "",
        "Date": "2024-02-29",
        "Author": "",
        "Checked by": "",
        "Approved by": "",
    }
    html = render(report, "html")
    assert "2024-02-29" in html and render(report, "html") == html
    assert "| Document number | DA\\-7 |" not in render(report, "md")  # "-" mid-cell is text
    assert "| Document number | DA-7 |" in render(report, "md")


def test_required_vs_achieved_of_the_linear_actuator(reports):
    sheet, _ = _sheet(reports["linear_screw_actuator.toml"])
    rows = {r.path: r for r in sheet.required}
    # seed 001: 5 s asked, 0.2 m at 2 mm a turn = 100 turns at 1392.47 rpm = 4.309 s
    travel = rows["linear.travel_time_s"]
    assert (travel.label, travel.value, travel.unit) == ("Time for the stroke", "5", "s")
    assert travel.check_id == "travel_time"
    assert travel.achieved == "4.309 against 5 s" and travel.margin == "1.160"
    # the force is covered by several checks; the governing one is the least margin
    force = rows["linear.force_N"]
    assert force.value == "3500" and force.unit == "N" and force.more >= 3
    assert force.check_id == "motor_rated_torque" and force.status == "tight"
    # a field at its default is counted, not listed
    assert "linear.end_fixity" not in rows and sheet.at_default > 0


def test_the_load_cycle_table_by_hand(reports):
    sheet, _ = _sheet(reports["indexing_table_duty.toml"])
    assert sheet.cycle.columns == ["phase", "time, s", "speed, rpm", "torque, N·m", "power, W"]
    accelerate = sheet.cycle.rows[0]
    # motor C: ω0 = 100 rad/s (954.93 rpm), M_λ = 45 N·m: P = 45 × 100 = 4500 W
    assert accelerate == ["accelerate", "0.3909", "954.9", "45", "4500"]
    assert sheet.cycle.rows[2][4] == "-4500"  # braking: the load drives the motor


def test_parts_name_what_a_buyer_orders(reports):
    sheet, _ = _sheet(reports["linear_screw_actuator.toml"])
    by = {r[0]: r for r in sheet.parts}
    assert by["motor"][1] == "4A71B4" and "rated power 0.75 kW" in by["motor"][2]
    assert by["motor"][4] == "15.1 kg" and "4A motor table" in by["motor"][5]
    assert by["screw"][1] == "Tr16x2" and "nominal diameter 16 mm" in by["screw"][3]
    sheet, _ = _sheet(reports["gyro_compensator.toml"])
    bearing = next(r for r in sheet.parts if r[1] == "7000 CD")
    assert "bore d 10 mm; outside diameter D 26 mm; width B 8 mm" == bearing[3]


def test_labels_are_words_not_keys(reports):
    assert split_key("p15_50_W_kg") == ("specific loss at 1.5 T, 50 Hz", "W/kg")
    assert short_description("torque at that current, 10⁻³ … 10⁴ N·m") == "torque at that current"
    html = render(reports["rudder_actuator.toml"], "html")
    assert ">p15 50<" not in html and "specific loss at 1.5 T, 50 Hz" in html


def test_covering_by_table_pattern_and_name():
    ids = ["duty_rms", "travel_time", "buckling", "nut_pressure"]
    covers = {"duty": ("duty_*",), "linear.force_N": ("nut_*", "buckling")}
    assert covering(("duty", "cycle_time_s"), covers, ids) == ["duty_rms"]
    assert covering(("linear", "force_N"), covers, ids) == ["buckling", "nut_pressure"]
    assert covering(("linear", "travel_time_s"), covers, ids) == ["travel_time"]
    assert covering(("screw", "lubrication"), covers, ids) == []


def test_the_loss_plot_draws_the_reports_curve_and_the_candidates_as_points(reports):
    """The losses against speed are the report's own curve (design.motor.loss_curve, the U
    the speed choice rests on), not a straight line between candidates: lines through the
    curve's points, the candidates as points on it."""
    from advisor.applications.rotary.plots import motor_losses
    from advisor.core.report import plain

    doc = plain(reports["rudder_actuator.toml"])
    plot = motor_losses(doc)
    curve = doc["design"]["motor"]["loss_curve"]
    lines = {line.label: line for line in plot.lines}
    assert lines["total"].style == "line" and lines["total"].x == curve["speed_rpm"]
    assert len(curve["speed_rpm"]) > 30  # a curve, not two points
    total = dict(zip(curve["speed_rpm"], curve["total_W"], strict=True))
    points = lines["candidates (total)"]
    assert points.style == "points"
    for n, loss in zip(points.x, points.y, strict=True):
        assert total[n] == pytest.approx(loss, rel=1e-12)  # the candidates lie on the curve
    u = curve["total_W"]
    assert min(u) < u[0] and min(u) < u[-1]  # U-shaped: the optimum lies inside
    assert [label for _, label in plot.vlines][-1].startswith("loss optimum 4055")
    assert plot.hlines and plot.hlines[0][1].startswith("frame's limit 228.4")
    assert set(curve["limit_W"]) == {doc["design"]["motor"]["loss_limit_W"]}


def test_without_a_curve_the_loss_plot_draws_points_only(reports):
    from advisor.applications.rotary.plots import motor_losses
    from advisor.core.report import plain

    doc = plain(reports["rudder_actuator.toml"])
    del doc["design"]["motor"]["loss_curve"]
    assert {line.style for line in motor_losses(doc).lines} == {"points"}


@pytest.mark.parametrize("fmt", ["html", "md"])
def test_two_renders_are_byte_identical(reports, fmt):
    report = reports["rudder_actuator_duty.toml"]
    assert render(report, fmt) == render(report, fmt)


def test_markdown_golden(reports):
    md = render(reports["gyro_compensator.toml"], "md")
    if os.environ.get("UPDATE_GOLDEN"):
        GOLDEN.parent.mkdir(exist_ok=True)
        GOLDEN.write_text(md, encoding="utf-8")
    assert md == GOLDEN.read_text(encoding="utf-8"), "UPDATE_GOLDEN=1 pytest … to accept"
