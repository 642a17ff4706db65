"""How the datasheet and the family study name and print what the report holds: a
multi-start screw by its full designation, units of every key suffix, tables of a
decision's inputs, the requirements at their defaults, an infeasible report's rows."""

import math

import pytest
from helpers import EXAMPLES, seed001_requirement

from advisor.applications.linear.family import key_outputs
from advisor.calc.checks import Check
from advisor.core.cite import cite
from advisor.core.engine import advise
from advisor.core.errors import InfeasibleError
from advisor.core.reading import parse_requirements, read_requirements
from advisor.datasheet import _sheet, render
from advisor.datasheet.content import input_value
from advisor.datasheet.labels import REPORT_LABELS, for_application, number, split_key
from advisor.infeasible import infeasible_report

pytest.importorskip("matplotlib")


def _four_start_screw() -> dict:
    """Seed 001's actuator held without power by a roller clutch, 3 s asked, four starts
    imposed: the joint choice takes Tr14x2 with four starts."""
    data = seed001_requirement(friction_coefficient=0.06, starts=4)
    data["application"]["hold_without_power"] = True
    data["linear"]["travel_time_s"] = 3
    data["one_way"] = {"type": "roller_clutch"}
    return data


def test_a_multi_start_screw_is_named_with_its_lead_everywhere():
    # GOST 24739-81: a multi-start trapezoidal thread is written Tr d x lead (P pitch);
    # Tr14x2 with 4 starts: lead = 4 × 2 mm = 8 mm, so Tr14x8(P2).
    report = advise(parse_requirements(_four_start_screw()))
    sheet, doc = _sheet(report)
    screw = doc["design"]["screw"]
    assert (screw["thread"], screw["starts"], screw["lead_mm"]) == ("Tr14x2", 4, 8)
    assert screw["designation"] == "Tr14x8(P2)"
    # the family's column: a change of starts is a change of screw
    assert key_outputs(doc)["screw_thread"] == "Tr14x8(P2)"
    parts = {r[0]: r for r in sheet.parts}
    assert parts["screw"][1] == "Tr14x8(P2)" and "lead 8 mm" in parts["screw"][3]
    # the warning that no lead suits names the finest passing screw the same way
    too_fast = next(w for w in doc["warnings"] if "No lead suits" in w)
    assert "is 8 mm (Tr14x8(P2))" in too_fast


def _positioning(duty: bool) -> dict:
    """Two listed motors, a 90° move of 2 kg·m² against 20 N·m within 0.8 s; with a
    3 s cycle where ``duty``."""
    data = {
        "application": {"kind": "positioning"},
        "positioning": {
            "profile": "triangular",
            "travel_rad": math.pi / 2,
            "load_inertia_kgm2": 2.0,
            "load_torque_Nm": 20.0,
            "move_time_s": 0.8,
            "motors": [
                {
                    "name": "A",
                    "speed_rad_s": 50 * math.pi,
                    "inertia_kgm2": 0.001,
                    "accel_torque_Nm": 9.0,
                    "rated_torque_Nm": 3.0,
                },
                {
                    "name": "B",
                    "speed_rad_s": 300.0,
                    "inertia_kgm2": 0.004,
                    "accel_torque_Nm": 20.0,
                    "rated_torque_Nm": 7.0,
                },
            ],
        },
    }
    if duty:
        data["duty"] = {"cycle_time_s": 3.0}
    return data


@pytest.mark.parametrize("duty", [False, True])
def test_the_required_move_time_is_checked_against_the_move(duty):
    report = advise(parse_requirements(_positioning(duty)))
    sheet, doc = _sheet(report)
    i = doc["design"]["motion"]["optimal_ratio"]  # the duty cycle keeps it: 19.299
    # seed 003, eq. (4), motor A (ω0 = 1500 rpm = 157.08 rad/s, J0 = 0.001 kg·m²,
    # M_λ = 9 N·m) at its ratio i = 19.299: I = J_p/J0 = 2000, m = M_p/M_λ = 20/9,
    # t = α·i/ω0 + ω0·J0/M_λ·(i² + I)/(i² − m²) = 0.19299 + 0.017453·6.4554 = 0.30566 s
    w0, m = 50 * math.pi, 20 / 9
    t = (math.pi / 2) * i / w0 + w0 * 0.001 / 9 * (i * i + 2000) / (i * i - m * m)
    assert t == pytest.approx(0.305658, rel=1e-5)
    check = next(c for c in doc["checks"] if c["id"] == "move_time")
    assert check["value"] == pytest.approx(t, rel=1e-5) and check["limit"] == 0.8
    assert check["margin"] == pytest.approx(0.8 / 0.305658, rel=1e-5)  # 2.617
    row = next(r for r in sheet.required if r.path == "positioning.move_time_s")
    assert (row.check_id, row.achieved, row.margin) == (
        "move_time",
        "0.3057 against 0.8 s",
        "2.617",
    )


