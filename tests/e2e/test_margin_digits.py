"""A check's margin shows the same digits in the datasheet (which reads the report's
six-digit values), the wizard's Checks view and the summaries (which hold the values as
computed): a margin the report's rounding left on a tie at the third decimal keeps the
fourth, as the datasheet's other numbers do."""

import pytest
from helpers import EXAMPLES

from advisor.core.engine import advise
from advisor.core.errors import InfeasibleError
from advisor.core.reading import read_requirements
from advisor.core.report import margin_text, plain
from advisor.datasheet import _sheet

pytest.importorskip("matplotlib")


def test_the_critical_speed_margin_of_seed_001_is_not_rounded_down():
    # seed 001's screw: n = 1392.47 rpm against 0.8 of n_cr = 10282.524 rpm (Blevins,
    # table 8-1), margin = 0.8 × 10282.524 / 1392.47 = 5.907502; the report stores 5.9075
    # (six digits), binary 5.90749999…, which f"{:.3f}" took down to 5.907
    report = advise(read_requirements(EXAMPLES / "linear_screw_actuator.toml"))
    check = next(c for c in report.checks if c.id == "critical_speed")
    assert check.margin == pytest.approx(0.8 * 10282.524 / 1392.47, rel=1e-6)
    sheet, doc = _sheet(report)
    assert next(c for c in doc["checks"] if c["id"] == "critical_speed")["margin"] == 5.9075
    row = next(c for c in sheet.checks if c.id == "critical_speed")
    assert row.margin == "5.9075" == margin_text(check.margin)
    assert margin_text(5.9075) == "5.9075" and margin_text(5.90749) == "5.907"
    assert margin_text(5.90751) == "5.908" and margin_text(1.0) == "1.000"


def _example_reports():
    files = [*EXAMPLES.glob("*.toml"), *(EXAMPLES / "uncertainty").glob("*.toml")]
    for f in sorted(files):
        try:
            yield f.name, advise(read_requirements(f))
        except InfeasibleError:
            continue


def test_every_example_margin_reads_the_same_from_the_report_and_as_computed():
    seen = 0
    for name, report in _example_reports():
        doc = plain(report)
        sheet, _ = _sheet(report)
        shown = {c.id: c.margin for c in sheet.checks}
        for c, written in zip(report.checks, doc["checks"], strict=True):
            assert shown[c.id] == margin_text(c.margin) == margin_text(written["margin"]), name
            seen += 1
    assert seen > 50
