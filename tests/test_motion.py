"""Seed 003: the ratio of the fastest move, by hand and by the engine."""

import math
import tomllib

import pytest
from helpers import EXAMPLES

from advisor.calc import motion as mo
from advisor.core.engine import advise
from advisor.core.errors import InputError
from advisor.core.report import to_toml
from advisor.core.requirements import parse_requirements, read_requirements

# motor A of the example: ω0 = 150 rad/s, J0 = 0.01 kg·m², M_λ = 20 N·m;
# load 5 kg·m², 100 N·m, path 10 rad
A = mo.Drive(150.0, 0.01, 20.0, 5.0, 100.0)


def test_eq7_by_hand():
    # I = 5/0.01 = 500, m = 100/20 = 5; A = 2·150²·0.01·(25 + 500)/(10·20) = 1181.25
    assert A.inertia_ratio == 500 and A.torque_ratio == 5
    assert mo.coefficient_a(A, 10.0) == pytest.approx(2 * 150**2 * 0.01 * 525 / 200)
    assert mo.coefficient_a(A, 10.0) == pytest.approx(1181.25)


def test_eq4_by_hand():
    # i = 12: t = 10·12/150 + 150·0.01/20·(144 + 500)/(144 − 25) = 0.8 + 0.075·5.41176
    t = mo.move_time_trapezoidal(A, 10.0, 12.0)
    assert t == pytest.approx(0.8 + 0.075 * 644 / 119)
    assert t == pytest.approx(1.205882, abs=1e-6)


def test_exact_optimum_solves_eq6_and_minimises_eq4():
    i = mo.optimal_ratio_trapezoidal(A, 10.0)
    a, m = 1181.25, 5.0
    assert a * i / (i * i - m * m) ** 2 == pytest.approx(1.0, abs=1e-10)
    t = mo.move_time_trapezoidal(A, 10.0, i)
    for f in (0.98, 0.995, 1.005, 1.02):
        assert mo.move_time_trapezoidal(A, 10.0, i * f) > t
    # by hand: i = 12.0 gives A·i = 14175 vs (144 − 25)² = 14161 → root just above 12
    assert 12.0 < i < 12.01


def test_graphical_method_fixed_point_is_the_exact_optimum():
    exact = mo.optimal_ratio_trapezoidal(A, 10.0)
    assert mo.fixed_point(A, 10.0) == pytest.approx(exact, rel=1e-10)
    # the first reading of the graph, K(μ0)·∛A, is within the seed's range K = 1…1.35
    est, i0, k = mo.graphical_estimate(A, 10.0)
    assert i0 == pytest.approx(1181.25 ** (1 / 3))
    assert 1.0 <= k <= 1.35
    # μ0 = 5/10.574 = 0.4729 → K = (1/(1 − 0.2236)²)^(1/3) = 1.1837 → 12.52
    assert est == pytest.approx(12.52, abs=0.01)
    # and the time curve is flat there: 4 % off in ratio costs 0.22 % of time
    # (1.20848 s at 12.515 against 1.20588 s at 12.003)
    assert (
        mo.move_time_trapezoidal(A, 10.0, est) / mo.move_time_trapezoidal(A, 10.0, exact) < 1.0025
    )


def test_k_is_1_to_1_35_for_mu_0_to_0_6():
    assert mo.k_factor(0.0) == 1.0
    assert mo.k_factor(0.6) == pytest.approx((1 / 0.64**2) ** (1 / 3))
    assert mo.k_factor(0.6) == pytest.approx(1.346, abs=1e-3)


def test_engineering_units_eq12_and_eq13():
    # motor A in the paper's (technical) units: n = 150·30/π rpm; GD² [kgf·m²] is numerically
    # 4·J [kg·m²] (weight in kgf = mass in kg); M [kgf·m] = M [N·m]/g; S = α/2π revolutions
    g = mo.G
    n = 150 * 30 / math.pi
    gd2 = 4 * 0.01
    m_kgf = 20 / g
    s_rev = 10 / (2 * math.pi)
    a12 = mo.coefficient_a_engineering(n, gd2, m_kgf, s_rev, 5.0, 500.0)
    assert a12 == pytest.approx(mo.coefficient_a(A, 10.0), rel=1e-12)
    # the paper's constant 11320 gives 0.7 % less
    a_paper = mo.coefficient_a_engineering(n, gd2, m_kgf, s_rev, 5.0, 500.0, constant=11320)
    assert a_paper / a12 == pytest.approx(3600 * g / math.pi / 11320)
    # C = 3600·9.80665/π = 11237.5: the paper's 11320 is 0.73 % too large
    assert 1 - a_paper / a12 == pytest.approx(0.0073, abs=1e-4)
    # (13) with 375 = 120·g/π equals (4)
    t13 = mo.move_time_engineering(n, gd2, m_kgf, s_rev, 12.0, 5.0, 500.0)
    assert t13 == pytest.approx(mo.move_time_trapezoidal(A, 10.0, 12.0), rel=1e-12)
    assert 120 * g / math.pi == pytest.approx(375, abs=0.5)


