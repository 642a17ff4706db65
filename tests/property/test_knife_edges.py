"""No design sits on a knife edge (issue 23): every shipped example, and the duty cases of
the feature pairs, give the same verdict and the same design when any one numeric field is
moved by ±1e-9 (relative). Exhaustive over the fields, not sampled: each example is small."""

import copy
import tomllib

import pytest
from helpers import EXAMPLES

from advisor.core.engine import advise
from advisor.core.errors import InfeasibleError
from advisor.core.reading import parse_requirements
from advisor.core.registry import headline


def _leaves(doc, path=()):
    """Paths of every numeric (not boolean) value of a requirement document."""
    if isinstance(doc, dict):
        for k, v in doc.items():
            yield from _leaves(v, (*path, k))
    elif isinstance(doc, list):
        for i, v in enumerate(doc):
            yield from _leaves(v, (*path, i))
    elif isinstance(doc, int | float) and not isinstance(doc, bool) and doc != 0:
        yield path


def _moved(doc: dict, path: tuple, factor: float) -> dict:
    out = copy.deepcopy(doc)
    node = out
    for k in path[:-1]:
        node = node[k]
    node[path[-1]] = float(node[path[-1]]) * factor
    return out


def _outcome(doc: dict) -> str:
    try:
        return headline(advise(parse_requirements(doc)))
    except InfeasibleError as e:
        return "infeasible: " + e.summary


def _duty_cases() -> list[tuple[str, dict]]:
    cases = []
    for name in ("rudder_actuator_duty", "valve_actuator_duty"):
        doc = tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))
        for device in ("roller_clutch", "em_clutch"):
            d = copy.deepcopy(doc)
            d["application"]["hold_without_power"] = True
            d["one_way"] = {"type": device}
            cases.append((f"{name}+{device}", d))
    return cases


CASES = [
    (p.stem, tomllib.loads(p.read_text(encoding="utf-8"))) for p in sorted(EXAMPLES.glob("*.toml"))
] + _duty_cases()


@pytest.mark.parametrize("name, doc", CASES, ids=[c[0] for c in CASES])
def test_stable_under_1e_9_on_every_field(name, doc):
    base = _outcome(doc)
    moved = []
    for path in _leaves(doc):
        if path[:2] == ("motor", "reference"):  # the frame's own data, not a requirement
            continue
        for factor in (1 - 1e-9, 1 + 1e-9):
            try:
                out = _outcome(_moved(doc, path, factor))
            except Exception as e:  # a field at its bound may be refused: not a knife edge
                if type(e).__name__ in ("InputError", "ValidationError"):
                    continue
                raise
            if out != base:
                moved.append(f"{'.'.join(map(str, path))} × {factor!r}: {out} (was {base})")
    assert not moved, moved[:5]
