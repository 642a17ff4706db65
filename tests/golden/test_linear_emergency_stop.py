"""The linear drive's emergency stop reaches the screw's own checks, the summary states the
torque the motor drives with a thrust face, and ``advisor verify`` reads the service factor
from the factored load: every expected number worked by hand here, with its formula, inputs
and source.

The screw jack of examples/linear_screw_jack_collar.toml: F = 5000 N, a fixed–free column of
0.5 m, steel–bronze (f = 0.13, the middle of the oiled 0.10…0.16; [p] = 10 MPa), steel 45
(σ_y = 355 MPa, S = 3, E = 210 GPa), f_B = 1.25, a collar d_c = 40 mm, f_c = 0.08. Its screw
is Tr26x3: d2 = 24.5 mm, d3 = 22.5 mm, H1 = 1.5 mm (GOST 24737-81)."""

import copy
import math
import tomllib

import pytest
from helpers import EXAMPLES

from advisor.calc.sizing import evaluate_thread, screen_threads, thread_geometry
from advisor.cli import main
from advisor.core.engine import advise
from advisor.core.errors import InfeasibleError
from advisor.core.reading import parse_requirements
from advisor.core.registry import summary_rows
from advisor.core.report import to_toml
from advisor.verify.runner import report_value
from catalogs import load_catalogs

F_N, STOP_N, F_B, SPAN_M = 5000.0, 30000.0, 1.25, 0.5
D2_M, D3_M, H1_M, PITCH_M = 0.0245, 0.0225, 0.0015, 0.003
E_PA, SIGMA_Y_PA, S_YIELD, S_BUCKLING, P_ALLOWED_MPA = 210e9, 355e6, 3.0, 3.0, 10.0
PSI = math.atan(PITCH_M / (math.pi * D2_M))  # lead angle, one start
PHI = math.atan(0.13 / math.cos(math.radians(15.0)))  # φ' = atan(f/cos(α/2)), α = 30°
# Euler, fixed–free (K = 2): P_cr = π²·E·I/(K·L)², I = π·d3⁴/64 = 26 074.7 N
P_CR_N = math.pi**2 * E_PA * (math.pi * D3_M**4 / 64.0) / (2.0 * SPAN_M) ** 2
# the nut's turns for f_B·F: z_p = 6250/(π·24.5·1.5·10) = 5.41 → 6; height 1.2·d2/P = 9.8 → 10
NUT_TURNS = 10


def _doc(**linear) -> dict:
    doc = tomllib.loads((EXAMPLES / "linear_screw_jack_collar.toml").read_text())
    doc["linear"].update(linear)
    return doc


def _report(doc: dict) -> dict:
    return tomllib.loads(to_toml(advise(parse_requirements(copy.deepcopy(doc)))))


def _tr26x3(stop_force_N: float):
    cat = load_catalogs()
    steel = cat.steel("45")
    assert steel.elastic_modulus_MPa * 1e6 == E_PA and steel.yield_strength_MPa * 1e6 == SIGMA_Y_PA
    ev = evaluate_thread(
        cat.thread("Tr26x3"),
        force_N=F_N,
        stroke_m=0.3,
        travel_time_s=10.0,
        span_m=SPAN_M,
        end_fixity="fixed-free",
        buckling_safety_factor=S_BUCKLING,
        starts=1,
        friction_model="standard",
        material=_material(),
        service_factor=F_B,
        stop_force_N=stop_force_N,
    )
    return ev, {c.id: c for c in ev.checks}


