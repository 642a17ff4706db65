"""The help screen: the wizard's keys, written in :file:`advisor/tui/help.md`."""

import re
from functools import cache
from importlib.resources import files
from typing import ClassVar

from textual import on
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical
from textual.screen import ModalScreen
from textual.widgets import Button, Static


@cache
def help_text() -> str:
    """The help, as console markup: Markdown's ``**bold**`` is the only markup it uses (a
    line such as ``[ / ]`` is no markup tag and shows as written)."""
    text = files("advisor.tui").joinpath("help.md").read_text(encoding="utf-8")
    return re.sub(r"\*\*(.+?)\*\*", r"[b]\1[/b]", text)


class HelpScreen(ModalScreen[None]):
    """The keys, from :file:`advisor/tui/help.md`."""

    BINDINGS: ClassVar = [Binding("escape,f1,q", "dismiss", "Close")]

    def compose(self) -> ComposeResult:
        with Vertical(id="dialog"):
            yield Static(help_text(), id="help-text")
            yield Button("Close", id="close", variant="primary")

    @on(Button.Pressed, "#close")
    def _close(self) -> None:
        self.dismiss()
