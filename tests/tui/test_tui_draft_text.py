"""A field whose text is refused keeps it in the draft: the resumed draft shows the text in
its field again with the same message, and the export still leaves the refused value out."""

import tomllib

from helpers import EXAMPLES
from textual.widgets import Input, Label

from advisor.tui import draft as drafts
from advisor.tui.app import ConfirmScreen, DriveAdvisorApp, ExportScreen

SPEEDS = "f-motor-candidate-speeds-rpm"
TORQUE = "f-rotary-torque-Nm"


async def _type(pilot, app, widget_id: str, text: str) -> None:
    box = app.query_one(f"#{widget_id}", Input)
    box.focus()
    box.value = ""
    await pilot.press(*text)
    await pilot.press("tab")
    await pilot.pause()


async def test_refused_text_is_kept_by_the_draft_and_shown_again(tmp_path, wizard):
    src = tmp_path / "rud.toml"
    src.write_bytes((EXAMPLES / "rudder_actuator_duty.toml").read_bytes())
    doc = tomllib.loads(src.read_text(encoding="utf-8"))
    app = DriveAdvisorApp(doc, src)
    async with app.run_test(size=wizard.SIZE) as pilot:
        await pilot.pause()
        await _type(pilot, app, SPEEDS, '"3,5 rpm"')
        await _type(pilot, app, TORQUE, "1,5")
        said = {w: wizard.text(app.query_one(f"#{w}-err", Label)) for w in (SPEEDS, TORQUE)}
        assert "',' is" in said[SPEEDS] and "'1,5'" in said[TORQUE]
        # what is computed is what the fields show: neither value is in the document
        assert "torque_Nm" not in app.doc["rotary"]
        assert "candidate_speeds_rpm" not in app.doc.get("motor", {})
    saved = drafts.load_draft(src).doc
    assert saved["rotary"]["torque_Nm"] == "1,5"
    assert saved["motor"]["candidate_speeds_rpm"] == ["3,5 rpm"]
    again = DriveAdvisorApp(doc, src)
    async with again.run_test(size=wizard.SIZE) as pilot:
        await pilot.pause()
        assert isinstance(again.screen, ConfirmScreen)
        await pilot.press("y")
        await pilot.pause()
        for w in (SPEEDS, TORQUE):
            step = again._field_by_id(w).step
            await again._ensure_step(step)
            await pilot.pause()
            assert wizard.text(again.query_one(f"#{w}-err", Label)) == said[w]
        assert again.query_one(f"#{SPEEDS}", Input).value == '"3,5 rpm"'
        assert again.query_one(f"#{TORQUE}", Input).value == "1,5"
        # the export refuses as before: the wizard goes to the field to fix
        await pilot.press("ctrl+s")
        await pilot.pause()
        assert not isinstance(again.screen, ExportScreen | ConfirmScreen)
        assert again.focused is not None and again.focused.id in (SPEEDS, TORQUE)
    # the resumed draft is saved with the texts still in it
    saved = drafts.load_draft(src).doc
    assert saved["rotary"]["torque_Nm"] == "1,5"
