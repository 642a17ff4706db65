"""Issue 26, item 1 (screw–nut) and item 5 (service factor) on the linear actuator: thrust
friction, nut wear and heat, whirling speed and buckling by end fixity, the service factor."""

import math
import tomllib

import pytest
from helpers import EXAMPLES

from advisor.calc import screw as sc
from advisor.calc.service_factor import load_classification, service_factor
from advisor.calc.sizing import ScrewMaterial, ThrustFace, evaluate_thread
from advisor.core.engine import advise
from advisor.core.errors import InputError
from advisor.core.reading import parse_requirements, read_requirements
from advisor.core.report import to_toml
from catalogs import load_catalogs

CAT = load_catalogs()
BRONZE = ScrewMaterial(
    friction_coefficient=0.15,
    friction_low=0.15,
    allowable_pressure_Pa=10e6,
    yield_strength_Pa=355e6,
    elastic_modulus_Pa=210e9,
    yield_safety_factor=3.0,
    nut_height_ratio_min=1.2,
    nut_height_ratio_max=2.5,
    nut_max_turns=10,
)


def _evaluate(thread, force, *, thrust=None, sf=1.0, stroke=0.2, time=5.0, span=0.4):
    return evaluate_thread(
        CAT.thread(thread),
        force_N=force,
        stroke_m=stroke,
        travel_time_s=time,
        span_m=span,
        end_fixity="pinned-pinned",
        buckling_safety_factor=3.0,
        starts=1,
        friction_model="standard",
        material=BRONZE,
        thrust=thrust,
        service_factor=sf,
    )


def _report(data: dict) -> dict:
    return tomllib.loads(to_toml(advise(parse_requirements(data))))


def _linear(force=3500.0, stroke=0.2, time=5.0, span=0.4, screw=None, **tables) -> dict:
    return {
        "application": {"kind": "linear"},
        "linear": {
            "force_N": force,
            "stroke_m": stroke,
            "travel_time_s": time,
            "support_span_m": span,
        },
        "motor": {"kind": "induction"},
        "screw": screw or {},
        **tables,
    }


# ------------------------------------------------------------------ thrust friction
def test_bhandari_example_6_6_with_the_thrust_collar():
    """Bhandari, Design of Machine Elements, Ex. 6.6: Tr52×8 single start, W = 2 kN,
    μ = 0.15, collar 60/100 mm, μc = 0.12, 30 rpm → 0.0618 kW and η 12.94 %.

    By hand, in the form that reproduces both figures: Bhandari's trapezoidal thread uses
    μ' = μ/cos θ with θ = 15° (half the 30° flank angle), i.e. this project's "standard"
    tan φ' = f/cos(α/2), and the collar's uniform-wear mean radius R_m = (D_o + D_i)/4:
      d_m = 52 − 4 = 48 mm; tan ψ = 8/(π·48) = 0.053052; μ' = 0.15/cos 15° = 0.155291
      M_thread = 2000·24·(0.155291 + 0.053052)/(1 − 0.155291·0.053052) = 10 083.5 N·mm
      M_collar = 0.12·2000·40 = 9 600 N·mm;  M = 19 683.5 N·mm
      P = 2π·30·19.6835/60 = 61.84 W = 0.0618 kW;  η = 2000·8/(2π·19 683.5) = 12.94 %
    No departure from the published figures. (The paper's f/cos(ψ/2) would not give them.)
    """
    collar = ThrustFace("collar", 0.12, 0.080)
    ev = _evaluate("Tr52x8", 2000.0, thrust=collar)
    assert ev.thread.d2_mm == 48.0
    assert ev.torque_Nm == pytest.approx(10.0835, abs=1e-4)  # the thread alone (issue: 10.08)
    assert ev.thrust_torque_Nm == pytest.approx(9.6, rel=1e-12)
    assert ev.drive_torque_Nm == pytest.approx(19.6835, abs=1e-4)
    power_kW = ev.drive_torque_Nm * 30 * math.pi / 30 / 1e3
    assert round(power_kW, 4) == 0.0618
    eta = sc.thread_efficiency_with_thrust(2000, 0.008, ev.torque_Nm, ev.thrust_torque_Nm)
    assert round(100 * eta, 2) == 12.94
    assert ev.efficiency == pytest.approx(0.2525, abs=1e-4)  # the thread alone (issue: 0.2525)


