"""Issue 13: never crash, never destroy, never hang. Every fault of the issue (other than the
numeric ranges and the calculation crashes, covered with each application) has a test here;
the bad files themselves are in tests/bad_inputs/."""

import io
import os
import shutil
import signal
import stat
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest
from helpers import EXAMPLES, ROOT, seed001_requirement

from advisor import many
from advisor.cli import main
from advisor.core import io_safety
from advisor.core.errors import ExitCode, InputError

LINEAR = EXAMPLES / "linear_screw_actuator.toml"
ROTARY = EXAMPLES / "rudder_actuator.toml"


def _lines(err: str) -> list[str]:
    return err.strip().splitlines()


def _linear(tmp_path: Path, name: str = "r.toml", title: str | None = None) -> Path:
    """A copy of the linear example, with a title when given (TOML basic string escapes)."""
    text = LINEAR.read_text(encoding="utf-8")
    if title is not None:
        import tomli_w

        doc = tomllib.loads(text)
        doc["application"]["title"] = title
        text = tomli_w.dumps(doc)
    p = tmp_path / name
    p.parent.mkdir(parents=True, exist_ok=True)
    p.write_text(text, encoding="utf-8")
    return p


def _run(*args: str, **kw) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "advisor", *args], capture_output=True, text=True, **kw
    )


# ------------------------------------------------------------------ deep nesting
def test_deep_nesting_is_one_line_also_when_the_wizard_opens_it(tmp_path, capsys):
    deep = tmp_path / "deep.toml"
    deep.write_text('[application]\nkind = "linear"\nx = ' + "[" * 5000 + "]" * 5000 + "\n")
    assert main([str(deep)]) == ExitCode.INVALID_INPUT  # the wizard, before any screen
    err = capsys.readouterr().err
    assert _lines(err) == [f"advisor: {deep}: " + err.split(f"{deep}: ", 1)[1].strip()]
    assert "nested more than 32 levels deep" in err and "Traceback" not in err


def test_depth_is_counted_without_recursion():
    doc: list = []
    node = doc
    for _ in range(100_000):  # far past the interpreter's recursion limit
        node.append([])
        node = node[0]
    assert io_safety.depth(doc) == io_safety.MAX_DEPTH + 1  # stops as soon as it is too deep
    assert io_safety.depth({"a": {"b": [1, {"c": 2}]}}) == 4
    assert io_safety.depth(5) == 0


# ------------------------------------------------------------------ user text is data
HOSTILE = "[/] [motor] [bold red]x \x1b[2J\x1b[H end"
SHOWN = "[/] [motor] [bold red]x \\x1b[2J\\x1b[H end"


def test_summary_shows_a_hostile_title_and_path_literally(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)  # a short relative path: the summary does not wrap it
    src = _linear(tmp_path, title=HOSTILE)
    out = Path("o[/]ut [red]") / "r[/].toml"  # "/" splits the path: "o[", "]ut [red]"…
    out.parent.mkdir(parents=True)
    assert main(["--batch", str(src), "-o", str(out)]) == ExitCode.OK
    printed = capsys.readouterr()
    assert SHOWN in printed.out
    assert "o[/]ut [red]" in printed.out and "r[/].toml" in printed.out
    assert "\x1b" not in printed.out and "Traceback" not in printed.err
    assert tomllib.loads(out.read_text())["report"]["title"] == HOSTILE  # the data is kept


def test_summary_shows_names_and_messages_literally(tmp_path, monkeypatch, capsys):
    """Motor and bearing names reach the summary through the headline; table names like
    [one_way] through the warnings: none is read as markup."""
    from advisor.core import registry

    monkeypatch.setattr(registry, "headline", lambda report: "motor [/]M1 [b]x, bearing 7000 [/i]")
    doc = seed001_requirement()
    doc["one_way"] = {"type": "worm"}  # ignored (hold_without_power = false): a warning
    import tomli_w

    src = tmp_path / "r.toml"
    src.write_text(tomli_w.dumps(doc))
    # the linear summary does not use the headline: use the rotary example for that row
    rot = tmp_path / "rot.toml"
    shutil.copy(ROTARY, rot)
    assert main(["--batch", str(rot), "-o", str(tmp_path / "rot.report.toml")]) == 0
    assert "motor [/]M1 [b]x, bearing 7000 [/i]" in capsys.readouterr().out
    assert main(["--batch", str(src), "-o", str(tmp_path / "r.report.toml")]) == 0
    printed = capsys.readouterr()
    assert "the [one_way] table" in printed.out  # the table name does not vanish


