"""The drivers of P(pass) as a tornado chart (issue 30, part 2): in the HTML datasheet (an
SVG bar per input, ρ-long, largest |ρ| on top), in the Markdown (the same numbers as a
table) and in the wizard (a bar plot of the least probable check, P(pass) in the Summary and
the Checks views)."""

import io
import math
import re
import tomllib
from html.parser import HTMLParser

import pytest
from helpers import EXAMPLES

from advisor.core.engine import advise
from advisor.core.reading import read_requirements
from advisor.datasheet import render
from advisor.uncertainty.drivers import charted, input_label, least_probable, tornado

ROBUST = EXAMPLES / "uncertainty" / "linear_screw_robust.toml"
FRICTION, FORCE = "Thread friction coefficient f", "Axial force"


@pytest.fixture(scope="module")
def report():
    return advise(read_requirements(ROBUST))


def _check(report, cid: str):
    return next(c for c in report.uncertainty.checks if c.id == cid)


def _rho(report, cid: str) -> dict[str, float]:
    return {d.input: d.rank_correlation for d in _check(report, cid).drivers}


def wilson(p: float, n: int, z: float = 1.959964) -> tuple[float, float]:
    """Wilson's score interval, written out: (p + z²/2n ± z·√(p(1−p)/n + z²/4n²)) / (1 + z²/n)."""
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z / (1 + z * z / n) * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n))
    return centre - half, centre + half


class Sheet(HTMLParser):
    """The Probability of passing section: its headings, and per figure the heading before
    it, the ids of its driver bars with each bar's path, and its text."""

    def __init__(self) -> None:
        super().__init__()
        self.section: str | None = None
        self.headings: list[str] = []
        self.figures: dict[str, dict] = {}
        self._figure: str | None = None
        self._heading = False
        self._bar: str | None = None
        self._in_text = False

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "section":
            self.section = a["id"]
        if self.section != "uncertainty":
            return
        if tag == "h3":
            self._heading = True
            self.headings.append("")
        elif tag == "figure":
            self._figure = a["id"]
            self.figures[self._figure] = {"heading": self.headings[-1], "bars": {}, "text": []}
        elif tag == "g" and self._figure and a.get("id", "").startswith("driver-"):
            self._bar = a["id"].removeprefix("driver-")
            self.figures[self._figure]["bars"][self._bar] = []
        elif tag == "path" and self._bar is not None:
            self.figures[self._figure]["bars"][self._bar].append(a)
        elif tag == "text" and self._figure:
            self._in_text = True

    def handle_endtag(self, tag):
        if tag == "h3":
            self._heading = False
        elif tag == "figure":
            self._figure = None
        elif tag == "g":
            self._bar = None
        elif tag == "text":
            self._in_text = False

    def handle_data(self, data):
        if self._heading:
            self.headings[-1] += data
        elif self._in_text and self._figure:
            self.figures[self._figure]["text"].append(data)


def _width(path: dict) -> float:
    """The horizontal extent of an SVG path (a bar's rectangle)."""
    xs = [float(x) for x in re.findall(r"[ML] ([-\d.]+) [-\d.]+", path["d"])]
    return max(xs) - min(xs)


def test_the_wilson_interval_of_the_title_is_the_reports(report):
    # 6 failures in 10 000 samples: P = 0.9994; by hand (z = 1.96) 0.998691 … 0.999725
    low, high = wilson(0.9994, 10_000)
    c = _check(report, "motor_rated_torque")
    assert (c.p_pass, c.p_pass_low, c.p_pass_high) == pytest.approx((0.9994, low, high), abs=1e-6)
    assert (round(low, 4), round(high, 4)) == (0.9987, 0.9997)


def test_the_html_datasheet_draws_a_tornado_of_the_least_probable_check(report):
    pytest.importorskip("matplotlib")
    page = Sheet()
    page.feed(render(report, "html"))
    # the only check that fails in some samples is the motor's rated torque (P = 0.9994, the
    # others 1.0): one chart, under a heading naming it
    assert list(page.figures) == ["tornado-motor_rated_torque"]
    fig = page.figures["tornado-motor_rated_torque"]
    assert fig["heading"] == (
        "Tornado chart: drivers of motor rated torque against the screw torque"
    )
    # one bar per input, the larger |ρ| first (friction −0.87, then force −0.46)
    rho = _rho(report, "motor_rated_torque")
    assert list(fig["bars"]) == ["screw.friction_coefficient", "linear.force_N"]
    assert abs(rho["screw.friction_coefficient"]) > abs(rho["linear.force_N"])
    # each bar as long as its ρ: 0.871209 / 0.455164 = 1.914
    widths = {k: _width(v[0]) for k, v in fig["bars"].items()}
    ratio = widths["screw.friction_coefficient"] / widths["linear.force_N"]
    assert ratio == pytest.approx(
        rho["screw.friction_coefficient"] / rho["linear.force_N"], rel=1e-3
    )
    assert ratio == pytest.approx(1.914, abs=1e-3)
    text = " ".join(fig["text"])
    assert FRICTION in text and FORCE in text  # the inputs by their labels
    assert "P(pass) = 0.9994 (95 % interval 0.9987 … 0.9997)" in text
    assert "−0.87" in text and "−0.46" in text  # the values at the bars' ends


