"""The wizard's staged start and lazy views (issue 14, latency), driven through textual's
Pilot: in a terminal a step's fields are built only when the step is first shown or found
wrong, the engine is warmed in a thread, and plots and the comparison are built when their
view is shown. Under a Pilot these are off by default (every step built at once); here
they are switched on, and what is computed must be exactly what the eager wizard computes."""

import tomllib

import pytest
from helpers import EXAMPLES
from rich.text import Text
from textual.widgets import Input, Label, Static

from advisor.core.engine import advise
from advisor.core.reading import parse_requirements, read_requirements
from advisor.core.report import to_toml
from advisor.tui.app import DriveAdvisorApp
from advisor.tui.widgets import SteadyStatic

#: the shared Pilot set-up (tests/conftest.py): own drafts, no animation, a temporary cwd
pytestmark = pytest.mark.usefixtures("wizard")

SIZE = (120, 40)
RUDDER = EXAMPLES / "rudder_actuator.toml"


def _doc(path=RUDDER) -> dict:
    return tomllib.loads(path.read_text(encoding="utf-8"))


def _app(doc: dict, lazy: bool = True, **kw) -> DriveAdvisorApp:
    return DriveAdvisorApp(
        doc, RUDDER, save_drafts=False, offer_draft=False, build_all_steps=not lazy, **kw
    )


async def test_a_first_compute_needs_no_step_built_and_equals_the_batch(wizard):
    app = _app(_doc(), warm_up=True)
    async with app.run_test(size=SIZE) as pilot:
        assert not app.query("#f-rotary-torque-Nm")  # step 2 is not built yet
        await wizard.compute(pilot)
        assert app.report is not None
        assert to_toml(app.report) == to_toml(advise(read_requirements(RUDDER)))
        assert not app.query("#f-rotary-torque-Nm")
        # walking the steps builds each one, showing the document's values
        await pilot.press("ctrl+e")
        await pilot.press("ctrl+n")
        torque = _doc()["rotary"]["torque_Nm"]
        assert app.query_one("#f-rotary-torque-Nm", Input).value == f"{torque:g}"


async def test_the_lazy_wizard_computes_what_the_fields_would_show(wizard):
    """A value with more digits than a field shows (1620.123456789 → "1620.12"): both
    wizards compute with what is shown, built or not."""
    doc = _doc()
    doc["rotary"]["torque_Nm"] = 1620.123456789
    computed = []
    for lazy in (False, True):
        app = _app(doc, lazy=lazy)
        async with app.run_test(size=SIZE) as pilot:
            await wizard.compute(pilot)
            computed.append(app.computed_doc)
    assert computed[0] == computed[1]
    assert computed[1]["rotary"]["torque_Nm"] == 1620.12


async def test_a_wrong_value_in_a_step_not_built_is_shown_in_its_field():
    doc = _doc()
    doc["rotary"]["torque_Nm"] = "8OO"  # letter O: kept, shown in its box to be fixed
    app = _app(doc)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+r")
        await pilot.pause()
        assert app.report is None and not app.computing
        assert app.step == 1  # the step asking the torque, built to show the error
        box = app.query_one("#f-rotary-torque-Nm", Input)
        assert box.value == "8OO" and app.focused is box
        assert "must be a number" in str(app.query_one("#f-rotary-torque-Nm-err", Label).render())


async def test_an_engine_message_on_a_step_not_built_takes_the_user_there():
    doc = _doc()
    doc["rotary"]["torque_Nm"] = -1620.0  # a number the engine refuses (must be > 0)
    app = _app(doc)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+r")
        await pilot.pause()
        assert app.report is None and app.step == 1
        assert str(app.query_one("#f-rotary-torque-Nm-err", Label).render()).strip()


async def test_plots_and_the_comparison_are_built_when_shown(wizard):
    app = _app(_doc())
    async with app.run_test(size=SIZE) as pilot:
        await wizard.compute(pilot)
        switcher = app.query_one("#plot-switcher")
        assert not switcher.children and not app.query_one("#compare-box").children
        app.query_one("#result-tabs").active = "tab-plot"
        await pilot.pause()
        assert len(switcher.children) == 1  # the plot shown, not every plot
        assert len(app.plot_titles) > 1
        await pilot.press("right_square_bracket")
        await pilot.pause()
        assert len(switcher.children) == 2 and app.plot_index == 1
        app.query_one("#result-tabs").active = "tab-compare"
        await pilot.pause()
        assert app.query_one("#compare-box").children


def test_a_steady_static_ignores_only_what_it_already_shows(monkeypatch):
    shown = []
    monkeypatch.setattr(Static, "update", lambda self, content="", **_: shown.append(content))
    w = SteadyStatic("")
    w.update("a")
    w.update("a")
    w.update(Text("a"))  # a Text is not the string "a": updated
    w.update(Text("a", style="bold"))  # same words, another style: updated
    w.update(Text("a", style="bold"))
    assert len(shown) == 3