def test_many_file_summary_survives_a_hostile_title_and_out_dir(tmp_path, capsys):
    d = tmp_path / "in"
    for i in range(3):
        _linear(d, f"r{i}.toml")
    _linear(d, "bad[b].toml", title=HOSTILE)
    (d / "broken[/i].toml".replace("/", "")).write_text("[application\n")
    out = tmp_path / "out [/]"
    rc = main(["--batch", str(d), "--out-dir", str(out)])
    printed = capsys.readouterr()
    assert rc == ExitCode.INVALID_INPUT
    assert "bad[b].toml" in printed.out and "broken[i].toml" in printed.out
    assert "out [/]" in printed.out and "4 designs, 0 infeasible, 1 invalid" in printed.out
    assert "Traceback" not in printed.err


def test_printable_escapes_controls_and_bidi_overrides():
    assert io_safety.printable("a\x1b[2Jb\u202e\x07") == "a\\x1b[2Jb\\u202e\\x07"
    assert io_safety.printable("Ø16 · N·m — ok") == "Ø16 · N·m — ok"


def test_messages_never_send_control_characters(tmp_path, capsys):
    bad = tmp_path / "bad\x1b[2J.toml"
    bad.write_text("[application\n")
    assert main(["--batch", str(bad)]) == ExitCode.INVALID_INPUT
    err = capsys.readouterr().err
    assert "\x1b" not in err and "bad\\x1b[2J.toml" in err


# ------------------------------------------------------------------ never destroy a file
def test_output_onto_the_input_is_refused(tmp_path, capsys):
    src = _linear(tmp_path)
    before = src.read_bytes()
    link = tmp_path / "link.toml"
    link.symlink_to(src)
    for target in (src, link):
        assert main(["--batch", str(src), "-o", str(target)]) == ExitCode.INVALID_INPUT
        assert "is the requirement file itself" in capsys.readouterr().err
    assert src.read_bytes() == before and link.is_symlink()


def test_output_onto_a_fifo_or_directory_is_refused(tmp_path, capsys):
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    assert main(["--batch", str(LINEAR), "-o", str(fifo)]) == ExitCode.INVALID_INPUT
    assert "exists and is a FIFO" in capsys.readouterr().err
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)
    assert main(["--batch", str(LINEAR), "-o", str(tmp_path)]) == ExitCode.INVALID_INPUT
    assert "exists and is a directory" in capsys.readouterr().err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fifo"]


def test_a_device_target_is_refused_before_anything_is_written():
    with pytest.raises(io_safety.OutputError, match="exists and is a device"):
        io_safety.check_target(Path(os.devnull))


def test_output_onto_a_symlink_writes_its_target(tmp_path, capsys):
    real = tmp_path / "real" / "report.toml"
    real.parent.mkdir()
    real.write_text("old = 1\n")
    link = tmp_path / "link.toml"
    link.symlink_to(real)
    dangling = tmp_path / "dangling.toml"
    dangling.symlink_to(tmp_path / "real" / "new.toml")
    assert main(["--batch", str(LINEAR), "-o", str(link)]) == ExitCode.OK
    assert main(["--batch", str(LINEAR), "-o", str(dangling)]) == ExitCode.OK
    capsys.readouterr()
    assert link.is_symlink() and dangling.is_symlink()
    assert (
        "[report]" in real.read_text()
        and "[report]" in (tmp_path / "real" / "new.toml").read_text()
    )
    assert sorted(p.name for p in real.parent.iterdir()) == ["new.toml", "report.toml"]


