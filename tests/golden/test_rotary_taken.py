"""Issue 14, "Use this imposes the alternative in the requirement": the rotary requirement can
take the design space's lightest or slimmest reducer (gearbox.choice) and put the one-way
device at the output (one_way.location); and the speed choice (BL-02) weighs the efficiency
of the reducer the design then adopts (issue 12: a decision states the design's numbers)."""

import tomllib
from pathlib import Path

import pytest

from advisor.core.engine import advise
from advisor.core.errors import InfeasibleError
from advisor.core.reading import parse_requirements
from advisor.core.report import to_toml

VALVE = Path(__file__).parents[2] / "examples" / "valve_actuator_hold.toml"


def _doc(**tables) -> dict:
    doc = tomllib.loads(VALVE.read_text(encoding="utf-8"))
    for table, values in tables.items():
        doc.setdefault(table, {}).update(values)
    return doc


def _report(doc: dict) -> dict:
    return tomllib.loads(to_toml(advise(parse_requirements(doc))))


def _decisions(rep: dict) -> dict[str, dict]:
    return {d["id"]: d for d in rep["decisions"]}


@pytest.fixture(scope="module")
def by_rules() -> dict:
    return _report(_doc())


@pytest.mark.parametrize(
    ("taken", "which"), [("lightest", "optimum"), ("slimmest", "optimum_min_diameter")]
)
def test_the_requirement_takes_the_space_reducer(by_rules, taken, which):
    rep = _report(_doc(gearbox={"choice": taken}))
    gb, best = rep["design"]["gearbox"], by_rules["design"]["gearbox"][which]
    for key in ("mass_kg", "outer_diameter_mm", "length_mm", "efficiency"):
        assert gb[key] == best[key], key
    assert [s["ratio"] for s in gb["stages"]] == [s["ratio"] for s in best["stages"]]
    d = _decisions(rep)
    assert "WG-04" not in d  # "the rule design is kept" would not be true
    wg6 = d["WG-06"]["inputs"]
    assert wg6["taken"] == wg6["asked"] == taken
    rule = by_rules["design"]["gearbox"]
    for key in ("mass_kg", "outer_diameter_mm", "length_mm", "efficiency"):
        assert wg6[f"rule_{key}"] == rule[key], key
    assert wg6["rule_stages"] == len(rule["stages"]) and wg6["rule_fits"] is True
    assert "as the requirement asks (gearbox.choice)" in d["WG-06"]["decision"]
    assert "is not used" in d["WG-06"]["decision"]
    assert not any("heavier than the lightest" in w for w in rep["warnings"])
    # the motor works behind the reducer taken: M_m = M_out/(q·η)
    m = rep["design"]["motor"]
    assert m["torque_Nm"] == pytest.approx(
        1000.0 / (gb["total_ratio"] * gb["efficiency"]), rel=1e-5
    )


def test_the_rules_stay_the_default(by_rules):
    assert by_rules["requirements"]["gearbox"]["choice"] == "rules"
    d = _decisions(by_rules)
    assert "WG-04" in d and "WG-06" not in d


def test_the_device_at_the_output_holds_the_output_torque(by_rules):
    rep = _report(_doc(one_way={"location": "output_side"}))
    ow, was = rep["design"]["one_way"], by_rules["design"]["one_way"]
    # q = 3000/5 = 600, two stages of η = 0.8944: the motor side holds 1000/(600·0.8) N·m
    at_motor = 1000.0 / (600 * 0.8944**2)
    assert was["torque_Nm"] == pytest.approx(at_motor, rel=1e-5)
    assert ow["location"] == "output side" and ow["torque_Nm"] == 1000.0
    assert ow["type"] == was["type"] == "roller_clutch"
    # the same clutch, now where the torque is 480 times larger, is the output_side row of
    # the motor-side report; the motor-side clutch is shown beside it
    assert ow["mass_kg"] == was["output_side"]["mass_kg"]
    assert ow["motor_side"]["mass_kg"] == was["mass_kg"]
    assert ow["motor_side"]["torque_Nm"] == pytest.approx(at_motor, rel=1e-5)
    assert "output_side" not in ow
    assert all(a["location"] == "output side" for a in ow["alternatives"])
    ow1 = _decisions(rep)["OW-01"]
    assert ow1["inputs"]["torque_Nm"] == 1000.0
    assert ow1["inputs"]["location"] == "output side"
    # the decision's q·η and motor-side torque are stated in its inputs too
    assert ow1["inputs"]["motor_side_torque_Nm"] == pytest.approx(at_motor, rel=1e-5)
    assert ow1["inputs"]["ratio_times_efficiency"] == pytest.approx(1000.0 / at_motor, rel=1e-5)
    assert "as the requirement asks (one_way.location)" in ow1["decision"]


