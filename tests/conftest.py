import os

import pytest


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


@pytest.fixture
def wizard(tmp_path, monkeypatch):
    """The wizard's Pilot tests: drafts in a state directory of the test's own, no
    animation, the working directory a temporary one (an export lands there)."""
    monkeypatch.setenv("XDG_STATE_HOME", str(tmp_path / "state"))
    monkeypatch.setenv("TEXTUAL_ANIMATIONS", "none")
    monkeypatch.chdir(tmp_path)
    return WizardPilot()
