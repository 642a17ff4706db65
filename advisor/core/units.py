"""Units people type: a numeric requirement field may be a string with a unit
(``force_N = "5 kN"``, ``stroke_m = "200 mm"``, ``speed_rpm = "0.5 rad/s"``), converted here
to the unit its key names before the requirement models see it. The report therefore echoes
the requirement in the keys' (SI) units.

pint parses the strings; it is imported only when a string sits in a numeric field, so a
file of plain numbers costs nothing (pint itself imports numpy). Its parsed unit definitions
are cached beside the catalog cache (``$XDG_CACHE_HOME/drive-advisor/pint``).

pint treats the radian as dimensionless, so ``1 Hz`` would become 9.55 rpm and ``5 rad`` a
valid force ratio. An angle is therefore checked apart from the dimension: a field whose
unit holds an angle (rad, deg, rpm, rad/s) takes only a value whose unit holds one, and the
other way round. A number in quotes without a unit is refused: it is a slip or a unit left
out, and guessing either way would hide it.
"""

import math
import os
import re
from functools import cache
from typing import Any, get_args, get_origin

from pydantic import BaseModel

from advisor.core.errors import InputError
from advisor.core.questions import _strip_optional

#: pint's spelling of the units the keys name (the display units of
#: :data:`advisor.core.questions.UNIT_SUFFIXES`); '' is a pure number.
PINT_UNITS = {
    "": "dimensionless",
    "N": "N",
    "N·m": "N*m",
    "m": "m",
    "mm": "mm",
    "mm²": "mm**2",
    "s": "s",
    "min": "minute",
    "h": "hour",
    "rpm": "rpm",
    "Hz": "Hz",
    "kg": "kg",
    "kg·m²": "kg*m**2",
    "kg·m²/s": "kg*m**2/s",
    "kg/m³": "kg/m**3",
    "m²/s": "m**2/s",
    "mm²/s": "mm**2/s",
    "rad": "rad",
    "rad/s": "rad/s",
    "deg": "deg",
    "W": "W",
    "kW": "kW",
    "A": "A",
    "T": "T",
    "Ω": "ohm",
}

#: Units that carry an angle (pint counts the radian as no dimension at all).
_ANGULAR = {"rad", "deg", "rpm", "rad/s"}

#: Words for what a unit measures, for messages (matched by dimension).
_DIMENSION_WORDS = (
    ("m", "a length"),
    ("kg", "a mass"),
    ("s", "a time"),
    ("Hz", "a frequency"),
    ("N", "a force"),
    ("N*m", "a torque or energy"),
    ("W", "a power"),
    ("kg*m**2", "a moment of inertia"),
    ("kg*m**2/s", "an angular momentum"),
    ("kg/m**3", "a density"),
    ("m**2/s", "a kinematic viscosity"),
    ("m**2", "an area"),
    ("A", "a current"),
    ("T", "a flux density"),
    ("ohm", "a resistance"),
    ("m/s", "a speed"),
    ("Pa", "a pressure"),
    ("V", "a voltage"),
    ("dimensionless", "a pure number"),
)

#: A number, then a unit: what the JSON Schema allows as a string.
PATTERN = r"^\s*[-+]?(\d+(\.\d*)?|\.\d+)([eE][-+]?\d+)?\s*[^\s\d.+-].*$"
_NUMBER = re.compile(r"^\s*[-+]?(\d+(\.\d*)?|\.\d+)([eE][-+]?\d+)?\s*$")


_GARBAGE = 'must be a number or a quantity with a unit, like "5 kN", "200 mm" or "1500 rpm"'


class UnitError(ValueError):
    """A string that is not a quantity of the field's unit; the message says why."""


@cache
def _registry() -> Any:
    import pint

    folder = None
    if not os.environ.get("DRIVE_ADVISOR_NO_CACHE"):
        base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
        folder = os.path.join(base, "drive-advisor", "pint")
    try:
        ureg = pint.UnitRegistry(cache_folder=folder)
    except OSError:  # an unwritable cache: parse the definitions every time
        ureg = pint.UnitRegistry()
    ureg.define("rev = revolution")  # "1 rev/s", as engineers write it
    return ureg


def _words(dimensionality: Any) -> str:
    ureg = _registry()
    for unit, words in _DIMENSION_WORDS:
        if ureg.Unit(unit).dimensionality == dimensionality:
            return words
    return f"of dimension {dimensionality}"


def _has_angle(units: Any) -> bool:
    """Whether a unit holds an angle: in base units, the radian stays (Hz does not)."""
    return "radian" in str((1 * units).to_base_units().units)


