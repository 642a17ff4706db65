"""Induction motor characteristic: Kloss, refined Kloss fitted to the catalog, working point."""

import math

import pytest

from advisor.calc import induction as im
from catalogs import load_catalogs


def test_synchronous_speed_and_pole_pairs():
    # seed 001: 1200 rpm needs p = 2, synchronous 60·50/2 = 1500 rpm
    assert im.synchronous_speed_rpm(50, 2) == 1500
    assert im.synchronous_speed_rpm(50, 3) == 1000 < 1200


def test_simple_kloss_critical_slip_root_sign():
    # s_k = s_n(λ + √(λ²−1)): the larger root; the smaller one is below s_n
    sn, lam = 0.05, 2.2
    sk = im.kloss_simple_critical_slip(sn, lam)
    assert sk == pytest.approx(0.05 * (2.2 + math.sqrt(2.2**2 - 1)))
    assert sk > sn
    # on the simple curve M(s_n)/M_k = 1/λ
    m = 2 / (sn / sk + sk / sn)
    assert m == pytest.approx(1 / lam)


def test_simple_kloss_misses_the_catalog_starting_torque():
    # why the refined form is used (DOMAIN.md: the simple form gives M(1) ≈ M_n): for 4A80B4
    # (s_n = 1 − 1415/1500 = 0.05667, λ = 2.2) s_k = 0.05667·(2.2 + 1.9596) = 0.2357 and
    # M(1)/M_n = 2λ/(1/s_k + s_k) = 4.4/4.4784 = 0.983, where the catalog says 2.0
    sn, lam = 1 - 1415 / 1500, 2.2
    sk = im.kloss_simple_critical_slip(sn, lam)
    assert sk == pytest.approx(0.2357, abs=1e-4)
    start_simple = lam * 2 / (1 / sk + sk)
    assert start_simple == pytest.approx(0.983, abs=1e-3)


@pytest.mark.parametrize("motor", load_catalogs().motors, ids=lambda m: m.model)
def test_refined_kloss_passes_through_the_catalog_points(motor):
    mn = motor.rated_torque_Nm
    c = im.fit_kloss(
        mn, motor.rated_slip, motor.breakdown_torque_ratio, motor.starting_torque_ratio
    )
    assert c.torque(0.0) == 0.0
    assert c.torque(motor.rated_slip) == pytest.approx(mn, rel=1e-9)
    assert c.torque(1.0) == pytest.approx(motor.starting_torque_ratio * mn, rel=1e-9)
    assert c.torque(min(c.critical_slip, 1.0)) == pytest.approx(motor.breakdown_torque_ratio * mn)
    # the maximum of the curve is M_k: nowhere above it
    grid = [i / 2000 for i in range(1, 2001)]
    assert max(c.torque(s) for s in grid) <= motor.breakdown_torque_ratio * mn * (1 + 1e-9)


def test_equal_start_and_breakdown_torque_puts_the_maximum_at_standstill():
    # 4A71B4: Mst/Mn = Mmax/Mn = 2.0 in the source table
    c = im.fit_kloss(5.1525, 1 - 1390 / 1500, 2.0, 2.0)
    assert c.critical_slip == 1.0
    # ε = (s_n + 1/s_n − 2λ)/(2(λ−1)), by hand
    sn = 1 - 1390 / 1500
    assert c.epsilon == pytest.approx((sn + 1 / sn - 4.0) / 2.0)


def test_working_point_on_the_stable_branch():
    c = im.fit_kloss(10.0, 0.05, 2.2, 2.0)
    s = c.stable_slip(10.0)
    assert s == pytest.approx(0.05)
    assert c.stable_slip(5.0) < 0.05
    assert c.stable_slip(22.0) == pytest.approx(c.critical_slip)
    assert c.stable_slip(22.1) is None


def test_impossible_catalog_points_are_refused():
    with pytest.raises(ValueError, match="starting torque ratio"):
        im.fit_kloss(10.0, 0.05, 2.0, 2.5)
    with pytest.raises(ValueError, match="breakdown"):
        im.fit_kloss(10.0, 0.05, 0.9, 0.5)
