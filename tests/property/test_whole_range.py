"""Every registered application, run with values drawn across each field's whole documented
range, edges included (issue 13, "done means"): exit 0, 2 (a cross-field rule of the
requirement) or 3, never an internal error; no nan or inf in a report; no numpy
RuntimeWarning.

The strategies are built from each application's JSON Schema (the same the wizard and
`advisor schema` read), so a new application or a new field is covered without a test edit.
A field whose range has an open end (``> 0``) is drawn down to the smallest positive double:
a field that accepts it must survive it.
"""

import math
import sys
import warnings
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from advisor.core import registry
from advisor.core.engine import advise
from advisor.core.errors import InfeasibleError, InputError
from advisor.core.reading import parse_requirements
from advisor.core.report import to_toml

#: Where a range has no stated end, the draw stops here (a finite number is then the rule).
OPEN_END = 1e12


def _resolve(root: dict, node: dict) -> dict:
    while "$ref" in node:
        node = {**root["$defs"][node["$ref"].rsplit("/", 1)[-1]], **_without(node, "$ref")}
    if "allOf" in node and len(node["allOf"]) == 1:
        node = {**_resolve(root, node["allOf"][0]), **_without(node, "allOf")}
    return node


def _without(d: dict, key: str) -> dict:
    return {k: v for k, v in d.items() if k != key}


def _number(node: dict, integer: bool) -> st.SearchStrategy:
    lo = node.get("minimum", node.get("exclusiveMinimum", -OPEN_END))
    hi = node.get("maximum", node.get("exclusiveMaximum", OPEN_END))
    if integer:
        lo = math.ceil(lo) + (1 if "exclusiveMinimum" in node and lo == int(lo) else 0)
        hi = math.floor(hi) - (1 if "exclusiveMaximum" in node and hi == int(hi) else 0)
        return st.sampled_from([lo, hi]) | st.integers(lo, hi)
    if "exclusiveMinimum" in node:  # the closest a value can come to an open end
        lo = (
            math.nextafter(lo, math.inf) if lo != 0 else sys.float_info.min * sys.float_info.epsilon
        )
    if "exclusiveMaximum" in node:
        hi = math.nextafter(hi, -math.inf)
    edges = st.sampled_from([lo, hi])
    inside = st.floats(lo, hi, allow_nan=False, allow_infinity=False)
    if lo > 0:  # across the decades, as the ranges are written
        logs = st.floats(math.log10(max(lo, 1e-300)), math.log10(hi)).map(lambda e: 10.0**e)
        inside = inside | logs.filter(lambda x: lo <= x <= hi)
    return edges | inside


def strategy(root: dict, node: dict) -> st.SearchStrategy:
    node = _resolve(root, node)
    if "const" in node:
        return st.just(node["const"])
    if "enum" in node:
        return st.sampled_from(node["enum"])
    for key in ("anyOf", "oneOf"):
        if key in node:
            options = [o for o in node[key] if _resolve(root, o).get("type") != "null"]
            return st.one_of([strategy(root, o) for o in options])
    kind = node.get("type")
    if kind == "number":
        return _number(node, integer=False)
    if kind == "integer":
        return _number(node, integer=True)
    if kind == "boolean":
        return st.booleans()
    if kind == "string":
        # free text (a title, a name) or a catalog name: its default or example stands
        known = [node["default"]] if "default" in node else node.get("examples", [])
        return st.sampled_from(known) if known else st.text("abc", min_size=1, max_size=8)
    if kind == "array":
        return st.lists(
            strategy(root, node["items"]),
            min_size=node.get("minItems", 0),
            max_size=min(node.get("maxItems", 3), 3),
            unique=node.get("uniqueItems", False),
        )
    if kind == "object":
        return _table(root, node)
    raise AssertionError(f"no strategy for schema node {node}")


@st.composite
def _table(draw, root: dict, node: dict) -> dict[str, Any]:
    required = set(node.get("required", ()))
    out = {}
    for name, sub in node.get("properties", {}).items():
        if name in required or draw(st.booleans()):
            out[name] = draw(strategy(root, sub))
    return out


def requirement_strategy(kind: str) -> st.SearchStrategy:
    schema = registry.requirements_model(kind).model_json_schema()
    return _table(schema, schema).map(
        lambda d: {**d, "application": {**d.get("application", {}), "kind": kind}}
    )


def _finite(obj: Any, key: str = "") -> None:
    if isinstance(obj, float):
        assert math.isfinite(obj), f"{key} = {obj}"
    elif isinstance(obj, dict):
        for k, v in obj.items():
            _finite(v, f"{key}.{k}")
    elif isinstance(obj, list):
        for i, v in enumerate(obj):
            _finite(v, f"{key}[{i}]")


def run(doc: dict) -> int:
    """The batch path's outcome for a requirement document: 0, 2 or 3 (anything else
    raises)."""
    try:
        req = parse_requirements(doc)
    except InputError:
        return 2
    try:
        report = advise(req)
    except InfeasibleError:
        return 3
    except InputError:
        return 2
    import tomllib

    _finite(tomllib.loads(to_toml(report)))
    return 0


@pytest.mark.parametrize("kind", registry.kinds())
def test_every_field_across_its_whole_range(kind):
    outcomes: list[int] = []

    @settings(
        max_examples=100,
        deadline=None,
        derandomize=True,
        suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
    )
    @given(requirement_strategy(kind))
    def check(doc):
        with warnings.catch_warnings():
            warnings.simplefilter("error", RuntimeWarning)
            outcomes.append(run(doc))

    check()
    # the draws reach designs, not only refusals
    assert 0 in outcomes or 3 in outcomes, outcomes
