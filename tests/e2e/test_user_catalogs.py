"""The documented user catalogs (examples/catalogs/, one file per kind a --catalog-dir
takes) load through the same validation as the shipped ones, and their rows are used."""

from helpers import EXAMPLES

from advisor.cli import main
from catalogs import loader
from catalogs.loader import _load_and_validate

USER = EXAMPLES / "catalogs"


def test_there_is_one_example_per_catalog_kind_a_user_can_give():
    kinds = {
        loader.THREADS_FILE,
        loader.MOTORS_FILE,
        loader.MATERIALS_FILE,
        loader.STEELS_FILE,
        loader.BEARINGS_FILE,
    }
    assert {p.name for p in USER.glob("*.toml")} == kinds


def test_the_examples_load_and_their_rows_are_there():
    shipped = _load_and_validate(None)
    cat = _load_and_validate(USER)
    assert len(cat.motors) == len(shipped.motors) + 1
    assert any(m.model == "AIR160M2-example" and m.rated_power_kW == 18.5 for m in cat.motors)
    assert [t.name for t in cat.threads if t.d_mm == 110] == ["Tr110x20", "Tr110x12", "Tr110x4"]
    assert cat.thread("Tr110x12").preferred
    assert cat.electrical_steel("2212", 0.5) is not None
    b = cat.bearing("6211")
    assert (b.d_mm, b.D_mm, b.B_mm, b.friction) == (55, 100, 21, "deep_groove_62")
    assert "ball_count" in b.estimated  # left out of the row: estimated by the loader
    # the materials file replaces the shipped one: the company's 8 MPa for bronze nuts
    assert cat.pair("steel_bronze").allowable_pressure_MPa == 8.0
    assert shipped.pair("steel_bronze").allowable_pressure_MPa == 10.0


def test_a_report_with_the_example_catalogs(tmp_path, capsys, monkeypatch):
    monkeypatch.setenv("DRIVE_ADVISOR_NO_CACHE", "1")
    out = tmp_path / "r.toml"
    src = EXAMPLES / "linear_screw_actuator.toml"
    assert main(["--batch", str(src), "--catalog-dir", str(USER), "-o", str(out)]) == 0
    text = out.read_text(encoding="utf-8")
    # 3500 N on Tr16x2 at 8 MPa: the nut grows to keep the flank pressure within the rule
    assert 'id = "nut_pressure"' in text and "limit = 8.0" in text


def test_a_materials_file_missing_a_pair_is_refused(tmp_path, capsys, monkeypatch):
    """It replaces the shipped file: a requirement naming the missing pair would find none."""
    monkeypatch.setenv("DRIVE_ADVISOR_NO_CACHE", "1")
    text = (USER / "screw_materials.toml").read_text(encoding="utf-8")
    start = text.index('[[pair]]\nname = "steel_steel"')
    end = text.index("[[", start + 2)
    (tmp_path / "screw_materials.toml").write_text(text[:start] + text[end:], encoding="utf-8")
    src = EXAMPLES / "linear_screw_actuator.toml"
    assert main(["--batch", str(src), "--catalog-dir", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert "[[pair]] 'steel_steel' missing; a user materials file replaces the shipped one" in err


def test_a_user_motor_of_the_same_power_and_poles_as_a_catalog_motor(tmp_path, capsys, monkeypatch):
    """A user 0.75 kW 4-pole motor beside the shipped 4A71B4 (same rating, a stronger start
    and breakdown) used to trip an internal assertion (exit 1): the motor line was keyed by
    rated power, so one of the two was dropped. Either may be chosen; the run must succeed
    and the report's motor must be one of them."""
    monkeypatch.setenv("DRIVE_ADVISOR_NO_CACHE", "1")
    (tmp_path / "induction_4a.toml").write_text(
        """supply_frequency_Hz = 50
[sources]
own = "a user's datasheet (test)"
[[motor]]
model = "USER-0.75-4"
poles = 4
rated_power_kW = 0.75
rated_speed_rpm = 1400.0
slip_pct = 6.7
breakdown_torque_ratio = 2.4
starting_torque_ratio = 2.2
efficiency_pct = 75.0
cos_phi = 0.75
starting_current_ratio = 5.0
inertia_kgm2 = 0.0015
mass_kg = 14.0
source = "own"
estimated = []
""",
        encoding="utf-8",
    )
    out = tmp_path / "r.toml"
    src = EXAMPLES / "linear_screw_actuator.toml"
    assert main(["--batch", str(src), "--catalog-dir", str(tmp_path), "-o", str(out)]) == 0
    text = out.read_text(encoding="utf-8")
    assert 'model = "USER-0.75-4"' in text or 'model = "4A71B4"' in text
