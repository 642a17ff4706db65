"""The wizard's drafts: saved on every change to the user's state directory, offered back at
the next start. Written atomically, like the reports, so a crash never leaves half a file.

Drafts are named by what they edit: a new requirement has ``draft.toml``; an opened file has
its own draft under ``drafts/`` (named after the file and a hash of its absolute path), so
opening a file never replaces the unsaved draft of another requirement."""

import hashlib
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


def draft_path(source: Path | None = None) -> Path:
    """``draft.toml`` for a new requirement; ``drafts/<stem>-<hash>.toml`` for a file."""
    if source is None:
        return state_dir() / "draft.toml"
    key = hashlib.sha256(str(Path(source).resolve()).encode()).hexdigest()[:10]
    return state_dir() / "drafts" / f"{Path(source).stem}-{key}.toml"


def save_draft(doc: dict[str, Any], source: Path | None = None) -> None:
    path = draft_path(source)
    path.parent.mkdir(parents=True, exist_ok=True)
    write_atomic(path, tomli_w.dumps(doc))


def load_draft(source: Path | None = None) -> dict[str, Any] | None:
    """The saved draft, or None when there is none (or it cannot be read: a broken draft is
    set aside, not shown as an error)."""
    path = draft_path(source)
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except (OSError, tomllib.TOMLDecodeError, UnicodeDecodeError):
        return None
    return data or None


def clear_draft(source: Path | None = None) -> None:
    try:
        draft_path(source).unlink()
    except OSError:
        pass
