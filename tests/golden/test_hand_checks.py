"""Fresh cases, one per application, recomputed by hand from the seed equations (the
arithmetic is written out in each test) and compared with the report to 1e-4.

These are not the papers' worked examples: they check that the advisor applies the
equations the same way away from the published points."""

import math

import pytest

from advisor.core.engine import advise
from advisor.core.reading import parse_requirements

REL = 1e-4


def _design(data: dict) -> dict:
    return advise(parse_requirements(data)).as_dict()


def test_linear_7kN_0_3m_in_6s_by_hand():
    rep = _design(
        {
            "application": {"kind": "linear", "hold_without_power": False, "title": "hand"},
            "linear": {
                "force_N": 7000,
                "stroke_m": 0.3,
                "travel_time_s": 6,
                "support_span_m": 0.5,
            },
            "motor": {"kind": "induction", "supply_frequency_Hz": 50},
            "screw": {"friction_coefficient": 0.1},
        }
    )
    s = rep["design"]["screw"]
    assert s["thread"] == "Tr20x4"
    # GOST 24737-81, Tr20x4: d2 = d − P/2 = 18, H1 = P/2 = 2, ac = 0.25, d3 = d − 2·(H1 + ac) = 15.5
    assert (s["d2_mm"], s["H1_mm"], s["d3_mm"]) == (18.0, 2.0, 15.5)
    # N = l/P = 300/4 = 75 rev; n = 60·N/t = 60·75/6 = 750 rpm (seed 001)
    assert s["revolutions"] == pytest.approx(75.0, rel=REL)
    assert s["speed_rpm"] == pytest.approx(750.0, rel=REL)
    # tan ψ = P/(π·d2) = 4/(π·18) = 0.0707355 → ψ = 4.04611°
    # tan φ' = f/cos 15° = 0.1/0.9659258 = 0.1035276 → φ' = 5.91064°
    # M = F·d2/2·tan(ψ + φ') = 7000·0.009·tan 9.95675° = 63·0.175550 = 11.0597 N·m (eq. (1))
    assert s["lead_angle_deg"] == pytest.approx(4.04611, rel=REL)
    assert s["friction_angle_deg"] == pytest.approx(5.91064, rel=REL)
    assert s["torque_Nm"] == pytest.approx(11.0597, rel=REL)
    # η = tan ψ / tan(ψ + φ') = 0.0707355/0.175550 = 0.402937
    assert s["efficiency"] == pytest.approx(0.402937, rel=REL)
    # nut: z = 7 turns; p = F/(π·d2·H1·z) = 7000/(π·18·2·7) = 7000/791.681 = 8.84194 MPa
    assert s["nut"]["turns"] == 7
    assert s["nut"]["bearing_pressure_MPa"] == pytest.approx(8.84194, rel=REL)
    # Euler, pinned-pinned: I = π·d3⁴/64 = π·57720.06/64 = 2833.27 mm⁴;
    # P_cr = π²·E·I/L² = 9.869604·2.1e5·2833.27/500² = 23489.6 N; allowed P_cr/3 = 7829.87 N
    assert s["buckling"]["critical_load_N"] == pytest.approx(23489.6, rel=REL)
    # core: σ = 4F/(π·d3²) = 28000/754.768 = 37.0975 MPa; τ = 16·M/(π·d3³) = 176955/11698.9
    # = 15.1259 MPa; von Mises √(σ² + 3τ²) = √(1376.22 + 686.37) = 45.4157 MPa
    core = next(c for c in rep["checks"] if c["id"] == "core_stress")
    assert core["value"] == pytest.approx(45.4157, rel=REL)
    # the motor turns the screw at its working speed: 75 rev at 923.363 rpm = 4.87349 s
    m = rep["design"]["motor"]
    assert m["travel_time_s"] == pytest.approx(75 * 60 / m["working_speed_rpm"], rel=REL)
    # power at the screw's speed: 11.0597·750·π/30 = 868.62 W
    assert m["required_power_kW"] == pytest.approx(0.86862, rel=REL)


