"""A comma in a number is read by the wizard as the batch reads it: ``1,5`` in a number box
is refused in the batch's words (the grammar has no decimal comma); a list item written
``"3,5 rpm"`` in a file stays one item, shown quoted in its box and refused there as the
batch refuses it; the box takes quoted items as a file does, and a list fixed in the box
computes and exports what ``--batch`` computes from the same list in a file."""

import json

import pytest
from helpers import EXAMPLES
from textual.widgets import Input, Static

from advisor.core.engine import advise
from advisor.core.errors import InputError
from advisor.core.reading import read_requirements
from advisor.core.report import to_toml
from advisor.tui import draft as drafts
from advisor.tui import fields
from advisor.tui.app import DriveAdvisorApp

#: the shared Pilot set-up (tests/conftest.py): own drafts, no animation, a temporary cwd
pytestmark = pytest.mark.usefixtures("wizard")

SIZE = (120, 40)
SPEEDS = "candidate_speeds_rpm = [5000, 10000]"
TORQUE = "torque_Nm = 1620"
BOX = "#f-motor-candidate-speeds-rpm"


def _field(kind: str, dotted: str) -> fields.Field:
    return next(f for f in fields.all_fields(kind) if f.dotted == dotted)


def _rudder_with(old: str, new: str, tmp_path, name: str = "ru.toml"):
    text = (EXAMPLES / "rudder_actuator.toml").read_text(encoding="utf-8")
    assert old in text
    path = tmp_path / name
    path.write_text(text.replace(old, new), encoding="utf-8")
    return path


def _batch_refusal(path) -> list[str]:
    """The lines ``--batch`` refuses ``path`` with."""
    with pytest.raises(InputError) as exc:
        read_requirements(path)
    return str(exc.value).splitlines()


@pytest.mark.parametrize("text", ["1,5", "1,5 kN*m", "1620,0"])
def test_a_decimal_comma_in_a_number_box_is_refused_in_the_batchs_words(text, tmp_path):
    src = _rudder_with(TORQUE, f'torque_Nm = "{text}"', tmp_path)
    (line,) = _batch_refusal(src)
    value, err = fields.parse_text(_field("rotary", "rotary.torque_Nm"), text)
    assert value is None
    assert line == f"rotary.torque_Nm = {err}"  # the field's path, then the same words


async def test_typing_1_comma_5_says_so_beside_the_field(wizard):
    src = EXAMPLES / "rudder_actuator.toml"
    app = DriveAdvisorApp(drafts.open_doc(src).doc, src, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+n")
        await pilot.pause()
        box = app.query_one("#f-rotary-torque-Nm", Input)
        box.focus()
        box.value = ""
        await pilot.press(*"1,5")
        await pilot.pause()
        said = wizard.text(app.query_one("#f-rotary-torque-Nm-err", Static))
        assert "'1,5'" in said and "',' is not allowed" in said and "N·m" in said
        assert "rotary" not in app.doc or "torque_Nm" not in app.doc["rotary"]


def test_a_loaded_item_with_a_comma_is_one_item_refused_as_the_batch_refuses_it(tmp_path):
    src = _rudder_with(SPEEDS, 'candidate_speeds_rpm = ["3000 rpm", "3,5 rpm"]', tmp_path)
    loaded = drafts.open_doc(src)
    assert loaded.doc["motor"]["candidate_speeds_rpm"] == ["3000 rpm", "3,5 rpm"]
    assert loaded.problems == [f"{line}; fix it here" for line in _batch_refusal(src)]
    speeds = _field("rotary", "motor.candidate_speeds_rpm")
    shown = fields.to_text(speeds, loaded.doc["motor"]["candidate_speeds_rpm"])
    assert shown == '3000 rpm, "3,5 rpm"'
    value, err = fields.parse_text(speeds, shown)
    (line,) = _batch_refusal(src)
    assert value is None
    assert err == line.replace("motor.candidate_speeds_rpm[2]", "item 2")


@pytest.mark.parametrize(
    ("items", "text"),
    [
        (["3000 rpm", "3,5 rpm"], '3000 rpm, "3,5 rpm"'),
        (["3000 rpm", "4000 rpm; 5000 rpm"], '3000 rpm, "4000 rpm; 5000 rpm"'),
        (["3000", 5000], '"3000", 5000'),  # a number in quotes: text, as in a file
        ([" ", 5000], '" ", 5000'),
        (['3"5 rpm'], '"3""5 rpm"'),
        ([4000.0, "9000 rpm"], "4000, 9000 rpm"),
    ],
)
def test_a_loaded_list_is_shown_as_text_that_reads_back_as_the_batch_reads_it(
    items, text, tmp_path
):
    speeds = _field("rotary", "motor.candidate_speeds_rpm")
    assert fields.to_text(speeds, items) == text
    value, err = fields.parse_text(speeds, text)
    src = _rudder_with(SPEEDS, f"candidate_speeds_rpm = {json.dumps(items)}", tmp_path)
    try:
        read = read_requirements(src).motor.candidate_speeds_rpm
    except InputError as exc:
        (line,) = str(exc).splitlines()
        where, said = line.split(" = ", 1)
        assert value is None and err == f"item {where[where.index('[') + 1 : -1]} = {said}"
    else:
        assert err is None and value == read


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ('"4000 rpm", "9000 rpm"', [4000.0, 9000.0]),  # pasted from a file
        ('4000 rpm; "9000 rpm"', [4000.0, 9000.0]),
        ("5000,10000", [5000.0, 10000.0]),  # a comma between items, as in a file's array
    ],
)
def test_the_list_box_takes_items_as_a_files_array_does(text, want):
    assert fields.parse_text(_field("rotary", "motor.candidate_speeds_rpm"), text) == (want, None)


