"""Duty-cycle verdicts a reviewer checked by hand: the winding's peak rise decides a cycle long
against its time constant, a load share above 1 loads the screw, keys said "ignored" are not
used, and the heat of an electric stop is counted once."""

import math
import tomllib

import pytest
from helpers import EXAMPLES

from advisor.core.engine import advise
from advisor.core.errors import InfeasibleError
from advisor.core.reading import parse_requirements

#: seed 000's frame at 5000 rpm: copper 68.97 W at its 2 N·m, iron + magnets 159.45 W, limit
#: 228.42 W; R = 105 K / 228.42 W maps the limit onto class F's rise
COPPER_W, CORE_W, LIMIT_W = 68.97, 159.45, 228.42
R_K_W = 105.0 / LIMIT_W


def _rotary_s9(tau_s: float) -> dict:
    doc = tomllib.loads((EXAMPLES / "rudder_actuator_duty.toml").read_text(encoding="utf-8"))
    doc["duty"] = {
        "load_inertia_kgm2": 2.0,
        "motor_inertia_kgm2": 0.00015,
        "thermal_time_constant_s": tau_s,
        "duty_type": "S9",
        "cycle_time_s": 6000.0,
        "loads": [
            {"load_share": 1.2, "time_share": 0.3},
            {"load_share": 0.5, "time_share": 0.7},
        ],
    }
    return doc


def test_a_cycle_long_against_tau_is_refused_on_the_windings_peak_rise():
    # load 1: 1.2 × 2 N·m at the motor for 1800 s = 30 τ: P = 68.97·1.2² + 159.45 = 258.77 W,
    # the winding settles at P·R = 258.77·105/228.42 = 118.95 K > 105 K (class F); the mean
    # losses 0.3·258.77 + 0.7·(68.97·0.25 + 159.45) = 201.3 W pass the 228.42 W limit
    p1 = COPPER_W * 1.2**2 + CORE_W
    assert p1 * R_K_W == pytest.approx(118.95, abs=0.01)
    with pytest.raises(InfeasibleError) as e:
        advise(parse_requirements(_rotary_s9(60.0)))
    assert any(
        "5000 rpm: within a cycle the winding peaks at 118.9 K" in r for r in e.value.reasons
    )


def test_the_peak_rise_is_a_check_with_the_losses_allowance():
    # τ = 6000 s: periodic steady state of two phases, ΔT₀ = B/(1 − A) with A = e^(−6000/τ),
    # B = (P1·R·(1 − a1))·a2 + P2·R·(1 − a2), a1 = e^(−1800/τ), a2 = e^(−4200/τ); the peak is
    # at the end of load 1: ΔT₀·a1 + P1·R·(1 − a1)
    tau = 6000.0
    p1, p2 = COPPER_W * 1.2**2 + CORE_W, COPPER_W * 0.5**2 + CORE_W
    a1, a2 = math.exp(-1800.0 / tau), math.exp(-4200.0 / tau)
    b = p1 * R_K_W * (1 - a1) * a2 + p2 * R_K_W * (1 - a2)
    start = b / (1 - a1 * a2)
    hand = start * a1 + p1 * R_K_W * (1 - a1)  # 96.69 K: passes
    r = advise(parse_requirements(_rotary_s9(tau)))
    check = next(c for c in r.checks if c.id == "duty_peak_rise")
    assert check.value == pytest.approx(hand, rel=1e-3)
    assert check.limit == pytest.approx(105.0 * 1.001)
    assert r.design.duty.thermal.peak_rise_K == pytest.approx(hand, rel=1e-3)


def test_the_thermal_history_reaches_the_settled_cycle():
    # rudder_actuator_duty with τ = 1e5 s: steady rise 17.647 K (its losses 38.39 W × R). The
    # history runs ⌈5τ/t_c⌉ = 50000 cycles of 10 s from cold, so it ends within e^(−5) = 0.7 %
    # of the settled rise, 17.647·(1 − e^(−5)) = 17.528 K (it stopped at 2000 cycles, 3.2 K)
    doc = tomllib.loads((EXAMPLES / "rudder_actuator_duty.toml").read_text(encoding="utf-8"))
    doc["duty"]["thermal_time_constant_s"] = 1e5
    th = advise(parse_requirements(doc)).design.duty.thermal
    assert th.steady_rise_K == pytest.approx(17.647, abs=1e-3)
    assert th.time_s[-1] == pytest.approx(5e5, rel=1e-9)
    assert th.rise_K[-1] >= 17.647 * (1 - math.exp(-5.0)) - 1e-3
    assert len(th.time_s) <= 1000  # thinned


