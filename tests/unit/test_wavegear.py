"""Wave gear stages with rolling bodies: seed 000 eqs. (12)–(19) and its heuristics."""

import math

import numpy as np
import pytest

from advisor.calc import reducer, wavegear
from rules.wavegear import split_ratio


def test_stage_geometry_by_hand():
    # M = 1000 N·m, q = 20, three rows of balls:
    # d = ∛(241·1000/(3·19)·sin(π/19)) = 8.862 mm; a = 2.06/sin(π/20) = 13.169
    d = float(wavegear.rolling_body_diameter(1000, 20, 3))
    assert d == pytest.approx((241000 / 57 * math.sin(math.pi / 19)) ** (1 / 3))
    a = 2.06 / math.sin(math.pi / 20)
    assert float(wavegear.outer_diameter(20, d)) == pytest.approx((a + 1.8) * d)
    assert float(wavegear.inner_diameter(20, d)) == pytest.approx((a - 4.4) * d)
    assert float(wavegear.stage_length(3, d)) == pytest.approx(5.4 * d)


def test_eq18_is_eq12_with_13_to_16():
    for q in (8, 12, 20, 35):
        for n in (2, 3, 6):
            d = wavegear.rolling_body_diameter(500.0, q, n, 2.0)
            w = wavegear.hollow_cylinder_volume(
                wavegear.outer_diameter(q, d),
                wavegear.inner_diameter(q, d),
                wavegear.stage_length(n, d),
            )
            assert float(w) / 500.0 == pytest.approx(
                float(wavegear.volume_per_torque(q, n, 2.0)), rel=1e-12
            )


def test_more_rows_shrink_the_outer_diameter():
    # seed 000: 3 and 4 rows cut D by ≈ 12 % and ≈ 20 % against 2 rows; by (16) the
    # diameter goes as n_p^(-1/3): 1 − (2/3)^(1/3) = 12.6 %, 1 − (2/4)^(1/3) = 20.6 %
    d2, d3, d4 = (
        float(wavegear.outer_diameter(20, wavegear.rolling_body_diameter(1000, 20, n)))
        for n in (2, 3, 4)
    )
    assert 1 - d3 / d2 == pytest.approx(0.126, abs=1e-3)
    assert 1 - d4 / d2 == pytest.approx(0.206, abs=1e-3)


def test_outer_diameter_per_torque_is_flat_near_q_9_to_16():
    # DOMAIN.md: with (13)+(16) alone the diameter's minimum falls near q ≈ 9
    q = np.arange(7.0, 41.0, 0.25)
    D = wavegear.outer_diameter(q, wavegear.rolling_body_diameter(1000, q, 3))
    assert 8.5 <= q[np.argmin(D)] <= 10
    assert D[(q >= 8) & (q <= 16)].max() / D.min() < 1.05


def test_bore_needs_q_above_6_45():
    # 2.06/sin(π/q) = 4.4 ⇔ q = π/asin(2.06/4.4) = π/0.48721 = 6.448
    assert wavegear.MIN_RATIO_FOR_BORE == pytest.approx(6.448, abs=1e-3)
    assert float(wavegear.inner_diameter(6.4, 1.0)) < 0 < float(wavegear.inner_diameter(6.5, 1.0))


def test_rows_for_a_diameter_inverts_eq16():
    d = float(wavegear.outer_diameter(20, wavegear.rolling_body_diameter(1620, 20, 5)))
    assert float(wavegear.rows_for_diameter(1620, 20, d)) == pytest.approx(5)


def test_two_stages_for_5000_rpm():
    # seed 000: 5000 rpm / (4…6 rpm) = 833…1250 → two stages, q_out = 20, q1 = 42…63
    for speed in (4, 5, 6):
        split = split_ratio(5000 / speed, reducer.STAGE_RATIO_MIN, reducer.STAGE_RATIO_MAX).value
        assert split[0] == 20 and len(split) == 2
        assert 41.6 <= split[1] <= 62.5


def test_three_stages_for_10000_rpm():
    # seed 000: 10000 rpm → 1667…2500 → three stages, q_out = 20, q2 = 12, q1 = 7…11
    for speed in (4, 5, 6):
        split = split_ratio(10000 / speed, reducer.STAGE_RATIO_MIN, reducer.STAGE_RATIO_MAX).value
        assert split[:2] == [20, 12] and len(split) == 3
        assert 6.9 <= split[2] <= 10.5


