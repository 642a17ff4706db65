"""The design report: a pydantic model, dumped to TOML with tomli-w and written atomically.

Stable keys (other tools read them) are documented in docs/reference/report.md. Floats are
rounded to six significant digits so that two runs of the same input give byte-identical
files and a changed input shows as a readable diff.
"""

import copy
import inspect
import math
import re
from decimal import Decimal
from typing import Any, ClassVar

from advisor.calc.checks import Check
from advisor.core import toml_text
from advisor.core.io_safety import write_atomic as write_atomic  # re-exported: the report writer

REPORT_FORMAT = 1


class ReportTable:
    """A report table: the fields its class annotates, in their declared order (a base
    class's first), with the defaults the class gives them.

    The engine builds the tables from values it has computed, so they are made with
    :meth:`make`, which checks the names (an unknown one or a missing required one is a bug
    of the advice) and copies mutable defaults, and dumped by :func:`plain_data`. A plain class
    rather than a pydantic model: the report validates nothing, and defining some fifty
    pydantic classes cost about 15 ms of every run.
    """

    field_names: ClassVar[tuple[str, ...]] = ()
    _names: ClassVar[frozenset[str]] = frozenset()
    _required: ClassVar[frozenset[str]] = frozenset()
    _defaults: ClassVar[dict[str, Any]] = {}

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        names: list[str] = []
        defaults: dict[str, Any] = {}
        for klass in reversed(cls.__mro__):
            for name, ann in inspect.get_annotations(klass).items():
                if name.startswith("_") or "ClassVar" in str(ann):
                    continue
                if name not in names:
                    names.append(name)
                if name in klass.__dict__:
                    defaults[name] = klass.__dict__[name]
                else:  # declared again without a default: required from here on
                    defaults.pop(name, None)
        cls.field_names = tuple(names)
        cls._names = frozenset(names)
        cls._required = frozenset(n for n in names if n not in defaults)
        cls._defaults = defaults

    @classmethod
    def make(cls, **values: Any):
        if not cls._names.issuperset(values):
            raise TypeError(f"{cls.__name__}: unknown fields {sorted(set(values) - cls._names)}")
        if not cls._required.issubset(values):
            raise TypeError(f"{cls.__name__}: missing fields {sorted(cls._required - set(values))}")
        obj = object.__new__(cls)
        d = obj.__dict__
        for name in cls.field_names:
            if name in values:
                d[name] = values[name]
            else:
                v = cls._defaults[name]
                d[name] = copy.copy(v) if isinstance(v, list | dict) else v
        return obj

    def replace(self, **update: Any):
        """A copy with some fields changed (checked as :meth:`make` checks them)."""
        return type(self).make(**{**self.__dict__, **update})

    def as_dict(self) -> dict[str, Any]:
        """The fields as a dict, tables within it as dicts too."""
        return {n: _as_dict(getattr(self, n)) for n in self.field_names}

    def __eq__(self, other: object) -> bool:
        return type(other) is type(self) and other.__dict__ == self.__dict__

    __hash__ = None  # type: ignore[assignment]  # mutable, as a pydantic model is

    def __repr__(self) -> str:
        inner = ", ".join(f"{n}={getattr(self, n)!r}" for n in self.field_names)
        return f"{type(self).__name__}({inner})"


def _as_dict(v: Any) -> Any:
    if isinstance(v, ReportTable):
        return v.as_dict()
    if isinstance(v, list | tuple):
        return [_as_dict(x) for x in v]
    if isinstance(v, dict):
        return {k: _as_dict(x) for k, x in v.items()}
    return v