def test_without_a_required_move_time_no_move_time_check():
    data = _positioning(duty=True)
    del data["positioning"]["move_time_s"]
    report = advise(parse_requirements(data))
    sheet, doc = _sheet(report)
    assert "move_time" not in {c["id"] for c in doc["checks"]}
    assert "positioning.move_time_s" not in {r.path for r in sheet.required}


#: The unit tokens a key's suffix is built of (docs/reference/units.md, the report's own).
UNIT_TOKENS = {
    "N", "Nm", "m", "mm", "mm2", "m2", "cm3", "s", "h", "rpm", "Hz", "kg", "kgm2", "m3", "W",
    "kW", "kN", "A", "V", "T", "K", "J", "MPa", "ohm", "rad", "deg", "pct", "uF", "hour",
}  # fmt: skip


def _keys(x, out: set[str]) -> set[str]:
    if isinstance(x, dict):
        for k, v in x.items():
            out.add(k)
            _keys(v, out)
    elif isinstance(x, list):
        for v in x:
            _keys(v, out)
    return out


def test_unit_suffixes_read_as_their_units():
    # the nut's p·v: 8.25248 MPa × 1.09456 m/s = 9.033 MPa·m/s, a product, not a speed
    assert split_key("pv_MPa_m_s") == ("p·v", "MPa·m/s")
    assert split_key("bus_voltage_V") == ("bus voltage", "V")
    assert split_key("bus_max_voltage_V") == ("bus max voltage", "V")
    assert split_key("capacitance_for_largest_uF") == ("capacitance for largest", "µF")
    assert split_key("sliding_speed_m_s") == ("sliding speed", "m/s")
    assert split_key("angular_momentum_kgm2_s") == ("angular momentum", "kg·m²/s")


def test_every_key_of_every_example_report_has_its_unit():
    """A key ending in a unit token has a unit, and no unit token is left in its label
    (``pv MPa`` with m/s, ``bus voltage V`` without a unit were the failures)."""
    keys: set[str] = set()
    for path in sorted(EXAMPLES.glob("*.toml")):
        _keys(_sheet(advise(read_requirements(path)))[1], keys)
    assert {"pv_MPa_m_s", "bus_voltage_V", "capacitance_for_largest_uF"} <= keys
    wrong = []
    for k in sorted(keys):
        if k in REPORT_LABELS or "_" not in k:
            continue
        label, unit = split_key(k)
        if k.split("_")[-1] in UNIT_TOKENS and not unit:
            wrong.append((k, label, unit))
        if label.split()[-1] in UNIT_TOKENS:
            wrong.append((k, label, unit))
    assert wrong == []


def test_requirement_rows_have_the_units_of_their_keys():
    labels, _ = for_application("rotary")
    assert labels[("drive", "bus_voltage_V")] == ("nominal DC-bus voltage", "V")
    assert labels[("drive", "bus_capacitance_uF")][1] == "µF"
    assert labels[("duty", "cycles_per_hour")][1] == "1/h"


def test_a_table_among_a_decisions_inputs_is_printed():
    report = advise(read_requirements(EXAMPLES / "positioning_drive.toml"))
    sheet, doc = _sheet(report)
    mo02 = next(d for d in sheet.decisions if d.id == "MO-02")
    times = next(d for d in doc["decisions"] if d["id"] == "MO-02")["inputs"]["move_time_s"]
    # the report's move times 1.20588, 1.15159, 1.02287 s, four significant digits
    assert times == {"A": 1.20588, "B": 1.15159, "C": 1.02287}
    assert mo02.inputs == "motor = C; move_time_s = (A = 1.206, B = 1.152, C = 1.023)"
    assert "{…}" not in render(report, "md")


def test_a_long_table_of_inputs_is_cut_with_a_count():
    # 20 items: the first 8 (INPUT_ITEMS) and "… 12 more"
    long = {f"m{n}": float(n) for n in range(20)}
    text = input_value(long)
    assert text.startswith("(m0 = 0, m1 = 1,") and text.endswith("m7 = 7, … 12 more)")
    assert input_value({"rows": [{"a": 1}, {"a": 2}]}) == "(rows = [(a = 1), (a = 2)])"


