"""Property tests: any valid linear requirement ends in a design whose every check passes,
or in a clear infeasibility — never in any other exception."""

import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from advisor.core.engine import advise
from advisor.core.errors import InfeasibleError, InputError
from advisor.core.reading import parse_requirements

finite = dict(allow_nan=False, allow_infinity=False)


@st.composite
def linear_requirements(draw):
    stroke = draw(st.floats(0.005, 3.0, **finite))
    screw = {
        "starts": draw(st.integers(1, 4)),
        "friction_model": draw(st.sampled_from(["standard", "paper"])),
        "material_pair": draw(
            st.sampled_from(
                ["steel_bronze", "hardened_steel_bronze", "steel_cast_iron", "steel_steel"]
            )
        ),
        "lubrication": draw(st.sampled_from(["oil", "dry"])),
        "screw_steel": draw(st.sampled_from(["45", "40X"])),
    }
    if draw(st.booleans()):
        screw["friction_coefficient"] = draw(st.floats(0.02, 0.5, **finite))
    return {
        "application": {"kind": "linear", "hold_without_power": draw(st.booleans())},
        "linear": {
            "force_N": draw(st.floats(1.0, 2e6, **finite)),
            "stroke_m": stroke,
            "travel_time_s": draw(st.floats(0.05, 2000.0, **finite)),
            "support_span_m": stroke * draw(st.floats(1.0, 4.0, **finite)),
            "end_fixity": draw(
                st.sampled_from(["pinned-pinned", "fixed-pinned", "fixed-fixed", "fixed-free"])
            ),
            "buckling_safety_factor": draw(st.floats(1.0, 6.0, **finite)),
        },
        "motor": {"kind": "induction", "supply_frequency_Hz": 50},
        "screw": screw,
    }


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(linear_requirements())
def test_design_or_clear_infeasibility(data):
    req = parse_requirements(data)
    try:
        rep = advise(req)
    except InfeasibleError as exc:
        assert exc.summary.startswith("no feasible design")
        assert exc.reasons
        return
    s, m = rep.design.screw, rep.design.motor
    # the chosen thread passes its own checks, and the motor carries the screw
    assert all(c.passed and c.margin >= 1 for c in rep.checks), [
        c for c in rep.checks if not c.passed
    ]
    assert m.rated_torque_Nm >= s.torque_Nm * (1 - 1e-12)
    assert m.travel_time_s <= data["linear"]["travel_time_s"] * (1 + 1e-9)
    assert m.working_speed_rpm >= s.speed_rpm * (1 - 1e-9)
    # dimensions positive and consistent
    assert 0 < s.d3_mm < s.d2_mm < s.nominal_diameter_mm < s.D4_mm
    assert s.nut.height_mm > 0 and s.nut.turns <= 10 + 1e-9
    assert math.isclose(s.revolutions * s.lead_mm / 1e3, data["linear"]["stroke_m"], rel_tol=1e-9)
    if data["application"]["hold_without_power"] and s.self_locking_at_low_friction:
        assert s.self_locking
    assert [c.role for c in m.candidates].count("selected") == 1


