"""The holding device (seed 004) in the linear and rotary drives: the load's inertia through
a device whose efficiency is below 1, the check that it holds the load with the power off,
and the words the report says about it. Every expected number is a hand calculation written
beside it."""

import math

import pytest

from advisor.applications.linear import duty as linear_duty
from advisor.calc import one_way as ow
from advisor.core.engine import advise
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
