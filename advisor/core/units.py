"""Units people type: a numeric requirement field may be a string with a unit
(``force_N = "5 kN"``, ``stroke_m = "200 mm"``, ``speed_rpm = "0.5 rad/s"``), converted here
to the unit its key names before the requirement models see it. The report therefore echoes
the requirement in the keys' (SI) units.

The strings are read by a strict grammar of this module, never evaluated (pint,
which read them before, parses a unit string as an arithmetic expression, so ``"9**9**9 N"``
never ended, ``"5 kN + 3 kN"`` was 8 kN, ``"3500 N*ln10"`` 8059 N, and its disk cache ran
pickles from a writable folder). A quantity is::

    quantity := number unit (op unit)*        at most 64 characters
    number   := [+-] digits [. digits] [e [+-] digits]     (finite)
    unit     := name [^n | **n | ² | ³ | ⁻¹ …]              n a whole number, 1 ≤ |n| ≤ 4
    op       := * | · | /                       at most one /, followed by one unit

with ``name`` one of :data:`UNITS` (an SI symbol with or without an SI prefix, or one of a
few other units engineers type: in, ft, lbf, kgf, rpm, deg, …). Nothing else: no
parentheses, no arithmetic between numbers, no functions or constants, no ``%``, no
comments, no control or bidi characters. A string is read in one pass, in time proportional
to its length after the length cap, so any input is answered within microseconds.

The conversion factors are exact definitions (SI Brochure, 9th ed., 2019, tables 8 and 9
for the prefixes and the non-SI units accepted with the SI; NIST SP 811, 2008, appendix B.8
for the inch, foot, pound, pound-force, kilogram-force, horsepower and psi), so no library
is needed. The radian is kept as a dimension of its own (pint counted it as none), so a
speed of rotation (rpm, rad/s, deg/s) is told apart from a frequency (Hz) and an angle from a
pure number. An energy (J, cal, W·h) has the dimension of a torque but is not one: a torque
field refuses it. A number in quotes without a unit is refused: it is a
slip or a unit left out, and guessing either way would hide it.
"""

import math
import re
import unicodedata
from functools import cache
from typing import TYPE_CHECKING, Any, NamedTuple, get_args, get_origin

from advisor.core.errors import InputError
from advisor.core.questions import strip_optional

if TYPE_CHECKING:  # the models are read by convert() only: reading by the spec needs none
    from pydantic import BaseModel

#: The longest quantity read; a longer string is refused before it is looked at.
MAX_CHARS = 64

# ------------------------------------------------------------------ the units known
#: Dimension exponents, in this order: metre, kilogram, second, ampere, radian.
Dims = tuple[int, int, int, int, int]


class Unit(NamedTuple):
    factor: float  # the SI value of one of it (in m, kg, s, A, rad and their products)
    dims: Dims
    energy: bool = False  # an energy or a power by name (J, cal, W·h, W, hp): never a torque


_L, _M, _T, _I, _R = (
    (1, 0, 0, 0, 0),
    (0, 1, 0, 0, 0),
    (0, 0, 1, 0, 0),
    (0, 0, 0, 1, 0),
    (0, 0, 0, 0, 1),
)
_NONE: Dims = (0, 0, 0, 0, 0)
_FORCE: Dims = (1, 1, -2, 0, 0)
_ENERGY: Dims = (2, 1, -2, 0, 0)  # also a torque (N·m)
_POWER: Dims = (2, 1, -3, 0, 0)
_PRESSURE: Dims = (-1, 1, -2, 0, 0)
_TESLA: Dims = (0, 1, -2, -1, 0)
_VOLT: Dims = (2, 1, -3, -1, 0)
_FARAD: Dims = (-2, -1, 4, 2, 0)
_OHM: Dims = (2, 1, -3, -2, 0)
_HERTZ: Dims = (0, 0, -1, 0, 0)
_ROTATION: Dims = (0, 0, -1, 0, 1)  # rad/s
_VISCOSITY: Dims = (2, 0, -1, 0, 0)  # m²/s

