"""The wizard's draft: saved on every change to the user's state directory, offered back at
the next start. Written atomically, like the reports, so a crash never leaves half a file."""

import os
import tomllib
from pathlib import Path
from typing import Any

import tomli_w

from advisor.core.report import write_atomic


def state_dir() -> Path:
    base = os.environ.get("XDG_STATE_HOME") or os.path.join(
        os.path.expanduser("~"), ".local", "state"
    )
    return Path(base) / "drive-advisor"


def draft_path() -> Path:
    return state_dir() / "draft.toml"


def save_draft(doc: dict[str, Any]) -> None:
    path = draft_path()
    path.parent.mkdir(parents=True, exist_ok=True)
    write_atomic(path, tomli_w.dumps(doc))


def load_draft() -> dict[str, Any] | None:
    """The saved draft, or None when there is none (or it cannot be read: a broken draft is
    set aside, not shown as an error)."""
    path = draft_path()
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except (OSError, tomllib.TOMLDecodeError, UnicodeDecodeError):
        return None
    return data or None


def clear_draft() -> None:
    try:
        draft_path().unlink()
    except OSError:
        pass
