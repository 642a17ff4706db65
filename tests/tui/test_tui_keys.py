"""Issue 24, the wizard: keys act in the order typed, even in a burst. A burst is what tmux's
``send-keys "600" Enter "25" Enter``, a terminal typing a paste, or a fast typist on a loaded
machine delivers: every key reaches the app before the first box has handled any of them.
Enter (and tab) must move to the next field before the next key lands; a paste of several
lines fills successive fields, a line each.

textual's ``pilot.press`` waits for the app to be idle after each key, so it never makes a
burst; :func:`_burst` hands every key to the app's driver at once, as a terminal does."""

import pytest
from textual import events
from textual.widgets import Input

from advisor.tui import draft as drafts
from advisor.tui import fields
from advisor.tui.app import DriveAdvisorApp

#: the shared Pilot set-up (tests/conftest.py): own drafts, no animation, a temporary cwd
pytestmark = pytest.mark.usefixtures("wizard")

SIZE = (120, 40)
LINEAR = {"application": {"kind": "linear"}}
FORCE, STROKE, TIME = "f-linear-force-N", "f-linear-stroke-m", "f-linear-travel-time-s"
SPAN = "f-linear-support-span-m"


#: what a terminal sends for the keys that are not characters (a Key's ``character``)
_CHARS = {
    "enter": "\r",
    "tab": "\t",
    "shift+tab": None,
    "backspace": "\x7f",
    "ctrl+n": "\x0e",
    "ctrl+q": "\x11",
}


def _burst(app, *keys: str) -> None:
    """Every key queued at once in the app, as the terminal driver queues a burst."""
    for key in keys:
        app._driver.send_message(events.Key(key, _CHARS.get(key, key)))


async def _until(pilot, done, what: str) -> None:
    for _ in range(200):
        await pilot.pause(0.01)
        if done():
            return
    raise AssertionError(f"never: {what}")


def _value(app, wid: str) -> str:
    return app.query_one(f"#{wid}", Input).value


async def _on_the_linear_step(app, pilot) -> None:
    await pilot.press("ctrl+n")
    await _until(pilot, lambda: app.focused is not None and app.focused.id == FORCE, "step 2")


async def test_a_burst_600_enter_25_enter_fills_two_fields():
    app = DriveAdvisorApp(dict(LINEAR), offer_draft=False)
    async with app.run_test(size=SIZE) as pilot:
        await _on_the_linear_step(app, pilot)
        _burst(app, "6", "0", "0", "enter", "2", "5", "enter")
        await _until(pilot, lambda: app.focused.id == TIME, "the third field focused")
        # (before: "60025" in the force, an empty stroke, the focus on the stroke)
        assert (_value(app, FORCE), _value(app, STROKE)) == ("600", "25")
        await _until(pilot, lambda: "stroke_m" in app.doc["linear"], "the stroke in the draft")
    saved = drafts.load_draft(None).doc
    assert saved["linear"] == {"force_N": 600.0, "stroke_m": 25.0}


async def test_keys_pressed_without_pauses_fill_two_fields():
    app = DriveAdvisorApp(dict(LINEAR), offer_draft=False)
    async with app.run_test(size=SIZE) as pilot:
        await _on_the_linear_step(app, pilot)
        await pilot.press("6", "0", "0", "enter", "2", "5", "enter")
        assert (_value(app, FORCE), _value(app, STROKE)) == ("600", "25")
        assert app.focused.id == TIME
    assert drafts.load_draft(None).doc["linear"] == {"force_N": 600.0, "stroke_m": 25.0}


def _first_of_step_2() -> str:
    """The id of the screw step's first field (the model decides which it is)."""
    return fields.fields_for("linear", 2)[0].id