#: SI prefixes (SI Brochure, table 7); the micro sign, the Greek mu and 'u' all mean 10⁻⁶.
_PREFIX = {"G": 1e9, "M": 1e6, "k": 1e3, "c": 1e-2, "d": 1e-1, "m": 1e-3, "u": 1e-6}
_PREFIX |= {"µ": 1e-6, "μ": 1e-6, "n": 1e-9}

#: Units that take prefixes: symbol → (the unit, the prefixes it takes).
_PREFIXED: dict[str, tuple[Unit, str]] = {
    "m": (Unit(1.0, _L), "kcdmuµμn"),
    "g": (Unit(1e-3, _M), "kmuµμ"),
    "s": (Unit(1.0, _T), "muµμn"),
    "N": (Unit(1.0, _FORCE), "GMkmuµμ"),
    "Hz": (Unit(1.0, _HERTZ), "GMkm"),
    "W": (Unit(1.0, _POWER, True), "GMkmuµμ"),
    "A": (Unit(1.0, _I), "kmuµμ"),
    "T": (Unit(1.0, _TESLA), "muµμn"),
    "Pa": (Unit(1.0, _PRESSURE), "GMk"),
    "bar": (Unit(1e5, _PRESSURE), "m"),
    "V": (Unit(1.0, _VOLT), "kmuµμ"),
    "F": (Unit(1.0, _FARAD), "muµμn"),  # a drive's bus capacitance: µF, uF
    "ohm": (Unit(1.0, _OHM), "GMkm"),
    "Ω": (Unit(1.0, _OHM), "GMkm"),
    "J": (Unit(1.0, _ENERGY, True), "GMkm"),
    "Wh": (Unit(3600.0, _ENERGY, True), "GMk"),
    "cal": (Unit(4.184, _ENERGY, True), "k"),  # thermochemical calorie (NIST SP 811, B.8)
    "rad": (Unit(1.0, _R), "m"),
    "Nm": (Unit(1.0, _ENERGY), "Mkm"),  # N·m written without its dot, as engineers do
    "St": (Unit(1e-4, _VISCOSITY), "c"),  # stokes; cSt = mm²/s
}

#: Units without prefixes.
_PLAIN: dict[str, Unit] = {
    "t": Unit(1e3, _M),  # tonne
    "lb": Unit(0.45359237, _M),
    "in": Unit(0.0254, _L),
    "inch": Unit(0.0254, _L),
    "ft": Unit(0.3048, _L),
    "lbf": Unit(4.4482216152605, _FORCE),
    "kgf": Unit(9.80665, _FORCE),
    "min": Unit(60.0, _T),
    "h": Unit(3600.0, _T),
    "hp": Unit(745.69987158227022, _POWER, True),  # 550 ft·lbf/s
    "psi": Unit(6894.757293168361, _PRESSURE),
    "G": Unit(1e-4, _TESLA),  # gauss: 10⁻⁴ T (SI Brochure, table 9, note)
    "deg": Unit(math.pi / 180, _R),
    "°": Unit(math.pi / 180, _R),
    "rev": Unit(2 * math.pi, _R),
    "turn": Unit(2 * math.pi, _R),
    "rpm": Unit(2 * math.pi / 60, _ROTATION),
    "rps": Unit(2 * math.pi, _ROTATION),
}


def _all_units() -> dict[str, Unit]:
    out = dict(_PLAIN)
    for symbol, (unit, prefixes) in _PREFIXED.items():
        for p in "" + prefixes:
            name = p + symbol
            assert name not in out, name  # every name means one unit
            out[name] = Unit(_PREFIX.get(p, 1.0) * unit.factor, unit.dims, unit.energy)
        out[symbol] = unit
    return out


#: Every unit name the grammar knows, with its SI value and dimension.
UNITS: dict[str, Unit] = _all_units()

