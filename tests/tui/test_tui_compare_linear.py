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
