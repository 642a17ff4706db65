"""Reports are written atomically: a failure never leaves a half-written or lost file."""

import os

import pytest

from advisor import io_safety
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
        "from advisor import io_safety as io\n"
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