def test_a_writer_touches_only_its_own_temporary_file(tmp_path, monkeypatch):
    target = tmp_path / "r.toml"
    notes = tmp_path / ".r.toml.mynotes.tmp"  # a user's file that looks like a temp file
    other = tmp_path / ".r.toml.12345-abcdef.tmp"  # another writer's, in mid-write
    notes.write_text("mine")
    other.write_text("half")
    seen = []
    real_replace = os.replace

    def spy(src, dst):
        seen.append(Path(src).name)
        real_replace(src, dst)

    monkeypatch.setattr(io_safety.os, "replace", spy)
    io_safety.write_atomic(target, "a = 1\n")
    io_safety.write_atomic(target, "a = 2\n")
    assert notes.read_text() == "mine" and other.read_text() == "half"
    assert len(set(seen)) == 2 and all(n.startswith(".r.toml.") for n in seen)  # unique names

    def boom(*_a):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(io_safety.os, "fsync", boom)
    with pytest.raises(OSError):
        io_safety.write_atomic(target, "a = 3\n")
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(
        [target.name, notes.name, other.name]
    )
    assert target.read_text() == "a = 2\n"


@pytest.mark.parametrize(("umask", "mode"), [(0o022, 0o644), (0o077, 0o600), (0o002, 0o664)])
def test_a_new_report_gets_the_umask_mode(tmp_path, umask, mode):
    old = os.umask(umask)
    try:
        io_safety.write_atomic(tmp_path / "r.toml", "a = 1\n")
    finally:
        os.umask(old)
    assert stat.S_IMODE(os.stat(tmp_path / "r.toml").st_mode) == mode


def test_an_existing_report_keeps_its_mode(tmp_path):
    target = tmp_path / "r.toml"
    target.write_text("old\n")
    target.chmod(0o640)
    io_safety.write_atomic(target, "a = 1\n")
    assert stat.S_IMODE(os.stat(target).st_mode) == 0o640 and target.read_text() == "a = 1\n"


# ------------------------------------------------------------------ never hang
def test_fifo_and_device_inputs_are_refused_without_blocking(tmp_path):
    fifo = tmp_path / "req.toml"
    os.mkfifo(fifo)  # no writer: reading it would block forever
    ok = _linear(tmp_path / "d", "ok.toml")
    for args in (
        ("--batch", str(fifo)),
        ("--batch", "/dev/zero"),
        ("--batch", str(fifo), str(ok), "--out-dir", str(tmp_path / "out")),
    ):
        r = _run(*args, timeout=60)
        assert r.returncode == ExitCode.INVALID_INPUT, r.stderr
        assert "not a regular file" in r.stderr and "Traceback" not in r.stderr
    assert (tmp_path / "out" / "ok.report.toml").exists()  # the good file was advised
    os.mkfifo(ok.parent / "pipe.toml")  # in a directory: listed as refused, not skipped
    r = _run("--batch", str(ok.parent), "--out-dir", str(tmp_path / "out2"), timeout=60)
    assert r.returncode == ExitCode.INVALID_INPUT
    assert "pipe.toml: " in r.stderr and "is a FIFO, not a regular file" in r.stderr
    assert (tmp_path / "out2" / "ok.report.toml").exists()


def test_input_larger_than_1_mib_is_refused(tmp_path, capsys):
    big = tmp_path / "big.toml"
    big.write_text("# " + "x" * io_safety.MAX_INPUT_BYTES + "\n")
    assert main(["--batch", str(big)]) == ExitCode.INVALID_INPUT
    err = capsys.readouterr().err
    assert len(_lines(err)) == 1 and "larger than 1024 KiB" in err


def test_read_input_stops_at_the_limit_on_an_endless_file():
    with pytest.raises(InputError, match="device"):
        io_safety.read_input(Path("/dev/zero"))


