"""Units people type: a numeric requirement field given as a string with a unit is converted
to the unit its key names (issue 17); a wrong dimension or a string that is no quantity is
refused in one line naming the field and the expected unit; pint is imported only when such
a string is present."""

import math
import subprocess
import sys
import tomllib

import pytest
from helpers import EXAMPLES

from advisor.cli import main
from advisor.core.engine import advise
from advisor.core.errors import InputError
from advisor.core.reading import parse_requirements
from advisor.core.report import to_toml
from advisor.core.units import UnitError, to_unit


@pytest.mark.parametrize(
    ("text", "unit", "by_hand"),
    [
        ("5 kN", "N", 5 * 1000.0),
        ("200 mm", "m", 200 / 1000),
        ("1500 rpm", "rad/s", 1500 * 2 * math.pi / 60),  # 157.0796
        ("90 deg", "rad", 90 * math.pi / 180),  # 1.5708
        ("0.5 rad/s", "rpm", 0.5 * 60 / (2 * math.pi)),  # 4.7746
        ("3 in", "mm", 3 * 25.4),
        ("2 h", "s", 2 * 3600.0),
        ("7.8 g/cm^3", "kg/m³", 7.8 * 1e-3 / 1e-6),
        ("1 turn", "rad", 2 * math.pi),
        ("250 N*cm", "N·m", 250 / 100),
    ],
)
def test_conversions_by_hand(text, unit, by_hand):
    assert to_unit(text, unit) == pytest.approx(by_hand, rel=1e-11)


@pytest.mark.parametrize(
    ("text", "unit", "by_hand"),
    [
        # gauss: 1 G = 1e-4 T (SI Brochure, 9th ed., table 9 note): 15000 G = 1.5 T (issue 23)
        ("15000 G", "T", 15000 * 1e-4),
        ("800 mT", "T", 0.8),
        # N·m however it is written (issue 24)
        ("1 kN*m", "N·m", 1000.0),
        ("1 kN·m", "N·m", 1000.0),
        ("1.62 kNm", "N·m", 1620.0),
        ("5 Nm", "N·m", 5.0),
        ("250 N*mm", "N·m", 0.25),
        ("10 lbf*ft", "N·m", 10 * 4.4482216152605 * 0.3048),  # 13.558 N·m (NIST SP 811)
        ("2 kgf", "N", 2 * 9.80665),
        ("3 MN", "N", 3e6),
        ("2 kg*m^2", "kg·m²", 2.0),
        ("2 kg·m²", "kg·m²", 2.0),
        ("2 kg*m**2", "kg·m²", 2.0),
        ("150 kg*cm^2", "kg·m²", 150 * 1e-4),
        ("7.8 g·cm⁻³", "kg/m³", 7800.0),
        ("7800 kg*m^-3", "kg/m³", 7800.0),
        ("32 cSt", "mm²/s", 32.0),
        ("1.5e-5 m^2/s", "m²/s", 1.5e-5),
        ("1.5e-5 m²/s", "mm²/s", 15.0),
        ("30 rev/min", "rpm", 30.0),
        ("3 rps", "rpm", 180.0),
        ("180 °", "rad", math.pi),
        ("90°", "deg", 90.0),
        ("360 deg/s", "rpm", 60.0),
        ("25 µm", "mm", 0.025),
        ("25 um", "mm", 0.025),
        ("2 ft", "m", 0.6096),
        ("1 hp", "kW", 0.74569987158227022),
        ("1 hp", "W", 745.69987158227022),
        ("40 min", "h", 40 / 60),
        ("1 h", "min", 60.0),
        ("2.2 kΩ", "Ω", 2200.0),
        ("2.2 kohm", "Ω", 2200.0),
        ("500 mA", "A", 0.5),
        ("5\u202fkN", "N", 5000.0),  # the thin space of typeset pages (SI Brochure 5.4.3)
        ("-5 kN", "N", -5000.0),  # the sign is the model's to judge
        ("1e-400 N", "N", 0.0),  # underflows to zero: the model's range says why not
    ],
)
def test_spellings_engineers_type(text, unit, by_hand):
    assert to_unit(text, unit) == pytest.approx(by_hand, rel=1e-11, abs=0)