@st.composite
def rotary_requirements(draw):
    speeds = draw(
        st.lists(st.floats(500.0, 30000.0, **finite), min_size=1, max_size=4, unique=True)
    )
    req = {
        "application": {"kind": "rotary", "hold_without_power": draw(st.booleans())},
        "rotary": {
            "torque_Nm": draw(st.floats(1.0, 20000.0, **finite)),
            "speed_rpm": draw(st.floats(0.2, 400.0, **finite)),
        },
        "motor": {"kind": "bldc", "candidate_speeds_rpm": speeds},
        "gearbox": {
            "rolling_body": draw(st.sampled_from(["ball", "roller"])),
            "stage_efficiency": draw(st.floats(0.7, 0.98, **finite)),
        },
    }
    env = {}
    if draw(st.booleans()):
        env["max_outer_diameter_mm"] = draw(st.floats(30.0, 600.0, **finite))
    if draw(st.booleans()):
        env["max_length_mm"] = draw(st.floats(20.0, 600.0, **finite))
    if env:
        req["envelope"] = env
    if draw(st.booleans()):
        req["one_way"] = {
            "type": draw(st.sampled_from(["auto", "roller_clutch", "em_clutch"])),
            "rollers": draw(st.integers(3, 12)),
            "priority": draw(st.sampled_from(["mass", "inertia", "power"])),
        }
    return req


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(rotary_requirements())
def test_rotary_design_or_clear_infeasibility(data):
    try:
        req = parse_requirements(data)
    except InputError as exc:  # only the output-faster-than-motor rule may refuse
        assert "is not below the slowest" in str(exc)
        return
    try:
        rep = advise(req)
    except InfeasibleError as exc:
        assert exc.summary.startswith("no feasible design") and exc.reasons
        return
    g, m = rep.design.gearbox, rep.design.motor
    assert all(c.passed for c in rep.checks)
    assert math.prod(s.ratio for s in g.stages) == pytest.approx(g.total_ratio, rel=1e-9)
    assert g.total_ratio == pytest.approx(m.speed_rpm / data["rotary"]["speed_rpm"], rel=1e-9)
    for s in g.stages:
        assert s.inner_diameter_mm > 0 and s.length_mm > 0 and s.mass_kg > 0
        assert s.own_outer_diameter_mm <= s.outer_diameter_mm * (1 + 1e-9)
    env = data.get("envelope", {})
    assert g.outer_diameter_mm <= env.get("max_outer_diameter_mm", math.inf) * (1 + 1e-9)
    assert g.length_mm <= env.get("max_length_mm", math.inf) * (1 + 1e-9)
    # the least lossy speed among those within the frame's loss limit (compared with the
    # rule's reducer at each speed) ...
    best = min((c for c in m.candidates if c.within_loss_limit), key=lambda c: c.losses_W.total)
    assert m.speed_rpm == best.speed_rpm
    # ... and the motor's own figures at the reducer adopted, within the limit
    assert m.torque_Nm == pytest.approx(
        data["rotary"]["torque_Nm"] / (g.total_ratio * g.efficiency), rel=1e-9
    )
    if g.efficiency == pytest.approx(best.gearbox_efficiency, rel=1e-12):
        assert m.losses_W.total == pytest.approx(best.losses_W.total, rel=1e-9)
    assert m.losses_W.total <= m.loss_limit_W * (1 + 1e-9)
    ow = rep.design.one_way
    assert (ow is not None) == data["application"]["hold_without_power"]
    if ow is not None:  # at the motor side, carrying M_out/(q·η); smaller than at the output
        out = data["rotary"]["torque_Nm"]
        assert ow.torque_Nm == pytest.approx(out / (g.total_ratio * g.efficiency), rel=1e-9)
        assert ow.outer_diameter_mm > 0 and ow.mass_kg > 0 and ow.inertia_kgm2 > 0
        if ow.output_side is not None:
            assert ow.output_side.mass_kg >= ow.mass_kg


@st.composite
def positioning_requirements(draw):
    motors = [
        {
            "name": f"M{k}",
            "speed_rad_s": draw(st.floats(10.0, 1000.0, **finite)),
            "inertia_kgm2": draw(st.floats(1e-4, 1.0, **finite)),
            "accel_torque_Nm": draw(st.floats(0.5, 500.0, **finite)),
        }
        for k in range(draw(st.integers(1, 4)))
    ]
    return {
        "application": {"kind": "positioning"},
        "positioning": {
            "profile": draw(st.sampled_from(["trapezoidal", "triangular"])),
            "travel_rad": draw(st.floats(0.01, 1000.0, **finite)),
            "load_inertia_kgm2": draw(st.floats(0.0, 100.0, **finite)),
            "load_torque_Nm": draw(st.floats(0.0, 2000.0, **finite)),
            "motors": motors,
        },
    }


