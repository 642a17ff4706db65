"""The wizard reads a file's quantities as the batch reads them: a list of speeds written with
their unit is kept, shown as written and computed as ``--batch`` computes it; a number the
batch refuses (``1_000``, full-width digits) is refused in its field too; a table whose
values are all refused is named by its fields on the Review step, not called missing."""

import pytest
from helpers import EXAMPLES
from textual.widgets import Input, Static

from advisor.core.engine import advise
from advisor.core.reading import read_requirements
from advisor.core.report import to_toml
from advisor.tui import draft as drafts
from advisor.tui import fields
from advisor.tui.app import DriveAdvisorApp

#: the shared Pilot set-up (tests/conftest.py): own drafts, no animation, a temporary cwd
pytestmark = pytest.mark.usefixtures("wizard")

SIZE = (120, 40)
SPEEDS = "candidate_speeds_rpm = [5000, 10000]"


def _rudder_with(speeds: str, tmp_path):
    text = (EXAMPLES / "rudder_actuator.toml").read_text(encoding="utf-8")
    assert SPEEDS in text
    path = tmp_path / "ru2.toml"
    path.write_text(text.replace(SPEEDS, f"candidate_speeds_rpm = {speeds}"), encoding="utf-8")
    return path


@pytest.mark.parametrize("speeds", ['["4000 rpm", "9000 rpm"]', '["500 rad/s", 9000]'])
async def test_a_list_of_speeds_with_units_is_kept_and_computed_as_the_batch(
    speeds, tmp_path, wizard
):
    src = _rudder_with(speeds, tmp_path)
    loaded = drafts.open_doc(src)
    assert loaded.problems == []
    app = DriveAdvisorApp(loaded.doc, src, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        while not app.query("#f-motor-candidate-speeds-rpm"):
            await pilot.press("ctrl+n")
            await pilot.pause()
        shown = app.query_one("#f-motor-candidate-speeds-rpm", Input).value
        assert shown == speeds.strip("[]").replace('"', "")
        assert not wizard.text(app.query_one("#f-motor-candidate-speeds-rpm-err", Static)).strip()
        await wizard.compute(pilot)
        target = tmp_path / "out.report.toml"
        await wizard.export_report(pilot, target)
    assert target.read_text(encoding="utf-8") == to_toml(advise(read_requirements(src)))


def test_a_list_item_that_is_no_quantity_is_said_and_kept_to_fix():
    doc = {"application": {"kind": "rotary"}, "motor": {"candidate_speeds_rpm": ["3000 N", 5]}}
    shaped, problems = drafts.shape(doc)
    assert shaped["motor"]["candidate_speeds_rpm"] == ["3000 N", 5]
    assert len(problems) == 1 and "motor.candidate_speeds_rpm[1] = '3000 N'" in problems[0]
    assert "fix it here" in problems[0] and "rpm" in problems[0]


def test_rows_of_tables_take_quantities_as_the_batch():
    doc = {
        "application": {"kind": "positioning"},
        "positioning": {"motors": [{"name": "a", "speed_rad_s": "3000 rpm"}]},
    }
    shaped, problems = drafts.shape(doc)
    assert problems == []
    assert shaped["positioning"]["motors"][0]["speed_rad_s"] == pytest.approx(314.159265359)


@pytest.mark.parametrize("text", ["1_000", "１６２０", "1_000 N*m", "inf"])
def test_a_number_the_batch_refuses_is_refused_in_its_field(text):
    torque = next(f for f in fields.all_fields("rotary") if f.dotted == "rotary.torque_Nm")
    value, err = fields.parse_text(torque, text)
    assert value is None and repr(text) in err and "N·m" in err


@pytest.mark.parametrize("text", ["1_000", "１６２０"])
def test_a_whole_number_the_batch_refuses_is_refused_in_its_field(text):
    starts = next(f for f in fields.all_fields("linear") if f.dotted == "screw.starts")
    value, err = fields.parse_text(starts, text)
    assert value is None and repr(text) in err and "whole number" in err


async def test_typing_1_000_says_so_beside_the_field(wizard):
    src = EXAMPLES / "rudder_actuator.toml"
    app = DriveAdvisorApp(drafts.open_doc(src).doc, src, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+n")
        await pilot.pause()
        box = app.query_one("#f-rotary-torque-Nm", Input)
        box.focus()
        box.value = ""
        await pilot.press(*"１６２０")
        await pilot.pause()
        said = wizard.text(app.query_one("#f-rotary-torque-Nm-err", Static))
        assert "'１６２０'" in said and "not allowed" in said and "N·m" in said


async def test_a_table_of_refused_values_is_named_by_its_fields_not_called_missing(
    tmp_path, wizard
):
    import re

    text = (EXAMPLES / "rudder_actuator.toml").read_text(encoding="utf-8")
    text = re.sub(r"^torque_Nm = .*$", 'torque_Nm = "9**9**9 N*m"', text, count=1, flags=re.M)
    text = re.sub(r"^speed_rpm = .*$", 'speed_rpm = "1e999 rpm"', text, count=1, flags=re.M)
    src = tmp_path / "hostile.toml"
    src.write_text(text, encoding="utf-8")
    app = DriveAdvisorApp(drafts.open_doc(src).doc, src, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+r")
        await pilot.pause()
        said = app._engine_errors()
        assert not any("missing" in line for line in said)
        assert [line.split(":")[0] for line in said] == ["rotary.torque_Nm", "rotary.speed_rpm"]
        assert not any("Remove" in str(b.label) for bs in app.fix_buttons.values() for b in bs)
        assert "finite" in wizard.text(app.query_one("#f-rotary-speed-rpm-err", Static))
