"""pydantic without its plugin discovery: the advisor uses no pydantic plugin.

On its first validator, pydantic asks :mod:`pydantic.plugin._loader` for plugins, and that
module imports :mod:`importlib.metadata` at its top (with ``email``, ``zipfile``, ``csv``,
``socket``…): about 20 ms of a 0.3 s batch run, even when ``PYDANTIC_DISABLE_PLUGINS`` tells
it to load none. :func:`disable` sets that variable and, before pydantic imports the loader,
puts in its place a module whose ``get_plugins`` returns what the real one returns then: no
plugin. Any other name asked of it comes from the real module, loaded on that request, so a
pydantic that asks more of its loader still gets it.

Nothing is replaced when the user chose plugins (``PYDANTIC_DISABLE_PLUGINS`` set to anything
else) or when the loader is already imported.
"""

import os
import sys
import types
from collections.abc import Iterable
from typing import Any

LOADER = "pydantic.plugin._loader"


def _no_plugins() -> Iterable[Any]:
    return ()


def _real_loader() -> types.ModuleType:
    """The real loader module, executed from its own file (not registered in sys.modules)."""
    import importlib.machinery
    import importlib.util

    import pydantic.plugin

    spec = importlib.machinery.PathFinder.find_spec("_loader", list(pydantic.plugin.__path__))
    if spec is None or spec.loader is None:
        raise ImportError(f"{LOADER} not found")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _loader_getattr(name: str) -> Any:
    if name.startswith("__"):
        raise AttributeError(name)
    real = _STUB.__dict__.get("_real")
    if real is None:
        real = _STUB.__dict__["_real"] = _real_loader()
    return getattr(real, name)


_STUB = types.ModuleType(LOADER, "pydantic's plugin loader when no plugin is wanted (advisor)")
_STUB.get_plugins = _no_plugins  # type: ignore[attr-defined]
_STUB.__getattr__ = _loader_getattr  # type: ignore[method-assign]


def disable() -> bool:
    """Tell pydantic to load no plugin, and spare it the metadata scan. True when the light
    loader is in place."""
    os.environ.setdefault("PYDANTIC_DISABLE_PLUGINS", "__all__")
    if os.environ["PYDANTIC_DISABLE_PLUGINS"] != "__all__":
        return False
    if LOADER not in sys.modules:
        sys.modules[LOADER] = _STUB
    return sys.modules[LOADER] is _STUB
