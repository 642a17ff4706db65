"""Where the linear and positioning features meet the holding device, the duty cycle and the
service factor (the audit of features meeting): every expected number is worked by hand here,
with its formula, inputs and source."""

import copy
import math
import tomllib

import pytest

from advisor.calc import one_way as ow
from advisor.core.engine import advise
from advisor.core.errors import InfeasibleError
from advisor.core.reading import parse_requirements
from advisor.core.report import to_toml

# Tr20x4, 4 starts (seed 001, GOST 24738-81): d2 = d − 0.5·P = 18 mm, lead L = 16 mm,
# tan ψ = L/(π·d2); f = 0.1, φ' = atan(f/cos 15°) (the standard model, α = 30°)
D2_M, LEAD_M, SPAN_M = 0.018, 0.016, 0.5
PSI = math.atan(LEAD_M / (math.pi * D2_M))
PHI = math.atan(0.1 / math.cos(math.radians(15.0)))
SCREW_TORQUE_NM = 1500.0 * D2_M / 2.0 * math.tan(PSI + PHI)  # M = F·d2/2·tan(ψ + φ') = 5.37478
SCREW_ETA = math.tan(PSI) / math.tan(PSI + PHI)  # η = tan ψ/tan(ψ + φ') = 0.7107
# the screw as a steel rod of d2 over the span, ρ·π·d2⁴/32·l = 4.045e-5 kg·m²
J_SCREW = 7850.0 * math.pi * D2_M**4 / 32.0 * SPAN_M
# 100 kg through the lead at the motor, m·(L/2π)²/η = 9.124e-4 kg·m²
J_NUT = 100.0 * (LEAD_M / (2.0 * math.pi)) ** 2 / SCREW_ETA
# seed 004's self-locking worm: f = 0.1, γ = φ/2: η = tan γ/tan(γ + φ) = 0.33112
WORM_ETA = math.tan(math.atan(0.1) / 2) / math.tan(1.5 * math.atan(0.1))


def report(doc: dict) -> dict:
    return tomllib.loads(to_toml(advise(parse_requirements(copy.deepcopy(doc)))))


def linear_doc(device: str | None, duty: dict | None) -> dict:
    """The audit's lind_*.toml: Tr20x4 with 4 starts (lead 16 mm, not self-locking at
    f = 0.1), 1500 N, 0.3 m in 3 s, a 0.5 m span."""
    doc = {
        "application": {"kind": "linear", "title": "features meet"},
        "linear": {
            "force_N": 1500.0,
            "stroke_m": 0.3,
            "travel_time_s": 3.0,
            "support_span_m": SPAN_M,
        },
        "motor": {"kind": "induction"},
        "screw": {"thread": "Tr20x4", "starts": 4, "friction_coefficient": 0.1},
    }
    if device is not None:
        doc["application"]["hold_without_power"] = True
        doc["one_way"] = {"type": device}
    if duty is not None:
        doc["duty"] = duty
    return doc


SEGMENTS_DUTY = {
    "cycles_per_hour": 20,
    "moving_mass_kg": 100.0,
    "segments": [
        {"kind": "move", "distance_m": 0.3, "time_s": 8.0, "direction": "against"},
        {"kind": "hold", "time_s": 60.0},
        {"kind": "move", "distance_m": 0.3, "time_s": 8.0, "direction": "with"},
        {"kind": "dwell", "time_s": 60.0},
    ],
}


def _phase(rep: dict, name: str) -> dict:
    return next(p for p in rep["design"]["duty"]["phases"] if p["name"] == name)


