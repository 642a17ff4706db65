"""The bad-input corpus: every file in tests/bad_inputs/ with the exit code and the words of
the message expected for it (tests/bad_inputs/expected.txt). Every file ends in exit 2 or 3
with at most 6 lines of at most 300 characters on stderr, no traceback."""

import tomllib
from pathlib import Path

import pytest

from advisor.cli import main

HERE = Path(__file__).parents[1] / "bad_inputs"
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
    assert rc in (2, 3)
    assert "Traceback" not in err and "internal error" not in err
    lines = err.splitlines()
    assert 1 <= len(lines) <= 6, err  # a few lines, whatever the file holds
    assert all(len(line) <= 300 for line in lines), max(map(len, lines))
    assert "\x1b" not in err  # control characters are shown escaped, never sent
    for word in exp["words"]:
        assert word in err, f"{word!r} not in {err!r}"
