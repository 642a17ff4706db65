"""The wizard's draft: saved on every change to the user's state directory, offered back at
the next start. Written atomically, like the reports, so a crash never leaves half a file.

Loading is defensive: a requirement file or draft is read like a batch input (regular file,
at most 1 MiB, no deep nesting), then :func:`shape` makes it a document the wizard can hold
(tables where tables belong, values of the right kind), saying what it changed. A draft that
cannot be read at all is set aside under a new name, never deleted.

Drafts are named by what they edit: a new requirement has ``draft.toml``; an opened file has
its own draft under ``drafts/`` (named after the file and a hash of its absolute path), so
opening a file never replaces the unsaved draft of another requirement.
"""

import hashlib
import os
import time
from pathlib import Path
from typing import Any, NamedTuple

import tomli_w

from advisor.core.errors import InputError
from advisor.core.io_safety import read_toml, show, show_repr, write_atomic
from advisor.tui import fields


def state_dir() -> Path:
    """``$XDG_STATE_HOME/drive-advisor``; a relative (or empty) XDG_STATE_HOME is ignored,
    as the XDG Base Directory specification requires, for ``~/.local/state``."""
    base = os.environ.get("XDG_STATE_HOME", "")
    if not os.path.isabs(base):
        base = os.path.join(os.path.expanduser("~"), ".local", "state")
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


class Loaded(NamedTuple):
    """A document as the wizard opens it, and what had to be changed or set aside."""

    doc: dict[str, Any] | None
    problems: list[str]
    set_aside: Path | None = None


def _type_name(value: Any) -> str:
    if isinstance(value, bool):
        return "true/false"
    if isinstance(value, int | float):
        return "a number"
    if isinstance(value, str):
        return "text"
    if isinstance(value, dict):
        return "a table"
    if isinstance(value, list):
        return "an array"
    return type(value).__name__


def _echo(value: Any) -> str:
    if isinstance(value, dict):
        return "{…}"
    if isinstance(value, bool):
        return "true" if value else "false"
    return show_repr(value) if isinstance(value, str) else show(value)


def _leaf_ok(field: fields.Field, value: Any) -> str | None:
    """Why ``value`` cannot be shown in ``field``'s widget, or None when it can. Numbers and
    text given with the wrong type stay: they appear in their input box and the field's own
    check says what to fix."""
    if field.kind == "fixed":  # one allowed value, shown not edited: the engine checks it
        return None
    if field.kind == "bool":
        return None if isinstance(value, bool) else "must be true or false"
    if field.kind == "choice":  # text not offered: set aside when its field is built
        ok = value in field.choices or isinstance(value, str)
        return None if ok else f"must be one of {', '.join(field.choices)}"
    if field.kind == "floats":  # a quantity with its unit ("3000 rpm") as the batch takes it
        ok = isinstance(value, list) and all(
            isinstance(v, int | float | str) and not isinstance(v, bool) for v in value
        )
        return None if ok else "must be an array of numbers (or quantities with their unit)"
    if isinstance(value, dict | list):
        return f"must be {'text' if field.kind == 'str' else 'a number'}, not {_type_name(value)}"
    return None


_APP_FIELDS = (fields.Field(("application", "title"), "Title", kind="str", optional=True),)


def shape(doc: Any) -> tuple[dict[str, Any], list[str]]:
    """``doc`` made safe for the wizard, and one message per change (wrong-typed values
    that no widget can show are removed; the message names field, value and what is
    allowed)."""
    problems: list[str] = []
    if not isinstance(doc, dict):
        return {}, ["the file is not a table of requirements"]
    doc = dict(doc)
    kind = _shape_application(doc, problems)
    for field in [*_APP_FIELDS, *(fields.all_fields(kind) if kind else [])]:
        _shape_path(doc, field, problems)
    return doc, problems


def _shape_application(doc: dict[str, Any], problems: list[str]) -> str | None:
    """The registered kind ``doc`` names (None: none); an ``application`` that is not a
    table goes, and so does a kind no application has."""
    app = doc.get("application")
    if app is not None and not isinstance(app, dict):
        problems.append(
            f"application = {_echo(app)}: must be a table ([application] with kind = …); "
            "choose the application again"
        )
        doc.pop("application")
        return None
    if not isinstance(app, dict):
        return None
    kinds = tuple(fields.titles())
    kind = app.get("kind") if app.get("kind") in kinds else None
    if "kind" in app and kind is None:
        problems.append(
            f"application.kind = {_echo(app['kind'])}: must be one of {', '.join(kinds)}; "
            "choose the application again"
        )
        doc["application"] = {k: v for k, v in app.items() if k != "kind"}
    return kind