#: Words for what a dimension measures, for messages.
_WORDS: dict[Dims, str] = {
    _NONE: "a pure number",
    _L: "a length",
    _M: "a mass",
    _T: "a time",
    _I: "a current",
    _R: "an angle",
    _HERTZ: "a frequency",
    _ROTATION: "a speed of rotation",
    (0, 0, -2, 0, 1): "an angular acceleration",
    _FORCE: "a force",
    _ENERGY: "a torque",
    _POWER: "a power",
    (2, 1, 0, 0, 0): "a moment of inertia",
    (2, 1, -1, 0, 0): "an angular momentum",
    (-3, 1, 0, 0, 0): "a density",
    _VISCOSITY: "a kinematic viscosity",
    (2, 0, 0, 0, 0): "an area",
    (3, 0, 0, 0, 0): "a volume",
    (1, 0, -1, 0, 0): "a speed",
    (1, 0, -2, 0, 0): "an acceleration",
    _PRESSURE: "a pressure",
    _TESLA: "a flux density",
    _VOLT: "a voltage",
    _FARAD: "a capacitance",
    _OHM: "a resistance",
}

#: A few units of each kind to name in a refusal ("what is allowed").
_SHOWN = (
    "N kN MN mN lbf kgf N·m kN·m N·cm N·mm lbf·ft m mm cm km µm in ft s ms min h rpm rad/s "
    "deg/s rev/s Hz kHz rad deg rev kg g t lb W kW MW hp A mA V kV mV F mF µF nF T mT G Ω "
    "kΩ mΩ Pa kPa MPa "
    "kg·m² kg·cm² kg·m²/s kg/m³ g/cm³ m²/s mm²/s cSt mm² cm² m²"
).split()

# ------------------------------------------------------------------ the grammar
#: The grammar's shape (not its list of names) as the JSON Schema states it, so that an
#: editor flags "5 kN + 3 kN" as the advisor would; the length cap and the names are checked
#: here. It takes what the reader takes before parsing (:data:`_SPACES`): the no-break and
#: thin spaces, the dot operator ⋅ (U+22C5) and the ohm sign Ω (U+2126).
_BLANK = "[ \\t\u00a0\u2009\u202f]*"
_U = "[A-Za-zµμΩ\u2126°]+((\\^|\\*\\*)[-+]?[0-9]+|⁻?[¹²³⁴])?"
PATTERN = (
    "^"
    + _BLANK
    + r"[-+]?([0-9]+(\.[0-9]*)?|\.[0-9]+)([eE][-+]?[0-9]+)?"
    + _BLANK
    + _U
    + "("
    + _BLANK
    + "[*·\u22c5/]"
    + _BLANK
    + _U
    + ")*"
    + _BLANK
    + "$"
)

#: What a quantity copied from a typeset page holds, read as what it stands for: the spaces
#: (SI Brochure 5.4.3: a thin space between number and unit) as a plain space, the dot
#: operator (LaTeX's \\cdot, the SI Brochure's half-high dot in its PDF) as ·, the ohm sign
#: as the Greek capital omega it is canonically (Unicode: U+2126 ≡ U+03A9).
_SPACES = str.maketrans({"\u00a0": " ", "\u2009": " ", "\u202f": " ", "\u22c5": "·", "\u2126": "Ω"})
_ALLOWED = set("0123456789.+-eE*/^ \t·²³¹⁴⁻µμΩ°")
_NUMBER_RE = re.compile(r"[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?", re.ASCII)
_NAME_RE = re.compile(r"[A-Za-zµμΩ°]+")
_POWER_RE = re.compile(r"(?:\^|\*\*)([+-]?[0-9]+)|(⁻?[¹²³⁴])")
_OP_RE = re.compile(r"[ \t]*([*·/])[ \t]*")
_SUPERSCRIPT = {"¹": 1, "²": 2, "³": 3, "⁴": 4}

_GARBAGE = "must be a number or a quantity with a unit"

#: What a quantity may be, said in every refusal of the grammar.
GRAMMAR = 'a number, then units joined by *, · or /, powers as ^2 (e.g. "5 kN", "2 kg*m^2")'


