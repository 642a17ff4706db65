"""Seed 001's worked example, end to end through the engine (DOMAIN.md, section 001)."""

import math
import tomllib

import pytest
from helpers import EXAMPLES, seed001_requirement

from advisor.core.engine import advise
from advisor.core.reading import parse_requirements, read_requirements
from advisor.core.report import to_toml
from rules import induction as im_rules


@pytest.fixture(scope="module")
def report():
    return tomllib.loads(
        to_toml(advise(read_requirements(EXAMPLES / "linear_screw_actuator.toml")))
    )


def test_thread_speed_and_pole_pairs(report):
    d = report["design"]
    # Seed 001: Tr16x2, N = 100, n = 1200 rpm, p = 2
    assert d["screw"]["thread"] == "Tr16x2"
    assert d["screw"]["revolutions"] == pytest.approx(100)
    assert d["screw"]["linear_speed_m_s"] == pytest.approx(0.04)
    assert d["motor"]["speed_rpm"] == pytest.approx(1200)
    assert d["motor"]["pole_pairs"] == 2


def test_torque_paper_and_standard_side_by_side(report):
    s = report["design"]["screw"]
    assert s["friction_model"] == "paper"
    assert s["torque_Nm"] == pytest.approx(5.085, abs=5e-4)  # seed 001, eq. (1)
    assert s["torque_paper_Nm"] == s["torque_Nm"]
    # standard form by hand: 3500·0.0075·tan(ψ + φ'), tan φ' = 0.15/cos 15° → 5.2249 N·m
    assert s["torque_standard_Nm"] == pytest.approx(5.2249, abs=1e-4)
    assert s["self_locking"] is True
    assert s["efficiency"] == pytest.approx(0.2191, abs=1e-4)


def test_motor_power_and_neighbours(report):
    m = report["design"]["motor"]
    # required power M·ω = 5.08485 · 1200·π/30 = 638.98 W → nearest rated power not below: 0.75
    assert m["required_power_kW"] == pytest.approx(5.08485 * 1200 * math.pi / 30 / 1e3, rel=1e-5)
    assert m["rated_power_kW"] == 0.75
    assert [c["rated_power_kW"] for c in m["candidates"]] == [0.55, 0.75, 1.1]
    assert [c["role"] for c in m["candidates"]] == ["lower", "selected", "higher"]
    lower, selected, higher = m["candidates"]
    assert not lower["suitable"] and selected["suitable"] and higher["suitable"]
    # rated torque of 4A71B4: 750 W / (1390·π/30) = 5.1525 N·m ≥ 5.085
    assert selected["rated_torque_Nm"] == pytest.approx(750 / (1390 * math.pi / 30), rel=1e-5)


def test_characteristics_are_arrays_with_both_ends(report):
    # the archive keeps the curves in [curves] at the end, keyed by where they belong
    assert list(report)[-1] == "curves"
    for i, c in enumerate(report["design"]["motor"]["candidates"], 1):
        assert "curve" not in c
        curve = report["curves"][f"design.motor.candidates[{i}].curve"]
        assert len(curve["slip"]) == len(curve["torque_Nm"]) == len(curve["speed_rpm"]) == 41
        assert curve["slip"][0] == 0 and curve["slip"][-1] == 1
        assert curve["torque_Nm"][0] == 0
        assert curve["torque_Nm"][-1] == pytest.approx(c["starting_torque_Nm"], rel=1e-5)
        assert curve["speed_rpm"][0] == 1500 and curve["speed_rpm"][-1] == 0


def test_every_check_reported_with_margin(report):
    ids = {c["id"] for c in report["checks"]}
    assert {"core_stress", "buckling", "nut_pressure", "nut_height", "nut_turns"} <= ids
    assert all(c["passed"] and c["margin"] >= 1 for c in report["checks"])
    buckling = next(c for c in report["checks"] if c["id"] == "buckling")
    # P_cr/3 = 21120.5/3 = 7040.2 N against 3500 N
    assert buckling["limit"] == pytest.approx(21120.5 / 3, rel=1e-5)