def record_fields(
    record: type,
    add: dict[str, dict[str, Any]] | None = None,
    retype: dict[str, Any] | None = None,
) -> dict[str, Any]:
    """The fields of a report table that shows a calculation's record (a NamedTuple), so
    that they are declared once, in the record: its fields in its order, ``retype`` giving
    a field the type the report writes it as, ``add`` inserting the table's own fields after
    a field of the record (``{"margin": {"passed": bool}}``). A table assigns the result to
    ``__annotations__``, and its defaults as class attributes."""
    add, retype = add or {}, retype or {}
    out: dict[str, Any] = {}
    for name, ann in inspect.get_annotations(record).items():
        out[name] = retype.get(name, ann)
        out.update(add.get(name, {}))
    return out


class CheckOut(ReportTable):
    """A check (:class:`advisor.calc.checks.Check`) as the report writes it: the record's
    fields, the verdict after its margin, its source in words and the source's bibliography
    ids after it. margin = limit/value (value/limit for a lower bound); under a service
    factor the value is the factored demand. ``factor`` is absent from the advisor's own
    checks (the factor is in the value)."""

    __annotations__ = record_fields(
        Check,
        add={"margin": {"passed": bool}, "source": {"sources": list[str]}},
        retype={"source": str},
    )
    sources = []  # copied by make, never shared
    factor = None


def check_out(c: Any, short: dict[str, str]) -> CheckOut:
    """A check's report table: its numbers, its verdict and its sources in words (``short``:
    the catalogs' short names of the bibliography ids; an empty map keeps the ids)."""
    from advisor.core.cite import Cite, text

    cited = isinstance(c.source, Cite)
    return CheckOut.make(
        id=c.id,
        name=c.name,
        value=c.value,
        limit=c.limit,
        unit=c.unit,
        margin=c.margin,
        passed=c.passed,
        source=text(c.source, short) if cited else str(c.source),
        sources=c.source.ids if cited else [],
        factor=getattr(c, "factor", None),
    )


class DecisionOut(ReportTable):
    id: str
    title: str
    decision: str
    rationale: str
    source: str
    sources: list[str] = []
    inputs: dict[str, Any] = {}


class SourceOut(ReportTable):
    """One entry of the bibliography (catalogs/bibliography.toml) the report cites."""

    id: str
    short: str
    authors: list[str]
    title: str
    journal: str | None = None
    volume: str | None = None
    year: int | None = None
    institution: str | None = None
    publisher: str | None = None
    number: str | None = None
    note: str | None = None
    file: str | None = None

    def reference(self) -> str:
        """The full reference in one line, as a reader would look it up."""
        head = ", ".join(self.authors)
        sep = " " if head.endswith(".") else ". "
        parts = [f"{head}{sep}{self.title}" if head else self.title]
        for x in (self.number, self.journal, self.volume and f"vol. {self.volume}"):
            if x:
                parts.append(x)
        for x in (self.institution, self.publisher, self.year and str(self.year)):
            if x:
                parts.append(x)
        if self.note:
            parts.append(f"({self.note})")
        if self.file:
            parts.append(f"seed file {self.file}")
        return ". ".join(parts)


class ReportHeader(ReportTable):
    format: int = REPORT_FORMAT
    advisor_version: str
    application: str
    title: str = ""
    status: str = "feasible"


class Report(ReportTable):
    report: ReportHeader
    requirements: dict[str, Any]
    design: Any  # LinearDesignOut, or RotaryDesignOut from advisor.applications.rotary.report
    checks: list[CheckOut]
    warnings: list[str] = []
    decisions: list[DecisionOut]
    sources: list[SourceOut] = []
    #: P(pass) under [uncertainty] (advisor.uncertainty.report.UncertaintyOut)
    uncertainty: Any = None


def round_sig(x: float, digits: int = 6) -> float:
    """Round to significant digits, for stable, diffable reports.

    >>> round_sig(5.084934), round_sig(0.000123456789), round_sig(1200.0)
    (5.08493, 0.000123457, 1200.0)
    """
    if x == 0 or not math.isfinite(x):
        return x
    return round(x, digits - 1 - math.floor(math.log10(abs(x))))


