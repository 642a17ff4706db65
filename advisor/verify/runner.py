"""Run the verification set: each case's published values against what the advisor computes.

The set is data (``advisor/verify/cases.toml``, read by :func:`load_cases`); a case either runs
the whole advisor on a requirement and reads its report, or calls a direct calculation of
:mod:`advisor.verify.models`. Each quantity gets a verdict:

- ``pass``: within its tolerance of the published value (or inside the published bound);
- ``departure``: outside it, but equal within its own tolerance to the value the advisor is
  stated to compute instead, for the reason the data gives (a departure on purpose);
- ``FAIL``: neither — the advisor does not reproduce the source, and does not say why;
- ``ERROR``: the case could not be run (the advisor raised, or the path is not in the report).
"""

import math
import re
import tomllib
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Any

#: Verdicts that count as verified.
GOOD = ("pass", "departure")


@dataclass(frozen=True)
class Departure:
    expected: Any
    tolerance: float | None
    abs_tolerance: float | None
    reason: str
    doc: str = ""  # "docs/FILE.md: heading" of the section that states it


@dataclass(frozen=True)
class Quantity:
    name: str
    published: Any
    unit: str
    locator: str  # the report path or the model's key
    tolerance: float | None = None
    abs_tolerance: float | None = None
    tolerance_basis: str = ""
    relation: str = "="
    departure: Departure | None = None
    note: str = ""


@dataclass(frozen=True)
class Case:
    id: str
    title: str
    source: str
    where: str
    checked: str
    kind: str
    quantities: tuple[Quantity, ...]
    requirement: dict[str, Any] = field(default_factory=dict)
    function: str = ""
    inputs: dict[str, Any] = field(default_factory=dict)
    golden: str = ""


@dataclass(frozen=True)
class Outcome:
    """One quantity's result."""

    case: Case
    quantity: Quantity
    computed: Any
    verdict: str
    deviation: float | None  # (computed − published)/|published|, None for text
    error: str = ""

    @property
    def ok(self) -> bool:
        return self.verdict in GOOD


class DataError(ValueError):
    """The verification data itself is malformed (a bug of the data, said in one line)."""


def data_path() -> Path:
    """The shipped verification set."""
    return Path(str(resources.files("advisor.verify").joinpath("cases.toml")))


def _kind(v: Any) -> str:
    if isinstance(v, bool):
        return "a boolean"
    if isinstance(v, int | float):
        return "a number"
    return {str: "text", dict: "a table", list: "an array"}.get(type(v), type(v).__name__)


def _text(v: Any) -> bool:
    return isinstance(v, str)


def _number(v: Any) -> bool:
    return isinstance(v, int | float) and not isinstance(v, bool)


def _tolerance(v: Any) -> bool:
    return _number(v) and math.isfinite(v) and v >= 0


def _table(v: Any) -> bool:
    return isinstance(v, dict)


def _published(v: Any) -> bool:
    return isinstance(v, str) or (_number(v) and math.isfinite(v))


#: Each key a case, a quantity and a departure may hold: (test, what it must be, required).
_CASE_KEYS: dict[str, tuple[Any, str, bool]] = {
    "id": (_text, "text", True),
    "title": (_text, "text", True),
    "source": (_text, "text", True),
    "where": (_text, "text", True),
    "checked": (_text, "text", True),
    "kind": (_text, "text", True),
    "requirement": (_table, "a table", False),
    "function": (_text, "text", False),
    "inputs": (_table, "a table", False),
    "golden": (_text, "text", False),
}
_QUANTITY_KEYS: dict[str, tuple[Any, str, bool]] = {
    "name": (_text, "text", True),
    "published": (_published, "a finite number or text", True),
    "unit": (_text, "text", False),
    "path": (_text, "text", False),
    "key": (_text, "text", False),
    "tolerance": (_tolerance, "a finite number ≥ 0", False),
    "abs_tolerance": (_tolerance, "a finite number ≥ 0", False),
    "tolerance_basis": (_text, "text", False),
    "relation": (_text, "text", False),
    "departure": (_table, "a table", False),
    "note": (_text, "text", False),
}
_DEPARTURE_KEYS: dict[str, tuple[Any, str, bool]] = {
    "expected": (_published, "a finite number or text", True),
    "tolerance": (_tolerance, "a finite number ≥ 0", False),
    "abs_tolerance": (_tolerance, "a finite number ≥ 0", False),
    "reason": (_text, "text", True),
    "doc": (_text, "text", False),
}


def _check_keys(table: dict[str, Any], keys: dict[str, tuple[Any, str, bool]], where: str) -> None:
    for name, (test, what, required) in keys.items():
        if name not in table:
            if required:
                raise DataError(f"{where}: {name} is missing")
        elif not test(table[name]):
            raise DataError(f"{where}: {name} must be {what}, not {_kind(table[name])}")