def test_a_list_of_tables_at_its_default_counts_as_at_its_default():
    # rudder_actuator gives no motor.reference.magnet_losses: the model's default
    # [{5000 rpm, 60 W}, {10000 rpm, 100 W}] is in the report's requirements; with the 31
    # other fields at their defaults it makes 32
    report = advise(read_requirements(EXAMPLES / "rudder_actuator.toml"))
    sheet, doc = _sheet(report)
    lines = (EXAMPLES / "rudder_actuator.toml").read_text().splitlines()
    assert not any("magnet_losses" in line.split("#")[0] for line in lines)
    given = doc["requirements"]["motor"]["reference"]["magnet_losses"]
    assert given == [{"speed_rpm": 5000.0, "loss_W": 60.0}, {"speed_rpm": 10000.0, "loss_W": 100.0}]
    assert "motor.reference.magnet_losses" not in {r.path for r in sheet.required}
    assert sheet.at_default == 32


def _infeasible(path):
    """The infeasible report the batch writes for ``path``."""
    req = read_requirements(path)
    with pytest.raises(InfeasibleError) as exc:
        advise(req)
    return infeasible_report(req, exc.value)


def _infeasible_sheet(exc: InfeasibleError):
    report = infeasible_report(read_requirements(EXAMPLES / "linear_screw_actuator.toml"), exc)
    return _sheet(report)


def test_an_infeasible_report_without_a_design_says_its_checks_were_not_reached():
    sheet, _ = _sheet(_infeasible(EXAMPLES / "infeasible" / "screw_buckles.toml"))
    rows = {r.path: r for r in sheet.required}
    force = rows["linear.force_N"]  # covered by core_stress, buckling, nut_* in a design
    assert force.check == "not reached: the requirement is infeasible (see why)"
    assert force.status == "unreached" and force.achieved == ""
    assert not any(r.check == "no check covers this requirement" for r in sheet.required)
    md = render(_infeasible(EXAMPLES / "infeasible" / "screw_buckles.toml"), "md")
    assert "No check: no design was reached (see why in the Summary)." in md
    assert "| check | utilisation |" not in md


@pytest.mark.parametrize("path", sorted((EXAMPLES / "infeasible").glob("*.toml")), ids=str)
def test_an_infeasible_report_says_why_its_sections_are_empty(path):
    # no design: no component, no check, no decision; each section says so in one line
    # (as Utilisation does) instead of a bare table header or an empty heading
    report = _infeasible(path)
    assert not (report.checks or report.decisions)
    said = "no design was reached (see why in the Summary)."
    md = render(report, "md")
    for what, next_heading in (
        ("component", "## Checks"),
        ("check", "## Probability of passing"),
        ("decision", "## Requirements (SI)"),
    ):
        assert f"\n\nNo {what}: {said}\n\n{next_heading}\n" in md
    assert "|  | check | value | limit | unit | margin | source |" not in md
    html = render(report, "html")
    for what, section in (
        ("component", "components"),
        ("check", "checks"),
        ("decision", "decisions"),
    ):
        assert f'<section id="{section}"><h2>' in html
        body = html.split(f'<section id="{section}">', 1)[1].split("</section>", 1)[0]
        assert f"<p>No {what}: {said}</p>" in body
    assert "<th>margin</th><th>source</th></tr></table>" not in html


def test_an_infeasible_report_with_checks_maps_them():
    # the nearest design's failing check: 15 nut turns where 10 are allowed, margin 10/15
    bad = Check("nut_turns", "engaged nut turns", 15.0, 10.0, "", 10.0 / 15.0, cite("GOST"))
    exc = InfeasibleError("no feasible design: the chosen parts fail checks", ["x"], checks=[bad])
    sheet, _ = _infeasible_sheet(exc)
    force = next(r for r in sheet.required if r.path == "linear.force_N")
    assert (force.check_id, force.achieved, force.margin) == ("nut_turns", "15 against 10", "0.667")
    assert force.status == "fails"


def test_an_empty_requirement_table_heads_nothing():
    report = advise(read_requirements(EXAMPLES / "linear_screw_actuator.toml"))
    sheet, doc = _sheet(report)
    assert doc["requirements"]["design"] == {}  # the report's empty [requirements.design]
    assert "design" not in {b.title for b in sheet.requirements}
    assert "### design\n" not in render(report, "md")


def test_a_value_the_report_rounded_to_a_tie_is_not_rounded_again():
    # seed 001's screw whirls at n_cr = 10282.524 rpm: the check's source says 10283 (one
    # rounding), the report stores 10282.5 (six digits); rounding that again to 4 digits
    # would say 10282 (half to even), so the datasheet keeps the stored digit
    report = advise(read_requirements(EXAMPLES / "linear_screw_actuator.toml"))
    sheet, doc = _sheet(report)
    assert doc["design"]["screw"]["critical_speed_rpm"] == 10282.5
    screw = next(b for b in sheet.components if b.title == "screw")
    assert ("critical speed", "10282.5", "rpm") in screw.rows
    assert number(10282.4) == "10282" and number(10282.6) == "10283"
