"""The bad-input corpus: every file in tests/bad_inputs/ with the exit code and the words of
the message expected for it (tests/bad_inputs/expected.txt)."""

import tomllib
from pathlib import Path

import pytest

from advisor.cli import main

HERE = Path(__file__).parent / "bad_inputs"
EXPECTED = tomllib.loads((HERE / "expected.txt").read_text(encoding="utf-8"))


def test_corpus_is_complete():
    files = {p.stem for p in HERE.glob("*.toml")}
    assert files == set(EXPECTED)
    assert len(files) >= 40
    assert sum(e["exit"] == 3 for e in EXPECTED.values()) >= 6


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_bad_input(name, capsys):
    exp = EXPECTED[name]
    rc = main(["--batch", str(HERE / f"{name}.toml")])
    err = capsys.readouterr().err
    assert rc == exp["exit"], err
    assert "Traceback" not in err and "internal error" not in err
    for word in exp["words"]:
        assert word in err, f"{word!r} not in {err!r}"