# ------------------------------------------------------------------ the device's inertia
def test_the_worm_inertia_counts_in_the_linear_cycle():
    """lind_worm.toml: the coast of move 1 is J·ω/M_L with J the whole motor side, the screw
    side reflected through the worm as its torque is (J_L/η_worm, as the rotary's /η_d):
    J = 0.013 (4A100L8) + 1.59855e-4 (worm, seed 004 sized at the screw torque 5.37478 N·m)
    + (4.045e-5 (screw) + 9.124e-4 (nut))/0.33112 = 0.0160375 kg·m² (0.014113 without
    the /η_worm); M_L = M/η_worm = 16.2321 N·m."""
    rep = report(linear_doc("worm", SEGMENTS_DUTY))
    duty, device = rep["design"]["duty"], rep["design"]["one_way"]
    assert duty["motor"] == "4A100L8"
    j_worm = ow.worm(SCREW_TORQUE_NM).inertia_kgm2
    assert j_worm == pytest.approx(1.59855e-4, rel=1e-5)
    assert device["inertia_kgm2"] == pytest.approx(j_worm, rel=1e-5)
    j_total = 0.013 + j_worm + (J_SCREW + J_NUT) / WORM_ETA
    assert j_total == pytest.approx(0.0160375, rel=1e-4)
    load = SCREW_TORQUE_NM / WORM_ETA
    assert load == pytest.approx(16.2321, rel=1e-5)
    coast = _phase(rep, "1 move: coast")
    w = coast["speed_start_rpm"] * math.pi / 30.0
    assert coast["time_s"] == pytest.approx(j_total * w / load, rel=1e-5)  # was 0.0648973 s
    # the inertia ratio: the load at the motor over the motor side, J_L/(J_M + J_d) = 0.07241
    ratio = (J_SCREW + J_NUT) / (0.013 + j_worm)
    assert duty["inertia_ratio"] == pytest.approx(ratio, rel=1e-5)  # was 0.0733002
    # FI = (J_M + J_d + J_L/η_worm)/J_M (IEC 60034-1, 3.18)
    assert duty["inertia_factor"] == pytest.approx(j_total / 0.013, rel=1e-5)


@pytest.mark.parametrize("device", ["em_clutch", "roller_clutch"])
def test_clutches_of_different_inertia_give_different_inertia_ratios(device):
    """lind_em_clutch / lind_roller_clutch: 4A80B2 (J_M = 0.002 kg·m²); the em clutch
    (1.50555e-4 kg·m²) is 8× the roller clutch (1.85823e-5): J_L/(J_M + J_d) = 0.44310 and
    0.47206, both printed 0.476451 = J_L/J_M before."""
    rep = report(linear_doc(device, SEGMENTS_DUTY))
    j_dev = ow.size(device, SCREW_TORQUE_NM).inertia_kgm2
    by_hand = {"em_clutch": 1.50555e-4, "roller_clutch": 1.85823e-5}[device]
    assert j_dev == pytest.approx(by_hand, rel=1e-5)
    ratio = (J_SCREW + J_NUT) / (0.002 + j_dev)
    assert ratio == pytest.approx({"em_clutch": 0.44310, "roller_clutch": 0.47206}[device], 1e-4)
    assert rep["design"]["duty"]["inertia_ratio"] == pytest.approx(ratio, rel=1e-5)


@pytest.mark.parametrize("device", ["em_clutch", "roller_clutch"])
def test_the_device_inertia_counts_in_an_iec_start(device):
    """linS4_*: an S4 start lasts t = J·ω/(M_m − M_L) (Chilikin, ch. 2) with J the motor
    side, device included: the em clutch and the roller clutch give different start times."""
    duty = {
        "duty_type": "S4",
        "cyclic_duration_factor": 0.4,
        "starts_per_hour": 60,
        "moving_mass_kg": 100.0,
    }
    rep = report(linear_doc(device, duty))
    d = rep["design"]["duty"]
    j_m = rep["design"]["motor"]["inertia_kgm2"]
    j_total = j_m + J_SCREW + J_NUT + ow.size(device, SCREW_TORQUE_NM).inertia_kgm2
    start, run = _phase(rep, "start"), _phase(rep, "run")
    w = run["speed_rpm"] * math.pi / 30.0
    # a clutch passes the screw torque with η = 1: M_L = 5.37478 N·m
    expected = j_total * w / (d["mean_starting_torque_Nm"] - SCREW_TORQUE_NM)
    assert start["time_s"] == pytest.approx(expected, rel=1e-5)


