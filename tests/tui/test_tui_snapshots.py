"""Snapshots of the wizard (pytest-textual-snapshot): every step of every application and
the results of every example at 80×24 and at 120×40, the comparison view, an infeasible
result, an invalid input, a file fixed inside the wizard, the export dialog and the help
screen, with nothing on screen that changes between runs (no clock, no timing, no blinking
cursor, fixed paths).

Update after an intended change with ``pytest tests/tui/test_tui_snapshots.py --snapshot-update``
and review the SVGs in ``tests/tui/__snapshots__``."""

import tomllib

import pytest
from helpers import EXAMPLES
from textual.widgets import Input

from advisor.tui.app import DriveAdvisorApp

#: the shared Pilot set-up (tests/conftest.py): own drafts, no animation, a temporary cwd
pytestmark = pytest.mark.usefixtures("wizard")

SIZE = (120, 40)
SIZES = {"80x24": (80, 24), "120x40": (120, 40)}
#: One example per application (every step of each is shot).
APPS = {
    "linear": "linear_screw_actuator.toml",
    "rotary": "valve_actuator_hold.toml",
    "positioning": "positioning_drive.toml",
    "spinning_rotor": "gyro_compensator.toml",
}


def _app(example: str) -> DriveAdvisorApp:
    src = EXAMPLES / example
    return DriveAdvisorApp(
        tomllib.loads(src.read_text(encoding="utf-8")), src, save_drafts=False, offer_draft=False
    )


def _steps_of(kind: str) -> int:
    from advisor.tui import fields

    return len(fields.steps_for(kind))


@pytest.mark.parametrize("size", sorted(SIZES))
@pytest.mark.parametrize(
    "kind,step", [(k, s) for k in APPS for s in range(_steps_of(k))], ids=lambda v: str(v)
)
def test_wizard_step(snap_compare, kind, step, size):
    assert snap_compare(_app(APPS[kind]), press=["ctrl+n"] * step, terminal_size=SIZES[size])


@pytest.mark.parametrize("size", sorted(SIZES))
@pytest.mark.parametrize("example", sorted(p.name for p in EXAMPLES.glob("*.toml")))
def test_results(snap_compare, example, size, wizard):
    assert snap_compare(_app(example), run_before=wizard.compute, terminal_size=SIZES[size])


@pytest.mark.parametrize("size", sorted(SIZES))
@pytest.mark.parametrize("example", ["rudder_actuator.toml", "valve_actuator_hold.toml"])
def test_compare_view(snap_compare, example, size, wizard):
    async def run_before(pilot):
        await wizard.compute(pilot)
        pilot.app.query_one("#result-tabs").active = "tab-compare"
        await pilot.pause()

    assert snap_compare(_app(example), run_before=run_before, terminal_size=SIZES[size])


@pytest.mark.parametrize("size", sorted(SIZES))
@pytest.mark.parametrize("tab", ["summary", "plot"])
def test_infeasible_result(snap_compare, tab, size, wizard):
    """After a feasible result, an infeasible one: no plot of the previous design stays."""

    async def run_before(pilot):
        await wizard.compute(pilot)
        pilot.app.query_one("#f-envelope-max-outer-diameter-mm", Input).value = "20"
        await pilot.pause()
        await wizard.compute(pilot)
        pilot.app.query_one("#result-tabs").active = f"tab-{tab}"
        await pilot.pause()

    assert snap_compare(
        _app("valve_actuator_hold.toml"), run_before=run_before, terminal_size=SIZES[size]
    )


def test_unknown_key_offers_a_rename(snap_compare):
    src = EXAMPLES / "linear_screw_actuator.toml"
    doc = tomllib.loads(src.read_text(encoding="utf-8"))
    doc["linear"]["strok_m"] = doc["linear"].pop("stroke_m")
    app = DriveAdvisorApp(doc, src, save_drafts=False, offer_draft=False)
    assert snap_compare(app, press=["ctrl+n", "ctrl+n"], terminal_size=(80, 24))


def test_components_of_the_valve(snap_compare, wizard):
    async def run_before(pilot):
        await wizard.compute(pilot)
        pilot.app.query_one("#result-tabs").active = "tab-components"
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


def test_export_dialog(snap_compare, wizard):
    async def run_before(pilot):
        await wizard.compute(pilot)
        await pilot.press("ctrl+s")
        await pilot.pause()
        pilot.app.screen.query_one("#export-path", Input).value = "rudder.report.toml"
        await pilot.pause()

    assert snap_compare(_app("rudder_actuator.toml"), run_before=run_before, terminal_size=SIZE)


def test_help_screen(snap_compare):
    assert snap_compare(_app("positioning_drive.toml"), press=["f1"], terminal_size=SIZE)
