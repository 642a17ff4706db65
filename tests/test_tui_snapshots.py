"""Snapshots of the wizard (pytest-textual-snapshot): every step, the results of every
example, an invalid input, the export dialog and the help screen, at 120×40, with nothing on
screen that changes between runs (no clock, no blinking cursor, fixed paths).

Update after an intended change with ``pytest tests/test_tui_snapshots.py --snapshot-update``
and review the SVGs in ``tests/__snapshots__``."""

import tomllib

import pytest
from helpers import EXAMPLES
from textual.widgets import Input

from advisor.tui.app import DriveAdvisorApp

SIZE = (120, 40)


@pytest.fixture(autouse=True)
def _state_dir(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_STATE_HOME", str(tmp_path / "state"))
    monkeypatch.setenv("TEXTUAL_ANIMATIONS", "none")


def _app(example: str) -> DriveAdvisorApp:
    src = EXAMPLES / example
    return DriveAdvisorApp(
        tomllib.loads(src.read_text(encoding="utf-8")), src, save_drafts=False, offer_draft=False
    )


async def _compute(pilot) -> None:
    app = pilot.app
    start = app.results_version
    await pilot.press("ctrl+r")
    for _ in range(500):
        await pilot.pause(0.02)
        if app.results_version > start:
            break
    await pilot.pause()


@pytest.mark.parametrize("steps", [0, 1, 2, 3, 4, 5])
def test_wizard_step(snap_compare, steps):
    assert snap_compare(
        _app("linear_screw_actuator.toml"), press=["ctrl+n"] * steps, terminal_size=SIZE
    )


@pytest.mark.parametrize("example", sorted(p.name for p in EXAMPLES.glob("*.toml")))
def test_results(snap_compare, example):
    assert snap_compare(_app(example), run_before=_compute, terminal_size=SIZE)


def test_components_of_the_valve(snap_compare):
    async def run_before(pilot):
        await _compute(pilot)
        pilot.app.query_one("#results").active = "tab-components"
        await pilot.pause()

    assert snap_compare(_app("valve_actuator_hold.toml"), run_before=run_before, terminal_size=SIZE)


def test_invalid_input(snap_compare):
    async def run_before(pilot):
        await pilot.press("ctrl+n")
        box = pilot.app.query_one("#f-linear-force-N", Input)
        box.value = "-3500"
        await pilot.pause()  # as typing would: the change is seen before Next
        await pilot.press("ctrl+n")
        await pilot.pause()

    assert snap_compare(
        _app("linear_screw_actuator.toml"), run_before=run_before, terminal_size=SIZE
    )


def test_export_dialog(snap_compare):
    async def run_before(pilot):
        await _compute(pilot)
        await pilot.press("ctrl+s")
        await pilot.pause()
        pilot.app.screen.query_one("#export-path", Input).value = "rudder.report.toml"
        await pilot.pause()

    assert snap_compare(_app("rudder_actuator.toml"), run_before=run_before, terminal_size=SIZE)


def test_help_screen(snap_compare):
    assert snap_compare(_app("positioning_drive.toml"), press=["f1"], terminal_size=SIZE)
