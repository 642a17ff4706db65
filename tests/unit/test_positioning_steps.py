"""The positioning advice's steps and records (seed 003): the ratio solution of calc, the
candidate sets, and one builder for a motor's report row."""

import math
import tomllib

import pytest
from helpers import EXAMPLES

from advisor.applications.positioning.advice import candidate_out, curve_out
from advisor.applications.positioning.candidates import (
    CandidateSet,
    Solved,
    candidates,
    catalog_candidates,
    listed_candidates,
    usable,
)
from advisor.calc.motion import (
    Drive,
    RatioSolution,
    move_time,
    optimal_ratio_trapezoidal,
    optimal_ratio_triangular,
    solve_ratio,
    transient_path,
    triangular_ratio,
)
from advisor.core.engine import advise
from advisor.core.errors import InfeasibleError
from advisor.core.reading import parse_requirements
from catalogs import load_catalogs
from rules.motion import INERTIA_BAND

# motor A of seed 003's example on its load: 5 kg·m², 100 N·m
A = Drive(150.0, 0.01, 20.0, 5.0, 100.0)


def _example(**positioning) -> dict:
    data = tomllib.loads((EXAMPLES / "positioning_drive.toml").read_text(encoding="utf-8"))
    data["positioning"].update(positioning)
    return data


def test_a_long_move_is_trapezoidal_at_the_root_of_eq_6():
    s = solve_ratio(A, 10.0, "trapezoidal")
    assert isinstance(s, RatioSolution)
    assert s.profile == "trapezoidal"
    assert s.ratio == s.exact_ratio == optimal_ratio_trapezoidal(A, 10.0)
    assert s.estimated_ratio == pytest.approx(s.ratio, rel=1e-12)  # the graphical fixed point
    assert s.ratio_i0 == pytest.approx(1181.25 ** (1 / 3))
    assert s.first_step_moves_load and s.first_step > s.ratio
    assert (s.move_time_s, s.profile) == move_time(A, 10.0, s.ratio)


def test_a_short_move_asked_trapezoidal_is_re_optimised_triangular():
    """0.2 rad is shorter than the transients at eq. (6)'s ratio: the triangular law governs,
    and its optimum (the closed form, seed 003's phases) is the ratio."""
    s = solve_ratio(A, 0.2, "trapezoidal")
    assert transient_path(A, s.exact_ratio) > 0.2
    assert s.profile == "triangular"
    assert s.ratio == optimal_ratio_triangular(A, 0.2)
    assert s.ratio == pytest.approx(triangular_ratio(A), rel=1e-6)
    assert s.exact_ratio != s.ratio


def test_listed_motors_are_sized_by_rated_power_only_when_every_one_has_a_rated_torque():
    cat = load_catalogs()
    req = parse_requirements(_example())
    cs = listed_candidates(req)
    assert [c.name for c in cs.candidates] == ["A", "B", "C"]
    assert cs.power_basis.startswith("power at the starting torque")
    assert cs.candidates[0].power_W == 20.0 * 150.0
    assert not any(c.inertia_estimated for c in cs.candidates)
    assert candidates(req, cat) == cs


def test_catalog_candidates_say_which_inertias_are_estimates():
    cat = load_catalogs()
    req = parse_requirements(_example(motors=[], move_time_s=3.0))
    cs = catalog_candidates(req, cat)
    assert isinstance(cs, CandidateSet)
    assert len(cs.candidates) == len(cat.motors)
    estimated = sum(c.inertia_estimated for c in cs.candidates)
    assert estimated == sum("inertia_kgm2" in m.estimated for m in cat.motors)
    assert cs.power_basis == "rated power of the catalog"
    (note,) = cs.warnings
    assert f"{estimated} of them are estimated" in note
    assert f"{INERTIA_BAND * 100:.0f} % higher" in note


WEAK = {"name": "weak", "speed_rad_s": 100, "inertia_kgm2": 0.01, "accel_torque_Nm": 1}


def test_no_usable_motor_is_no_feasible_design():
    req = parse_requirements(_example(motors=[WEAK], load_torque_Nm=1e6))
    with pytest.raises(InfeasibleError, match="no motor can move the load"):
        usable(listed_candidates(req))


def test_a_motor_that_only_balances_the_load_is_left_out_with_a_warning():
    req = parse_requirements(
        _example(
            motors=[
                WEAK,
                {"name": "strong", "speed_rad_s": 100, "inertia_kgm2": 0.01, "accel_torque_Nm": 90},
            ],
            load_torque_Nm=1e6,
        )
    )
    kept, warnings = usable(listed_candidates(req))
    assert [c.name for c in kept] == ["strong"]
    assert warnings == [
        "1 motor(s) left out: each needs a ratio above 500000 only to balance the load torque"
    ]


def test_the_report_rows_and_the_chosen_motor_come_from_one_builder():
    """The chosen motor's move in [design.motion] is its own row of the candidates' table."""
    rep = advise(parse_requirements(_example()))
    m = rep.design.motion
    row = next(c for c in m.candidates if c.name == m.motor)
    for field in (
        "optimal_ratio",
        "estimated_ratio",
        "estimated_ratio_first_step",
        "first_step_moves_load",
        "move_time_s",
    ):
        assert getattr(m, field) == getattr(row, field), field
    assert row.profile == m.profile_actual


def test_candidate_row_and_curve_are_built_from_the_records():
    cat = load_catalogs()
    req = parse_requirements(_example())
    (first, *_), _ = usable(candidates(req, cat))
    s = Solved(first, solve_ratio(first.drive, 10.0, "trapezoidal"))
    row = candidate_out(s)
    assert (row.name, row.speed_rad_s, row.optimal_ratio) == ("A", 150.0, s.solution.ratio)
    curve = curve_out(first.drive, 10.0, s.solution.ratio)
    assert len(curve.ratio) == 61
    assert min(curve.move_time_s) == pytest.approx(s.solution.move_time_s, rel=1e-3)
    assert all(math.isfinite(t) for t in curve.move_time_s)
