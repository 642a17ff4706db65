"""The terminal wizard driven as a user would, through textual's Pilot: typing the seed 001
values, loading every example and exporting its report, invalid input, the draft, a crash in
a calculation, and replacing an existing file."""

import subprocess
import sys
import tomllib

import pytest
from helpers import EXAMPLES
from textual.widgets import Input, Label, Static

from advisor.core.engine import advise
from advisor.core.reading import read_requirements
from advisor.core.report import to_toml
from advisor.tui import draft as drafts
from advisor.tui.app import ConfirmScreen, DriveAdvisorApp

#: the shared Pilot set-up (tests/conftest.py): own drafts, no animation, a temporary cwd
pytestmark = pytest.mark.usefixtures("wizard")

SIZE = (120, 40)


async def _type(pilot, app, widget_id: str, text: str) -> None:
    box = app.query_one(f"#{widget_id}", Input)
    box.focus()
    box.value = ""
    await pilot.press(*text)


async def test_typing_the_seed_001_values_finds_tr16x2_at_1200_rpm(wizard):
    app = DriveAdvisorApp(save_drafts=False, offer_draft=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.click("#kind-linear")
        await pilot.press("ctrl+n")
        assert app.step == 1
        await _type(pilot, app, "f-linear-force-N", "3500")
        await _type(pilot, app, "f-linear-stroke-m", "0.2")
        await _type(pilot, app, "f-linear-travel-time-s", "5")
        await _type(pilot, app, "f-linear-support-span-m", "0.4")
        await pilot.press("ctrl+n")
        assert app.step == 2
        await _type(pilot, app, "f-screw-thread", "Tr16x2")
        # the paper's screw has one start; left free, two starts would take a 0.55 kW motor
        await _type(pilot, app, "f-screw-starts", "1")
        await pilot.press("ctrl+n", "ctrl+n")
        assert app.step == 4
        await wizard.compute(pilot)
        summary = wizard.text(app.query_one("#view-summary", Static))
        comps = wizard.text(app.query_one("#view-components", Static))
        assert "Tr16x2" in summary and "1200 rpm" in comps


@pytest.mark.parametrize("example", sorted(p.name for p in EXAMPLES.glob("*.toml")))
async def test_each_example_exports_the_batch_report(example, tmp_path, wizard):
    src = EXAMPLES / example
    app = DriveAdvisorApp(tomllib.loads(src.read_text(encoding="utf-8")), src, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await wizard.compute(pilot)
        target = tmp_path / "out.report.toml"
        await wizard.export_report(pilot, target)
    assert target.read_text(encoding="utf-8") == to_toml(advise(read_requirements(src)))


@pytest.mark.parametrize("suffix", [".json", ".md", ".html"])
async def test_export_offers_the_batch_formats(suffix, tmp_path, wizard):
    """ctrl+s writes the report in the format its file suffix names, as --format does."""
    pytest.importorskip("matplotlib")
    from advisor.datasheet import format_of, render

    src = EXAMPLES / "positioning_drive.toml"
    app = DriveAdvisorApp(tomllib.loads(src.read_text(encoding="utf-8")), src, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await wizard.compute(pilot)
        target = tmp_path / f"design{suffix}"
        await wizard.export_report(pilot, target)
    expected = render(advise(read_requirements(src)), format_of(target))
    assert target.read_text(encoding="utf-8") == expected


async def test_number_fields_take_units(wizard):
    src = EXAMPLES / "linear_screw_actuator.toml"
    app = DriveAdvisorApp(tomllib.loads(src.read_text(encoding="utf-8")), src, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+n")
        await _type(pilot, app, "f-linear-force-N", "3.5 kN")
        await _type(pilot, app, "f-linear-stroke-m", "200 mm")
        assert app.doc["linear"]["force_N"] == 3500.0 and app.doc["linear"]["stroke_m"] == 0.2
        await _type(pilot, app, "f-linear-stroke-m", "5 kN")
        err = wizard.text(app.query_one("#f-linear-stroke-m-err", Label))
        assert "kN is a force, not a length; expected m" in err


async def test_invalid_input_is_shown_inline_and_next_waits(wizard):
    src = EXAMPLES / "linear_screw_actuator.toml"
    app = DriveAdvisorApp(tomllib.loads(src.read_text(encoding="utf-8")), src, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+n")
        await _type(pilot, app, "f-linear-force-N", "-3500")
        await pilot.press("ctrl+n")
        assert app.step == 1  # Next waited
        err = wizard.text(app.query_one("#f-linear-force-N-err", Label))
        assert "must be ≥ 1" in err and "1 N … 5 MN" in err
        await _type(pilot, app, "f-linear-stroke-m", "abc")
        assert "must be a number" in wizard.text(app.query_one("#f-linear-stroke-m-err", Label))
        # Back keeps what was typed
        await pilot.press("ctrl+b", "ctrl+n")
        assert app.query_one("#f-linear-stroke-m", Input).value == "abc"


async def test_every_change_is_saved_and_offered_back():
    app = DriveAdvisorApp(offer_draft=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.click("#kind-rotary")
        await pilot.press("ctrl+n")
        await _type(pilot, app, "f-rotary-torque-Nm", "750")
    saved = drafts.load_draft().doc
    assert saved["application"]["kind"] == "rotary" and saved["rotary"]["torque_Nm"] == 750
    again = DriveAdvisorApp()
    async with again.run_test(size=SIZE) as pilot:
        await pilot.pause()
        assert isinstance(again.screen, ConfirmScreen)
        await pilot.press("y")
        await pilot.pause()
        await pilot.press("ctrl+n")
        assert again.query_one("#f-rotary-torque-Nm", Input).value == "750"


async def test_a_crash_in_a_calculation_keeps_the_app_and_the_input(monkeypatch, wizard):
    import advisor.core.engine

    def boom(*_a, **_k):
        raise ZeroDivisionError("float division by zero")

    monkeypatch.setattr(advisor.core.engine, "advise", boom)
    src = EXAMPLES / "positioning_drive.toml"
    doc = tomllib.loads(src.read_text(encoding="utf-8"))
    app = DriveAdvisorApp(doc, src, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await wizard.compute(pilot)
        assert "internal error" in wizard.text(app.query_one("#review-error", Static))
        assert app.doc == doc and app.is_running


async def test_infeasible_design_is_explained(wizard):
    src = EXAMPLES / "rudder_actuator.toml"
    doc = tomllib.loads(src.read_text(encoding="utf-8"))
    doc["envelope"] = {"max_outer_diameter_mm": 20.0}
    app = DriveAdvisorApp(doc, src, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await wizard.compute(pilot)
        text = wizard.text(app.query_one("#view-summary", Static))
        assert "No feasible design" in text and "envelope" in text


async def test_existing_file_asks_before_it_is_replaced(tmp_path):
    src = EXAMPLES / "linear_screw_actuator.toml"
    target = tmp_path / "req.toml"
    target.write_text("keep me", encoding="utf-8")
    app = DriveAdvisorApp(tomllib.loads(src.read_text(encoding="utf-8")), src, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+s")
        await pilot.pause()
        app.screen.query_one("#export-path", Input).value = str(target)
        await pilot.click("#save-requirements")
        await pilot.pause()
        assert isinstance(app.screen, ConfirmScreen)
        await pilot.press("n")
        await pilot.pause()
        assert target.read_text(encoding="utf-8") == "keep me"
        await pilot.click("#save-requirements")
        await pilot.pause()
        await pilot.press("y")
        await pilot.pause()
    assert tomllib.loads(target.read_text(encoding="utf-8")) == tomllib.loads(
        src.read_text(encoding="utf-8")
    )


def test_batch_path_imports_no_textual_for_any_example():
    for src in sorted(EXAMPLES.glob("*.toml")):
        code = (
            "import sys, io, contextlib\n"
            "from advisor.cli import main\n"
            "with contextlib.redirect_stdout(io.StringIO()):\n"
            f"    assert main(['--batch', {str(src)!r}]) == 0\n"
            "assert 'textual' not in sys.modules, src\n"
        )
        r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
        assert r.returncode == 0, (src, r.stderr)


def test_each_application_has_its_plots():
    from advisor.tui import views

    titles = {}
    for src in sorted(EXAMPLES.glob("*.toml")):
        rep = advise(read_requirements(src))
        figs = views.plots(rep)
        titles[src.stem] = [f.title for f in figs]
        for f in figs:
            assert f.series and all(len(xs) == len(ys) > 0 for _, xs, ys in f.series)
    assert "M(n)" in titles["linear_screw_actuator"][0]
    assert titles["rudder_actuator"][0] == "Motor losses against speed"
    assert "fig. 1" in titles["rudder_actuator"][1]
    assert titles["positioning_drive"] == ["Move time against ratio"]
    # the run-up (seconds) on its own axis, apart from a sustained slew (minutes)
    assert titles["gyro_compensator"] == ["Run-up of the rotor", "Speed during a sustained slew"]
