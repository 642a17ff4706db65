"""The linear Compare view: the thread runners-up SCR-04 reports, each a "Use" button that
the keyboard reaches and that imposes the thread; "imposed" said only when it is."""

import tomllib

from helpers import EXAMPLES
from textual.widgets import Button, Static

from advisor.tui.app import DriveAdvisorApp


def _doc(thread: bool) -> dict:
    doc = tomllib.loads((EXAMPLES / "linear_screw_actuator.toml").read_text(encoding="utf-8"))
    if not thread:
        del doc["screw"]["thread"]
    return doc


async def _open_compare(pilot, wizard) -> str:
    app = pilot.app
    await wizard.compute(pilot)
    while app.query_one("#result-tabs").active != "tab-compare":
        await pilot.press("right")
        await pilot.pause()
    return "\n".join(wizard.text(w) for w in app.query("#compare-box Static"))


async def test_a_chosen_thread_shows_its_runners_up_and_use_imposes_one(wizard):
    app = DriveAdvisorApp(_doc(thread=False), save_drafts=False, offer_draft=False)
    async with app.run_test(size=wizard.SIZE) as pilot:
        text = await _open_compare(pilot, wizard)
        assert "imposes the thread." not in text
        assert "Thread and motor: the runners-up" in text and "▶ Tr14x2" in text
        assert "Tr16x2" in text and "▶ chosen: SCR-04" in text
        labels = [str(b.label) for b in app.query("#compare-box Button")]
        assert labels[:2] == ["Use Tr16x2", "Use Tr16x4"]
        # one tab from the view's tabs focuses the first "Use", and enter presses it
        await pilot.press("tab")
        assert isinstance(app.focused, Button) and str(app.focused.label) == "Use Tr16x2"
        start = app.results_version
        await pilot.press("enter")
        await wizard.settle(pilot, start)
        assert app.doc["screw"]["thread"] == "Tr16x2"
        assert app.report.design.screw.thread == "Tr16x2"  # the next compute is that thread
        text = await _open_compare(pilot, wizard)
        assert "the requirement imposes the thread." in text
        assert "runners-up" not in text and not app.query("#compare-box Button")


async def test_an_imposed_thread_is_said_imposed(wizard):
    app = DriveAdvisorApp(_doc(thread=True), save_drafts=False, offer_draft=False)
    async with app.run_test(size=wizard.SIZE) as pilot:
        text = await _open_compare(pilot, wizard)
        assert "the requirement imposes the thread." in text and "runners-up" not in text
        assert isinstance(app.query_one("#compare-box Static"), Static)


def _multi_start_doc() -> dict:
    """A fast stroke (0.3 m in 1 s, 3000 N): the chosen screw and its runners-up are
    multi-start (the chosen one Tr22x20(P5), 4 starts of pitch 5)."""
    return {
        "application": {"kind": "linear", "title": "multi-start"},
        "linear": {
            "force_N": 3000,
            "stroke_m": 0.3,
            "travel_time_s": 1.0,
            "support_span_m": 0.4,
        },
        "motor": {"kind": "induction"},
    }


async def test_use_on_a_multi_start_runner_up_imposes_its_thread_and_starts(wizard):
    """GOST 24739-81 writes a multi-start screw TrD x lead (P pitch): Tr24x20(P5) is the
    thread Tr24x5 (d 24 mm, P 5 mm) cut with 20 / 5 = 4 starts. "Use" puts both in the
    requirement (the designation itself is no thread the requirement takes), and the
    chosen row shows the chosen screw's designation, as its runners-up do."""
    app = DriveAdvisorApp(_multi_start_doc(), save_drafts=False, offer_draft=False)
    async with app.run_test(size=wizard.SIZE) as pilot:
        text = await _open_compare(pilot, wizard)
        assert "▶ Tr22x20(P5)" in text  # SCR-04: "Thread Tr22x20(P5) with 4A90L6"
        labels = [str(b.label) for b in app.query("#compare-box Button")]
        assert labels[0] == "Use Tr24x20(P5)"
        start = app.results_version
        app.query("#compare-box Button").first().press()
        await wizard.settle(pilot, start)
        assert app.doc["screw"]["thread"] == "Tr24x5"  # d 24 mm, P 5 mm
        assert app.doc["screw"]["starts"] == 4  # lead / pitch = 20 / 5
        screw = app.report.design.screw  # computed: the requirement is accepted
        assert screw.designation == "Tr24x20(P5)" and screw.imposed
