"""The batch command as a user runs it: exit codes, messages, no traceback, atomic output."""

import os
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest
from helpers import EXAMPLES

from advisor.cli import main
from advisor.core.errors import ExitCode

EXAMPLE = EXAMPLES / "linear_screw_actuator.toml"
GOOD = EXAMPLE.read_text(encoding="utf-8")


def run(*args: str) -> subprocess.CompletedProcess:
    env = {**os.environ}
    return subprocess.run(
        [sys.executable, "-m", "advisor", *args], capture_output=True, text=True, env=env
    )


def test_batch_prints_the_report():
    r = run("--batch", str(EXAMPLE))
    assert r.returncode == 0, r.stderr
    report = tomllib.loads(r.stdout)
    assert report["design"]["screw"]["thread"] == "Tr16x2"
    assert r.stderr == ""


def test_batch_is_deterministic():
    assert run("--batch", str(EXAMPLE)).stdout == run("--batch", str(EXAMPLE)).stdout


def test_output_file_and_summary(tmp_path):
    out = tmp_path / "report.toml"
    r = run("--batch", str(EXAMPLE), "-o", str(out))
    assert r.returncode == 0, r.stderr
    assert tomllib.loads(out.read_text())["design"]["motor"]["pole_pairs"] == 2
    assert "Tr16x2" in r.stdout and "4A71B4" in r.stdout and str(out) in r.stdout
    assert list(tmp_path.iterdir()) == [out]  # no temporary file left behind


@pytest.mark.parametrize("example", sorted(p.name for p in EXAMPLES.glob("*.toml")))
def test_every_example_to_stdout_and_to_a_file(tmp_path, capsys, example):
    """Each application's report, printed and written with its summary, the same TOML, and
    nothing on stderr (no numerical warnings leak out)."""
    src = EXAMPLES / example
    assert main(["--batch", str(src)]) == 0
    printed = capsys.readouterr()
    assert printed.err == ""
    out = tmp_path / "r.toml"
    assert main(["--batch", str(src), "-o", str(out)]) == 0
    summary = capsys.readouterr()
    assert summary.err == "" and "lowest margin" in summary.out
    assert out.read_text(encoding="utf-8") == printed.out
    assert tomllib.loads(printed.out)["report"]["status"] == "feasible"


def test_version():
    r = run("--version")
    assert r.returncode == 0 and r.stdout.startswith("advisor 0.")


def test_linear_batch_path_imports_no_textual_rich_numpy_or_optimize():
    code = (
        "import sys, io, contextlib\n"
        "from advisor.cli import main\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n"
        f"    rc = main(['--batch', {str(EXAMPLE)!r}])\n"
        "assert rc == 0\n"
        "bad = [m for m in ('textual', 'rich', 'scipy.optimize', 'numpy') if m in sys.modules]\n"
        "print(','.join(bad))\n"
    )
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == ""


def _bad(tmp_path: Path, text: str) -> Path:
    p = tmp_path / "req.toml"
    p.write_text(text, encoding="utf-8")
    return p


def _replace(old: str, new: str) -> str:
    assert old in GOOD
    return GOOD.replace(old, new)


