"""The family file: a base requirement, axes, and the variants they span.

Two forms. One application::

    [family]
    name = "Valve actuators"
    [family.axes]
    "rotary.torque_Nm" = { from = 100, to = 2000, steps = 20, scale = "log" }
    "rotary.speed_rpm" = [2, 5, 10]

    [application]          # the base requirement: the rest of the file
    kind = "rotary"
    ...

Several members (a range built two ways, or several applications)::

    [family]
    name = "Actuators"
    [[family.members]]
    name = "rotary"
    base = "rudder_actuator.toml"      # relative to the family file
    [family.members.axes]
    "rotary.torque_Nm" = [500, 1000]

The variants are numbered member by member, in the product order of the axes (the last axis
varies fastest). Every problem of the file is an :class:`InputError` raised before any work
starts: an unknown key, an empty range, a value outside its field's range, a value given
twice, an axis on the ``application`` table, or more variants than the stated limit (the
count is the product of the axis lengths: the product itself is never built).
"""

import hashlib
import json
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from advisor.family.adapter import InputError, field_problems

FAMILY_KEYS = ("name", "axes", "base", "members", "chunk_size")
MEMBER_KEYS = ("name", "base", "axes")
RANGE_KEYS = ("from", "to", "steps", "scale")
SCALES = ("linear", "log")
MAX_STEPS = 100_000
#: Variants a study may have unless ``--max-variants`` raises it: at 0.5–10 ms a variant on
#: one core (benchmarks/README.md), a million variants are minutes to hours of work.
DEFAULT_MAX_VARIANTS = 1_000_000


@dataclass(frozen=True)
class Axis:
    key: str  # dotted requirement key, e.g. rotary.torque_Nm
    values: tuple[Any, ...]
    scale: str  # linear, log, or list (values given one by one)


@dataclass(frozen=True)
class Member:
    name: str
    application: str
    base: dict[str, Any]
    axes: tuple[Axis, ...]

    @property
    def size(self) -> int:
        return math.prod(len(a.values) for a in self.axes)

    def coords(self, local: int) -> tuple[int, ...]:
        """Index of each axis value of the ``local``-th variant (last axis fastest)."""
        out = []
        for a in reversed(self.axes):
            local, k = divmod(local, len(a.values))
            out.append(k)
        return tuple(reversed(out))

    def requirement(self, coords: tuple[int, ...]) -> dict[str, Any]:
        """The base requirement with each axis key set to its value at ``coords``."""
        req = json.loads(json.dumps(self.base))  # a deep copy of plain TOML data
        for a, k in zip(self.axes, coords, strict=True):
            set_dotted(req, a.key, a.values[k])
        return req


@dataclass(frozen=True)
class Family:
    name: str
    source: str
    members: tuple[Member, ...]
    chunk_size: int | None = None
    #: every file the family was read from (the family file, the members' bases): the
    #: study must never write over one of them
    inputs: tuple[str, ...] = ()

    @property
    def size(self) -> int:
        return sum(m.size for m in self.members)

    def locate(self, index: int) -> tuple[int, int]:
        """(member number, index within the member) of a variant."""
        for n, m in enumerate(self.members):
            if index < m.size:
                return n, index
            index -= m.size
        raise IndexError(index)

    def variant(self, index: int) -> tuple[Member, tuple[int, ...], dict[str, Any]]:
        n, local = self.locate(index)
        m = self.members[n]
        coords = m.coords(local)
        return m, coords, m.requirement(coords)

    def axis_keys(self) -> list[str]:
        """Every axis key of every member, in order of first appearance."""
        keys: list[str] = []
        for m in self.members:
            keys += [a.key for a in m.axes if a.key not in keys]
        return keys

    def fingerprint(self) -> str:
        """Identifies the variants (not the name): a rerun resumes only the same study."""
        doc = [[m.name, m.base, [[a.key, list(a.values)] for a in m.axes]] for m in self.members]
        return hashlib.sha256(json.dumps(doc, sort_keys=True).encode()).hexdigest()[:16]


def set_dotted(doc: dict[str, Any], key: str, value: Any) -> None:
    """``set_dotted(d, "rotary.torque_Nm", 5)``: d["rotary"]["torque_Nm"] = 5 (tables made)."""
    *tables, last = key.split(".")
    for t in tables:
        nxt = doc.setdefault(t, {})
        if not isinstance(nxt, dict):
            raise InputError(f"family axis {key!r}: {t} is a value, not a table")
        doc = nxt
    doc[last] = value


def _num(x: Any) -> bool:
    return isinstance(x, int | float) and not isinstance(x, bool) and math.isfinite(x)