def test_a_bar_that_raises_the_margin_is_hatched(report):
    """Grey print: a positive ρ is told from a negative one by its hatching, not a colour."""
    pytest.importorskip("matplotlib")
    from advisor.datasheet.plots import tornado_svg
    from advisor.uncertainty.drivers import labels_of

    # the whirling margin rises with friction (a slower motor): ρ = +0.87, +0.46
    t = tornado(_check(report, "critical_speed"), labels_of("linear"))
    assert [b.rho > 0 for b in t.bars] == [True, True]
    buckling = tornado(_check(report, "buckling"), labels_of("linear"))
    assert [b.input for b in buckling.bars] == ["linear.force_N", "screw.friction_coefficient"]
    page = Sheet()
    page.feed(f'<section id="uncertainty"><h3>x</h3><figure id="f">{tornado_svg(buckling, "s")}')
    bars = page.figures["f"]["bars"]
    hatched = {k: any("url(#h" in p.get("style", "") for p in v) for k, v in bars.items()}
    # force: ρ = −1.00 (solid); friction: ρ = +0.02 (hatched)
    assert hatched == {"linear.force_N": False, "screw.friction_coefficient": True}


def test_the_tornado_svg_is_deterministic(report):
    pytest.importorskip("matplotlib")
    assert render(report, "html") == render(report, "html")


def test_the_markdown_has_the_drivers_as_tables(report):
    md = render(report, "md")
    assert "## Probability of passing" in md
    rho = _rho(report, "motor_rated_torque")
    f, F = rho["screw.friction_coefficient"], rho["linear.force_N"]
    assert (round(f, 2), round(F, 2)) == (-0.87, -0.46)
    # ten cells a side: |−0.871| → 9 cells left of zero, |−0.455| → 5
    table = (
        "### Tornado chart: drivers of motor rated torque against the screw torque\n\n"
        "P(pass) = 0.9994 (95 % interval 0.9987 … 0.9997)\n\n"
        "| input | ρ | −1 … 0 … +1 |\n|---|---|---|\n"
        f"| {FRICTION} | {f:+.2f} | ░█████████│░░░░░░░░░░ |\n"
        f"| {FORCE} | {F:+.2f} | ░░░░░█████│░░░░░░░░░░ |\n"
    )
    assert table in md
    # every check's P(pass) and ρ in one table: the columns follow the inputs' order
    assert f"| ρ {FORCE} | ρ {FRICTION} |" in md
    assert (
        "| motor rated torque against the screw torque | 1.176 | 0.9994 | 0.9987 … 0.9997 "
        f"| 1.110 | {F:+.2f} | {f:+.2f} |"
    ) in md
    # a check the inputs do not move: no ρ, its nominal verdict
    assert "| nut height ratio H/d2 | 2.000 | 1.0000 | 0.9996 … 1.0000 | 2.000 | — | — |" in md
    assert "the nominal rule would have chosen Tr14x2 (1 start) with 4A71B4 (P = 0.8422)" in md


def test_without_an_uncertainty_table_the_section_says_so():
    rep = advise(read_requirements(EXAMPLES / "linear_screw_actuator.toml"))
    md = render(rep, "md")
    assert r"No \[uncertainty\] table: every margin above is at the nominal inputs only." in md
    assert "Tornado chart" not in md


def _section(checks: list[dict]) -> dict:
    return {"confidence": 0.95, "checks": checks}


def _c(cid: str, p: float, p05: float, rho: dict[str, float], modelled: bool = True) -> dict:
    return {
        "id": cid,
        "name": cid,
        "modelled": modelled,
        "p_pass": p,
        "p_pass_low": p - 0.01,
        "p_pass_high": min(p + 0.01, 1.0),
        "margin_p05": p05,
        "drivers": [{"input": k, "rank_correlation": v} for k, v in rho.items()],
    }


