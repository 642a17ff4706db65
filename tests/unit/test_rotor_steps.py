"""The spinning-rotor advice's steps and records (seed 002): the loads, steady torques and
slew loss of calc agree with the term-by-term resistance, and the report is built from them."""

import math

import pytest
from helpers import EXAMPLES

from advisor.applications.spinning_rotor.steps import (
    RPM,
    bearing_rating,
    chosen_bearing,
    rotor_model,
    run_up,
    slew_duration,
)
from advisor.calc.rotor import (
    gyroscopic_loads,
    gyroscopic_moment,
    resisting_torque,
    run_up_time,
    slew_loss,
    steady_torques,
)
from advisor.core.engine import advise
from advisor.core.reading import read_requirements
from advisor.core.rulebook import Trace
from catalogs import load_catalogs

GYRO = EXAMPLES / "gyro_compensator.toml"


@pytest.fixture(scope="module")
def steps():
    req, cat = read_requirements(GYRO), load_catalogs()
    r = req.rotor
    b, angle = chosen_bearing(req, cat)
    rotor = rotor_model(req, b, angle)
    moment = gyroscopic_moment(
        r.angular_momentum, r.slew_rate_rad_s, math.radians(r.axis_angle_deg)
    )
    loads = gyroscopic_loads(rotor, moment, r.speed_rad_s)
    return req, cat, b, angle, rotor, loads


def test_the_model_is_the_seeds_rotor(steps):
    _, _, b, angle, rotor, loads = steps
    assert (b.designation, angle) == ("7000 CD", 15.0)
    assert rotor.bearings == 2
    assert rotor.weight_share_N == pytest.approx(0.56 * 9.80665 / 2)
    assert rotor.plane_to_cg_m == pytest.approx(0.010)
    assert loads.moment_Nm == pytest.approx(0.1388, rel=1e-3)


def test_preload_is_the_axial_load_less_the_reaction(steps):
    *_, loads = steps
    assert loads.preload_N == loads.slewing.axial_N - loads.reaction_axial_N
    assert loads.calm.radial_N < loads.slewing.radial_N
    assert loads.friction_calm.total_Nm < loads.friction_slewing.total_Nm


def test_steady_torques_are_the_resistance_of_eq_5_at_speed(steps):
    """With the moment of the slew at speed, J·ω·Ω·sin α = H·Ω·sin α, the steady torques
    equal the term-by-term resistance of the motion equation."""
    req, _, _, _, rotor, loads = steps
    w = req.rotor.speed_rad_s
    s = steady_torques(rotor, loads, w)
    assert s.calm_Nm == pytest.approx(resisting_torque(rotor, w, False), rel=1e-12)
    assert s.slewing_Nm == pytest.approx(resisting_torque(rotor, w, True), rel=1e-9)
    assert s.aero_Nm * w == pytest.approx(32.15)  # the seed's aerodynamic loss


def test_run_up_record_and_its_decision(steps):
    req, _, _, _, rotor, loads = steps
    w = req.rotor.speed_rad_s
    trace = Trace()
    ru = run_up(req, rotor, steady_torques(rotor, loads, w), trace)
    assert [d.id for d in trace.decisions] == ["RO-02"]
    assert ru.required_torque_Nm >= ru.run_up_torque_Nm
    assert ru.time_s == run_up_time(rotor, ru.required_torque_Nm, w) <= req.rotor.run_up_time_s
    assert ru.curve_time_s[-1] == pytest.approx(ru.time_s)
    assert ru.curve_speed_rad_s[-1] == w


def test_slew_loss_record(steps):
    req, _, _, _, rotor, loads = steps
    w = req.rotor.speed_rad_s
    calm = steady_torques(rotor, loads, w).calm_Nm
    duration = slew_duration(req)
    assert duration == pytest.approx(math.radians(9) / 0.0765)
    s = slew_loss(rotor, calm, w, duration)
    assert s.balance_speed_rad_s < s.speed_after_rad_s < w
    assert s.time_s[0] == 0.0 and s.speed_rad_s[0] == w


