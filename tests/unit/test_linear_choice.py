"""The linear drive's joint choice of thread, starts and motor (issue 12, items 3–5):
decisions state the design's numbers, more force never gives a smaller drive, and no design
sits on a knife edge."""

import math
import tomllib

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from advisor.calc.sizing import ScrewMaterial, evaluate_thread
from advisor.core.engine import advise
from advisor.core.errors import InfeasibleError
from advisor.core.reading import parse_requirements
from advisor.core.report import to_toml
from catalogs import load_catalogs
from rules import screw as screw_rules

finite = dict(allow_nan=False, allow_infinity=False)
PAIRS = ["steel_bronze", "hardened_steel_bronze", "steel_cast_iron", "steel_steel"]
SLOW = settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def _req(force_N, stroke_m, travel_time_s, span_m, *, hold=False, pair="steel_bronze", **screw):
    return {
        "application": {"kind": "linear", "hold_without_power": hold},
        "linear": {
            "force_N": force_N,
            "stroke_m": stroke_m,
            "travel_time_s": travel_time_s,
            "support_span_m": span_m,
        },
        "motor": {"kind": "induction"},
        "screw": {"material_pair": pair, **screw},
    }


@st.composite
def linear_requirements(draw):
    """Across the documented ranges (models.LinearReq), kept to where designs exist."""
    stroke = draw(st.floats(0.001, 3.0, **finite))
    req = _req(
        draw(st.floats(1.0, 2e5, **finite)),
        stroke,
        draw(st.floats(0.05, 500.0, **finite)),
        stroke * draw(st.floats(1.0, 3.0, **finite)),
        hold=draw(st.booleans()),
        pair=draw(st.sampled_from(PAIRS)),
    )
    if draw(st.booleans()):
        req["screw"]["starts"] = draw(st.integers(1, 4))
    return req


def _report(data):
    try:
        return tomllib.loads(to_toml(advise(parse_requirements(data))))
    except InfeasibleError:
        return None


def _drive(rep):
    s, m = rep["design"]["screw"], rep["design"]["motor"]
    return (s["thread"], s["starts"], s["nut"]["turns"], m["model"], m["pole_pairs"])


# ------------------------------------------------------------------ item 3
@SLOW
@given(linear_requirements())
def test_every_decision_states_the_designs_values(data):
    rep = _report(data)
    if rep is None:
        return
    d = {x["id"]: x.get("inputs", {}) for x in rep["decisions"]}
    s, m = rep["design"]["screw"], rep["design"]["motor"]
    assert d["SCR-02"]["friction_coefficient"] == s["friction_coefficient"]
    assert d["SCR-02"]["range"] == s["friction_range"]
    assert d["SCR-03"]["friction_model"] == s["friction_model"]
    assert d["SCR-04"]["thread"] == s["thread"]
    assert d["SCR-04"]["starts_chosen"] == s["starts"]
    assert d["SCR-04"]["motor"] == m["model"]
    assert d["SCR-04"]["rated_power_kW"] == m["rated_power_kW"]
    assert d["SCR-04"]["pole_pairs"] == m["pole_pairs"]
    if "self_locking" in d["SCR-05"]:
        assert d["SCR-05"]["self_locking"] == s["self_locking"]
    else:
        sl = d["SCR-05"]["self_locking_at_low_friction"]
        assert sl == s["self_locking_at_low_friction"]
    assert d["IM-01"]["pole_pairs"] == m["pole_pairs"]
    im2 = d["IM-02"]
    assert im2["required_power_kW"] == m["required_power_kW"]
    assert im2["working_power_kW"] == m["working_power_kW"]
    assert im2["rated_power_kW"] == m["rated_power_kW"]
    assert im2["band_kW"] == [c["rated_power_kW"] for c in m["candidates"]]
    selected = next(c for c in m["candidates"] if c["role"] == "selected")
    assert d["IM-03"]["model"] == m["model"] == selected["model"]
    assert d["IM-03"]["rated_power_kW"] == m["rated_power_kW"]
    assert d["IM-03"]["rated_torque_margin"] == selected["rated_torque_margin"]
    # and the prose says the same
    im2_text = next(x["decision"] for x in rep["decisions"] if x["id"] == "IM-02")
    assert im2_text.startswith(f"Rated power {m['rated_power_kW']:g} kW")
    assert ", ".join(f"{c['rated_power_kW']:g}" for c in m["candidates"]) in im2_text