@pytest.mark.parametrize("lazy", [False, True])
async def test_a_choice_not_offered_is_shown_in_its_own_field(lazy, wizard):
    """A list cannot show 'cylinder': its field says so (the default shown), and the first
    step lists it among the loading problems; built at once or later, the same."""
    doc = _doc()
    doc["gearbox"]["rolling_body"] = "cylinder"
    app = _app(doc, lazy=lazy)
    async with app.run_test(size=SIZE) as pilot:
        said = str(app.query_one("#step-0-error", Static).render())
        assert "gearbox.rolling_body = 'cylinder': must be one of ball, roller" in said
        assert "rolling_body" not in app.doc["gearbox"]  # set aside: the default applies
        while not app.query("#f-gearbox-rolling-body"):
            await pilot.press("ctrl+n")
        err = str(app.query_one("#f-gearbox-rolling-body-err", Label).render())
        assert "'cylinder' in the file is not one of ball, roller" in err
        await wizard.compute(pilot)
        assert app.report is not None


@pytest.mark.parametrize(
    "doc",
    [
        {"application": "linear"},
        {"application": {"kind": "linear", "title": 5}, "linear": 7},
        {"application": {"kind": "rotary"}, "motor": {"candidate_speeds_rpm": "fast"}},
        {"application": {"kind": "positioning"}, "positioning": {"motors": [1, "x"]}},
        {"application": {"kind": "linear"}, "linear": {"strok_m": 0.2, "force_N": "3 kN"}},
    ],
)
async def test_wrong_files_walk_and_compute_with_steps_built_late(doc):
    """Every step of a file with problems builds when reached, and ctrl+r from the first
    step takes the user to the first problem (or computes): never an exception."""
    app = DriveAdvisorApp(doc, save_drafts=False, offer_draft=False, build_all_steps=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+r")
        await pilot.pause()
        for _ in range(5):
            await pilot.press("ctrl+n")
            await pilot.pause()
        await pilot.press("ctrl+r")
        await pilot.pause(0.3)
        assert app.is_running
    assert app.return_code in (None, 0)


@pytest.mark.parametrize("edit", [False, True])
async def test_the_first_compute_takes_the_warm_ups_design_only_for_the_same_document(
    monkeypatch, edit, wizard
):
    """The warm-up advises once on the file as given; a first ctrl+r on that very document
    shows that design (the engine is not run again), an edited one is computed anew."""
    from advisor.core import engine

    calls = []
    real = engine.advise
    monkeypatch.setattr(engine, "advise", lambda *a, **k: calls.append(1) or real(*a, **k))
    app = _app(_doc(), warm_up=True)
    async with app.run_test(size=SIZE) as pilot:
        if edit:
            app.query_one("#f-application-title", Input).value = "edited before ctrl+r"
            await pilot.pause()
        await wizard.compute(pilot)
        assert app.report is not None
        expected = _doc()
        if edit:
            expected["application"]["title"] = "edited before ctrl+r"
        assert app.report.report.title == expected["application"]["title"]
        assert to_toml(app.report) == to_toml(advise(parse_requirements(expected)))
        assert len(calls) == (2 if edit else 1)  # the warm-up's, and the edited document's
        # a second ctrl+r computes again: the warm-up's design is taken once
        await wizard.compute(pilot)
        assert len(calls) == (3 if edit else 2)


def test_the_plotting_library_is_loaded_after_the_first_results_not_in_the_warm_up(tmp_path):
    """The warm-up imports what a compute needs, not the plotting library (it ran as the
    first ctrl+r painted); that is imported once the first results are shown."""
    script = f"""
import asyncio, sys, tomllib
from pathlib import Path
from advisor.tui.app import DriveAdvisorApp

async def main():
    doc = tomllib.loads(Path({str(RUDDER)!r}).read_text(encoding="utf-8"))
    app = DriveAdvisorApp(doc, save_drafts=False, offer_draft=False, warm_up=True)
    async with app.run_test(size=(120, 40)) as pilot:
        app._warmed.wait(60)
        await pilot.pause(0.3)
        assert "textual_plotext" not in sys.modules, "warm-up loaded plots"
        await pilot.press("ctrl+r")
        for _ in range(500):
            await pilot.pause(0.02)
            if "textual_plotext" in sys.modules and app.report is not None:
                break
        assert app.report is not None and "textual_plotext" in sys.modules
    print("ok")

asyncio.run(main())
"""
    import subprocess
    import sys

    env = {**__import__("os").environ, "XDG_STATE_HOME": str(tmp_path)}
    out = subprocess.run(
        [sys.executable, "-c", script], capture_output=True, text=True, env=env, timeout=120
    )
    assert out.returncode == 0 and out.stdout.strip() == "ok", out.stderr[-2000:]