def test_the_stop_force_is_checked_at_buckling_core_and_nut():
    ev, checks = _tr26x3(STOP_N)
    assert ev.nut_turns == NUT_TURNS
    # buckling: value f_B·F_stop = 37 500 N against P_cr/S_b = 8691.6 N (static, S_b kept)
    b = checks["buckling_emergency_stop"]
    assert b.value == pytest.approx(F_B * STOP_N)
    assert b.limit == pytest.approx(P_CR_N / S_BUCKLING, rel=1e-9)
    assert b.margin == pytest.approx(26074.7 / 3.0 / 37500.0, rel=1e-5)  # 0.23177
    assert "30000 N × f_B = 1.25" in b.name and not b.passed
    # nut: p = F_stop/(π·d2·H1·z) = 30000/(π·24.5·1.5·10) = 25.98 MPa, × f_B = 32.48 MPa
    n = checks["nut_pressure_emergency_stop"]
    p_mpa = STOP_N / (math.pi * D2_M * H1_M * NUT_TURNS) / 1e6
    assert n.value == pytest.approx(F_B * p_mpa, rel=1e-12)
    assert n.margin == pytest.approx(P_ALLOWED_MPA / (F_B * 25.9845), rel=1e-5)  # 0.30788
    # core: σ = 4F/(π·d3²) = 75.45 MPa, τ = 16·M/(π·d3³) with M = F·d2/2·tan(ψ + φ')
    # = 64.12 N·m: τ = 28.66 MPa; σ_eq = √(σ² + 3τ²) = 90.32 MPa, × f_B = 112.9 against 118.33
    m_stop = STOP_N * D2_M / 2.0 * math.tan(PSI + PHI)
    sigma = 4.0 * STOP_N / (math.pi * D3_M**2)
    tau = 16.0 * m_stop / (math.pi * D3_M**3)
    c = checks["core_stress_emergency_stop"]
    assert c.value == pytest.approx(F_B * math.hypot(sigma, math.sqrt(3.0) * tau) / 1e6)
    assert c.limit == pytest.approx(SIGMA_Y_PA / S_YIELD / 1e6)
    assert c.margin == pytest.approx(118.333 / 112.90, rel=1e-3)  # 1.0481
    # the rated checks are untouched: buckling at f_B·F = 6250 N, margin 8691.6/6250
    assert checks["buckling"].margin == pytest.approx(P_CR_N / S_BUCKLING / (F_B * F_N))
    assert not ev.passed and {x.id for x in ev.failed} == {
        "buckling_emergency_stop",
        "nut_pressure_emergency_stop",
    }


def test_a_stop_below_the_rated_force_is_checked_at_the_rated_force():
    _, checks = _tr26x3(3000.0)
    # max(F, F_stop) = 5000 N: the same value and margin as the rated check, said so
    b, rated = checks["buckling_emergency_stop"], checks["buckling"]
    assert (b.value, b.margin) == (rated.value, rated.margin) == (F_B * F_N, b.limit / 6250.0)
    assert "the rated 5000 N (above the emergency stop's 3000 N)" in b.name
    _, none = _tr26x3(0.0)
    assert not any(i.endswith("_emergency_stop") for i in none)


def test_the_thread_screen_rejects_what_the_stop_checks_reject():
    """The joint choice's screen gives the full evaluation's verdict with a stop force."""
    cat = load_catalogs()
    case = dict(
        force_N=F_N,
        stroke_m=0.3,
        travel_time_s=10.0,
        span_m=SPAN_M,
        end_fixity="fixed-free",
        buckling_safety_factor=S_BUCKLING,
        friction_model="standard",
        material=_material(),
        service_factor=F_B,
    )
    for stop in (0.0, 3000.0, STOP_N, 60000.0):
        screens = screen_threads(
            [thread_geometry(t) for t in cat.threads], (1, 2, 3), stop_force_N=stop, **case
        )
        for s in screens:
            e = evaluate_thread(s.thread, starts=s.starts, stop_force_N=stop, **case)
            assert s.passed == e.passed, (stop, s.name, s.starts, [c.id for c in e.failed])
    tr26 = [s for s in screens if s.name == "Tr26x3"]
    assert tr26 and not any(s.passed for s in tr26)


def _material():
    from advisor.applications.linear.advice import screw_demand
    from advisor.core.rulebook import Trace

    return screw_demand(parse_requirements(_doc()), load_catalogs(), Trace())[0].material


