"""A value typed as a quantity string and refused by its range is echoed as typed, with the
SI number it was read as beside it, so the reader finds what they wrote; a plain number is
echoed as before."""

import pytest

from advisor.cli import main
from advisor.core.errors import InputError
from advisor.core.reading import parse_requirements

_RANGE = "must be ≥ 1 (rated axial force, N; 1 N … 5 MN)"


def _doc(force, frequency=50) -> dict:
    return {
        "application": {"kind": "linear"},
        "linear": {
            "force_N": force,
            "stroke_m": 0.2,
            "travel_time_s": 5,
            "support_span_m": 0.4,
        },
        "motor": {"kind": "induction", "supply_frequency_Hz": frequency},
    }


def _messages(doc: dict, compiled: bool) -> list[str]:
    with pytest.raises(InputError) as exc:
        parse_requirements(doc, compiled=compiled)
    return exc.value.messages


@pytest.mark.parametrize("compiled", [True, False])
def test_a_quantity_below_its_range_is_echoed_as_typed_with_its_si_value(compiled):
    # 3500 µN = 3500·10⁻⁶ N = 0.0035 N, below the 1 N allowed
    assert _messages(_doc("3500 µN"), compiled) == [
        f"linear.force_N = '3500 µN' (0.0035 N): {_RANGE}"
    ]


@pytest.mark.parametrize("compiled", [True, False])
def test_a_quantity_that_reads_as_typed_is_echoed_once(compiled):
    # '-5 N' is -5 N: the SI value would only repeat it; '60 Hz' likewise, refused by the
    # catalog's 50 Hz
    lines = _messages(_doc("-5 N", "60 Hz"), compiled)
    assert lines[0] == f"linear.force_N = '-5 N': {_RANGE}"
    assert lines[1].startswith("motor.supply_frequency_Hz = '60 Hz': must be 50")


def test_a_plain_number_is_echoed_as_before():
    assert _messages(_doc(0.0035, 60), True) == [
        f"linear.force_N = 0.0035: {_RANGE}",
        "motor.supply_frequency_Hz = 60: must be 50: the induction motor catalog holds 50 Hz "
        "ratings (supply frequency, Hz)",
    ]


def test_an_item_of_a_list_of_quantities():
    # rotary motor speeds: 100 … 2·10⁵ rpm each; '1 rad/s' = 60/(2π) rpm = 9.5493 rpm
    doc = {
        "application": {"kind": "rotary"},
        "rotary": {"torque_Nm": 100, "speed_rpm": 10},
        "motor": {"kind": "bldc", "candidate_speeds_rpm": [5000, "1 rad/s"]},
    }
    (line,) = _messages(doc, True)
    assert line.startswith("motor.candidate_speeds_rpm[2] = '1 rad/s' (9.5493 rpm): must be ≥ 100")


def test_the_batch_prints_the_line(tmp_path, capsys):
    f = tmp_path / "r.toml"
    f.write_text(
        '[application]\nkind = "linear"\n[linear]\nforce_N = "3500 µN"\nstroke_m = 0.2\n'
        'travel_time_s = 5\nsupport_span_m = 0.4\n[motor]\nkind = "induction"\n',
        encoding="utf-8",
    )
    assert main(["--batch", str(f)]) == 2
    assert f"linear.force_N = '3500 µN' (0.0035 N): {_RANGE}" in capsys.readouterr().err


def test_a_family_variant_is_worded_as_the_batch_words_it():
    from advisor.family.adapter import field_problems

    (problem,) = field_problems(_doc("3500 µN"))
    assert problem.message == f"linear.force_N = '3500 µN' (0.0035 N): {_RANGE}"


@pytest.mark.parametrize("compiled", [True, False])
@pytest.mark.parametrize("typed", ["0.9999999 N", "0.9999995 N", "0.99999949 N"])
def test_a_value_just_below_the_limit_is_not_echoed_as_the_limit(compiled, typed):
    # 0.9999999 N < 1 N is refused; six digits of it read "1 N", which "must be ≥ 1" would
    # contradict: typed in the field's own unit, the text alone is echoed
    assert _messages(_doc(typed), compiled) == [f"linear.force_N = '{typed}': {_RANGE}"]


@pytest.mark.parametrize("compiled", [True, False])
def test_a_converted_value_just_below_the_limit_shows_the_digits_that_keep_it_below(compiled):
    # 0.0009999995 kN = 0.9999995 N: six digits would say 1 N; seven say 0.9999995
    (line,) = _messages(_doc("0.0009999995 kN"), compiled)
    assert line == f"linear.force_N = '0.0009999995 kN' (0.9999995 N): {_RANGE}"


def _uncertain_force(sd) -> dict:
    doc = _doc(3500)
    doc["uncertainty"] = {
        "inputs": [{"name": "linear.force_N", "distribution": "normal", "sd": sd}]
    }
    return doc


@pytest.mark.parametrize("compiled", [True, False])
def test_an_uncertainty_row_is_echoed_in_the_unit_of_its_input(compiled):
    # a row's numbers are in the unit of the input it names: -0.175 kN = -175 N
    (line,) = _messages(_uncertain_force("-0.175 kN"), compiled)
    assert line.startswith("uncertainty.inputs[1].sd = '-0.175 kN' (-175 N): must be > 0")
    (line,) = _messages(_uncertain_force("-175 N"), compiled)
    assert line.startswith("uncertainty.inputs[1].sd = '-175 N': must be > 0")


@pytest.mark.parametrize("compiled", [True, False])
@pytest.mark.parametrize("sd", ["175 N", 175])
def test_a_mistyped_input_name_is_refused_for_the_name(compiled, sd):
    # 'linear.force' (the _N forgotten) names no input, so there is no unit to read
    # '175 N' in: the refusal names the input and the allowed ones, not the unit
    doc = _uncertain_force(sd)
    doc["uncertainty"]["inputs"][0]["name"] = "linear.force"
    (line,) = _messages(doc, compiled)
    assert line.startswith(
        "uncertainty.inputs[1].name = 'linear.force': must be one of 'linear.force_N', "
        "'linear.support_span_m', 'screw.friction_coefficient' or "
        "'screw.thrust.friction_coefficient'"
    )
