"""TOML text of a report: tomli-w's layout, byte for byte, in less time.

tomli-w formats through generators and one ``isinstance`` chain per value, and escapes
strings character by character; a report holds a few thousand values, and that made TOML
output a third of a warm linear advice. This writer takes the plain data a report
is made of (dicts, lists, str, int, float, bool, as :func:`advisor.core.report.plain_data`
returns them) and writes what ``tomli_w.dumps(doc)`` writes with its defaults (indent 4, no
multi-line strings): the same table order, the same inline-table heuristic (an array of
tables is written inline when every table fits on a line of 100 characters), the same
escapes. ``tests/unit/test_report.py`` holds it to tomli-w on the examples and on generated
documents.
"""

import re
from collections.abc import Callable
from typing import Any, NamedTuple

#: tomli-w's: a line of an inline array of tables holds at most this many characters.
MAX_LINE_LENGTH = 100
INDENT = "    "

_ILLEGAL = re.compile(r'[\x00-\x08\x0a-\x1f\x7f"\\]')  # ASCII controls but tab, " and \
_ESCAPES = {"\b": "\\b", "\n": "\\n", "\f": "\\f", "\r": "\\r", '"': '\\"', "\\": "\\\\"}
_BARE = re.compile(r"[A-Za-z0-9_-]+")
_keys: dict[str, str] = {}
_FLOAT, _STR = {float}, {str}


def _escape(m: re.Match) -> str:
    c = m.group()
    return _ESCAPES.get(c) or f"\\u{ord(c):04x}"


def string(s: str) -> str:
    """A basic string: ``"`` and ``\\`` escaped, control characters (tab kept) escaped as
    tomli-w escapes them."""
    return f'"{_ILLEGAL.sub(_escape, s)}"' if _ILLEGAL.search(s) else f'"{s}"'


def key(part: str) -> str:
    """A key: bare where it is made of ``A-Za-z0-9_-`` only, else quoted."""
    out = _keys.get(part)
    if out is None:
        if not isinstance(part, str):
            raise TypeError(f"Invalid mapping key '{part}' of type '{type(part).__qualname__}'.")
        out = part if _BARE.fullmatch(part) else string(part)
        if len(_keys) < 4096:
            _keys[part] = out
    return out


def _joined_str(xs: list[float], sep: str) -> str:
    return sep.join(map(str, xs))


class Floats(NamedTuple):
    """How floats are written: ``one(x)`` a float, ``many(xs, sep)`` the floats of an array
    joined by ``sep`` (what ``sep.join(map(one, xs))`` writes, in fewer calls: a curve is
    hundreds of them). tomli-w's ``str`` by default."""

    one: Callable[[float], str] = str
    many: Callable[[list[float], str], str] = _joined_str


#: tomli-w's floats: ``str``.
TOMLI_W = Floats()


def literal(obj: Any, nest: int = 0, floats: Floats = TOMLI_W) -> str:
    """A value on the right of ``=`` (arrays one item a line, indented by ``nest``)."""
    t = type(obj)
    if t is str:
        return string(obj)
    if t is float:
        return floats.one(obj)
    if t is int:
        return str(obj)
    if t is bool:
        return "true" if obj else "false"
    if t is list or t is tuple:
        return array(obj, nest, floats)
    if t is dict:
        return inline_table(obj, floats)
    if isinstance(obj, bool):
        return "true" if obj else "false"
    if isinstance(obj, float):
        return floats.one(obj)
    if isinstance(obj, int):
        return str(obj)
    if isinstance(obj, str):
        return string(obj)
    if isinstance(obj, list | tuple):
        return array(list(obj), nest, floats)
    if isinstance(obj, dict):
        return inline_table(obj, floats)
    raise TypeError(f"Object of type '{type(obj).__qualname__}' is not TOML serializable")


