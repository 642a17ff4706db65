"""Seed 000's motor loss model and pole/slot sets."""

import math

import pytest

from advisor.calc import bldc
from advisor.core.errors import InfeasibleError


def test_pole_slot_relation_eq1():
    # 2p = z/(m·k)·(k·m ± 1): 9 teeth, k = 3 → 2p = 1·(9 ± 1) = 10 or 8
    combos = {(c.slots, c.poles) for c in bldc.pole_slot_combinations(3, 36)}
    assert {(9, 8), (9, 10), (12, 10), (12, 14), (12, 8), (18, 16), (18, 20)} <= combos
    # every set satisfies eq. (1)
    for c in bldc.pole_slot_combinations(3, 36):
        groups = c.slots // (3 * c.teeth_per_group)
        assert c.poles in (
            groups * (3 * c.teeth_per_group + 1),
            groups * (3 * c.teeth_per_group - 1),
        )
    # the seed motor's p = 6 (12 magnets) comes from 9 or 18 teeth
    assert {
        (c.slots, c.teeth_per_group)
        for c in bldc.pole_slot_combinations(3, 36)
        if c.pole_pairs == 6
    } == {(9, 1), (18, 1)}


@pytest.mark.parametrize(
    ("z", "p", "k", "kw"),
    # published fundamental winding factors of tooth-coil windings
    [(12, 5, 2, 0.933), (9, 4, 3, 0.945), (12, 4, 1, 0.866), (18, 8, 3, 0.945), (24, 11, 4, 0.949)],
)
def test_winding_factors(z, p, k, kw):
    assert bldc.winding_factor(z, p, k) == pytest.approx(kw, abs=5e-4)


def test_seed_000_worked_example_at_5000_rpm():
    # stator steel: 7.8 g/cm³ × 12 cm² × 5 cm × 0.85 = 0.3978 kg ≈ 0.4 kg
    m = bldc.stator_steel_mass(1200, 50, 0.85, 7800)
    assert m == pytest.approx(0.3978)
    # 5000 rpm, p = 6 → 500 Hz; 2.5 W/kg × (500/50)² = 250 W/kg → ≈ 100 W
    f = bldc.flux_frequency_Hz(5000, 6)
    assert f == 500
    iron = m * bldc.iron_specific_loss_quadratic(2.5, f)
    assert iron == pytest.approx(100, rel=0.01)
    # ohmic: 2 · 1.14 · 5.5² = 68.97 ≈ 70 W
    ohmic = 2 * 1.14 * 5.5**2
    assert ohmic == pytest.approx(70, rel=0.02)
    magnets = bldc.magnet_loss([(5000, 60), (10000, 100)], 5000)
    assert magnets == 60
    assert iron + magnets + ohmic == pytest.approx(230, rel=0.01)


def test_seed_000_worked_example_at_10000_rpm():
    m = bldc.stator_steel_mass(1200, 50, 0.85, 7800)
    iron = m * bldc.iron_specific_loss_quadratic(2.5, bldc.flux_frequency_Hz(10000, 6))
    assert iron == pytest.approx(400, rel=0.01)  # 4 × 100 W
    ohmic = bldc.ohmic_loss(2 * 1.14 * 5.5**2, 5000, 10000)  # two parallels: R/4
    assert ohmic == pytest.approx(18, abs=1)
    magnets = bldc.magnet_loss([(5000, 60), (10000, 100)], 10000)
    assert iron + magnets + ohmic == pytest.approx(518, rel=0.01)


def test_the_seeds_magnet_values_do_not_follow_its_f2_law():
    # 60 W → 100 W for twice the speed is n^0.74, not n²: the f² law would give 240 W
    assert math.log(100 / 60) / math.log(2) == pytest.approx(0.737, abs=1e-3)
    assert bldc.magnet_loss([(5000, 60)], 10000) == 240
    # between given points the interpolation follows the same power law
    assert bldc.magnet_loss([(5000, 60), (10000, 100)], 7071.07) == pytest.approx(
        math.sqrt(60 * 100), rel=1e-4
    )