def _shape_path(doc: dict[str, Any], field: "fields.Field", problems: list[str]) -> None:
    """The tables on ``field``'s path made tables (copies, so the caller's stay as given)
    and its value one the field can show, each change said in ``problems``."""
    node: Any = doc
    path = field.path
    for i, key in enumerate(path):
        where = ".".join(path[: i + 1])
        if isinstance(node, list):
            if int(key) >= len(node):
                return
            value = node[int(key)]
        else:
            if key not in node:
                return
            value = node[key]
        if i == len(path) - 1:
            _shape_leaf(node, key, field, value, where, problems)
            return
        value = _shape_table(value, list if path[i + 1].isdigit() else dict, where, problems)
        node[int(key) if isinstance(node, list) else key] = value
        node = value


def _shape_table(value: Any, want: type, where: str, problems: list[str]) -> Any:
    """``value`` as a copy of the table (``dict``) or array of tables (``list``) it must be;
    anything else is replaced by an empty one."""
    if not isinstance(value, want):
        what = "an array of tables" if want is list else "a table"
        problems.append(f"{where} = {_echo(value)}: must be {what}; removed")
        value = want()
    else:
        value = (
            [dict(v) if isinstance(v, dict) else v for v in value] if want is list else dict(value)
        )
    if want is list:
        for j, item in enumerate(value):
            if not isinstance(item, dict):
                problems.append(f"{where}[{j + 1}] = {_echo(item)}: must be a table; removed")
                value[j] = {}
    return value


def _shape_leaf(
    node: Any, key: str, field: "fields.Field", value: Any, where: str, problems: list[str]
) -> None:
    """A field's value in its table ``node``: a number written with its unit read as the
    batch reads it, text made text, and a value of a type the field cannot hold removed."""
    index = key if isinstance(node, dict) else int(key)
    why = _leaf_ok(field, value)
    if why is None and field.kind == "float" and isinstance(value, str):
        number, err = fields.parse_text(field, value)  # "5 kN", as batch reads it
        if err is None and number is not None:
            node[index] = number
            return
    if why is None and field.kind == "floats" and any(isinstance(v, str) for v in value):
        problems.extend(_item_problems(field, value, where))  # each said as the batch says it
    elif why is None and field.kind in ("float", "int") and isinstance(value, str | bool):
        problems.append(f"{where} = {_echo(value)}: must be a number; fix it here")
    elif why is None and field.kind == "choice" and value not in field.choices:
        choices = ", ".join(field.choices)
        problems.append(f"{where} = {_echo(value)}: must be one of {choices}; shown in its field")
    elif why is None and field.kind == "str" and not isinstance(value, str):
        problems.append(f"{where} = {_echo(value)}: must be text in quotes")
        node[index] = str(value)
    if why is not None:
        problems.append(f"{where} = {_echo(value)}: {why}; removed")
        del node[index]


def _item_problems(field: "fields.Field", value: list[Any], where: str) -> list[str]:
    """The strings of a loaded list that are no quantity of its field, one line each in the
    batch's words (``motor.candidate_speeds_rpm[2] = '3,5 rpm': …``); kept in the field
    (shown quoted, as written) to be fixed there."""
    out = []
    for k, item in enumerate(value, start=1):
        if isinstance(item, str):
            try:
                fields.quantity(field, item)
            except ValueError as exc:
                out.append(f"{where}[{k}] = {_echo(item)}: {exc}; fix it here")
    return out


def open_doc(path: Path) -> Loaded:
    """A requirement file for the wizard; :class:`InputError` when it cannot be read."""
    doc, problems = shape(read_toml(path))
    return Loaded(doc, problems)


def _set_aside(path: Path) -> Path | None:
    """Rename an unreadable draft beside itself (``draft.unreadable-20261121-124501.toml``)."""
    stamp = time.strftime("%Y%m%d-%H%M%S", time.gmtime())
    for n in range(1, 100):
        new = path.with_name(f"draft.unreadable-{stamp}{'' if n == 1 else f'-{n}'}.toml")
        if new.exists() or new.is_symlink():
            continue
        try:
            os.rename(path, new)
        except OSError:
            return None
        return new
    return None


def load_draft(source: Path | None = None) -> Loaded:
    """The saved draft of a new requirement, or of the file ``source`` (None when there is
    none). A draft that cannot be read is set aside under a new name and the problem
    returned, so the wizard can say so."""
    path = draft_path(source)
    if not os.path.lexists(path):
        return Loaded(None, [])
    try:
        doc, problems = shape(read_toml(path))
    except InputError as exc:
        moved = _set_aside(path)
        why = str(exc).splitlines()[0].removeprefix(f"{show(path, 200)}: ")
        where = f"set aside as {moved}" if moved else f"left at {path} (it could not be moved)"
        return Loaded(None, [f"the saved draft could not be read ({why}); it was {where}"], moved)
    return Loaded(doc or None, problems)


def clear_draft(source: Path | None = None) -> None:
    try:
        draft_path(source).unlink()
    except OSError:
        pass
