"""Catalogs: every row has a source; broken or inconsistent rows are refused with file, row
and field named."""

import itertools
import math
import shutil
import tomllib
from pathlib import Path

import pytest

from advisor.core.errors import CatalogError
from catalogs import load_catalogs
from catalogs.loader import HERE, MATERIALS_FILE, MOTORS_FILE


def test_shipped_catalogs_load_with_sources():
    cat = load_catalogs()
    assert len(cat.motors) >= 50
    for m in cat.motors:
        assert m.source in cat.motor_sources
    assert {m.poles for m in cat.motors} == {2, 4, 6, 8}
    assert min(m.rated_power_kW for m in cat.motors) <= 0.18
    assert max(m.rated_power_kW for m in cat.motors) >= 15
    for pair in cat.materials.pair:
        assert pair.source and all(s in cat.materials.sources for s in pair.source)


def test_every_motor_row_is_consistent():
    # n ≈ n₀(1 − s) within 1.5 % of n₀; P = M·ω holds by construction of rated torque
    for m in load_catalogs().motors:
        n0 = m.synchronous_speed_rpm
        assert abs(n0 * (1 - m.slip_pct / 100) - m.rated_speed_rpm) <= 0.015 * n0, m.model
        assert m.starting_torque_ratio <= m.breakdown_torque_ratio


def test_gost_12139_series():
    powers = load_catalogs().rated_powers_kW
    assert {0.37, 0.55, 0.75, 1.1} <= set(powers)
    # 0.5 kW (seed 001, fig. 4) is a value of the additional series (clause 1.3), not of the
    # main series the advisor selects from
    assert 0.5 not in powers
    data = tomllib.loads((HERE / "gost_12139_84_powers.toml").read_text(encoding="utf-8"))
    assert 0.5 in data["additional_rated_powers_kW"]
    assert "clause 1.3" in data["additional_source"]


def test_4a_powers_are_the_main_series_and_the_additional_one_would_not_change_seed_001():
    # the evidence for selecting from the main series: every 4A motor is rated on it
    cat = load_catalogs()
    assert {m.rated_power_kW for m in cat.motors} <= set(cat.rated_powers_kW)
    # seed 001 needs 5.085 N·m × 1200 rpm = 0.639 kW: 0.75 kW covers it; in the main series
    # and in the main series merged with 0.5 kW its neighbours are the same, 0.55 and 1.1 kW
    need = 5.085 * 1200 * math.pi / 30 / 1000
    assert need == pytest.approx(0.639, abs=5e-4)
    for series in (sorted(cat.rated_powers_kW), sorted({*cat.rated_powers_kW, 0.5})):
        i = next(k for k, p in enumerate(series) if p >= need)
        assert series[i - 1 : i + 2] == [0.55, 0.75, 1.1]


def _user_dir(tmp_path, name, text):
    d = tmp_path / "cat"
    d.mkdir()
    (d / name).write_text(text, encoding="utf-8")
    return d


MOTOR_ROW = """
[sources]
mine = "my test bench"

[[motor]]
model = "X71B8"
poles = 8
rated_power_kW = 0.25
rated_speed_rpm = 680.0
slip_pct = {slip}
breakdown_torque_ratio = 1.7
starting_torque_ratio = 1.3
efficiency_pct = 56.0
cos_phi = 0.65
starting_current_ratio = 3.0
inertia_kgm2 = 0.0019
mass_kg = 15.1
source = "mine"
"""


def test_user_motor_with_inconsistent_slip_is_refused(tmp_path):
    # the 4A71B8 row of the source table: s = 12.7 % gives 655 rpm, not 680
    d = _user_dir(tmp_path, MOTORS_FILE, MOTOR_ROW.format(slip=12.7))
    with pytest.raises(CatalogError) as e:
        load_catalogs(d)
    msg = str(e.value)
    assert MOTORS_FILE in msg and "row 1" in msg and "X71B8" in msg and "slip_pct = 12.7" in msg


def test_user_motor_is_added(tmp_path):
    d = _user_dir(tmp_path, MOTORS_FILE, MOTOR_ROW.format(slip=9.3))
    cat = load_catalogs(d)
    assert any(m.model == "X71B8" for m in cat.motors)


def test_user_motor_with_bad_field_is_refused(tmp_path):
    text = MOTOR_ROW.format(slip=9.3).replace("cos_phi = 0.65", "cos_phi = 1.65")
    d = _user_dir(tmp_path, MOTORS_FILE, text)
    with pytest.raises(CatalogError, match=r"row 1 \(model = 'X71B8'\): field cos_phi = 1.65"):
        load_catalogs(d)