class UnitError(ValueError):
    """A string that is not a quantity of the field's unit; the message says why."""


class _NumberOnly(UnitError):
    """A number in quotes without a unit."""


class _Infinite(UnitError):
    """A number beyond the largest float (1e400)."""


class _Structure(UnitError):
    """Units not joined as the grammar joins them."""


class Parsed(NamedTuple):
    number: float
    unit_text: str  # the unit as typed, for messages
    factor: float  # SI value of one of the unit
    dims: Dims
    energy: bool  # holds an energy or power by name (J, cal, W·h, W, hp)


def _char_problem(text: str) -> str | None:
    """The first character no quantity holds, named (a control or bidi character by its
    code point and Unicode name, so that the message shows what cannot be seen)."""
    for ch in text:
        if ch in _ALLOWED or (ch.isascii() and ch.isalpha()):
            continue
        if ch in "()[]{}":
            return "parentheses are not allowed"
        if ch.isascii() and ch.isprintable():
            return f"{ch!r} is not allowed"
        return _named(ch)
    return None


def _named(ch: str) -> str:
    """A refused character by its code point and Unicode name (a look-alike prints as the
    character it resembles), and that character where Unicode says it is one (NFKC: the
    fullwidth ｋ is k)."""
    name = unicodedata.name(ch, "a control character")
    if ch.isprintable() and unicodedata.category(ch)[0] not in "CZ":
        out = f"{ch!r} (U+{ord(ch):04X} {name}) is not allowed"
    else:  # nothing to see: the code point alone
        out = f"U+{ord(ch):04X} ({name}) is not allowed"
    same = unicodedata.normalize("NFKC", ch)
    if len(same) == 1 and same != ch and (same in _ALLOWED or (same.isascii() and same.isalnum())):
        out += f"; use {same!r} (U+{ord(same):04X})"
    return out


def _power(text: str, pos: int) -> tuple[int, int]:
    """The exponent written at ``pos`` (1 if none) and the position after it."""
    m = _POWER_RE.match(text, pos)
    if not m:
        return 1, pos
    if m.group(1) is not None:
        digits = m.group(1)
        n = int(digits) if len(digits) <= 3 else 99
    else:
        sup = m.group(2)
        n = -_SUPERSCRIPT[sup[-1]] if sup.startswith("⁻") else _SUPERSCRIPT[sup]
    if not 1 <= abs(n) <= 4:
        raise _Structure(f"a power is a whole number from -4 to 4, not {m.group(0)!r}")
    return n, m.end()


def _units(text: str, pos: int) -> tuple[float, Dims, bool]:
    """The unit expression of ``text`` from ``pos`` to its end: its SI factor, dimension and
    whether it names an energy; :class:`UnitError` for anything the grammar does not hold."""
    factor, dims, energy = 1.0, (0, 0, 0, 0, 0), False
    sign, divided = 1, False
    while True:
        m = _NAME_RE.match(text, pos)
        if not m:
            at = repr(text[pos : pos + 8]) if pos < len(text) else "the end"
            raise _Structure(f"a unit expected at {at}")
        unit = UNITS.get(m.group(0))
        if unit is None:
            raise UnitError(f"{m.group(0)[:16]!r} is not a unit known here")
        n, pos = _power(text, m.end())
        n *= sign
        factor *= unit.factor**n
        dims = tuple(d + n * u for d, u in zip(dims, unit.dims, strict=True))  # type: ignore[assignment]
        energy = energy or unit.energy
        if pos == len(text):
            return factor, dims, energy
        op = _OP_RE.match(text, pos)
        if not op:
            raise _Structure(f"{text[pos : pos + 8]!r} cannot follow a unit")
        if divided:
            raise _Structure("one unit only after '/' (kg/m^3, not kg/m/s)")
        if op.group(1) == "/":
            sign, divided = -1, True
        pos = op.end()