def to_unit(text: str, unit: str) -> float:
    """The value of ``text`` (``"5 kN"``) in ``unit`` (a key's unit, as
    :func:`advisor.core.questions.unit_of` names it), rounded to 12 significant digits so
    that a decimal conversion reads as typed (200 mm → 0.2 m, not 0.20000000000000004).

    >>> to_unit("5 kN", "N"), to_unit("200 mm", "m"), to_unit("1500 rpm", "rad/s")
    (5000.0, 0.2, 157.079632679)
    >>> to_unit("90 deg", "rad"), to_unit("3 N*m", "N·m")
    (1.57079632679, 3.0)
    """
    if _NUMBER.match(text):  # a number in quotes: a slip, or a unit left out
        n = text.strip()
        if len(n) > 24:
            raise UnitError("must be a number, or a quantity with its unit; not a number in quotes")
        raise UnitError(
            f"must be a number ({n})"
            + (f' or a quantity with its unit ("{n} {unit}")' if unit else "")
        )
    if not re.match(PATTERN, text):  # a unit alone ("kN") is 1 kN to pint: not here
        raise UnitError(_expected(unit, _GARBAGE))
    target = PINT_UNITS.get(unit)
    if target is None:
        raise UnitError(f"this field takes numbers in {unit} only")
    ureg = _registry()
    import pint

    try:
        q = ureg.Quantity(text.strip())
    except (pint.errors.PintError, ValueError, TypeError, SyntaxError, AttributeError):
        raise UnitError(_expected(unit, _GARBAGE)) from None
    if not isinstance(q, ureg.Quantity) or not isinstance(q.magnitude, int | float):
        raise UnitError(_expected(unit, _GARBAGE))
    want = ureg.Unit(target)
    if q.dimensionality != want.dimensionality or _has_angle(q.units) != (unit in _ANGULAR):
        raise UnitError(
            _expected(unit, f"{_given(q)} is {_kind(q, ureg)}, not {_wanted(unit, want)}")
        )
    value = float(q.to(want).magnitude)
    if not math.isfinite(value):
        raise UnitError(_expected(unit, "must be finite"))
    return _round12(value)


def _round12(x: float) -> float:
    if x == 0 or not math.isfinite(x):
        return x
    return round(x, 11 - math.floor(math.log10(abs(x))))


def _expected(unit: str, what: str) -> str:
    return f"{what}; expected {unit or 'a pure number'}"


def _given(q: Any) -> str:
    return f"{q.units:~P}" or "a pure number"


def _kind(q: Any, ureg: Any) -> str:
    """What a quantity measures, in words (an angle told apart from a pure number)."""
    if _has_angle(q.units):
        return "an angle" if q.dimensionality == {} else "a speed of rotation"
    return _words(q.dimensionality)


def _wanted(unit: str, want: Any) -> str:
    if unit in ("rad", "deg"):
        return "an angle"
    if unit in ("rpm", "rad/s"):
        return "a speed of rotation"
    return _words(want.dimensionality)


# ------------------------------------------------------------------ requirement documents
def _is_number(ann: Any) -> bool:
    """A quantity: a float field (whole-number fields are counts, without a unit)."""
    return ann is float


def _models(ann: Any) -> list[type[BaseModel]]:
    args = get_args(ann)
    return [a for a in (ann, *args) if isinstance(a, type) and issubclass(a, BaseModel)]


def _model_for(ann: Any, value: dict) -> type[BaseModel] | None:
    """The model a table is validated with (a union of tables: the one whose ``kind``
    literal matches)."""
    members = _models(ann)
    if len(members) == 1:
        return members[0]
    for m in members:
        f = m.model_fields.get("kind")
        if f is not None and value.get("kind") in get_args(f.annotation):
            return m
    return None


def _where(path: tuple[Any, ...]) -> str:
    out = ""
    for part in path:
        out += f"[{part + 1}]" if isinstance(part, int) else (f".{part}" if out else str(part))
    return out


def _unit(name: str, info: Any) -> str:
    extra = info.json_schema_extra if isinstance(info.json_schema_extra, dict) else {}
    if "x-unit" in extra:
        return extra["x-unit"]
    from advisor.core.questions import unit_of

    return unit_of(name)


def convert(data: Any, model: type[BaseModel]) -> Any:
    """``data`` (a requirement document) with every string in a numeric field converted to
    the field's unit; anything else is left for the model to judge. Raises
    :class:`InputError`, one line per field, for strings that are not quantities of the
    field's unit."""
    errors: list[str] = []
    out = _convert(data, model, (), errors)
    if errors:
        raise InputError(*errors)
    return out


def _convert(data: Any, model: type[BaseModel], path: tuple[Any, ...], errors: list[str]) -> Any:
    if not isinstance(data, dict):
        return data
    out = dict(data)
    for name, value in data.items():
        info = model.model_fields.get(name)
        if info is None:
            continue
        ann = _strip_optional(info.annotation)
        here = (*path, name)
        if isinstance(value, str) and _is_number(ann):
            out[name] = _one(value, _unit(name, info), ann, here, errors)
        elif isinstance(value, list) and get_origin(ann) is list:
            item = _strip_optional(get_args(ann)[0])
            item = get_args(item)[0] if get_origin(item) is not None and get_args(item) else item
            if _is_number(item):
                unit = _unit(name, info)
                out[name] = [
                    _one(v, unit, item, (*here, i), errors) if isinstance(v, str) else v
                    for i, v in enumerate(value)
                ]
            elif _models(item):
                out[name] = [
                    _convert(v, m, (*here, i), errors)
                    if isinstance(v, dict) and (m := _model_for(item, v))
                    else v
                    for i, v in enumerate(value)
                ]
        elif isinstance(value, dict):
            sub = _model_for(ann, value)
            if sub is not None:
                out[name] = _convert(value, sub, here, errors)
    return out


def _one(text: str, unit: str, ann: Any, path: tuple[Any, ...], errors: list[str]) -> Any:
    try:
        value = to_unit(text, unit)
    except UnitError as exc:
        from advisor.io_safety import show_repr

        errors.append(f"{_where(path)} = {show_repr(text)}: {exc}")
        return text
    return value