def test_no_em_clutch_at_the_output_says_where_one_would_fit():
    doc = _doc(one_way={"location": "output_side", "type": "em_clutch"})
    with pytest.raises(InfeasibleError) as exc:
        advise(parse_requirements(doc))
    said = " ".join(exc.value.reasons)
    assert "1000 N·m at the output side" in said
    assert "one_way.location = 'motor_side'" in said
    # at the motor side (2.08 N·m) the same clutch exists
    advise(parse_requirements(_doc(one_way={"type": "em_clutch"})))


def test_the_speed_choice_weighs_the_reducer_adopted():
    """q_Σ = 3000/60 = 50: the rules split it in two stages (WG-02), whose design is too long
    for 30 mm, so the space's lightest that fits, a single stage, is adopted. BL-02 used to
    state the losses behind two stages (η = 0.81: 162.5 W) while the motor works behind one
    (η = 0.9: 142.55 W)."""
    doc = {
        "application": {"kind": "rotary"},
        "rotary": {"torque_Nm": 100.0, "speed_rpm": 60.0},
        "motor": {"kind": "bldc", "candidate_speeds_rpm": [3000.0]},
        "envelope": {"max_length_mm": 30.0},
    }
    rep = _report(doc)
    d = _decisions(rep)
    assert len(d["WG-02"]["inputs"]["ratios"]) == 2
    assert len(rep["design"]["gearbox"]["stages"]) == 1
    m = rep["design"]["motor"]
    assert m["torque_Nm"] == pytest.approx(100.0 / (50 * 0.9), rel=1e-5)  # 2.2222 N·m
    assert d["BL-02"]["inputs"]["total_loss_W"] == pytest.approx(m["losses_W"]["total"], rel=1e-5)


def test_a_rule_design_that_does_not_fit_is_said_once_and_the_lightest_taken():
    """The same 30 mm case: WG-06 (not WG-04, which would call the lightest "the rule
    design") says the rule design does not fit; the Compare view marks the lightest."""
    from advisor.applications.rotary.views import compare

    doc = {
        "application": {"kind": "rotary"},
        "rotary": {"torque_Nm": 100.0, "speed_rpm": 60.0},
        "motor": {"kind": "bldc", "candidate_speeds_rpm": [3000.0]},
        "envelope": {"max_length_mm": 30.0},
    }
    report = advise(parse_requirements(doc))
    rep = tomllib.loads(to_toml(report))
    d = _decisions(rep)
    assert "WG-04" not in d
    wg6 = d["WG-06"]["inputs"]
    assert (wg6["taken"], wg6["asked"], wg6["rule_fits"]) == ("lightest", "rules", False)
    assert wg6["rule_length_mm"] > 30.0 >= rep["design"]["gearbox"]["length_mm"]
    assert "because the rule design cannot be used" in d["WG-06"]["decision"]
    assert "does not fit the envelope" in d["WG-06"]["decision"]
    reducer = next(s for s in compare(report) if s.title.startswith("Reducer"))
    assert [o.label for o in reducer.options] == ["Use the slimmest"]  # the rest change nothing


def test_the_slimmest_is_the_lightest_of_the_equally_slim():
    """The output stage alone sets the outer diameter, so many splits share the least one:
    of those the lightest is taken (it was 7.280 kg where 7.128 kg had the same Ø)."""
    import numpy as np

    from advisor.calc import reducer, wavegear

    rep = _report(_doc())
    slim = rep["design"]["gearbox"]["optimum_min_diameter"]
    params = reducer.ReducerParams(
        torque_Nm=1000.0,
        k_rb=wavegear.ROLLING_BODY_FACTOR["ball"],
        stage_efficiency=0.8944,
        density_kg_m3=7800.0,
        fill_factor=0.75,
    )
    space = reducer.sweep(600.0, params)
    d_min = space.outer_diameter_mm.min()
    lightest_of_slim = space.mass_kg[space.outer_diameter_mm == d_min].min()
    assert slim["outer_diameter_mm"] == pytest.approx(d_min, rel=1e-6)
    assert slim["mass_kg"] <= lightest_of_slim * (1 + 1e-6)
    assert slim["mass_kg"] < 7.2  # not the 7.280 kg one
    assert np.count_nonzero(space.outer_diameter_mm == d_min) > 1  # a real tie


