"""Duty values far below any physical cycle (5e-324 s, 1e-300 of a load) are refused by name,
and the smallest values allowed give a design or a stated infeasibility: never an internal
error (found by a reviewer: a segment of 5e-324 s divided by zero, exit 1)."""

import copy
from pathlib import Path

import pytest

from advisor.core.engine import advise
from advisor.core.errors import InfeasibleError, InputError
from advisor.core.io_safety import read_toml
from advisor.core.reading import parse_requirements
from advisor.core.report import to_toml

EXAMPLES = Path(__file__).parents[2] / "examples"
ROTARY = read_toml(EXAMPLES / "rudder_actuator_duty.toml")
LINEAR = read_toml(EXAMPLES / "valve_actuator_duty.toml")
KEEP = ("load_inertia_kgm2", "motor_inertia_kgm2", "thermal_time_constant_s", "moving_mass_kg")


def _with(base: dict, duty: dict | None = None, **keys) -> dict:
    doc = copy.deepcopy(base)
    if duty is not None:
        doc["duty"] = {k: v for k, v in doc["duty"].items() if k in KEEP} | duty
    doc["duty"].update(keys)
    return doc


def _segment(base: dict, key: str, value: float) -> dict:
    doc = copy.deepcopy(base)
    doc["duty"]["segments"][0][key] = value
    return doc


S9 = {"duty_type": "S9", "loads": [{"load_share": 1.0, "time_share": 0.5}]}

REFUSED = [
    ("duty.segments[1].force_N", _segment(LINEAR, "force_N", 1e-300)),
    ("duty.segments[1].force_N", _segment(LINEAR, "force_N", 0.5)),
    ("duty.segments[1].time_s", _segment(ROTARY, "time_s", 5e-324)),
    ("duty.segments[1].time_s", _segment(ROTARY, "time_s", 1e-300)),
    ("duty.segments[1].accel_fraction", _segment(ROTARY, "accel_fraction", 1e-300)),
    ("duty.cycles_per_hour", _with(ROTARY, cycles_per_hour=5e-324)),
    ("duty.motor_inertia_kgm2", _with(ROTARY, motor_inertia_kgm2=5e-324)),
    ("duty.starts_per_hour", _with(ROTARY, {"duty_type": "S7", "starts_per_hour": 5e-324})),
    ("duty.cycle_time_s", _with(ROTARY, {"duty_type": "S1", "cycle_time_s": 5e-324})),
    ("duty.cycle_time_s", _with(LINEAR, {"duty_type": "S1", "cycle_time_s": 5e-324})),
    (
        "duty.loads[1].load_share",
        _with(
            LINEAR,
            S9
            | {
                "loads": [
                    {"load_share": 1e-300, "time_share": 0.5},
                    {"load_share": 1.0, "time_share": 0.5},
                ]
            },
        ),
    ),
]


@pytest.mark.parametrize(("field", "doc"), REFUSED, ids=[f for f, _ in REFUSED])
def test_a_vanishing_duty_value_is_refused_by_name(field, doc):
    with pytest.raises(InputError) as exc:
        parse_requirements(doc)
    assert any(m.startswith(field) for m in exc.value.messages), exc.value.messages


SMALLEST = [
    _segment(ROTARY, "time_s", 1e-3),
    _segment(ROTARY, "accel_fraction", 1e-3),
    _with(ROTARY, motor_inertia_kgm2=1e-11),
    _segment(LINEAR, "force_N", 0.0),
    _segment(LINEAR, "force_N", 1.0),
    _with(ROTARY, {"duty_type": "S7", "starts_per_hour": 1e-3}),
    _with(ROTARY, {"duty_type": "S1", "cycle_time_s": 1e-3}),
    _with(LINEAR, {"duty_type": "S1", "cycle_time_s": 1e-3}),
    _with(
        LINEAR,
        {
            "duty_type": "S9",
            "loads": [
                {"load_share": 0.0, "time_share": 0.5},
                {"load_share": 1e-3, "time_share": 0.5},
            ],
        },
    ),
]


@pytest.mark.parametrize("doc", SMALLEST)
def test_the_smallest_values_allowed_give_a_design_or_a_reason(doc):
    try:
        report = advise(parse_requirements(doc))
    except InfeasibleError as exc:
        assert exc.reasons
    else:
        assert to_toml(report)  # every number of the report finite
