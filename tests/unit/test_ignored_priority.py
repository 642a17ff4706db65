"""``one_way.priority`` ranks the devices for the automatic choice only (rule OW-02): with a
named ``one_way.type`` it changes nothing, and the report says it is ignored, as it says of
the other keys a design does not use."""

import copy
import tomllib

from helpers import EXAMPLES

from advisor.core.engine import advise
from advisor.core.reading import parse_requirements
from advisor.core.report import to_toml

VALVE = tomllib.loads((EXAMPLES / "valve_actuator_hold.toml").read_text(encoding="utf-8"))


def _valve(**one_way) -> dict:
    doc = copy.deepcopy(VALVE)
    doc["one_way"] = {**doc.get("one_way", {}), **one_way}
    return doc


def test_a_named_type_leaves_the_priority_unused_and_says_so():
    by_power = advise(parse_requirements(_valve(type="em_clutch", priority="power")))
    by_mass = advise(parse_requirements(_valve(type="em_clutch", priority="mass")))
    said = [w for w in by_power.warnings if w.startswith("ignored: one_way.priority")]
    assert len(said) == 1 and "type = 'em_clutch'" in said[0]
    # the same design either way: only the requirement's echo differs
    assert to_toml(by_power).replace('priority = "power"', 'priority = "mass"') == to_toml(by_mass)


def test_the_automatic_choice_uses_the_priority():
    rep = advise(parse_requirements(_valve(type="auto", priority="power")))
    assert not [w for w in rep.warnings if "one_way.priority" in w]
