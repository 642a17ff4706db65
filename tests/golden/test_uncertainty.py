"""The probability of passing (issue 30, part 2): closed forms, determinism, a tighter law
never lowers P(pass), the margin model equals the advisor's own checks, and the robust
choice takes the first candidate in the advisor's order that reaches the target."""

import math
import time

import numpy as np
import pytest
from helpers import EXAMPLES, seed001_requirement
from hypothesis import given, settings
from hypothesis import strategies as st

from advisor.applications.linear import uncertainty as linear
from advisor.calc import screw as sc
from advisor.calc.sizing import fit_motor
from advisor.cli import main
from advisor.core.engine import advise, advise_with
from advisor.core.reading import parse_requirements, read_requirements
from advisor.uncertainty import evaluate, replaced
from advisor.uncertainty.analysis import check_results, wilson
from advisor.uncertainty.sampling import Distribution, sample
from catalogs import load_catalogs

CAT = load_catalogs()
ROBUST = EXAMPLES / "uncertainty" / "linear_screw_robust.toml"


def _req(inputs, **u):
    data = seed001_requirement(material_pair="steel_bronze", thread="Tr16x2")
    data["uncertainty"] = {"inputs": inputs, **u}
    return parse_requirements(data)


def _section(req):
    return evaluate(req, advise_with(replaced(req, uncertainty=None), CAT), CAT)


def _check(section, cid):
    return next(c for c in section.checks if c.id == cid)


def test_a_margin_linear_in_one_uniform_input_gives_the_closed_form():
    """margin = 0.7 + x, x uniform on 0 … 1: P(margin ≥ 1) = P(x ≥ 0.3) = 0.7."""
    n = 4000
    x = sample([Distribution("x", "uniform", 0.5, 0.0, 1.0)], n, seed=7)
    (res,), every = check_results({"c": 0.7 + x["x"]}, x)
    half = (res.probability.high - res.probability.low) / 2
    assert abs(res.probability.p - 0.7) <= half
    assert every == res.probability
    assert res.drivers == [("x", pytest.approx(1.0))]


def test_nut_pressure_under_a_uniform_force_is_the_closed_form():
    """Tr16x2's nut (9 turns): p = F/(π·d2·H1·z) against 10 MPa, margin 1.21177 at 3500 N, so
    it passes while F ≤ 3500·1.21177 = 4241.2 N. F uniform on 3000 … 4500 N:
    P = (4241.2 − 3000)/1500 = 0.8275, within the sampling error the report states."""
    req = _req([{"name": "linear.force_N", "distribution": "uniform", "low": 3000, "high": 4500}])
    c = _check(_section(req), "nut_pressure")
    limit = 10e6 * math.pi * 0.015 * 0.001 * 9
    assert c.nominal_margin == pytest.approx(limit / 3500, rel=1e-5)
    closed = (limit - 3000) / 1500
    assert closed == pytest.approx(0.8275, abs=1e-4)
    assert c.p_pass_low <= closed <= c.p_pass_high
    assert abs(c.p_pass - closed) < 2e-3  # a Latin hypercube is far tighter than binomial
    assert c.drivers[0].input == "linear.force_N"
    assert c.drivers[0].rank_correlation == pytest.approx(-1.0)


def test_same_seed_same_numbers_other_seed_other_numbers():
    inputs = [{"name": "linear.force_N", "distribution": "normal", "sd": 300}]
    a, b = _section(_req(inputs, seed=3)), _section(_req(inputs, seed=3))
    assert a == b
    c = _section(_req(inputs, seed=4))
    # other samples: other percentiles and correlations (P itself agrees to 10⁻⁴: a Latin
    # hypercube stratifies every input)
    assert c != a and _check(c, "core_stress").margin_p05 != _check(a, "core_stress").margin_p05


