"""Issue 13, the wizard: any file or draft opens, with what could not be used shown; a
draft that cannot be read is set aside under a new name, and the wizard says so."""

import pytest
from textual.widgets import Input, RadioButton, Static

from advisor.tui import draft as drafts
from advisor.tui.app import ConfirmScreen, DriveAdvisorApp

#: the shared Pilot set-up (tests/conftest.py): own drafts, no animation, a temporary cwd
pytestmark = pytest.mark.usefixtures("wizard")

SIZE = (120, 40)


@pytest.mark.parametrize(
    ("doc", "words"),
    [
        ({"application": "linear"}, "application = 'linear': must be a table"),
        ({"application": {"kind": 5}}, "application.kind = 5: must be one of linear"),
        (
            {"application": {"kind": "linear", "title": 5}, "linear": 7},
            "linear = 7: must be a table; removed",
        ),
        (
            {"application": {"kind": "rotary"}, "motor": {"candidate_speeds_rpm": "fast"}},
            "motor.candidate_speeds_rpm = 'fast': must be an array of numbers",
        ),
        (
            {"application": {"kind": "positioning"}, "positioning": {"motors": [1, "x"]}},
            "positioning.motors[1] = 1: must be a table; removed",
        ),
        (
            {"application": {"kind": "positioning", "title": "[/] [motor]"}, "positioning": 3},
            "positioning = 3: must be a table",
        ),
    ],
)
async def test_wrong_typed_files_open_with_the_problems_shown(doc, words, wizard):
    app = DriveAdvisorApp(doc, save_drafts=False, offer_draft=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        assert words in wizard.text(app.query_one("#step-0-error", Static))
        for _ in range(4):  # every step builds and validates without an exception
            await pilot.press("ctrl+n")
            await pilot.pause()
    assert app.return_code in (None, 0)


async def test_a_numeric_title_is_shown_as_text_to_fix(wizard):
    app = DriveAdvisorApp({"application": {"kind": "linear", "title": 5}}, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        assert app.query_one("#f-application-title", Input).value == "5"
        assert app.query_one("#kind-linear", RadioButton).value
        assert "application.title = 5: must be text" in wizard.text(app.query_one("#step-0-error"))


async def test_a_wrong_typed_value_stays_in_its_field_to_fix(wizard):
    doc = {"application": {"kind": "linear"}, "linear": {"force_N": "lots"}}
    app = DriveAdvisorApp(doc, save_drafts=False, offer_draft=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.click("#kind-linear")
        await pilot.press("ctrl+n")
        await pilot.pause()
        assert app.query_one("#f-linear-force-N", Input).value == "lots"
        await pilot.press("ctrl+n")  # the field's own check says what to fix
        await pilot.pause()
        assert app.step == 1
        assert "number" in wizard.text(app.query_one("#f-linear-force-N-err"))


async def test_a_wrong_typed_draft_is_offered_shaped(tmp_path, wizard):
    path = drafts.draft_path()
    path.parent.mkdir(parents=True)
    path.write_text('[application]\nkind = "rotary"\ntitle = 5\n[rotary]\ntorque_Nm = "x"\n')
    app = DriveAdvisorApp()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        assert isinstance(app.screen, ConfirmScreen)
        await pilot.press("y")
        await pilot.pause()
        assert app.query_one("#f-application-title", Input).value == "5"
        shown = wizard.text(app.query_one("#step-0-error", Static))
        assert "application.title = 5" in shown and "rotary.torque_Nm = 'x'" in shown


async def test_a_draft_that_says_application_linear_does_not_crash(wizard):
    path = drafts.draft_path()
    path.parent.mkdir(parents=True)
    path.write_text('application = "linear"\n')
    app = DriveAdvisorApp()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        assert "application = 'linear'" in wizard.text(app.query_one("#step-0-error", Static))
    assert app.return_code in (None, 0)


@pytest.mark.parametrize(
    "content", [b"[application\n", b"\xff\xfe", b"x = " + b"[" * 5000 + b"]" * 5000]
)
async def test_an_unreadable_draft_is_set_aside_and_said(content, wizard):
    path = drafts.draft_path()
    path.parent.mkdir(parents=True)
    path.write_bytes(content)
    app = DriveAdvisorApp()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        assert not isinstance(app.screen, ConfirmScreen)
        shown = wizard.text(app.query_one("#step-0-error", Static))
    assert "the saved draft could not be read" in shown and "set aside as" in shown
    assert not path.exists()
    aside = list(path.parent.glob("draft.unreadable-*.toml"))
    assert len(aside) == 1 and aside[0].read_bytes() == content  # kept, not deleted
    assert str(aside[0]) in shown.replace("\n", "")


def test_a_second_unreadable_draft_gets_its_own_name():
    path = drafts.draft_path()
    path.parent.mkdir(parents=True)
    names = set()
    for _ in range(2):
        path.write_text("[broken\n")
        loaded = drafts.load_draft()
        assert loaded.doc is None and loaded.set_aside is not None
        names.add(loaded.set_aside.name)
    assert len(names) == 2


def test_the_wizard_refuses_a_file_it_cannot_read_in_one_line(tmp_path, capsys, monkeypatch):
    import advisor.cli
    from advisor.cli import main

    monkeypatch.setattr(advisor.cli, "_is_terminal", lambda stream: True)  # as in a terminal

    fifo = tmp_path / "req.toml"
    import os

    os.mkfifo(fifo)
    assert main([str(fifo)]) == 2
    big = tmp_path / "big.toml"
    big.write_text("#" * (1 << 21))
    assert main([str(big)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 2 and "not a file" in err[0] and "larger than 1024 KiB" in err[1]


async def test_a_draft_that_cannot_be_saved_is_a_notice_not_a_crash(wizard):
    import os

    path = drafts.draft_path()
    path.parent.mkdir(parents=True)
    os.mkfifo(path)  # neither readable as a draft nor replaceable by one
    app = DriveAdvisorApp()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        assert "set aside as" in wizard.text(app.query_one("#step-0-error", Static))
        os.mkfifo(path)  # and again, for the saves
        await pilot.click("#kind-linear")
        await pilot.pause()
        notes = [n.message for n in app._notifications]
        assert any("the draft cannot be saved" in m and "FIFO" in m for m in notes)
    assert app.return_code in (None, 0)


def _notes(app, words: str) -> list[str]:
    return [n.message for n in app._notifications if words in n.message]


async def _type_force(app, pilot, keys: str) -> None:
    await pilot.press("ctrl+n")
    await pilot.pause()
    assert app.focused.id == "f-linear-force-N"
    await pilot.press(*keys)
    await pilot.pause()


async def test_a_state_directory_that_is_a_file_is_said_once_and_the_input_kept(
    tmp_path, monkeypatch, wizard
):
    """XDG_STATE_HOME names a regular file: no draft can be written below it. Said once (a
    notice and the status line), not at each of the four keys; the input stays in memory."""
    blocker = tmp_path / "not-a-dir"
    blocker.write_text("")
    monkeypatch.setenv("XDG_STATE_HOME", str(blocker))
    app = DriveAdvisorApp({"application": {"kind": "linear"}}, offer_draft=False)
    async with app.run_test(size=SIZE) as pilot:
        await _type_force(app, pilot, "3500")
        assert len(_notes(app, "the draft cannot be saved")) == 1
        assert "Not a directory" in _notes(app, "the draft cannot be saved")[0]
        status = app.query_one("#draft-status", Static)
        assert status.display and "Draft not saved" in wizard.text(status)
        assert "Not a directory" in wizard.text(status)
        assert app.doc["linear"]["force_N"] == 3500.0
        # the place can be written again: the next change is saved and the line goes
        blocker.unlink()
        await pilot.press("0")
        await pilot.pause()
        assert not status.display
        assert drafts.load_draft(None).doc["linear"]["force_N"] == 35000.0
    assert app.return_code in (None, 0)


async def test_a_read_only_state_directory_is_said_once_and_the_input_kept(monkeypatch, wizard):
    """A read-only directory (root writes there all the same, so the write is made to fail
    as it does for a user: PermissionError)."""

    def refuse(path, text):
        raise PermissionError(13, "Permission denied", str(path))

    monkeypatch.setattr(drafts, "write_atomic", refuse)
    app = DriveAdvisorApp({"application": {"kind": "linear"}}, offer_draft=False)
    async with app.run_test(size=SIZE) as pilot:
        await _type_force(app, pilot, "600")
        await pilot.press("enter", "2", "5")
        await pilot.pause()
        assert len(_notes(app, "the draft cannot be saved")) == 1
        status = app.query_one("#draft-status", Static)
        assert status.display and "Permission denied" in wizard.text(status)
        assert app.doc["linear"] == {"force_N": 600.0, "stroke_m": 25.0}
        assert app.query_one("#f-linear-stroke-m", Input).value == "25"
    assert app.return_code in (None, 0)
    assert drafts.load_draft(None).doc is None  # nothing was written
