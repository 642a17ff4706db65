"""``advisor diff`` (issue 28, item 3): what changed between two reports, in words and a
table; exit 0 the same, 1 different, 2 bad input (one line)."""

import tomllib

import pytest
from helpers import EXAMPLES

from advisor.cli import main
from advisor.core.engine import advise
from advisor.core.report import to_toml
from advisor.core.requirements import parse_requirements
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
