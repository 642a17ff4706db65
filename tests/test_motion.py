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
    # by hand: i0 = ∛1181.25 = 10.5709, μ0 = 5/10.5709 = 0.47299, μ0² = 0.22372;
    # the curves of figs. 4–5 cross where x⁴ − x − μ0² = 0 (x = √K):
    # x = 1.0656: 1.28937 − 1.0656 − 0.22372 = 0.00004 → K1 = x² = 1.1355,
    # i = K1·i0 = 1.1355·10.5709 = 12.003, the root of eq. (6) (12.0031)
    fp = mo.graphical_fixed_point(A, 10.0)
    assert fp.k == pytest.approx(1.1355, abs=1e-4)
    assert fp.ratio == pytest.approx(12.003, abs=1e-3)
    assert fp.ratio == pytest.approx(mo.optimal_ratio_trapezoidal(A, 10.0), rel=1e-12)
    # it is a fixed point of i = K(m/i)·∛A: K read at μ1 = m/i gives K1 back
    assert mo.k_factor(5.0 / fp.ratio) == pytest.approx(fp.k, rel=1e-12)
    assert fp.mu == pytest.approx(5.0 / fp.ratio)
    # the first step, K read at μ0, is what the report shows beside it
    est, i0, k = mo.graphical_estimate(A, 10.0)
    assert i0 == pytest.approx(1181.25 ** (1 / 3))
    assert 1.0 <= k <= 1.35
    # μ0 = 0.4730 → K = (1/(1 − 0.22372)²)^(1/3) = 1.1839 → 12.515
    assert est == pytest.approx(12.515, abs=1e-3)
    # and the time curve is flat there: 4 % off in ratio costs 0.22 % of time
    # (1.20848 s at 12.515 against 1.20588 s at 12.003)
    assert (
        mo.move_time_trapezoidal(A, 10.0, est) / mo.move_time_trapezoidal(A, 10.0, fp.ratio)
        < 1.0025
    )


def test_fixed_point_where_plain_iteration_diverges():
    # i ← K(m/i)·∛A converges only while |dK/di·i0| = (4/3)μ²/(1 − μ²) < 1, i.e. μ < 0.655;
    # a heavy load, m = 1000/20 = 50: A = 2·150²·0.01·(2500 + 500)/(10·20) = 6750,
    # i0 = 18.899, μ0 = 50/18.899 = 2.6457 (off the chart), μ0² = 6.9996,
    # x⁴ − x − 6.9996 = 0 → x = 1.7183,
    # K1 = 2.9526, i = 55.80 (μ1 = 0.896)
    heavy = mo.Drive(150.0, 0.01, 20.0, 5.0, 1000.0)
    assert mo.coefficient_a(heavy, 10.0) == pytest.approx(6750.0)
    fp = mo.graphical_fixed_point(heavy, 10.0)
    assert fp.k == pytest.approx(2.9526, abs=1e-4)
    assert fp.ratio == pytest.approx(55.80, abs=0.01)
    assert fp.ratio == pytest.approx(mo.optimal_ratio_trapezoidal(heavy, 10.0), rel=1e-12)
    # the first step K(μ0)·i0 = (1/(1 − 6.9996)²)^(1/3)·18.899 = 0.30287·18.899 = 5.724 < 50:
    # a ratio at which the motor cannot move the load
    first, _, _ = mo.graphical_estimate(heavy, 10.0)
    assert first == pytest.approx(5.724, abs=1e-3)
    assert not mo.first_step_moves_load(heavy, first)
    assert mo.first_step_moves_load(heavy, fp.ratio)


def test_triangular_ratio_counts_the_load_torque():
    # motor A, I = 500, m = 5: i² = [(3·25 + 500) + √(575² + 4·500·25)]/2
    # = [575 + √380625]/2 = [575 + 616.948]/2 = 595.974 → i = 24.4126
    assert mo.triangular_ratio(A) == pytest.approx(24.4126, abs=1e-4)
    # it is the minimum of the triangular time law, found independently
    assert mo.optimal_ratio_triangular(A, 0.2) == pytest.approx(24.4126, abs=1e-4)
    # the inertia match √I = 22.36 ignores the load torque and is slower
    t = mo.move_time_triangular(A, 0.2, 24.4126)
    assert mo.move_time_triangular(A, 0.2, math.sqrt(500)) > t
    # the two limits: no load torque → √I; no load inertia → √3·m
    assert mo.triangular_ratio(A._replace(load_torque_Nm=0.0)) == pytest.approx(math.sqrt(500))
    assert mo.triangular_ratio(A._replace(load_inertia_kgm2=0.0)) == pytest.approx(math.sqrt(3) * 5)


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
    # the graphical method's answer (fixed point) with its first step beside it, motor A:
    # 12.003 against 12.515 (test_graphical_method_fixed_point_is_the_exact_optimum)
    assert a["estimated_ratio"] == pytest.approx(12.003, abs=1e-3)
    assert a["estimated_ratio_first_step"] == pytest.approx(12.515, abs=1e-3)
    assert a["first_step_moves_load"] is True
    assert m["profile_actual"] == "trapezoidal"
    assert len(m["curve"]["ratio"]) == len(m["curve"]["move_time_s"]) == 61
    assert min(m["curve"]["move_time_s"]) >= m["move_time_s"] * (1 - 1e-6)
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
    with pytest.raises(InputError, match=r"positioning.travel_rad = 0.0: must be ≥ 0.0001"):
        parse_requirements(_req(travel_rad=0.0))
    with pytest.raises(InputError, match="used twice"):
        m = {"name": "A", "speed_rad_s": 1.0, "inertia_kgm2": 1.0, "accel_torque_Nm": 1.0}
        parse_requirements(_req(motors=[m, m]))
    with pytest.raises(InputError, match=r"positioning.profile = 'sinusoidal'"):
        parse_requirements(_req(profile="sinusoidal"))


