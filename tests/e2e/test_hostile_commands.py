"""Every subcommand under the exit-code contract, run as a user runs it (a real process):
a full stdout (``> /dev/full``) is one line and exit 2, a reader that leaves (``| head -1``)
ends the command quietly, a FIFO or a device given as data is refused at once (never a hang)."""

import os
import subprocess
import sys
from pathlib import Path

import pytest
from helpers import ROOT

FULL = Path("/dev/full")
pytestmark = pytest.mark.skipif(not FULL.exists(), reason="needs /dev/full (Linux)")

#: The report of a linear design, small enough to write by hand: what diff reads.
REPORT = """warnings = ["w1"]

[report]
application = "linear"
status = "feasible"

[[checks]]
id = "core_stress"
value = 30.5
limit = 118.3
unit = "MPa"
margin = 3.88
"""


def _advisor(args: list[str], stdout: object, timeout: float = 120) -> subprocess.CompletedProcess:
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    return subprocess.run(
        [sys.executable, "-m", "advisor", *args],
        stdout=stdout,
        stderr=subprocess.PIPE,
        text=True,
        timeout=timeout,  # a hang fails the test instead of the suite
        cwd=ROOT,
        env=env,
    )


@pytest.fixture(scope="module")
def reports(tmp_path_factory) -> tuple[str, str]:
    d = tmp_path_factory.mktemp("reports")
    (d / "a.toml").write_text(REPORT, encoding="utf-8")
    (d / "b.toml").write_text(REPORT.replace("3.88", "2.5"), encoding="utf-8")
    return str(d / "a.toml"), str(d / "b.toml")


COMMANDS = [
    ["rules"],
    ["rules", "--markdown"],
    ["schema"],
    ["schema", "--markdown"],
    ["verify", "--list"],
    ["verify", "seed003-constants"],
    ["diff", "A", "B"],
    ["diff", "A", "B", "--format", "md"],
    ["diff", "A", "B", "--format", "html"],
]


def _args(cmd: list[str], reports: tuple[str, str]) -> list[str]:
    return [{"A": reports[0], "B": reports[1]}.get(x, x) for x in cmd]


@pytest.mark.parametrize("cmd", COMMANDS, ids=" ".join)
def test_a_full_stdout_is_one_line_and_exit_2(cmd, reports):
    with FULL.open("w") as full:
        r = _advisor(_args(cmd, reports), full)
    assert r.returncode == 2, r.stderr
    assert r.stderr.count("\n") == 1 and "Traceback" not in r.stderr
    assert r.stderr.startswith("advisor: standard output: cannot write")
    assert "(No space left on device)" in r.stderr


@pytest.mark.parametrize("cmd", [c for c in COMMANDS if c[0] != "verify"], ids=" ".join)
def test_a_reader_that_leaves_ends_the_command_quietly(cmd, reports):
    # `advisor rules | head -1`: the reader closes the pipe after the first line
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    p = subprocess.Popen(
        [sys.executable, "-m", "advisor", *_args(cmd, reports)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        cwd=ROOT,
        env=env,
    )
    assert p.stdout is not None and p.stderr is not None
    p.stdout.readline()
    p.stdout.close()
    try:
        code = p.wait(timeout=120)
    finally:
        p.kill()
    err = p.stderr.read().decode()
    p.stderr.close()
    assert err == ""
    # 0 (the reader left) or, had the output fitted the pipe, the command's own code
    assert code in (0, 1), code


def test_a_fifo_or_a_device_as_verification_data_is_refused_at_once(tmp_path):
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    for data, kind in ((fifo, "a FIFO"), (Path("/dev/zero"), "a device")):
        r = _advisor(["verify", "--data", str(data)], subprocess.PIPE, timeout=60)
        assert r.returncode == 2 and r.stdout == ""
        assert r.stderr.count("\n") == 1
        assert r.stderr.startswith(f"advisor: verification data {data}: is {kind}, not a regular")


def test_a_fifo_as_a_report_is_refused_at_once(tmp_path, reports):
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    r = _advisor(["diff", reports[0], str(fifo)], subprocess.PIPE, timeout=60)
    assert r.returncode == 2 and r.stdout == ""
    assert r.stderr.count("\n") == 1 and "is a FIFO" in r.stderr


def test_verify_output_onto_its_data_keeps_the_data(tmp_path):
    data = tmp_path / "cases.toml"
    text = (ROOT / "advisor" / "verify" / "cases.toml").read_text(encoding="utf-8")
    data.write_text(text, encoding="utf-8")
    r = _advisor(["verify", "--data", str(data), "-o", str(data)], subprocess.PIPE, timeout=60)
    assert r.returncode == 2 and r.stderr.count("\n") == 1
    assert "is the verification data itself" in r.stderr
    assert data.read_text(encoding="utf-8") == text
