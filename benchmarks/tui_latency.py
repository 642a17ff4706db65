"""The wizard's latency as a user sees it: in a real pseudo-terminal, from the keystroke
written to the terminal to the screen painted back. Nothing of textual's test harness is in
the loop: the wizard runs as ``python -m advisor EXAMPLE`` on the slave side of a pty (as in
a terminal emulator), keys are written to the master side and the painted output is read
from it until the text that only the new screen shows has arrived.

Per example:

- **first screen**: from starting the process to the first step painted;
- **first compute**: ctrl+r on that first screen to the results painted (cold: the
  application's modules, catalogs and the engine are loaded on that key);
- **recompute**: an edit (a new title), then ctrl+r to the results painted, the median and
  the maximum over repeats.

Goals (issue 14): first screen ≤ 0.5 s; keystroke → results painted ≤ 100 ms, the first
compute included.

``--first-key`` measures a key pressed the moment the first screen paints (F1, the help
screen, written as soon as the first step is read back) against the same key in the same
process once the screen has settled, paired per start; with ``--tree DIR`` the runs
alternate between this checkout and the one in DIR (the same measurement on old code and
new, at the same moments). Goal (issue 29): ≤ 100 ms at the first paint.

``--floor`` measures the floor of the first screen in the same harness: a minimal textual
app that paints one Static with the same words (textual's import, its start and one paint).
"""

import fcntl
import os
import pty
import re
import select
import statistics
import struct
import sys
import tempfile
import termios
import time
from pathlib import Path

from _results import examples

COLS, ROWS = 120, 40
ANSI = re.compile(rb"\x1b\[[0-9;?<>=]*[ -/]*[@-~]|\x1b[()][0-9A-Za-z]|\x1b[=>78]|\x1b\].*?\x07")
TIMEOUT_S = 60.0


class Terminal:
    """The wizard on the slave side of a pseudo-terminal of COLS × ROWS."""

    def __init__(self, example: Path | None, state_dir: str, tree: Path | None = None) -> None:
        env = {
            **os.environ,
            "TERM": "xterm-256color",
            "COLUMNS": str(COLS),
            "LINES": str(ROWS),
            "XDG_STATE_HOME": state_dir,
            "TEXTUAL_ANIMATIONS": "none",
        }
        self.started = time.perf_counter()
        pid, fd = pty.fork()
        if pid == 0:  # the child: the wizard, its terminal sized before it starts
            fcntl.ioctl(0, termios.TIOCSWINSZ, struct.pack("HHHH", ROWS, COLS, 0, 0))
            if tree is not None:  # ``-m advisor`` then imports that checkout's package
                os.chdir(tree)
            args = ["-m", "advisor", str(example)] if example else ["-c", FLOOR_APP]
            os.execve(sys.executable, [sys.executable, *args], env)
        self.pid, self.fd = pid, fd
        self.seen = b""

    def _read(self, until: float) -> None:
        while time.perf_counter() < until:
            ready, _, _ = select.select([self.fd], [], [], max(0.0, until - time.perf_counter()))
            if not ready:
                return
            try:
                chunk = os.read(self.fd, 65536)
            except OSError:
                return
            if not chunk:
                return
            self.seen += chunk
            return

    def wait_for(self, text: str) -> float:
        """Read until ``text`` is painted; the time it arrived (perf_counter)."""
        want = text.encode()
        end = time.perf_counter() + TIMEOUT_S
        while time.perf_counter() < end:
            if want in ANSI.sub(b"", self.seen):
                return time.perf_counter()
            self._read(end)
        raise TimeoutError(f"{text!r} was never painted")

    def drain(self, quiet_s: float = 0.3) -> None:
        """Read until the screen has been still for ``quiet_s``; forget what was read."""
        while True:
            before = len(self.seen)
            self._read(time.perf_counter() + quiet_s)
            if len(self.seen) == before:
                break
        self.seen = b""

    def send(self, keys: str) -> float:
        """Write keys as a terminal would; the time they were written."""
        self.seen = b""
        t = time.perf_counter()
        os.write(self.fd, keys.encode())
        return t

    def close(self) -> None:
        try:
            os.write(self.fd, b"\x11")  # ctrl+q
            time.sleep(0.3)
        except OSError:
            pass
        try:
            os.kill(self.pid, 9)
        except ProcessLookupError:
            pass
        os.waitpid(self.pid, 0)
        os.close(self.fd)


CTRL_R, CTRL_E, TAB = "\x12", "\x05", "\t"

#: The floor of a first screen: textual imported, started, one Static painted.
FLOOR_APP = """
from textual.app import App
from textual.widgets import Static
class Floor(App):
    def compose(self):
        yield Static("What must the drive do?")
Floor().run()
"""


def floor(repeats: int) -> list[float]:
    """Start → first screen painted (ms) of :data:`FLOOR_APP`, ``repeats`` times."""
    out = []
    with tempfile.TemporaryDirectory() as state:
        for _ in range(repeats):
            term = Terminal(None, state)
            try:
                out.append(1e3 * (term.wait_for("What must the drive do?") - term.started))
            finally:
                term.close()
    return out