def test_estimated_inertias_decide_only_through_mo_04():
    from rules.motion import robust_motor

    # A is nominally fastest (1.10 s), but with inertias ±30 % A spans 1.00…1.20 s and B
    # 1.05…1.15 s: either could be the fastest; B is the faster in the worst case
    f = robust_motor("A", {"A": 1.0, "B": 1.05, "C": 1.5}, {"A": 1.2, "B": 1.15, "C": 1.9}, 0.3)
    assert f.value == ("B", ("B", "A"))
    assert "cannot separate 2 motors" in f.decision and "maker's data" in f.decision
    # A spans 1.00…1.04 s and nothing else can get below 1.05 s: A stands
    f = robust_motor("A", {"A": 1.0, "B": 1.05}, {"A": 1.04, "B": 1.2}, 0.3)
    assert f.value == ("A", ("A",)) and "do not decide" in f.rationale


def test_catalog_choice_when_the_estimate_cannot_separate_motors():
    from catalogs import load_catalogs

    req = _req(travel_rad=0.5, load_torque_Nm=10.0)
    req["positioning"]["motors"] = []
    rep = advise(parse_requirements(req))
    mo04 = next(d for d in rep.decisions if d.id == "MO-04")
    assert "cannot separate" in mo04.decision
    assert mo04.decision.startswith(f"Motor {rep.design.motion.motor}:")
    assert "MO-02" not in [d.id for d in rep.decisions]
    assert any("decision MO-04" in w for w in rep.warnings)
    # the motor taken is the one with the least time when every inertia is 30 % above its
    # estimate, each at its own optimal ratio (computed here independently)
    worst = {}
    for m in load_catalogs().motors:
        d = mo.Drive(
            m.rated_speed_rpm * math.pi / 30,
            m.inertia_kgm2 * 1.3,
            m.starting_torque_ratio * m.rated_torque_Nm,
            5.0,
            10.0,
        )
        i = mo.optimal_ratio_trapezoidal(d, 0.5)
        if mo.move_time(d, 0.5, i)[1] == "triangular":
            i = mo.optimal_ratio_triangular(d, 0.5)
        worst[m.model] = mo.move_time(d, 0.5, i)[0]
    assert rep.design.motion.motor == min(worst, key=worst.get)


def test_catalog_choice_that_the_estimate_does_not_change():
    req = _req()
    req["positioning"]["motors"] = []
    rep = advise(parse_requirements(req))
    ids = [d.id for d in rep.decisions]
    assert ids == ["MO-04", "MO-01", "MO-03"]  # MO-04 takes the motor decision
    assert rep.decisions[0].decision.startswith(
        f"Motor {rep.design.motion.motor} stays the fastest"
    )
    times = {c.name: c.move_time_s for c in rep.design.motion.candidates}
    assert rep.design.motion.motor == min(times, key=times.get)


def test_no_load_torque_has_no_checks_and_the_summary_says_so(tmp_path, capsys):
    # issue 13: with M_p = 0 no check applies; the summary used to fail after the report was
    # written (exit 1)
    from advisor.cli import main

    src = tmp_path / "r.toml"
    src.write_text(
        '[application]\nkind = "positioning"\n[positioning]\ntravel_rad = 10\n'
        "load_inertia_kgm2 = 5\nload_torque_Nm = 0\n[[positioning.motors]]\n"
        'name = "A"\nspeed_rad_s = 150\ninertia_kgm2 = 0.01\naccel_torque_Nm = 20\n',
        encoding="utf-8",
    )
    rc = main(["--batch", str(src), "-o", str(tmp_path / "out.toml")])
    out, err = capsys.readouterr()
    assert rc == 0, err
    assert "no check applies" in out
    rep = tomllib.loads((tmp_path / "out.toml").read_text(encoding="utf-8"))
    assert rep.get("checks", []) == []
    # m = 0: the graphical method needs no K (K = 1), i = ∛A with A = 2·150²·0.01·500/(10·20)
    # = 1125 → i = 10.400
    assert rep["design"]["motion"]["estimated_ratio"] == pytest.approx(1125 ** (1 / 3), rel=1e-5)
    assert rep["design"]["motion"]["optimal_ratio"] == pytest.approx(10.400, abs=1e-3)


def test_fixed_point_with_a_negligible_load_torque():
    # found by the whole-range property test: μ0 ≈ 4e-17, so 1 + μ0 rounds to 1 and the
    # bracket was empty. Near x = 1, x⁴ − x ≈ 3·(x − 1), so K1 = x² ≈ 1 + 2μ0²/3 → 1 and the
    # fixed point is i0 = ∛A.
    d = mo.Drive(1e4, 1e-9, 1e6, 1e7, 1e-6)
    fp = mo.graphical_fixed_point(d, 1e-4)
    assert fp.k == 1.0
    assert fp.ratio == pytest.approx(mo.coefficient_a(d, 1e-4) ** (1 / 3), rel=1e-15)
    # μ0 = 1e-4: K1 − 1 = 2μ0²/3 = 6.6667e-9 to first order (the next term is O(μ0⁴))
    m = 1e-4 * 1181.25 ** (1 / 3)  # motor A's i0 = ∛A with the torque ratio making μ0 = 1e-4
    light = A._replace(load_torque_Nm=m * 20.0)
    i0 = mo.coefficient_a(light, 10.0) ** (1 / 3)
    mu0 = light.torque_ratio / i0
    assert mo.graphical_fixed_point(light, 10.0).k - 1 == pytest.approx(2 * mu0**2 / 3, rel=1e-6)