def _same_key(v: Any) -> Any:
    """A key equal for values a requirement reads as equal: ``100`` and ``100.0`` (and
    ``[1, 2]`` and ``[1.0, 2]``) are one value; ``true`` is not ``1``."""
    if isinstance(v, bool):
        return ("bool", v)
    if isinstance(v, int | float):
        return ("number", v)  # 100 == 100.0 and hash(100) == hash(100.0)
    if isinstance(v, list):
        return ("list", tuple(_same_key(x) for x in v))
    if isinstance(v, dict):
        return ("table", tuple(sorted((str(k), _same_key(x)) for k, x in v.items())))
    return (type(v).__name__, str(v))


def _show(v: Any) -> str:
    from advisor.core.io_safety import show_repr

    return show_repr(v) if isinstance(v, str) else repr(v)[:80]


def _round6(x: float) -> float:
    """Six significant digits, as the report writes numbers: clean axis values in the CSV."""
    if x == 0:
        return 0.0
    return round(x, 5 - math.floor(math.log10(abs(x))))


def _in_unit(key: str, v: Any) -> Any:
    """An axis value as the batch reads it: a quantity string (``"1 kN*m"``) converted to
    the unit the key names (``rotary.torque_Nm`` → N·m) by :func:`advisor.core.units.to_unit`,
    the converter of the requirement models (a whole number as an int, written as a plain
    one is); anything else (a number, a designation such as
    ``"6309"`` or ``"auto"``, a string that is no quantity of that unit) as given, for the
    requirement to judge per variant."""
    if not isinstance(v, str):
        return v
    from advisor.core.questions import unit_of
    from advisor.core.units import UnitError, to_unit

    unit = unit_of(key.rsplit(".", 1)[-1])
    if not unit:
        return v
    try:
        x = to_unit(v, unit)
    except UnitError:
        return v
    # "1.5 kN*m" is written 1500 as a plain 1500 is; a value not whole stays exact (a row
    # must equal the batch's advice for that variant, which reads the same string)
    return int(x) if isinstance(x, float) and x.is_integer() and abs(x) < 2**53 else x


def axis_values(key: str, spec: Any) -> Axis:
    """The values of one axis: a list as given, or a range ``{from, to, steps, scale}``."""
    if isinstance(spec, list):
        return list_axis(key, spec)
    if not isinstance(spec, dict):
        raise InputError(
            f"family axis {key!r} = {spec!r}: must be a list of values or a range "
            "{ from = A, to = B, steps = N, scale = 'linear' or 'log' }"
        )
    return range_axis(key, spec)


def list_axis(key: str, typed: list[Any]) -> Axis:
    """An axis of values given one by one (quantity strings converted to the key's unit);
    refused if empty, not finite, or holding one value twice."""
    where = f"family axis {key!r}"
    if not typed:
        raise InputError(f"{where}: empty list; give at least one value")
    spec = [_in_unit(key, v) for v in typed]  # "1 kN*m" and 1000 are one
    seen: dict[Any, int] = {}
    for i, v in enumerate(spec):
        if isinstance(v, float) and not math.isfinite(v):
            raise InputError(f"{where}: value {v!r}: must be a finite number")
        j = seen.setdefault(_same_key(v), i)
        if j != i:
            first, again = typed[j], typed[i]
            twice = (
                f"{_show(again)} appears twice"
                if repr(first) == repr(again)
                else f"{_show(first)} and {_show(again)} are the same value"
                + (f" ({_show(v)})" if isinstance(first, str) or isinstance(again, str) else "")
            )
            raise InputError(f"{where}: {twice}; give each value once")
    return Axis(key, tuple(spec), "list")


def check_range(where: str, spec: dict[str, Any]) -> tuple[Any, Any, Any, Any]:
    """``(from, to, steps, scale)`` of a range, each checked on its own and together."""
    unknown = [k for k in spec if k not in RANGE_KEYS]
    if unknown:
        raise InputError(f"{where}: unknown key {unknown[0]!r}; allowed: {', '.join(RANGE_KEYS)}")
    for k in ("from", "to", "steps"):
        if k not in spec:
            raise InputError(f"{where}: range without {k!r}; a range needs from, to and steps")
    lo, hi, steps, scale = spec["from"], spec["to"], spec["steps"], spec.get("scale", "linear")
    if not (_num(lo) and _num(hi)):
        raise InputError(f"{where}: from = {lo!r}, to = {hi!r}: must be finite numbers")
    if not isinstance(steps, int) or isinstance(steps, bool) or not 1 <= steps <= MAX_STEPS:
        raise InputError(f"{where}: steps = {steps!r}: must be a whole number, 1 to {MAX_STEPS}")
    if scale not in SCALES:
        raise InputError(f"{where}: scale = {scale!r}: must be one of {', '.join(SCALES)}")
    if steps == 1 and lo != hi:
        raise InputError(f"{where}: steps = 1 spans no range from {lo:g} to {hi:g}; use ≥ 2")
    if steps > 1 and lo == hi:
        raise InputError(f"{where}: empty range (from = to = {lo:g}) with {steps} steps")
    if scale == "log" and (lo <= 0 or hi <= 0):
        raise InputError(f"{where}: a log range needs from > 0 and to > 0 (got {lo:g}, {hi:g})")
    return lo, hi, steps, scale