def test_rotary_300Nm_8rpm_at_4000rpm_by_hand():
    rep = _design(
        {
            "application": {"kind": "rotary", "hold_without_power": False, "title": "hand"},
            "rotary": {"torque_Nm": 300, "speed_rpm": 8},
            "motor": {"kind": "bldc", "candidate_speeds_rpm": [4000]},
            "gearbox": {"rolling_body": "ball", "stage_efficiency": 0.9},
        }
    )
    g, mot = rep["design"]["gearbox"], rep["design"]["motor"]
    # q_Σ = 4000/8 = 500 = 20 (output) × 25 (input); η = 0.9² = 0.81
    assert g["total_ratio"] == pytest.approx(500.0)
    out = next(s for s in g["stages"] if s["position"] == "output")
    inp = next(s for s in g["stages"] if s["position"] == "input")
    assert (out["ratio"], out["rows"], inp["ratio"], inp["rows"]) == (20.0, 3, 25.0, 2)
    # output stage, eq. (16): d = ∛(241·300/(3·19)·sin(π/19)) = ∛(1268.421·0.1645946)
    # = ∛208.7752 = 5.93234 mm
    assert out["rolling_body_diameter_mm"] == pytest.approx(5.93234, rel=REL)
    # eq. (13): D = (2.06/sin(π/20) + 1.8)·d = (13.16855 + 1.8)·5.93234 = 88.7980 mm
    # eq. (14): d_in = (13.16855 − 4.4)·5.93234 = 52.0180 mm; eq. (15): L = (1.2·3 + 1.8)·d = 32.0346
    assert out["outer_diameter_mm"] == pytest.approx(88.7980, rel=REL)
    assert out["inner_diameter_mm"] == pytest.approx(52.0180, rel=REL)
    assert out["length_mm"] == pytest.approx(32.0346, rel=REL)
    # input stage carries 300/(20·0.9) = 16.6667 N·m:
    # d = ∛(241·16.6667/(2·24)·sin(π/24)) = ∛(83.68056·0.1305262) = ∛10.92250 = 2.21875 mm
    assert inp["torque_Nm"] == pytest.approx(16.6667, rel=REL)
    assert inp["rolling_body_diameter_mm"] == pytest.approx(2.21875, rel=REL)
    # equal-diameter layout: L_in = L_out·∛(1/20) = 32.0346·0.3684031 = 11.8017 mm
    assert inp["length_mm"] == pytest.approx(11.8017, rel=REL)
    # eq. (19): m = ρ·k·π/4·(D² − d_in²)·ΣL = 7800·0.75·π/4·(7885.09 − 2705.87)·43.8363e-9
    # = 7800·0.75·0.7853982·5179.22·43.8363e-9 = 1.04314 kg
    assert g["mass_kg"] == pytest.approx(1.04314, rel=REL)
    # motor torque 300/(500·0.81) = 0.740741 N·m; f = 4000·6/60 = 400 Hz
    assert mot["torque_Nm"] == pytest.approx(0.740741, rel=REL)
    assert mot["electrical_frequency_Hz"] == pytest.approx(400.0)
    # ohmic at a given torque does not depend on the winding: 2·1.14·5.5²·(0.740741/2)²
    # = 68.97·0.1371742 = 9.46091 W
    # iron: 0.3978 kg (1200 mm²·50 mm·0.85·7800) × 2.5·(400/50)² = 160 W/kg → 63.648 W
    # magnets: 60 W at 5000 rpm scaled by (4000/5000)² = 38.4 W
    losses = mot["losses_W"]
    assert losses["ohmic"] == pytest.approx(9.46091, rel=REL)
    assert losses["iron"] == pytest.approx(63.648, rel=REL)
    assert losses["magnets"] == pytest.approx(38.4, rel=REL)
    # limit: the reference's own losses at 5000 rpm, 2 N·m: 68.97 + 99.45 + 60 = 228.42 W
    assert mot["loss_limit_W"] == pytest.approx(228.42, rel=REL)
    # rewound for 4000 rpm: k_T = (2/5.5)·5000/4000 = 0.454545 N·m/A → I = 0.740741/0.454545
    # = 1.62963 A
    assert mot["current_A"] == pytest.approx(1.62963, rel=REL)