@settings(max_examples=100, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(positioning_requirements())
def test_positioning_fastest_motor_at_its_best_ratio(data):
    from advisor.calc import motion as mo

    try:
        req = parse_requirements(data)
    except InputError as exc:
        assert "are both 0" in str(exc) or "must be 0 or from" in str(exc)
        return
    rep = advise(req)
    m = rep.design.motion
    assert all(c.passed for c in rep.checks)
    times = {c.name: c.move_time_s for c in m.candidates}
    assert m.move_time_s == min(times.values()) and times[m.motor] == m.move_time_s
    assert m.optimal_ratio > m.torque_ratio
    # no ratio of the tabulated curve is faster than the chosen one
    assert min(m.curve.move_time_s) >= m.move_time_s * (1 - 1e-6)
    # the time reported is the one of the profile that happens
    pos = data["positioning"]
    c = next(x for x in pos["motors"] if x["name"] == m.motor)
    d = mo.Drive(
        c["speed_rad_s"],
        c["inertia_kgm2"],
        c["accel_torque_Nm"],
        pos["load_inertia_kgm2"],
        pos["load_torque_Nm"],
    )
    t, prof = mo.move_time(d, pos["travel_rad"], m.optimal_ratio)
    assert prof == m.profile_actual and t == pytest.approx(m.move_time_s, rel=1e-5)


def _log_uniform(lo: float, hi: float):
    """A value anywhere in [lo, hi] on a log scale, the edges drawn often."""
    inner = st.floats(math.log10(lo), math.log10(hi), **finite).map(
        lambda e: min(max(10.0**e, lo), hi)
    )
    return st.one_of(st.sampled_from([lo, hi]), inner)


@st.composite
def positioning_across_ranges(draw):
    """Every numeric field drawn across its whole documented range
    (advisor/applications/positioning/requirements.py), edges included; the loads are 0 as
    often as not."""
    motors = [
        {
            "name": f"M{k}",
            "speed_rad_s": draw(_log_uniform(0.1, 1e4)),
            "inertia_kgm2": draw(_log_uniform(1e-9, 1e3)),
            "accel_torque_Nm": draw(_log_uniform(1e-5, 1e6)),
        }
        for k in range(draw(st.integers(1, 3)))
    ]
    inertia = draw(st.one_of(st.just(0.0), _log_uniform(1e-9, 1e7)))
    torque = draw(st.one_of(st.just(0.0), _log_uniform(1e-6, 1e7)))
    if inertia == 0.0 and torque == 0.0:
        torque = 1e-6
    return {
        "application": {"kind": "positioning"},
        "positioning": {
            "profile": draw(st.sampled_from(["trapezoidal", "triangular"])),
            "travel_rad": draw(_log_uniform(1e-4, 1e5)),
            "load_inertia_kgm2": inertia,
            "load_torque_Nm": torque,
            "motors": motors,
        },
    }


def _finite_numbers(node, where=""):
    if isinstance(node, dict):
        for k, v in node.items():
            _finite_numbers(v, f"{where}.{k}")
    elif isinstance(node, list):
        for k, v in enumerate(node):
            _finite_numbers(v, f"{where}[{k}]")
    elif isinstance(node, float):
        assert math.isfinite(node), where


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(positioning_across_ranges())
def test_positioning_whole_ranges_end_in_a_finite_report_or_exit_3(data):
    """Issue 13: no crash, no nan or inf anywhere in the report, over every documented range."""
    import tomllib

    from advisor.core.report import to_toml

    req = parse_requirements(data)
    try:
        rep = advise(req)
    except InfeasibleError as exc:
        assert "no motor can move the load" in str(exc)
        return
    _finite_numbers(tomllib.loads(to_toml(rep)))
    m = rep.design.motion
    assert m.estimated_ratio > m.torque_ratio  # the fixed point (or closed form) moves the load
    assert m.first_step_moves_load == (m.estimated_ratio_first_step > m.torque_ratio)


@st.composite
def rotor_requirements(draw):
    from catalogs import load_catalogs

    names = [b.designation for b in load_catalogs().bearings]
    bearing = draw(st.sampled_from(names))
    rotor = {
        "mass_kg": draw(st.floats(0.05, 20.0, **finite)),
        "speed_rad_s": draw(st.floats(50.0, 8000.0, **finite)),
        "bearing": bearing,
        "bearing_count": draw(st.integers(2, 4)),
        "ball_plane_to_cg_mm": draw(st.floats(1.0, 200.0, **finite)),
        # 0 (no slew) or from 1e-6 rad/s (the model's range)
        "slew_rate_rad_s": draw(st.just(0.0) | st.floats(1e-6, 5.0, **finite)),
        "axis_angle_deg": draw(st.floats(0.0, 180.0, **finite)),
        "slew_angle_deg": draw(st.floats(1.0, 360.0, **finite)),
        "run_up_time_s": draw(st.floats(0.5, 600.0, **finite)),
        "rolling_friction_mm": draw(st.floats(0.005, 0.1, **finite)),
        "lubricant_viscosity_mm2_s": draw(st.floats(2.0, 200.0, **finite)),
    }
    if bearing[0] == "6":
        rotor["contact_angle_deg"] = draw(st.floats(5.0, 25.0, **finite))
    if draw(st.booleans()):
        rotor["inertia_kgm2"] = draw(st.floats(1e-6, 0.1, **finite))
    else:
        rotor["angular_momentum_kgm2_s"] = draw(st.floats(1e-3, 100.0, **finite))
    if draw(st.booleans()):
        rotor["aero"] = {"loss_W": draw(st.floats(0.0, 500.0, **finite))}
    else:
        ro_mm = draw(st.floats(5.0, 100.0, **finite))
        rotor["aero"] = {
            "outer_radius_mm": ro_mm,
            "outer_length_mm": draw(st.floats(0.0, 100.0, **finite)),
            "inner_radius_mm": ro_mm * draw(st.floats(0.0, 0.95, **finite)),
            "inner_length_mm": draw(st.floats(0.0, 100.0, **finite)),
        }
    return {"application": {"kind": "spinning_rotor"}, "rotor": rotor}


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(rotor_requirements())
def test_rotor_design_meets_its_run_up_time_and_holds_speed(data):
    req = parse_requirements(data)
    try:
        rep = advise(req)
    except InfeasibleError as exc:
        assert "limiting speed" in str(exc) or "static safety" in str(exc)
        return
    r = rep.design.rotor
    assert all(c.passed for c in rep.checks)
    assert r.run_up_time_s <= data["rotor"]["run_up_time_s"] * (1 + 1e-6)
    assert r.required_torque_Nm >= r.steady_torque_Nm.with_reaction * (1 - 1e-9)
    assert r.steady_torque_Nm.with_reaction >= r.steady_torque_Nm.without_reaction
    assert r.bearing_friction_Nm.with_reaction >= r.bearing_friction_Nm.without_reaction
    assert r.bearing_life_h > 0 and r.preload_N > 0
    assert r.run_up.speed_rad_s[-1] == pytest.approx(r.speed_rad_s, rel=1e-6)
    assert all(
        b >= a - 1e-9 * r.speed_rad_s
        for a, b in zip(r.run_up.speed_rad_s, r.run_up.speed_rad_s[1:], strict=False)
    )
    # the design's drive holds at least the resistance with the reaction: a slew costs nothing
    assert r.slew.speed_drop_pct == 0.0 and r.slew.balance_speed_rad_s == r.speed_rad_s
    assert 0 <= r.slew_if_sized_without_reaction.balance_speed_rad_s <= r.speed_rad_s


def test_self_locking_is_judged_by_the_standard_friction_under_the_paper_model():
    """Hypothesis found it: Tr60x9 with two starts (ψ = atan(18/(π·55.5)) = 5.89°) at
    f = 0.1016 self-locks by the standard reduced friction, atan(0.1016/cos 15°) = 6.00°, but
    not by the paper's f/cos(ψ/2), atan(0.1017) = 5.81°. Holding is physics: the report's
    `self_locking` agrees with the holding rule's standard judgement."""
    data = {
        "application": {"kind": "linear", "hold_without_power": True},
        "linear": {"force_N": 1.0, "stroke_m": 1.0, "travel_time_s": 2.0, "support_span_m": 1.0},
        "motor": {"kind": "induction", "supply_frequency_Hz": 50},
        "screw": {"starts": 2, "friction_model": "paper", "friction_coefficient": 0.1015625},
    }
    try:
        rep = advise(parse_requirements(data))
    except InfeasibleError:
        return
    s = rep.design.screw
    if s.self_locking_at_low_friction:
        assert s.self_locking
