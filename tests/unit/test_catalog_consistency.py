"""Issue 24, "User catalogs": every row of a catalog, shipped or a user's, is checked for
physical consistency when it is loaded, and a row that fails is refused in one line naming
the file, the row and the field (exit 2). One test of the shipped rows and one of refused
user rows per catalog kind (threads, motors, bearings), the numbers worked by hand."""

import math
from pathlib import Path

import pytest
from helpers import EXAMPLES

from advisor.cli import main
from advisor.core.errors import CatalogError, ExitCode
from catalogs.loader import BEARINGS_FILE, MOTORS_FILE, THREADS_FILE, _load_and_validate
from catalogs.threads import crest_clearance_mm, trapezoidal_profile

LINEAR = EXAMPLES / "linear_screw_actuator.toml"


@pytest.fixture(autouse=True)
def _no_cache(monkeypatch):
    monkeypatch.setenv("DRIVE_ADVISOR_NO_CACHE", "1")


def _dir(tmp_path: Path, name: str, text: str) -> Path:
    d = tmp_path / "cat"
    d.mkdir(exist_ok=True)
    (d / name).write_text(text, encoding="utf-8")
    return d


def _refusal(d: Path) -> str:
    with pytest.raises(CatalogError) as e:
        _load_and_validate(d)
    msg = str(e.value)
    assert "\n" not in msg
    return msg


# ------------------------------------------------------------------ threads
THREAD = """source = "a test plan"
[[thread]]
d_mm = {d}
series = 2
pitches_mm = {pitches}
preferred_mm = {preferred}
"""


def test_every_shipped_and_example_thread_has_a_positive_gost_24737_profile():
    # ac of GOST 24737-81: 0.15 (P 1.5), 0.25 (P 2…5), 0.5 (P 6…12), 1 (P 14…44)
    assert [crest_clearance_mm(p) for p in (1.5, 2, 5, 6, 12, 14, 44)] == [
        0.15,
        0.25,
        0.25,
        0.5,
        0.5,
        1.0,
        1.0,
    ]
    cat = _load_and_validate(EXAMPLES / "catalogs")
    assert len(cat.threads) == 98  # 95 shipped diameter–pitch pairs and 3 of the example
    for t in cat.threads:
        assert 1.5 <= t.pitch_mm <= 44 and t.pitch_mm < t.d_mm, t.name
        assert t.d3_mm == pytest.approx(t.d_mm - t.pitch_mm - 2 * t.ac_mm), t.name
        assert 0 < t.d3_mm < t.D1_mm < t.d2_mm < t.d_mm, t.name
    # the coarsest shipped thread, by hand: Tr22x8, ac = 0.5, h3 = 4.5, d3 = 22 − 9 = 13
    tr22 = next(t for t in cat.threads if t.name == "Tr22x8")
    assert (tr22.d2_mm, tr22.d3_mm, tr22.D1_mm) == (18.0, 13.0, 14.0)


def test_the_tr3x40_of_the_issue_is_refused_in_one_line(tmp_path, capsys):
    """It gave a 'feasible' design with d2 = 3 − 20 = −17 mm, d3 = 3 − 2·21 = −39 mm and an
    efficiency of 1.342."""
    d = _dir(tmp_path, THREADS_FILE, THREAD.format(d=3, pitches=[40], preferred=40))
    req = tmp_path / "r.toml"
    req.write_text(
        LINEAR.read_text(encoding="utf-8").replace('"Tr16x2"', '"Tr3x40"'), encoding="utf-8"
    )
    assert main(["--batch", str(req), "--catalog-dir", str(d)]) == ExitCode.INVALID_INPUT
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert f"catalog {d / THREADS_FILE}, row 1 (d_mm = 3): field pitches_mm = 40.0" in err
    assert "the pitch must be below the diameter d_mm = 3" in err