def test_optimum_frequency_balances_ohmic_and_core_losses():
    ohmic, core, f = 68.97, 160.0, 500.0
    f_opt = bldc.optimum_frequency_Hz(ohmic, core, f)
    k_om, k_mag = ohmic * f**2, core / f**2
    # at f* the two parts are equal (seed 000, after eq. (10))
    assert k_om / f_opt**2 == pytest.approx(k_mag * f_opt**2)
    # and it is the minimum of P(f) = K_mag·f² + K_om/f²
    total = lambda x: k_mag * x**2 + k_om / x**2  # noqa: E731
    assert total(f_opt) < total(f_opt * 0.99) and total(f_opt) < total(f_opt * 1.01)
    assert f_opt == pytest.approx(405.1, abs=0.1)


def test_eq5_fit_reproduces_the_catalog_points():
    t = bldc.fit_eq5(1.0, 2.5, 17.0)
    assert t.specific_loss(50, 1.0) == pytest.approx(1.0)
    assert t.specific_loss(50, 1.5) == pytest.approx(2.5)
    assert t.specific_loss(400, 1.0) == pytest.approx(17.0)
    # the three-term law grows slower than the seed's f²: at 500 Hz, 1.5 T it is ≈ 65 W/kg
    assert t.specific_loss(500, 1.5) < bldc.iron_specific_loss_quadratic(2.5, 500) / 3


def test_magnet_loss_of_zero_watts_is_valid():
    # issue 13: log(0) crashed the power-law interpolation. Between 0 W at 5000 rpm and 100 W
    # at 10000 rpm the loss is linear: 7500 rpm → 50 W; below and beyond a zero it stays 0
    assert bldc.magnet_loss([(5000, 0.0), (10000, 100.0)], 7500) == pytest.approx(50.0)
    assert bldc.magnet_loss([(5000, 0.0), (10000, 100.0)], 4000) == 0.0
    assert bldc.magnet_loss([(5000, 60.0), (10000, 0.0)], 7500) == pytest.approx(30.0)
    assert bldc.magnet_loss([(5000, 60.0), (10000, 0.0)], 12000) == 0.0
    assert bldc.magnet_loss([(5000, 0.0)], 10000) == 0.0


# ---- the frame's limit is thermal (issue 12, item 2) ------------------------------------
# The seed 000 reference motor at its own rated point (5000 rpm, 2.0 N·m at 5.5 A):
# ohmic 2 · 1.14 · 5.5² = 68.97 W; iron 0.3978 kg × 2.5 · (500/50)² W/kg = 99.45 W;
# magnets 60 W (the seed's FEM value): 228.42 W, what the frame's cooling carries.
REFERENCE_LOSSES_W = 68.97 + 0.3978 * 250 + 60.0


def test_copper_loss_at_a_torque_does_not_depend_on_the_winding():
    # seed 000's 10000 rpm motor: two parallels (R/4 = 0.285 Ω) at the same 5.5 A give
    # 1.0 N·m: 2 · 0.285 · 5.5² = 17.2425 W, and the same frame at 1.0 N·m with the
    # 5000 rpm winding (R = 1.14 Ω, 2.75 A) loses 2 · 1.14 · 2.75² = 17.2425 W
    assert bldc.ohmic_loss_at_torque(68.97, 2.0, 1.0) == pytest.approx(17.2425)
    assert 2 * 1.14 * 2.75**2 == pytest.approx(17.2425)
    # eq. (4) at the reducer's torque (∝ 1/n) is the same number
    assert bldc.ohmic_loss(68.97, 5000, 10000) == pytest.approx(17.2425)
    # the current of the rewound winding: 5.5 A · (M/2 N·m) · (n/5000 rpm)
    assert bldc.rewound_current_A(5.5, 2.0, 5000, 1.0, 10000) == pytest.approx(5.5)
    assert bldc.rewound_current_A(5.5, 2.0, 5000, 20 / 3, 1500) == pytest.approx(5.5)
    assert bldc.rewound_current_A(5.5, 2.0, 5000, 1700 / 729, 4500) == pytest.approx(5.771605)


def _rotary(torque_Nm: float, speeds: list[float], **motor) -> dict:
    return {
        "application": {"kind": "rotary"},
        "rotary": {"torque_Nm": torque_Nm, "speed_rpm": 5},
        "motor": {"kind": "bldc", "candidate_speeds_rpm": speeds, **motor},
    }


