"""A unit string in a user catalog ("125 kg") is refused in one line that names the file, the
row, the field and the value, and says that catalogs take plain SI numbers (a requirement
file converts unit strings; a catalog does not), with the number to write where it can be
read."""

import pytest
from helpers import EXAMPLES

from advisor.cli import main

USER = EXAMPLES / "catalogs"


@pytest.mark.parametrize(
    ("name", "old", "new", "said"),
    [
        (
            "induction_4a.toml",
            "mass_kg = 125.0",
            'mass_kg = "125 kg"',
            "row 1 (model = 'AIR160M2-example'): field mass_kg = '125 kg': "
            "catalogs take plain SI numbers in the unit the key names, no unit strings "
            "(write mass_kg = 125)",
        ),
        (
            "induction_4a.toml",
            "mass_kg = 125.0",
            'mass_kg = 125.0\nrated_torque_Nm = "60.1 N*m"',
            "field rated_torque_Nm = '60.1 N*m': catalogs take plain SI numbers in the unit "
            "the key names, no unit strings (write rated_torque_Nm = 60.1)",
        ),
        (
            "induction_4a.toml",
            "rated_power_kW = 18.5",
            'rated_power_kW = "18.5 kW"',
            "field rated_power_kW = '18.5 kW': catalogs take plain SI numbers in the unit the "
            "key names, no unit strings (e.g. rated_power_kW = 1.2)",
        ),
        (
            "induction_4a.toml",
            "poles = 2 ",
            'poles = "2" ',
            "field poles = '2': catalogs take plain SI numbers",
        ),
        (
            "induction_4a.toml",
            "supply_frequency_Hz = 50",
            'supply_frequency_Hz = "50 Hz"',
            "supply_frequency_Hz = '50 Hz': catalogs take plain SI numbers in the unit the key "
            "names, no unit strings (write supply_frequency_Hz = 50)",
        ),
        (
            "gost_24738_81_trapezoidal.toml",
            "pitches_mm = [20, 12, 4]",
            'pitches_mm = [20, "12 mm", 4]',
            "row 1 (d_mm = 110): field pitches_mm.1 = '12 mm': catalogs take plain SI numbers "
            "in the unit the key names, no unit strings (write 12)",
        ),
        (
            "skf_bearings.toml",
            "d_mm = 55",
            'd_mm = "5.5 cm"',
            "row 1 (designation = '6211'): field d_mm = '5.5 cm': catalogs take plain SI "
            "numbers in the unit the key names, no unit strings (write d_mm = 55)",
        ),
    ],
)
def test_a_unit_string_in_a_catalog_is_refused_in_one_line_saying_catalogs_take_numbers(
    name, old, new, said, tmp_path, capsys, monkeypatch
):
    monkeypatch.setenv("DRIVE_ADVISOR_NO_CACHE", "1")
    text = (USER / name).read_text(encoding="utf-8")
    assert old in text
    catalog = tmp_path / name
    catalog.write_text(text.replace(old, new, 1), encoding="utf-8")
    src = EXAMPLES / "linear_screw_actuator.toml"
    assert main(["--batch", str(src), "--catalog-dir", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert err.startswith(f"advisor: catalog {catalog}")
    assert said in err