def test_a_long_history_keeps_its_clock_and_its_cost_with_the_points_kept():
    # 10⁶ cycles of (100 W, 1 s), (0 W, 1 s), R = 0.5 K/W, τ = 4e5 s: the last point is at
    # 2e6 s, and the cycle starts from cold at B·(1 − A^c)/(1 − A) ≈ 25 K·(1 − e^(−5)) there
    from advisor.calc.duty import thermal_history

    hist = thermal_history([(100.0, 1.0), (0.0, 1.0)], 0.5, 4e5, 1_000_000, max_points=400)
    assert len(hist) <= 402
    assert hist[-1][0] == pytest.approx(2e6, rel=1e-12)
    assert hist[-1][1] == pytest.approx(25.0 * (1 - math.exp(-5.0)), rel=1e-4)


def _linear(**duty) -> dict:
    doc = tomllib.loads((EXAMPLES / "valve_actuator_duty.toml").read_text(encoding="utf-8"))
    doc["duty"] = duty
    return doc


def test_a_linear_load_share_above_one_is_refused_as_a_segment_force_above_rating_is():
    # valve example, Tr16x2 at 3500 N: nut flank pressure 8.25248 MPa (p = F/(π·d2·H1·z),
    # linear in F). An S9 share of 1.5 loads the screw with 5250 N: p = 8.25248 × 1.5 =
    # 12.379 MPa > [p] = 10 MPa, which the checks at 3500 N passed (margin 1.212)
    from advisor.core.errors import InputError

    r = advise(parse_requirements(_linear(duty_type="S3", cyclic_duration_factor=0.4)))
    nut = next(c for c in r.checks if c.id == "nut_pressure")
    assert nut.value == pytest.approx(8.25248, rel=1e-5)
    assert nut.value * 1.5 == pytest.approx(12.379, abs=1e-3) and nut.value * 1.5 > nut.limit
    loads = [{"load_share": 1.5, "time_share": 0.1}, {"load_share": 0.5, "time_share": 0.9}]
    with pytest.raises(InputError, match=r"load_share = 1\.5: loads the screw with 5250 N"):
        advise(parse_requirements(_linear(duty_type="S9", loads=loads)))


@pytest.mark.parametrize("duty_type", ["S3", "S6"])
def test_s3_and_s6_starts_are_ignored_as_said(duty_type):
    # IEC 60034-1: in S3 and S6 starting does not significantly affect the temperature; the
    # key is said ignored, so 30000 starts/h (above the 6334 the 4A71B4 allows by z = z0·(1 −
    # u²)/(FI·k_L)) neither enters a check nor refuses the design
    r = advise(
        parse_requirements(
            _linear(duty_type=duty_type, cyclic_duration_factor=0.25, starts_per_hour=30000.0)
        )
    )
    assert any(w.startswith("ignored: duty.starts_per_hour") for w in r.warnings)
    assert not any(c.id == "duty_starts_per_hour" for c in r.checks)
    assert r.design.duty.starts_per_hour == 0.0
    assert r.design.duty.allowed_starts_per_hour is None


def _nut_heat_doc(**duty) -> dict:
    """The valve example's screw, Tr16x2 at 3500 N, under a duty type."""
    doc = tomllib.loads((EXAMPLES / "valve_actuator_duty.toml").read_text(encoding="utf-8"))
    doc["linear"]["force_N"] = 3500.0
    doc["screw"]["thread"] = "Tr16x2"
    doc["duty"] = duty
    return doc


def _nut_heat_words(duty: dict) -> str:
    r = advise(parse_requirements(_nut_heat_doc(**duty)))
    return next(w for w in r.warnings if w.startswith("the nut overheats"))


