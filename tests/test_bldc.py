"""Seed 000's motor loss model and pole/slot sets."""

import math

import pytest

from advisor.calc import bldc


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
