"""The shipped catalogs' snapshot (catalogs/validated.py): what validating the files gives,
used on a first run (no cache) only while its stamp matches the files and the code."""

import os
import subprocess
import sys

from catalogs import loader

FILES = [loader.HERE / f for f in loader.SHIPPED_FILES]


def test_the_committed_snapshot_is_the_validated_catalogs():
    committed = (loader.HERE / f"{loader.SNAPSHOT_MODULE}.py").read_text(encoding="utf-8")
    assert committed == loader.snapshot_text(), (
        "the catalogs or their code changed: run python -m catalogs.loader"
    )


def test_the_snapshot_gives_the_validated_catalogs():
    assert loader.shipped_snapshot(FILES) == loader._load_and_validate(None)


def test_a_stale_snapshot_is_not_used(monkeypatch):
    from catalogs import validated

    monkeypatch.setattr(validated, "STAMP", validated.STAMP ^ 1)
    assert loader.shipped_snapshot(FILES) is None


def test_a_first_run_without_a_cache_imports_no_pydantic(tmp_path):
    code = (
        "import sys\n"
        "from advisor.cli import main\n"
        "main(['--batch', sys.argv[1], '-o', sys.argv[2]])\n"
        "print('pydantic.main' in sys.modules)\n"
    )
    example = loader.HERE.parent / "examples" / "rudder_actuator.toml"
    env = {**os.environ, "XDG_CACHE_HOME": str(tmp_path / "empty")}
    env.pop("DRIVE_ADVISOR_NO_CACHE", None)
    out = subprocess.run(
        [sys.executable, "-c", code, str(example), str(tmp_path / "r.toml")],
        capture_output=True,
        text=True,
        env=env,
        check=True,
    ).stdout
    assert out.splitlines()[-1] == "False"
    assert list((tmp_path / "empty" / "drive-advisor").glob("catalogs-*.marshal"))
