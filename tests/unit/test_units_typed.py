"""Unit strings as they are typed: the drive's volts and microfarads, the numbers of an
uncertain input in that input's unit, a number in the key's own unit read as typed (not
rounded onto a limit), and what a typeset page pastes (the dot operator, the ohm sign)
read as what it stands for; a character still refused is named by its code point."""

import pytest
from helpers import EXAMPLES

from advisor.core.engine import advise
from advisor.core.errors import InputError
from advisor.core.io_safety import read_toml
from advisor.core.reading import parse_requirements
from advisor.core.report import to_toml
from advisor.core.units import UnitError, to_unit

ROTARY = EXAMPLES / "rudder_actuator.toml"
ROBUST = EXAMPLES / "uncertainty" / "linear_screw_robust.toml"


@pytest.mark.parametrize(
    ("text", "unit", "by_hand"),
    [
        ("300 V", "V", 300.0),
        ("0.4 kV", "V", 0.4 * 1000),  # SI prefix k = 10³
        ("24000 mV", "V", 24000 / 1000),
        ("470 uF", "µF", 470.0),
        ("470 µF", "µF", 470.0),
        ("0.47 mF", "µF", 0.47e-3 / 1e-6),  # 470 µF
        ("4.7e5 nF", "µF", 4.7e5 * 1e-9 / 1e-6),  # 470 µF
    ],
)
def test_volts_and_farads_convert(text, unit, by_hand):
    assert to_unit(text, unit) == pytest.approx(by_hand, rel=1e-12)


def test_a_capacitance_is_not_a_voltage():
    with pytest.raises(UnitError, match="mF is a capacitance, not a voltage; expected V"):
        to_unit("2 mF", "V")


def _rotary_drive(**drive) -> dict:
    doc = read_toml(ROTARY)
    doc["drive"] = drive
    return doc


def test_the_drive_keys_take_their_units_and_give_the_plain_report():
    """[drive] bus_voltage_V, bus_max_voltage_V, bus_capacitance_uF as strings in their
    units: the same report as the plain numbers 300, 400, 470."""
    typed = _rotary_drive(
        bus_voltage_V="300 V", bus_max_voltage_V="0.4 kV", bus_capacitance_uF="470 uF"
    )
    plain = _rotary_drive(bus_voltage_V=300, bus_max_voltage_V=400, bus_capacitance_uF=470)
    assert to_toml(advise(parse_requirements(typed))) == to_toml(advise(parse_requirements(plain)))


def _robust(**row) -> dict:
    doc = read_toml(ROBUST)
    force = next(r for r in doc["uncertainty"]["inputs"] if r["name"] == "linear.force_N")
    force.update(row)
    return doc


def test_an_uncertain_input_takes_strings_in_its_own_unit():
    """sd = "175 N", mean = "3.5 kN" for linear.force_N are sd = 175, mean = 3500 (N):
    the models read them so (the report of the robust choice is not needed to see it)."""
    from advisor.core.requirements import validate_with_models

    req = validate_with_models(_robust(distribution="normal", sd="0.175 kN", mean="3.5 kN"))
    row = next(r for r in req.uncertainty.inputs if r.name == "linear.force_N")
    assert (row.sd, row.mean) == (0.175 * 1000, 3.5 * 1000)


def test_an_uncertain_input_refuses_another_kind_naming_its_unit():
    with pytest.raises(InputError) as err:
        parse_requirements(_robust(distribution="normal", sd=175, mean="3.5 m"))
    assert "mean = '3.5 m': m is a length, not a force; expected N" in str(err.value)


def test_a_friction_input_takes_plain_numbers():
    doc = read_toml(ROBUST)
    doc["uncertainty"]["inputs"].append(
        {"name": "screw.thrust.friction_coefficient", "distribution": "uniform", "low": "1 N"}
    )
    with pytest.raises(InputError, match="N is a force, not a pure number"):
        parse_requirements(doc)


def test_a_number_in_the_keys_own_unit_is_read_as_typed():
    """No conversion, no rounding: 0.99999999999999 N is below the 1 N limit of force_N,
    as the plain number is (12-digit rounding once made it 1.0 and let it pass)."""
    assert to_unit("0.99999999999999 N", "N") == 0.99999999999999
    assert to_unit("0.0009999999999999 m", "m") == 0.0009999999999999
    assert to_unit("200 mm", "m") == 0.2  # a conversion is still rounded (not 0.2000…04)
    doc = read_toml(EXAMPLES / "linear_screw_actuator.toml")
    doc["screw"].pop("thread", None)
    for value in (0.99999999999999, "0.99999999999999 N"):
        doc["linear"]["force_N"] = value
        with pytest.raises(InputError, match="must be ≥ 1"):
            parse_requirements(doc)


@pytest.mark.parametrize(
    ("text", "unit", "by_hand"),
    [
        ("1620 N\u22c5m", "N·m", 1620.0),  # DOT OPERATOR, LaTeX's \cdot
        ("1.62 kN\u22c5m", "N·m", 1.62 * 1000),
        ("1.14 \u2126", "Ω", 1.14),  # OHM SIGN, canonically Ω U+03A9
        ("1140 m\u2126", "Ω", 1140 / 1000),
    ],
)
def test_what_a_typeset_page_pastes_is_read(text, unit, by_hand):
    assert to_unit(text, unit) == pytest.approx(by_hand, rel=1e-12)


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("1 N\u2219m", "'∙' (U+2219 BULLET OPERATOR) is not allowed"),
        ("\uff11 N", "'１' (U+FF11 FULLWIDTH DIGIT ONE) is not allowed; use '1' (U+0031)"),
        ("5 kN\u200f", "U+200F (RIGHT-TO-LEFT MARK) is not allowed"),
        ("5 %", "'%' is not allowed"),
    ],
)
def test_a_refused_character_is_named_by_its_code_point(text, said):
    with pytest.raises(UnitError) as err:
        to_unit(text, "N·m")
    assert said in str(err.value)