@pytest.mark.parametrize(
    ("d", "pitches", "field", "why"),
    [
        # P = 3 < d = 3.4 but d3 = 3.4 − 2·(1.5 + 0.25) = −0.1 mm
        (3.4, [3], "pitches_mm = 3.0", "d3 = d − 2·h3 = 3.4 − 2·1.75 = -0.1 mm"),
        # the standard's ac table ends at 44 mm and starts at 1.5 mm
        (200, [48], "pitches_mm = 48.0", "for pitches 1.5 … 44 mm"),
        (8, [1], "pitches_mm = 1.0", "for pitches 1.5 … 44 mm"),
    ],
)
def test_a_thread_outside_the_gost_profile_is_refused(tmp_path, d, pitches, field, why):
    msg = _refusal(
        _dir(tmp_path, THREADS_FILE, THREAD.format(d=d, pitches=pitches, preferred=pitches[0]))
    )
    assert THREADS_FILE in msg and f"row 1 (d_mm = {d})" in msg
    assert f"field {field}" in msg and why in msg


def test_given_pitch_and_minor_diameters_must_agree_with_the_profile(tmp_path):
    # Tr110x12 by hand: d2 = 110 − 6 = 104; ac = 0.5, h3 = 6.5, d3 = 110 − 13 = 97
    # Tr110x20: d2 = 100; ac = 1, h3 = 11, d3 = 88
    row = THREAD.format(d=110, pitches=[20, 12], preferred=12)
    good = row + "d2_mm = [100.0, 104.0]\nd3_mm = [88.0, 97.005]\n"
    cat = _load_and_validate(_dir(tmp_path, THREADS_FILE, good))
    assert trapezoidal_profile(110, 12).d3_mm == 97.0
    assert cat.thread("Tr110x12").d3_mm == 97.0  # the computed value is kept, not the given
    bad = row + "d3_mm = [88.0, 98.0]\n"
    msg = _refusal(_dir(tmp_path, THREADS_FILE, bad))
    assert "row 1 (d_mm = 110): field d3_mm = 98.0: Tr110x12 has d3 = 97 mm" in msg
    short = row + "d2_mm = [100.0]\n"
    msg = _refusal(_dir(tmp_path, THREADS_FILE, short))
    assert "field d2_mm = [100.0]: give one value per pitch (2)" in msg


# ------------------------------------------------------------------ induction motors
MOTOR = """supply_frequency_Hz = 50
[sources]
mine = "a test datasheet"
[[motor]]
model = "BIG-{power}"
poles = 4
rated_power_kW = {power}
rated_speed_rpm = 1480.0
slip_pct = 1.3
breakdown_torque_ratio = 2.5
starting_torque_ratio = 2.0
efficiency_pct = {eff}
cos_phi = 0.88
starting_current_ratio = 7.0
inertia_kgm2 = 1.2
mass_kg = 600.0
source = "mine"
"""


def test_every_shipped_and_example_motor_keeps_its_power_flow():
    # η < n/n₀: the rotor loses the slip's share of the air-gap power
    cat = _load_and_validate(EXAMPLES / "catalogs")
    for m in cat.motors:
        assert m.efficiency_pct / 100 < m.rated_speed_rpm / m.synchronous_speed_rpm, m.model
        assert 1 < m.breakdown_torque_ratio <= 5 and 0 < m.starting_torque_ratio, m.model
        assert 0 < m.rated_slip < 1 and 0 < m.cos_phi <= 1, m.model
        assert m.rated_power_kW <= 1e5, m.model
    # the row nearest the limit, by hand: the example's AIR160M2, 2940 of 3000 rpm: η = 90 %
    # against n/n₀ = 98 %, a ratio of 0.918
    m = max(
        cat.motors, key=lambda m: m.efficiency_pct * m.synchronous_speed_rpm / m.rated_speed_rpm
    )
    assert (m.model, m.efficiency_pct, m.rated_speed_rpm) == ("AIR160M2-example", 90.0, 2940.0)
    assert 0.90 / (2940 / 3000) == pytest.approx(0.918, abs=5e-4)


