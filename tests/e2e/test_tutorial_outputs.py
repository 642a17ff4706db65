"""The batch summaries the tutorials quote are what the advisor prints today: each
tutorial's requirement (its first ``toml`` block, with what the prose adds) is run as the
quoted command runs it, and the quoted lines are compared with the output."""

import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).parents[2]
TUTORIALS = ROOT / "docs" / "tutorials"

#: what a tutorial's prose adds to its requirement before the quoted run
ADDED = {"positioning.md": ("load_torque_Nm = 5\n", "load_torque_Nm = 5\nmove_time_s = 0.3\n")}


def _blocks(text: str) -> list[tuple[str, str]]:
    return re.findall(r"```(\w*)\n(.*?)```", text, flags=re.S)


def _quoted_run(blocks: list[tuple[str, str]]) -> tuple[list[str], list[str]] | None:
    """The command and the lines it printed, of the block that writes the first report."""
    for lang, body in blocks:
        lines = body.splitlines()
        if not lang and lines and re.match(r"\$ advisor --batch \S+ -o \S+$", lines[0]):
            return lines[0][2:].split(), lines[1:]
    return None


@pytest.mark.parametrize("name", ["linear.md", "rotary.md", "positioning.md", "spinning-rotor.md"])
def test_the_quoted_summary_is_the_output(name, tmp_path):
    blocks = _blocks((TUTORIALS / name).read_text(encoding="utf-8"))
    requirement = next(body for lang, body in blocks if lang == "toml")
    if name in ADDED:
        requirement = requirement.replace(*ADDED[name])
    run = _quoted_run(blocks)
    assert run is not None
    command, quoted = run
    (tmp_path / command[2]).write_text(requirement, encoding="utf-8")
    out = subprocess.run(
        [sys.executable, "-m", "advisor", *command[1:]],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"},
        check=False,
    )
    printed = (out.stdout + out.stderr).splitlines()
    assert sorted(printed) == sorted(quoted)