def array(obj: list | tuple, nest: int = 0, floats: Floats = TOMLI_W) -> str:
    """An array, one item a line. An array of one kind of value (a curve of floats, a list of
    words) is written in one join, as :func:`literal` writes each item."""
    if not obj:
        return "[]"
    inner = INDENT * (nest + 1)
    kinds = set(map(type, obj))  # one pass in C: a curve is hundreds of floats
    sep = f",\n{inner}"
    if kinds == _FLOAT:
        items = floats.many(obj, sep)
    elif kinds == _STR:
        items = sep.join(map(string, obj))
    else:
        items = sep.join(literal(x, nest + 1, floats) for x in obj)
    return f"[\n{inner}{items},\n{INDENT * nest}]"


def inline_table(obj: dict, floats: Floats = TOMLI_W) -> str:
    if not obj:
        return "{}"
    return "{ " + ", ".join(f"{key(k)} = {literal(v, 0, floats)}" for k, v in obj.items()) + " }"


def _inline_tables(tables: list | tuple, floats: Floats) -> str | None:
    """An array of tables written inline, each on its line, as tomli-w writes one when every
    table fits on a line of :data:`MAX_LINE_LENGTH`; None when one does not (it is written
    as ``[[name]]`` tables)."""
    texts = []
    for t in tables:
        text = inline_table(t, floats)
        if len(text) > MAX_LINE_LENGTH - len(INDENT) - 1 or "\n" in text:  # indent + text + ","
            return None
        texts.append(text)
    return "[\n" + "".join(f"{INDENT}{text},\n" for text in texts) + "]"


def _is_aot(v: list | tuple) -> bool:
    """A non-empty array of tables (tomli-w's test; the first item tells most arrays)."""
    return bool(v) and isinstance(v[0], dict) and all(isinstance(x, dict) for x in v)


def _table(
    table: dict, out: list[str], name: str, floats: Floats, inside_aot: bool = False
) -> None:
    literals: list[str] = []
    tables: list[tuple[str, dict, bool]] = []
    keys, needs_escape, one = _keys, _ILLEGAL.search, floats.one
    for k, v in table.items():
        t = type(v)  # the scalars first, as key() and literal() write them: most values are
        if t is str:
            key_text = keys.get(k) or key(k)
            if needs_escape(v) is None:
                literals.append(f'{key_text} = "{v}"\n')
            else:
                literals.append(f"{key_text} = {string(v)}\n")
        elif t is float:
            literals.append(f"{keys.get(k) or key(k)} = {one(v)}\n")
        elif t is int:
            literals.append(f"{keys.get(k) or key(k)} = {v}\n")
        elif isinstance(v, dict):
            tables.append((k, v, False))
        elif isinstance(v, list | tuple):
            text = _inline_tables(v, floats) if _is_aot(v) else array(v, 0, floats)
            if text is None:  # tables too wide to be written inline: [[name]] tables
                tables.extend((k, t, True) for t in v)
            else:
                literals.append(f"{keys.get(k) or key(k)} = {text}\n")
        else:
            literals.append(f"{key(k)} = {literal(v, 0, floats)}\n")
    yielded = False
    if inside_aot or (name and (literals or not tables)):
        yielded = True
        out.append(f"[[{name}]]\n" if inside_aot else f"[{name}]\n")
    if literals:
        yielded = True
        out.extend(literals)
    for k, v, in_aot in tables:
        if yielded:
            out.append("\n")
        else:
            yielded = True
        part = key(k)
        _table(v, out, f"{name}.{part}" if name else part, floats, in_aot)


def dumps(doc: dict, floats: Floats = TOMLI_W) -> str:
    """``doc`` as TOML text, as ``tomli_w.dumps(doc)`` writes it; with ``floats`` each float
    is written as it says (:func:`advisor.core.report.float_text`: rounded as it is written,
    in one formatting per number)."""
    out: list[str] = []
    _table(doc, out, "", floats)
    return "".join(out)