def range_axis(key: str, spec: dict[str, Any]) -> Axis:
    """An axis of ``steps`` values from ``from`` to ``to`` (both as written, a quantity
    string converted to the key's unit as a list axis's is), the others rounded to six
    significant digits; whole numbers stay whole."""
    where = f"family axis {key!r}"
    ends = {k: _in_unit(key, spec[k]) for k in ("from", "to") if k in spec}
    if any(isinstance(v, str) for v in ends.values()):  # no quantity of the key's unit
        from advisor.core.questions import unit_of

        unit = unit_of(key.rsplit(".", 1)[-1])
        shown = ", ".join(f"{k} = {spec[k]!r}" for k in ("from", "to") if k in spec)
        raise InputError(
            f"{where}: {shown}: must be finite numbers"
            + (f", or quantities in {unit} (e.g. '100 {unit}')" if unit else "")
        )
    lo, hi, steps, scale = check_range(where, {**spec, **ends})
    if steps == 1:
        return Axis(key, (lo,), scale)
    raw = _range(lo, hi, steps, scale)
    if not all(math.isfinite(v) and (scale == "linear" or v > 0) for v in raw):
        raise InputError(
            f"{where}: {steps} {scale} steps from {lo:g} to {hi:g} leave the finite "
            "numbers; use a narrower range"
        )
    values = [_round6(v) for v in raw]
    values[0], values[-1] = lo, hi  # the ends exactly as written
    if all(isinstance(v, int) for v in (lo, hi)) and all(float(v).is_integer() for v in values):
        values = [int(v) for v in values]  # a whole-number range stays whole (pole pairs)
    if len(set(values)) != len(values):
        raise InputError(f"{where}: {steps} steps from {lo:g} to {hi:g} repeat values; use fewer")
    return Axis(key, tuple(values), scale)


def _range(lo: float, hi: float, steps: int, scale: str) -> list[float]:
    """``steps`` values from ``lo`` to ``hi``, written so that no intermediate overflows:
    a log range from 1e-300 to 1e300 (whose ratio is not a float) and a linear one from
    -1e308 to 1e308 (whose width is not a float) give finite values."""
    if scale == "log":
        a, b = math.log(lo), math.log(hi)
        return [math.exp(a + (b - a) * k / (steps - 1)) for k in range(steps)]
    return [lo * (1 - k / (steps - 1)) + hi * (k / (steps - 1)) for k in range(steps)]


def _axes(table: Any, where: str) -> tuple[Axis, ...]:
    if not isinstance(table, dict) or not table:
        raise InputError(f'{where}: no axes; give at least one, e.g. "rotary.torque_Nm" = [1, 2]')
    return tuple(axis_values(str(k), v) for k, v in table.items())


def check_member(member: Member) -> None:
    """Refuse a bad axis or a broken base before any work starts.

    Every value of every axis is validated with the other axes at their first value: a
    problem located at the axis key (unknown key, wrong type, out of range) refuses the axis;
    a problem of a field no axis sets refuses the base. A check between several fields (e.g.
    the output slower than the motor) depends on the combination and only makes the variants
    that break it invalid.
    """
    keys = [a.key for a in member.axes]

    def on_axis(where: str, key: str) -> bool:
        return where == key or where.startswith((key + ".", key + "["))

    first = tuple(0 for _ in member.axes)
    for p in field_problems(member.requirement(first)):
        if p.cross_field or any(on_axis(p.where, k) for k in keys):
            continue
        raise InputError(f"{member.name}: base requirement: {p.message}")
    for i, a in enumerate(member.axes):
        for k in range(len(a.values)):
            coords = tuple(k if j == i else 0 for j in range(len(member.axes)))
            for p in field_problems(member.requirement(coords)):
                if not p.cross_field and on_axis(p.where, a.key):
                    raise InputError(
                        f"family axis {a.key!r} value {a.values[k]!r}: {p.message}"
                        + ("" if len(member.axes) == 1 else " (other axes at their first value)")
                    )


def _member(name: str, base: dict[str, Any], axes: tuple[Axis, ...]) -> Member:
    """A member, its values not yet checked against the fields (see :func:`check_member`)."""
    app = base.get("application", {})
    kind = app.get("kind", "") if isinstance(app, dict) else ""
    for a in axes:
        # the whole table: an axis "application" = [{kind = …}, …] or "application.kind"
        # would change the application, and with it the meaning of every other key
        if a.key.split(".")[0].strip() == "application":
            raise InputError(
                f"family axis {a.key!r}: the [application] table cannot vary along an axis; "
                "use [[family.members]], one per application"
            )
    return Member(name or str(kind), str(kind), base, axes)