def test_the_report_is_built_from_the_records(steps):
    req, cat, b, _, _, loads = steps
    rating = bearing_rating(req, cat, b, loads)
    out = advise(req).design.rotor
    assert out.preload_N == loads.preload_N
    assert out.bearing_friction_Nm.with_reaction == loads.friction_slewing.total_Nm
    assert out.bearing_life_h == rating.life_h
    assert out.bearing.static_safety == rating.static_safety
    assert out.skf_friction_Nm.without_reaction == rating.skf_calm.total_Nm
    assert out.speed_rpm == req.rotor.speed_rad_s * RPM


@pytest.mark.parametrize(("count", "per_side"), [(2, 1), (3, 1), (4, 2), (6, 3), (8, 4)])
def test_more_bearings_share_the_pairs_reaction(count, per_side):
    """Seed 002's eq. (3) is each support's reaction; n bearings stand n/2 a side (⌊n/2⌋ on the
    smaller side of an odd count), and a side's bearings share its force.

    By hand for the example (M = H·Ω·sin α = 1.814·0.0765·1 = 0.138771 N·m, r = 6.6 mm,
    h = 10 mm, ωt = 0): r² + h² = 4.356e-5 + 1e-4 = 1.4356e-4 m²,
    F_ax = M·r/(r² + h²) = 0.138771·0.0066/1.4356e-4 = 6.37983 N,
    F_rad = M·h/(r² + h²) = 0.138771·0.010/1.4356e-4 = 9.66641 N per support; per bearing
    F/⌊n/2⌋. The weight 0.56·9.80665 = 5.49172 N is shared n ways."""
    import tomllib

    from advisor.core.reading import parse_requirements

    data = tomllib.loads(GYRO.read_text(encoding="utf-8"))
    data["rotor"]["bearing_count"] = count
    req = parse_requirements(data)
    cat = load_catalogs()
    b, angle = chosen_bearing(req, cat)
    rotor = rotor_model(req, b, angle)
    loads = gyroscopic_loads(rotor, 1.814 * 0.0765, req.rotor.speed_rad_s)
    assert loads.moment_Nm == pytest.approx(0.138771)  # the rotor's moment, not a share
    assert loads.reaction_axial_N == pytest.approx(6.37983 / per_side, rel=1e-5)
    assert loads.reaction_radial_N == pytest.approx(9.66641 / per_side, rel=1e-5)
    assert loads.slewing.radial_N == pytest.approx(5.49172 / count + 9.66641 / per_side, rel=1e-5)
    # the motion equation's resistance uses the same loads: n bearings' friction + drag
    w = req.rotor.speed_rad_s
    s = steady_torques(rotor, loads, w)
    assert s.slewing_Nm == pytest.approx(resisting_torque(rotor, w, True), rel=1e-9)
    assert s.slewing_Nm == pytest.approx(
        count * loads.friction_slewing.total_Nm + s.aero_Nm, rel=1e-12
    )


@pytest.mark.parametrize("mass_kg", [0.3, 0.4, 0.5, 0.56, 0.7, 1.0, 2.0])
def test_without_a_slew_the_steady_torque_never_reaches_speed(mass_kg):
    """With Ω = 0 the moment is M = H·Ω·sin α = 0, so the steady torque with the reaction is
    the resistance at speed, M_steady = M_res(ω): J·dω/dt = M_steady − M_res(ω') → 0 as ω' → ω
    and t = ∫₀^ω J dω'/(M_steady − M_res(ω')) diverges (like ln, the integrand ≈ J/(slope·(ω −
    ω')) at the top). The key is absent, whatever way the two routes to M_res round (the
    term-by-term sum and the polynomial differed by ±1e-18 N·m and gave 4244 s for some
    masses)."""
    import tomllib

    from advisor.core.reading import parse_requirements

    data = tomllib.loads(GYRO.read_text(encoding="utf-8"))
    data["rotor"].update(slew_rate_rad_s=0.0, mass_kg=mass_kg)
    req = parse_requirements(data)
    out = advise(req).design.rotor
    assert out.steady_torque_Nm.with_reaction == out.steady_torque_Nm.without_reaction
    assert out.run_up_time_at_steady_torque_s is None
    # the slowest slew the requirements take still gives a finite (long) time: a real excess
    data["rotor"]["slew_rate_rad_s"] = 1e-6
    slow = advise(parse_requirements(data)).design.rotor
    assert slow.steady_torque_Nm.with_reaction > slow.steady_torque_Nm.without_reaction
    assert math.isfinite(slow.run_up_time_at_steady_torque_s)