def ends_in_tie(x: float, decimals: int) -> bool:
    """Whether ``x`` as written (``repr``) ends in a single 5 just past ``decimals``
    decimals: a value the report's six-digit rounding left on a tie (5.9075 of 5.907502),
    which rounding again to ``decimals`` can take the wrong way (5.907, binary 5.90749…).

    >>> ends_in_tie(5.9075, 3), ends_in_tie(5.90751, 3), ends_in_tie(10282.5, 0)
    (True, False, True)
    """
    digits = Decimal(repr(x)).as_tuple()
    return (
        isinstance(digits.exponent, int)
        and -digits.exponent == decimals + 1
        and digits.digits[-1] == 5
    )


def margin_text(margin: float) -> str:
    """A check's margin as every view shows it: three decimals of the report's value
    (:func:`round_sig`, six significant digits), and a fourth where that value is a tie at
    the third, so the datasheet (which reads the rounded report), the wizard and the
    summaries (which hold the value as computed) show the same digits.

    >>> margin_text(5.907502), margin_text(5.9075), margin_text(1.51), margin_text(0.98765)
    ('5.9075', '5.9075', '1.510', '0.988')
    """
    if not math.isfinite(margin):
        return f"{margin:.3f}"
    value = round_sig(margin)
    decimals = 4 if ends_in_tie(value, 3) else 3
    return f"{value:.{decimals}f}"


class NonFiniteValue(ValueError):
    """A report value that is nan or inf: a bug of the advice, never written to a file."""


def float_text(x: float) -> str:
    """``repr(round_sig(x))`` in one formatting: ``format(x, ".6")`` rounds as
    :func:`round_sig` does (correctly, to six significant digits) and writes the rounded
    number as ``repr`` does, but where it writes an exponent (from 10⁵ on where ``repr``
    waits for 10¹⁶; a subnormal number's digits beyond its precision): those few are read
    back.
    ``tests/unit/test_report_float_text.py`` holds it to ``repr``.

    >>> float_text(5.084934), float_text(1200.0), float_text(1234567.0), float_text(1.5e-5)
    ('5.08493', '1200.0', '1234570.0', '1.5e-05')
    """
    s = f"{x:.6}"
    return repr(float(s)) if "e" in s else s


_EXPONENT = re.compile(r"[-+.\d]+e[-+]\d+")


def floats_text(xs: list[float], sep: str) -> str:
    """``sep.join(map(float_text, xs))`` in one formatting call for the whole array (a curve
    is hundreds of numbers); the numbers written with an exponent are read back as
    :func:`float_text` reads them (``sep`` holds no digit, sign or point: TOML's ``",\\n    "``)."""
    text = sep.join(["{:.6}"] * len(xs)).format(*xs)
    if "e" not in text:
        return text
    return _EXPONENT.sub(lambda m: repr(float(m.group())), text)


#: The report's floats in TOML: rounded as they are written.
ROUNDED_FLOATS = toml_text.Floats(float_text, floats_text)


def plain_data(obj: Any, rounded: bool = True) -> Any:
    """Plain dicts and lists of a report, without None (TOML has no null), floats rounded
    to six significant digits (or, ``rounded=False``, as computed: for a writer that rounds
    as it writes, :func:`float_text`), fields in their declared order. A nan or an inf is
    refused with its key named (:class:`NonFiniteValue`): a report states numbers a reader
    can check.
    """
    try:
        return _plain_fast(obj, rounded)
    except NonFiniteValue:
        _plain_keyed(obj, "")  # the slow pass names the key; it raises
        raise


_floor, _log10, _isfinite = math.floor, math.log10, math.isfinite
_FLOAT = {float}
_KEPT = frozenset((str, int, bool))  # exact types a plain report holds as they are


