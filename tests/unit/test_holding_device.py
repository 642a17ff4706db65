"""The holding device (seed 004) in the linear and rotary drives: the load's inertia through
a device whose efficiency is below 1, the check that it holds the load with the power off,
and the words the report says about it. Every expected number is a hand calculation written
beside it."""

import fnmatch
import math

import pytest
from helpers import seed001_requirement

from advisor.applications.linear import duty as linear_duty
from advisor.calc import one_way as ow
from advisor.core.engine import advise
from advisor.core.errors import InfeasibleError
from advisor.core.reading import parse_requirements


def _linear_worm(moving_mass_kg: float = 2000.0, **one_way) -> dict:
    """Tr14x4(P2) (2 starts, f = 0.05: not self-locking at the low end), held by a worm at the
    motor side, in a cycle of a move up, a hold, a move down and a dwell."""
    return {
        "application": {"kind": "linear", "hold_without_power": True, "title": "lin worm"},
        "linear": {"force_N": 3500, "stroke_m": 0.2, "travel_time_s": 5, "support_span_m": 0.4},
        "motor": {"kind": "induction"},
        "screw": {"friction_coefficient": 0.05, "starts": 2},
        "one_way": {"type": "worm", **one_way},
        "duty": {
            "cycles_per_hour": 20,
            "moving_mass_kg": moving_mass_kg,
            "segments": [
                {"kind": "move", "distance_m": 0.2, "time_s": 8, "direction": "against"},
                {"kind": "hold", "time_s": 60},
                {"kind": "move", "distance_m": 0.2, "time_s": 8, "direction": "with"},
                {"kind": "dwell", "time_s": 60},
            ],
        },
    }


def test_linear_start_accelerates_the_screw_side_through_the_worm():
    # The motor accelerates the screw and the nut's mass THROUGH the worm, whose mesh
    # friction acts on the inertia's torque as on the load's (the rotary cycle's
    # J_L/(q²·η·η_d)). By hand, Tr14x4(P2): d2 = 13 mm, L = 4 mm, η_screw = 0.651:
    #   J_L = 7850·π·0.013⁴/32·0.4 + 2000·(0.004/2π)²/η_screw = 0.0012541 kg·m²
    #   4A80B6: J_M = 0.0046; worm (seed 004, sized for 3.42315 N·m): J_d = 7.53649e-5,
    #   η_d = 0.33112; J_Σ = J_M + J_d + J_L/η_d = 0.0046754 + 0.0037874 = 0.0084628
    #   ω = 929.902 rpm = 97.379 rad/s; M_m = 22.8629 N·m; M_L = 3.42315/0.33112 = 10.3381
    #   t_start = J_Σ·ω/(M_m − M_L) = 0.0084628·97.379/12.5248 = 0.06580 s (0.04610 s
    #   without the /η_d); FI = J_Σ/J_M = 0.0084628/0.0046 = 1.840 (1.289 without)
    rep = advise(parse_requirements(_linear_worm()))
    duty = rep.design.duty
    assert duty.motor == "4A80B6"
    start = next(p for p in duty.phases if p.name == "1 move: start")
    assert start.time_s == pytest.approx(0.06580, rel=2e-4)
    assert duty.inertia_factor == pytest.approx(1.840, rel=1e-3)
    # the inertia ratio stays the rotary's J_L/(J_M + J_d), without η_d
    assert duty.inertia_ratio == pytest.approx(0.0012541 / 0.0046754, rel=1e-3)