def test_positioning_one_motor_by_hand():
    rep = _design(
        {
            "application": {"kind": "positioning", "title": "hand"},
            "positioning": {
                "profile": "trapezoidal",
                "travel_rad": 20,
                "load_inertia_kgm2": 2,
                "load_torque_Nm": 30,
                "motors": [
                    {"name": "M", "speed_rad_s": 200, "inertia_kgm2": 0.005, "accel_torque_Nm": 10}
                ],
            },
        }
    )
    mo = rep["design"]["motion"]
    # I = 2/0.005 = 400; m = 30/10 = 3; A = 2·ω0²·J0·(m² + I)/(α·M_λ) = 2·40000·0.005·409/200 = 818
    assert mo["coefficient_A"] == pytest.approx(818.0, rel=REL)
    # root of A·i = (i² − m²)² (eq. (6)): i = 9.96394: 818·9.96394 = 8150.50,
    # (99.28010 − 9)² = 90.28010² = 8150.50
    assert mo["optimal_ratio"] == pytest.approx(9.96394, rel=REL)
    i = 9.96394
    assert 818 * i == pytest.approx((i * i - 9) ** 2, rel=1e-5)
    # eq. (4): t = α·i/ω0 + ω0·J0/M_λ·(i² + I)/(i² − m²) = 0.996394 + 0.1·499.2801/90.2801
    # = 0.996394 + 0.553034 = 1.549428 s
    assert mo["move_time_s"] == pytest.approx(1.549428, rel=REL)
    # first step of the graphical method: μ0 = 3/∛818 = 3/9.352290 = 0.3207770;
    # K = ∛(1/(1 − μ0²)²) = ∛(1/0.8047913²) = 1.075093 → 9.352290·1.075093 = 10.05459
    assert mo["estimated_ratio_first_step"] == pytest.approx(10.05459, rel=REL)


def test_spinning_rotor_reactions_and_friction_by_hand():
    rep = _design(
        {
            "application": {"kind": "spinning_rotor", "title": "hand"},
            "rotor": {
                "mass_kg": 0.56,
                "angular_momentum_kgm2_s": 1.814,
                "speed_rad_s": 4453,
                "bearing": "7000 CD",
                "bearing_count": 2,
                "ball_plane_to_cg_mm": 15,
                "slew_rate_rad_s": 0.1,
                "axis_angle_deg": 60,
                "slew_angle_deg": 9,
                "run_up_time_s": 30,
                "rolling_friction_mm": 0.028,
                "lubricant_viscosity_mm2_s": 10,
                "aero": {"loss_W": 32.15},
            },
        }
    )
    r = rep["design"]["rotor"]
    # M = H·Ω·sin α = 1.814·0.1·0.8660254 = 0.1570970 N·m
    assert r["gyroscopic_moment_Nm"] == pytest.approx(0.1570970, rel=REL)
    # eq. (3), r = 6.6 mm, h = 15 mm: r² + h² = 43.56 + 225 = 268.56 mm²
    # F_ax = M·r/(r² + h²) = 0.157097·0.0066/268.56e-6 = 3.86074 N
    # F_rad = M·h/(r² + h²) = 0.157097·0.015/268.56e-6 = 8.77441 N
    assert r["reaction_axial_N"] == pytest.approx(3.86074, rel=REL)
    assert r["reaction_radial_N"] == pytest.approx(8.77441, rel=REL)
    # radial on one bearing: 0.56·9.80665/2 + 8.77441 = 2.745862 + 8.77441 = 11.52027 N;
    # preload F_H = 1.58·11.52027·tan 15° = 1.58·11.52027·0.2679492 = 4.87722 N
    assert r["preload_N"] == pytest.approx(4.87722, rel=REL)
    # eq. (4), D = 4.76 mm, r_B = 6.6 − 2.38 = 4.22 mm, 2r_B/D = 1.773109, λ = 0.028 mm:
    # radial 1.4·11.52027·0.028e-3·(1 + 1.773109) = 1.25232e-3 N·m
    # axial (4.87722 + 3.86074)·0.028e-3/sin 15°·(1.773109 + 0.9659258)
    #   = 8.73796·0.028e-3/0.2588190·2.739035 = 2.58922e-3 N·m
    t = r["bearing_friction_terms"]["with_reaction"]
    assert t["radial_Nm"] == pytest.approx(1.25232e-3, rel=REL)
    assert t["axial_Nm"] == pytest.approx(2.58922e-3, rel=REL)
    # centrifugal term: z·F_c·λ/cos β·r_B/D with F_c = m_b·ω_c²·r; the advisor's F_c enters
    # linearly: 8·F_c·0.028e-3/0.9659258·0.8865546
    fc = r["bearing"]["loads_with_reaction"]["centrifugal_per_ball_N"]
    assert t["centrifugal_Nm"] == pytest.approx(8 * fc * 0.028e-3 / 0.9659258 * 0.8865546, rel=REL)
    # m_b = 7850·π/6·(4.76e-3)³ = 4.43272e-4 kg (bearing steel 7850 kg/m³);
    # ω_c = ω/2·(1 − D·cos β/(2r)) = 2226.5·(1 − 0.3483168) = 1450.97 rad/s;
    # F_c = 4.43272e-4·1450.97²·0.0066 = 6.1596 N
    assert fc == pytest.approx(6.1596, rel=REL)
    # steady torque with the reaction: 2·5.10791e-3 + 32.15/4453 = 0.01021582 + 0.00721985
    assert r["steady_torque_Nm"]["with_reaction"] == pytest.approx(0.0174357, rel=REL)