def _advise(data: dict):
    from advisor.core.engine import advise
    from advisor.core.reading import parse_requirements

    return advise(parse_requirements(data))


def test_1500_rpm_at_the_reference_current_is_refused_for_its_losses():
    # 1620 N·m at 5 rpm from 1500 rpm: q = 300 in two stages (η = 0.81), so the motor gives
    # 1620/(300 · 0.81) = 6.6667 N·m — at the reference current 5.5 A · (6.6667/2) · 0.3,
    # which is why a current limit let it pass. Its losses:
    #   ohmic   68.97 W · (6.6667/2)² = 766.33 W
    #   iron    0.3978 kg × 2.5 · (150/50)² W/kg = 8.9505 W   (150 Hz)
    #   magnets 60 W · (1500/5000)² = 5.4 W                   (below the data: n²)
    #   total   780.68 W against the frame's 228.42 W
    total = 68.97 * (20 / 3 / 2) ** 2 + 0.3978 * 2.5 * 9 + 60 * 0.3**2
    assert total == pytest.approx(780.68, abs=0.01)
    with pytest.raises(InfeasibleError) as e:
        _advise(_rotary(1620, [1500]))
    text = str(e.value) + " ".join(e.value.reasons)
    assert "780.7 W" in text and "228.4 W" in text
    assert "1500 rpm" in text


def test_a_current_above_the_reference_is_not_a_limit():
    # 1700 N·m at 5 rpm from 4500 rpm: q = 900, two stages (η = 0.81), motor torque
    # 1700/729 = 2.331962 N·m, current 5.5 · 1.165981 · 0.9 = 5.771605 A (above 5.5 A).
    #   ohmic   68.97 W · 1.165981² = 93.7656 W
    #   iron    0.3978 kg × 2.5 · 9² W/kg = 80.5545 W         (450 Hz)
    #   magnets 60 W · 0.9² = 48.6 W
    #   total   222.920 W ≤ 228.42 W: the frame carries it
    rep = _advise(_rotary(1700, [4500]))
    m = rep.design.motor
    assert m.speed_rpm == 4500
    assert m.torque_Nm == pytest.approx(1700 / 729, rel=1e-6)
    assert m.current_A == pytest.approx(5.771605, rel=1e-6)
    assert m.losses_W.ohmic == pytest.approx(93.7656, rel=1e-5)
    assert m.losses_W.iron == pytest.approx(80.5545, rel=1e-5)
    assert m.losses_W.magnets == pytest.approx(48.6, rel=1e-9)
    assert m.losses_W.total == pytest.approx(222.920, rel=1e-5)
    assert m.loss_limit_W == pytest.approx(REFERENCE_LOSSES_W, rel=1e-9)
    check = next(c for c in rep.checks if c.id == "motor_losses")
    # the check applies the frame's 228.42 W with the stated 0.1 % allowance (rules/bldc.py)
    assert (check.value, check.limit, check.unit) == pytest.approx(
        (222.920, 228.42 * 1.001, "W"), rel=1e-5
    )
    assert check.passed and check.margin == pytest.approx(228.42 * 1.001 / 222.920, rel=1e-5)
    assert "228.42 W + 0.1% allowance" in check.name
    assert not any(c.unit == "A" for c in rep.checks)  # the current is no check
    speed = next(d for d in rep.decisions if d.id == "BL-02")
    assert "5.77 A" in speed.rationale and "not a limit" in speed.rationale