def _plain_fast(obj: Any, rounded: bool) -> Any:
    t = type(obj)  # the exact types first: a report holds thousands of values
    if t is float:
        if obj - obj != 0.0:  # nan or ±inf, one subtraction instead of a call
            raise NonFiniteValue("a report value is not a finite number")
        if not rounded:
            return obj
        # round_sig(obj), written out: a report rounds about five hundred numbers
        return round(obj, 5 - _floor(_log10(abs(obj)))) if obj else obj
    if t is str or t is int or t is bool:
        return obj
    if t is list or t is tuple:
        kinds = set(map(type, obj))  # one pass in C: a curve is hundreds of floats
        if kinds == _FLOAT:  # a curve: checked without a call per item
            if not all(map(_isfinite, obj)):
                raise NonFiniteValue("a report value is not a finite number")
            if not rounded:
                return list(obj)
            return [round(v, 5 - _floor(_log10(abs(v)))) if v else v for v in obj]
        if kinds <= _KEPT:  # words, counts: as they are
            return list(obj)
        return [_plain_fast(v, rounded) for v in obj if v is not None]
    # in tables, words, counts and flags are kept without a call: they are most of the values
    if t is dict:
        return {
            str(k): v if type(v) in _KEPT else _plain_fast(v, rounded)
            for k, v in obj.items()
            if v is not None
        }
    if isinstance(obj, ReportTable):
        values = obj.__dict__
        return {
            n: v if type(v) in _KEPT else _plain_fast(v, rounded)
            for n in t.field_names
            if (v := values.get(n)) is not None
        }
    return _plain_keyed(obj, "")


def _plain_keyed(obj: Any, key: str) -> Any:
    """The same, naming the key of the value it refuses (the error path only)."""
    if isinstance(obj, ReportTable):
        return {
            name: _plain_keyed(getattr(obj, name), _join(key, name))
            for name in obj.field_names
            if getattr(obj, name) is not None
        }
    if isinstance(obj, float):
        if not math.isfinite(obj):
            raise NonFiniteValue(f"the report's {key or 'value'} is {obj}: not a finite number")
        return round_sig(obj)
    if isinstance(obj, bool | int | str):
        return obj
    if isinstance(obj, dict):
        return {
            str(k): _plain_keyed(v, _join(key, str(k))) for k, v in obj.items() if v is not None
        }
    if isinstance(obj, list | tuple):
        return [_plain_keyed(v, f"{key}[{i}]") for i, v in enumerate(obj) if v is not None]
    raise TypeError(f"a report cannot hold {type(obj).__name__} at {key}: {obj!r}")


def _join(key: str, name: str) -> str:
    return f"{key}.{name}" if key else name


#: A table of number arrays is a curve when its longest array has at least this many points.
CURVE_POINTS = 10


def plain(report: Report) -> dict[str, Any]:
    """The report as nested plain data (curves where the design holds them): what the
    datasheet reads."""
    return plain_data(report)


_NUMBER_TYPES = frozenset((float, int))  # exact types: a bool is no number here
_SCALARS = frozenset((str, float, int, bool))


def _numbers(v: Any) -> bool:
    """An array of numbers (or of arrays of them)."""
    if not isinstance(v, list):
        return False
    if set(map(type, v)) <= _NUMBER_TYPES:  # one pass in C: a curve is hundreds of floats
        return True
    return all((isinstance(x, int | float) and not isinstance(x, bool)) or _numbers(x) for x in v)


def _holds_containers(items: list) -> bool:
    """Some item of ``items`` is a dict or a list (checked once per kind of item)."""
    return any(issubclass(kind, dict | list) for kind in set(map(type, items)))


def curve_part(table: Any) -> dict[str, Any]:
    """The curve data of a table: its number arrays, when one of them has at least
    :data:`CURVE_POINTS` points (a characteristic, a sweep, a time history, the columns of a
    front) — data for a plot rather than the design. Empty when there is none."""
    if not isinstance(table, dict):
        return {}
    arrays = {k: v for k, v in table.items() if isinstance(v, list) and _numbers(v)}
    if not arrays or max(len(v) for v in arrays.values()) < CURVE_POINTS:
        return {}
    return arrays


def is_curve(table: Any) -> bool:
    """A table that is all curve data (nothing of it stays in the design)."""
    part = curve_part(table)
    return bool(part) and len(part) == len(table)