def test_ramps_of_a_load_lowered_through_a_self_locking_device():
    # M_m = 20 N·m, J_R = 0.005, J_L = 0.001 kg·m² at the motor shaft.
    worm = ow.passage("worm")  # η_d = 0.33112, lowering factor k = 1
    j = 0.005 + 0.001 / worm.efficiency
    # a load of 10 N·m lowered: the worm asks k·|M_s| = 10; J = J_R − k·J_L = 0.004;
    # ε = (20 − 10)/0.004 = 2500 rad/s², J_L·ε = 2.5 ≤ 10 (the load's torque outweighs its
    # inertia's); the coast: the rotor drives the load down, ε = 10/0.004 = 2500
    e1, e2 = linear_duty.ramp_accelerations(20.0, 10.0, -10.0, (0.005, 0.001), worm, j)
    assert (e1, e2) == pytest.approx((2500.0, 2500.0))
    # a load of 3 N·m: the back branch gives (20 − 3)/0.004 = 4250, J_L·ε = 4.25 > 3: the
    # motor drives the load's inertia through the worm: ε = (20 + 3/0.33112)/(0.005 +
    # 0.001/0.33112) = 29.0601/0.0080201 = 3623.4
    e1, _ = linear_duty.ramp_accelerations(20.0, 3.0, -3.0, (0.005, 0.001), worm, j)
    assert e1 == pytest.approx((20 + 3 / worm.efficiency) / j) == pytest.approx(3623.4, rel=1e-4)
    # the roller clutch (k = 0, η_d = 1) lowering 10 N·m: the motor accelerates its rotor
    # alone, ε = 20/0.005 = 4000 (J_L·ε = 4 ≤ 10), and the coast stops at once (∞)
    roller = ow.passage("roller_clutch")
    e1, e2 = linear_duty.ramp_accelerations(20.0, 0.0, -10.0, (0.005, 0.001), roller, 0.006)
    assert e1 == pytest.approx(4000.0) and e2 == math.inf
    # driving the load (M_s ≥ 0) through the worm: (M_m − M_s/η_d)/(J_R + J_L/η_d)
    e1, e2 = linear_duty.ramp_accelerations(
        20.0, 3.0 / worm.efficiency, 3.0, (0.005, 0.001), worm, j
    )
    assert e1 == pytest.approx((20 - 3 / 0.33112) / (0.005 + 0.001 / 0.33112), rel=1e-4)
    assert e2 == pytest.approx(3 / 0.33112 / (0.005 + 0.001 / 0.33112), rel=1e-4)


def _check(rep, cid: str):
    return next(c for c in rep.checks if c.id == cid)


def _linear_device(kind: str) -> dict:
    data = _linear_worm(type=kind)
    del data["duty"]
    return data


def test_linear_device_holds_the_back_driving_torque():
    # Tr14x4(P2): d2 = 13 mm, lead 4 mm, ψ = atan(4/(π·13)) = 5.5939°; the low end of the
    # friction range f = 0.05: φ' = atan(0.05/cos 15°) = 2.9632° (standard reduced friction).
    # The load gives the device F·d2/2·tan(ψ − φ') = 3500·0.0065·tan(2.6307°) = 1.04524 N·m;
    # the device is sized for the screw torque F·d2/2·tan(ψ + φ') = 3500·0.0065·tan(8.5571°)
    # = 3.42315 N·m (f_B = 1): margin 3.42315/1.04524 = 3.275
    for kind in ("roller_clutch", "worm", "em_clutch", "inverse_gear"):
        rep = advise(parse_requirements(_linear_device(kind)))
        c = _check(rep, "one_way_holds_load")
        assert (c.value, c.limit) == pytest.approx((1.04524, 3.42315), rel=1e-5), kind
        assert c.margin == pytest.approx(3.2750, rel=1e-4)
        assert "with the power off" in c.name
    # the worm's self-locking: γ = 0.5·φ, φ = atan 0.1 = 5.711°, γ = 2.856°: γ/φ = 0.5, φ/γ = 2
    worm = _check(advise(parse_requirements(_linear_device("worm"))), "one_way_self_locking")
    assert (worm.value, worm.limit, worm.margin) == pytest.approx((0.5, 1.0, 2.0))
    # the braking-profile gear: η = γ/(γ + φ) = 0.45 ⇒ γ/φ = 0.45/0.55 = 0.81818, margin 1.2222
    gear = _check(
        advise(parse_requirements(_linear_device("inverse_gear"))), "one_way_self_locking"
    )
    assert (gear.value, gear.margin) == pytest.approx((0.81818, 1.22222), rel=1e-5)
    roller = advise(parse_requirements(_linear_device("roller_clutch")))
    assert not any(c.id == "one_way_self_locking" for c in roller.checks)  # holds by wedging