def test_50000_unknown_keys_give_a_few_lines(tmp_path, capsys):
    req = tmp_path / "keys.toml"
    req.write_text("".join(f"k{i} = 1\n" for i in range(50_000)) + LINEAR.read_text())
    assert main(["--batch", str(req)]) == ExitCode.INVALID_INPUT
    err = capsys.readouterr().err
    lines = _lines(err)
    assert len(lines) == 4 and all(len(line) <= 300 for line in lines)
    assert lines[0].startswith("advisor: k0: unknown key; allowed keys here: application,")
    assert lines[-1] == "advisor: … and 49,997 more unknown keys"


def test_a_near_1_mib_title_gives_a_short_line(tmp_path, capsys):
    req = _linear(tmp_path, title="T" * 1_000_000)
    assert main(["--batch", str(req)]) == ExitCode.INVALID_INPUT
    lines = _lines(capsys.readouterr().err)
    assert len(lines) == 1 and len(lines[0]) <= 300 and "(1,000,000 characters)" in lines[0]


def test_many_problems_are_capped(tmp_path, capsys):
    doc = tomllib.loads(ROTARY.read_text())
    doc["motor"]["candidate_speeds_rpm"] = ["x"] * 20  # 20 problems
    import tomli_w

    req = tmp_path / "r.toml"
    req.write_text(tomli_w.dumps(doc))
    assert main(["--batch", str(req)]) == ExitCode.INVALID_INPUT
    lines = _lines(capsys.readouterr().err)
    assert len(lines) <= 6 and lines[-1].endswith("more problems")


def test_jobs_are_capped_at_files_and_cpus(tmp_path, monkeypatch, capsys):
    import concurrent.futures

    made = []
    real = concurrent.futures.ProcessPoolExecutor

    def spy(max_workers=None, **kw):
        made.append(max_workers)
        return real(max_workers=max_workers, **kw)

    monkeypatch.setattr(concurrent.futures, "ProcessPoolExecutor", spy)
    monkeypatch.setattr(many, "usable_cpus", lambda: 2)
    files = [str(_linear(tmp_path / "in", f"r{i}.toml")) for i in range(3)]
    assert main(["--batch", *files, "--out-dir", str(tmp_path / "o"), "-j", "1000"]) == 0
    assert made == [2]
    made.clear()
    monkeypatch.setattr(many, "usable_cpus", lambda: 64)
    assert main(["--batch", *files[:2], "--out-dir", str(tmp_path / "o"), "-j", "1000"]) == 0
    assert made == [2]
    capsys.readouterr()


# ------------------------------------------------------------------ many files
def test_ctrl_c_says_how_many_reports_were_written(tmp_path, monkeypatch, capsys):
    real = many.advise_one
    calls = []

    def interrupted_third(source, target, catalog_dir):
        calls.append(source)
        if len(calls) == 3:
            raise KeyboardInterrupt
        return real(source, target, catalog_dir)

    monkeypatch.setattr(many, "advise_one", interrupted_third)
    files = [str(_linear(tmp_path / "in", f"r{i}.toml")) for i in range(5)]
    rc = main(["--batch", *files, "--out-dir", str(tmp_path / "o")])
    err = capsys.readouterr().err
    assert rc == 130
    assert _lines(err) == [f"advisor: interrupted; 2 of 5 reports were written to {tmp_path / 'o'}"]
    assert len(list((tmp_path / "o").iterdir())) == 2  # no temporary file left