# ------------------------------------------------------------------ the device's power share
def test_em_clutch_power_share_is_over_the_motor_mechanical_power():
    """lind_em_clutch: 2.16021 W of the clutch over the motor's M·ω at the working point,
    5.37478 N·m × 909.9 rpm = 512 W: 0.00422 (was 2.16021/211.07 W = 0.0102 at the screw's
    required 375 rpm). report.md: the share of the motor's mechanical power."""
    rep = report(linear_doc("em_clutch", SEGMENTS_DUTY))
    device, motor = rep["design"]["one_way"], rep["design"]["motor"]
    assert device["power_W"] == pytest.approx(2.16021, rel=1e-5)
    w = motor["working_speed_rpm"] * math.pi / 30.0
    assert motor["working_speed_rpm"] == pytest.approx(909.9, abs=0.1)
    share = 2.16021 / (SCREW_TORQUE_NM * w)
    assert share == pytest.approx(0.00422, abs=5e-6)
    assert device["power_share"] == pytest.approx(share, rel=1e-4)
    assert motor["working_power_kW"] * 1e3 == pytest.approx(SCREW_TORQUE_NM * w, rel=1e-5)


# ------------------------------------------------------------------ the matrix
IEC_DUTIES = {
    "S1": {"duty_type": "S1", "cycle_time_s": 600.0},
    "S2": {"duty_type": "S2", "duration_min": 30.0},
    "S3": {"duty_type": "S3", "cyclic_duration_factor": 0.4, "cycle_time_s": 600.0},
    "S4": {"duty_type": "S4", "cyclic_duration_factor": 0.4, "starts_per_hour": 60},
    "S5": {"duty_type": "S5", "cyclic_duration_factor": 0.4, "starts_per_hour": 60},
}


@pytest.mark.parametrize(
    "device", [None, "auto", "roller_clutch", "em_clutch", "worm", "inverse_gear"]
)
@pytest.mark.parametrize("duty", [None, "segments", *IEC_DUTIES])
def test_every_device_and_duty_gives_the_inertia_ratio_by_hand(device, duty):
    """Every holding device × no duty, a cycle of moves and the IEC types: a report or a
    refusal with reasons, never a traceback; where there is a duty, the inertia ratio is
    J_L/(J_M + J_d) with J_L = screw + m·(L/2π)²/η and J_d the reported device's."""
    spec = None
    if duty == "segments":
        spec = SEGMENTS_DUTY
    elif duty is not None:
        spec = {**IEC_DUTIES[duty], "moving_mass_kg": 100.0}
    try:
        rep = report(linear_doc(device, spec))
    except InfeasibleError as e:
        assert e.reasons
        return
    design = rep["design"]
    if spec is None:
        assert "duty" not in design
        return
    j_dev = design["one_way"]["inertia_kgm2"] if device is not None else 0.0
    ratio = (J_SCREW + J_NUT) / (design["motor"]["inertia_kgm2"] + j_dev)
    assert design["duty"]["inertia_ratio"] == pytest.approx(ratio, rel=1e-5)


