"""The linear screw's rolling thrust bearing: its basic rating life (ISO 281:2007, eq. (1)),
reported in the thrust table beside the static check, at the screw's mean speed."""

import tomllib

import pytest

from advisor.core.engine import advise
from advisor.core.reading import parse_requirements
from advisor.core.report import to_toml

# SKF 7205 BECBP (catalogs/skf_bearings.toml): single-row angular contact, 40°,
# C = 15.6 kN. ISO 281:2007 table 3, α = 40°, F_a/F_r > e = 1.14: X = 0.35, Y = 0.57.
C_N = 15600.0
Y_40 = 0.57


def _thrust(force_N=5000.0, service_factor=None, duty=None, thrust=None, stop_N=None) -> dict:
    data = {
        "application": {"kind": "linear"},
        "linear": {
            "force_N": force_N,
            "stroke_m": 0.3,
            "travel_time_s": 10,
            "support_span_m": 0.5,
        },
        "motor": {"kind": "induction"},
        "screw": {"thrust": thrust or {"kind": "bearing", "bearing": "7205 BECBP"}},
    }
    if stop_N:
        data["linear"]["emergency_stop_force_N"] = stop_N
    if service_factor:
        data["design"] = {"service_factor": service_factor}
    if duty:
        data["duty"] = duty
    return tomllib.loads(to_toml(advise(parse_requirements(data))))["design"]


def test_l10_under_the_factored_force_at_the_working_speed_without_a_duty():
    """5 kN × f_B 1.25 on the 7205 BECBP (a 12 kN stop), no [duty]: continuous running (as the
    nut heat).
    P = Y·F_a = 0.57·1.25·5000 = 3562.5 N; L10 = (15600/3562.5)³ = 4.3789³ = 83.967·10⁶ rev;
    L10h = 10⁶·L10/(60·n) at the motor's working speed n ≈ 718 rpm → 83.967e6/43 077 ≈ 1949 h.
    """
    d = _thrust(service_factor=1.25, stop_N=12000.0)
    t, n_work = d["screw"]["thrust"], d["motor"]["working_speed_rpm"]
    p = Y_40 * 1.25 * 5000.0
    l10 = (C_N / p) ** 3
    assert p == pytest.approx(3562.5)
    assert l10 == pytest.approx(83.967, rel=1e-4)
    assert t["equivalent_load_N"] == pytest.approx(p, rel=1e-5)
    assert t["life_L10_Mrev"] == pytest.approx(l10, rel=1e-5)
    assert t["life_speed_rpm"] == pytest.approx(n_work, rel=1e-5)
    assert n_work == pytest.approx(718, abs=1)
    assert t["life_L10_h"] == pytest.approx(1e6 * l10 / (60 * n_work), rel=1e-5)
    assert t["life_L10_h"] == pytest.approx(1949, abs=1)
    assert "continuous running" in t["life_basis"] and "0.57" in t["life_basis"]


def test_l10h_at_the_mean_speed_of_the_duty_segments():
    """3500 N, f_B 1: P = 0.57·3500 = 1995 N; L10 = (15600/1995)³ = 478.12·10⁶ rev. The
    screw's lead is read from the report; the cycle moves 0.3 m out and back: 2·0.3/lead
    revolutions × 6 cycles/h → n̄ = that/60 rpm; L10h = 10⁶·L10/(60·n̄)."""
    duty = {
        "cycles_per_hour": 6,
        "segments": [
            {"kind": "move", "distance_m": 0.3, "time_s": 10, "direction": "against"},
            {"kind": "move", "distance_m": 0.3, "time_s": 10, "direction": "with"},
        ],
    }
    d = _thrust(force_N=3500.0, duty=duty)
    t = d["screw"]["thrust"]
    lead_m = d["screw"]["lead_mm"] * 1e-3
    mean_rpm = 2 * 0.3 / lead_m * 6 / 60
    l10 = (C_N / (Y_40 * 3500.0)) ** 3
    assert l10 == pytest.approx(478.12, rel=1e-4)
    assert t["life_speed_rpm"] == pytest.approx(mean_rpm, rel=1e-5)
    assert t["life_L10_h"] == pytest.approx(1e6 * l10 / (60 * mean_rpm), rel=1e-5)
    assert "cycles/h" in t["life_basis"]


def test_l10h_of_an_iec_duty_type_at_its_running_share():
    """S3 with cdf 0.4: the screw turns 40 % of the time at the working speed, so
    n̄ = 0.4·n and L10h = 10⁶·L10/(60·0.4·n), 2.5× the continuous one."""
    d = _thrust(duty={"duty_type": "S3", "cyclic_duration_factor": 0.4})
    t, n_work = d["screw"]["thrust"], d["motor"]["working_speed_rpm"]
    l10 = (C_N / (Y_40 * 5000.0)) ** 3
    assert t["life_speed_rpm"] == pytest.approx(0.4 * n_work, rel=1e-5)
    assert t["life_L10_h"] == pytest.approx(1e6 * l10 / (60 * 0.4 * n_work), rel=1e-5)


def test_a_collar_has_no_rating_life():
    thrust = {"kind": "collar", "mean_diameter_mm": 30, "friction_coefficient": 0.1}
    t = _thrust(thrust=thrust)["screw"]["thrust"]
    assert t["kind"] == "collar"
    assert not {"life_L10_Mrev", "life_L10_h", "equivalent_load_N"} & set(t)