def _departure(d: dict[str, Any] | None, where: str) -> Departure | None:
    if d is None:
        return None
    _check_keys(d, _DEPARTURE_KEYS, f"{where}: departure")
    return Departure(
        d["expected"], d.get("tolerance"), d.get("abs_tolerance"), d["reason"], d.get("doc", "")
    )


def _quantity(case_id: str, i: int, q: Any) -> Quantity:
    where = f"case {case_id}: quantity[{i}]"
    if not isinstance(q, dict):
        raise DataError(f"{where} must be a table, not {_kind(q)}")
    _check_keys(q, _QUANTITY_KEYS, where)
    where = f"case {case_id}: quantity {q['name']!r}"
    locator = q.get("path", q.get("key"))
    if locator is None:
        raise DataError(f"{where}: path (or key) is missing")
    relation = q.get("relation", "=")
    if relation not in ("=", "<=", ">="):
        raise DataError(f"{where}: relation {relation!r} is not =, <= or >=")
    numeric = not isinstance(q["published"], str)
    if not numeric and relation != "=":
        raise DataError(f"{where}: published must be a number with relation {relation!r}")
    if numeric and q.get("tolerance") is None and q.get("abs_tolerance") is None:
        raise DataError(f"{where}: tolerance (or abs_tolerance) is missing")
    return Quantity(
        name=q["name"],
        published=q["published"],
        unit=q.get("unit", ""),
        locator=locator,
        tolerance=q.get("tolerance"),
        abs_tolerance=q.get("abs_tolerance"),
        tolerance_basis=q.get("tolerance_basis", ""),
        relation=relation,
        departure=_departure(q.get("departure"), where),
        note=q.get("note", ""),
    )


def _case(i: int, c: Any) -> Case:
    """One case, every key checked for its type (a hand-edited set fails in one line)."""
    if not isinstance(c, dict):
        raise DataError(f"case[{i}] must be a table, not {_kind(c)}")
    cid = c.get("id")
    where = f"case {cid}" if isinstance(cid, str) else f"case[{i}]"
    _check_keys(c, _CASE_KEYS, where)
    kind = c["kind"]
    if kind not in ("requirement", "calc"):
        raise DataError(f"{where}: kind {kind!r} is not requirement or calc")
    if kind == "requirement" and "requirement" not in c:
        raise DataError(f'{where}: requirement is missing (kind = "requirement")')
    if kind == "calc":
        from advisor.verify.models import MODELS

        fn = c.get("function")
        if fn not in MODELS:
            raise DataError(
                f"{where}: function {fn!r} is not a model of advisor/verify/models.py"
                if fn is not None
                else f'{where}: function is missing (kind = "calc")'
            )
    quantities = c.get("quantity")
    if not isinstance(quantities, list) or not quantities:
        raise DataError(
            f"{where}: quantity is missing"
            if quantities is None
            else f"{where}: quantity must be a non-empty array of tables, not {_kind(quantities)}"
        )
    return Case(
        id=c["id"],
        title=c["title"],
        source=c["source"],
        where=c["where"],
        checked=c["checked"],
        kind=kind,
        quantities=tuple(_quantity(c["id"], j, q) for j, q in enumerate(quantities)),
        requirement=c.get("requirement", {}),
        function=c.get("function", ""),
        inputs=c.get("inputs", {}),
        golden=c.get("golden", ""),
    )


def load_cases(path: Path | None = None) -> list[Case]:
    """The cases of the verification set (the shipped one unless ``path`` is given).

    Read as the batch reads a requirement file (:func:`advisor.core.io_safety.read_input`: a
    regular file of at most 1 MiB, never blocking on a FIFO); an :class:`InputError` or a
    :class:`DataError` names the file, the case and the key that is wrong."""
    from advisor.core.io_safety import parse_toml, read_input, show

    source = path or data_path()
    name = show(source, 200)
    data = parse_toml(read_input(source, what="verification data "), name)
    raw = data.get("case")
    if raw is None or raw == []:
        raise DataError(f"no verification cases in {name} (no [[case]] tables)")
    if not isinstance(raw, list):
        raise DataError(f"{name}: case must be an array of tables, not {_kind(raw)}")
    try:
        cases = [_case(i, c) for i, c in enumerate(raw)]
    except DataError as exc:
        raise DataError(f"{name}: {exc}") from None
    ids = [c.id for c in cases]
    if len(set(ids)) != len(ids):
        dup = next(i for i in ids if ids.count(i) > 1)
        raise DataError(f"{name}: case id {dup!r} is not unique")
    return cases


# ------------------------------------------------------------------ reading a report
_ITEM = re.compile(r"^(?P<name>[A-Za-z_0-9]+)\[(?P<key>[A-Za-z_0-9]+)=(?P<value>[^\]]+)\]$")


def _same(a: Any, text: str) -> bool:
    if isinstance(a, bool) or not isinstance(a, int | float):
        return str(a) == text
    try:
        return float(a) == float(text)
    except ValueError:
        return False