# ------------------------------------------------------------------ the service factor
def test_a_check_under_the_service_factor_states_the_factored_load():
    """examples/linear_screw_jack_collar.toml, f_B = 1.25, Tr26x3 (d2 = 24.5, d3 = 22.5,
    H1 = 1.5 mm, 10 nut turns), 5000 N, fixed-free over 0.5 m, E = 2.1e5 MPa, S_b = 3.
    A reader recomputes margin = limit/value: the value is f_B·load."""
    from helpers import EXAMPLES

    doc = tomllib.loads((EXAMPLES / "linear_screw_jack_collar.toml").read_text("utf-8"))
    rep = report(doc)
    checks = {c["id"]: c for c in rep["checks"]}
    f_b, force, d3 = 1.25, 5000.0, 0.0225
    # buckling (Euler, fixed-free, μ = 2): P_cr/S_b = π²·E·I/(2L)²/3 = 8691.56 N
    limit = math.pi**2 * 2.1e11 * (math.pi * d3**4 / 64.0) / (2.0 * 0.5) ** 2 / 3.0
    c = checks["buckling"]
    assert c["value"] == pytest.approx(f_b * force) == 6250.0  # was 5000
    assert c["limit"] == pytest.approx(limit, rel=1e-5)
    assert c["margin"] == pytest.approx(limit / 6250.0, rel=1e-5) == pytest.approx(1.39065, 1e-5)
    assert "× f_B = 1.25" in c["name"]
    assert "factor" not in c  # the factor is in the value: margin = limit/value
    # core stress: von Mises of F/(π·d3²/4) and T/(π·d3³/16), T the thread torque 10.6868 N·m
    sigma = force / (math.pi * d3**2 / 4.0)
    tau = 10.6868 / (math.pi * d3**3 / 16.0)
    core_MPa = math.hypot(sigma, math.sqrt(3.0) * tau) / 1e6  # 15.0543
    c = checks["core_stress"]
    assert c["value"] == pytest.approx(f_b * core_MPa, rel=1e-5)  # 18.8179, was 15.0543
    assert c["margin"] == pytest.approx(c["limit"] / c["value"], rel=1e-5)
    assert c["margin"] == pytest.approx(118.333 / (1.25 * 15.0543), rel=1e-4)  # 6.28836
    # nut flank pressure p = F/(π·d2·H1·z) = 4.3307 MPa, ×1.25 = 5.4134 against 10 MPa
    pressure_MPa = force / (math.pi * 24.5 * 1.5 * 10.0)
    c = checks["nut_pressure"]
    assert c["value"] == pytest.approx(f_b * pressure_MPa, rel=1e-5)
    assert c["margin"] == pytest.approx(10.0 / (f_b * pressure_MPa), rel=1e-5)  # 1.84726
    # the datasheet: the checks table and the required-and-achieved rows agree, and the
    # service factor names the checks it enters
    from advisor.datasheet import render

    md = render(advise(parse_requirements(copy.deepcopy(doc))), "md")
    assert "no check covers this requirement" not in next(
        line for line in md.splitlines() if line.startswith("| Service factor")
    )
    assert "| 6250 against 8692 N | 1.391 |" in md
    assert "× f\\_B = 1.25 | 6250 | 8692 | N | 1.391 |" in md


def test_the_thrust_bearing_check_states_the_factored_load():
    """A thrust bearing under f_B = 1.5: 7204 BECBP (40° angular contact, C0 = 8.15 kN)
    under the axial 1500 N alone: P0 = max(F_r, 0.5·F_r + 0.26·F_a) = 390 N (ISO 76), stated
    as f_B·P0 = 585 N; margin C0/value = 8150/585 = 13.932."""
    doc = linear_doc(None, None)
    doc["screw"]["thrust"] = {"kind": "bearing", "bearing": "7204 BECBP"}
    doc["design"] = {"service_factor": 1.5}
    try:
        rep = report(doc)
    except InfeasibleError as e:
        pytest.skip(f"no design: {e}")
    c = next(x for x in rep["checks"] if x["id"] == "thrust_bearing_static")
    assert c["value"] == pytest.approx(1.5 * 0.26 * 1500.0, rel=1e-6)  # was 390 N
    assert c["margin"] == pytest.approx(8150.0 / 585.0, rel=1e-5)
    assert c["name"].endswith("× f_B = 1.5")


# ------------------------------------------------------------------ positioning with a duty
def test_positioning_ratio_check_is_at_the_ratio_the_cycle_builds():
    """examples/indexing_table_duty.toml: the cycle builds motor C (M_λ = 45 N·m) at
    i = 7.34461 (design.duty.ratio, MO-06); the load torque 100 N·m only balances at
    m = M_p/M_λ = 100/45 = 2.22222 (seed 003, eq. (3)): margin i/m = 3.3051, not the
    2.98044 of the fastest ratio without the cycle (6.6232)."""
    from helpers import EXAMPLES

    doc = tomllib.loads((EXAMPLES / "indexing_table_duty.toml").read_text("utf-8"))
    rep = report(doc)
    duty = rep["design"]["duty"]
    assert duty["motor"] == "C"
    assert duty["ratio"] == pytest.approx(7.34461, rel=1e-5)
    c = next(x for x in rep["checks"] if x["id"] == "ratio_moves_load")
    m = 100.0 / 45.0
    assert c["value"] == pytest.approx(duty["ratio"], rel=1e-6)
    assert c["limit"] == pytest.approx(m, rel=1e-5)
    assert c["margin"] == pytest.approx(7.34461 / m, rel=1e-5) == pytest.approx(3.3051, 1e-4)
    assert "6.6232" in c["source"]  # the fastest ratio without the cycle, named