@settings(max_examples=12, deadline=None)
@given(
    wide=st.floats(min_value=0.05, max_value=0.5),
    shrink=st.floats(min_value=0.0, max_value=0.95),
)
def test_a_tighter_law_never_lowers_the_probability(wide, shrink):
    """The design's margins are above 1 at its nominal inputs and move monotonically with
    the force: a range around the nominal force shrunk towards it (same seed) keeps every
    passing sample passing, so P(pass) cannot fall."""

    def p(half):
        inputs = [
            {
                "name": "linear.force_N",
                "distribution": "uniform",
                "low": 3500 * (1 - half),
                "high": 3500 * (1 + half),
            },
            {
                "name": "screw.friction_coefficient",
                "distribution": "uniform",
                "low": 0.14,
                "high": 0.16,
            },
        ]
        return _section(_req(inputs, samples=1000, seed=5)).p_pass

    assert p(wide * (1 - shrink)) >= p(wide)


def test_the_margin_model_is_the_advisors_checks():
    """At the nominal inputs the model's margins are the report's; at other inputs (the
    thread, its nut and the motor held: Tr16x2, 9 turns, 4A80A4) they equal the checks of
    the advisor run on those inputs."""
    req = _req([])
    nominal = advise_with(replaced(req, uncertainty=None), CAT)
    margins, x0 = linear.margin_model(req, nominal, CAT)
    at0 = margins({k: np.array([v]) for k, v in x0.items()})
    for c in nominal.checks:
        assert at0[c.id][0] == pytest.approx(c.margin, rel=1e-12), c.id
    data = seed001_requirement(material_pair="steel_bronze", thread="Tr16x2")
    data["linear"].update(force_N=3600.0, support_span_m=0.42)
    data["screw"]["friction_coefficient"] = 0.155
    other = advise(parse_requirements(data))
    assert other.design.motor.model == nominal.design.motor.model == "4A80A4"
    assert other.design.screw.nut.turns == nominal.design.screw.nut.turns
    got = margins(
        {
            "linear.force_N": np.array([3600.0]),
            "linear.support_span_m": np.array([0.42]),
            "screw.friction_coefficient": np.array([0.155]),
        }
    )
    assert {c.id for c in other.checks} == set(got)
    for c in other.checks:
        assert got[c.id][0] == pytest.approx(c.margin, rel=1e-6), c.id


def test_numpy_forms_equal_the_calc_functions():
    rng = np.random.default_rng(0)
    for f_n, f, span in rng.uniform((500, 0.05, 0.1), (20000, 0.25, 2.0), (20, 3)):
        d2, d3, p = 0.015, 0.0135, 0.002
        psi = sc.lead_angle(p, d2)
        for model in ("standard", "paper"):
            assert linear.thread_torque(f_n, d2, psi, f, model) == pytest.approx(
                sc.thread_torque(f_n, d2, p, f, model), rel=1e-12
            )
        m = sc.thread_torque(f_n, d2, p, f)
        assert linear.core_stress(f_n, m, d3) == pytest.approx(
            sc.core_equivalent_stress(f_n, m, d3), rel=1e-12
        )
        assert linear.critical_load(d3, span, 1.0, 210e9, 355e6) == pytest.approx(
            sc.critical_buckling_load(d3, span, "pinned-pinned", 210e9, 355e6)[0], rel=1e-12
        )
    curve = fit_motor(next(m for m in CAT.motors if m.model == "4A71B4")).curve
    for t in (0.5, 3.0, 5.0, 9.0):
        assert linear.working_slip(curve, t) == pytest.approx(curve.stable_slip(t), rel=1e-12)
    assert np.isnan(linear.working_slip(curve, curve.max_torque_Nm * 1.01))


def test_wilson_interval_by_hand():
    """95 successes in 100: p = 0.95, z = 1.96: centre (0.95 + 0.019208)/1.038415 = 0.93335,
    half 1.96·√(0.000475 + 0.0000960)/1.038415 = 0.04510 → 0.8883 … 0.9785."""
    i = wilson(95, 100)
    assert (i.low, i.high) == pytest.approx((0.8883, 0.9785), abs=1e-4)
    assert wilson(0, 50).low == 0.0 and wilson(50, 50).high == 1.0