def test_one_way_roller_clutch_by_hand():
    rep = _design(
        {
            "application": {"kind": "rotary", "hold_without_power": True, "title": "hand"},
            "rotary": {"torque_Nm": 500, "speed_rpm": 5},
            "motor": {"kind": "bldc", "candidate_speeds_rpm": [3000]},
            "gearbox": {"rolling_body": "ball", "stage_efficiency": 0.85},
            "one_way": {"type": "roller_clutch", "rollers": 8},
        }
    )
    ow = rep["design"]["one_way"]
    # motor side: M_out/(q·η) = 500/(600·0.85²) = 500/433.5 = 1.153403 N·m
    assert ow["torque_Nm"] == pytest.approx(1.153403, rel=REL)
    # eq. (1): d_p = 0.583·∛(M/z), M in N·mm: 0.583·∛(1153.403/8) = 0.583·∛144.1753
    # = 0.583·5.243684 = 3.057068 mm; D = 12·d_p = 36.6848 mm; L = 1.5·d_p = 4.58560 mm
    assert ow["outer_diameter_mm"] == pytest.approx(36.6848, rel=REL)
    assert ow["length_mm"] == pytest.approx(4.58560, rel=REL)
    # output side for comparison: ∛(500000/8) = 39.68503 → d_p = 23.13637, D = 277.636 mm
    assert ow["output_side"]["outer_diameter_mm"] == pytest.approx(277.636, rel=REL)
    worm = next(a for a in ow["alternatives"] if a["type"] == "worm")
    # self-locking worm, γ = 0.5·φ, φ = atan 0.1 = 5.710593°: η = tan γ/tan(γ + φ)
    # = tan 2.855297°/tan 8.565890° = 0.04987532/0.1506240 = 0.331125
    assert worm["efficiency"] == pytest.approx(0.331125, rel=REL)
    inv = next(a for a in ow["alternatives"] if a["type"] == "inverse_gear")
    # m = ∛(M/(σ_t·z)) = ∛(1153.403/(400·20)) = ∛0.1441753 = 0.5243684 mm; d = m·z = 10.48737
    assert inv["outer_diameter_mm"] == pytest.approx(10.48737, rel=REL)
    assert math.isfinite(ow["mass_kg"])


def test_rotary_eq10_optimum_is_finite_when_the_reference_speed_cannot_be_reduced():
    """1 N·m at 800 rpm from a 6000 rpm motor (q = 7.5, one stage): at the reference speed,
    5000 rpm, the ratio 6.25 is below one stage's 6.5, so eq. (10) is evaluated at the
    candidate instead of writing nan into the report (issue 13: no nan, ever)."""
    rep = _design(
        {
            "application": {"kind": "rotary", "title": "hand"},
            "rotary": {"torque_Nm": 1, "speed_rpm": 800},
            "motor": {"kind": "bldc", "candidate_speeds_rpm": [6000]},
        }
    )
    mot = rep["design"]["motor"]
    # motor torque 1/(7.5·0.9) = 0.1481481 N·m; ohmic 68.97·(0.1481481/2)² = 0.378436 W;
    # f = 6000·6/60 = 600 Hz; iron 0.3978·2.5·(600/50)² = 143.208 W; magnets on the power law
    # through 60 W @ 5000 and 100 W @ 10000: 60·1.2^(log(100/60)/log 2) = 68.6286 W.
    # eq. (10): f* = f·(P_om/P_core)^(1/4) = 600·(0.378436/211.8366)^0.25 = 600·0.205590
    # = 123.354 Hz → n* = 123.354·60/6 = 1233.54 rpm
    assert mot["losses_W"]["ohmic"] == pytest.approx(0.378436, rel=REL)
    assert mot["optimum_frequency_Hz"] == pytest.approx(123.354, rel=REL)
    assert mot["optimum_speed_rpm"] == pytest.approx(1233.54, rel=REL)