def test_equal_diameter_layout_lengths():
    # L2 = L_out·∛(1/q_out), L3 = L_out·∛(1/(q_out·q2)) (seed 000, after eq. (19))
    p = reducer.ReducerParams(1620.0, 1.0, 0.9, 7800.0, 0.75)
    r = reducer.evaluate([20.0, 12.0, 8.0], [3, 2, 2], p)
    out, mid, inp = r.stages[2], r.stages[1], r.stages[0]
    assert (inp.position, mid.position, out.position) == ("input", "intermediate", "output")
    assert mid.length_mm == pytest.approx(out.length_mm * (1 / 20) ** (1 / 3))
    assert inp.length_mm == pytest.approx(out.length_mm * (1 / 240) ** (1 / 3))
    assert r.total_ratio == pytest.approx(20 * 12 * 8)
    assert r.efficiency == pytest.approx(0.9**3)
    # torques fall through the chain: M/(q·η)
    assert mid.torque_Nm == pytest.approx(1620 / (20 * 0.9))
    # mass by eq. (19): ρ·k·W
    assert r.mass_kg == pytest.approx(7800 * 0.75 * r.volume_mm3 * 1e-9)
    assert r.volume_mm3 == pytest.approx(
        math.pi / 4 * (r.outer_diameter_mm**2 - r.inner_diameter_mm**2) * r.length_mm
    )


def test_sweep_contains_the_rule_design_and_finds_a_lighter_one():
    p = reducer.ReducerParams(1620.0, 1.0, 0.9, 7800.0, 0.75)
    space = reducer.sweep(1000.0, p)
    rule = reducer.evaluate([20.0, 50.0], [3, 2], p)
    match = (space.stages == 2) & (space.q_out == 20) & (space.rows_out == 3)
    assert match.sum() == 1
    assert space.mass_kg[match][0] == pytest.approx(rule.mass_kg)
    i = reducer.best(space, "mass")
    assert space.mass_kg[i] <= rule.mass_kg
    # with an envelope, the best fits it
    j = reducer.best(space, "mass", max_outer_diameter_mm=120, max_length_mm=100)
    assert space.outer_diameter_mm[j] <= 120 and space.length_mm[j] <= 100
    assert reducer.best(space, "mass", max_outer_diameter_mm=10) is None


def test_sweep_agrees_with_a_finer_brute_force_grid():
    # the optimum of the coarse grid is within 2 % of a twice-as-fine grid's
    p = reducer.ReducerParams(1620.0, 1.0, 0.9, 7800.0, 0.75)
    coarse = reducer.sweep(1000.0, p)
    fine_q = np.arange(7.0, 40.0 + 1e-9, 0.25)
    fine = []
    for q_out in fine_q:
        q1 = 1000.0 / q_out
        if reducer.STAGE_RATIO_MIN <= q1 <= reducer.STAGE_RATIO_MAX:
            fine.append(min(reducer.evaluate([q_out, q1], [n, 2], p).mass_kg for n in range(2, 13)))
    assert coarse.mass_kg.min() <= min(fine) * 1.02


def test_eq17_is_the_sum_of_stage_volumes_of_eq18():
    # three stages of q = 16 and three rows each; torques M, M/16, M/256 (no losses, as in
    # the seed); each stage's own volume by (18) is W/M·M_stage
    q, n, m = 16.0, 3, 1200.0
    stages = [m, m / q, m / q**2]
    total = sum(float(wavegear.volume_per_torque(q, n)) * t for t in stages)
    w_out = float(wavegear.volume_per_torque(q, n)) * m
    assert float(wavegear.reducer_volume_eq17(w_out, [q, q, q])) == pytest.approx(total)
    assert float(wavegear.reducer_volume_eq17(1.0, [20, 12, 8])) == pytest.approx(
        1 + 1 / 20 + 1 / 240
    )


def test_equal_diameter_volume_estimate():
    # seed 000: with equal diameters W_red = W_out + (0.4…0.5)·W_out + (0.15…0.2)·W_out, the
    # smaller values for q = 20: the volumes go as the lengths, ∛(1/20) = 0.368 and
    # ∛(1/240) = 0.161
    p = reducer.ReducerParams(1000.0, 1.0, 1.0, 7800.0, 0.75)
    r = reducer.evaluate([20.0, 12.0, 8.0], [3, 2, 2], p)
    out = r.stages[-1].mass_kg
    assert r.stages[1].mass_kg / out == pytest.approx(0.368, abs=1e-3)
    assert r.stages[0].mass_kg / out == pytest.approx(0.161, abs=1e-3)