def test_triangular_without_load_matches_inertias():
    d = mo.Drive(150.0, 0.01, 20.0, 5.0, 0.0)
    assert mo.optimal_ratio_triangular(d, 0.1) == pytest.approx(math.sqrt(500), rel=1e-6)


def test_short_move_is_triangular_and_the_time_law_is_continuous():
    i = 12.0
    boundary = mo.transient_path(A, i)  # = ω_p·t_j/2 = 12.5·0.4870 = 6.09 rad
    assert boundary == pytest.approx(150 / 12 * 0.075 * 644 / 119 * 2 / 2)
    assert mo.move_time(A, boundary * 0.5, i)[1] == "triangular"
    assert mo.move_time(A, boundary * 2, i)[1] == "trapezoidal"
    # at the boundary both laws give the same time (the motor just touches ω0)
    assert mo.move_time_triangular(A, boundary, i) == pytest.approx(
        mo.move_time_trapezoidal(A, boundary, i), rel=1e-9
    )
    assert mo.triangular_peak_speed(A, boundary, i) == pytest.approx(150.0, rel=1e-9)


@pytest.fixture(scope="module")
def report():
    return tomllib.loads(to_toml(advise(read_requirements(EXAMPLES / "positioning_drive.toml"))))


def test_example_picks_the_fastest_motor(report):
    m = report["design"]["motion"]
    times = {c["name"]: c["move_time_s"] for c in m["candidates"]}
    assert m["motor"] == min(times, key=times.get) == "C"
    a = next(c for c in m["candidates"] if c["name"] == "A")
    assert a["optimal_ratio"] == pytest.approx(mo.optimal_ratio_trapezoidal(A, 10.0), rel=1e-5)
    assert a["move_time_s"] == pytest.approx(
        mo.move_time_trapezoidal(A, 10.0, a["optimal_ratio"]), rel=1e-5
    )
    assert m["profile_actual"] == "trapezoidal"
    curve = report["curves"]["design.motion.curve"]
    assert len(curve["ratio"]) == len(curve["move_time_s"]) == 61
    assert min(curve["move_time_s"]) >= m["move_time_s"] * (1 - 1e-6)
    assert [d["id"] for d in report["decisions"]] == ["MO-02", "MO-01", "MO-03"]


def _req(**pos):
    base = {
        "profile": "trapezoidal",
        "travel_rad": 10.0,
        "load_inertia_kgm2": 5.0,
        "load_torque_Nm": 100.0,
    }
    base.update(pos)
    base.setdefault(
        "motors",
        [{"name": "A", "speed_rad_s": 150.0, "inertia_kgm2": 0.01, "accel_torque_Nm": 20.0}],
    )
    return {"application": {"kind": "positioning"}, "positioning": base}


def test_a_short_move_is_reported_and_reoptimised():
    # 0.2 rad: the trapezoidal optimum would need more path for starting and stopping than
    # the move has (α_j/α = (i² + I)(i² − m²)/(2i²(m² + I)) > 1 at that ratio)
    d = mo.Drive(150.0, 0.01, 20.0, 5.0, 100.0)
    i_trap = mo.optimal_ratio_trapezoidal(d, 0.2)
    assert mo.transient_path(d, i_trap) > 0.2
    rep = advise(parse_requirements(_req(travel_rad=0.2)))
    m = rep.design.motion
    assert m.profile_actual == "triangular"
    assert any("not trapezoidal" in w for w in rep.warnings)
    assert m.optimal_ratio == pytest.approx(mo.optimal_ratio_triangular(d, 0.2), rel=1e-6)
    # the triangular optimum is faster than the (impossible) trapezoidal figure suggests
    assert m.move_time_s == pytest.approx(mo.move_time_triangular(d, 0.2, m.optimal_ratio))


def test_catalog_candidates_when_none_given():
    req = _req()
    req["positioning"]["motors"] = []
    rep = advise(parse_requirements(req))
    assert len(rep.design.motion.candidates) >= 50
    assert any("estimated" in w for w in rep.warnings)


def test_bad_positioning_inputs():
    with pytest.raises(InputError, match=r"positioning.travel_rad = 0.0: must be > 0"):
        parse_requirements(_req(travel_rad=0.0))
    with pytest.raises(InputError, match="used twice"):
        m = {"name": "A", "speed_rad_s": 1.0, "inertia_kgm2": 1.0, "accel_torque_Nm": 1.0}
        parse_requirements(_req(motors=[m, m]))
    with pytest.raises(InputError, match=r"positioning.profile = 'sinusoidal'"):
        parse_requirements(_req(profile="sinusoidal"))