def test_ctrl_c_with_workers_ends_with_130_and_no_traceback(tmp_path):
    d = tmp_path / "in"
    # enough files that the run cannot end between the first report and the key (a linear
    # file takes a few milliseconds)
    for i in range(600):
        _linear(d, f"r{i:03}.toml")
    proc = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "advisor",
            "--batch",
            str(d),
            "--out-dir",
            str(tmp_path / "o"),
            "-j",
            "2",
        ],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
        # Ctrl-C acts as in a terminal even when the tests run as a background job, whose
        # children inherit SIGINT ignored (Python then keeps ignoring it, as it should)
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL),
    )
    import time

    for _ in range(600):  # wait for the first report, then press Ctrl-C (the whole group)
        if (tmp_path / "o").exists() and any((tmp_path / "o").glob("*.report.toml")):
            break
        time.sleep(0.05)
    os.killpg(proc.pid, signal.SIGINT)
    _out, err = proc.communicate(timeout=120)
    assert proc.returncode == 130, err
    assert "Traceback" not in err and "KeyboardInterrupt" not in err
    assert "interrupted;" in err and "reports were written" in err
    assert len(_lines(err)) == 1
    said = int(err.split("interrupted; ", 1)[1].split(" ", 1)[0])
    written = list((tmp_path / "o").iterdir())
    assert said == len(written) >= 1  # the count is true, and no temporary file is left
    assert all(p.name.endswith(".report.toml") for p in written)


def _killing_advise_one(source, target, catalog_dir):
    """A worker that dies on the file named killer.toml (as one the OOM killer picks)."""
    if Path(source).name == "killer.toml":
        os.kill(os.getpid(), signal.SIGKILL)
    return many._real_advise_one(source, target, catalog_dir)


def test_a_killed_worker_fails_only_its_file(tmp_path, monkeypatch, capsys):
    import multiprocessing

    if multiprocessing.get_start_method() != "fork":
        pytest.skip("the patched worker function reaches workers only when they are forked")
    monkeypatch.setattr(many, "_real_advise_one", many.advise_one, raising=False)
    monkeypatch.setattr(many, "advise_one", _killing_advise_one)
    monkeypatch.setattr(many, "usable_cpus", lambda: 2)
    d = tmp_path / "in"
    for i in range(6):
        _linear(d, f"r{i}.toml")
    _linear(d, "killer.toml")
    rc = main(["--batch", str(d), "--out-dir", str(tmp_path / "o"), "-j", "2"])
    printed = capsys.readouterr()
    assert rc == ExitCode.INTERNAL_ERROR
    assert sorted(p.name for p in (tmp_path / "o").iterdir()) == [
        f"r{i}.report.toml" for i in range(6)
    ]
    assert "6 designs, 0 infeasible, 0 invalid, 1 internal errors" in printed.out
    assert "killer.toml: the worker process advising this file died" in printed.err
    assert "Traceback" not in printed.err and "BrokenProcessPool" not in printed.err


def test_out_dir_inside_the_inputs_skips_reports(tmp_path, capsys):
    d = tmp_path / "in"
    _linear(d, "a.toml")
    _linear(d, "b.toml")
    for _ in range(2):
        assert main(["--batch", str(d), "--out-dir", str(d)]) == ExitCode.OK
        assert "2 designs, 0 infeasible, 0 invalid" in capsys.readouterr().out
    assert sorted(p.name for p in d.iterdir()) == [
        "a.report.toml",
        "a.toml",
        "b.report.toml",
        "b.toml",
    ]


def test_an_input_named_like_a_report_is_not_replaced(tmp_path, capsys):
    a = _linear(tmp_path, "a.toml")
    src = _linear(tmp_path, "a.report.toml")  # given explicitly: a.toml's report would be it
    before = src.read_bytes()
    rc = main(["--batch", str(a), str(src), "--out-dir", str(tmp_path)])
    assert rc == ExitCode.INVALID_INPUT
    assert "would replace an input file; nothing was written" in capsys.readouterr().err
    assert src.read_bytes() == before