def test_issue_repro_power_decision_is_the_motors():
    # 40 kN, 0.4 m in 20 s, span 1.2 m: the design's motor is 15 kW (11/15/18.5 kW); the
    # decision used to say 3 kW with 2.2/3/4 kW, the power at the screw's required speed.
    rep = _report(_req(40000, 0.4, 20, 1.2))
    m = rep["design"]["motor"]
    im2 = next(x for x in rep["decisions"] if x["id"] == "IM-02")
    assert m["rated_power_kW"] == 15.0
    assert im2["decision"] == "Rated power 15 kW, with neighbours 11, 15, 18.5 kW."
    # the screw needs M·n_req = 165.33 N·m × 150 rpm = 2.597 kW; the motor runs it at its own
    # working speed (≈ 734 rpm), where the load takes ≈ 12.7 kW
    assert m["required_power_kW"] == pytest.approx(165.331 * 150 * math.pi / 30 / 1e3, rel=1e-4)
    assert im2["inputs"]["working_power_kW"] == m["working_power_kW"]


# ------------------------------------------------------------------ item 4
@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    linear_requirements(),
    st.lists(st.floats(1.0, 2e5, **finite), min_size=2, max_size=6, unique=True),
)
def test_more_force_never_gives_a_smaller_motor(data, forces):
    """A heavier load never finds a smaller drive that a lighter one missed. Most checks get
    harder with the force, so the smallest motor usually cannot shrink and, with the same
    motor, the lightest screw it drives cannot get thinner. The exception is speed: an
    induction motor runs faster under a lighter load (less slip), so a thread that turns
    below 80 % of its whirling speed under the heavier load can turn above it under the
    lighter one (1 N against 24 N, 1 m in 2 s over a 2.94 m span: 0.37 kW and 85 mm, then
    0.18 kW and 100 mm). So where the drive steps back, the heavier load's thread imposed at
    the lighter load must fail or need at least the lighter load's motor: otherwise the
    choice at the lighter load missed it. (When the motor steps up to a faster pole count
    the thread may get thinner: see docs/reference/departures.md, "Thread and motor chosen
    together".) Holding without power is left out: there a self-locking screw comes first,
    and when the last one fails, a smaller motor with a one-way device may take over."""
    data["application"]["hold_without_power"] = False
    last = None  # the previous force and its drive (None: infeasible)
    for f in sorted(forces):
        data["linear"]["force_N"] = f
        rep = _report(data)
        if rep is None:
            last = (f, None)
            continue
        s, m = rep["design"]["screw"], rep["design"]["motor"]
        cur = ((m["rated_power_kW"], m["rated_torque_Nm"]), s["nominal_diameter_mm"])
        if last is not None and (last[1] is None or cur < last[1]):
            _assert_missed_nothing(data, last[0], s, last[1])
        last = (f, cur)


def _assert_missed_nothing(data, lighter_N, screw, lighter_drive):
    """The thread chosen under a heavier load, imposed under the lighter load ``lighter_N``:
    infeasible there, or a drive (motor, then screw) no smaller than the lighter load's own
    choice."""
    imposed = {
        **data,
        "linear": {**data["linear"], "force_N": lighter_N},
        "screw": {**data["screw"], "thread": screw["thread"], "starts": screw["starts"]},
    }
    rep = _report(imposed)
    if rep is None or lighter_drive is None:
        assert rep is None, "a design the lighter load's choice called infeasible"
        return
    m, s = rep["design"]["motor"], rep["design"]["screw"]
    drive = ((m["rated_power_kW"], m["rated_torque_Nm"]), s["nominal_diameter_mm"])
    assert drive >= lighter_drive, (lighter_drive, drive)


