"""One end-to-end run in a real terminal: `advisor REQ.toml` in tmux, driven with send-keys,
read with capture-pane; the exported report must equal the batch report of the same file.
.ci/run installs tmux when the machine lacks it."""

import os
import shutil
import subprocess
import sys
import time
import tomllib
import uuid

import pytest
from helpers import EXAMPLES

from advisor.core.engine import advise
from advisor.core.reading import read_requirements
from advisor.core.report import to_toml
from advisor.tui.draft import draft_path

pytestmark = pytest.mark.skipif(shutil.which("tmux") is None, reason="tmux is not installed")


# a private server per test: tests running side by side (or a user's own tmux) never share
# it, killing our session never takes another run's server down, and a test never starts
# its server on the socket of one still shutting down ("server exited unexpectedly")
_SOCKET = [""]


@pytest.fixture(autouse=True)
def _own_server():
    _SOCKET[0] = f"advisor-e2e-{uuid.uuid4().hex[:8]}"
    yield
    _tmux("kill-server", check=False)


def _tmux(*args: str, check: bool = True) -> str:
    r = subprocess.run(
        ["tmux", "-L", _SOCKET[0], *args], capture_output=True, text=True, check=check
    )
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


def test_a_burst_of_keys_in_tmux_fills_field_after_field(tmp_path, monkeypatch):
    """Issue 24: ``send-keys "600" Enter "25" Enter`` in one call (one write to the terminal,
    read by the wizard as one burst) gave an axial force of 60025 N and no stroke; each
    number must land in its own field, and the draft must hold 600 N and 25 m."""
    src = tmp_path / "lin.toml"
    src.write_text('[application]\nkind = "linear"\n', encoding="utf-8")
    state = tmp_path / "state"
    session = f"advisor-e2e-{uuid.uuid4().hex[:8]}"
    env = (
        f"XDG_STATE_HOME={state} TEXTUAL_ANIMATIONS=none "
        f"PATH={os.path.dirname(sys.executable)}:{os.environ.get('PATH', '')}"
    )
    command = f"cd {tmp_path} && env {env} {sys.executable} -m advisor {src}"
    _tmux("new-session", "-d", "-s", session, "-x", "120", "-y", "40", command)
    try:
        _wait_for(session, "What must the drive do?")
        _tmux("send-keys", "-t", session, "C-n")
        _wait_for(session, "Axial force [N]")
        _tmux("send-keys", "-t", session, "600", "Enter", "25", "Enter")
        monkeypatch.setenv("XDG_STATE_HOME", str(state))  # where the wizard saves its draft
        draft = draft_path(src)
        want = {"force_N": 600.0, "stroke_m": 25.0}
        saved: dict = {}
        for _ in range(300):  # a loaded machine can take seconds (the draft goes key by key)
            if draft.exists():
                saved = tomllib.loads(draft.read_text(encoding="utf-8"))
                if saved.get("linear") == want:
                    break
            time.sleep(0.1)
        assert saved.get("linear") == want
        shown: dict[str, str] = {}
        for _ in range(300):  # the screen is painted after the draft is written
            shown = {
                name: line.split("▊")[-1].strip(" ▎")
                for line in _tmux("capture-pane", "-p", "-t", session).splitlines()
                for name in ("Axial force [N]", "Stroke [m]")
                if name in line
            }
            if shown == {"Axial force [N]": "600", "Stroke [m]": "25"}:
                break
            time.sleep(0.1)
        assert shown == {"Axial force [N]": "600", "Stroke [m]": "25"}
        _tmux("send-keys", "-t", session, "C-q")
    finally:
        _tmux("kill-server", check=False)


def test_keys_at_the_first_paint_are_answered_before_the_rest_of_the_start(tmp_path):
    """f1 the moment the first step shows opens the help (the warm-up and the result views
    wait until the keyboard is quiet); closed, a ctrl+r then computes, the result views
    mounted by then."""
    src = EXAMPLES / "rudder_actuator.toml"
    session = f"advisor-e2e-{uuid.uuid4().hex[:8]}"
    env = (
        f"XDG_STATE_HOME={tmp_path / 'state'} TEXTUAL_ANIMATIONS=none "
        f"PATH={os.path.dirname(sys.executable)}:{os.environ.get('PATH', '')}"
    )
    command = f"cd {tmp_path} && env {env} {sys.executable} -m advisor {src}"
    _tmux("new-session", "-d", "-s", session, "-x", "120", "-y", "40", command)
    try:
        _wait_for(session, "What must the drive do?")
        _tmux("send-keys", "-t", session, "F1")
        _wait_for(session, "f1       this help")
        _tmux("send-keys", "-t", session, "Escape")
        for _ in range(150):  # (an escape alone waits a moment for a sequence to follow)
            if "this help" not in _tmux("capture-pane", "-p", "-t", session):
                break
            time.sleep(0.2)
        _tmux("send-keys", "-t", session, "C-r")
        screen = _wait_for(session, "status: feasible")
        assert "Results" in screen
        _tmux("send-keys", "-t", session, "C-q")
    finally:
        _tmux("kill-server", check=False)