def parse(text: str) -> Parsed:
    """A quantity read by the grammar of this module; :class:`UnitError` saying why not.

    >>> parse("5 kN").number, parse("5 kN").factor, parse("5 kN").dims
    (5.0, 1000.0, (1, 1, -2, 0, 0))
    """
    if len(text) > MAX_CHARS:  # before anything looks at it: a 1 MiB string costs nothing
        raise UnitError(f"at most {MAX_CHARS} characters")
    text = text.translate(_SPACES)
    bad = _char_problem(text)
    if bad:
        raise UnitError(bad)
    s = text.strip(" \t")
    m = _NUMBER_RE.match(s)
    if not m:
        raise _Structure("a number first")
    number = float(m.group(0))
    if not math.isfinite(number):
        raise _Infinite("must be finite")
    pos = m.end()
    while pos < len(s) and s[pos] in " \t":
        pos += 1
    if pos == len(s):
        raise _NumberOnly(m.group(0))
    factor, dims, energy = _units(s, pos)
    return Parsed(number, s[pos:], factor, dims, energy)


@cache
def _target(unit: str) -> Parsed | None:
    """A key's unit (``N·m``, ``kg·m²``, ``mm²/s``) read by the same grammar; None for
    a pure number ('')."""
    if not unit:
        return None
    return parse("1 " + unit)


def _kind(dims: Dims, energy: bool) -> str:
    if dims == _ENERGY and energy:
        return "an energy"
    return _WORDS.get(dims, "of another kind")


@cache
def allowed(unit: str) -> str:
    """Units a field of ``unit`` takes, a few named (for a refusal)."""
    want = _target(unit)
    dims = want.dims if want else _NONE
    same = [u for u in _SHOWN if parse("1 " + u).dims == dims]
    if unit and unit not in same:
        same.insert(0, unit)
    return ", ".join(same[:8]) if same else "a pure number"


def to_unit(text: str, unit: str) -> float:
    """The value of ``text`` (``"5 kN"``) in ``unit`` (a key's unit, as
    :func:`advisor.core.questions.unit_of` names it). A decimal conversion reads as typed
    (200 mm → 0.2 m, not 0.20000000000000004): where the product lies within a few units in
    the last place of its 12-significant-digit rounding, that rounding is the value. A
    conversion through π (rpm, degrees) is kept as computed: rounded, 40000 rpm would be
    4188.79020479 rad/s, 3.4e-8 rpm above a bearing's 40000 rpm limit, and refused at it.
    A number in the key's own unit is taken as typed (no conversion: nothing to round).

    >>> to_unit("5 kN", "N"), to_unit("200 mm", "m"), to_unit("1500 rpm", "rad/s")
    (5000.0, 0.2, 157.07963267948966)
    >>> to_unit("90 deg", "rad"), to_unit("3 N*m", "N·m")
    (1.5707963267948966, 3.0)
    """
    try:
        want = _target(unit)
    except UnitError:
        raise UnitError(f"this field takes numbers in {unit} only") from None
    try:
        q = parse(text)
    except _NumberOnly as exc:  # a number in quotes: a slip, or a unit left out
        n = str(exc)
        if len(n) > 24:
            raise UnitError(
                "must be a number, or a quantity with its unit; not a number in quotes"
            ) from None
        raise UnitError(
            f"must be a number ({n})"
            + (f' or a quantity with its unit ("{n} {unit}")' if unit else "")
        ) from None
    except _Infinite:
        raise UnitError(_expected(unit, "must be finite")) from None
    except _Structure as exc:
        raise UnitError(_expected(unit, f"{_GARBAGE} ({exc}; {GRAMMAR})")) from None
    except UnitError as exc:
        raise UnitError(
            _expected(unit, f"{_GARBAGE} ({exc}; units here: {allowed(unit)})")
        ) from None
    dims, factor = (want.dims, want.factor) if want else (_NONE, 1.0)
    wrong = q.dims != dims or (q.energy and dims == _ENERGY)
    if wrong:
        what = "a torque" if dims == _ENERGY else _kind(dims, False)
        raise UnitError(_expected(unit, f"{q.unit_text} is {_kind(q.dims, q.energy)}, not {what}"))
    if q.factor == factor:  # the key's own unit: the number as typed, nothing to round
        return q.number
    value = q.number * (q.factor / factor)
    if not math.isfinite(value):
        raise UnitError(_expected(unit, "must be finite"))
    return _decimal_or_exact(value)