BAD_INPUTS = [
    # (requirement text, words the one-line message must contain)
    ("[application\nkind = 'linear'", ["broken TOML", "line 1"]),
    (
        _replace("force_N = 3500", "force_N = -3500"),
        ["linear.force_N = -3500", "must be ≥ 1", "1 N … 5 MN"],
    ),
    (_replace("force_N = 3500", "force_N = 0"), ["linear.force_N = 0", "must be ≥ 1"]),
    (_replace("force_N = 3500", "force_N = nan"), ["linear.force_N = nan", "finite"]),
    (_replace("stroke_m = 0.2", "stroke_m = inf"), ["linear.stroke_m = inf", "finite"]),
    (
        _replace("travel_time_s = 5", 'travel_time_s = "5"'),
        ["linear.travel_time_s = '5'", "number"],
    ),
    (_replace("force_N = 3500\n", ""), ["linear.force_N: missing", "rated axial force, N"]),
    (
        _replace('kind = "linear"', 'kind = "hovercraft"'),
        ["application.kind = 'hovercraft'", "'linear'"],
    ),
    (_replace('kind = "induction"', 'kind = "steam"'), ["motor.kind = 'steam'", "'induction'"]),
    (
        _replace("supply_frequency_Hz = 50", "supply_frequency_Hz = 60"),
        ["motor.supply_frequency_Hz = 60", "50"],
    ),
    (_replace("starts = 1", "starts = 1.5"), ["screw.starts = 1.5", "whole number"]),
    (
        _replace('friction_model = "paper"', 'friction_model = "magic"'),
        ["screw.friction_model = 'magic'", "'standard'", "'paper'"],
    ),
    (
        _replace("friction_coefficient = 0.15", "friction_coefficient = -0.1"),
        ["screw.friction_coefficient = -0.1", "≥ 0.01"],
    ),
    (_replace('thread = "Tr16x2"', 'thread = "M16"'), ["screw.thread = 'M16'", "Tr16x2"]),
    (
        _replace('thread = "Tr16x2"', 'thread = "Tr17x3"'),
        ["screw.thread = 'Tr17x3'", "GOST 24738-81"],
    ),
    (
        _replace("force_N = 3500", "force_N = 3500\nforse_N = 1"),
        ["linear.forse_N: unknown key", "force_N"],
    ),
    (
        _replace("hold_without_power = false", "hold_without_power = 1"),
        ["application.hold_without_power = 1", "true or false"],
    ),
    (
        _replace("support_span_m = 0.4", "support_span_m = 0.1"),
        ["stroke_m = 0.2", "support_span_m = 0.1"],
    ),
    (
        "[application]\nkind = 'linear'\n[motor]\nkind = 'induction'\n",
        ["linear: missing", "force_N, stroke_m"],
    ),
    ("", ["application: missing"]),
    (
        "[application]\nkind = 'linear'\n[linear]\nforce_N = 1\nstroke_m = 0.1\ntravel_time_s = 1\nsupport_span_m = 1\n",
        ["motor: missing"],
    ),
]


@pytest.mark.parametrize(("text", "words"), BAD_INPUTS, ids=[w[0] for _, w in BAD_INPUTS])
def test_bad_input_exit_2_with_a_clear_message(tmp_path, capsys, text, words):
    rc = main(["--batch", str(_bad(tmp_path, text))])
    err = capsys.readouterr().err
    assert rc == ExitCode.INVALID_INPUT
    assert "Traceback" not in err
    for w in words:
        assert w in err, f"{w!r} not in {err!r}"
    for line in err.strip().splitlines():
        assert line.startswith("advisor: ")


def test_missing_file_and_directory(tmp_path, capsys):
    assert main(["--batch", str(tmp_path / "nope.toml")]) == 2
    assert "no such file" in capsys.readouterr().err
    # a directory is a set of requirement files: it needs somewhere to put their reports
    assert main(["--batch", str(tmp_path)]) == 2
    assert "need --out-dir" in capsys.readouterr().err


def test_infeasible_exit_3_with_reasons(tmp_path, capsys):
    # 5 MN on a 20 m span: even Tr100x4 (d3 = 95.5 mm) buckles
    text = _replace("force_N = 3500", "force_N = 5000000")
    text = text.replace("support_span_m = 0.4", "support_span_m = 20").replace(
        'thread = "Tr16x2"\n', ""
    )
    rc = main(["--batch", str(_bad(tmp_path, text))])
    err = capsys.readouterr().err
    assert rc == ExitCode.INFEASIBLE
    assert "no feasible design" in err and "buckling" in err and "Traceback" not in err


def test_imposed_thread_that_fails_exit_3(tmp_path, capsys):
    # a steel nut (5 MPa allowed) on Tr16x2 needs 3500/(π·15·1·5) = 14.85 → 15 whole turns > 10
    rc = main(["--batch", str(_bad(tmp_path, _replace('"steel_bronze"', '"steel_steel"')))])
    err = capsys.readouterr().err
    assert rc == ExitCode.INFEASIBLE
    assert "Tr16x2" in err and "engaged nut turns: 15 against the limit 10" in err


def test_unwritable_output_is_reported(tmp_path, capsys):
    rc = main(["--batch", str(EXAMPLE), "-o", str(tmp_path / "no" / "such" / "dir" / "r.toml")])
    assert rc == ExitCode.INVALID_INPUT
    assert "cannot write the report" in capsys.readouterr().err


def test_no_arguments_open_the_wizard_and_a_missing_file_is_refused(monkeypatch, capsys):
    import advisor.cli as cli
    import advisor.tui.app as tui

    opened = []
    monkeypatch.setattr(tui, "run", lambda path, catalog_dir: opened.append(path) or 0)
    monkeypatch.setattr(cli, "_is_terminal", lambda stream: True)  # as in a terminal
    assert main([]) == 0 and opened == [None]
    assert main([str(EXAMPLE)]) == 0 and opened[-1] == EXAMPLE
    assert main(["nowhere.toml"]) == ExitCode.INVALID_INPUT
    assert "nowhere.toml: no such file" in capsys.readouterr().err
    assert len(opened) == 2  # the wizard was not opened for a missing file