def test_issue_repro_forces_give_a_monotonic_drive():
    # the force steps of issue 12 on the 40 kN case's geometry: neither the motor nor the
    # thread steps back as the force rises
    prev = None
    for f in (4297, 5013, 8176, 8920, 11150, 20000, 40000):
        rep = _report(_req(f, 0.4, 20, 1.2))
        m, s = rep["design"]["motor"], rep["design"]["screw"]
        cur = ((m["rated_power_kW"], m["rated_torque_Nm"]), s["nominal_diameter_mm"])
        if prev:
            assert cur[0] >= prev[0] and cur[1] >= prev[1]
        prev = cur


def test_smallest_motor_first_then_lightest_screw():
    def opt(thread, d, power, torque, *, starts=1, locking=True):
        return screw_rules.DriveOption(
            thread, d, 2.0, starts, locking, 1.0, f"M{power}", 2, power, torque, 3.0
        )

    light_big = opt("Tr16x2", 16, 1.1, 7.4)
    heavy_small = opt("Tr20x4", 20, 0.75, 10.2)
    heavier_small = opt("Tr22x5", 22, 0.75, 10.2)
    f = screw_rules.choose_drive([light_big, heavier_small, heavy_small], False, None, None)
    assert f.value is heavy_small
    assert f.inputs["runners_up"][0].startswith("Tr22x5")
    # same power: the smaller rated torque (the faster motor, a smaller frame) wins
    fast = opt("Tr30x6", 30, 0.75, 5.2)
    assert screw_rules.choose_drive([heavy_small, fast], False, None, None).value is fast
    # holding without power: a screw that holds by itself comes before a smaller motor
    slipping = opt("Tr16x4", 16, 0.37, 2.6, starts=2, locking=False)
    assert screw_rules.choose_drive([slipping, heavy_small], True, None, None).value is heavy_small
    assert screw_rules.choose_drive([slipping, heavy_small], False, None, None).value is slipping
    assert screw_rules.thread_label("Tr16x4", 2) == "Tr16x8(P4)"


def test_multi_start_when_the_starts_are_free():
    # 2 kN, 1 m in 3 s (0.333 m/s), span 1.2 m, bronze nut. One start needs a 20 mm lead to
    # run a 1000 rpm motor, which only coarse, heavy threads have; with the starts free the
    # advisor may cut several starts on a lighter screw. With one start imposed, the drive
    # can only be the same or bigger.
    free = _report(_req(2000, 1.0, 3, 1.2))
    one = _report(_req(2000, 1.0, 3, 1.2, starts=1))
    fm, om = free["design"]["motor"], one["design"]["motor"]
    fs, os_ = free["design"]["screw"], one["design"]["screw"]
    assert (fm["rated_power_kW"], fm["rated_torque_Nm"]) <= (
        om["rated_power_kW"],
        om["rated_torque_Nm"],
    )
    if (fm["rated_power_kW"], fm["rated_torque_Nm"]) == (
        om["rated_power_kW"],
        om["rated_torque_Nm"],
    ):
        assert fs["nominal_diameter_mm"] <= os_["nominal_diameter_mm"]
    assert fs["lead_mm"] == fs["pitch_mm"] * fs["starts"]
    assert fm["travel_time_s"] <= 3


def test_no_lead_suits_says_so_and_what_a_reducer_saves():
    rep = _report(_req(40000, 0.4, 20, 1.2))
    w = " ".join(rep["warnings"])
    # 0.02 m/s at the slowest catalog motor (4A80A8, 675 rpm) needs a lead of
    # 0.02·60/675 = 1.78 mm; the finest lead that carries 40 kN is 8 mm (Tr46x8)
    assert "No lead suits" in w and "1.78 mm" in w and "8 mm (Tr46x8)" in w
    # with a reducer the screw's 2.597 kW / 0.97 = 2.68 kW needs a 3 kW motor, not 15 kW
    assert "3 kW motor (2.68 kW needed)" in w and "instead of 15 kW" in w


# ------------------------------------------------------------------ item 5
def _material(p_MPa):
    return ScrewMaterial(0.13, 0.1, p_MPa * 1e6, 355e6, 210e9, 3.0, 1.2, 2.5, 10)


