"""A choice made from a list enters the requirement, the first of the list too: a choice
field with no default shows a blank Select, so whatever the user picks there is a choice,
never "the shown default" (the duty type S1 and a segment's "move" were once dropped while
the field showed them)."""

import tomllib

import pytest
from helpers import EXAMPLES
from textual.widgets import Select, Static

from advisor.core.engine import advise
from advisor.core.reading import read_requirements
from advisor.core.report import to_toml
from advisor.tui import fields
from advisor.tui.app import DriveAdvisorApp

#: the shared Pilot set-up (tests/conftest.py): own drafts, no animation, a temporary cwd
pytestmark = pytest.mark.usefixtures("wizard")

SIZE = (120, 40)
LINEAR = EXAMPLES / "linear_screw_actuator.toml"
DUTY_STEP = 4  # "Duty cycle" in fields.steps_for("linear")


async def _pick_first(pilot, app, select_id: str) -> None:
    """As a user picks: focus the blank Select, open it, one down from the blank row to
    the first choice, enter."""
    select = app.query_one(f"#{select_id}", Select)
    assert select.value is Select.NULL  # no default: the field shows blank
    select.focus()
    await pilot.press("enter")
    await pilot.pause()
    await pilot.press("down", "enter")
    await pilot.pause()


async def _to_duty_step(pilot, app) -> None:
    while app.step < DUTY_STEP:
        await pilot.press("ctrl+n")
        await pilot.pause()
    assert app.step == DUTY_STEP


async def test_picking_s1_enters_the_duty_and_the_export_is_the_batchs(tmp_path, wizard):
    doc = tomllib.loads(LINEAR.read_text(encoding="utf-8"))
    assert "duty" not in doc
    app = DriveAdvisorApp(doc, LINEAR, save_drafts=False, offer_draft=False)
    async with app.run_test(size=SIZE) as pilot:
        await _to_duty_step(pilot, app)
        await _pick_first(pilot, app, "f-duty-duty-type")
        assert app.query_one("#f-duty-duty-type", Select).value == "S1"
        assert fields.get(app.doc, ("duty", "duty_type")) == "S1"
        await pilot.press("ctrl+n")
        await pilot.pause()
        assert app.step == fields.REVIEW
        review = wizard.text(app.query_one("#review-text", Static))
        assert "[duty]" in review and 'duty_type = "S1"' in review
        await wizard.compute(pilot)
        target = tmp_path / "out.report.toml"
        await wizard.export_report(pilot, target)
    # the batch's report of the same file with the S1 written by hand
    by_hand = tmp_path / "s1.toml"
    by_hand.write_text(LINEAR.read_text(encoding="utf-8") + '\n[duty]\nduty_type = "S1"\n')
    expected = to_toml(advise(read_requirements(by_hand)))
    assert "[requirements.duty]" in expected
    assert target.read_text(encoding="utf-8") == expected


async def test_picking_move_enters_the_segments_kind(wizard):
    doc = tomllib.loads(LINEAR.read_text(encoding="utf-8"))
    app = DriveAdvisorApp(doc, LINEAR, save_drafts=False, offer_draft=False)
    async with app.run_test(size=SIZE) as pilot:
        await _to_duty_step(pilot, app)
        await _pick_first(pilot, app, "f-duty-segments-0-kind")
        assert app.query_one("#f-duty-segments-0-kind", Select).value == "move"
        assert fields.get(app.doc, ("duty", "segments", "0", "kind")) == "move"


async def test_an_untouched_field_with_a_default_stays_out(wizard):
    """The other side: a choice field with a real default shows it, and the file that did
    not name it still does not once the wizard has shown it (nothing was chosen)."""
    doc = tomllib.loads(LINEAR.read_text(encoding="utf-8"))
    assert "end_fixity" not in doc["linear"]
    app = DriveAdvisorApp(doc, LINEAR, save_drafts=False, offer_draft=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+n")
        await pilot.pause()
        assert app.query_one("#f-linear-end-fixity", Select).value == "pinned-pinned"
        assert fields.get(app.doc, ("linear", "end_fixity")) is None
