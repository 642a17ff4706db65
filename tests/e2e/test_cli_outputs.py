"""The batch's output options said plainly when they are wrong: -o with --out-dir, an empty
or blank -o or --out-dir (and family --out), an --out-dir that is a file; and ``advisor diff`` given a folder asks for a report.
Each is exit 2 in one line, before anything is read or written."""

import pytest
from helpers import EXAMPLES

from advisor.cli import main

LINEAR = EXAMPLES / "linear_screw_actuator.toml"


def _one_line(capsys) -> str:
    out, err = capsys.readouterr()
    assert out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    return lines[0]


def test_o_and_out_dir_exclude_each_other_for_one_input(tmp_path, capsys):
    argv = ["--batch", str(LINEAR), "-o", str(tmp_path / "r.toml")]
    assert main([*argv, "--out-dir", str(tmp_path / "od")]) == 2
    line = _one_line(capsys)
    assert "-o/--output and --out-dir exclude each other" in line
    assert list(tmp_path.iterdir()) == []


def test_an_empty_o_is_said_to_be_empty(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(["--batch", str(LINEAR), "-o", ""]) == 2
    assert _one_line(capsys) == (
        "advisor: -o/--output: an empty output path; give the report's file name"
    )


@pytest.mark.parametrize(
    ("argv", "said"),
    [
        (["-o", " "], "-o/--output: a blank output path; give the report's file name"),
        (["-o", "\t"], "-o/--output: a blank output path; give the report's file name"),
        (["--out-dir", ""], "--out-dir: an empty folder name; give the folder for the reports"),
        (["--out-dir", "  "], "--out-dir: a blank folder name; give the folder for the reports"),
    ],
)
def test_a_blank_output_is_refused_and_nothing_written(tmp_path, capsys, monkeypatch, argv, said):
    # Path('') is '.': --out-dir '' (an unset $OUT) wrote into the current folder, and
    # -o ' ' a file named by a blank
    monkeypatch.chdir(tmp_path)
    assert main(["--batch", str(LINEAR), *argv]) == 2
    assert _one_line(capsys) == f"advisor: {said}"
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("out", ["", " "])
def test_a_blank_family_out_is_refused_and_nothing_written(tmp_path, capsys, monkeypatch, out):
    from advisor.family.cli import main as family_main

    monkeypatch.chdir(tmp_path)
    family = EXAMPLES / "families" / "valve_actuators.toml"
    assert family_main([str(family), "--out", out, "--quiet"]) == 2
    blank = "an empty" if out == "" else "a blank"
    assert _one_line(capsys) == (
        f"advisor: --out: {blank} folder name; give the folder for the results"
    )
    assert list(tmp_path.iterdir()) == []


def test_an_out_dir_that_is_a_file_is_said_to_be_one(tmp_path, capsys):
    target = tmp_path / "in.toml"
    target.write_bytes(LINEAR.read_bytes())
    assert main(["--batch", str(LINEAR), "--out-dir", str(target)]) == 2
    assert _one_line(capsys) == (
        f"advisor: --out-dir {target}: is a file, not a directory; give a folder for the reports"
    )
    assert target.read_bytes() == LINEAR.read_bytes()


@pytest.mark.parametrize("other", ["folder", "/dev/zero"])
def test_diff_of_a_folder_or_a_device_asks_for_a_report(tmp_path, capsys, other):
    report = tmp_path / "r.toml"
    assert main(["--batch", str(LINEAR), "-o", str(report)]) == 0
    capsys.readouterr()
    other = str(tmp_path) if other == "folder" else other
    assert main(["diff", str(report), other]) == 2
    line = _one_line(capsys)
    assert "expected a report file" in line or "give a report file" in line
    assert "requirement" not in line