def test_same_basenames_are_listed_with_their_directories(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    _linear(tmp_path / "a", "r.toml")
    (tmp_path / "b").mkdir()
    (tmp_path / "b" / "r.toml").write_text("[application\n")
    assert main(["--batch", "a/r.toml", "b/r.toml", "--out-dir", "o"]) == 2
    printed = capsys.readouterr()
    assert "a/r.toml" in printed.out and "b/r.toml" in printed.out
    assert "advisor: b/r.toml: broken TOML" in printed.err
    assert many.display_names([Path("a/r.toml"), Path("b/r.toml"), Path("c/s.toml")]) == [
        "a/r.toml",
        "b/r.toml",
        "s.toml",
    ]


def test_an_unreadable_directory_names_the_problem(tmp_path, monkeypatch, capsys):
    d = tmp_path / "locked"
    d.mkdir()
    real = os.scandir

    def denied(path="."):
        if Path(path) == d:
            raise PermissionError(13, "Permission denied")
        return real(path)

    monkeypatch.setattr(many.os, "scandir", denied)  # the tests may run as root
    assert main(["--batch", str(d), "--out-dir", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert f"{d}: the directory cannot be read (Permission denied)" in err


# ------------------------------------------------------------------ output that cannot be written
def test_dev_full_is_exit_2_one_line():
    if not os.path.exists("/dev/full"):
        pytest.skip("no /dev/full here")
    r = subprocess.run(
        f"{sys.executable} -m advisor --batch {LINEAR} > /dev/full",
        shell=True,
        capture_output=True,
        text=True,
    )
    assert r.returncode == ExitCode.INVALID_INPUT
    assert _lines(r.stderr) == [
        "advisor: standard output: cannot write the report (No space left on device); "
        "it is incomplete"
    ]


class _FullDisk(io.StringIO):
    """stdout on a full filesystem: writes are buffered, the flush fails."""

    def flush(self):
        raise OSError(28, "No space left on device")


def test_a_full_disk_in_stdout_mode_is_not_exit_0(monkeypatch, capsys):
    monkeypatch.setattr(sys, "stdout", _FullDisk())
    rc = main(["--batch", str(LINEAR)])
    assert rc == ExitCode.INVALID_INPUT
    assert "cannot write the report (No space left on device)" in capsys.readouterr().err


def test_a_full_disk_for_the_summary_is_exit_2(tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(sys, "stdout", _FullDisk())
    rc = main(["--batch", str(LINEAR), "-o", str(tmp_path / "r.toml")])
    assert rc == ExitCode.INVALID_INPUT
    err = capsys.readouterr().err
    assert "cannot write the summary (No space left on device); the report was written to" in err
    assert (tmp_path / "r.toml").exists()


@pytest.mark.parametrize("many_files", [False, True])
def test_head_ends_quietly(tmp_path, many_files):
    args = f"--batch {LINEAR}"
    if many_files:
        d = tmp_path / "in"
        for i in range(30):
            _linear(d, f"r{i:02}.toml")
        args = f"--batch {d} --out-dir {tmp_path / 'o'}"
    r = subprocess.run(
        f"{sys.executable} -m advisor {args} | head -1; exit ${{PIPESTATUS[0]}}",
        shell=True,
        executable="/bin/bash",
        capture_output=True,
        text=True,
    )
    assert r.stderr == "" and r.returncode == 0
    assert len(r.stdout.splitlines()) == 1


# ------------------------------------------------------------------ say what was ignored
def test_one_way_table_without_holding_is_reported_as_ignored(tmp_path, capsys):
    import tomli_w

    doc = seed001_requirement()
    doc["one_way"] = {"type": "worm"}
    src = tmp_path / "r.toml"
    src.write_text(tomli_w.dumps(doc))
    assert main(["--batch", str(src)]) == ExitCode.OK
    printed = capsys.readouterr()
    report = tomllib.loads(printed.out)
    assert report["warnings"][0].startswith("ignored: the [one_way] table")
    assert "one_way" not in report["design"]
    assert _lines(printed.err) == [f"advisor: warning: {report['warnings'][0]}"]
    # many files: said on stderr with the file's name
    assert main(["--batch", str(src), "--out-dir", str(tmp_path / "o")]) == ExitCode.OK
    assert f"advisor: {src.name}: warning: ignored: the [one_way]" in capsys.readouterr().err


def test_one_way_table_with_holding_is_used_without_warning(tmp_path, capsys):
    assert main(["--batch", str(EXAMPLES / "valve_actuator_hold.toml")]) == ExitCode.OK
    printed = capsys.readouterr()
    assert printed.err == "" and "ignored:" not in printed.out


# ------------------------------------------------------------------ smaller ones
def test_a_bom_is_accepted(tmp_path, capsys):
    src = tmp_path / "bom.toml"
    src.write_bytes(b"\xef\xbb\xbf" + LINEAR.read_bytes())
    assert main(["--batch", str(src)]) == ExitCode.OK
    assert tomllib.loads(capsys.readouterr().out)["report"]["status"] == "feasible"


@pytest.mark.parametrize(
    ("thread", "ok"),
    [
        ("Tr16x2", True),
        ("tr 16 x 2", True),
        ("Tr16.0x2.0", True),
        ("Tr10x1.5", True),
        ("Tr16.00000000001x2", False),
        ("Tr16x2.0000001", False),
        ("Tr16.123x2", False),
    ],
)
def test_thread_sizes_are_taken_only_as_written_in_the_standard(thread, ok):
    from advisor.applications.linear.requirements import ScrewReq

    if ok:
        assert ScrewReq(thread=thread).thread in ("Tr16x2", "Tr10x1.5")
    else:
        with pytest.raises(Exception, match="GOST 24738"):
            ScrewReq(thread=thread)


def test_values_are_never_rounded_onto_the_limit():
    from advisor.core.requirements import _show

    assert _show(50.000000000001) == "50.000000000001"
    assert _show(1e12) == "1e+12"
    assert _show(0.1 + 0.2) == "0.30000000000000004"


def test_relative_xdg_state_home_is_ignored(monkeypatch, tmp_path):
    from advisor.tui import draft

    monkeypatch.setenv("HOME", str(tmp_path))
    monkeypatch.setenv("XDG_STATE_HOME", "relative/state")
    assert draft.state_dir() == tmp_path / ".local" / "state" / "drive-advisor"
    monkeypatch.setenv("XDG_STATE_HOME", "")
    assert draft.state_dir() == tmp_path / ".local" / "state" / "drive-advisor"
    monkeypatch.setenv("XDG_STATE_HOME", str(tmp_path / "abs"))
    assert draft.state_dir() == tmp_path / "abs" / "drive-advisor"


def test_the_batch_path_still_imports_no_textual():
    code = (
        "import sys, io, contextlib\n"
        "from advisor.cli import main\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n"
        f"    rc = main(['--batch', {str(LINEAR)!r}])\n"
        "print(rc, 'textual' in sys.modules, 'numpy' in sys.modules)\n"
    )
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert r.stdout.split() == ["0", "False", "False"], r.stderr


def test_the_wizard_views_show_user_names_literally(tmp_path):
    """A positioning motor is named by the user: its name reaches the components table,
    the decisions and the summary of the wizard, never as markup or a control sequence."""
    from rich.console import Console

    from advisor.core.engine import advise
    from advisor.core.reading import parse_requirements
    from advisor.tui import views

    doc = tomllib.loads((EXAMPLES / "positioning_drive.toml").read_text())
    name = "M[/]1 [b]\x1b[2J"
    doc["positioning"]["motors"][0]["name"] = name
    doc["application"]["title"] = "T[/i] [red]\x1b]0;x\x07"
    report = advise(parse_requirements(doc))
    console = Console(width=400, record=True, file=io.StringIO())
    for render in (views.summary, views.components, views.decisions, views.checks):
        console.print(render(report))
    text = console.export_text()
    assert "M[/]1 [b]\\x1b[2J" in text and "T[/i] [red]\\x1b]0;x\\x07" in text
    assert "\x1b" not in text


def test_a_user_catalog_that_is_a_fifo_or_too_deep_is_refused_in_one_line(tmp_path):
    from advisor.core.errors import CatalogError
    from catalogs import load_catalogs
    from catalogs.loader import MOTORS_FILE

    d = tmp_path / "cat"
    d.mkdir()
    os.mkfifo(d / MOTORS_FILE)  # no writer: reading it would block forever
    with pytest.raises(CatalogError, match="is a FIFO, not a regular file"):
        load_catalogs(d)
    (d / MOTORS_FILE).unlink()
    (d / MOTORS_FILE).write_text("x = " + "[" * 5000 + "]" * 5000 + "\n")
    with pytest.raises(CatalogError, match=r"^catalog .*nested more than 32 levels deep"):
        load_catalogs(d)


def test_a_pool_broken_while_tasks_are_handed_out_loses_no_file(tmp_path, monkeypatch, capsys):
    """A worker may die between two hand-outs: the next ``submit`` then raises
    BrokenProcessPool itself. That is a dead worker like any other (its files run again), not
    an internal error of the run (a reviewer's run hit it once in three)."""
    from concurrent.futures import ProcessPoolExecutor
    from concurrent.futures.process import BrokenProcessPool

    real_submit = ProcessPoolExecutor.submit
    calls = {"n": 0}

    def submit(self, *args, **kwargs):
        calls["n"] += 1
        if calls["n"] == 3:  # once: as if a worker had just died
            raise BrokenProcessPool("A child process terminated abruptly")
        return real_submit(self, *args, **kwargs)

    monkeypatch.setattr(ProcessPoolExecutor, "submit", submit)
    monkeypatch.setattr(many, "usable_cpus", lambda: 2)
    d = tmp_path / "in"
    for i in range(40):
        _linear(d, f"r{i:02}.toml")
    rc = main(["--batch", str(d), "--out-dir", str(tmp_path / "o"), "-j", "2"])
    printed = capsys.readouterr()
    assert rc == ExitCode.OK, printed.err
    assert len(list((tmp_path / "o").iterdir())) == 40
    assert "40 designs" in printed.out
    assert "a worker process died" in printed.err and "BrokenProcessPool" not in printed.err


def test_a_worker_writes_nothing_the_parent_writes_the_report(tmp_path):
    """The cause of the temp file a killed worker left (issue 24): the pool kills a worker's
    siblings when one dies, and a sibling killed while it wrote left its
    ``.NAME.report.toml.PID-XXXX.tmp``. A worker now only advises (:func:`many.advise_one`
    writes nothing); the parent writes (:func:`many.write_report`)."""
    src = _linear(tmp_path / "in")
    target = tmp_path / "o" / "r.report.toml"
    target.parent.mkdir()
    advised = many.advise_one(src, target, None)
    assert list(target.parent.iterdir()) == []  # nothing on disk yet, not even a temp file
    assert advised.outcome.code == ExitCode.OK and advised.outcome.report == str(target)
    assert many.write_report(advised) == advised.outcome
    assert target.read_text(encoding="utf-8") == advised.text
    assert [p.name for p in target.parent.iterdir()] == ["r.report.toml"]


def test_ctrl_c_while_the_parent_writes_counts_what_is_on_disk(tmp_path, monkeypatch):
    """SIGINT arriving in the middle of a write is held until the batch is recorded: both
    reports are on disk and both are counted, then KeyboardInterrupt is raised."""
    from advisor.core import io_safety

    real = io_safety.write_atomic
    writes = []

    def interrupted_write(path, text):
        writes.append(path)
        if len(writes) == 1:
            os.kill(os.getpid(), signal.SIGINT)  # Ctrl-C lands in the middle of the batch
        real(path, text)

    monkeypatch.setattr(io_safety, "write_atomic", interrupted_write)
    import advisor.core.report as report_module

    monkeypatch.setattr(report_module, "write_atomic", interrupted_write)
    out = tmp_path / "o"
    out.mkdir()
    batch = [
        (
            i,
            many.advise_one(
                _linear(tmp_path / "in", f"r{i}.toml"), out / f"r{i}.report.toml", None
            ),
        )
        for i in range(2)
    ]
    outcomes: dict = {}
    with pytest.raises(KeyboardInterrupt):
        many.settle(batch, outcomes)
    assert sorted(outcomes) == [0, 1] and all(o.code == ExitCode.OK for o in outcomes.values())
    assert sorted(p.name for p in out.iterdir()) == ["r0.report.toml", "r1.report.toml"]
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