def test_shigley_example_8_1_thread_and_collar_torques():
    """Shigley, Mechanical Engineering Design, Ex. 8-1: square thread, d = 32 mm, p = 4 mm,
    double start, f = f_c = 0.08, d_c = 40 mm, F = 6.4 kN. By hand (eqs. (8-1), (8-6)):
      d_m = 30 mm, l = 8 mm; T_R = 6400·0.030/2·(8 + π·0.08·30)/(π·30 − 0.08·8)
          = 96·15.540/93.608 = 15.94 N·m;  T_c = 6400·0.08·0.040/2 = 10.24 N·m;
      T = 26.18 N·m; e = 6400·0.008/(2π·26.18) = 0.311.
    (T_R and T_c as printed in the example, recalled; the search found the example's
    statement but not its solution text.) A square thread has no flank angle: φ = atan f.
    """
    psi = sc.lead_angle(0.004, 0.030, 2)
    t_r = sc.torque_from_angles(6400, 0.030, psi, math.atan(0.08))
    t_c = sc.collar_torque(6400, 0.08, 0.040)
    assert round(t_r, 2) == 15.94
    assert t_c == pytest.approx(10.24)
    assert round(t_r + t_c, 2) == 26.18
    assert round(sc.thread_efficiency_with_thrust(6400, 0.008, t_r, t_c), 3) == 0.311


def test_the_collar_torque_enters_the_motor_choice_and_its_checks():
    # Seed 001's load with a collar of d_c = 30 mm, f_c = 0.1: 3500·0.1·0.015 = 5.25 N·m
    # more than the thread's 5.2249 N·m (standard form): 10.4749 N·m, which a 0.75 kW 4A71B4
    # (5.15 N·m) cannot drive; the motor's checks state the sum.
    collar = {"kind": "collar", "mean_diameter_mm": 30, "friction_coefficient": 0.1}
    screw = {"thread": "Tr16x2", "starts": 1, "friction_coefficient": 0.15, "thrust": collar}
    r = _report(_linear(screw=screw))
    s = r["design"]["screw"]
    assert s["thrust"]["torque_Nm"] == pytest.approx(5.25)
    assert s["thrust"]["drive_torque_Nm"] == pytest.approx(5.2249 + 5.25, abs=1e-4)
    rated = next(c for c in r["checks"] if c["id"] == "motor_rated_torque")
    assert rated["value"] == pytest.approx(10.4749, abs=1e-4)
    assert "thrust-face" in rated["name"]
    assert r["design"]["motor"]["rated_torque_Nm"] >= 10.4749
    assert r["design"]["motor"]["required_torque_Nm"] == pytest.approx(10.4749, abs=1e-4)
    assert not any("excludes thrust friction" in w for w in r["warnings"])


def test_without_a_thrust_face_the_report_warns():
    r = read_requirements(EXAMPLES / "linear_screw_actuator.toml")
    warnings = _report(r.model_dump())["warnings"]
    assert any("excludes thrust friction" in w for w in warnings)


def test_a_rolling_thrust_bearing_by_the_skf_model():
    # 7205 BECBP under 3500 N axial at the screw's 1200 rpm: its SKF friction moment, as
    # advisor.calc.bearing_life computes it, adds to the thread torque; C0/P0 is checked.
    thrust = {"kind": "bearing", "bearing": "7205 BECBP"}
    r = _report(_linear(screw={"thread": "Tr16x2", "starts": 1, "thrust": thrust}))
    from advisor.calc.bearing_life import skf_friction

    b = CAT.bearing("7205 BECBP")
    expected = skf_friction(b, CAT.bearing_friction[b.friction], 0.0, 3500, 1200, 68.0).total_Nm
    s = r["design"]["screw"]
    assert expected > 0
    assert s["thrust"]["torque_Nm"] == pytest.approx(expected, rel=1e-5)
    static = next(c for c in r["checks"] if c["id"] == "thrust_bearing_static")
    assert static["limit"] == pytest.approx(b.C0_kN * 1e3)