#: Units in the last place within which a converted value is taken as the decimal it rounds
#: to: the error of one or two float operations on a decimal number.
_NOISE_ULPS = 4


def _decimal_or_exact(x: float) -> float:
    """``x`` rounded to 12 significant digits where it differs from that only by float noise
    (a decimal conversion), else ``x`` as computed."""
    if x == 0 or not math.isfinite(x):
        return x
    r = round(x, 11 - math.floor(math.log10(abs(x))))
    return r if abs(r - x) <= _NOISE_ULPS * math.ulp(x) else x


def _expected(unit: str, what: str) -> str:
    return f"{what}; expected {unit or 'a pure number'}"


# ------------------------------------------------------------------ requirement documents
def _is_number(ann: Any) -> bool:
    """A quantity: a float field (whole-number fields are counts, without a unit)."""
    return ann is float


def _models(ann: Any) -> "list[type[BaseModel]]":
    from pydantic import BaseModel

    args = get_args(ann)
    return [a for a in (ann, *args) if isinstance(a, type) and issubclass(a, BaseModel)]


def _model_for(ann: Any, value: dict) -> "type[BaseModel] | None":
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


#: Lists of tables whose numbers without a unit of their own are in the unit of the key
#: each row's ``name`` names: an ``[[uncertainty.inputs]]`` row of ``linear.force_N`` takes
#: ``sd = "175 N"`` (keys.md: "in the input's unit").
UNIT_OF_NAME = frozenset({("uncertainty", "inputs")})


def row_unit(table: tuple[Any, ...], row: Any) -> str:
    """The unit of a row of ``table`` by its ``name`` ('' for none: pure numbers)."""
    if (
        table not in UNIT_OF_NAME
        or not isinstance(row, dict)
        or not isinstance(row.get("name"), str)
    ):
        return ""
    from advisor.core.questions import unit_of

    return unit_of(row["name"].rsplit(".", 1)[-1])


def _names_known(table: tuple[Any, ...], row: Any, model: "type[BaseModel]") -> bool:
    """Whether a row whose numbers take the unit of its ``name`` names one of the inputs
    its model allows: an unknown name ('linear.force', the _N forgotten) gives no unit to
    read the row's quantity strings in, so they are left out and the model's refusal names
    the input and the allowed ones (not "N is a force, not a pure number")."""
    if table not in UNIT_OF_NAME or not isinstance(row, dict):
        return True
    field = model.model_fields.get("name")
    allowed = get_args(strip_optional(field.annotation)) if field is not None else ()
    return not allowed or row.get("name") in allowed


def _convert_row(table: tuple[Any, ...], i: int, row: Any, item: Any, errors: list[str]) -> Any:
    """One row of a list of tables, converted with its model (and the unit of its name)."""
    m = _model_for(item, row) if isinstance(row, dict) else None
    if m is None:
        return row
    if not _names_known(table, row, m):  # no unit to read its strings in: the name alone
        return {k: v for k, v in row.items() if not (isinstance(v, str) and _numeric(m, k))}
    return _convert(row, m, (*table, i), errors, row_unit(table, row))


def _numeric(model: "type[BaseModel]", name: str) -> bool:
    info = model.model_fields.get(name)
    return info is not None and _is_number(strip_optional(info.annotation))


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


def convert(data: Any, model: "type[BaseModel]") -> Any:
    """``data`` (a requirement document) with every string in a numeric field converted to
    the field's unit; anything else is left for the model to judge. Raises
    :class:`InputError`, one line per field, for strings that are not quantities of the
    field's unit."""
    errors: list[str] = []
    out = _convert(data, model, (), errors)
    if errors:
        raise InputError(*errors)
    return out