def _lift(node: Any, path: str, curves: dict[str, Any]) -> Any:
    """A part of the design with its curve data moved to ``curves`` and its ``None`` values
    dropped (one pass: what :func:`_drop_empty` does, done on the way). A table that was
    all curve data becomes ``None``, and its parent drops it."""
    if isinstance(node, dict):
        part = curve_part(node)
        if part:
            curves[path] = part
        out = {}
        for k, v in node.items():
            if type(v) in _SCALARS:  # most values: never a curve, kept as they are
                out[k] = v
                continue
            if v is None or k in part:
                continue
            if isinstance(v, dict) or (isinstance(v, list) and _holds_containers(v)):
                v = _lift(v, f"{path}.{k}", curves)  # a path is made for containers only
                if v is None:
                    continue
            out[k] = v
        return out if out or not part else None
    if isinstance(node, list):
        if not _holds_containers(node):  # numbers, words: as they are
            return node
        return [_lift(v, f"{path}[{i + 1}]", curves) for i, v in enumerate(node)]
    return node


def _drop_empty(node: Any) -> Any:
    if isinstance(node, dict):
        return {k: _drop_empty(v) for k, v in node.items() if v is not None}
    if isinstance(node, list):
        if not _holds_containers(node):
            return node
        return [_drop_empty(v) for v in node]
    return node


def archive(doc: dict[str, Any], *, none_dropped: bool = False) -> dict[str, Any]:
    """The archive layout: the curve data of the design (see :func:`curve_part`) moved into
    one ``[curves]`` table at the end, keyed by the table that held it
    (``"design.motion.curve"``, ``"design.motor.candidates[2].curve"``, list items counted
    from 1), so the design reads first; the table's other keys stay where they were.
    ``None`` values are dropped (TOML has no null). Only a top-level table whose key begins
    with ``design`` is searched for curves; the others are copied as they are, or, with
    ``none_dropped`` (``doc`` holds no ``None``, as :func:`plain_data` makes it), kept.

    >>> archive({"design": {"m": 1.0, "curve": {"t": list(range(10))}}})["curves"]
    {'design.curve': {'t': [0, 1, 2, 3, 4, 5, 6, 7, 8, 9]}}
    """
    curves: dict[str, Any] = {}
    out = {}
    for k, v in doc.items():
        if v is None:
            continue
        if k.startswith("design"):
            v = _lift(v, k, curves)
        elif not none_dropped:
            v = _drop_empty(v)
        if v is not None:
            out[k] = v
    if curves:
        out["curves"] = curves
    return out


def nest_curves(doc: dict[str, Any]) -> dict[str, Any]:
    """The inverse of :func:`archive`: a report read back from its TOML or JSON with its
    curves where the design holds them (for tools that prefer them there)."""
    import copy
    import re

    out = copy.deepcopy({k: v for k, v in doc.items() if k != "curves"})
    for where, curve in doc.get("curves", {}).items():
        parts = [int(p) - 1 if p.isdigit() else p for p in re.findall(r"[^.\[\]]+", where)]
        node: Any = out
        for p in parts[:-1]:
            node = node[p]
        node[parts[-1]] = {**node.get(parts[-1], {}), **curve}
    return out


def to_toml(report: Report) -> str:
    """The report as TOML text (no nulls: TOML has none), curves in ``[curves]`` at the
    end, as tomli-w writes it (:mod:`advisor.core.toml_text` writes the same bytes faster)."""
    # rounded as written: one formatting per number instead of a round() and a str()
    doc = archive(plain_data(report, rounded=False), none_dropped=True)
    return toml_text.dumps(doc, ROUNDED_FLOATS)


def to_json(report: Report) -> str:
    """The report as JSON: the same document as the TOML, keys in the same order."""
    import json

    doc = archive(plain_data(report), none_dropped=True)
    return json.dumps(doc, indent=2, ensure_ascii=False) + "\n"