def test_decisions_trace(report):
    ids = [d["id"] for d in report["decisions"]]
    assert ids == ["SCR-01", "SCR-02", "SCR-03", "SCR-04", "SCR-05", "IM-01", "IM-02", "IM-03"]
    for d in report["decisions"]:
        assert d["title"] and d["decision"] and d["rationale"] and d["source"]
    # the sources by bibliography id, the text by the authors' names
    assert all("seed-001" in d["sources"] for d in report["decisions"])
    assert report["decisions"][0]["source"] == "Ivanov, Kolesnik, Koloshenko (seed 001)"
    seed = next(s for s in report["sources"] if s["id"] == "seed-001")
    assert seed["file"] == "001_085658f38eaaea54.txt"
    assert seed["authors"] == ["Ivanov S. N.", "Kolesnik M. B.", "Koloshenko Yu. B."]


def test_free_choice_is_the_smallest_passing_thread():
    # Without an imposed thread: Tr12 fails buckling (Tr12x2: d3 = 9.5 mm, P_cr = 5180 N,
    # margin 0.49); Tr14x3 (d3 = 10.5): P_cr = π²·E·(π·10.5⁴/64)/0.4² = 7.74 kN, 7.74/3/3.5
    # = 0.74 fails; Tr14x2 (d3 = 11.5): P_cr = 11.14 kN, margin 1.06 passes.
    e = 210e9

    def p_cr(d3_mm):
        return math.pi**2 * e * (math.pi * (d3_mm / 1e3) ** 4 / 64) / 0.4**2

    assert p_cr(10.5) / 3 < 3500 < p_cr(11.5) / 3
    rep = advise(parse_requirements(seed001_requirement(material_pair="steel_bronze")))
    assert rep.design.screw.thread == "Tr14x2"
    assert rep.design.screw.imposed is False
    assert rep.design.motor.pole_pairs == 2  # 0.2 m / 2 mm = 100 rev in 5 s: 1200 rpm


def test_imposed_thread_reports_the_advisors_own_choice(report):
    s = report["design"]["screw"]
    assert s["imposed"] is True and s["advisor_choice"] == "Tr14x2"


def test_holding_takes_the_finest_self_locking_pitch():
    req = seed001_requirement()
    req["application"]["hold_without_power"] = True
    req["linear"]["force_N"] = 20000
    req["linear"]["travel_time_s"] = 20
    rep = advise(parse_requirements(req))
    s = rep.design.screw
    assert s.self_locking_at_low_friction
    # d = 28 mm offers 8, 5 and 3 mm. The finest, Tr28x3, needs z = 20000/(π·26.5·1.5·10)
    # = 16.0 turns of nut (more than 10): it fails, so the finest passing pitch is 5 mm.
    assert 20000 / (math.pi * 26.5 * 1.5 * 10) > 10
    assert (s.thread, s.pitch_mm) == ("Tr28x5", 5.0)
    holding = next(d for d in rep.decisions if d.id == "SCR-05")
    assert "holds the load without power" in holding.decision


def test_motor_speed_under_the_load_uses_the_slip():
    # 4A71B4: 0.75 kW, rated 1390 rpm, s_n = 1 - 1390/1500 = 0.0733. At its rated torque
    # (5.1525 N·m) it cannot reach 1450 rpm; at 2 N·m the slip is about s_n·2/5.1525 = 0.028
    # on the near-linear part of the curve, i.e. ≈ 1457 rpm (the refined curve: 1470 rpm).
    from advisor.calc.sizing import drive_working_speed, fit_motor
    from catalogs import load_catalogs

    m = next(m for m in load_catalogs().motors if m.model == "4A71B4")
    fit = fit_motor(m)
    assert drive_working_speed(fit, 5.15, 1450) is None
    n = drive_working_speed(fit, 2.0, 1450)
    assert n is not None and n == pytest.approx(1457, rel=0.01)
    assert drive_working_speed(fit, 5.2, 1000) is None  # above its rated torque


def test_power_band_rule_states_the_designs_power():
    series = [0.25, 0.37, 0.55, 0.75, 1.1]
    f = im_rules.rated_power_band(0.639, 0.742, 0.75, series)
    assert f.value == [0.55, 0.75, 1.1]
    assert f.inputs == {
        "required_power_kW": 0.639,
        "working_power_kW": 0.742,
        "rated_power_kW": 0.75,
        "band_kW": [0.55, 0.75, 1.1],
    }
    assert "0.75 kW" in f.decision and "0.742 kW" in f.rationale
    assert im_rules.rated_power_band(0.1, 0.2, 0.25, series).value == [0.25, 0.37]
    assert im_rules.rated_power_band(1.0, 1.05, 1.1, series).value == [0.75, 1.1]