def test_the_wizard_without_a_terminal_or_with_batch_options_is_refused(tmp_path):
    # without a terminal the wizard would wait for keys that never come; -o without --batch
    # would open the wizard and write nothing: both are one line and exit 2, at once
    import subprocess
    import sys

    def run(*args: str) -> subprocess.CompletedProcess:
        return subprocess.run(
            [sys.executable, "-m", "advisor", *args],
            stdin=subprocess.DEVNULL,
            capture_output=True,
            text=True,
            timeout=60,
        )

    out = run(str(EXAMPLE))
    assert out.returncode == ExitCode.INVALID_INPUT
    assert out.stderr.strip() == (
        "advisor: the wizard needs a terminal (standard input and output are not one); "
        "for a report without it: advisor --batch REQ.toml"
    )
    out = run(str(EXAMPLE), "-o", str(tmp_path / "r.toml"), "-j", "2")
    assert out.returncode == ExitCode.INVALID_INPUT
    assert "-o/--output, -j/--jobs: only with --batch" in out.stderr
    assert len(out.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "r.toml").exists()


def test_unknown_option_is_a_usage_error(capsys):
    assert main(["--bogus"]) == 2


def test_a_bug_is_one_line_not_a_traceback(monkeypatch, capsys):
    import advisor.core.engine

    def broken(*a, **k):
        raise ZeroDivisionError("float division by zero")

    monkeypatch.setattr(advisor.core.engine, "advise", broken)
    assert main(["--batch", str(EXAMPLE)]) == ExitCode.INTERNAL_ERROR
    err = capsys.readouterr().err
    assert "internal error (ZeroDivisionError" in err and "Traceback" not in err
    assert len(err.strip().splitlines()) == 1


def test_closed_pipe_is_quiet():
    r = subprocess.run(
        f"{sys.executable} -m advisor --batch {EXAMPLE} | head -c 10",
        shell=True,
        capture_output=True,
        text=True,
    )
    assert r.stdout == "warnings ="[:10]
    assert "Traceback" not in r.stderr and "internal error" not in r.stderr


def test_a_long_message_line_is_cut_to_the_stated_width(capsys):
    from advisor.cli import LINE_CHARS, print_error

    print_error("x" * 1000)
    line = capsys.readouterr().err.rstrip("\n")
    assert len(line) == LINE_CHARS, line
    assert line.startswith("advisor: xxx") and line.endswith("… (1,000 characters)")


def test_unknown_bearing_names_the_catalog_in_runs():
    from advisor.applications.spinning_rotor.advice import designation_runs

    # consecutive numbers of one series (same suffix, same width) make a run; others stand
    names = ["7000 CD", "7200 BECBP", "7201 BECBP", "7202 BECBP", "6000", "6001", "6003", "X1"]
    assert designation_runs(names) == "7000 CD, 7200 … 7202 BECBP, 6000 … 6001, 6003, X1"


def test_one_blas_thread_unless_the_user_sized_the_pool():
    from advisor.cli import one_blas_thread

    env: dict[str, str] = {}
    one_blas_thread(env)
    assert env == {"OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1"}
    for name in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS"):
        env = {name: "4"}
        one_blas_thread(env)
        assert env == {name: "4"}  # the user's choice stands, the other left to the library


def test_the_batch_runs_numpy_with_one_blas_thread(tmp_path):
    code = (
        "import os, sys\n"
        "from advisor.cli import main\n"
        "assert 'numpy' not in sys.modules  # set before numpy reads it\n"
        "main(['--batch', sys.argv[1], '-o', sys.argv[2]])\n"
        "print(os.environ['OPENBLAS_NUM_THREADS'], os.environ['OMP_NUM_THREADS'])\n"
    )
    env = {k: v for k, v in os.environ.items() if not k.endswith("_NUM_THREADS")}
    out = subprocess.run(
        [sys.executable, "-c", code, str(EXAMPLES / "rudder_actuator.toml"), str(tmp_path / "r")],
        capture_output=True,
        text=True,
        env=env,
        check=True,
    ).stdout
    assert out.splitlines()[-1] == "1 1"