def test_broken_toml_catalog_is_refused(tmp_path):
    d = _user_dir(tmp_path, MOTORS_FILE, "[[motor]\nmodel = ")
    with pytest.raises(CatalogError, match="broken TOML"):
        load_catalogs(d)


def test_materials_with_unknown_source_are_refused(tmp_path):
    text = (HERE / MATERIALS_FILE).read_text(encoding="utf-8")
    text = text.replace('source = ["shigley-8-5", "ivanov"]', 'source = ["nowhere"]', 1)
    d = _user_dir(tmp_path, MATERIALS_FILE, text)
    with pytest.raises(CatalogError, match="nowhere"):
        load_catalogs(d)


def test_cache_follows_file_changes(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "c"))
    d = _user_dir(tmp_path, MOTORS_FILE, MOTOR_ROW.format(slip=9.3))
    load_catalogs.cache_clear()
    assert any(m.model == "X71B8" for m in load_catalogs(d).motors)
    assert list((tmp_path / "c" / "drive-advisor").glob("catalogs-*.marshal"))
    # a cached run gives the same catalogs
    load_catalogs.cache_clear()
    again = load_catalogs(d)
    assert any(m.model == "X71B8" and m.slip_pct == 9.3 for m in again.motors)
    # editing the file invalidates the cache: the broken row is seen
    (d / MOTORS_FILE).write_text(MOTOR_ROW.format(slip=12.7) + "\n", encoding="utf-8")
    load_catalogs.cache_clear()
    with pytest.raises(CatalogError):
        load_catalogs(d)
    shutil.rmtree(tmp_path / "c")


def test_cache_key_follows_the_catalog_code(tmp_path, monkeypatch):
    """The cache is keyed by the source of the code that makes the cached rows: an edit to
    the loader, the rows or the schema gives a new key, with no version to bump by hand."""
    from catalogs import loader

    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "c"))
    files = [HERE / MOTORS_FILE]
    before = loader.cache_file(files)
    assert before == loader.cache_file(files)  # the same code, the same key
    real = Path.read_bytes

    def edited(path: Path) -> bytes:
        data = real(path)
        return data + b"# edited\n" if path.name == "rows.py" else data

    loader.code_stamp.cache_clear()
    with monkeypatch.context() as m:
        m.setattr(Path, "read_bytes", edited)
        assert loader.cache_file(files) != before
    loader.code_stamp.cache_clear()
    assert loader.cache_file(files) == before