def test_self_locking_screw_states_its_own_margin():
    # seed 001's Tr14x2, f = 0.15 (range 0.10 … 0.16): ψ = atan(2/(π·13)) = 2.8036°,
    # φ' = atan(0.10/cos 15°) = 5.9108° at the low end: ψ/φ' = 0.47433, margin 2.1082
    data = seed001_requirement()
    data["application"]["hold_without_power"] = True
    rep = advise(parse_requirements(data))
    assert rep.design.one_way.type == "none"
    c = _check(rep, "screw_self_locking")
    assert (c.value, c.margin) == pytest.approx((0.47433, 2.1082), rel=1e-4)
    assert not any(c.id.startswith("one_way") for c in rep.checks)


def _rotary(kind: str, location: str = "motor_side") -> dict:
    return {
        "application": {"kind": "rotary", "hold_without_power": True, "title": "valve"},
        "rotary": {"torque_Nm": 1000, "speed_rpm": 5},
        "motor": {
            "kind": "bldc",
            "frame": "reference",
            "candidate_speeds_rpm": [3000],
            "max_losses_W": 1500,
        },
        "gearbox": {"stage_efficiency": 0.8944},
        "one_way": {"type": kind, "location": location},
    }


def test_rotary_device_holds_the_load_back_through_the_wave_gear():
    # q = 600, η = 0.8944² = 0.799951: the device at the motor side is sized for
    # M/(q·η) = 1000/(600·0.799951) = 2.08346 N·m; the standing load gives it, back through
    # the wave gear (its back-driven η taken equal to the forward one), M·η/q =
    # 1000·0.799951/600 = 1.33325 N·m: margin 1/η² = 1.56269
    for kind in ("roller_clutch", "em_clutch"):
        c = _check(advise(parse_requirements(_rotary(kind))), "one_way_holds_load")
        assert (c.value, c.limit, c.margin) == pytest.approx((1.33325, 2.08346, 1.56269), rel=1e-5)
    # a worm at the output holds exactly the torque it is sized for (a capacity check would
    # only say 1.000): its self-locking is checked, γ/φ = 0.5
    rep = advise(parse_requirements(_rotary("worm", "output_side")))
    assert not any(c.id == "one_way_holds_load" for c in rep.checks)
    assert _check(rep, "one_way_self_locking").margin == pytest.approx(2.0)


def test_datasheet_covers_hold_without_power():
    from advisor.core.registry import covers

    patterns = covers("linear")["application.hold_without_power"]
    for cid in ("one_way_holds_load", "one_way_self_locking", "screw_self_locking"):
        assert any(fnmatch.fnmatch(cid, p) for p in patterns), cid
    assert any(
        fnmatch.fnmatch("one_way_holds_load", p)
        for p in covers("rotary")["application.hold_without_power"]
    )


def test_ow02_states_the_seeds_inertia_claim_beside_the_sizes_here():
    # the valve (2.08346 N·m at the motor side): roller clutch, seed 004 eqs. (1)–(9),
    # J = 3.82948e-6 kg·m²; em clutch D = 80 mm, armature disc 0.06·D thick:
    # m = 7800·π·0.08²/4·0.0048 = 0.188195 kg, J = m·D²/8 = 1.50556e-4 kg·m²:
    # 1.50556e-4/3.82948e-6 = 39.3 times the roller clutch's
    rep = advise(parse_requirements(_rotary("auto") | {"one_way": {"priority": "inertia"}}))
    ow02 = next(d for d in rep.decisions if d.id == "OW-02")
    assert ow02.decision.startswith("roller irreversible clutch")
    assert "seed 004, fig. 8 and conclusion 5, finds its inertia the least" in ow02.rationale
    assert "its inertia is 39.3× the roller clutch's" in ow02.rationale


def test_em_clutch_holds_as_a_clutch_brake():
    rep = advise(parse_requirements(_rotary("em_clutch")))
    basis = rep.design.one_way.basis
    assert "clutch-brake" in basis and "no power in holds" in basis


