"""The linear duty's IEC types as a reviewer checked them by hand (issue 15): the decisions
state the design's numbers, S2 is one run (no cycles per hour), starts are reported only
where they are counted, an unused duty key is said, and minutes are a unit.

Hand basis (4A71B4, 0.75 kW at 1390 rpm): M_n = 750/(1390·π/30) = 5.1525 N·m; the screw's
5.08485 N·m (seed 001, paper friction)."""

import re
import tomllib

import pytest
from helpers import EXAMPLES

from advisor.core.engine import advise
from advisor.core.reading import parse_requirements

M_N = 750.0 / (1390.0 * 3.141592653589793 / 30.0)
M_L = 5.08485


def _doc(**duty) -> dict:
    doc = tomllib.loads((EXAMPLES / "valve_actuator_duty.toml").read_text(encoding="utf-8"))
    doc["duty"] = duty
    return doc


def _decision(report, rule_id):
    return next(d for d in report.decisions if d.id == rule_id)


def test_s2_is_one_run_and_its_limit_is_k_times_rated():
    r = advise(parse_requirements(_doc(duty_type="S2", duration_min=30.0)))
    duty = r.design.duty
    assert duty.thermal_utilisation == pytest.approx(M_L / (1.2 * M_N), rel=1e-5)  # 0.8224
    assert duty.cycles_per_hour is None  # one run from cold, not a repeated cycle
    assert duty.allowed_starts_per_hour is None  # nothing counts starts in S2
    check = next(c for c in r.checks if c.id == "duty_rms_torque")
    assert check.name == "torque of the S2 run within K·M_n (K = 1.2, SEW's S2 factor)"
    assert "sew-gearmotors" in check.sources and "klyuchev" not in " ".join(check.sources)


def test_du09_names_the_cdf_it_was_given():
    # 0.405 is read at the 60 % row (the next larger cdf): K = 1.1; the text must not say 40 %
    r = advise(parse_requirements(_doc(duty_type="S3", cyclic_duration_factor=0.405)))
    d = _decision(r, "DU-09")
    assert d.decision.startswith("S3 at cdf 40.5 %: the motor may carry K = 1.1 times")
    assert "cdf 40 % → 1.15" in d.rationale and "on-time, here 4.05 min" in d.rationale


def test_du05_states_the_cycles_peak_and_says_when_no_start_is_counted():
    r = advise(parse_requirements(_doc(duty_type="S3", cyclic_duration_factor=0.4)))
    d = _decision(r, "DU-05")
    peak = r.design.duty.peak_torque_Nm
    assert f"the cycle's peak torque is {peak:.4g} N·m" in d.decision
    assert "No start is counted in this duty" in d.rationale
    # the segment example counts starts: there the peak is the motor's starting torque
    seg = tomllib.loads((EXAMPLES / "valve_actuator_duty.toml").read_text(encoding="utf-8"))
    r = advise(parse_requirements(seg))
    d = _decision(r, "DU-05")
    assert "mean starting torque in a start" in d.rationale
    assert re.search(r"peak torque is 9\.42 N·m", d.decision)
    assert r.design.duty.allowed_starts_per_hour is not None


@pytest.mark.parametrize(
    "duty, words",
    [
        (
            {"duty_type": "S2", "duration_min": 30.0, "cyclic_duration_factor": 0.4},
            "duty.cyclic_duration_factor, because duty_type = 'S2' does not use it",
        ),
        (
            {"duty_type": "S3", "cyclic_duration_factor": 0.4, "duration_min": 5.0},
            "duty.duration_min, because duty_type = 'S3' does not use it",
        ),
        (
            {
                "duty_type": "S4",
                "cyclic_duration_factor": 0.4,
                "starts_per_hour": 10.0,
                "cycle_time_s": 900.0,
            },
            "duty.cycle_time_s, because duty_type = 'S4' does not use it",
        ),
    ],
)
def test_a_duty_key_the_form_does_not_use_is_said(duty, words):
    r = advise(parse_requirements(_doc(**duty)))
    assert any(words in w for w in r.warnings), r.warnings


@pytest.mark.parametrize("text", ["30 min", "1800 s", "0.5 h"])
def test_the_s2_duration_takes_minutes_seconds_and_hours(text):
    r = advise(parse_requirements(_doc(duty_type="S2", duration_min=text)))
    assert r.design.duty.thermal_utilisation == pytest.approx(M_L / (1.2 * M_N), rel=1e-5)
