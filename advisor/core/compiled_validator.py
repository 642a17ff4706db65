"""A requirement document validated without pydantic, against the compiled spec.

The requirement models are the one source of truth (:mod:`advisor.core.requirements` and
``advisor/applications/*/requirements.py``); :mod:`advisor.core.spec_gen` compiles them into
:mod:`advisor.core.requirement_spec`: each field's type, range and default, and each model's
own checks, which are pure functions the models run too. This module applies that spec, so
that a batch run does not import pydantic's model machinery (about 0.1 s, more than the
advice itself).

It decides only *whether* a document is valid, and builds the same values the models would.
It never words a refusal: a document it refuses or cannot judge (a number given as a string
with a unit, an application it has no spec of) goes to the pydantic models, which validate
it again and word every message (:mod:`advisor.core.reading`). So the worst a gap here can do
is cost time. ``tests/unit/test_compiled_validator.py`` checks, on the examples and on many
generated documents, that both accept the same documents and give the same values.
"""

import math
from functools import cache
from importlib import import_module
from typing import Any

from advisor.core.requirement_spec import APPLICATION, MODELS, ROOTS


class Refused(Exception):
    """The document is not one the compiled validator accepts (the models will say why)."""


class Record:
    """A validated table: its keys as read-only attributes, like the frozen pydantic model it
    stands for, with the two things of a model the advisor reads besides its keys:
    ``model_fields_set`` (the keys the file gave) and ``model_dump``."""

    _model = ""
    _fields: tuple[str, ...] = ()
    model_fields_set: set[str]

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError(f"{type(self).__name__} is read-only (a validated requirement)")

    def model_dump(self, exclude_none: bool = False) -> dict[str, Any]:
        """The table as plain data, keys in the model's order (as pydantic's model_dump)."""
        out = {}
        for key in self._fields:
            v = _dump(self.__dict__[key], exclude_none)
            if v is None and exclude_none:
                continue
            out[key] = v
        return out

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Record):
            return NotImplemented
        return self._model == other._model and self.model_dump() == other.model_dump()

    def __hash__(self) -> int:
        # as a frozen pydantic model: by its values (a table holding a list is unhashable)
        return hash((self._model, *(self.__dict__[k] for k in self._fields)))

    def __reduce__(self) -> tuple[Any, ...]:
        values = {k: self.__dict__[k] for k in self._fields}
        return (make_record, (self._model, values, set(self.model_fields_set)))

    def __repr__(self) -> str:
        inner = ", ".join(f"{k}={self.__dict__[k]!r}" for k in self._fields)
        return f"{type(self).__name__}({inner})"


def _dump(v: Any, exclude_none: bool) -> Any:
    if isinstance(v, Record):
        return v.model_dump(exclude_none)
    if isinstance(v, list):
        return [_dump(x, exclude_none) for x in v]
    return v


def _load(path: str) -> Any:
    module, _, name = path.partition(":")
    obj: Any = import_module(module)
    for part in name.split("."):
        obj = getattr(obj, part)
    return obj


@cache
def _record_class(name: str) -> type[Record]:
    spec = MODELS[name]
    mixins = tuple(_load(m) for m in spec["mixins"])
    fields = tuple(f[0] for f in spec["fields"])
    return type(name.rpartition(":")[2], (*mixins, Record), {"_model": name, "_fields": fields})


@cache
def _validators(name: str) -> tuple[dict[str, tuple[Any, ...]], tuple[Any, ...]]:
    spec = MODELS[name]
    fields = {k: tuple(_load(c) for c in cs) for k, cs in spec["field_checks"].items()}
    return fields, tuple(_load(c) for c in spec["after"])


def make_record(name: str, values: dict[str, Any], given: set[str]) -> Record:
    rec = object.__new__(_record_class(name))
    rec.__dict__.update(values)
    rec.__dict__["model_fields_set"] = given
    return rec