def test_the_loss_optimum_uses_the_efficiency_adopted_near_it():
    """An 80 mm envelope: the space's reducer at the reference 5000 rpm has three stages
    (η = 0.8944³ = 0.7155), near the optimum two (η = 0.8). Eq. (10) with the three-stage η
    put the optimum at 3390 rpm; with the two-stage one, by hand: T = 1000/(1000·0.8) =
    1.25 N·m at 5000 rpm, P_om = P_om,3 · (0.7155/0.8)² and f* = f·(P_om/P_core)^¼ ≈ 320.6 Hz,
    3206 rpm at two pole pairs... the speed the losses of the candidates also put first."""
    doc = _doc(
        envelope={"max_outer_diameter_mm": 80.0},
        motor={"candidate_speeds_rpm": [3000.0, 3206.0, 3390.0, 4000.0, 5000.0]},
    )
    rep = _report(doc)
    m = rep["design"]["motor"]
    losses = {c["speed_rpm"]: c["losses_W"]["total"] for c in m["candidates"]}
    assert min(losses, key=losses.get) == m["speed_rpm"] == 3206.0
    assert m["optimum_speed_rpm"] == pytest.approx(3206, abs=1.0)
    stages = {c["speed_rpm"]: c["stages"] for c in m["candidates"]}
    assert stages[3206.0] == len(rep["design"]["gearbox"]["stages"]) == 2
    assert stages[5000.0] == 3  # the count adopted there, not the rules' two


def test_the_device_types_that_cannot_carry_the_torque_are_named():
    rep = _report(_doc(one_way={"location": "output_side"}))
    ow2 = _decisions(rep)["OW-02"]
    assert "No electromagnetic clutch of the seed's range carries this torque." in ow2["rationale"]
    assert all(a["type"] != "em_clutch" for a in rep["design"]["one_way"]["alternatives"])


def test_a_taken_reducer_that_overloads_the_motor_says_what_else_to_take():
    rudder = Path(__file__).parents[2] / "examples" / "rudder_actuator.toml"
    doc = tomllib.loads(rudder.read_text(encoding="utf-8"))
    doc.setdefault("gearbox", {})["choice"] = "slimmest"
    with pytest.raises(InfeasibleError) as exc:
        advise(parse_requirements(doc))
    assert "gearbox.choice = 'slimmest' takes a reducer of η" in exc.value.reasons[-1]
    assert "'rules' or 'lightest'" in exc.value.reasons[-1]
    assert "gearbox.choice" in str(exc.value)


def test_wg06_makes_the_choice_it_states():
    """WG-06 is handed the candidates, not the reducer already taken: it fires where the rule
    design does not stand and returns the reducer of the space it takes."""
    from advisor.calc import reducer
    from rules import wavegear as wavegear_rules

    params = reducer.ReducerParams(1000.0, 1.0, 0.8944, 7800.0, 0.75)
    rule_design = reducer.evaluate([20.0, 30.0], [3, 2], params)
    space = reducer.sweep(600.0, params)
    lightest = reducer.evaluate(*_config(space, reducer.best(space, "mass")), params)
    slimmest = reducer.evaluate(*_config(space, reducer.best(space, "diameter")), params)
    roomy = rule_design.outer_diameter_mm * 2
    assert wavegear_rules.space_choice("rules", rule_design, roomy, None) is None
    assert wavegear_rules.space_choice("rules", None, roomy, None) == "lightest"
    tight = rule_design.outer_diameter_mm * 0.99
    for asked, rule_d, d_max, want in (
        ("rules", rule_design, tight, lightest),
        ("slimmest", rule_design, roomy, slimmest),
        ("lightest", rule_design, roomy, lightest),
    ):
        options = wavegear_rules.ReducerOptions(asked, rule_d, lightest, slimmest, d_max, None)
        finding = wavegear_rules.taken_from_space(options)
        assert finding.value is want
        assert finding.inputs["taken"] == ("slimmest" if want is slimmest else "lightest")
        assert finding.inputs["rule_fits"] == (d_max == roomy)
    with pytest.raises(ValueError):
        wavegear_rules.taken_from_space(
            wavegear_rules.ReducerOptions("rules", rule_design, lightest, slimmest, roomy, None)
        )


def _config(space, i: int) -> tuple[list[float], list[int]]:
    ratios = space.ratios_out_to_in(i)
    return ratios, [int(space.rows_out[i])] + [2] * (len(ratios) - 1)