@pytest.mark.parametrize(
    ("text", "unit", "said"),
    [
        # issue 23 item 9: an energy has a torque's dimension but is not one
        ("1620 J", "N·m", "J is an energy, not a torque; expected N·m"),
        ("1 kcal", "N·m", "kcal is an energy, not a torque; expected N·m"),
        ("1 kWh", "N·m", "kWh is an energy, not a torque; expected N·m"),
        ("1620 W*s", "N·m", "W*s is an energy, not a torque; expected N·m"),
        ("5 N*m", "N", "N*m is a torque, not a force; expected N"),
        ("15000 G", "N", "G is a flux density, not a force; expected N"),
        ("5 N m", "N·m", "' m' cannot follow a unit"),  # units are joined by * or ·
        ("5 kg/m/s", "N", "one unit only after '/'"),
        ("5 N^0", "N", "a power is a whole number from -4 to 4, not '^0'"),
        ("5 N^5", "N", "not '^5'"),
        ("5 daN", "N", "'daN' is not a unit known here; units here: N, kN, MN, mN, lbf, kgf"),
        ("5 newton", "N", "'newton' is not a unit known here"),
        ("0,5 kN", "N", "',' is not allowed"),
        ("5 kN\n", "N", "U+000A (a control character) is not allowed"),
        ("5 kN\u200f", "N", "U+200F (RIGHT-TO-LEFT MARK) is not allowed"),
        ("5 N" + "m" * 70, "N", "at most 64 characters"),
        ("1 m", "", "m is a length, not a pure number; expected a pure number"),
    ],
)
def test_what_the_grammar_refuses(text, unit, said):
    with pytest.raises(UnitError) as err:
        to_unit(text, unit)
    assert said in str(err.value)


def test_every_field_unit_is_read_by_the_grammar():
    """Every unit a requirement key names converts to itself: 1 of it is 1."""
    from advisor.core.questions import UNIT_SUFFIXES

    for unit in [*UNIT_SUFFIXES.values(), "min", "kW"]:
        assert to_unit(f"1 {unit}", unit) == 1.0, unit


def test_the_unit_table_holds_exact_definitions():
    from advisor.core.units import UNITS

    # SI Brochure table 8 and NIST SP 811 B.8, by hand
    assert UNITS["in"].factor == 0.0254 and UNITS["ft"].factor == 0.3048
    assert UNITS["lbf"].factor == 4.4482216152605 and UNITS["kgf"].factor == 9.80665
    assert UNITS["kcal"].factor == 4184.0 and UNITS["kWh"].factor == 3.6e6
    assert UNITS["rpm"].factor == pytest.approx(2 * math.pi / 60, rel=1e-15)
    assert UNITS["kg"].factor == 1.0 and UNITS["t"].factor == 1000.0
    assert UNITS["µm"] == UNITS["μm"] == UNITS["um"]  # micro sign, Greek mu, u
    assert UNITS["Nm"].dims == UNITS["J"].dims and UNITS["J"].energy and not UNITS["Nm"].energy


def test_the_hand_values_of_the_issue():
    assert to_unit("5 kN", "N") == 5000.0
    assert round(to_unit("1500 rpm", "rad/s"), 2) == 157.08
    assert round(to_unit("90 deg", "rad"), 4) == 1.5708
    assert to_unit("200 mm", "m") == 0.2  # rounded to 12 digits: no 0.20000000000000004


@pytest.mark.parametrize(
    ("text", "unit", "said"),
    [
        ("5 m", "N", "m is a length, not a force; expected N"),
        ("5 kN", "mm", "kN is a force, not a length; expected mm"),
        ("5 rad", "N", "rad is an angle, not a force; expected N"),
        ("10 N", "rad", "N is a force, not an angle; expected rad"),
        # pint counts the radian as no dimension: Hz and rpm would convert by 2π silently
        ("50 Hz", "rpm", "Hz is a frequency, not a speed of rotation; expected rpm"),
        ("3000 rpm", "Hz", "rpm is a speed of rotation, not a frequency; expected Hz"),
        ("five kN", "N", "must be a number or a quantity with a unit"),
        ("5 kN kN", "N", "expected N"),
        ("", "N", "must be a number or a quantity with a unit"),
        ("5 bananas", "N", "must be a number or a quantity with a unit"),
        ("kN", "N", "expected N"),
        ("inf N", "N", "must be a number or a quantity with a unit"),
        ("1e400 N", "N", "must be finite"),
        # a number in quotes: a slip or a unit left out, never guessed
        ("3500", "N", 'must be a number (3500) or a quantity with its unit ("3500 N")'),
    ],
)
def test_wrong_dimensions_and_garbage_are_refused(text, unit, said):
    with pytest.raises(UnitError) as err:
        to_unit(text, unit)
    assert said in str(err.value)


