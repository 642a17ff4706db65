"""Shared fixtures, and the suite's organisation: a test's folder is its kind, and its marker.

- ``unit``: one module's calculation or contract, in process, milliseconds each;
- ``golden``: a published worked example or a hand calculation reproduced;
- ``property``: hypothesis and exhaustive sweeps over the input space;
- ``tui``: the wizard under textual's Pilot, its snapshots, and in a real terminal (tmux);
- ``e2e``: the commands as a user runs them (batch, family, diff, verify), files and docs.

``python -m pytest -q -m fast`` is the quick subset (unit and golden, less the few tests
marked ``slow``); the whole suite stays the README's test command.
"""

import os
from pathlib import Path

import pytest

KINDS = ("unit", "golden", "property", "tui", "e2e")
FAST = ("unit", "golden")


def pytest_collection_modifyitems(config, items):
    """Mark every test with its folder's kind, and ``fast`` where the kind is quick and the
    test is not marked ``slow``."""
    tests = Path(__file__).parent
    for item in items:
        try:
            kind = Path(item.fspath).relative_to(tests).parts[0]
        except ValueError:  # a doctest in the package
            kind = "unit"
        if kind in KINDS:
            item.add_marker(getattr(pytest.mark, kind))
        if kind in FAST and item.get_closest_marker("slow") is None:
            item.add_marker(pytest.mark.fast)


@pytest.fixture(autouse=True)
def _isolated_cache(tmp_path_factory, monkeypatch):
    """Each test session validates catalogs into its own cache, never the user's."""
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path_factory.getbasetemp() / "cache"))
    os.environ.setdefault("PYDANTIC_DISABLE_PLUGINS", "__all__")


class WizardPilot:
    """What every test of the wizard under textual's Pilot shares: the screen size, a
    compute waited for, and what a Static or Label shows as plain text."""

    SIZE = (120, 40)

    @staticmethod
    def text(widget, width: int = 300) -> str:
        """What ``widget`` shows (its content, else its render), as plain text."""
        from rich.console import Console

        with open(os.devnull, "w") as sink:
            console = Console(width=width, record=True, file=sink)
            console.print(widget.content if hasattr(widget, "content") else widget.render())
            return console.export_text()

    @staticmethod
    async def settle(pilot, start: int) -> None:
        """Until a result newer than ``start`` (a ``results_version``) is shown and nothing
        computes; a loaded machine can take seconds for a first compute."""
        app = pilot.app
        for _ in range(3000):
            await pilot.pause(0.02)
            if app.results_version > start and not app.computing:
                return
        raise AssertionError("no result")

    async def compute(self, pilot) -> None:
        """ctrl+r, and its result shown (painted: a snapshot can follow)."""
        start = pilot.app.results_version
        await pilot.press("ctrl+r")
        await self.settle(pilot, start)
        await pilot.pause()

    @staticmethod
    async def export_report(pilot, target: Path) -> None:
        """ctrl+s, the report's path typed into the export screen, saved, the screen gone."""
        from textual.widgets import Input

        from advisor.tui.screens.export import ExportScreen

        await pilot.press("ctrl+s")
        await pilot.pause()
        assert isinstance(pilot.app.screen, ExportScreen)
        pilot.app.screen.query_one("#export-path", Input).value = str(target)
        await pilot.click("#save-report")
        await pilot.pause()
        assert not isinstance(pilot.app.screen, ExportScreen)


@pytest.fixture
def wizard(tmp_path, monkeypatch):
    """The wizard's Pilot tests: drafts in a state directory of the test's own, no
    animation, the working directory a temporary one (an export lands there)."""
    monkeypatch.setenv("XDG_STATE_HOME", str(tmp_path / "state"))
    monkeypatch.setenv("TEXTUAL_ANIMATIONS", "none")
    monkeypatch.chdir(tmp_path)
    return WizardPilot()