def test_the_advice_picks_a_thread_that_holds_the_stop_and_refuses_one_that_does_not():
    rep = _report(_doc(emergency_stop_force_N=STOP_N))
    stops = [c for c in rep["checks"] if c["id"].endswith("_emergency_stop")]
    assert {c["id"] for c in stops} == {
        "core_stress_emergency_stop",
        "buckling_emergency_stop",
        "nut_pressure_emergency_stop",
    }
    assert all(c["passed"] and c["margin"] >= 1.0 for c in stops)
    assert rep["design"]["screw"]["thread"] != "Tr26x3"  # Tr26x3 buckles in the stop
    # without the key the example keeps its Tr26x3 and has no stop check
    plain = _report(_doc())
    assert plain["design"]["screw"]["thread"] == "Tr26x3"
    assert not any(c["id"].endswith("_emergency_stop") for c in plain["checks"])
    doc = _doc(emergency_stop_force_N=STOP_N)
    doc["screw"]["thread"] = "Tr26x3"
    with pytest.raises(InfeasibleError) as err:
        advise(parse_requirements(doc))
    why = " ".join(err.value.reasons)
    assert "buckling" in why and "margin 0.232" in why and "margin 0.308" in why


def test_the_thrust_bearing_takes_the_stop_force_against_its_c0():
    doc = _doc(emergency_stop_force_N=9000.0)
    doc["screw"]["thrust"] = {"kind": "bearing", "bearing": "7205 BECBP"}
    rep = _report(doc)
    checks = {c["id"]: c for c in rep["checks"]}
    # ISO 76, 40° angular contact under pure axial load: P0 = Y0·F_a = 0.26·F_a; C0 = 10 kN
    rated, stop = checks["thrust_bearing_static"], checks["thrust_bearing_static_emergency_stop"]
    assert rated["value"] == pytest.approx(F_B * 0.26 * F_N)  # 1625 N
    assert rated["margin"] == pytest.approx(10000.0 / 1625.0, rel=1e-5)  # 6.15385
    assert stop["value"] == pytest.approx(F_B * 0.26 * 9000.0)  # 2925 N
    assert stop["margin"] == pytest.approx(10000.0 / 2925.0, rel=1e-5)  # 3.4188
    # 60 kN: P0 = 1.25·0.26·60000 = 19 500 N > C0, margin 0.513: infeasible like any check
    doc["linear"]["emergency_stop_force_N"] = 60000.0
    with pytest.raises(InfeasibleError) as err:
        advise(parse_requirements(doc))
    assert "thrust bearing 7205 BECBP at the emergency stop's 60000 N" in " ".join(
        err.value.reasons
    )
    assert "margin 0.513" in " ".join(err.value.reasons)


def test_the_datasheet_maps_the_stop_force_and_the_thrust_face(tmp_path, capsys):
    path = tmp_path / "jack.toml"
    src = (EXAMPLES / "linear_screw_jack_collar.toml").read_text()
    path.write_text(
        src.replace("force_N = 5000\n", "force_N = 5000\nemergency_stop_force_N = 9000\n")
    )
    assert main(["--batch", str(path), "--format", "md"]) == 0
    rows: dict[str, str] = {}  # the required-and-achieved table comes before the echo
    for line in capsys.readouterr().out.splitlines():
        if line.startswith("| "):
            rows.setdefault(line.split("|")[1].strip(), line)
    assert "emergency stop's 9000 N" in rows["Emergency-stop force"]
    assert "no check covers" not in rows["Emergency-stop force"]
    assert "no check covers" not in rows["Thrust face"]