@pytest.mark.parametrize(
    ("thrust", "words"),
    [
        ({"kind": "collar", "mean_diameter_mm": 30}, "screw.thrust.friction_coefficient"),
        ({"kind": "bearing"}, "screw.thrust.bearing"),
        ({"mean_diameter_mm": 30}, "screw.thrust.mean_diameter_mm is given"),
    ],
)
def test_an_incomplete_thrust_table_is_refused(thrust, words):
    with pytest.raises(InputError) as e:
        parse_requirements(_linear(screw={"thrust": thrust}))
    assert words in " ".join(e.value.messages)


# ------------------------------------------------------------------ nut wear and heat
def test_the_8_kN_drive_of_issue_26_is_caught_by_the_wear_check():
    """Issue 26: 8 kN, 150 mm in 3 s gets Tr18x4 at 943 rpm, its nut sized to 1.005 of a flat
    10 MPa. By hand: d2 = 16 mm, tan ψ = 4/(π·16) → ψ = 4.55°;
    v_s = π·0.016·943/60/cos ψ = 0.7925 m/s = 47.6 m/min ≥ 15 m/min, where Shigley's Table
    8-4 allows 1–1.7 MPa for steel on bronze: 9.95 MPa is ten times that; p·v = 7.9 MPa·m/s.
    """
    r = _report(_linear(8000, 0.15, 3.0, 0.3))
    s, m = r["design"]["screw"], r["design"]["motor"]
    assert s["thread"] == "Tr18x4" and round(m["working_speed_rpm"]) == 943
    nut = s["nut"]
    assert nut["sliding_speed_m_s"] == pytest.approx(
        math.pi * 0.016 * m["working_speed_rpm"] / 60 / math.cos(math.atan(4 / (math.pi * 16))),
        rel=1e-5,
    )
    assert nut["sliding_speed_m_s"] == pytest.approx(0.7925, abs=5e-4)
    assert nut["safe_pressure_MPa"] == 1.0
    assert nut["pv_MPa_m_s"] == pytest.approx(nut["bearing_pressure_MPa"] * 0.7925, rel=1e-3)
    assert any(w.startswith("the nut wears fast") for w in r["warnings"])
    assert any(w.startswith("the nut overheats") for w in r["warnings"])


def test_shigley_table_8_4_bands():
    # steel on bronze: low speed 17.2, ≤ 3 m/min 11.0, 6–12 m/min 5.5, ≥ 15 m/min 1.0 MPa
    assert sc.shigley_bearing_pressure("bronze", 0.005)[0] == 17.2e6
    assert sc.shigley_bearing_pressure("bronze", 2.0 / 60)[0] == 11.0e6
    assert sc.shigley_bearing_pressure("bronze", 10.0 / 60)[0] == 5.5e6
    assert sc.shigley_bearing_pressure("bronze", 20.0 / 60)[0] == 1.0e6
    # cast iron: ≤ 2.4 m/min 12.4, 6–12 m/min 4.1 MPa, nothing above
    assert sc.shigley_bearing_pressure("cast_iron", 2.0 / 60)[0] == 12.4e6
    assert sc.shigley_bearing_pressure("cast_iron", 0.5)[0] == 0.0