def test_linear_warning_names_the_device_with_its_article():
    rep = advise(parse_requirements(_linear_device("em_clutch")))
    assert any(
        "an electromagnetic clutch at the motor side holds the load" in w for w in rep.warnings
    )
    rep = advise(parse_requirements(_linear_device("inverse_gear")))
    assert any("a gear with braking (inverse) profile at the motor side" in w for w in rep.warnings)


def test_unheld_screw_in_a_cycle_is_refused_for_its_real_cause():
    # Tr14x4(P2) at f = 0.05 is back-driven (ψ 5.59° > φ' 2.96°) and nothing holds it: no
    # motor size cures that, so the refusal names the cause and the remedies
    data = _linear_worm()
    data["application"]["hold_without_power"] = False
    del data["one_way"]
    with pytest.raises(InfeasibleError) as info:
        advise(parse_requirements(data))
    err = info.value
    assert "the load back-drives the screw" in str(err) and "nothing holds it" in str(err)
    text = " ".join(err.reasons)
    assert "hold_without_power = true" in text and "brake" in text
    assert "larger motors of the same pole count" not in text


def _four_starts_unheld(duty: dict) -> dict:
    """Seed 001's load (3500 N, 0.2 m in 3 s, span 0.4 m) on four starts at f = 0.06,
    nothing to hold it."""
    data = seed001_requirement(friction_coefficient=0.06, starts=4)
    data["linear"]["travel_time_s"] = 3
    data["duty"] = duty
    return data


@pytest.mark.parametrize(
    "duty",
    [
        {
            "cycles_per_hour": 20,
            "moving_mass_kg": 40,
            "segments": [
                {"kind": "move", "distance_m": 0.2, "time_s": 8, "direction": "against"},
                {"kind": "hold", "time_s": 60},
                {"kind": "move", "distance_m": 0.2, "time_s": 8, "direction": "with"},
                {"kind": "dwell", "time_s": 60},
            ],
        },
        {"duty_type": "S3", "cyclic_duration_factor": 0.4, "cycle_time_s": 600},
    ],
    ids=["segments", "S3"],
)
def test_the_unheld_refusal_names_the_multi_start_screw(duty):
    # Tr14x2 with 4 starts is Tr14x8(P2) (GOST 24739-81, lead 4 × 2 = 8 mm): d2 = 13 mm,
    # ψ = atan(8 / (π·13)) = 11.08° > φ' = atan(0.06 / cos 15°) = 3.55°, so it back-drives;
    # the one-start Tr14x2 (ψ = atan(2 / (π·13)) = 2.80° < 3.55°) would hold, so the
    # refusal must not name it
    with pytest.raises(InfeasibleError) as info:
        advise(parse_requirements(_four_starts_unheld(duty)))
    text = " ".join([str(info.value), *info.value.reasons])
    assert "back-drives the screw Tr14x8(P2) whenever the motor is off" in str(info.value)
    assert "the load of 3500 N back-drives the screw Tr14x8(P2) (not self-locking" in text
    assert "screw Tr14x2" not in text


def test_held_by_names_the_multi_start_screw():
    # Tr26x3 with 2 starts is Tr26x6(P3): lead 2 × 3 = 6 mm; it holds by itself here
    data = seed001_requirement(thread="Tr26x3", starts=2)
    data["application"]["hold_without_power"] = True
    data["linear"]["travel_time_s"] = 3
    data["duty"] = {
        "cycles_per_hour": 20,
        "moving_mass_kg": 40,
        "segments": [
            {"kind": "move", "distance_m": 0.2, "time_s": 8, "direction": "against"},
            {"kind": "hold", "time_s": 60},
            {"kind": "move", "distance_m": 0.2, "time_s": 8, "direction": "with"},
            {"kind": "dwell", "time_s": 60},
        ],
    }
    rep = advise(parse_requirements(data))
    held_by = rep.design.duty.held_by
    assert held_by == "the screw Tr26x6(P3), self-locking over its whole friction range"
