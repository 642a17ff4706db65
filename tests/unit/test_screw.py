"""Screw–nut calculations against seed 001 and hand calculations."""

import math

import pytest

from advisor.calc import screw as sc


def test_seed_001_kinematics():
    # Seed 001: v = 0.2/5 = 0.04 m/s; N = 0.2e3/2 = 100; n = 60·100/5 = 1200 rpm
    assert sc.linear_speed(0.2, 5) == pytest.approx(0.04)
    n_rev = sc.revolutions(0.2, 0.002)
    assert n_rev == pytest.approx(100)
    assert sc.screw_speed_rpm(n_rev, 5) == pytest.approx(1200)


def test_seed_001_torque_paper_formula():
    # Seed 001, eq. (1), Tr16x2, F = 3500 N, f = 0.15, one start: M = 5.085 N·m
    m = sc.thread_torque(3500, 0.015, 0.002, 0.15, "paper", 1)
    assert m == pytest.approx(5.085, abs=5e-4)


def test_standard_torque_by_hand():
    # tan ψ = 2/(π·15) = 0.0424413; tan φ' = 0.15/cos 15° = 0.1552914
    # tan(ψ+φ') = (0.0424413 + 0.1552914)/(1 − 0.0424413·0.1552914) = 0.1990446
    # M = 3500 · 0.0075 · 0.1990446 = 5.224921 N·m
    tan_psi = 2 / (math.pi * 15)
    tan_phi = 0.15 / math.cos(math.radians(15))
    by_hand = 3500 * 0.0075 * (tan_psi + tan_phi) / (1 - tan_psi * tan_phi)
    assert by_hand == pytest.approx(5.224921, abs=1e-6)
    assert sc.thread_torque(3500, 0.015, 0.002, 0.15, "standard") == pytest.approx(by_hand)


def test_standard_model_is_about_three_percent_above_the_paper():
    std = sc.thread_torque(3500, 0.015, 0.002, 0.15, "standard")
    paper = sc.thread_torque(3500, 0.015, 0.002, 0.15, "paper")
    assert std / paper == pytest.approx(1.0275, abs=1e-3)


def test_efficiency_and_self_locking_by_hand():
    psi = sc.lead_angle(0.002, 0.015)
    phi = sc.friction_angle(0.15, "paper", psi)
    # η = tan ψ / tan(ψ+φ) = 0.0424413 / 0.1937087 = 0.219099 (power check: 140 W / η = M·ω)
    assert sc.efficiency(psi, phi) == pytest.approx(0.219099, abs=1e-6)
    assert 3500 * 0.04 / sc.efficiency(psi, phi) == pytest.approx(
        5.08485 * 1200 * math.pi / 30, rel=1e-5
    )
    assert sc.is_self_locking(psi, phi)
    assert sc.back_driving_efficiency(psi, phi) < 0
    # a steep lead (Tr16x4 with 4 starts: lead 16 mm) is not self-locking at f = 0.1
    psi4 = sc.lead_angle(0.004, 0.014, starts=4)
    assert not sc.is_self_locking(psi4, sc.friction_angle(0.10, "standard", psi4))


def test_core_stress_by_hand():
    # σ = 4·3500/(π·13.5²) = 24.452 MPa; τ = 16·5.085/(π·0.0135³) = 10.526 MPa;
    # σ_eq = √(24.452² + 3·10.526²) = 30.50 MPa
    sigma = 4 * 3500 / (math.pi * 13.5**2)
    tau = 16 * 5085 / (math.pi * 13.5**3)
    expected = math.sqrt(sigma**2 + 3 * tau**2) * 1e6
    assert sc.core_equivalent_stress(3500, 5.085, 0.0135) == pytest.approx(expected)
    assert expected / 1e6 == pytest.approx(30.50, abs=0.01)


def test_buckling_euler_by_hand():
    # Tr16x2 core, pinned ends, L = 0.4 m, E = 210 GPa: P = π²EI/L², I = π·13.5⁴/64 mm⁴
    inertia = math.pi * 13.5**4 / 64 * 1e-12
    expected = math.pi**2 * 210e9 * inertia / 0.4**2
    p, lam, how = sc.critical_buckling_load(0.0135, 0.4, "pinned-pinned", 210e9, 355e6)
    assert how == "Euler" and p == pytest.approx(expected)
    assert lam == pytest.approx(0.4 / (0.0135 / 4))
    # fixed-fixed halves the effective length: four times the load (still Euler? λ = 59 < 108: no)
    _p2, lam2, how2 = sc.critical_buckling_load(0.0135, 0.4, "fixed-fixed", 210e9, 355e6)
    assert how2 == "Johnson" and lam2 == pytest.approx(lam / 2)


def test_buckling_johnson_by_hand():
    # d3 = 13.5 mm, fixed-fixed over 0.4 m: λ = 0.5·400/3.375 = 59.26 < λc = 108.06
    # σcr = σy − (σy·λ/2π)²/E = 355 − (355·59.26/6.2832)²/210000 = 355 − 53.39 = 301.61 MPa
    lam = 0.5 * 400 / 3.375
    sigma_cr = 355 - (355 * lam / (2 * math.pi)) ** 2 / 210000
    assert sigma_cr == pytest.approx(301.61, abs=0.01)
    area = math.pi * 13.5**2 / 4
    p, _, how = sc.critical_buckling_load(0.0135, 0.4, "fixed-fixed", 210e9, 355e6)
    assert how == "Johnson"
    assert p == pytest.approx(area * sigma_cr, rel=1e-9)


def test_euler_and_johnson_meet_at_the_transition():
    e, sy = 210e9, 355e6
    lam_c = math.pi * math.sqrt(2 * e / sy)
    d3 = 0.02
    span_at = lam_c * d3 / 4  # pinned-pinned
    p_hi, _, a = sc.critical_buckling_load(d3, span_at * 1.000001, "pinned-pinned", e, sy)
    p_lo, _, b = sc.critical_buckling_load(d3, span_at * 0.999999, "pinned-pinned", e, sy)
    assert (a, b) == ("Euler", "Johnson")
    assert p_hi == pytest.approx(p_lo, rel=1e-5)


def test_nut_by_hand():
    # z = F/(π·d2·H1·[p]) = 3500/(π·15·1·10) = 7.427 turns
    assert sc.nut_turns_required(3500, 0.015, 0.001, 10e6) == pytest.approx(3500 / (math.pi * 150))
    assert sc.nut_bearing_pressure(3500, 0.015, 0.001, 9) == pytest.approx(
        3500 / (math.pi * 15 * 9) * 1e6
    )
