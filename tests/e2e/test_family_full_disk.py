"""``advisor family`` when its results cannot be written (a full disk, a read-only folder):
exit 2 and one line naming the file that could not be written (exit-codes.md: a full disk is
exit 2, not a bug), and a DIR the run created itself, with nothing in it yet, removed
(family.md). The chunks written before the failure stay, for a resume."""

import errno
import os
from pathlib import Path

import pytest
from helpers import EXAMPLES

from advisor.cli import main
from advisor.family import study

LINEAR = (EXAMPLES / "linear_screw_actuator.toml").read_text(encoding="utf-8")
FULL = OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))  # "No space left on device"
READ_ONLY = OSError(errno.EROFS, os.strerror(errno.EROFS))


def _study(tmp_path: Path, *extra: str) -> tuple[Path, list[str]]:
    """Four variants in two chunks of two, in this process."""
    fam = tmp_path / "f.toml"
    fam.write_text(
        "[family]\nname = 'x'\n[family.axes]\n'linear.travel_time_s' = [4, 5, 6, 7]\n\n" + LINEAR,
        encoding="utf-8",
    )
    out = tmp_path / "new" / "out"
    argv = ["family", str(fam), "--out", str(out), "--workers", "1", "--chunk-size", "2"]
    return out, [*argv, "--quiet", *extra]


def _one_line(capsys) -> str:
    err = capsys.readouterr().err
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert "internal error" not in lines[0] and "report it" not in lines[0]
    return lines[0]


def _failing_write(monkeypatch, exc: OSError, fails, module=study, name="write_atomic") -> None:
    """``module.name`` raising ``exc`` for the paths ``fails(path)`` picks."""
    real = getattr(module, name)

    def write(path, text):
        if fails(Path(path)):
            raise exc
        return real(path, text)

    monkeypatch.setattr(module, name, write)


@pytest.mark.parametrize("exc", [FULL, READ_ONLY], ids=["full", "read-only"])
def test_a_manifest_that_cannot_be_written_is_exit_2_and_leaves_no_folder(
    tmp_path, capsys, monkeypatch, exc
):
    out, argv = _study(tmp_path)
    _failing_write(monkeypatch, exc, lambda p: p.name == study.MANIFEST)
    assert main(argv) == 2
    line = _one_line(capsys)
    assert f"{out / 'chunks' / study.MANIFEST}: cannot write ({exc.strerror})" in line
    assert "nothing was written" in line
    assert not (tmp_path / "new").exists()  # both folders it created, removed


def test_a_first_chunk_on_a_full_disk_is_exit_2_and_leaves_no_folder(tmp_path, capsys, monkeypatch):
    out, argv = _study(tmp_path)
    _failing_write(monkeypatch, FULL, lambda p: p.suffix == ".csv")
    assert main(argv) == 2
    line = _one_line(capsys)
    assert f"{out / 'chunks' / 'c000000.csv'}: cannot write (No space left on device)" in line
    # no chunk to keep (the folder is removed): the words say so, not "kept … to resume"
    assert line.endswith("; nothing was written: free space and run the same command again")
    assert "kept" not in line and "resume" not in line
    assert not (tmp_path / "new").exists()  # the manifest alone resumes nothing


def test_a_report_on_a_full_disk_is_exit_2_and_leaves_no_folder(tmp_path, capsys, monkeypatch):
    out, argv = _study(tmp_path, "--reports")
    _failing_write(monkeypatch, FULL, lambda p: True, name="write_replace")
    assert main(argv) == 2
    line = _one_line(capsys)
    assert f"{out / 'reports'}" in line and "cannot write (No space left on device)" in line
    assert "nothing was written" in line and "kept" not in line
    assert not (tmp_path / "new").exists()


def test_a_second_chunk_on_a_full_disk_keeps_the_first_for_a_resume(tmp_path, capsys, monkeypatch):
    out, argv = _study(tmp_path)
    _failing_write(monkeypatch, FULL, lambda p: p.name == "c000001.csv")
    assert main(argv) == 2
    line = _one_line(capsys)
    assert "c000001.csv: cannot write (No space left on device)" in line
    assert "run the same command again to resume" in line
    assert sorted(p.name for p in (out / "chunks").iterdir()) == ["c000000.csv", study.MANIFEST]
    monkeypatch.undo()  # space freed: the same command resumes and completes
    assert main(argv) == 0
    assert "1 of 2 chunks computed" in capsys.readouterr().out


def test_a_summary_on_a_full_disk_is_exit_2_and_keeps_the_chunks(tmp_path, capsys, monkeypatch):
    from advisor.family import adapter

    out, argv = _study(tmp_path)
    _failing_write(monkeypatch, FULL, lambda p: p.name == "summary.toml", module=adapter)
    assert main(argv) == 2
    line = _one_line(capsys)
    assert f"{out / 'summary.toml'}: cannot write (No space left on device)" in line
    assert len(list((out / "chunks").glob("c*.csv"))) == 2


def test_a_full_disk_in_an_existing_folder_keeps_the_folder(tmp_path, capsys, monkeypatch):
    out, argv = _study(tmp_path)
    out.mkdir(parents=True)
    (out / "mine.txt").write_text("the user's", encoding="utf-8")
    _failing_write(monkeypatch, FULL, lambda p: p.name == study.MANIFEST)
    assert main(argv) == 2
    _one_line(capsys)
    assert (out / "mine.txt").read_text(encoding="utf-8") == "the user's"
