"""How each message the engine gives about a requirement can be resolved inside the wizard,
when no field of the wizard can: an unknown key is removed or renamed to the closest known
key (by :mod:`difflib`), a value the wizard does not ask for is removed so that its default
applies. Pure functions of the document; no textual here."""

import difflib
import re
from typing import Any, NamedTuple

from advisor.tui import fields as F


class Fix(NamedTuple):
    label: str  # the button's words
    op: str  # "remove" | "rename"
    path: tuple[str, ...]  # into the document; list items by index from 0
    to: str = ""  # the new key of a rename


def message_path(line: str) -> tuple[str, ...]:
    """The path an engine message names (``positioning.motors[2].nam: …`` →
    ``('positioning', 'motors', '1', 'nam')``); list items are counted from 1 in messages."""
    head = re.split(r"[ :=]", line, maxsplit=1)[0]
    parts: list[str] = []
    for token in re.findall(r"[^.\[\]]+|\[\d+\]", head):
        parts.append(str(int(token[1:-1]) - 1) if token.startswith("[") else token)
    return tuple(parts)


def _parent(doc: Any, path: tuple[str, ...]) -> Any:
    node = doc
    for key in path[:-1]:
        if isinstance(node, list) and key.isdigit() and int(key) < len(node):
            node = node[int(key)]
        elif isinstance(node, dict) and key in node:
            node = node[key]
        else:
            return None
    return node


def present(doc: Any, path: tuple[str, ...]) -> bool:
    parent = _parent(doc, path)
    return bool(path) and isinstance(parent, dict) and path[-1] in parent


def closest(key: str, allowed: list[str]) -> str | None:
    """The known key closest to a mistyped one (``strok_m`` → ``stroke_m``), None if none is
    close."""
    found = difflib.get_close_matches(key, allowed, n=1, cutoff=0.6)
    return found[0] if found else None


def fixes_for(line: str, doc: dict[str, Any], kind: str | None) -> list[Fix]:
    """The ways to resolve a message that no field of the wizard resolves (empty: a field
    does, or nothing in the document can be changed for it)."""
    path = message_path(line)
    if not path or not present(doc, path):
        return []
    dotted = ".".join(path)
    asked = {f.dotted for f in F.all_fields(kind)} if kind else set()
    asked.add("application.title")
    if dotted in asked:
        return []  # its own field shows and resolves it
    key = path[-1]
    if "unknown key" in line:
        allowed = [k.strip() for k in line.split("allowed keys here:", 1)[-1].split(",")]
        out = [Fix(f"Remove {key}", "remove", path)]
        target = closest(key, [a for a in allowed if a])
        parent = _parent(doc, path)
        if target is not None and not (isinstance(parent, dict) and target in parent):
            out.insert(0, Fix(f"Rename to {target}", "rename", path, target))
        return out
    return [Fix(f"Remove {dotted} (its default applies)", "remove", path)]


def apply(doc: dict[str, Any], fix: Fix) -> None:
    """Carry out a fix on the document (in place)."""
    parent = _parent(doc, fix.path)
    if not isinstance(parent, dict) or fix.path[-1] not in parent:
        return
    value = parent.pop(fix.path[-1])
    if fix.op == "rename":
        parent[fix.to] = value


def fill_fixed(doc: dict[str, Any], kind: str) -> list[str]:
    """Put the values that allow one choice only (the motor kind) where a file lacks them;
    the dotted paths filled."""
    filled = []
    for path, value in F.starting_doc_values(kind).items():
        if F.get(doc, path) is None and isinstance(_parent_or_make(doc, path), dict):
            F.put(doc, path, value)
            filled.append(".".join(path))
    return filled


def _parent_or_make(doc: dict[str, Any], path: tuple[str, ...]) -> Any:
    node: Any = doc
    for key in path[:-1]:
        if not isinstance(node, dict):
            return None
        node = node.get(key, {})
    return node
