"""Many requirement files at once: one report each, summary, worst exit code, -j N."""

import shutil
import subprocess
import sys

from helpers import EXAMPLES

from advisor.cli import main
from advisor.core.errors import ExitCode
from advisor.many import SEVERITY, expand, report_name


def _corpus(tmp_path):
    d = tmp_path / "reqs"
    d.mkdir()
    for f in EXAMPLES.glob("*.toml"):
        shutil.copy(f, d / f.name)
    (d / "broken.toml").write_text("[application\n")
    (d / "notes.txt").write_text("not a requirement")
    return d


def test_directory_reports_and_worst_exit(tmp_path, capsys):
    d = _corpus(tmp_path)
    out = tmp_path / "out"
    rc = main(["--batch", str(d), "--out-dir", str(out)])
    captured = capsys.readouterr()
    assert rc == ExitCode.INVALID_INPUT  # the broken file is the worst outcome
    names = sorted(p.name for p in out.iterdir())
    assert names == sorted(f"{f.stem}.report.toml" for f in EXAMPLES.glob("*.toml"))
    # the same report as a single batch run, byte for byte
    single = subprocess.run(
        [sys.executable, "-m", "advisor", "--batch", str(EXAMPLES / "rudder_actuator.toml")],
        capture_output=True,
        text=True,
    ).stdout
    assert (out / "rudder_actuator.report.toml").read_text() == single
    n = len(list(EXAMPLES.glob("*.toml")))
    assert "broken.toml" in captured.out and f"{n} designs, 0 infeasible, 1 invalid" in captured.out
    assert "broken TOML" in captured.err and "Traceback" not in captured.err


def test_parallel_gives_the_same_reports(tmp_path, capsys):
    d = _corpus(tmp_path)
    rc1 = main(["--batch", str(d), "--out-dir", str(tmp_path / "o1"), "-j", "1"])
    rc2 = main(["--batch", str(d), "--out-dir", str(tmp_path / "o2"), "-j", "2"])
    capsys.readouterr()
    assert rc1 == rc2
    for f in (tmp_path / "o1").iterdir():
        assert f.read_text() == (tmp_path / "o2" / f.name).read_text()


def test_all_good_is_exit_0(tmp_path, capsys):
    files = [str(f) for f in sorted(EXAMPLES.glob("*.toml"))]
    assert main(["--batch", *files, "--out-dir", str(tmp_path / "o")]) == ExitCode.OK
    assert "designs, 0 infeasible, 0 invalid" in capsys.readouterr().out


def test_infeasible_beats_ok_and_invalid_beats_infeasible():
    order = sorted(SEVERITY, key=SEVERITY.get)
    assert order == [
        ExitCode.OK,
        ExitCode.INFEASIBLE,
        ExitCode.INVALID_INPUT,
        ExitCode.INTERNAL_ERROR,
    ]


def test_usage_errors(tmp_path, capsys):
    a = str(EXAMPLES / "linear_screw_actuator.toml")
    assert main(["--batch", a, a]) == ExitCode.INVALID_INPUT
    assert "need --out-dir" in capsys.readouterr().err
    assert (
        main(["--batch", a, a, "--out-dir", str(tmp_path), "-o", "x.toml"])
        == ExitCode.INVALID_INPUT
    )
    assert "-o/--output and --out-dir exclude each other" in capsys.readouterr().err
    assert main(["--batch", a, "--out-dir", str(tmp_path), "-j", "0"]) == ExitCode.INVALID_INPUT
    assert main(["--batch", str(tmp_path / "none.toml"), a, "--out-dir", str(tmp_path)]) == 2
    assert "no such file" in capsys.readouterr().err


def test_same_name_twice_gets_two_reports(tmp_path):
    taken: set[str] = set()
    assert report_name(EXAMPLES / "a.toml", taken) == "a.report.toml"
    assert report_name(tmp_path / "a.toml", taken) == "a-2.report.toml"


def test_the_summary_names_a_report_that_took_another_name(tmp_path, capsys):
    # two inputs called a.toml: the second's report is a-2.report.toml, and the summary
    # says so on its line (the first keeps its own name and needs no word)
    for sub in ("x", "y"):
        (tmp_path / sub).mkdir()
        shutil.copy(EXAMPLES / "positioning_drive.toml", tmp_path / sub / "a.toml")
    files = [str(tmp_path / "x" / "a.toml"), str(tmp_path / "y" / "a.toml")]
    assert main(["--batch", *files, "--out-dir", str(tmp_path / "o")]) == ExitCode.OK
    lines = capsys.readouterr().out.splitlines()
    first = next(line for line in lines if "x/a.toml" in line)
    second = next(line for line in lines if "y/a.toml" in line)
    assert "→" not in first and "y/a.toml → a-2.report.toml" in second
    assert (tmp_path / "o" / "a-2.report.toml").exists()


def test_expand_keeps_files_and_sorts_directories(tmp_path):
    d = _corpus(tmp_path)
    got = [p.name for p in expand([d])]
    assert got == sorted(["broken.toml", *(f.name for f in EXAMPLES.glob("*.toml"))])