async def test_a_burst_runs_on_into_the_next_step():
    """enter on a step's last field is ctrl+n: the keys after it act on the next step's
    first field. Every field of the load step gets a value or, optional, enter alone."""
    values = {FORCE: "3500", STROKE: "0.2", TIME: "5", SPAN: "0.4"}
    load_fields = fields.fields_for("linear", 1)
    assert all(f.optional for f in load_fields if f.id not in values)
    app = DriveAdvisorApp(dict(LINEAR), offer_draft=False)
    async with app.run_test(size=SIZE) as pilot:
        await _on_the_linear_step(app, pilot)
        _burst(app, *(k for f in load_fields for k in (*values.get(f.id, ""), "enter")))
        await _until(pilot, lambda: app.step == 2, "the screw step")
        await _until(pilot, lambda: app.focused.id == _first_of_step_2(), "its first field")
        assert {w: _value(app, w) for w in values} == values


async def test_ctrl_n_in_a_burst_sees_the_text_typed_before_it():
    """The support span is required: ctrl+n right after its "0.4" finds it typed (before,
    it checked the step first and said "Not yet")."""
    app = DriveAdvisorApp(dict(LINEAR), offer_draft=False)
    async with app.run_test(size=SIZE) as pilot:
        await _on_the_linear_step(app, pilot)
        _burst(app, *"3500", "enter", *"0.2", "enter", "5", "enter", *"0.4", "ctrl+n")
        await _until(pilot, lambda: app.step == 2, "the screw step")
        assert _value(app, SPAN) == "0.4"
        assert app.focused.id == _first_of_step_2()


async def test_tab_and_shift_tab_in_a_burst_move_before_the_next_key():
    app = DriveAdvisorApp(dict(LINEAR), offer_draft=False)
    async with app.run_test(size=SIZE) as pilot:
        await _on_the_linear_step(app, pilot)
        _burst(app, "7", "tab", "8", "tab", "9", "shift+tab", "shift+tab", "backspace", "1")
        await _until(pilot, lambda: _value(app, FORCE) == "1", "the force retyped")
        assert [_value(app, w) for w in (FORCE, STROKE, TIME)] == ["1", "8", "9"]


@pytest.mark.parametrize("newline", ["\n", "\r\n", "\r"])  # tmux pastes line ends as \r
async def test_a_paste_of_two_lines_fills_two_fields(newline):
    app = DriveAdvisorApp(dict(LINEAR), offer_draft=False)
    async with app.run_test(size=SIZE) as pilot:
        await _on_the_linear_step(app, pilot)
        app._driver.send_message(events.Paste(f"6 kN{newline}250 mm{newline}"))
        await _until(pilot, lambda: app.focused.id == TIME, "the third field focused")
        # (before: "6 kN" alone, the second line dropped; typed, "6 kN250 mm")
        assert (_value(app, FORCE), _value(app, STROKE)) == ("6 kN", "250 mm")
        await _until(pilot, lambda: "stroke_m" in app.doc["linear"], "the stroke in the draft")
    # 6 kN = 6000 N; 250 mm = 0.25 m
    assert drafts.load_draft(None).doc["linear"] == {"force_N": 6000.0, "stroke_m": 0.25}


async def test_a_paste_without_a_line_end_stays_in_its_field():
    app = DriveAdvisorApp(dict(LINEAR), offer_draft=False)
    async with app.run_test(size=SIZE) as pilot:
        await _on_the_linear_step(app, pilot)
        app._driver.send_message(events.Paste("6 kN"))
        await _until(pilot, lambda: _value(app, FORCE) == "6 kN", "the paste")
        _burst(app, "enter")
        await _until(pilot, lambda: app.focused.id == STROKE, "the stroke focused")
        assert _value(app, STROKE) == ""


async def test_quitting_right_after_typing_keeps_the_text_in_the_draft():
    """ctrl+q right after "25" in a burst: the 25 was still on its way to the document when
    the wizard quit, and the draft lacked it."""
    app = DriveAdvisorApp(dict(LINEAR), offer_draft=False)
    async with app.run_test(size=SIZE) as pilot:
        await _on_the_linear_step(app, pilot)
        _burst(app, "6", "0", "0", "enter", "2", "5", "ctrl+q")
        await _until(pilot, lambda: app._exit, "the wizard quit")
    assert drafts.load_draft(None).doc["linear"] == {"force_N": 600.0, "stroke_m": 25.0}