def measure(example: Path, repeats: int, tree: Path | None = None) -> dict:
    # the floor's first screen just before, paired: the virtual machine's speed drifts, and a
    # first screen is judged against what textual alone takes at the same moment
    floor_ms = floor(1)[0]
    with tempfile.TemporaryDirectory() as state:
        term = Terminal(example, state, tree)
        try:
            first_screen = term.wait_for("What must the drive do?") - term.started
            term.drain()
            t = term.send(CTRL_R)
            first_compute = term.wait_for("status: ") - t
            times = []
            for k in range(repeats):
                term.drain()
                # back to the inputs (step 1: the kind has the focus), tab to the title,
                # type a new one (the box selects its text on focus: typing replaces it)
                title = f"what-if {k:03d}"
                term.send(CTRL_E)
                term.wait_for("What must the drive do?")
                term.drain()
                term.send(TAB)
                term.drain()
                term.send(title)
                term.wait_for(title)
                term.drain()
                t = term.send(CTRL_R)
                times.append(term.wait_for(title) - t)
        finally:
            term.close()
    return {
        "floor_first_screen_ms": floor_ms,
        "first_screen_ms": 1e3 * first_screen,
        "first_compute_ms": 1e3 * first_compute,
        "median_ms": 1e3 * statistics.median(times),
        "max_ms": 1e3 * max(times),
    }


F1, ESCAPE = "\x1bOP", "\x1b"
#: Text only the help screen shows.
HELP_SHOWN = "this help"


def first_key(example: Path, tree: Path | None = None) -> tuple[float, float]:
    """F1 written the moment the first step is read back → the help painted (ms), and the
    same once the screen has settled, in one start of the wizard on ``example``."""
    with tempfile.TemporaryDirectory() as state:
        term = Terminal(example, state, tree)
        try:
            term.wait_for("What must the drive do?")
            t = term.send(F1)
            at_paint = term.wait_for(HELP_SHOWN) - t
            term.drain()
            term.send(ESCAPE)
            term.drain(1.0)
            t = term.send(F1)
            settled = term.wait_for(HELP_SHOWN) - t
        finally:
            term.close()
    return 1e3 * at_paint, 1e3 * settled


def first_keys(example: Path, runs: int, tree: Path | None = None) -> dict:
    """:func:`first_key` ``runs`` times on this checkout (and on ``tree``'s, alternating)."""
    mine: list[tuple[float, float]] = []
    theirs: list[tuple[float, float]] = []
    for _ in range(runs):
        if tree is not None:
            theirs.append(first_key(example, tree))
        mine.append(first_key(example))

    def summary(pairs: list[tuple[float, float]]) -> dict:
        at_paint, settled = zip(*pairs, strict=True)
        return {
            "at_paint_median_ms": statistics.median(at_paint),
            "at_paint_range_ms": (min(at_paint), max(at_paint)),
            "settled_median_ms": statistics.median(settled),
            "settled_range_ms": (min(settled), max(settled)),
        }

    out = {"this": summary(mine)}
    if theirs:
        out[str(tree)] = summary(theirs)
    return out


def tui_latency(repeats: int) -> dict:
    return {ex.name: measure(ex, repeats) for ex in examples()}


if __name__ == "__main__":
    print(f"load average before: {os.getloadavg()[0]:.2f}, {os.cpu_count()} CPUs")
    if "--first-key" in sys.argv:
        sys.argv.remove("--first-key")
        tree = None
        if "--tree" in sys.argv:
            i = sys.argv.index("--tree")
            tree = Path(sys.argv[i + 1]).resolve()
            del sys.argv[i : i + 2]
        runs = int(sys.argv[1]) if len(sys.argv) > 1 else 10
        for name in ("rudder_actuator.toml", "linear_screw_actuator.toml"):
            ex = next(e for e in examples() if e.name == name)
            for which, r in first_keys(ex, runs, tree).items():
                lo, hi = r["at_paint_range_ms"]
                slo, shi = r["settled_range_ms"]
                print(
                    f"{name} [{which}]: F1 at the first paint {r['at_paint_median_ms']:.0f} ms "
                    f"median ({lo:.0f}–{hi:.0f}), settled {r['settled_median_ms']:.0f} ms "
                    f"({slo:.0f}–{shi:.0f})"
                )
        print(f"load average after: {os.getloadavg()[0]:.2f}")
        sys.exit(0)
    if "--floor" in sys.argv:
        sys.argv.remove("--floor")
        ms = floor(int(sys.argv[1]) if len(sys.argv) > 1 else 10)
        print(
            f"floor (a textual app painting one Static): first screen {statistics.median(ms):.0f}"
            f" ms median ({min(ms):.0f}–{max(ms):.0f} ms)"
        )
        sys.exit(0)
    for name, r in tui_latency(int(sys.argv[1]) if len(sys.argv) > 1 else 10).items():
        print(
            f"{name}: first screen {r['first_screen_ms']:.0f} ms (floor just before "
            f"{r['floor_first_screen_ms']:.0f} ms), first compute "
            f"{r['first_compute_ms']:.0f} ms, recompute {r['median_ms']:.0f} ms median "
            f"({r['max_ms']:.0f} ms max)"
        )
    print(f"load average after: {os.getloadavg()[0]:.2f}")