def test_a_stated_rated_torque_must_be_power_over_speed(tmp_path):
    # 100 kW at 1480 rpm: M = 100000 / (1480·π/30) = 645.2 N·m; 3 % is 19.4 N·m
    ok = MOTOR.format(power=100, eff=94.0) + "rated_torque_Nm = 645.0\n"
    cat = _load_and_validate(_dir(tmp_path, MOTORS_FILE, ok))
    assert any(m.model == "BIG-100" for m in cat.motors)
    assert 100000 / (1480 * math.pi / 30) == pytest.approx(645.2, abs=0.05)
    bad = MOTOR.format(power=100, eff=94.0) + "rated_torque_Nm = 700.0\n"
    msg = _refusal(_dir(tmp_path, MOTORS_FILE, bad))
    assert "row 1 (model = 'BIG-100'): field rated_torque_Nm = 700.0" in msg
    assert "is 645.2 N·m (allowed difference 3%)" in msg


def test_an_efficiency_the_slip_does_not_allow_is_refused(tmp_path):
    # n/n₀ = 1480/1500 = 98.67 %: 99 % would need the rotor to lose less than its slip share
    msg = _refusal(_dir(tmp_path, MOTORS_FILE, MOTOR.format(power=100, eff=99.0)))
    assert "field efficiency_pct = 99.0: must be below n/n₀ = 1480/1500 = 98.7%" in msg


def test_a_motor_of_1e300_kw_is_refused_as_non_physical(tmp_path, capsys):
    d = _dir(tmp_path, MOTORS_FILE, MOTOR.format(power="1e300", eff=94.0))
    assert main(["--batch", str(LINEAR), "--catalog-dir", str(d)]) == ExitCode.INVALID_INPUT
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert f"catalog {d / MOTORS_FILE}, row 1 (model = 'BIG-1e300'): field rated_power_kW" in err
    assert "above 100000 kW (100 MW)" in err


def _big_linear(tmp_path: Path, force_N: int) -> Path:
    """The linear example scaled up until only a user's large motor drives it: 1 m in 4 s,
    the thread free."""
    text = LINEAR.read_text(encoding="utf-8")
    for a, b in (
        ("force_N = 3500", f"force_N = {force_N}"),
        ("stroke_m = 0.2", "stroke_m = 1.0"),
        ("travel_time_s = 5", "travel_time_s = 4"),
        ("support_span_m = 0.4", "support_span_m = 1.2"),
        ('thread = "Tr16x2"', ""),
        ('friction_model = "paper"', ""),
    ):
        assert a in text
        text = text.replace(a, b)
    p = tmp_path / f"big{force_N}.toml"
    p.write_text(text, encoding="utf-8")
    return p


@pytest.mark.parametrize(
    ("power", "force_N", "band"),
    [
        # 100 kW lies between 90 and 110 kW of GOST 12139-84's main series
        (100, 80000, "Rated power 100 kW, with neighbours 90, 100, 110 kW."),
        # 500 kW lies above the series' last value, 400 kW: no higher neighbour
        (500, 120000, "Rated power 500 kW, with neighbours 400, 500 kW."),
    ],
)
def test_a_user_motor_off_the_power_series_gets_neighbours_from_the_catalog(
    tmp_path, capsys, power, force_N, band
):
    """It crashed when chosen: ValueError: 100.0 is not in list (exit 1)."""
    d = _dir(tmp_path, MOTORS_FILE, MOTOR.format(power=power, eff=94.0))
    out = tmp_path / "r.toml"
    rc = main(
        ["--batch", str(_big_linear(tmp_path, force_N)), "--catalog-dir", str(d), "-o", str(out)]
    )
    assert rc == ExitCode.OK, capsys.readouterr().err
    text = out.read_text(encoding="utf-8")
    assert f'model = "BIG-{power}"' in text and band in text
    cat = _load_and_validate(d)
    assert power in cat.power_series(4) and power not in cat.power_series(2)
    assert _load_and_validate(None).power_series(4) == list(cat.rated_powers_kW)