def _convert(
    data: Any,
    model: "type[BaseModel]",
    path: tuple[Any, ...],
    errors: list[str],
    row_unit: str = "",
) -> Any:
    if not isinstance(data, dict):
        return data
    out = dict(data)
    for name, value in data.items():
        info = model.model_fields.get(name)
        if info is None:
            continue
        ann = strip_optional(info.annotation)
        here = (*path, name)
        if isinstance(value, str) and _is_number(ann):
            out[name] = _one(value, _unit(name, info) or row_unit, here, errors)
        elif isinstance(value, list) and get_origin(ann) is list:
            item = strip_optional(get_args(ann)[0])
            item = get_args(item)[0] if get_origin(item) is not None and get_args(item) else item
            if _is_number(item):
                unit = _unit(name, info)
                out[name] = [
                    _one(v, unit, (*here, i), errors) if isinstance(v, str) else v
                    for i, v in enumerate(value)
                ]
            elif _models(item):
                out[name] = [_convert_row(here, i, v, item, errors) for i, v in enumerate(value)]
        elif isinstance(value, dict):
            sub = _model_for(ann, value)
            if sub is not None:
                out[name] = _convert(value, sub, here, errors)
    return out


def _one(text: str, unit: str, path: tuple[Any, ...], errors: list[str]) -> Any:
    try:
        value = to_unit(text, unit)
    except UnitError as exc:
        from advisor.core.io_safety import show_repr

        errors.append(f"{_where(path)} = {show_repr(text)}: {exc}")
        return text
    return value


# ------------------------------------------------------------------ without the models
def _may_hold_quantity(node: Any) -> bool:
    """Whether a document holds a string that begins as a number does (a cheap look before
    the spec is read: a file of plain numbers is left at once)."""
    if isinstance(node, str):
        return node.lstrip(" \t\u00a0\u2009\u202f")[:1] in "0123456789+-."
    if isinstance(node, dict):
        return any(_may_hold_quantity(v) for v in node.values())
    if isinstance(node, list):
        return any(_may_hold_quantity(v) for v in node)
    return False


def convert_by_spec(data: Any) -> Any:
    """``data`` with its quantities converted as :func:`convert` converts them, the fields
    and their units read from the compiled spec of a shipped application
    (:mod:`advisor.core.requirement_spec` and the datasheet's compiled labels), so that a file
    with unit strings imports no pydantic. ``data`` itself, unchanged, where it holds no
    quantity or anything is in doubt (an application the spec does not hold, a string that
    is no quantity of its field): the models then convert it and word every refusal."""
    if not isinstance(data, dict) or not _may_hold_quantity(data):
        return data
    from advisor.core.compiled_validator import compiled

    try:
        kind = data["application"]["kind"]
        if not compiled(kind):
            return data
        from advisor.core.requirement_spec import ROOTS
        from advisor.datasheet.compiled_labels import LABELS

        units = {path: unit for path, (_, unit) in LABELS[kind].items()}
        return _by_spec(data, ROOTS[kind], (), units)
    except (UnitError, LookupError, TypeError):
        return data


def _by_spec(data: dict, model: str, prefix: tuple[str, ...], units: dict) -> dict:
    from advisor.core.requirement_spec import MODELS

    out = dict(data)
    for key, t, _, _ in MODELS[model]["fields"]:
        v = data.get(key)
        t = t[1] if t[0] == "optional" else t
        path = (*prefix, key)
        if t[0] == "float" and isinstance(v, str):
            out[key] = to_unit(v, units[path])
        elif t[0] == "model" and isinstance(v, dict):
            out[key] = _by_spec(v, t[1], path, units)
        elif t[0] == "list" and isinstance(v, list):
            item = t[1][1] if t[1][0] == "optional" else t[1]
            if item[0] == "float":
                out[key] = [to_unit(x, units[path]) if isinstance(x, str) else x for x in v]
            elif item[0] == "model":
                row = (*prefix, f"{key}[]")
                out[key] = [
                    _by_spec(x, item[1], row, units) if isinstance(x, dict) else x for x in v
                ]
    return out
