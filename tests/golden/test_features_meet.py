"""Where features meet (issue 23): the holding device with the motor choice and the duty
cycle, a back-driving load held in every phase, the duty filter's edge, the duty tables'
edges, the headline that states the design, checks against independent capacities, and
decisions that state the numbers they say. Every number asserted is worked by hand here."""

import copy
import math
import re
import tomllib
from types import SimpleNamespace

import pytest
from helpers import EXAMPLES

from advisor.applications.rotary import duty as rotary_duty
from advisor.calc import duty as du
from advisor.calc import one_way as ow
from advisor.core.engine import advise
from advisor.core.errors import InfeasibleError
from advisor.core.reading import parse_requirements
from advisor.core.report import to_toml

DEVICES = ("auto", "roller_clutch", "em_clutch", "worm", "inverse_gear")

# seed 004's self-locking worm: f = 0.1, γ = φ/2 (the aviation margin)
PHI = math.atan(0.1)
WORM_ETA = math.tan(PHI / 2) / math.tan(PHI / 2 + PHI)  # 0.049875/0.15063 = 0.33112


def report(doc: dict) -> dict:
    return tomllib.loads(to_toml(advise(parse_requirements(copy.deepcopy(doc)))))


def linear_doc(device: str | None = "worm", duty: dict | None = None) -> dict:
    """Tr20x4 with 4 starts (lead 16 mm, not self-locking), 1500 N, f = 0.1."""
    doc = {
        "application": {"kind": "linear", "title": "features meet"},
        "linear": {
            "force_N": 1500.0,
            "stroke_m": 0.2,
            "travel_time_s": 5.0,
            "support_span_m": 0.4,
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


def screw_torque_by_hand(force_N: float, direction: str = "against") -> float:
    """Tr20x4, 4 starts: d2 = d − 0.5·P = 18 mm, lead 16 mm, tan ψ = 16/(π·18) = 0.28294,
    φ' = atan(0.1/cos 15°) (the standard model, α = 30°); M = F·d2/2·tan(ψ ± φ')."""
    psi = math.atan(16.0 / (math.pi * 18.0))
    phi = math.atan(0.1 / math.cos(math.radians(15.0)))
    sign = 1.0 if direction == "against" else -1.0
    return force_N * 0.018 / 2.0 * math.tan(sign * psi + phi)


# ------------------------------------------------------------------ 1. linear motor choice
def test_worm_efficiency_by_hand():
    assert WORM_ETA == pytest.approx(0.33112, abs=1e-5)
    assert ow.passage("worm").efficiency == pytest.approx(WORM_ETA, rel=1e-12)
    # tan(γ − φ)/tan γ = −1 at γ = φ/2: the motor lowers a load with its whole torque
    assert ow.passage("worm").lowering_factor == pytest.approx(1.0, rel=1e-12)
    # braking-profile gear, η 0.45: 1/η − 2 = 0.2222 by the small-angle model
    assert ow.passage("inverse_gear").lowering_factor == pytest.approx(1 / 0.45 - 2, rel=1e-12)


@pytest.mark.parametrize("device, eta", [("worm", WORM_ETA), ("inverse_gear", 0.45)])
def test_linear_motor_is_chosen_through_the_device(device, eta):
    """The screw needs M = 1500·0.009·tan(ψ + φ') = 5.375 N·m; through a worm (η 0.3311)
    the motor must give 5.375/0.3311 = 16.23 N·m, above the 4A71B6's rated 5.84 N·m and
    starting 11.67 N·m (the motor chosen before, checked against the screw alone): the
    motor's rated torque must carry M/η, and the checks state M/η."""
    rep = report(linear_doc(device))
    m = screw_torque_by_hand(1500.0)
    assert m == pytest.approx(5.375, abs=1e-3)
    assert m / WORM_ETA == pytest.approx(16.23, abs=0.01)
    assert rep["design"]["screw"]["torque_Nm"] == pytest.approx(m, rel=1e-5)
    motor = rep["design"]["motor"]
    assert motor["required_torque_Nm"] == pytest.approx(m / eta, rel=1e-5)
    assert motor["rated_torque_Nm"] >= m / eta
    checks = {c["id"]: c for c in rep["checks"]}
    assert checks["motor_rated_torque"]["value"] == pytest.approx(m / eta, rel=1e-5)
    assert checks["motor_starting_torque"]["value"] == pytest.approx(m / eta, rel=1e-5)
    assert "through the" in checks["motor_rated_torque"]["name"]
    # the same drive with a clutch (η = 1) needs only M: a smaller or equal motor
    plain = report(linear_doc("roller_clutch"))
    assert plain["design"]["motor"]["required_torque_Nm"] == pytest.approx(m, rel=1e-5)
    assert plain["design"]["motor"]["rated_power_kW"] <= motor["rated_power_kW"]


def test_linear_worm_motor_choice_is_infeasible_when_no_motor_carries_it():
    """At 30 kN the screw torque is 20× larger (107.5 N·m); through the worm 324.6 N·m, which
    no motor of the catalog driving the imposed thread at its speed gives: exit 3, never a
    feasible design checked against the screw alone."""
    doc = linear_doc("worm")
    doc["linear"]["force_N"] = 30000.0
    try:
        rep = report(doc)
    except InfeasibleError:
        return
    m = screw_torque_by_hand(30000.0)
    assert rep["design"]["motor"]["rated_torque_Nm"] >= m / WORM_ETA


# ------------------------------------------------------------------ 2. rotary duty
def _rotary_req(segments, rest_s: float = 5.0):
    total = sum(s.time_s for s in segments) + rest_s
    duty = SimpleNamespace(
        segments=segments,
        load_inertia_kgm2=2.0,
        motor_inertia_kgm2=0.00015,
        cycles_per_hour=3600.0 / total,
        duty_type=None,
    )
    return SimpleNamespace(duty=duty, rotary=SimpleNamespace(torque_Nm=1620.0))


def _move(direction: str):
    return SimpleNamespace(
        kind="move",
        time_s=1.0,
        angle_deg=25.0,
        profile="trapezoidal",
        accel_fraction=0.1,
        direction=direction,
        torque_Nm=1200.0,
    )


def test_rotary_duty_through_a_worm_by_hand():
    """25° in 1 s, 10 % accelerating, 1200 N·m, J_L = 2, J_M = 0.00015, q = 1000,
    η = 0.81, worm at the motor side (η_w = 0.33112, lowering factor 1).
    ω_out = 0.43633/0.9 = 0.48481 rad/s, ε = 4.8481 rad/s², J_M·ε·q = 0.72722 N·m.
    Against, accelerating: (2·4.8481 + 1200)/(1000·0.81)/0.33112 + 0.72722 = 5.2375 N·m
    (without the worm 1.49345 + 0.72722 = 2.2207 N·m).
    With the load, decelerating: the reducer is back-driven, −1209.70·0.81/1000 = −0.97985;
    the worm cannot be back-driven, the motor lowers it: +0.97985 − 0.72722 = 0.25263 N·m.
    With the load, accelerating: −1190.30·0.81/1000 → +0.96415 + 0.72722 = 1.69137 N·m.
    Nothing is regenerated: no phase has a negative torque at a positive speed."""
    req = _rotary_req([_move("against"), _move("with")])
    frame = SimpleNamespace(limit_W=1e9)
    worm = rotary_duty.Holder(ow.passage("worm"))
    ph, problems = rotary_duty.cycle(req, 1000.0, 0.81, 5000.0, frame, worm)
    assert not problems
    by = {p.name: p.torque_Nm for p in ph}
    eps = math.radians(25.0) / 0.9 / 0.1
    rotor = 0.00015 * eps * 1000.0
    assert rotor == pytest.approx(0.72722, abs=1e-5)
    assert by["1 move: accelerate"] == pytest.approx(
        (2 * eps + 1200) / (1000 * 0.81) / WORM_ETA + rotor, rel=1e-9
    )
    assert by["1 move: accelerate"] == pytest.approx(5.2375, abs=1e-4)
    assert by["2 move: decelerate"] == pytest.approx(
        (2 * eps + 1200) * 0.81 / 1000 - rotor, rel=1e-9
    )
    assert by["2 move: accelerate"] == pytest.approx(
        (1200 - 2 * eps) * 0.81 / 1000 + rotor, rel=1e-9
    )
    assert du.energies(ph)[1] == 0.0
    # the same cycle with no device regenerates (the load drives the motor back)
    free, _ = rotary_duty.cycle(req, 1000.0, 0.81, 5000.0, frame, rotary_duty.NO_HOLDER)
    assert du.energies(free)[1] > 0.0
    assert {p.name: p.torque_Nm for p in free}["1 move: accelerate"] == pytest.approx(
        (2 * eps + 1200) / (1000 * 0.81) + rotor, rel=1e-9
    )


@pytest.mark.parametrize("kind", ["roller_clutch", "worm", "inverse_gear"])
def test_only_the_rotor_regenerates_behind_a_self_locking_device(kind):
    """The load gives nothing back through a self-locking device; the rotor, upstream of it,
    is braked by the motor and its energy comes back. The move with the load decelerates
    with M = k·|T_load| − J_M·ε·q (k the lowering factor): at the motor side
    |T_load| = (2·ε + 1200)·0.81/1000 = 0.97985 N·m, at the output (2·ε + 1200)/(1000·0.81)
    (the reducer drives); J_M·ε·q = 0.72722 N·m (test above). Where M < 0 the energy back
    is |M|·ω_m/2·t_a, ω_m = 484.81 rad/s, t_a = 0.1 s; roller clutch (k = 0): ½·J_M·ω_m²
    = 17.628 J, the rotor's whole energy; worm (k = 1): nothing; braking-profile gear
    (k = 0.2222): (0.72722 − 0.21774)·24.2406 = 12.350 J at the motor side. Before the
    rotor's braking was clamped to 0 and nothing came back (the rotor then could not stop
    in t_a)."""
    req = _rotary_req([_move("against"), _move("with")])
    frame = SimpleNamespace(limit_W=1e9)
    eps = math.radians(25.0) / 0.9 / 0.1
    w_m = eps * 0.1 * 1000.0
    rotor = 0.00015 * eps * 1000.0
    k = ow.passage(kind).lowering_factor
    for at_output, load in (
        (False, (2 * eps + 1200) * 0.81 / 1000),
        (True, (2 * eps + 1200) / 810),
    ):
        ph, _ = rotary_duty.cycle(
            req, 1000.0, 0.81, 5000.0, frame, rotary_duty.Holder(ow.passage(kind), at_output)
        )
        back = max(0.0, rotor - k * load) * w_m / 2 * 0.1
        assert du.energies(ph)[1] == pytest.approx(back, rel=1e-9, abs=1e-12)
    if kind == "roller_clutch":
        assert back == pytest.approx(0.5 * 0.00015 * w_m**2, rel=1e-12)
        assert back == pytest.approx(17.628, abs=1e-3)


def test_rotary_motor_holds_a_standing_load_in_the_closing_rest():
    """A cycle ending on a move leaves 1200 N·m on the drive; with no device the motor
    holds it through the back-driven wave gear: 1200·0.81/1000 = 0.972 N·m in the rest."""
    req = _rotary_req([_move("against")], rest_s=5.0)
    ph, _ = rotary_duty.cycle(
        req, 1000.0, 0.81, 5000.0, SimpleNamespace(limit_W=1e9), rotary_duty.NO_HOLDER
    )
    assert ph[-1].name == "rest"
    assert ph[-1].torque_Nm == pytest.approx(0.972, rel=1e-12)
    held, _ = rotary_duty.cycle(
        req,
        1000.0,
        0.81,
        5000.0,
        SimpleNamespace(limit_W=1e9),
        rotary_duty.Holder(ow.passage("worm")),
    )
    assert held[-1].torque_Nm == 0.0


def test_rotary_duty_report_names_what_holds():
    doc = tomllib.loads((EXAMPLES / "rudder_actuator_duty.toml").read_text(encoding="utf-8"))
    rep = report(doc)
    assert rep["design"]["duty"]["held_by"].startswith("the motor with power on")
    doc["application"]["hold_without_power"] = True
    doc["one_way"] = {"type": "roller_clutch"}
    rep = report(doc)
    assert rep["design"]["duty"]["held_by"] == "the roller clutch at the motor side"
    # the load gives nothing back through the clutch; the rotor's own energy comes back
    assert 0.0 < rep["design"]["duty"]["regenerated_per_cycle_J"] <= _rotor_energy(rep) * (1 + 1e-5)


def _rotor_energy(rep: dict) -> float:
    """What the rotor side can give back per cycle: ½·(J_m + J_dev)·ω_m² per deceleration
    (J_dev of a device at the motor side, which turns with the rotor); a self-locking device
    lets the load give back nothing more."""
    d, dev = rep["design"]["duty"], rep["design"].get("one_way") or {}
    j = d["motor_inertia_kgm2"]
    if dev.get("location") == "motor side":
        j += dev["inertia_kgm2"]
    stops = [ph for ph in d["phases"] if ph["name"].endswith("decelerate")]
    return sum(0.5 * j * (ph["speed_rpm"] * math.pi / 30.0) ** 2 for ph in stops)


# ------------------------------------------------------------------ 3. linear back-driving
def _linear_duty(direction: str, time_s: float = 10.0) -> dict:
    return {
        "cycles_per_hour": 60,
        "moving_mass_kg": 300.0,
        "segments": [
            {"kind": "move", "distance_m": 0.2, "time_s": time_s, "direction": direction},
            {"kind": "dwell", "time_s": 5.0},
        ],
    }


def test_linear_back_driving_load_is_held_or_refused():
    """Tr20x4, 4 starts: back-driving efficiency tan(ψ − φ')/tan ψ = 0.62 > 0. A move with
    the load then rest: nothing holds the load when the motor is switched off: exit 3."""
    psi = math.atan(16.0 / (math.pi * 18.0))
    phi = math.atan(0.1 / math.cos(math.radians(15.0)))
    assert math.tan(psi - phi) / math.tan(psi) == pytest.approx(0.62, abs=0.01)
    with pytest.raises(InfeasibleError) as e:
        report(linear_doc(None, _linear_duty("with")))
    assert "back-drives the screw" in " ".join(e.value.reasons)


def test_linear_duty_through_a_worm_lowers_the_load_without_regenerating():
    """With the worm at the motor side the move with the load is driven down: the motor
    gives the screw's |F·d2/2·tan(φ' − ψ)|·1 = 1500·0.009·|tan(φ' − ψ)| N·m and nothing
    comes back; the move against the load asks M/η_w."""
    duty = _linear_duty("with")
    duty["segments"].insert(
        0, {"kind": "move", "distance_m": 0.2, "time_s": 10.0, "direction": "against"}
    )
    rep = report(linear_doc("worm", duty))
    d = rep["design"]["duty"]
    assert d["regenerated_per_cycle_J"] == 0.0
    assert d["held_by"] == "the worm at the motor side"
    runs = {p["name"]: p["torque_Nm"] for p in d["phases"] if p["name"].endswith("run")}
    against = screw_torque_by_hand(1500.0, "against") / WORM_ETA
    with_load = abs(screw_torque_by_hand(1500.0, "with"))
    assert runs["1 move: run"] == pytest.approx(against, rel=1e-5)  # the report's 6 digits
    assert runs["2 move: run"] == pytest.approx(with_load, rel=1e-5)


# ------------------------------------------------------------------ 4, 5. edges
def test_duty_filter_uses_the_checks_allowance():
    """The reference frame runs at its own limit: 1620·(1 + 2e-9) N·m passes the point check
    (0.1 % allowance) and must not be dropped by the cycle's filter (it uses 17 %)."""
    doc = tomllib.loads((EXAMPLES / "rudder_actuator_duty.toml").read_text(encoding="utf-8"))
    doc["rotary"]["torque_Nm"] = 1620.0000032
    rep = report(doc)
    assert rep["design"]["motor"]["speed_rpm"] == 5000.0


def test_duty_refusal_names_every_candidates_reason():
    doc = tomllib.loads((EXAMPLES / "rudder_actuator_duty.toml").read_text(encoding="utf-8"))
    doc["duty"]["cycles_per_hour"] = 360
    doc["duty"]["load_inertia_kgm2"] = 2000.0  # no speed can accelerate it
    with pytest.raises(InfeasibleError) as e:
        report(doc)
    text = " ".join(e.value.reasons)
    for speed in doc["motor"]["candidate_speeds_rpm"]:
        assert f"{speed:g} rpm" in text


@pytest.mark.parametrize(
    "cdf, k", [(0.15, 1.4), (0.25, 1.3), (0.40, 1.15), (0.60, 1.1), (0.61, 1.0)]
)
def test_duty_tables_have_no_knife_edge(cdf, k):
    """SEW's S3 rows (cdf 15/25/40/60 % → K 1.4/1.3/1.15/1.1): a cdf within 1e-9 of a row
    reads that row."""
    for f in (1 - 1e-9, 1.0, 1 + 1e-9):
        assert du.s3_power_factor(cdf * f) == k
    for minutes, k2 in ((10.0, 1.4), (30.0, 1.2), (60.0, 1.1)):
        assert du.s2_power_factor(minutes * (1 + 1e-9)) == k2


# ------------------------------------------------------------------ 6. the headline
def test_headline_states_the_duty_design():
    from advisor.core.registry import headline, summary_rows
    from advisor.datasheet import render

    doc = tomllib.loads((EXAMPLES / "indexing_table_duty.toml").read_text(encoding="utf-8"))
    rep_obj = advise(parse_requirements(doc))
    d = rep_obj.design.duty
    text = headline(rep_obj)
    assert text.startswith(f"motor {d.motor}, i = {d.ratio:.4g}, {d.move_time_s:.4g} s")
    assert "fastest move without the cycle" in text
    assert f"i = {rep_obj.design.motion.optimal_ratio:.4g}" in text
    assert summary_rows(rep_obj)[0][1] == text
    assert text in render(rep_obj, "md")  # the datasheet's summary states the same design


def test_family_row_states_the_duty_ratio():
    from advisor.applications.positioning.family import key_outputs as positioning_outputs

    doc = tomllib.loads((EXAMPLES / "indexing_table_duty.toml").read_text(encoding="utf-8"))
    rep = report(doc)
    row = positioning_outputs(rep)
    assert row["ratio"] == rep["design"]["duty"]["ratio"]


# ------------------------------------------------------------------ 7. checks
@pytest.mark.parametrize("duty_type", ["S4", "S5"])
def test_linear_peak_check_is_the_load_against_the_starting_torque(duty_type):
    """S4/S5 of the valve actuator: the check's value is the largest load torque at the
    motor (the screw torque, no device), its limit the starting torque; the design's
    peak_torque_Nm and peak_torque_limit_Nm are those numbers, and the motor's own mean
    starting torque is stated beside them, never compared with the motor."""
    doc = tomllib.loads((EXAMPLES / "valve_actuator_duty.toml").read_text(encoding="utf-8"))
    doc["duty"] = {
        "duty_type": duty_type,
        "starts_per_hour": 20,
        "cyclic_duration_factor": 0.4,
        "moving_mass_kg": 40,
    }
    rep = report(doc)
    d = rep["design"]["duty"]
    check = next(c for c in rep["checks"] if c["id"] == "duty_peak_torque")
    assert check["value"] == d["peak_torque_Nm"]
    assert check["limit"] == d["peak_torque_limit_Nm"]
    assert d["peak_torque_Nm"] == pytest.approx(rep["design"]["screw"]["torque_Nm"], rel=1e-5)
    assert d["mean_starting_torque_Nm"] != check["value"]


# ------------------------------------------------------------------ 8. decisions state
_NOT_A_VALUE = re.compile(
    r"(eqs?\.|figs?\.|seed|table|class|S\d|step|ch\.|IP|ISO|IEC|GOST)\s*\(?[\d.,–\s]*$", re.I
)
_NUM = re.compile(r"(?<![\w./·(])[-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?(?![\w])")


def _numbers(v) -> list[float]:
    if isinstance(v, bool):
        return []
    if isinstance(v, int | float):
        return [float(v)]
    if isinstance(v, dict):
        return [x for k in v for x in _numbers(v[k])]
    if isinstance(v, list | tuple):
        return [x for i in v for x in _numbers(i)]
    return []


def _stated(x: float, text: str, pool: list[float]) -> bool:
    digits = len(re.sub(r"\D", "", text.split("e")[0]).lstrip("0")) or 1
    return any(y == x or (y != 0 and float(f"{y:.{digits}g}") == x) for y in pool)


def _unstated(rep: dict) -> list[str]:
    req_pool = _numbers(rep["requirements"])
    out = []
    for d in rep["decisions"]:
        pool = _numbers(d.get("inputs", {})) + req_pool
        for m in _NUM.finditer(d["decision"]):
            if _NOT_A_VALUE.search(d["decision"][max(0, m.start() - 12) : m.start()]):
                continue
            if not _stated(float(m.group()), m.group(), pool):
                out.append(f"{d['id']}: {m.group()} in {d['decision']!r}")
    return out


def _pair_docs() -> list[dict]:
    docs = [tomllib.loads(p.read_text(encoding="utf-8")) for p in sorted(EXAMPLES.glob("*.toml"))]
    for device in DEVICES:
        docs.append(linear_doc(device))
        rot = tomllib.loads((EXAMPLES / "valve_actuator_hold.toml").read_text(encoding="utf-8"))
        rot["one_way"]["type"] = device
        docs.append(rot)
    return docs


def test_every_decision_states_numbers_it_carries():
    """Every number a decision says is in its structured inputs (or is the requirement's
    own), over every example and every holding device on both applications."""
    bad = []
    for doc in _pair_docs():
        try:
            bad += _unstated(report(doc))
        except InfeasibleError:
            continue
    assert not bad, bad[:10]


# ------------------------------------------------------------------ pairs: every device
@pytest.mark.parametrize("device", DEVICES)
@pytest.mark.parametrize("with_duty", [False, True])
def test_every_device_with_the_linear_drive(device, with_duty):
    duty = None
    if with_duty:
        duty = _linear_duty("with")
        duty["segments"].insert(
            0, {"kind": "move", "distance_m": 0.2, "time_s": 10.0, "direction": "against"}
        )
    try:
        rep = report(linear_doc(device, duty))
    except InfeasibleError as e:
        assert e.reasons  # refused with its reasons, never a design that ignores the device
        return
    eta = 1.0 if device == "auto" else ow.passage(device).efficiency
    m = screw_torque_by_hand(1500.0)
    check = next(c for c in rep["checks"] if c["id"] == "motor_rated_torque")
    assert check["value"] == pytest.approx(m / eta, rel=1e-5)
    assert rep["design"]["one_way"]["type"] in ("roller_clutch", "em_clutch", device)
    if with_duty:
        kind = rep["design"]["one_way"]["type"]
        if not ow.passage(kind).back_drivable:
            assert rep["design"]["duty"]["regenerated_per_cycle_J"] == 0.0


@pytest.mark.parametrize("device", DEVICES)
@pytest.mark.parametrize("with_duty", [False, True])
def test_every_device_with_the_rotary_drive(device, with_duty):
    doc = tomllib.loads((EXAMPLES / "valve_actuator_hold.toml").read_text(encoding="utf-8"))
    doc["one_way"]["type"] = device
    doc["rotary"]["torque_Nm"] = 300.0  # light enough for the frame through a worm too
    if with_duty:
        doc["duty"] = {
            "cycles_per_hour": 60,
            "load_inertia_kgm2": 1.0,
            "motor_inertia_kgm2": 0.0002,
            "thermal_time_constant_s": 900,
            "segments": [
                {"kind": "move", "angle_deg": 90, "time_s": 10, "torque_Nm": 250},
                {"kind": "hold", "time_s": 20},
                {"kind": "move", "angle_deg": 90, "time_s": 10, "direction": "with"},
                {"kind": "dwell", "time_s": 10},
            ],
        }
    rep = report(doc)  # every device carries 300 N·m within the frame
    kind = rep["design"]["one_way"]["type"]
    p = ow.passage(kind)
    ids = {c["id"] for c in rep["checks"]}
    assert ("motor_losses_with_one_way" in ids) == (p.efficiency < 1.0)
    if with_duty:
        d = rep["design"]["duty"]
        assert kind.replace("_", " ") in d["held_by"]
        hold = next(ph for ph in d["phases"] if ph["name"] == "2 hold")
        assert hold["torque_Nm"] == 0.0  # the device holds, not the motor
        if not p.back_drivable:
            assert 0.0 <= d["regenerated_per_cycle_J"] <= _rotor_energy(rep) * (1 + 1e-5)
        run = next(ph for ph in d["phases"] if ph["name"] == "1 move: run")
        q, eta = d["ratio"], rep["design"]["gearbox"]["efficiency"]
        assert run["torque_Nm"] == pytest.approx(250.0 / (q * eta) / p.efficiency, rel=1e-4)


# ------------------------------------------------------------------ the emergency stop
def test_linear_holding_device_is_sized_for_the_emergency_stop():
    """Tr20x4 (4 starts) with a roller clutch, 1500 N rated, 4500 N in an emergency stop:
    the thread torque grows with the force, 5.375·4500/1500 = 16.12 N·m; the clutch is sized
    for it and says so. No check restates the sizing (it could only say 1.000: a knife edge
    that a 1e-9 change of the force flips). A stop below the rated force leaves the device
    at the rated 5.375 N·m."""
    doc = linear_doc("roller_clutch")
    doc["linear"]["emergency_stop_force_N"] = 4500.0
    rep = report(doc)
    m = screw_torque_by_hand(1500.0)
    assert rep["design"]["one_way"]["torque_Nm"] == pytest.approx(m * 3.0, rel=1e-5)
    assert "sized for the emergency stop's 4500 N" in rep["design"]["one_way"]["basis"]
    assert not any(c["id"] == "one_way_holds_emergency_stop" for c in rep["checks"])
    for f in (1 - 1e-9, 1 + 1e-9):  # no knife edge
        moved = copy.deepcopy(doc)
        moved["linear"]["emergency_stop_force_N"] = 4500.0 * f
        assert report(moved)["design"]["one_way"]["type"] == "roller_clutch"
    doc["linear"]["emergency_stop_force_N"] = 1000.0
    rep = report(doc)
    assert rep["design"]["one_way"]["torque_Nm"] == pytest.approx(m, rel=1e-5)


def test_linear_device_carries_the_thrust_collar_too():
    """A collar of 30 mm mean diameter, μc = 0.08, at 1500 N adds 1500·0.08·0.015 = 1.8 N·m:
    the device at the motor side passes thread and collar torque, 5.375 + 1.8 N·m."""
    doc = linear_doc("roller_clutch")
    doc["screw"]["thrust"] = {
        "kind": "collar",
        "mean_diameter_mm": 30.0,
        "friction_coefficient": 0.08,
    }
    rep = report(doc)
    m = screw_torque_by_hand(1500.0) + 1500.0 * 0.08 * 0.015
    assert rep["design"]["one_way"]["torque_Nm"] == pytest.approx(m, rel=1e-5)


def test_linear_regenerated_energy_goes_to_the_supply():
    """An em clutch (energised, back-drivable) lets the load drive the motor down: the energy
    comes back and, on the line, goes to the mains — nothing to size on a DC bus."""
    duty = _linear_duty("with")
    duty["segments"].insert(
        0, {"kind": "move", "distance_m": 0.2, "time_s": 10.0, "direction": "against"}
    )
    rep = report(linear_doc("em_clutch", duty))
    d = rep["design"]["duty"]
    assert d["regenerated_per_cycle_J"] > 0.0
    assert d["regenerated_to"].startswith("the supply")


# ------------------------------------------------------------------ IEC duty types meet holding
def test_linear_iec_duty_with_a_back_driving_screw_needs_a_holder():
    """S3 run-then-rest of Tr20x4 (4 starts, back-driving efficiency 0.62) with nothing to
    hold it: the same verdict as a cycle of segments — refused, naming why."""
    duty = {"duty_type": "S3", "cyclic_duration_factor": 0.4, "moving_mass_kg": 30.0}
    with pytest.raises(InfeasibleError) as e:
        report(linear_doc(None, duty))
    assert "back-drives the screw" in " ".join(e.value.reasons)
    held = report(linear_doc("roller_clutch", duty))  # with the clutch it is a design
    assert held["design"]["duty"]["held_by"] == "the roller clutch at the motor side"


def test_an_electric_stop_returns_nothing_to_the_supply():
    """S5 stops each run by DC injection below synchronous speed: the kinetic energy heats
    the rotor, none reaches the mains (and none could through the worm)."""
    duty = {
        "duty_type": "S5",
        "cyclic_duration_factor": 0.4,
        "starts_per_hour": 60,
        "moving_mass_kg": 30.0,
    }
    rep = report(linear_doc("worm", duty))
    d = rep["design"]["duty"]
    assert any(p["name"] == "electric brake" and p["torque_Nm"] < 0 for p in d["phases"])
    assert d["regenerated_per_cycle_J"] == 0.0
    assert "regenerated_to" not in d


def test_a_check_under_a_service_factor_states_it():
    from advisor.applications.linear.advice import _describe
    from advisor.calc.checks import Check
    from advisor.core.cite import cite

    c = Check(
        "buckling", "buckling", 3500.0, 3707.0, "N", 3707.0 / (1.5 * 3500.0), cite("seed-001"), 1.5
    )
    text = _describe(c)
    assert "3500 N × service factor 1.5 against the limit 3707 N (margin 0.706)" in text


# ------------------------------------------------------------------ the reducer under a device
def _valve_worm(location: str, duty: dict | None) -> dict:
    doc = tomllib.loads((EXAMPLES / "valve_actuator_hold.toml").read_text(encoding="utf-8"))
    doc["one_way"] = {"type": "worm", "location": location}
    doc["motor"]["frame"] = "auto"
    if duty is not None:
        doc["duty"] = duty
    return doc


def test_a_worm_at_the_motor_side_leaves_the_reducer_its_own_load():
    """S1 at the rated 1000 N·m: the worm sits before the reducer, so the output stage
    carries T_av = 1000 N·m (not 1000/0.3311 = 3020), the torque it is sized for."""
    rep = report(_valve_worm("motor_side", {"duty_type": "S1", "load_inertia_kgm2": 1.0}))
    load = rep["design"]["reducer_load"]
    assert load["mean_torque_Nm"] == pytest.approx(1000.0, rel=1e-9)
    assert load["rated_torque_Nm"] == pytest.approx(1000.0, rel=1e-9)


def test_a_worm_at_the_output_makes_the_reducer_deliver_its_input_torque():
    """At the output the worm sits between the load and the reducer: the reducer delivers
    1000/0.3311 = 3020 N·m into it at the rated point, and is sized for that; a run at 800 N·m
    asks 800/0.3311 = 2416 N·m of it; in a hold the worm holds the load at the output and the
    reducer carries nothing."""
    duty = {
        "cycles_per_hour": 60,
        "load_inertia_kgm2": 1.0,
        "segments": [
            {
                "kind": "move",
                "angle_deg": 90,
                "time_s": 20,
                "accel_fraction": 0.1,
                "torque_Nm": 800,
            },
            {"kind": "hold", "time_s": 20},
            {"kind": "dwell", "time_s": 10},
        ],
    }
    rep = report(_valve_worm("output_side", duty))
    load = rep["design"]["reducer_load"]
    assert load["rated_torque_Nm"] == pytest.approx(1000.0 / WORM_ETA, rel=1e-5)
    phases = list(zip(load["phases_torque_Nm"], load["phases_time_s"], strict=True))
    run = next(t for t, dt in phases if dt == pytest.approx(16.0))  # 20 s less two 2 s ramps
    assert run == pytest.approx(800.0 / WORM_ETA, rel=1e-5)
    hold = next(t for t, dt in phases if dt == pytest.approx(20.0) and t == 0.0)
    assert hold == 0.0


# ------------------------------------------------------------------ a catalog motor, end to end
def test_a_catalog_bldc_motor_gives_a_written_report(tmp_path, capsys):
    """A motor of the user's bldc_motors.toml states no core losses: eq. (10) has no optimum,
    and the report says so (no infinite number in the file), through the real command."""
    from advisor.cli import main

    cat = tmp_path / "cat"
    cat.mkdir()
    (cat / "bldc_motors.toml").write_text(
        '[sources]\nacme-2024 = "ACME frameless kit datasheet, 2024"\n\n[[motor]]\n'
        'name = "ACME-K40"\ncontinuous_torque_Nm = 1.0\npeak_torque_Nm = 3.0\n'
        "rated_speed_rpm = 6000\nphase_resistance_ohm = 0.5\ntorque_constant_Nm_A = 0.1\n"
        "rotor_inertia_kgm2 = 2e-5\nmass_kg = 0.3\nouter_diameter_mm = 40\nlength_mm = 60\n"
        'thermal_time_constant_s = 400\nsource = "acme-2024"\n',
        encoding="utf-8",
    )
    req = tmp_path / "r.toml"
    req.write_text(
        '[application]\nkind = "rotary"\n[rotary]\ntorque_Nm = 400\nspeed_rpm = 5\n'
        '[motor]\nkind = "bldc"\nframe = "ACME-K40"\ncandidate_speeds_rpm = [6000]\n',
        encoding="utf-8",
    )
    out = tmp_path / "o.toml"
    assert main(["--batch", str(req), "--catalog-dir", str(cat), "-o", str(out)]) == 0
    rep = tomllib.loads(out.read_text(encoding="utf-8"))
    assert "optimum_speed_rpm" not in rep["design"]["motor"]
    bl02 = next(d for d in rep["decisions"] if d["id"] == "BL-02")
    assert "no minimum" in bl02["rationale"] and "inf" not in bl02["rationale"]
    capsys.readouterr()


def test_the_html_datasheet_shows_control_characters_escaped():
    """ESC, NUL and a right-to-left override in a title and a [project] field reach the page
    escaped (\\x1b, \\x00, \\u202e), never raw."""
    from advisor.datasheet import render

    doc = tomllib.loads((EXAMPLES / "linear_screw_actuator.toml").read_text(encoding="utf-8"))
    doc["application"]["title"] = "A\x1b[2J\x00B\u202eC"
    doc["project"] = {"author": "X\u202eY\x07"}
    page = render(advise(parse_requirements(doc)), "html")
    assert not any(ch in page for ch in "\x1b\x00\u202e\x07")
    assert "A\\x1b[2J\\x00B\\u202eC" in page


def test_at_the_working_point_the_reducer_delivers_what_an_output_device_asks():
    """No duty cycle: the braking-profile gear (η 0.45) at the output asks 1000/0.45 =
    2222.2 N·m of the reducer's output stage, which is sized for it."""
    doc = tomllib.loads((EXAMPLES / "valve_actuator_hold.toml").read_text(encoding="utf-8"))
    doc["one_way"] = {"type": "inverse_gear", "location": "output_side"}
    doc["motor"]["frame"] = "auto"
    load = report(doc)["design"]["reducer_load"]
    assert load["mean_torque_Nm"] == pytest.approx(1000.0 / 0.45, rel=1e-5)
    assert load["rated_torque_Nm"] == pytest.approx(1000.0 / 0.45, rel=1e-5)