def test_the_summary_states_the_torque_with_the_collar():
    rep = advise(parse_requirements(_doc()))
    screw_row = dict(summary_rows(rep))["screw"]
    # thread M = F·d2/2·tan(ψ + φ') = 10.687 N·m; collar T_c = F·f_c·d_c/2 = 5000·0.08·0.02
    # = 8 N·m (Shigley, eq. (8-6)); η = F·L/(2π·(M + T_c)) = 15/(2π·18.687) = 0.128
    thread = F_N * D2_M / 2.0 * math.tan(PSI + PHI)
    drive = thread + 8.0
    eta = F_N * PITCH_M / (2.0 * math.pi * drive)
    assert f"{drive:.3f} N·m with the collar's 8.000 N·m (thread {thread:.3f}" in screw_row
    assert f"η = {eta:.3f} with the collar" in screw_row
    assert (f"{drive:.3f}", f"{eta:.3f}") == ("18.687", "0.128")


def test_verify_reads_the_service_factor_as_the_factored_load_over_the_force():
    # SEW's f_B = 1.5 on seed 001's 3500 N: the buckling check states 1.5·3500 = 5250 N
    tree = {
        "checks": [{"id": "buckling", "value": 5250.0}],
        "requirements": {"linear": {"force_N": 3500}},
    }
    assert report_value(tree, "checks[id=buckling].value / requirements.linear.force_N") == 1.5
    assert report_value(tree, "checks[id=buckling].value") == 5250.0
    with pytest.raises(KeyError):
        report_value(tree, "checks[id=buckling].value / requirements.linear.nothing")


# The nut sized for the stop: Tr24x5 with 3 starts (d2 = 21.5 mm, H1 = 2.5 mm, P = 5 mm;
# GOST 24737-81), F = 2500 N, F_stop = 9000 N, f_B = 1.2, a bronze nut ([p] = 10 MPa,
# z ≤ 10, 1.2 ≤ H/d2 ≤ 2.5; Ivanov, power screws: z = f_B·F/(π·d2·H1·[p]))
TR24_D2_M, TR24_H1_M, TR24_P_M = 0.0215, 0.0025, 0.005


def _tr24x5(stop_force_N: float):
    case = dict(
        force_N=2500.0,
        stroke_m=0.25,
        travel_time_s=2.5,
        span_m=0.6,
        end_fixity="pinned-pinned",
        buckling_safety_factor=S_BUCKLING,
        friction_model="standard",
        material=_material(),
        service_factor=1.2,
        stop_force_N=stop_force_N,
    )
    thread = load_catalogs().thread("Tr24x5")
    assert (thread.d2_mm, thread.H1_mm, thread.pitch_mm) == (21.5, 2.5, 5.0)
    screen = screen_threads([thread_geometry(thread)], (3,), **case)[0]
    ev = evaluate_thread(thread, starts=3, **case)
    assert screen.passed == ev.passed  # the thread screen agrees with the full evaluation
    return ev, {c.id: c for c in ev.checks}


def test_the_stop_force_sizes_the_nut_where_a_longer_nut_carries_it():
    # rated: z_p = 3000/(π·21.5·2.5·10) = 1.78 → 2; height 1.2·21.5/5 = 5.16 → 6 turns
    rated, _ = _tr24x5(0.0)
    assert rated.nut_turns == rated.nut_turns_rated == 6
    # stop: z_p = 1.2·9000/(π·21.5·2.5·10) = 6.40 → 7 turns (6 turns gave 10.66 MPa, margin
    # 0.938); p = 10800/(π·21.5·2.5·7) = 9.137 MPa, margin 10/9.137 = 1.094
    ev, checks = _tr24x5(9000.0)
    assert (ev.nut_turns, ev.nut_turns_rated) == (7, 6)
    stop = checks["nut_pressure_emergency_stop"]
    p_mpa = 1.2 * 9000.0 / (math.pi * TR24_D2_M * TR24_H1_M * 7) / 1e6
    assert stop.value == pytest.approx(p_mpa, rel=1e-12) and p_mpa == pytest.approx(9.1369, 1e-4)
    assert stop.margin == pytest.approx(1.0945, rel=1e-4)
    assert checks["nut_height"].value == pytest.approx(7 * TR24_P_M / TR24_D2_M)  # 1.628 ≤ 2.5
    assert checks["nut_turns"].value == 7 and ev.passed
    # the rated pressure falls with the longer nut: 3000/(π·21.5·2.5·7) = 2.538 MPa
    assert checks["nut_pressure"].value == pytest.approx(
        1.2 * 2500.0 / (math.pi * TR24_D2_M * TR24_H1_M * 7) / 1e6, rel=1e-12
    )