def _linear(**linear):
    base = {"force_N": 3500, "stroke_m": 0.2, "travel_time_s": 5, "support_span_m": 0.4}
    return {
        "application": {"kind": "linear"},
        "linear": {**base, **linear},
        "motor": {"kind": "induction"},
        "screw": {"friction_coefficient": 0.15, "thread": "Tr16x2", "friction_model": "paper"},
    }


def test_a_file_with_units_gives_the_report_of_the_file_in_si():
    """The report echoes the requirement in SI: the same TOML byte for byte."""
    si = to_toml(advise(parse_requirements(_linear())))
    typed = _linear(
        force_N="3.5 kN", stroke_m="200 mm", travel_time_s="5000 ms", support_span_m="40 cm"
    )
    assert to_toml(advise(parse_requirements(typed))) == si
    assert tomllib.loads(si)["requirements"]["linear"]["force_N"] == 3500


def test_lists_and_tables_in_lists_take_units_too():
    rotary = tomllib.loads((EXAMPLES / "rudder_actuator.toml").read_text(encoding="utf-8"))
    rotary["motor"]["candidate_speeds_rpm"] = ["5000 rpm", "1047.19755 rad/s"]
    rotary["rotary"]["torque_Nm"] = "1.62 kN*m"
    req = parse_requirements(rotary)
    assert req.motor.candidate_speeds_rpm == [5000.0, pytest.approx(10000.0, rel=1e-8)]
    assert req.rotary.torque_Nm == 1620.0
    pos = tomllib.loads((EXAMPLES / "positioning_drive.toml").read_text(encoding="utf-8"))
    pos["positioning"]["motors"][0]["speed_rad_s"] = "1432.394 rpm"  # 150 rad/s
    pos["positioning"]["travel_rad"] = "572.9578 deg"  # 10 rad
    req = parse_requirements(pos)
    assert req.positioning.motors[0].speed_rad_s == pytest.approx(150.0, rel=1e-6)
    assert req.positioning.travel_rad == pytest.approx(10.0, rel=1e-6)


def test_the_range_is_checked_after_conversion():
    with pytest.raises(InputError) as err:
        parse_requirements(_linear(stroke_m="30 m"))
    # echoed as typed ('30 m' is 30 m, so no SI value beside it)
    assert str(err.value).startswith("linear.stroke_m = '30 m': must be ≤ 20 (stroke, m")
    with pytest.raises(InputError) as err:
        parse_requirements(_linear(stroke_m="30000 mm"))
    assert str(err.value).startswith("linear.stroke_m = '30000 mm' (30 m): must be ≤ 20")


def test_strings_elsewhere_are_still_refused_by_the_model():
    # a count has no unit: a string there is the model's "must be a whole number"
    doc = _linear()
    doc["screw"]["starts"] = "2"
    with pytest.raises(InputError, match=r"screw.starts = '2': must be a whole number"):
        parse_requirements(doc)


def test_cli_wrong_dimension_is_one_line_exit_2(tmp_path, capsys):
    text = (EXAMPLES / "linear_screw_actuator.toml").read_text(encoding="utf-8")
    bad = tmp_path / "bad.toml"
    bad.write_text(text.replace("force_N = 3500", 'force_N = "5 m"'), encoding="utf-8")
    assert 'force_N = "5 m"' in bad.read_text(encoding="utf-8")
    assert main(["--batch", str(bad)]) == 2
    err = capsys.readouterr().err
    assert err == "advisor: linear.force_N = '5 m': m is a length, not a force; expected N\n"


def test_every_bad_string_of_a_file_is_named(tmp_path, capsys):
    text = (EXAMPLES / "linear_screw_actuator.toml").read_text(encoding="utf-8")
    bad = tmp_path / "bad.toml"
    text = text.replace("force_N = 3500", 'force_N = "3.5 kilo newtons"')
    bad.write_text(text.replace("stroke_m = 0.2", 'stroke_m = "0.2 s"'), encoding="utf-8")
    assert main(["--batch", str(bad)]) == 2
    lines = capsys.readouterr().err.splitlines()
    assert len(lines) == 2
    assert lines[0].startswith(
        "advisor: linear.force_N = '3.5 kilo newtons': must be a number or a quantity"
    )
    assert lines[1] == "advisor: linear.stroke_m = '0.2 s': s is a time, not a length; expected m"


