"""GOST 24737-81 profile dimensions and the GOST 24738-81 diameter-pitch plan."""

import pytest

from catalogs import load_catalogs
from catalogs.threads import trapezoidal_profile


def test_tr16x2_matches_seed_001_and_gost():
    # Seed 001 quotes, for Tr16x2: d2 = 15, d3 = 13.5, D1 = 14, D2 = 15, D4 = 16.5 mm.
    t = load_catalogs().thread("Tr16x2")
    assert t is not None
    assert (t.d2_mm, t.d3_mm, t.D1_mm, t.D2_mm, t.D4_mm) == (15.0, 13.5, 14.0, 15.0, 16.5)
    # GOST 24737-81: ac = 0.25 for P = 2, H1 = P/2 = 1, h3 = P/2 + ac = 1.25
    assert (t.ac_mm, t.H1_mm, t.h3_mm) == (0.25, 1.0, 1.25)


@pytest.mark.parametrize(
    ("d", "p", "d3", "D4"),
    [
        # hand calculation with the formulas of GOST 24737-81
        (8, 1.5, 8 - 2 * (0.75 + 0.15), 8 + 2 * 0.15),  # ac = 0.15
        (20, 4, 20 - 2 * (2 + 0.25), 20 + 2 * 0.25),  # ac = 0.25
        (40, 7, 40 - 2 * (3.5 + 0.5), 40 + 2 * 0.5),  # ac = 0.5
        (100, 20, 100 - 2 * (10 + 1.0), 100 + 2 * 1.0),  # ac = 1.0
    ],
)
def test_profile_formulas(d, p, d3, D4):
    t = trapezoidal_profile(d, p)
    assert t.d3_mm == pytest.approx(d3)
    assert t.D4_mm == pytest.approx(D4)
    assert t.d2_mm == t.D2_mm == pytest.approx(d - p / 2)
    assert t.D1_mm == pytest.approx(d - p)


def test_plan_covers_8_to_100_with_preferred_pitches():
    cat = load_catalogs()
    diameters = sorted({t.d_mm for t in cat.threads})
    assert diameters[0] == 8 and diameters[-1] == 100
    assert len(diameters) == 35
    for d in diameters:
        rows = [t for t in cat.threads if t.d_mm == d]
        assert sum(t.preferred for t in rows) == 1, f"d = {d}: exactly one preferred pitch"
    preferred = {t.name for t in cat.threads if t.preferred}
    # the common designations of ISO 2902 / GOST 24738-81
    assert {"Tr10x2", "Tr16x4", "Tr20x4", "Tr24x5", "Tr32x6", "Tr40x7", "Tr100x12"} <= preferred
    assert {t.name for t in cat.threads if t.d_mm == 16} == {"Tr16x2", "Tr16x4"}
    assert {t.name for t in cat.threads if t.d_mm == 100} == {"Tr100x4", "Tr100x12", "Tr100x20"}


def test_thread_lookup_accepts_common_spellings():
    cat = load_catalogs()
    assert cat.thread("tr16x2") is cat.thread("Tr16×2") is cat.thread("Tr 16x2")
    assert cat.thread("Tr17x2") is None