def lookup(tree: Any, path: str) -> Any:
    """The value at ``path`` in a report read as TOML (``a.b``, ``list[key=value]``)."""
    node = tree
    for part in path.split("."):
        m = _ITEM.match(part)
        name = m.group("name") if m else part
        if not isinstance(node, dict) or name not in node:
            raise KeyError(f"{path}: no {name!r} in the report")
        node = node[name]
        if m:
            key, value = m.group("key"), m.group("value")
            hits = [x for x in node if isinstance(x, dict) and _same(x.get(key), value)]
            if len(hits) != 1:
                raise KeyError(f"{path}: {len(hits)} items with {key} = {value}")
            node = hits[0]
    return node


#: Between two report paths: the quantity is the first value over the second.
RATIO = " / "


def report_value(tree: Any, locator: str) -> Any:
    """The quantity at ``locator`` in a report read as TOML: one path (:func:`lookup`), or
    the ratio of two, ``a / b`` (a factor the advisor applies, read as the factored value
    over the value it multiplies: f_B = (f_B·F)/F)."""
    if RATIO not in locator:
        return lookup(tree, locator)
    top, bottom = (lookup(tree, part.strip()) for part in locator.split(RATIO, 1))
    if not all(_number(x) for x in (top, bottom)) or bottom == 0:
        raise KeyError(f"{locator}: {top!r} / {bottom!r} is not a ratio of numbers")
    return top / bottom


def _requirement_values(case: Case, catalog_dir: Path | None) -> dict[str, Any]:
    from advisor.core.engine import advise
    from advisor.core.reading import parse_requirements
    from advisor.core.report import to_toml

    report = tomllib.loads(to_toml(advise(parse_requirements(case.requirement), catalog_dir)))
    out: dict[str, Any] = {}
    for q in case.quantities:
        try:
            out[q.locator] = report_value(report, q.locator)
        except KeyError as exc:
            out[q.locator] = exc
    return out


def _calc_values(case: Case) -> dict[str, Any]:
    from advisor.verify.models import MODELS

    fn = MODELS.get(case.function)
    if fn is None:
        raise DataError(f"case {case.id}: no model function {case.function!r}")
    return fn(dict(case.inputs))


# ------------------------------------------------------------------ verdicts
def within(
    computed: Any, target: Any, tol: float | None, abs_tol: float | None, relation: str = "="
) -> bool:
    """Whether ``computed`` meets ``target``: equal text; for numbers, within the larger of
    the relative and the absolute tolerance, or on the allowed side of a bound."""
    if isinstance(target, str) or isinstance(computed, str):
        return str(computed) == str(target)
    if isinstance(computed, bool) or not isinstance(computed, int | float):
        return False
    if not math.isfinite(computed):
        return False
    room = max((tol or 0.0) * abs(target), abs_tol or 0.0)
    if relation == "<=":
        return computed <= target + room
    if relation == ">=":
        return computed >= target - room
    return abs(computed - target) <= room


def deviation(computed: Any, published: Any) -> float | None:
    """Relative deviation from the published value (None for text or a zero target)."""
    if isinstance(published, str) or not isinstance(computed, int | float):
        return None
    if isinstance(computed, bool) or published == 0:
        return None
    return (computed - published) / abs(published)


def judge(case: Case, q: Quantity, computed: Any) -> Outcome:
    if isinstance(computed, Exception):
        return Outcome(case, q, None, "ERROR", None, str(computed))
    dev = deviation(computed, q.published)
    if within(computed, q.published, q.tolerance, q.abs_tolerance, q.relation):
        return Outcome(case, q, computed, "pass", dev)
    d = q.departure
    if d is not None and within(computed, d.expected, d.tolerance, d.abs_tolerance):
        return Outcome(case, q, computed, "departure", dev)
    return Outcome(case, q, computed, "FAIL", dev)


def run_case(case: Case, catalog_dir: Path | None = None) -> list[Outcome]:
    """Every quantity of one case; a case that cannot run gives ERROR for each."""
    try:
        values = (
            _requirement_values(case, catalog_dir)
            if case.kind == "requirement"
            else _calc_values(case)
        )
    except DataError:
        raise
    except Exception as exc:  # the advisor failed on a published example: a finding
        msg = f"{type(exc).__name__}: {exc}"
        return [Outcome(case, q, None, "ERROR", None, msg) for q in case.quantities]
    out = []
    for q in case.quantities:
        if q.locator not in values:
            out.append(Outcome(case, q, None, "ERROR", None, f"no {q.locator!r} computed"))
        else:
            out.append(judge(case, q, values[q.locator]))
    return out


def run(
    cases: list[Case], only: str | None = None, catalog_dir: Path | None = None
) -> list[Outcome]:
    """All cases (or the one named ``only``), in the order of the data."""
    chosen = [c for c in cases if only is None or c.id == only]
    return [o for c in chosen for o in run_case(c, catalog_dir)]


def all_verified(outcomes: list[Outcome]) -> bool:
    return bool(outcomes) and all(o.ok for o in outcomes)
