"""The wizard's modal screens, one a module."""

from advisor.tui.screens.confirm import ConfirmScreen
from advisor.tui.screens.export import ExportScreen
from advisor.tui.screens.help import HelpScreen

__all__ = ["ConfirmScreen", "ExportScreen", "HelpScreen"]