# ------------------------------------------------------------------ bearings
BEARING = """[sources]
mine = "a test row"
[[bearing]]
designation = "6211-test"
type = "deep_groove"
friction = "deep_groove_62"
d_mm = 55
D_mm = 100
B_mm = 21
contact_angle_deg = 0
C_kN = 46.2
C0_kN = 29
f0 = 14
limiting_speed_rpm = 9000
reference_speed_rpm = 14000
source = ["mine"]
"""


def test_every_shipped_and_example_bearing_is_a_possible_bearing():
    cat = _load_and_validate(EXAMPLES / "catalogs")
    for b in cat.bearings:
        assert 0 < b.d_mm < b.pitch_diameter_mm < b.D_mm and b.B_mm > 0, b.designation
        assert b.C_kN > 0 and b.C0_kN > 0 and b.limiting_speed_rpm > 0, b.designation
        assert b.Pu_kN is None or b.Pu_kN < b.C0_kN, b.designation
        if b.mass_kg is not None:
            solid = 7850 * math.pi / 4 * (b.D_mm**2 - b.d_mm**2) * b.B_mm * 1e-9
            assert b.mass_kg < solid, b.designation
    # by hand, 6200 (10×30×9 mm, 0.032 kg): solid ring 7850·π/4·(30² − 10²)·9e-9 = 0.0444 kg
    assert 7850 * math.pi / 4 * (30**2 - 10**2) * 9e-9 == pytest.approx(0.0444, abs=1e-4)
    assert cat.bearing("6200").mass_kg < 0.0444


@pytest.mark.parametrize(
    ("change", "field"),
    [
        (("D_mm = 100", "D_mm = 50"), "D_mm = 50"),  # below the bore
        (("C_kN = 46.2", "C_kN = -46.2"), "field C_kN = -46.2"),
        (("C0_kN = 29", "C0_kN = 0"), "field C0_kN = 0"),
        (("B_mm = 21", "B_mm = 0"), "field B_mm = 0"),
        (("limiting_speed_rpm = 9000", "limiting_speed_rpm = -1"), "limiting_speed_rpm = -1"),
        (("reference_speed_rpm = 14000", "reference_speed_rpm = 0"), "reference_speed_rpm = 0"),
        # the fatigue load limit is a small share of C0 (SKF: 6211 has Pu = 1.43 kN)
        (("source = [", "Pu_kN = 30\nsource = ["), "field Pu_kN = 30.0: the fatigue load limit"),
        # 55×100×21 mm: a solid steel ring weighs 7850·π/4·(100² − 55²)·21e-9 = 0.90 kg
        (("source = [", "mass_kg = 1.5\nsource = ["), "field mass_kg = 1.5: heavier than a solid"),
    ],
)
def test_an_impossible_bearing_is_refused(tmp_path, change, field):
    assert 7850 * math.pi / 4 * (100**2 - 55**2) * 21e-9 == pytest.approx(0.90, abs=0.005)
    text = BEARING.replace(*change)
    assert text != BEARING
    msg = _refusal(_dir(tmp_path, BEARINGS_FILE, text))
    assert BEARINGS_FILE in msg and "row 1 (designation = '6211-test')" in msg and field in msg


def test_the_bearing_row_without_a_flaw_loads(tmp_path):
    cat = _load_and_validate(_dir(tmp_path, BEARINGS_FILE, BEARING.replace("6211-test", "X1")))
    assert cat.bearing("X1").C_kN == 46.2


# ------------------------------------------------------------------ physical bounds of a row
BLDC = """[sources]
acme = "ACME frameless kit datasheet"
[[motor]]
name = "ACME-K40"
continuous_torque_Nm = 1.0
peak_torque_Nm = 3.0
rated_speed_rpm = 6000
phase_resistance_ohm = 0.5
torque_constant_Nm_A = 0.1
rotor_inertia_kgm2 = 2e-5
mass_kg = 0.3
outer_diameter_mm = 40
length_mm = 60
thermal_time_constant_s = 400
pole_pairs = 4
source = "acme"
"""