def test_the_nut_is_lengthened_only_to_the_longest_allowed():
    # 20 kN: z_p = 24000/(π·21.5·2.5·10) = 14.2 turns > z_max = 10 (H/d2 allows 10.75): the
    # nut stops at 10 turns, its rated checks pass, the stop's pressure fails
    # 24000/(π·21.5·2.5·10) = 14.21 MPa, margin 0.7036 (the column and the core fail too)
    ev, checks = _tr24x5(20000.0)
    assert (ev.nut_turns, ev.nut_turns_rated) == (10, 6)
    assert checks["nut_turns"].passed and checks["nut_height"].passed
    assert checks["nut_pressure_emergency_stop"].margin == pytest.approx(0.70364, rel=1e-4)
    failed = {c.id for c in ev.failed}
    assert "nut_pressure_emergency_stop" in failed and not failed & {"nut_turns", "nut_height"}


def _l2_doc() -> dict:
    doc = _doc(force_N=2500.0, stroke_m=0.25, travel_time_s=2.5, emergency_stop_force_N=9000.0)
    doc["linear"].update(support_span_m=0.6, end_fixity="pinned-pinned")
    doc["screw"] = {"thread": "Tr24x5", "starts": 3, "friction_coefficient": 0.08}
    doc["design"] = {"service_factor": 1.2}
    return doc


def test_an_imposed_thread_whose_longer_nut_holds_the_stop_is_accepted():
    rep = _report(_l2_doc())
    nut = rep["design"]["screw"]["nut"]
    assert nut["turns"] == 7.0 and nut["height_mm"] == pytest.approx(35.0)
    assert "sized by the emergency stop's 9000 N × f_B = 1.2" in nut["turns_basis"]
    assert "the rated 2500 N alone gives 6" in nut["turns_basis"]
    stop = next(c for c in rep["checks"] if c["id"] == "nut_pressure_emergency_stop")
    assert stop["passed"] and stop["margin"] == pytest.approx(1.0945, rel=1e-4)
    # without the stop the nut keeps its 6 turns and states no basis
    plain = _l2_doc()
    del plain["linear"]["emergency_stop_force_N"]
    nut = _report(plain)["design"]["screw"]["nut"]
    assert nut["turns"] == 6.0 and "turns_basis" not in nut


def test_the_free_choice_takes_a_smaller_thread_with_a_longer_nut():
    # F = 8000 N, F_stop = 20 kN, f_B = 1.4, fixed–pinned 0.8 m, a collar: Tr34x6 (d2 = 31 mm,
    # H1 = 3 mm) with z_p = 28000/(π·31·3·10) = 9.58 → 10 turns, 9.584 MPa, margin 1.043;
    # with the rated force's 7 turns the choice was Tr40x7
    doc = _doc(force_N=8000.0, stroke_m=0.4, travel_time_s=12.0, emergency_stop_force_N=20000.0)
    doc["linear"].update(support_span_m=0.8, end_fixity="fixed-pinned")
    doc["screw"] = {"material_pair": "steel_bronze"}
    doc["screw"]["thrust"] = {"kind": "collar", "mean_diameter_mm": 50, "friction_coefficient": 0.1}
    doc["design"] = {"service_factor": 1.4}
    rep = _report(doc)
    screw_out = rep["design"]["screw"]
    assert screw_out["thread"] == "Tr34x6" and screw_out["nut"]["turns"] == 10.0
    stop = next(c for c in rep["checks"] if c["id"] == "nut_pressure_emergency_stop")
    assert stop["value"] == pytest.approx(28000.0 / (math.pi * 0.031 * 0.003 * 10) / 1e6)
    assert stop["margin"] == pytest.approx(1.0434, rel=1e-4)