def test_robust_choice_takes_the_first_candidate_that_reaches_the_target():
    rep = advise(read_requirements(ROBUST))
    u = rep.uncertainty
    r = u.robust
    assert r.target == 0.99
    assert r.nominal_p_pass < 0.99 <= u.p_pass_low and r.chosen == u.design
    assert r.chosen != r.nominal_choice
    assert all(c.p_pass_low < 0.99 for c in r.candidates[:-1])
    assert r.candidates[-1].label == r.chosen
    # the candidates are the advisor's, in its order; the chosen one is its first that reaches
    req = read_requirements(ROBUST)
    order = [f"{t} ({k} start{'s' if k > 1 else ''})" for t, k, _ in linear.candidates(req, CAT)]
    assert any(r.chosen.startswith(o) for o in order)
    d = next(x for x in rep.decisions if x.id == "UQ-01")
    assert r.nominal_choice in d.decision and f"{r.nominal_p_pass:.4f}" in d.decision
    assert {"mckay-1979", "wilson-1927"} <= {s.id for s in rep.sources}
    assert rep.requirements["uncertainty"]["target"] == 0.99  # the requirement as given
    assert "starts" in rep.requirements["screw"]


def test_without_the_table_nothing_changes():
    rep = advise(parse_requirements(seed001_requirement(material_pair="steel_bronze")))
    assert rep.uncertainty is None


def test_refusals_are_one_line_exit_2(tmp_path, capsys):
    p = tmp_path / "r.toml"
    p.write_text(
        ROBUST.read_text(encoding="utf-8").replace("sd = 175", "sd = 175\nlow = 100"),
        encoding="utf-8",
    )
    assert main(["--batch", str(p)]) == 2
    assert "low is given but distribution = 'normal'" in capsys.readouterr().err
    p.write_text(
        ROBUST.read_text(encoding="utf-8").replace(
            'distribution = "normal"\nsd = 175', 'distribution = "uniform"\nlow = 100\nhigh = 200'
        ),
        encoding="utf-8",
    )
    assert main(["--batch", str(p)]) == 2
    assert "lies outside 100 … 200" in capsys.readouterr().err
    rot = tmp_path / "rot.toml"
    rot.write_text(
        (EXAMPLES / "rudder_actuator.toml").read_text(encoding="utf-8") + "\n[uncertainty]\n",
        encoding="utf-8",
    )
    assert main(["--batch", str(rot)]) == 2
    assert "uncertainty" in capsys.readouterr().err


def test_ten_thousand_samples_well_within_a_second():
    req = _req([{"name": "linear.force_N", "distribution": "normal", "sd": 175}])
    nominal = advise_with(replaced(req, uncertainty=None), CAT)
    evaluate(req, nominal, CAT)  # warm
    t0 = time.perf_counter()
    section = evaluate(req, nominal, CAT)
    assert time.perf_counter() - t0 < 1.0
    assert section.samples == 10_000


def test_the_linear_model_gives_the_friction_law_the_catalog_states():
    """Where the [uncertainty] table leaves the screw's friction out, the linear model gives
    it uniform over the material pair's range for its lubrication: steel on tin bronze, oiled,
    f = 0.10 … 0.16 (catalogs/screw_materials.toml, after Shigley's Table 8-5); given in the
    table, it is not given twice. The design is named as its reports name it."""
    req, cat = read_requirements(ROBUST), load_catalogs()
    nominal = {"screw.friction_coefficient": 0.15, "linear.force_N": 3500.0}
    (law,) = linear.default_inputs(req, cat, nominal, given={"linear.force_N"})
    assert (law.name, law.kind, law.nominal) == ("screw.friction_coefficient", "uniform", 0.15)
    assert (law.low, law.high) == (0.10, 0.16)
    assert linear.default_inputs(req, cat, nominal, given={"screw.friction_coefficient"}) == []
    rep = advise(req)
    assert linear.design_label(rep) == rep.uncertainty.design == "Tr18x4 (1 start) with 4A80A6"