def test_nut_in_whole_turns_off_the_knife_edge():
    # Tr16x2 (d2 = 15 mm, H1 = 1 mm) on a 5 MPa nut at F = 9.5·π·15·1·5 = 2238.4 N needs
    # z = 9.5 turns; sized exactly, its pressure was the limit to the last bit. Whole turns:
    # 10 turns, p = 2238.4/(π·15·1·10) = 4.75 MPa, margin 5/4.75 = 1.0526.
    t = load_catalogs().thread("Tr16x2")
    force = 9.5 * math.pi * 15 * 1 * 5
    for f in (force * (1 - 1e-9), force, force * (1 + 1e-9)):
        ev = evaluate_thread(
            t,
            force_N=f,
            stroke_m=0.2,
            travel_time_s=5,
            span_m=0.4,
            end_fixity="pinned-pinned",
            buckling_safety_factor=3,
            starts=1,
            friction_model="standard",
            material=_material(5),
        )
        assert ev.nut_turns == 10
        nut = next(c for c in ev.checks if c.id == "nut_pressure")
        assert nut.value == pytest.approx(4.75, rel=1e-6)
        assert nut.margin == pytest.approx(5 / 4.75, rel=1e-6)


@SLOW
@given(
    linear_requirements(),
    st.sampled_from(["force_N", "stroke_m", "travel_time_s", "support_span_m"]),
    st.sampled_from([1 - 1e-9, 1 + 1e-9]),
)
def test_a_requirement_perturbed_by_1e_9_gives_the_same_design(data, field, factor):
    rep = _report(data)
    lo, hi = {"force_N": (1, 5e6), "travel_time_s": (0.01, 1e5)}.get(field, (1e-3, 20))
    value = min(max(data["linear"][field] * factor, lo), hi)  # the documented range
    if field == "stroke_m":
        value = min(value, data["linear"]["support_span_m"])
    if field == "support_span_m":
        value = max(value, data["linear"]["stroke_m"])
    data["linear"][field] = value
    moved = _report(data)
    if rep is None:
        assert moved is None
        return
    assert moved is not None
    assert _drive(moved) == _drive(rep)


def test_a_multi_start_screw_is_named_so_in_the_summary_and_the_wizard():
    # the case above: Tr28x8 with 3 starts, lead 3 × 8 = 24 mm (single start: no label)
    from rich.console import Console

    from advisor.applications.linear.report import headline, summary_rows
    from advisor.applications.linear.views import components

    rep = advise(parse_requirements(_req(2000, 1.0, 3, 1.2)))
    s = rep.design.screw
    assert (s.thread, s.starts, s.lead_mm) == ("Tr28x8", 3, 24.0)
    assert headline(rep).startswith("Tr28x8 (3 starts), ")
    assert dict(summary_rows(rep))["screw"].startswith("Tr28x8, 3 starts, lead 24 mm, ")
    console = Console(width=100, record=True)
    for part in components(rep):
        console.print(part)
    assert "3 (lead 24 mm)" in console.export_text()
    one = advise(parse_requirements(_req(2000, 1.0, 3, 1.2, starts=1)))
    assert "starts" not in headline(one) + dict(summary_rows(one))["screw"]


def test_thread_and_starts_reads_a_designation_back():
    """GOST 24739-81: TrD x lead (P pitch); starts = lead / pitch: Tr30x20(P10) is Tr30x10
    with 20 / 10 = 2 starts, Tr24x20(P5) Tr24x5 with 4; a one-start Tr16x2 is itself, 1."""
    assert screw_rules.thread_and_starts("Tr30x20(P10)") == ("Tr30x10", 2)
    assert screw_rules.thread_and_starts("Tr24x20(P5)") == ("Tr24x5", 4)
    assert screw_rules.thread_and_starts("Tr16x2") == ("Tr16x2", 1)
    for thread, starts in (("Tr14x2", 4), ("Tr26x3", 2), ("Tr12x3", 1)):
        label = screw_rules.thread_label(thread, starts)
        assert screw_rules.thread_and_starts(label) == (thread, starts)
