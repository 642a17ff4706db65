"""``advisor diff`` (issue 28, item 3): what changed between two reports, in words and a
table; exit 0 the same, 1 different, 2 bad input (one line)."""

import tomllib

import pytest
from helpers import EXAMPLES

from advisor.cli import main
from advisor.core.engine import advise
from advisor.core.reading import parse_requirements
from advisor.core.report import to_toml
from advisor.diff import changes_between, differences


def _report(tmp_path, name: str, text: str | None = None):
    src = (EXAMPLES / name).read_text(encoding="utf-8") if text is None else text
    report = advise(parse_requirements(tomllib.loads(src)))
    out = tmp_path / f"{len(list(tmp_path.iterdir()))}.report.toml"
    out.write_text(to_toml(report), encoding="utf-8")
    return out, report


def test_the_same_report_is_no_change(tmp_path, capsys):
    a, _ = _report(tmp_path, "rudder_actuator.toml")
    b, _ = _report(tmp_path, "rudder_actuator.toml")
    assert main(["diff", str(a), str(b)]) == 0
    assert capsys.readouterr().out == f"{a} and {b}: the same\n"


def test_a_changed_torque_names_the_requirement_the_parts_and_the_margins(tmp_path, capsys):
    text = (EXAMPLES / "rudder_actuator.toml").read_text(encoding="utf-8")
    assert "torque_Nm = 1620" in text
    a, before = _report(tmp_path, "rudder_actuator.toml")
    b, after = _report(tmp_path, "", text.replace("torque_Nm = 1620", "torque_Nm = 1500"))
    assert main(["diff", str(a), str(b)]) == 1
    out = capsys.readouterr().out.splitlines()
    assert "  requirement rotary.torque_Nm: 1620 N·m → 1500 N·m" in out
    # every check whose margin moved, with both margins and both values
    moved = [c for c in before.checks if c.id in {x.id for x in after.checks}]
    new = {c.id: c for c in after.checks}
    for c in moved:
        if abs(c.margin - new[c.id].margin) > 5e-4 * c.margin:
            line = next(x for x in out if x.startswith(f"  check {c.id}: margin {c.margin:.3f}"))
            assert f"→ margin {new[c.id].margin:.3f}" in line
    # the same lines as the wizard's "changed since the previous result"
    assert [x.strip() for x in out[1:]] == changes_between(before, after)


def test_a_changed_application_says_so_first(tmp_path, capsys):
    a, _ = _report(tmp_path, "linear_screw_actuator.toml")
    b, _ = _report(tmp_path, "gyro_compensator.toml")
    assert main(["diff", str(a), str(b)]) == 1
    out = capsys.readouterr().out.splitlines()
    assert out[1] == "  application: linear → spinning_rotor"
    assert "  requirement linear.force_N: dropped (was 3500 N)" in out
    assert "  requirement rotor.mass_kg: new, 0.56 kg" in out
    assert "  component motor: dropped (was 4A71B4, 15.1 kg)" in out


@pytest.mark.parametrize("fmt", ["md", "html"])
def test_formats_for_a_review(tmp_path, capsys, fmt):
    a, _ = _report(tmp_path, "positioning_drive.toml")
    text = (EXAMPLES / "positioning_drive.toml").read_text(encoding="utf-8")
    b, _ = _report(tmp_path, "", text.replace("load_torque_Nm = 100", "load_torque_Nm = 120"))
    assert main(["diff", str(a), str(b), "--format", fmt]) == 1
    out = capsys.readouterr().out
    if fmt == "md":
        assert "| requirement | positioning.load\\_torque\\_Nm | 100 N·m | 120 N·m |" in out
    else:
        assert out.startswith("<!DOCTYPE html>")
        assert "<td>positioning.load_torque_Nm</td><td>100 N·m</td><td>120 N·m</td>" in out