def _modules_after(src: str, out) -> str:
    code = (
        "import sys\n"
        "from advisor.cli import main\n"
        f"assert main(['--batch', {src!r}, '-o', {str(out)!r}]) == 0\n"
        "print('pint' in sys.modules, 'numpy' in sys.modules)\n"
    )
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return [line for line in r.stdout.splitlines() if line.startswith(("True", "False"))][-1]


def test_no_unit_library_is_imported_even_with_a_string(tmp_path):
    """The grammar of advisor.core.units converts by itself (issue 24): neither pint nor
    numpy (which pint imports, about 0.4 s) is loaded, with or without a unit string."""
    plain = EXAMPLES / "linear_screw_actuator.toml"
    assert _modules_after(str(plain), tmp_path / "a.toml") == "False False"
    typed = tmp_path / "typed.toml"
    typed.write_text(
        plain.read_text(encoding="utf-8").replace("force_N = 3500", 'force_N = "3.5 kN"'),
        encoding="utf-8",
    )
    assert 'force_N = "3.5 kN"' in typed.read_text(encoding="utf-8")
    assert _modules_after(str(typed), tmp_path / "b.toml") == "False False"


def test_the_schema_allows_the_strings_on_number_fields_only():
    import json
    import re

    from advisor.core.schema import requirement_schema

    schema = requirement_schema()
    force = schema["$defs"]["LinearReq"]["properties"]["force_N"]
    number, quantity = force["anyOf"]
    # the number keeps the model's range; the string branch has no range of its own
    limits = {k: v for k, v in number.items() if k != "type"}
    assert number["type"] == "number" and "maximum" in limits and len(limits) == 2
    assert quantity["type"] == "string" and set(quantity) == {"type", "pattern", "description"}
    pattern = re.compile(quantity["pattern"])
    assert all(pattern.match(t) for t in ("5 kN", "200 mm", "1.5e3 rpm", "90 deg"))
    assert not any(pattern.match(t) for t in ("kN", "five kN", "", "5.5.5 m", "3"))
    # the grammar's shape: an editor flags arithmetic, parentheses and comments too
    assert all(pattern.match(t) for t in ("2 kg*m^2", "7.8 g·cm⁻³", "1 kN·m", "32 mm²/s"))
    bad = ("5 kN + 3 kN", "1 N*(1/0)", "5 kN # x", "3500 N%", "5 N*", "9**9**8 N", "5 kN\u202e")
    assert not any(pattern.match(t) for t in bad)
    # what the reader takes from a typeset page, the schema takes too: the dot operator
    # U+22C5, the ohm sign U+2126, the no-break, thin and narrow no-break spaces
    typeset = ("1620 N\u22c5m", "1.14 \u2126", "2 m\u2126", "5\u00a0kN", "5\u2009kN", "5\u202fkN")
    assert all(pattern.match(t) for t in typeset)
    assert [
        to_unit(t, u) for t, u in zip(typeset, ("N·m", "Ω", "Ω", "N", "N", "N"), strict=True)
    ] == [
        1620.0,
        1.14,
        0.002,
        5000.0,
        5000.0,
        5000.0,
    ]
    shipped = json.loads((EXAMPLES / "requirements.schema.json").read_text(encoding="utf-8"))
    assert shipped == json.loads(json.dumps(schema))  # the shipped file is regenerated
    starts = schema["$defs"]["ScrewReq"]["properties"]["starts"]
    assert starts["type"] == "integer" and "anyOf" not in starts
    text = json.dumps(schema, ensure_ascii=False)
    assert (
        '"type": "number"' in text
        and text.count(json.dumps(quantity["pattern"], ensure_ascii=False)[1:-1]) > 10
    )


def test_the_wizard_opens_a_file_with_units_in_si():
    from advisor.tui.draft import shape

    doc = _linear(force_N="3.5 kN", stroke_m="5 kN")
    shaped, problems = shape(doc)
    assert shaped["linear"]["force_N"] == 3500.0
    # a wrong one stays in its field to be fixed, named
    assert shaped["linear"]["stroke_m"] == "5 kN"
    assert problems == ["linear.stroke_m = '5 kN': must be a number; fix it here"]