def test_nut_temperature_with_a_duty_cycle():
    """Friction power averaged over the cycle. Seed 001's screw (Tr16x2, paper friction,
    f = 0.15), one move of 0.2 m against 3500 N and one back with it, 6 cycles/h.
    By hand: lead 2 mm → 100 turns; against: M = 5.0849 N·m, work 5.0849·2π·100 = 3194.9 J,
    minus F·s = 700 J → 2494.9 J of friction; with: M = F·d2/2·tan(φ − ψ) and the load's
    700 J, both heat: (M·2π·100 + 700) J. Mean power = Σ/600 s; ΔT = P̄/(15·A),
    A = π·24·18 + 2·π/4·(24² − 16²) mm² = 1859.9 mm² (9 turns of 2 mm: an 18 mm nut)."""
    data = _linear(
        screw={
            "thread": "Tr16x2",
            "starts": 1,
            "friction_model": "paper",
            "friction_coefficient": 0.15,
        },
        duty={
            "cycles_per_hour": 6,
            "segments": [
                {"kind": "move", "distance_m": 0.2, "time_s": 5, "direction": "against"},
                {"kind": "move", "distance_m": 0.2, "time_s": 5, "direction": "with"},
            ],
        },
    )
    r = _report(data)
    nut = r["design"]["screw"]["nut"]
    psi = math.atan(0.002 / (math.pi * 0.015))
    phi = math.atan(0.15 / math.cos(psi / 2))
    against = 3500 * 0.0075 * math.tan(psi + phi) * 2 * math.pi * 100 - 700
    with_load = 3500 * 0.0075 * math.tan(phi - psi) * 2 * math.pi * 100 + 700
    mean = (against + with_load) * 6 / 3600
    assert against == pytest.approx(2494.9, abs=0.5)
    assert nut["mean_friction_power_W"] == pytest.approx(mean, rel=1e-5)
    area = math.pi * 24 * 18 + 2 * math.pi / 4 * (24**2 - 16**2)
    assert nut["temperature_rise_K"] == pytest.approx(mean / (15 * area * 1e-6), rel=1e-5)


# ------------------------------------------------------------------ whirling and buckling
@pytest.mark.parametrize(
    ("fixity", "beta_l", "n_cr", "formula", "p_cr"),
    [
        # core d3 = 13.5 mm over 0.4 m, steel E = 210 GPa, ρ = 7850, σ_y = 355 MPa.
        # ω = (βL)²/L²·√(E/ρ)·d3/4 = (βL)²·109.10 rad/s; λ = μL/(d3/4), λ_c = 108.1:
        # fixed-free μ = 2: λ = 237.0 Euler, π²·210000·1630.44/800² = 5280.1 N
        ("fixed-free", 1.87510, 3663.1, "Euler", 5280.1),
        # pinned μ = 1: λ = 118.5 Euler, 21 120.5 N
        ("pinned-pinned", math.pi, 10282.5, "Euler", 21120.5),
        # fixed-pinned μ = 0.7: λ = 82.96 Johnson: 143.14·(355 − (355·82.96/2π)²/210000)
        # = 143.14·250.38 = 35 838 N
        ("fixed-pinned", 3.92660, 16063.2, "Johnson", 35838.0),
        # fixed-fixed μ = 0.5: λ = 59.26 Johnson: 143.14·(355 − 53.39) = 43 173 N
        ("fixed-fixed", 4.73004, 23309.3, "Johnson", 43173.3),
    ],
)
def test_whirling_speed_and_buckling_per_fixity(fixity, beta_l, n_cr, formula, p_cr):
    by_hand = beta_l**2 / 0.4**2 * math.sqrt(210e9 / 7850) * 0.0135 / 4 * 30 / math.pi
    assert by_hand == pytest.approx(n_cr, abs=0.1)
    assert sc.critical_speed_rpm(0.0135, 0.4, fixity, 210e9, 7850) == pytest.approx(n_cr, abs=0.1)
    p, _, how = sc.critical_buckling_load(0.0135, 0.4, fixity, 210e9, 355e6)
    assert how == formula and p == pytest.approx(p_cr, abs=0.1)


def test_the_report_says_why_euler_and_checks_the_whirling_speed():
    r = _report(read_requirements(EXAMPLES / "linear_screw_actuator.toml").model_dump())
    b = r["design"]["screw"]["buckling"]
    assert b["formula"] == "Euler" and "118.5 ≥ the transition" in b["why"]
    whirl = next(c for c in r["checks"] if c["id"] == "critical_speed")
    # 0.8 of 10 282.5 rpm against the motor's working speed
    assert whirl["limit"] == pytest.approx(0.8 * 10282.5, abs=0.1)
    assert whirl["value"] == pytest.approx(r["design"]["motor"]["working_speed_rpm"])