@pytest.mark.parametrize("text", ["3000 rpm, 3,5 rpm", "3000 rpm,3,5 rpm", '3000 rpm, "3,5 rpm"'])
def test_a_decimal_comma_typed_in_the_list_box_is_one_item_refused_as_the_batch_does(
    text, tmp_path
):
    """Typed with no space before a unit, ``3,5 rpm`` is the item a file would hold, not the
    items 3 and 5 rpm; the batch refuses ``["3000 rpm", "3,5 rpm"]`` in the same words."""
    src = _rudder_with(SPEEDS, 'candidate_speeds_rpm = ["3000 rpm", "3,5 rpm"]', tmp_path)
    (line,) = _batch_refusal(src)
    value, err = fields.parse_text(_field("rotary", "motor.candidate_speeds_rpm"), text)
    assert value is None
    assert err == line.replace("motor.candidate_speeds_rpm[2]", "item 2")


@pytest.mark.parametrize("text", ['"3,5 rpm', '"3000 rpm" 5'])
def test_an_unclosed_quote_in_the_list_box_is_said(text):
    value, err = fields.parse_text(_field("rotary", "motor.candidate_speeds_rpm"), text)
    assert value is None and "closing quote" in err


async def test_a_loaded_comma_item_is_fixed_in_its_box_and_computed_as_the_batch(tmp_path, wizard):
    src = _rudder_with(SPEEDS, 'candidate_speeds_rpm = ["3000 rpm", "3,5 rpm"]', tmp_path)
    fixed = _rudder_with(
        SPEEDS, 'candidate_speeds_rpm = ["3000 rpm", "3500 rpm"]', tmp_path, "fixed.toml"
    )
    app = DriveAdvisorApp(drafts.open_doc(src).doc, src, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        while not app.query(BOX):
            await pilot.press("ctrl+n")
            await pilot.pause()
        box = app.query_one(BOX, Input)
        assert box.value == '3000 rpm, "3,5 rpm"'
        said = wizard.text(app.query_one(f"{BOX}-err", Static))
        assert "item 2 = '3,5 rpm'" in said and "',' is not allowed" in said
        await pilot.press("ctrl+r")  # refused while the box shows an error
        await pilot.pause()
        assert app.results_version == 0
        box.focus()
        box.value = ""
        await pilot.press(*"3000 rpm, 3,5 rpm")
        await pilot.pause()
        said = wizard.text(app.query_one(f"{BOX}-err", Static))
        assert "item 2 = '3,5 rpm'" in said and "',' is not allowed" in said
        box.value = ""
        await pilot.press(*'3000 rpm, "3500 rpm"')
        await pilot.pause()
        assert not wizard.text(app.query_one(f"{BOX}-err", Static)).strip()
        await wizard.compute(pilot)
        target = tmp_path / "out.report.toml"
        await wizard.export_report(pilot, target)
    assert app.doc["motor"]["candidate_speeds_rpm"] == [3000.0, 3500.0]
    assert target.read_text(encoding="utf-8") == to_toml(advise(read_requirements(fixed)))