def _default(v: Any) -> Any:
    """A default of the spec as a fresh value (a record where the model holds a table)."""
    if isinstance(v, tuple):  # ("record", name, fields_set, values)
        _, name, given, values = v
        return make_record(name, {k: _default(x) for k, x in values.items()}, set(given))
    if isinstance(v, list):
        return [_default(x) for x in v]
    return v


def _bounded(v: Any, cons: dict[str, Any]) -> Any:
    for key, limit in cons.items():
        if key == "ge":
            ok = v >= limit
        elif key == "gt":
            ok = v > limit
        elif key == "le":
            ok = v <= limit
        elif key == "lt":
            ok = v < limit
        elif key == "min_length":
            ok = len(v) >= limit
        elif key == "max_length":
            ok = len(v) <= limit
        else:  # the generator writes no other constraint
            raise Refused(key)
        if not ok:
            raise Refused(key)
    return v


def _value(t: tuple, v: Any) -> Any:
    """``v`` validated as the spec's type ``t`` (pydantic's strict mode: no coercion, except
    an integer where a float is asked, which becomes a float)."""
    tag = t[0]
    if tag == "float":
        if type(v) is not float and type(v) is not int:
            raise Refused(tag)
        v = float(v)
        if not math.isfinite(v):
            raise Refused("finite")
        return _bounded(v, t[1])
    if tag == "int":
        if type(v) is not int:
            raise Refused(tag)
        return _bounded(v, t[1])
    if tag == "bool":
        if type(v) is not bool:
            raise Refused(tag)
        return v
    if tag == "str":
        if type(v) is not str:
            raise Refused(tag)
        return _bounded(v, t[1])
    if tag == "literal":
        if type(v) is not str or v not in t[1]:
            raise Refused(tag)
        return v
    if tag == "optional":
        return None if v is None else _value(t[1], v)
    if tag == "list":
        if type(v) is not list:
            raise Refused(tag)
        return _bounded([_value(t[1], x) for x in v], t[2])
    if tag == "model":
        return _table(t[1], v)
    raise Refused(tag)


def _table(name: str, data: Any) -> Record:
    if type(data) is not dict:
        raise Refused(name)
    spec = MODELS[name]
    values: dict[str, Any] = {}
    for key, t, required, default in spec["fields"]:
        if key in data:
            values[key] = _value(t, data[key])
        elif required:
            raise Refused(key)
        else:
            values[key] = _default(default)
    if any(k not in values for k in data):  # every field has a value: unknown keys left
        raise Refused("unknown key")
    field_checks, after = _validators(name)
    for key, checks in field_checks.items():
        if key in data:  # pydantic checks a value given, not a default
            for check in checks:
                values[key] = check(values[key])
    rec = make_record(name, values, set(data))
    for check in after:
        check(rec)
    return rec


def validate(data: Any) -> Record | None:
    """The requirement of document ``data`` as records, or None when the compiled validator
    does not accept it (then the pydantic models validate it, and word what is wrong). The
    checks across tables (:mod:`advisor.core.ignored`) are the reading path's
    (:func:`advisor.core.reading.compiled_or_none`)."""
    from advisor.core.registry import application

    try:
        app = _table(APPLICATION, data["application"])
        root = ROOTS.get(app.kind)
        if root is None or application(app.kind).requirements != root:
            return None  # an application the spec does not hold (one registered later)
        return _table(root, data)
    except Exception:  # any doubt goes to the models, which say what is wrong
        return None


def prepare() -> None:
    """Import every check and build every record class now (before a fork: the workers of
    ``advisor --batch -j N`` then share them)."""
    for name in MODELS:
        _record_class(name)
        _validators(name)


def compiled(kind: str) -> bool:
    """Whether the spec holds the requirement model ``kind`` is registered with (not one a
    test or a plug-in registered in its place)."""
    from advisor.core.registry import application

    root = ROOTS.get(kind)
    return root is not None and application(kind).requirements == root


def has_table(kind: str, key: str) -> bool | None:
    """Whether the requirement of ``kind`` has field ``key``; None for a kind the spec does
    not hold."""
    if not compiled(kind):
        return None
    return any(f[0] == key for f in MODELS[ROOTS[kind]]["fields"])
