"""The rule table (`advisor rules`): printed from the registry of rules, the docs' copy kept
current, and every rule id exercised by a functional test somewhere in the suite; DU-06 and
DU-08, which had none, get theirs here, worked by hand on the valve actuator's cycle."""

import tomllib
from pathlib import Path

import pytest
from helpers import EXAMPLES

from advisor.cli import main
from advisor.core.engine import advise
from advisor.core.reading import parse_requirements
from advisor.core.rules_table import DOC, as_markdown, rows

TESTS = Path(__file__).resolve().parents[1]


def test_advisor_rules_prints_every_registered_rule(capsys):
    assert main(["rules"]) == 0
    out = capsys.readouterr().out
    table = rows()
    assert out.rstrip().endswith(f"{len(table)} rules")
    for r in table:
        assert r.id in out and r.title in out
    assert {"SCR-04", "WG-06", "OW-02", "BL-03"} <= {r.id for r in table}


def test_the_docs_rule_table_is_current():
    assert DOC.read_text(encoding="utf-8") == as_markdown(rows()), (
        "regenerate: python -m advisor.core.rules_table"
    )


def test_every_rule_id_has_a_functional_test():
    """Each rule id appears in a test file as a string (a test that runs the rule and reads
    its decision; DU-06 and DU-08 are read below)."""
    texts = [p.read_text(encoding="utf-8") for p in TESTS.rglob("test_*.py")]
    missing = [r.id for r in rows() if not any(r.id in t for t in texts)]
    assert missing == []


@pytest.fixture(scope="module")
def valve_cycle() -> dict:
    doc = tomllib.loads((EXAMPLES / "valve_actuator_duty.toml").read_text(encoding="utf-8"))
    rep = advise(parse_requirements(doc))
    return {d.id: d for d in rep.decisions}, rep


def test_du06_counts_the_starts_of_the_cycle(valve_cycle):
    """20 cycles an hour, two moves each (open, close): 40 starts per hour, each a start of
    the motor on the line; DU-06 states them against what the motor allows."""
    decisions, rep = valve_cycle
    du06 = decisions["DU-06"]
    assert du06.inputs["starts_per_hour"] == 20 * 2
    assert du06.inputs["allowed_starts_per_hour"] == pytest.approx(
        rep.design.duty.allowed_starts_per_hour, rel=1e-9
    )
    assert du06.inputs["starts_per_hour"] < du06.inputs["allowed_starts_per_hour"]


def test_du08_keeps_the_rated_points_motor_when_it_passes(valve_cycle):
    """The valve actuator's rated point takes 4A71B4 (seed 001); its cycle (equivalent
    torque, starts, starting torque) passes with it, so DU-08 keeps it and says so."""
    decisions, rep = valve_cycle
    du08 = decisions["DU-08"]
    assert du08.inputs["motor"] == du08.inputs["point_motor"] == "4A71B4"
    assert rep.design.motor.model == "4A71B4"
    assert "the rated point's motor" in du08.decision
