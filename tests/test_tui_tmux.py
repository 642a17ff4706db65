"""One end-to-end run in a real terminal: `advisor REQ.toml` in tmux, driven with send-keys,
read with capture-pane; the exported report must equal the batch report of the same file.
.ci/run installs tmux when the machine lacks it."""

import os
import shutil
import subprocess
import sys
import time
import uuid

import pytest
from helpers import EXAMPLES

from advisor.core.engine import advise
from advisor.core.report import to_toml
from advisor.core.requirements import read_requirements

pytestmark = pytest.mark.skipif(shutil.which("tmux") is None, reason="tmux is not installed")


# a private server: tests running side by side (or a user's own tmux) never share it, and
# killing our session never takes another run's server down
_SOCKET = f"advisor-e2e-{uuid.uuid4().hex[:8]}"


def _tmux(*args: str, check: bool = True) -> str:
    r = subprocess.run(["tmux", "-L", _SOCKET, *args], capture_output=True, text=True, check=check)
    return r.stdout


def _wait_for(session: str, text: str, timeout: float = 30.0) -> str:
    end = time.monotonic() + timeout
    screen = ""
    while time.monotonic() < end:
        screen = _tmux("capture-pane", "-p", "-t", session)
        if text in screen:
            return screen
        time.sleep(0.2)
    raise AssertionError(f"{text!r} never appeared; the screen was:\n{screen}")


def test_wizard_in_tmux_exports_the_batch_report(tmp_path):
    src = EXAMPLES / "linear_screw_actuator.toml"
    out = tmp_path / "e2e.report.toml"
    session = f"advisor-e2e-{uuid.uuid4().hex[:8]}"
    env = (
        f"XDG_STATE_HOME={tmp_path / 'state'} TEXTUAL_ANIMATIONS=none "
        f"PATH={os.path.dirname(sys.executable)}:{os.environ.get('PATH', '')}"
    )
    command = f"cd {tmp_path} && env {env} {sys.executable} -m advisor {src}"
    _tmux("new-session", "-d", "-s", session, "-x", "120", "-y", "40", command)
    try:
        _wait_for(session, "What must the drive do?")
        _tmux("send-keys", "-t", session, "C-r")
        screen = _wait_for(session, "Tr16x2, 4A71B4 0.75 kW")
        assert "Results" in screen
        _tmux("send-keys", "-t", session, "C-s")
        _wait_for(session, "Export to")
        # clear the proposed name, type ours, tab to "Save report" and press it
        _tmux("send-keys", "-t", session, "C-u")
        # relative to the wizard's working directory (tmp_path), short enough to show whole
        _tmux("send-keys", "-t", session, "-l", out.name)
        _wait_for(session, out.name)  # the path typed must show before it is saved
        _tmux("send-keys", "-t", session, "Tab", "Enter")
        for _ in range(300):  # a loaded machine can take seconds to write it
            if out.exists():
                break
            time.sleep(0.1)
        assert out.read_text(encoding="utf-8") == to_toml(advise(read_requirements(src)))
        _tmux("send-keys", "-t", session, "C-q")
    finally:
        _tmux("kill-server", check=False)