def test_a_long_span_steers_the_choice_away_from_whirling():
    # 2 kN, 1 m in 3 s over 1.2 m, one start: the lightest thread that passes its strength
    # checks and a motor drives would whirl (Tr28x8's 0.8·n_cr = 1286 rpm against the
    # 2500 rpm it needs); the joint choice skips every (thread, motor) whose working speed
    # is above 0.8·n_cr, so the design it gives passes the whirling check.
    r = _report(_linear(2000, 1.0, 3.0, 1.2, screw={"starts": 1}))
    whirl = next(c for c in r["checks"] if c["id"] == "critical_speed")
    assert whirl["passed"] and whirl["value"] <= whirl["limit"]
    assert r["design"]["screw"]["thread"] != "Tr28x8"
    d3 = r["design"]["screw"]["d3_mm"] * 1e-3
    n_cr = math.pi**2 / 1.2**2 * math.sqrt(210e9 / 7850) * d3 / 4 * 30 / math.pi
    assert whirl["limit"] == pytest.approx(0.8 * n_cr, rel=1e-3)


# ------------------------------------------------------------------ service factor
def test_service_factor_multiplies_the_strength_demands():
    # Tr16x2 at 3500 N, f_B = 1.5: the nut is sized for 5250 N: z = 5250/(π·15·1·10) = 11.14
    # → 12 turns > z_max = 10, so the nut check fails; the core stress margin is
    # σ_allow/(1.5·σ): 118.33/(1.5·σ). The check states the factored demand 1.5·σ, so that
    # its margin is limit/value for a reader.
    one = _evaluate("Tr16x2", 3500.0)
    fb = _evaluate("Tr16x2", 3500.0, sf=1.5)
    assert one.nut_turns == 9 and fb.nut_turns == 12
    core1 = next(c for c in one.checks if c.id == "core_stress")
    core = next(c for c in fb.checks if c.id == "core_stress")
    assert core.factor is None and core1.factor is None  # the factor is in the value
    assert core.name == f"{core1.name} × f_B = 1.5"
    assert core.value == pytest.approx(1.5 * core1.value)
    assert core.margin == pytest.approx(core1.margin / 1.5)
    buck = next(c for c in fb.checks if c.id == "buckling")
    assert buck.value == pytest.approx(1.5 * 3500)
    assert buck.margin == pytest.approx(21120.5 / 3 / (1.5 * 3500), rel=1e-5)
    assert {c.id for c in fb.failed} == {"nut_turns"}


def test_service_factor_in_the_report():
    data = _linear(
        screw={"thread": "Tr16x2", "starts": 1, "friction_coefficient": 0.15},
        design={"service_factor": 1.2},
    )
    r = _report(data)
    checks = {c["id"]: c for c in r["checks"]}
    # the strength checks state f_B·demand (buckling: 1.2 × 3500 N) and say so in their
    # names: margin = limit/value as a reader recomputes it
    assert checks["buckling"]["value"] == pytest.approx(1.2 * 3500.0)
    for cid in ("core_stress", "buckling", "nut_pressure"):
        c = checks[cid]
        assert "factor" not in c and c["name"].endswith("× f_B = 1.2")
        assert c["margin"] == pytest.approx(c["limit"] / c["value"], rel=1e-5)
    # thermal and function checks carry no factor
    assert "factor" not in checks["motor_rated_torque"]
    assert r["design"]["screw"]["service_factor"] == 1.2


def test_sew_load_classification_and_the_given_factor():
    # SEW: mass acceleration factor 2.5 is load classification II (its published example,
    # f_B = 1.5 at 16 h/d and 300 cycles/h, is read from the chart by the engineer)
    assert load_classification(2.5) == "II"
    assert load_classification(0.1) == "I" and load_classification(7) == "III"
    with pytest.raises(ValueError):
        load_classification(12)
    assert service_factor(None).value == 1.0