@pytest.mark.parametrize("with_duty", [False, True])
@pytest.mark.parametrize("example", ["positioning_drive.toml", "indexing_table_duty.toml"])
def test_positioning_with_and_without_a_duty_states_its_built_ratio(example, with_duty):
    """Positioning with and without a [duty]: the ratio check is at the ratio the design
    states (design.duty.ratio with a cycle, design.motion.optimal_ratio without), margin i/m,
    and the inertia ratio is J_L/(i²·J0) of the motor at that ratio (seed 003)."""
    from helpers import EXAMPLES

    doc = tomllib.loads((EXAMPLES / example).read_text("utf-8"))
    doc.pop("duty", None)
    if with_duty:
        doc["duty"] = {"cycle_time_s": 4.0}
        for m in doc["positioning"].get("motors", []):  # a cycle needs the S1 torque
            m.setdefault("rated_torque_Nm", m["accel_torque_Nm"] / 2.0)
    try:
        rep = report(doc)
    except InfeasibleError as e:
        assert e.reasons
        return
    design, pos = rep["design"], doc["positioning"]
    motion = design["motion"]
    motor = design["duty"]["motor"] if with_duty else motion["motor"]
    i = design["duty"]["ratio"] if with_duty else motion["optimal_ratio"]
    row = next(m for m in pos.get("motors", []) if m["name"] == motor) if "motors" in pos else None
    c = next((x for x in rep["checks"] if x["id"] == "ratio_moves_load"), None)
    if row is None or c is None:
        return
    m = pos["load_torque_Nm"] / row["accel_torque_Nm"]
    assert c["value"] == pytest.approx(i, rel=1e-5)
    assert c["margin"] == pytest.approx(i / m, rel=1e-5)
    if with_duty:
        j_ratio = pos["load_inertia_kgm2"] / (i**2 * row["inertia_kgm2"])
        assert design["duty"]["inertia_ratio"] == pytest.approx(j_ratio, rel=1e-5)


# ------------------------------------------------------------------ a device the screw makes unused
def test_a_requested_device_left_out_by_a_self_locking_screw_is_said():
    """Tr16x2, one start: tan ψ = 2/(π·15) → ψ = 2.43°; at the low end of steel–bronze's
    friction range f = 0.1, φ' = atan(0.1/cos 15°) = 5.91° > ψ: the screw holds by itself
    (OW-03), so the requested worm is not used, and the report says so in one line."""
    psi = math.degrees(math.atan(2.0 / (math.pi * 15.0)))
    phi_low = math.degrees(math.atan(0.1 / math.cos(math.radians(15.0))))
    assert psi == pytest.approx(2.43, abs=0.01) and phi_low == pytest.approx(5.91, abs=0.01)
    doc = linear_doc("worm", None)
    doc["linear"].update(force_N=3500.0, stroke_m=0.2, travel_time_s=5.0, support_span_m=0.4)
    doc["screw"] = {"thread": "Tr16x2", "starts": 1, "friction_coefficient": 0.15}
    rep = report(doc)
    assert rep["design"]["one_way"]["type"] == "none"
    said = [w for w in rep["warnings"] if w.startswith("ignored: the [one_way] table")]
    assert len(said) == 1 and "'worm'" in said[0] and "Tr16x2 is self-locking" in said[0]
    doc.pop("one_way")  # no table given: nothing to say
    assert not [w for w in report(doc)["warnings"] if "[one_way]" in w]