def test_10000_rpm_is_judged_by_its_losses_not_its_current():
    # 1620 N·m at 5 rpm from 10000 rpm: q = 2000, three stages (η = 0.729), motor torque
    # 1620/1458 = 1.111111 N·m at 5.5 · 0.555556 · 2 = 6.111111 A.
    #   ohmic   68.97 W · 0.555556² = 21.2870 W
    #   iron    0.3978 kg × 2.5 · 20² W/kg = 397.8 W          (1000 Hz)
    #   magnets 100 W (the seed's FEM value)
    #   total   519.087 W: over the frame's 228.42 W ...
    with pytest.raises(InfeasibleError) as e:
        _advise(_rotary(1620, [10000]))
    text = str(e.value) + " ".join(e.value.reasons)
    assert "519.1 W" in text and "228.4 W" in text
    # ... but within a cooling the requirement states as carrying 600 W
    rep = _advise(_rotary(1620, [10000], max_losses_W=600))
    m = rep.design.motor
    assert m.speed_rpm == 10000
    assert m.current_A == pytest.approx(6.111111, rel=1e-6)
    assert m.losses_W.ohmic == pytest.approx(21.2870, rel=1e-5)
    assert m.losses_W.total == pytest.approx(519.087, rel=1e-5)
    assert m.loss_limit_W == 600
    check = next(c for c in rep.checks if c.id == "motor_losses")
    assert check.limit == pytest.approx(600.6) and check.margin == pytest.approx(
        600.6 / 519.087, rel=1e-5
    )
    assert "motor.max_losses_W" in check.source


def test_a_stated_loss_limit_can_refuse_the_reference_point():
    # the rudder actuator at 5000 rpm loses 228.42 W: a cooling for 200 W cannot carry it
    with pytest.raises(InfeasibleError) as e:
        _advise(_rotary(1620, [5000, 10000], max_losses_W=200))
    text = str(e.value) + " ".join(e.value.reasons)
    assert "228.4 W" in text and "519.1 W" in text and "200 W" in text


def test_zero_magnet_loss_runs_end_to_end():
    # issue 13: loss_W = 0 at either point crashed with exit 1. With 0 W at 5000 rpm the
    # rudder motor loses 68.97 + 99.45 + 0 = 168.42 W, which is also its frame's limit.
    ref = {"magnet_losses": [{"speed_rpm": 5000, "loss_W": 0}, {"speed_rpm": 10000, "loss_W": 100}]}
    rep = _advise(_rotary(1620, [5000, 10000], reference=ref))
    assert rep.design.motor.losses_W.magnets == 0
    assert rep.design.motor.losses_W.total == pytest.approx(168.42, rel=1e-4)
    ref = {"magnet_losses": [{"speed_rpm": 5000, "loss_W": 60}, {"speed_rpm": 10000, "loss_W": 0}]}
    rep = _advise(_rotary(1620, [5000, 10000], reference=ref))
    by_speed = {c.speed_rpm: c.losses_W.magnets for c in rep.design.motor.candidates}
    assert by_speed == {5000: 60, 10000: 0}


def test_magnet_loss_points_at_one_speed_are_refused():
    from advisor.core.errors import InputError

    ref = {"magnet_losses": [{"speed_rpm": 5000, "loss_W": 60}, {"speed_rpm": 5000, "loss_W": 80}]}
    with pytest.raises(InputError, match="magnet_losses"):
        _advise(_rotary(1620, [5000], reference=ref))


def test_too_lossy_message_stays_short():
    # five candidates, all over the limit at four times the rudder torque: the three least
    # lossy are shown, the rest counted (issue 13: at most six lines)
    with pytest.raises(InfeasibleError) as e:
        _advise(_rotary(4 * 1620, [3000, 4000, 5000, 7000, 10000]))
    lines = str(e.value).splitlines()
    assert len(lines) == 6 and all(len(x) <= 300 for x in lines)
    assert "and 2 more candidate speeds" in lines[4]


@pytest.mark.parametrize("rel", [-1e-9, 1e-9, 1e-6, 5e-4])
def test_the_reference_point_is_no_knife_edge(rel):
    """The rudder runs the seed's frame exactly at its reference point: 1620 N·m through
    q = 1000 at η = 0.9² is 1620 / 810 = 2.0 N·m, the reference torque, so its losses equal
    the limit (228.42 W). A requirement perturbed by up to the stated 0.1 % allowance
    (rules/bldc.py LIMIT_REL_TOL) keeps the same design: 5000 rpm, total losses ∝ M² for the
    ohmic part, within 2·rel of the limit."""
    report = _advise(_rotary(1620 * (1 + rel), [5000, 10000]))
    assert report.design.motor.speed_rpm == 5000
    assert report.design.motor.losses_W.total == pytest.approx(
        228.42 * (1 + 2 * rel * 68.97 / 228.42), rel=1e-4
    )