def test_which_checks_are_charted():
    labels = {("linear", "force_N"): ("Axial force", "N")}
    a = _c("a", 0.95, 0.9, {"linear.force_N": -0.3, "x.y_z": 0.8})
    b = _c("b", 0.80, 0.8, {"linear.force_N": -1.0})
    fixed = _c("fixed", 1.0, 2.0, {"linear.force_N": 0.0})  # no input moves it
    model = _c("model", 0.5, 0.5, {"linear.force_N": -1.0}, modelled=False)
    safe = _c("safe", 1.0, 1.3, {"linear.force_N": -0.9})
    safer = _c("safer", 1.0, 1.6, {"linear.force_N": -0.9})
    # the failing ones, least probable first; the largest |ρ| on top, labelled
    charts = charted(_section([a, fixed, b, model, safe]), labels)
    assert [t.check_id for t in charts] == ["b", "a"]
    assert [(x.label, x.rho) for x in charts[1].bars] == [("x y z", 0.8), ("Axial force", -0.3)]
    # none fails in any sample: the one nearest to failing (the lower 5th percentile)
    assert [t.check_id for t in charted(_section([safer, safe, fixed]), labels)] == ["safe"]
    assert least_probable(_section([fixed, model]), labels) is None
    assert input_label("screw.friction_coefficient", {}) == "screw friction coefficient"


def test_the_wizard_plots_the_drivers_of_the_least_probable_check(report):
    from advisor.tui import views

    rho = _rho(report, "motor_rated_torque")
    plots = views.plots(report)
    assert plots[0].title.startswith("M(n)")  # the application's plots first
    drivers = plots[-1]
    assert drivers.title == (
        "Drivers of motor rated torque against the screw torque: "
        "P(pass) = 0.9994 (95 % interval 0.9987 … 0.9997)"
    )
    assert drivers.bars == (
        (FRICTION, rho["screw.friction_coefficient"]),
        (FORCE, rho["linear.force_N"]),
    )
    assert "Spearman" in views.legend(drivers)
    lines = views.probability_lines(report)
    assert lines[0].startswith("P(pass): 0.9994 (95 % interval 0.9987 … 0.9997, 10000 samples")
    assert lines[1] == (
        "least probable: motor rated torque against the screw torque, P(pass) 0.9994; "
        f"driven by {FRICTION} (ρ −0.87), {FORCE} (ρ −0.46)"
    )
    # a report without the table: no drivers plot, no P(pass) line
    plain_rep = advise(read_requirements(EXAMPLES / "linear_screw_actuator.toml"))
    assert all(not p.bars for p in views.plots(plain_rep))
    assert views.probability_lines(plain_rep) == []


def _text(widget) -> str:
    """What a Static shows, as plain text."""
    from rich.console import Console

    console = Console(width=200, record=True, file=io.StringIO())
    console.print(widget.content)
    return console.export_text()


async def _computed(app, pilot) -> None:
    start = app.results_version
    await pilot.press("ctrl+r")
    for _ in range(400):
        await pilot.pause(0.02)
        if app.results_version > start:
            return
    raise AssertionError("no result")


async def test_the_wizard_shows_the_drivers_plot_and_the_p_pass(tmp_path, monkeypatch):
    pytest.importorskip("textual_plotext")
    monkeypatch.setenv("XDG_STATE_HOME", str(tmp_path / "state"))
    monkeypatch.chdir(tmp_path)
    from advisor.tui.app import DriveAdvisorApp

    doc = tomllib.loads(ROBUST.read_text(encoding="utf-8"))
    app = DriveAdvisorApp(doc, ROBUST, save_drafts=False, offer_draft=False)
    async with app.run_test(size=(120, 40)) as pilot:
        await _computed(app, pilot)
        summary = _text(app.query_one("#view-summary"))
        assert "P(pass): 0.9994" in summary and "least probable: motor rated torque" in summary
        checks = _text(app.query_one("#view-checks"))
        assert "P(pass)" in checks and "0.9994" in checks
        app.query_one("#result-tabs").active = "tab-plot"
        await pilot.pause()
        assert app.plot_titles[-1].startswith("Drivers of motor rated torque")
        await pilot.press("right_square_bracket")
        await pilot.pause()
        assert app.plot_index == len(app.plot_titles) - 1
        assert "Drivers of motor rated torque" in _text(app.query_one("#plot-note"))
        assert len(app.query_one("#plot-switcher").children) == 2