def check_size(members: list[Member], max_variants: int) -> None:
    """Refuse more variants than ``max_variants``, counted as the product of the axis
    lengths (the product itself is never built)."""
    total = sum(m.size for m in members)
    if total <= max_variants:
        return
    shape = " + ".join(" × ".join(str(len(a.values)) for a in m.axes) for m in members)
    raise InputError(
        f"family: {total:,} variants ({shape}) are more than the limit of {max_variants:,}; "
        "use fewer values or steps, or raise the limit with --max-variants N"
    )


def _read_toml(path: Path) -> dict[str, Any]:
    """A family or base file, read with the batch command's care (a regular file of at most
    1 MiB, UTF-8, not nested deeper than TOML needs); every problem an InputError."""
    from advisor.core.io_safety import read_toml

    return read_toml(path)


def family_head(fam: Any, source: Path) -> tuple[str, int | None]:
    """The ``[family]`` table's own keys: ``(name, chunk_size)``, unknown keys refused."""
    if not isinstance(fam, dict):
        raise InputError(
            f"{source}: no [family] table; a family file is a base requirement "
            "plus [family] with [family.axes]"
        )
    unknown = [k for k in fam if k not in FAMILY_KEYS]
    if unknown:
        raise InputError(f"family.{unknown[0]}: unknown key; allowed: {', '.join(FAMILY_KEYS)}")
    name = fam.get("name", source.stem)
    if not isinstance(name, str):
        raise InputError(f"family.name = {name!r}: must be a string in quotes")
    chunk = fam.get("chunk_size")
    if chunk is not None and (not isinstance(chunk, int) or isinstance(chunk, bool) or chunk < 1):
        raise InputError(f"family.chunk_size = {chunk!r}: must be a whole number ≥ 1")
    return name, chunk


def listed_members(raw: Any, here: Path, inputs: list[Path]) -> list[Member]:
    """The members of ``[[family.members]]``, each from its base file (added to ``inputs``)."""
    if not isinstance(raw, list) or not raw:
        raise InputError("family.members: must be a non-empty array of tables [[family.members]]")
    members = []
    for n, m in enumerate(raw, 1):
        where = f"family.members[{n}]"
        if not isinstance(m, dict):
            raise InputError(f"{where}: must be a table")
        bad = [k for k in m if k not in MEMBER_KEYS]
        if bad:
            raise InputError(f"{where}.{bad[0]}: unknown key; allowed: {', '.join(MEMBER_KEYS)}")
        if not isinstance(m.get("base"), str):
            raise InputError(f"{where}.base: missing; the requirement file of this member")
        inputs.append(here / m["base"])
        base = _read_toml(inputs[-1])
        members.append(_member(str(m.get("name", "")), base, _axes(m.get("axes"), where)))
    names = [m.name for m in members]
    dup = next((x for x in names if names.count(x) > 1), None)
    if dup is not None:
        raise InputError(f"family.members: two members named {dup!r}; give each a name")
    return members


def only_member(
    fam: dict[str, Any], inline: dict[str, Any], here: Path, inputs: list[Path]
) -> Member:
    """The one member of a family file without members: the base in the file itself, or
    in the file ``family.base`` names (added to ``inputs``)."""
    if "base" in fam:
        if inline:
            raise InputError(
                "family.base: give the base requirement in the file or as family.base, not both"
            )
        inputs.append(here / str(fam["base"]))
        base = _read_toml(inputs[-1])
    else:
        base = inline
    return _member("", base, _axes(fam.get("axes"), "family.axes"))


def parse_family(
    doc: dict[str, Any], source: Path, max_variants: int = DEFAULT_MAX_VARIANTS
) -> Family:
    """Validate a family document; ``source`` locates relative ``base`` files."""
    fam = doc.get("family")
    name, chunk = family_head(fam, source)
    inline = {k: v for k, v in doc.items() if k != "family"}
    inputs = [source]
    if "members" in fam:
        if inline or "axes" in fam or "base" in fam:
            raise InputError(
                "family.members: with members, each member has its own base and axes; "
                "remove the top-level requirement tables, family.base and family.axes"
            )
        members = listed_members(fam["members"], source.parent, inputs)
    else:
        members = [only_member(fam, inline, source.parent, inputs)]
    check_size(members, max_variants)  # before the values are checked: that costs time
    for m in members:
        check_member(m)
    return Family(name, str(source), tuple(members), chunk, tuple(str(p) for p in inputs))


def read_family(path: Path, max_variants: int = DEFAULT_MAX_VARIANTS) -> Family:
    return parse_family(_read_toml(path), path, max_variants)