def test_bad_input_is_one_line_exit_2(tmp_path, capsys):
    a, _ = _report(tmp_path, "positioning_drive.toml")
    req = EXAMPLES / "positioning_drive.toml"  # a requirement, not a report
    assert main(["diff", str(a), str(req)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "not a Drive Advisor report" in err
    assert main(["diff", str(a), str(tmp_path / "missing.toml")]) == 2
    assert capsys.readouterr().err.count("\n") == 1


def test_differences_of_plain_data():
    a = {"report": {"application": "x"}, "warnings": ["w1"], "checks": []}
    b = {"report": {"application": "x"}, "warnings": ["w2"], "checks": []}
    assert [c.words() for c in differences(a, b)] == [
        "warning: dropped (was w1)",
        "warning: new, w2",
    ]
    assert differences(a, a) == []


# ------------------------------------------------------------------ hostile reports
#: The least a report diff reads: the header, one check, one decision, the warnings.
MINIMAL = """warnings = ["w1"]

[report]
application = "linear"
status = "feasible"

[[checks]]
id = "core_stress"
value = 30.5
limit = 118.3
unit = "MPa"
margin = 3.88

[[decisions]]
id = "SCR-01"
decision = "a sliding screw"
"""


def _file(tmp_path, text: str, name: str = "r.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


def test_a_minimal_report_is_read(tmp_path, capsys):
    a = _file(tmp_path, MINIMAL)
    assert main(["diff", str(a), str(a)]) == 0
    assert capsys.readouterr().out == f"{a} and {a}: the same\n"


@pytest.mark.parametrize(
    ("old", "new", "says"),
    [
        ('warnings = ["w1"]', "warnings = 5", "warnings must be an array of text, not a number"),
        ('warnings = ["w1"]', "warnings = [true]", "warnings[0] must be text, not a boolean"),
        ('warnings = ["w1"]', "design = 5", "design must be a table, not a number"),
        ('warnings = ["w1"]', "requirements = [1]", "requirements must be a table, not an array"),
        ('warnings = ["w1"]\n', "", None),  # no warnings at all is a report with none
        ('application = "linear"', "application = 5", "report.application must be text"),
        ('status = "feasible"', "", "report.status is missing"),
        ('status = "feasible"', "status = 1.5", "report.status must be text, not a number"),
        ('id = "core_stress"', "id = [1]", "checks[0].id must be text, not an array"),
        ('id = "core_stress"', "a = { b = 1 }", "checks[0].id is missing"),
        ("margin = 3.88", 'margin = "x"', "checks[0].margin must be a number, not text"),
        ("margin = 3.88", "margin = true", "checks[0].margin must be a number, not a boolean"),
        ('unit = "MPa"', "unit = 5", "checks[0].unit must be text, not a number"),
        ("value = 30.5", "value = [1]", "checks[0].value must be a number or text"),
        ('id = "SCR-01"', "id = 1", "decisions[0].id must be text, not a number"),
        ('decision = "a sliding screw"', "", "decisions[0].decision is missing"),
    ],
)
def test_a_malformed_report_is_refused_in_one_line(tmp_path, capsys, old, new, says):
    assert old in MINIMAL
    good = _file(tmp_path, MINIMAL, "good.toml")
    bad = _file(tmp_path, MINIMAL.replace(old, new, 1), "bad.toml")
    for fmt in ("text", "md", "html"):
        code = main(["diff", str(good), str(bad), "--format", fmt])
        out, err = capsys.readouterr()
        if says is None:
            assert code == 1 and err == ""
            continue
        assert code == 2 and out == ""
        assert err == f"advisor: {bad}: not a report of the advisor: {err.split(': ', 3)[3]}"
        assert err.count("\n") == 1 and says in err


@pytest.mark.parametrize(
    "text",
    [
        'checks = "x"\n[report]\napplication = "linear"\nstatus = "feasible"\n',
        'checks = [{ a = { b = 1 } }]\n[report]\napplication = "linear"\nstatus = "feasible"\n',
        'checks = [5]\n[report]\napplication = "linear"\nstatus = "feasible"\n',
        'decisions = 5\n[report]\napplication = "linear"\nstatus = "feasible"\n',
        "report = 5\n",
    ],
)
def test_arrays_that_are_not_arrays_of_tables_are_refused(tmp_path, capsys, text):
    good = _file(tmp_path, MINIMAL, "good.toml")
    bad = _file(tmp_path, text, "bad.toml")
    assert main(["diff", str(good), str(bad)]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and str(bad) in err


def test_html_style_sheet_is_css_not_a_format_string(tmp_path, capsys):
    a = _file(tmp_path, MINIMAL, "a.toml")
    b = _file(tmp_path, MINIMAL.replace("margin = 3.88", "margin = 2.5"), "b.toml")
    assert main(["diff", str(a), str(b), "--format", "html"]) == 1
    out = capsys.readouterr().out
    css = out.split("<style>", 1)[1].split("</style>", 1)[0]
    assert "{{" not in css and "}}" not in css
    assert css.count("{") == css.count("}") == 3
    assert "body { font-family: sans-serif;" in css
    assert "table { border-collapse: collapse; }" in css
    # the check's row: margin 3.880 → 2.500, both with their values (30.5 against 118.3 MPa)
    assert "<td>margin 3.880 (30.5 against 118.3 MPa)</td>" in out
    assert "<td>margin 2.500 (30.5 against 118.3 MPa)</td>" in out


HOSTILE = "a\\u001b[2Jb\\u0007c\\u0000d\\u202ee"  # ESC, BEL, NUL, right-to-left override


@pytest.mark.parametrize("fmt", ["text", "html"])
def test_control_characters_in_a_report_are_shown_escaped(tmp_path, capsys, fmt):
    a = _file(tmp_path, MINIMAL, "a.toml")
    b = _file(tmp_path, MINIMAL.replace('"w1"', f'"{HOSTILE}"'), "b.toml")
    assert main(["diff", str(a), str(b), "--format", fmt]) == 1
    out = capsys.readouterr().out
    for raw in ("\x1b", "\x07", "\x00", "\u202e"):
        assert raw not in out
    assert "new warning: a\\x1b[2Jb\\x07c\\x00d\\u202ee" in out


@pytest.mark.parametrize(
    ("old", "new", "says"),
    [
        ("margin = 3.88", "margin = nan", "checks[0].margin = nan"),
        ("margin = 3.88", "margin = inf", "checks[0].margin = inf"),
        ("margin = 3.88", "margin = -inf", "checks[0].margin = -inf"),
        ("margin = 3.88", "margin = 1e400", "checks[0].margin = inf"),  # overflows to inf
        ("value = 30.5", "value = nan", "checks[0].value = nan"),
        ('warnings = ["w1"]', 'warnings = ["w1"]\n[requirements.linear]\nforce_N = inf', None),
    ],
)
def test_a_non_finite_number_is_refused_naming_its_key(tmp_path, capsys, old, new, says):
    """|nan − 3.88| > tol and |inf − 3.88| > tol·inf are both false: without the refusal
    such a report read as "the same" as the good one (exit 0). A report never holds nan or
    inf (docs/reference/report.md): exit 2, one line naming the key and the value."""
    says = says or "requirements.linear.force_N = inf"
    good = _file(tmp_path, MINIMAL, "good.toml")
    bad = _file(tmp_path, MINIMAL.replace(old, new, 1), "bad.toml")
    for pair in ([good, bad], [bad, good]):
        assert main(["diff", *map(str, pair)]) == 2
        out, err = capsys.readouterr()
        assert out == "" and err.count("\n") == 1
        assert f"{bad}: not a report of the advisor: {says}: " in err and "finite" in err