@pytest.mark.parametrize(
    ("name", "text", "change", "said"),
    [
        # GOST 24738-81 ends at Tr640: 1e300 overflowed the profile (OverflowError, exit 1)
        (
            THREADS_FILE,
            THREAD.format(d=20, pitches=[4], preferred=4),
            ("20", "1e300"),
            "field d_mm = 1e+300: must be ≤ 640",
        ),
        # the largest bearing of a catalog is about 2 m across
        (
            BEARINGS_FILE,
            BEARING,
            ("D_mm = 100", "D_mm = 1e300"),
            "field D_mm = 1e+300: must be ≤ 2000",
        ),
        # a denormal torque made the motor's current T/k_T overflow
        (
            "bldc_motors.toml",
            BLDC,
            ("continuous_torque_Nm = 1.0", "continuous_torque_Nm = 1e-300"),
            "field continuous_torque_Nm = 1e-300: must be ≥ 0.0001",
        ),
        (
            "bldc_motors.toml",
            BLDC,
            ("rated_speed_rpm = 6000", "rated_speed_rpm = 1e-300"),
            "field rated_speed_rpm = 1e-300: must be ≥ 1",
        ),
        (
            "bldc_motors.toml",
            BLDC,
            ("torque_constant_Nm_A = 0.1", "torque_constant_Nm_A = 1e-300"),
            "field torque_constant_Nm_A = 1e-300: must be ≥ 0.0001",
        ),
        (
            "bldc_motors.toml",
            BLDC,
            ("phase_resistance_ohm = 0.5", "phase_resistance_ohm = 5e-324"),
            "field phase_resistance_ohm = 5e-324: must be ≥ 1e-05",
        ),
    ],
)
def test_a_field_beyond_its_physical_range_is_refused_naming_file_row_field(
    tmp_path, capsys, name, text, change, said
):
    bad = text.replace(*change, 1)
    assert bad != text
    d = _dir(tmp_path, name, bad)
    msg = _refusal(d)
    assert name in msg and "row 1 (" in msg and said in msg, msg
    # through the CLI: exit 2, one line, and the file is called a catalog
    req = tmp_path / "r.toml"
    req.write_text(LINEAR.read_text(encoding="utf-8"), encoding="utf-8")
    assert main(["--batch", str(req), "--catalog-dir", str(d)]) == ExitCode.INVALID_INPUT
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and said in err and "requirement file" not in err


@pytest.mark.parametrize("value", ['"5 kN"', "[]", "{}", "true", "1e300", "0"])
def test_a_motor_catalogs_supply_frequency_must_be_a_number_in_range(tmp_path, value):
    text = MOTOR.format(power=500, eff=95.0).replace(
        "supply_frequency_Hz = 50", f"supply_frequency_Hz = {value}"
    )
    msg = _refusal(_dir(tmp_path, MOTORS_FILE, text))
    assert MOTORS_FILE in msg and "supply_frequency_Hz = " in msg
    if value.startswith('"'):  # text where a number belongs: catalogs take no unit strings
        assert "catalogs take plain SI numbers" in msg and "no unit strings" in msg
    else:
        assert "must be a number 1 … 1000 Hz" in msg


def test_a_file_level_source_must_be_text(tmp_path):
    text = THREAD.format(d=20, pitches=[4], preferred=4).replace(
        'source = "a test plan"', "source = [1, 2]"
    )
    assert "source = [1, 2]: must be a string" in _refusal(_dir(tmp_path, THREADS_FILE, text))


def test_a_fifo_given_as_a_catalog_is_called_a_catalog(tmp_path):
    import os

    d = tmp_path / "cat"
    d.mkdir()
    os.mkfifo(d / THREADS_FILE)
    msg = _refusal(d)
    assert "give a catalog file (.toml)" in msg and "requirement" not in msg
