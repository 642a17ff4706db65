"""Modules of the wizard imported when first used, not when the app module is.

The wizard's fields, drafts, fixes and views import the requirement models (pydantic), which
the first screen must not wait for: the app names them through these stand-ins, and the
module is imported at the first attribute read.
"""

import importlib
from typing import Any


class OnFirstUse:
    """A module imported when first used (an attribute read imports it, then reads it)."""

    def __init__(self, name: str) -> None:
        self.__dict__["_name"] = name

    def __getattr__(self, attr: str) -> Any:
        return getattr(importlib.import_module(self._name), attr)


drafts: Any = OnFirstUse("advisor.tui.draft")
fields: Any = OnFirstUse("advisor.tui.fields")
fixes: Any = OnFirstUse("advisor.tui.fixes")
views: Any = OnFirstUse("advisor.tui.views")