@pytest.mark.parametrize("damage", ["truncated", "garbage", "empty", "other data"])
def test_a_damaged_cache_is_ignored_and_rewritten(tmp_path, monkeypatch, damage):
    import marshal

    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "c"))
    load_catalogs.cache_clear()
    first = load_catalogs()
    (cache,) = (tmp_path / "c" / "drive-advisor").glob("catalogs-*.marshal")
    good = cache.read_bytes()
    cache.write_bytes(
        {
            "truncated": good[: len(good) // 2],
            "garbage": bytes(range(256)) * 4,
            "empty": b"",
            "other data": marshal.dumps({"threads": [1, 2]}),
        }[damage]
    )
    load_catalogs.cache_clear()
    assert load_catalogs() == first  # validated again from the files
    assert cache.read_bytes() == good  # and the cache written anew
    load_catalogs.cache_clear()


BEARING_ROW = """
[sources]
mine = "a test row"

[[bearing]]
designation = "7001 CD"
type = "angular_contact"
friction = "angular_single_row"
d_mm = 12
D_mm = {D}
B_mm = 8
contact_angle_deg = 15
C_kN = 4.8
C0_kN = 2.4
limiting_speed_rpm = 60000
source = ["mine"]
"""


def test_bearing_rows_and_estimated_ball_geometry():
    cat = load_catalogs()
    b = cat.bearing("7000  cd")  # spacing and case are forgiven
    assert (b.d_mm, b.D_mm, b.B_mm, b.contact_angle_deg) == (10, 26, 8, 15)
    assert (b.ball_count, b.ball_diameter_mm, b.pitch_radius_mm) == (8, 4.76, 6.6)
    assert b.inner_raceway_radius_mm == pytest.approx(4.22)
    assert set(b.estimated) == {"C_kN", "C0_kN"}
    g = cat.bearing("6000")  # SKF table: 10×26×8, C 4.75 kN, C0 1.96 kN, 40000 rpm
    assert (g.C_kN, g.C0_kN, g.limiting_speed_rpm, g.f0) == (4.75, 1.96, 40000, 12)
    # ball geometry not published: D_w = 0.3·(26 − 10) = 4.8, Z = round(0.67·π·18/4.8) = 8
    assert (g.ball_diameter_mm, g.ball_count) == (pytest.approx(4.8), 8)
    assert {"ball_diameter_mm", "ball_count", "pitch_diameter_mm"} <= set(g.estimated)
    for row in cat.bearings:
        assert row.source and all(s in cat.bearing_sources for s in row.source)


def test_user_bearing_is_added(tmp_path):
    d = _user_dir(tmp_path, "skf_bearings.toml", BEARING_ROW.format(D=28))
    assert load_catalogs(d).bearing("7001 CD").C_kN == 4.8


def test_user_bearing_with_bore_above_outer_diameter_is_refused(tmp_path):
    d = _user_dir(tmp_path, "skf_bearings.toml", BEARING_ROW.format(D=11))
    with pytest.raises(CatalogError) as e:
        load_catalogs(d)
    msg = str(e.value)
    assert "skf_bearings.toml" in msg and "row 1 (designation = '7001 CD')" in msg
    assert "D_mm = 11" in msg


def test_user_bearing_with_unknown_friction_series_is_refused(tmp_path):
    text = BEARING_ROW.format(D=28).replace('"angular_single_row"', '"tapered"')
    d = _user_dir(tmp_path, "skf_bearings.toml", text)
    with pytest.raises(CatalogError, match="field friction = 'tapered'"):
        load_catalogs(d)


def test_estimated_4a_inertias_grow_with_the_frame():
    cat = load_catalogs()
    for poles in (2, 4, 6, 8):
        line = sorted(cat.motors_with_poles(poles), key=lambda m: m.rated_power_kW)
        for a, b in itertools.pairwise(line):
            assert a.inertia_kgm2 < b.inertia_kgm2, (a.model, b.model)
    by = {m.model: m for m in cat.motors}

    def between(lo: str, mid: str, hi: str) -> float:
        # the file's rule: log–log interpolation in rated torque between the kept rows
        a, m, b = by[lo], by[mid], by[hi]
        t = math.log(m.rated_torque_Nm / a.rated_torque_Nm) / math.log(
            b.rated_torque_Nm / a.rated_torque_Nm
        )
        return a.inertia_kgm2 * (b.inertia_kgm2 / a.inertia_kgm2) ** t

    # 4AA63B4: M_n = 370/(1365·π/30) = 2.589 N·m between 4AA63A4 (1.730 N·m, 0.0012 kg·m²) and
    # 4A71A4 (3.779 N·m, 0.0013 kg·m²): t = ln(2.589/1.730)/ln(3.779/1.730) = 0.5158,
    # J = 0.0012·(13/12)^0.5158 = 0.001251
    assert between("4AA63A4", "4AA63B4", "4A71A4") == pytest.approx(0.001251, abs=1e-6)
    assert by["4AA63B4"].inertia_kgm2 == pytest.approx(
        between("4AA63A4", "4AA63B4", "4A71A4"), rel=0.01
    )
    assert by["4A71A6"].inertia_kgm2 == pytest.approx(
        between("4AA63B6", "4A71A6", "4A71B6"), rel=0.01
    )


def test_skf_rows_d40_to_50_from_the_catalogue():
    cat = load_catalogs()
    # SKF General Catalogue (2006, Russian edition), d 40–60 mm table: C, C0, Pu, speeds, mass
    # and the printed f0 (text of github.com/ArtemFilin1990/Mar, lines 17948–18019)
    table = {
        "6008": (40, 68, 15, 17.8, 11.6, 0.49, 22000, 14000, 0.19, 15),
        "6009": (45, 75, 16, 22.1, 14.6, 0.64, 20000, 12000, 0.25, 15),
        "6010": (50, 80, 16, 22.9, 16.0, 0.71, 18000, 11000, 0.26, 15),
        "6208": (40, 80, 18, 32.5, 19.0, 0.80, 18000, 11000, 0.37, 14),
        "6209": (45, 85, 19, 35.1, 21.6, 0.92, 17000, 11000, 0.41, 14),
        "6210": (50, 90, 20, 37.1, 23.2, 0.98, 15000, 10000, 0.46, 14),
    }
    for name, (d, D, B, C, C0, Pu, nr, nl, m, f0) in table.items():
        b = cat.bearing(name)
        got = (b.d_mm, b.D_mm, b.B_mm, b.C_kN, b.C0_kN, b.Pu_kN)
        assert got == (d, D, B, C, C0, Pu), name
        assert (b.reference_speed_rpm, b.limiting_speed_rpm, b.mass_kg, b.f0) == (nr, nl, m, f0)
        assert "f0" not in b.estimated and b.source == ["skf-gc-40"]
    b = cat.bearing("7210 BECBP")  # 50×90×20, 40°, C 40 kN, C0 31 kN, Pu 1.32 kN, 9000 rpm
    assert (b.d_mm, b.D_mm, b.B_mm, b.contact_angle_deg) == (50, 90, 20, 40)
    assert (b.C_kN, b.C0_kN, b.Pu_kN, b.limiting_speed_rpm, b.mass_kg) == (40, 31, 1.32, 9000, 0.47)
    for name in (*table, "7210 BECBP"):
        assert all(s in cat.bearing_sources for s in cat.bearing(name).source)


def test_4a_frames_56_and_63_carry_the_4aa_designation():
    # Issue 23, item 10. The 4A series (Kravchik et al., «Асинхронные двигатели серии 4А»,
    # 1982) builds frames 50–63 with an aluminium-alloy frame and end shields and designates
    # them 4AA (4AA56A2, 4AA63B4, …); frames 71 and up are 4A. A public reproduction of the
    # same course-design table (a C# course-work listing found by the stored code search)
    # prints 4АА56А2, 4АА56В2, 4АА56А4, 4АА63А4, 4АА63В4, 4АА63А6, 4АА63В6 with the same
    # P, s, n, Mmax/Mn, Mst/Mn as our rows (see catalogs/induction_4a.toml).
    by = {m.model: m for m in load_catalogs().motors}
    small = sorted(n for n in by if n[2:4] in ("56", "63") or n[3:5] in ("56", "63"))
    assert small == [
        "4AA56A2", "4AA56B2", "4AA56B4", "4AA63A2", "4AA63A4",
        "4AA63A6", "4AA63B2", "4AA63B4", "4AA63B6",
    ]  # fmt: skip
    assert not any(n.startswith(("4A56", "4A63")) for n in by)
    # the frame from 71 up keeps the one-A designation
    assert {"4A71A4", "4A71B6", "4A80A2"} <= set(by)
    # the rename touched names only: 4AA63B4 is the table's 0.37 kW, s = 9.0 %, 1365 rpm,
    # Mmax/Mn = Mst/Mn = 2.0; M_n = 370 W / (1365·π/30 rad/s) = 2.5885 N·m
    m = by["4AA63B4"]
    assert (m.poles, m.rated_power_kW, m.slip_pct, m.rated_speed_rpm) == (4, 0.37, 9.0, 1365.0)
    assert (m.breakdown_torque_ratio, m.starting_torque_ratio) == (2.0, 2.0)
    assert m.rated_torque_Nm == pytest.approx(2.5885, abs=1e-4)


def test_tr11_row_gost_24738_81():
    # Issue 23, item 10. GOST 24738-81 (= ISO 2902, ST SEV 639-77), table 1, row d = 11
    # (2nd row of diameters): pitches 3 and 2. The pitch list is the one of the ISO 2904
    # basic-dimension table at roymech.org/Useful_Tables/Screws/Trapezoidal.html (rows
    # "11 | 2" and "11 | 3") and of engineersedge.com/hardware/iso-metric-trapezoidal-threads1.htm
    # (TR11x2, TR11x3). Preferred pitch 2, as the catalog row states: the plan's preferred
    # pitches run 2 for d = 9…11, 3 for d = 12 and 14, 4 for d = 16…20 (no copy showing the bold
    # marking could be opened; see the comment on the row in the catalog).
    cat = load_catalogs()
    tr11 = [t for t in cat.threads if t.d_mm == 11]
    assert [t.name for t in tr11] == ["Tr11x3", "Tr11x2"]
    assert {t.series for t in tr11} == {2}
    assert [t.name for t in tr11 if t.preferred] == ["Tr11x2"]
    # the neighbours Tr8…Tr20 as the table gives them (pitches, preferred pitch)
    plan = {
        8: ([1.5], 1.5), 9: ([2, 1.5], 2), 10: ([2, 1.5], 2), 11: ([3, 2], 2),
        12: ([3, 2], 3), 14: ([3, 2], 3), 16: ([4, 2], 4), 18: ([4, 2], 4), 20: ([4, 2], 4),
    }  # fmt: skip
    for d, (pitches, preferred) in plan.items():
        rows = [t for t in cat.threads if t.d_mm == d]
        assert [t.pitch_mm for t in rows] == pitches, d
        assert [t.pitch_mm for t in rows if t.preferred] == [preferred], d
    # GOST 24737-81 dimensions of Tr11x2: ac = 0.25, d2 = 11 − 1 = 10, d3 = 11 − 2·1.25 = 8.5,
    # D1 = 11 − 2 = 9, D4 = 11 + 0.5 = 11.5 (the roymech row "11 | 2 | 10,000 | 11,500 |
    # 8,500 | 9,000")
    t = cat.thread("Tr11x2")
    assert (t.d2_mm, t.D4_mm, t.d3_mm, t.D1_mm) == (10.0, 11.5, 8.5, 9.0)