def test_the_slew_plots_name_each_drive_torque():
    """Both plots of a sustained slew (datasheet and wizard) draw the design's drive, held at
    4453 rad/s (0.06563 N·m > 0.01935 N·m, the resistance with the reaction at speed), and a
    drive limited to the steady torque without the reaction, 49.15 W / 4453 rad/s =
    0.01104 N·m, which settles at 2784 rad/s; each line is named with its torque."""
    from advisor.applications.spinning_rotor import plots, views
    from advisor.core.report import plain

    report = advise(read_requirements(GYRO))
    sheet = plots.slew(plain(report))
    labels = [line.label for line in sheet.lines]
    assert labels == ["design drive, 0.06563 N·m", "drive sized without the reaction, 0.01104 N·m"]
    assert set(sheet.lines[0].y) == {4453.0}
    assert sheet.lines[0].x[-1] == sheet.lines[1].x[-1]
    wizard = views.slew_plot(report.design.rotor)
    assert [name for name, _, _ in wizard.series] == [
        "design drive, 0.06563 N·m",
        "sized without reaction, 0.01104 N·m",
    ]


def test_each_bearing_of_a_pair_answers_the_whole_moment(steps):
    """Seed 002's eq. (3) is one contact answering the whole moment (fig. 1, "a rotor in a
    bearing"): the resultant F = √(F_ax² + F_rad²) = M/R at the lever R = √(r² + h²). Its
    example loads each bearing of the pair with it; the advisor keeps that reading (a pair
    carries 2·M, conservative against equilibrium with one bearing a side, M/(2R) each).
    By hand: R = √(6.6² + 10²) mm = 11.9817 mm, F = 0.138771/0.0119817 = 11.5819 N, and
    √(9.66641² + 6.37983²) = 11.5819 N; F·R = 0.138771 N·m = M, on each of the two."""
    *_, loads = steps
    resultant = math.hypot(loads.reaction_radial_N, loads.reaction_axial_N)
    assert resultant == pytest.approx(11.5819, rel=1e-5)
    assert resultant * math.hypot(0.0066, 0.010) == pytest.approx(loads.moment_Nm, rel=1e-12)


def test_a_rotor_family_row_has_the_drive_torque_and_the_life():
    """designs.csv of a rotor family: the drive torque that sizes the drive, 0.06563 N·m for
    the example (RO-02: the 30 s run-up, above the 86.15 W / 4453 rad/s = 0.01935 N·m that
    holds speed), and one bearing's L10h = 10⁶/(60·42523)·(4427/22.56)³ = 2.97e6 h (ISO 281,
    P = 0.44·12.41 + 1.47·11.63 = 22.56 N), beside the steady power 86.15 W."""
    from advisor.core.report import plain
    from advisor.family.outputs import key_outputs

    row = key_outputs(plain(advise(read_requirements(GYRO))))
    assert row["required_torque_Nm"] == pytest.approx(0.06563, rel=1e-4)
    assert row["bearing_life_h"] == pytest.approx(2.97e6, rel=2e-3)
    assert row["losses_W"] == pytest.approx(86.15, rel=1e-4)


def test_the_life_is_each_bearings_and_the_sets_is_beside_it():
    """The life check is one bearing's L10h (every bearing of the rotor at the same loads);
    the set of n fails when its first bearing does: L_set = (Σ L_i^(−e))^(−1/e) = L·n^(−1/e),
    e = 10/9 for ball bearings (SKF, system life). The example's pair: 2965960 h ×
    2^(−0.9) = 2965960 × 0.535887 = 1589420 h."""
    data = _gyro_data()
    data["rotor"]["required_life_h"] = 1000
    from advisor.core.reading import parse_requirements

    report = advise(parse_requirements(data))
    r = report.design.rotor
    assert r.bearing_set_life_h == pytest.approx(r.bearing_life_h * 0.535887, rel=1e-6)
    assert r.bearing_set_life_h == pytest.approx(1589420, rel=1e-5)
    (life,) = [c for c in report.checks if c.id == "bearing_life"]
    assert "of each bearing" in life.name and life.value == r.bearing_life_h


def _gyro_data() -> dict:
    import tomllib

    return tomllib.loads(GYRO.read_text(encoding="utf-8"))
