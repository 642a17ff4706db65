"""The datasheet labels a report key by the table that holds it where its meaning depends on
the table: positioning's two inertia ratios share the key ``inertia_ratio`` (a stable
report key) but not the quantity."""

import pytest
from helpers import EXAMPLES

from advisor.core.engine import advise
from advisor.core.reading import read_requirements
from advisor.core.report import plain
from advisor.datasheet.content import sheet
from advisor.datasheet.labels import split_key


def _rows(block, label: str) -> list[str]:
    return [value for lab, value, _ in block.rows if lab == label]


def test_the_two_inertia_ratios_of_positioning_have_their_own_labels():
    """The indexing table (seed 003's move, J_p = 5 kg·m²), motor C of the example
    (J0 = 0.03 kg·m²) in both tables: motion's I = J_p/J0 = 5/0.03 = 166.7 (the load at its
    own shaft); the duty's is the load reflected to the motor, J_p/(i²·J0) at the cycle's
    ratio i = 7.34461: 5/(53.943·0.03) = 3.090. Two quantities, two labels."""
    report = advise(read_requirements(EXAMPLES / "indexing_table_duty.toml"))
    s = sheet(plain(report), "h", [])
    blocks = {b.title: b for b in s.components}
    motion = "load/motor inertia I = J_p/J0 (seed 003, no reducer)"
    duty = "load/motor inertia at the motor J_L/(i²·J_m)"
    assert _rows(blocks["motion"], motion) == ["166.7"]
    assert _rows(blocks["duty"], duty) == ["3.09"]
    assert not _rows(blocks["motion"], "inertia ratio")
    assert not _rows(blocks["duty"], "inertia ratio")
    d = report.design.duty
    assert d is not None and d.motor == report.design.motion.motor == "C"
    assert report.design.motion.inertia_ratio == pytest.approx(5 / 0.03, rel=1e-5)
    assert d.inertia_ratio == pytest.approx(5 / (d.ratio**2 * 0.03), rel=1e-5)


def test_a_key_outside_those_tables_keeps_its_words():
    assert split_key("inertia_ratio") == ("inertia ratio", "")
    assert split_key("inertia_ratio", "screw") == ("inertia ratio", "")