@pytest.mark.parametrize(
    "duty",
    [
        {"duty_type": "S7", "starts_per_hour": 60.0},
        {"duty_type": "S2", "duration_min": 30.0},
    ],
)
def test_the_nut_heat_takes_the_running_share_of_the_duty_type_not_an_ignored_cdf(duty):
    # S7 runs throughout (start, load, electric stop, no rest: IEC 60034-1 4.2.7), S2 for its
    # whole run: mean thread friction = P·1 (579 W here), not P·cdf = 579 × 0.2 = 116 W from
    # a cdf the report says it ignores
    without = _nut_heat_words(duty)
    with_cdf = _nut_heat_words({**duty, "cyclic_duration_factor": 0.2})
    assert "running share 1)" in with_cdf
    assert with_cdf == without


def test_an_electric_stop_is_counted_once_by_the_starts_not_again_in_the_rms():
    # valve example screw (Tr16x2, 3500 N), S5 at cdf 0.4, 600 starts/h, 4A71B4 (Klyuchev §11,
    # β0 = 0.5): start 0.0476126 s and electric stop 0.014231 s both at zero torque (β 0.75),
    # run 2.33816 s at 5.08485 N·m, rest 3.6 s (β 0.5):
    # M_eq = √(5.08485²·2.33816/(0.75·(0.0476126 + 0.014231) + 2.33816 + 0.5·3.6)) = 3.80095
    # z = z0·(1 − u²)/(FI·k_L·(1 + k_b)) = 22797.3·(1 − (3.80095/5.1525)²)/(1.01115·2.17285·2)
    #   = 2364.8 /h (the stop's −M_m in the RMS counted its heat again: 3.84044, 2305.8)
    m_eq = math.sqrt(5.08485**2 * 2.33816 / (0.75 * (0.0476126 + 0.014231) + 2.33816 + 1.8))
    assert m_eq == pytest.approx(3.80095, abs=2e-5)
    z = 22797.3 * (1 - (m_eq / 5.1525) ** 2) / (1.01115 * 2.17285 * 2)
    doc = _nut_heat_doc(duty_type="S5", cyclic_duration_factor=0.4, starts_per_hour=600.0)
    duty = advise(parse_requirements(doc)).design.duty
    assert duty.rms_torque_Nm == pytest.approx(m_eq, rel=1e-5)
    assert duty.allowed_starts_per_hour == pytest.approx(z, rel=1e-4)


def _rotary_iec(**duty) -> dict:
    doc = tomllib.loads((EXAMPLES / "rudder_actuator_duty.toml").read_text(encoding="utf-8"))
    keep = ("load_inertia_kgm2", "motor_inertia_kgm2", "thermal_time_constant_s")
    doc["duty"] = {k: doc["duty"][k] for k in keep} | duty
    return doc


@pytest.mark.parametrize("minutes", [2.0, 30.0])
def test_a_rotary_s2_run_lasts_its_duration_and_does_not_repeat(minutes):
    # S2 (IEC 60034-1): one run of duration_min from cold: a run of 60·minutes s, no cycles per
    # hour (it was a 600 s run 6 times an hour whatever the duration); checked as S1, so the
    # losses are the rated point's whatever the duration
    r = advise(parse_requirements(_rotary_iec(duty_type="S2", duration_min=minutes)))
    d = r.design.duty
    assert [(p.name, p.time_s) for p in d.phases] == [("run", pytest.approx(60.0 * minutes))]
    assert d.cycles_per_hour is None
    assert not any(w.startswith("ignored") for w in r.warnings)
    r = advise(parse_requirements(_rotary_iec(duty_type="S2", duration_min=2, cycle_time_s=60)))
    assert "ignored: duty.cycle_time_s, because duty_type = 'S2' does not use it" in r.warnings


