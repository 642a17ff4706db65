"""Reports are written atomically: a failure never leaves a half-written or lost file."""

import math
import os

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from advisor.core import io_safety
from advisor.core import report as rp


def test_write_atomic_replaces(tmp_path):
    target = tmp_path / "r.toml"
    rp.write_atomic(target, "a = 1\n")
    rp.write_atomic(target, "a = 2\n")
    assert target.read_text() == "a = 2\n"
    assert list(tmp_path.iterdir()) == [target]


@pytest.mark.parametrize("where", ["write", "fsync", "replace"])
def test_failure_midway_keeps_the_old_file(tmp_path, monkeypatch, where):
    target = tmp_path / "r.toml"
    target.write_text("old = true\n")

    def boom(*a, **k):
        raise OSError(28, "No space left on device")

    if where == "replace":
        monkeypatch.setattr(io_safety.os, "replace", boom)
    elif where == "fsync":
        monkeypatch.setattr(io_safety.os, "fsync", boom)
    else:
        real_write = os.write

        def half(fd, data):  # half the report reaches the disk, then the disk is full
            real_write(fd, bytes(data[: len(data) // 2]))
            raise OSError(28, "No space left on device")

        monkeypatch.setattr(io_safety.os, "write", half)
    with pytest.raises(OSError):
        rp.write_atomic(target, "new = true\n" * 1000)
    assert target.read_text() == "old = true\n"
    assert list(tmp_path.iterdir()) == [target]


def test_round_sig():
    assert rp.round_sig(5.0848496) == 5.08485
    assert rp.round_sig(0.0) == 0.0
    assert rp.round_sig(-1234567.0) == -1234570.0


def test_killed_writer_leaves_the_old_file_and_no_one_deletes_its_temp(tmp_path):
    """A writer killed outright cannot remove its temporary file. The next writer does not
    delete it either: it cannot know the file is not another writer's, in mid-write."""
    import signal
    import subprocess
    import sys

    target = tmp_path / "r.toml"
    target.write_text("old = true\n")
    child = (
        "import os, time, sys\n"
        "from advisor.core import io_safety as io\n"
        "real = os.fsync\n"
        "def slow(fd):\n"
        "    real(fd); print('written', flush=True); time.sleep(60)\n"
        "io.os.fsync = slow\n"
        f"io.write_atomic({str(target)!r}, 'new = true\\n' * 100000)\n"
    )
    proc = subprocess.Popen([sys.executable, "-c", child], stdout=subprocess.PIPE, text=True)
    assert proc.stdout.readline().strip() == "written"  # the temp file is full, not renamed
    proc.send_signal(signal.SIGKILL)
    proc.wait(timeout=10)
    assert target.read_text() == "old = true\n"
    leftovers = [p for p in tmp_path.iterdir() if p != target]
    assert len(leftovers) == 1 and leftovers[0].name.startswith(".r.toml.")
    rp.write_atomic(target, "next = true\n")
    assert target.read_text() == "next = true\n"
    assert sorted(tmp_path.iterdir()) == sorted([target, leftovers[0]])


# ------------------------------------------------------------------ TOML text (issue 16)
def _examples():
    from helpers import EXAMPLES

    return sorted(EXAMPLES.glob("*.toml"))


@pytest.mark.parametrize("example", _examples(), ids=lambda p: p.name)
def test_toml_text_writes_what_tomli_w_writes_for_every_example(example):
    """The report's own writer against tomli-w, byte for byte, on each example's report."""
    import tomli_w

    from advisor.core.engine import advise
    from advisor.core.reading import read_requirements

    plain = rp.archive(rp.plain_data(advise(read_requirements(example))))
    assert rp.to_toml(advise(read_requirements(example))) == tomli_w.dumps(plain)


_KEYS = st.text(alphabet=st.sampled_from('ab_-Z9 ."\\\x01é\t'), max_size=6)
_SCALARS = (
    st.booleans()
    | st.integers(-(10**12), 10**12)
    | st.floats(allow_nan=False)
    | st.text(alphabet=st.characters(codec="utf-8", exclude_categories=("Cs",)), max_size=30)
)
_VALUES = st.recursive(
    _SCALARS,
    lambda inner: st.lists(inner, max_size=4) | st.dictionaries(_KEYS, inner, max_size=4),
    max_leaves=25,
)


@settings(max_examples=300, deadline=None)
@given(st.dictionaries(_KEYS, _VALUES, max_size=6))
def test_toml_text_writes_what_tomli_w_writes(doc):
    """Any plain document: tables, arrays of tables (inline when they fit on 100 characters,
    else [[...]]), nested arrays, quoted keys, escapes, long and short floats."""
    import tomli_w

    from advisor.core import toml_text

    assert toml_text.dumps(doc) == tomli_w.dumps(doc)


_FINITE = st.floats(allow_nan=False, allow_infinity=False)
_CURVES = st.lists(_FINITE | st.integers(-1000, 1000), min_size=8, max_size=30) | st.lists(
    _FINITE, min_size=10, max_size=40
)
_DESIGN = st.recursive(
    st.booleans() | st.integers(-(10**12), 10**12) | _FINITE | st.text(max_size=12) | _CURVES,
    lambda inner: st.lists(inner, max_size=3) | st.dictionaries(_KEYS, inner, max_size=5),
    max_leaves=30,
)


@settings(max_examples=300, deadline=None)
@given(st.dictionaries(st.sampled_from(["design", "designs", "checks", "x"]), _DESIGN))
def test_the_report_writer_writes_what_tomli_w_writes_of_the_rounded_archive(doc):
    """Nested data with curves (number arrays of 10 points or more, some of ints) as to_toml
    writes it: plain data unrounded, its curves lifted, floats rounded as they are written —
    against tomli-w writing the archive of the rounded data."""
    import tomli_w

    from advisor.core import toml_text

    archived = rp.archive(rp.plain_data(doc, rounded=False), none_dropped=True)
    try:
        expected = tomli_w.dumps(rp.archive(rp.plain_data(doc)))
    except TypeError:  # an array item that was all curve data leaves a None: refused by both
        with pytest.raises(TypeError):
            toml_text.dumps(archived, rp.ROUNDED_FLOATS)
        return
    assert toml_text.dumps(archived, rp.ROUNDED_FLOATS) == expected


def test_a_nan_or_an_inf_is_never_written_and_its_key_is_named():
    # issue 13: a denormal span once gave margin = inf in a report
    from advisor.core.report import NonFiniteValue, ReportTable

    class Inner(ReportTable):
        margin: float

    class Outer(ReportTable):
        checks: list[Inner]

    good = Outer.make(checks=[Inner.make(margin=1.5)])
    assert "margin = 1.5" in rp.to_toml(good)
    for bad in (math.inf, -math.inf, math.nan):
        with pytest.raises(NonFiniteValue, match=r"checks\[1\]\.margin is"):
            rp.to_toml(Outer.make(checks=[Inner.make(margin=1.0), Inner.make(margin=bad)]))


def test_a_check_of_an_unloaded_part_is_left_out_not_written_as_inf():
    """A check value ≤ 0 against an upper limit gives margin = inf (calc/sizing._upper): the
    part carries nothing, so there is nothing to check, and the report keeps the others."""
    from advisor.calc.checks import Check
    from advisor.core.cite import note
    from advisor.core.engine import finite_checks

    loaded = Check("loaded", "loaded part", 2.0, 4.0, "N", 2.0, note("hand"))
    idle = Check("idle", "unloaded part", 0.0, 4.0, "N", math.inf, note("hand"))
    assert finite_checks([loaded, idle]) == [loaded]