def test_a_rotary_s2_thermal_history_is_its_one_run_from_cold():
    # S2 for 2 min, τ = 900 s, at the rated point: P = 68.97 + 159.45 = 228.42 W, the frame's
    # limit, so the steady rise is P·R = 105 K. One run from cold rises
    # ΔT(t) = ΔT_ss·(1 − e^(−t/τ)): 105·(1 − e^(−120/900)) = 13.107 K at its end, the peak
    # stated (the history drew 38 runs back to back to 104.3 K at 4560 s, continuous running).
    # The verdict stays S1's: the check holds the run's losses until the rise settles, 105 K.
    doc = _rotary_iec(duty_type="S2", duration_min=2)
    doc["duty"]["thermal_time_constant_s"] = 900.0
    r = advise(parse_requirements(doc))
    th = r.design.duty.thermal
    assert th.steady_rise_K == pytest.approx(105.0, rel=1e-3)
    assert th.time_s[0] == 0.0 and th.time_s[-1] == pytest.approx(120.0, rel=1e-12)
    assert len(th.time_s) > 100  # a curve, not the line of two points
    for t, rise in zip(th.time_s, th.rise_K, strict=True):
        assert rise == pytest.approx(th.steady_rise_K * -math.expm1(-t / 900.0), rel=1e-9)
    assert th.peak_rise_K == pytest.approx(105.0 * (1 - math.exp(-120 / 900)), rel=1e-3)
    assert th.peak_rise_K == pytest.approx(13.107, abs=0.02)
    check = next(c for c in r.checks if c.id == "duty_peak_rise")
    assert check.value == pytest.approx(th.steady_rise_K, rel=1e-12)
    assert "S2 run held as S1" in check.name


def test_s1_reports_no_cycles_per_hour():
    # S1 runs continuously: the default cycle_time_s of 600 s is no cycle (it said 6 an hour)
    assert (
        advise(parse_requirements(_rotary_iec(duty_type="S1"))).design.duty.cycles_per_hour is None
    )
    linear = advise(parse_requirements(_nut_heat_doc(duty_type="S1")))
    assert linear.design.duty.cycles_per_hour is None


def test_a_positioning_rated_torque_without_a_duty_is_said_ignored():
    # the rated (S1) torque is held only against a duty cycle's RMS torque: without [duty]
    # it checks nothing, and the report says so rather than drop it silently
    doc = tomllib.loads((EXAMPLES / "indexing_table_duty.toml").read_text(encoding="utf-8"))
    del doc["duty"]
    r = advise(parse_requirements(doc))
    said = [w for w in r.warnings if w.startswith("ignored: positioning.motors[].rated_torque_Nm")]
    assert said and "(A, B, C)" in said[0]
    r = advise(
        parse_requirements(
            tomllib.loads((EXAMPLES / "indexing_table_duty.toml").read_text(encoding="utf-8"))
        )
    )
    assert not any("rated_torque_Nm" in w for w in r.warnings)


def test_each_rotary_refusal_line_names_its_speed():
    # S4, cdf 0.001 at 600 starts/h: 6 s cycles, 0.006 s under load; the 5000 rpm start takes
    # t_a = J·ω/(M_peak − M_run) = 0.02 s, longer: its line names its speed as the others do
    doc = _rotary_iec(duty_type="S4", cyclic_duration_factor=0.001, starts_per_hour=600.0)
    with pytest.raises(InfeasibleError) as e:
        advise(parse_requirements(doc))
    assert any(r.startswith("5000 rpm: S4: starting at the peak torque") for r in e.value.reasons)


def test_the_s6_idle_run_is_at_the_no_load_speed():
    # S6 cdf 0.4 of 600 s, 4A71B4 (1500 rpm synchronous): loaded at 1392.47 rpm for 240 s, the
    # idle run at slip 0, 1500 rpm, for 360 s: mean speed 0.4·1392.47 + 0.6·1500 = 1456.99 rpm
    d = advise(
        parse_requirements(_nut_heat_doc(duty_type="S6", cyclic_duration_factor=0.4))
    ).design.duty
    idle = next(p for p in d.phases if p.name == "no load")
    assert idle.speed_rpm == pytest.approx(1500.0)
    assert d.mean_speed_rpm == pytest.approx(0.4 * 1392.47 + 0.6 * 1500.0, rel=1e-5)
    assert d.rms_torque_Nm == pytest.approx(5.08485 * math.sqrt(0.4), rel=1e-5)  # 3.21594
