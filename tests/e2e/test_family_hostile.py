"""Hostile input on ``advisor family`` (issue 24, "Family studies").

The contract: exit 0 a complete study, 2 invalid input (one line naming the field, the value
and what is allowed), 130 interrupted (one line); exit 1, a traceback, a hang or a lost file
is a bug. Every refusal here is made before any cluster starts: the ``no_cluster`` fixture
turns starting one into a failure of the test, and one subprocess shows that Dask is not
even imported. One test starts real clusters (three study runs): ctrl+c after a worker was
killed, then two identical studies into one folder at once.
"""

import contextlib
import csv
import io
import json
import os
import signal
import socket
import subprocess
import sys
import threading
import time
import tomllib
import warnings
from dataclasses import replace
from pathlib import Path

import pytest
from helpers import EXAMPLES

from advisor.cli import main
from advisor.core.errors import InputError
from advisor.family import cli as family_cli
from advisor.family.cells import cell, neutral, uncell
from advisor.family.chunks import rows_csv, run_chunk
from advisor.family.spec import axis_values, parse_family, read_family
from advisor.family.study import write_replace
from advisor.family.summary import read_rows

ROTARY = (EXAMPLES / "rudder_actuator.toml").read_text(encoding="utf-8")
LINEAR = (EXAMPLES / "linear_screw_actuator.toml").read_text(encoding="utf-8")


class ClusterStarted(BaseException):
    """Raised where a cluster would start: a BaseException, so that nothing catches it."""


@pytest.fixture
def no_cluster(monkeypatch):
    def tripwire(*args, **kwargs):
        raise ClusterStarted

    monkeypatch.setattr(family_cli, "make_runner", tripwire)


def family_file(path: Path, axes: str, base: str = ROTARY, name: str = "x") -> Path:
    path.write_text(f"[family]\nname = '{name}'\n[family.axes]\n{axes}\n\n{base}", encoding="utf-8")
    return path


def refused(capsys, argv: list[str], *words: str) -> str:
    """Run ``advisor family ARGV``: exit 2 with one line holding every word."""
    assert main(["family", *argv]) == 2
    err = capsys.readouterr().err
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    for w in words:
        assert w in lines[0], lines[0]
    return lines[0]


def tree(folder: Path) -> dict[str, bytes]:
    return {
        str(p.relative_to(folder)): p.read_bytes() if p.is_file() else b"<dir>"
        for p in sorted(folder.rglob("*"))
    }


# ------------------------------------------------------------------ the study's own input


def _summary_is_family(tmp_path: Path) -> tuple[Path, Path]:
    d = tmp_path / "d"
    d.mkdir()
    return family_file(d / "summary.toml", '"rotary.speed_rpm" = [2, 5]'), d


def _designs_is_family(tmp_path: Path) -> tuple[Path, Path]:
    d = tmp_path / "d"
    d.mkdir()
    return family_file(d / "designs.csv", '"rotary.speed_rpm" = [2, 5]'), d


def _html_is_family(tmp_path: Path) -> tuple[Path, Path]:
    d = tmp_path / "d"
    d.mkdir()
    return family_file(d / "family.html", '"rotary.speed_rpm" = [2, 5]'), d


def _family_in_reports(tmp_path: Path) -> tuple[Path, Path]:
    d = tmp_path / "d"
    (d / "reports").mkdir(parents=True)
    return family_file(d / "reports" / "f.toml", '"rotary.speed_rpm" = [2, 5]'), d


def _family_in_chunks(tmp_path: Path) -> tuple[Path, Path]:
    d = tmp_path / "d"
    (d / "chunks").mkdir(parents=True)
    return family_file(d / "chunks" / "f.toml", '"rotary.speed_rpm" = [2, 5]'), d


def _link_to_summary(tmp_path: Path) -> tuple[Path, Path]:
    fam, d = _summary_is_family(tmp_path)
    link = tmp_path / "link.toml"
    link.symlink_to(fam)
    return link, d


def _summary_links_to_family(tmp_path: Path) -> tuple[Path, Path]:
    fam = family_file(tmp_path / "f.toml", '"rotary.speed_rpm" = [2, 5]')
    d = tmp_path / "d"
    d.mkdir()
    (d / "summary.toml").symlink_to(fam)
    return fam, d


def _out_links_to_family_folder(tmp_path: Path) -> tuple[Path, Path]:
    fam, d = _designs_is_family(tmp_path)
    (tmp_path / "alias").symlink_to(d)
    return fam, tmp_path / "alias"


def _member_base_is_designs(tmp_path: Path) -> tuple[Path, Path]:
    d = tmp_path / "d"
    d.mkdir()
    (d / "designs.csv").write_text(ROTARY, encoding="utf-8")
    fam = tmp_path / "f.toml"
    fam.write_text(
        "[family]\n[[family.members]]\nname = 'm'\nbase = 'd/designs.csv'\n"
        "[family.members.axes]\n'rotary.speed_rpm' = [2, 5]\n",
        encoding="utf-8",
    )
    return fam, d


@pytest.mark.parametrize(
    ("setup", "words"),
    [
        (_summary_is_family, "writes summary.toml there"),
        (_designs_is_family, "writes designs.csv there"),
        (_html_is_family, "writes family.html there"),
        (_family_in_reports, "writes into reports/ there"),
        (_family_in_chunks, "writes into chunks/ there"),
        (_link_to_summary, "writes summary.toml there"),
        (_summary_links_to_family, "writes summary.toml there"),
        (_out_links_to_family_folder, "writes designs.csv there"),
        (_member_base_is_designs, "writes designs.csv there"),
    ],
)
def test_the_study_never_writes_over_its_own_input(tmp_path, capsys, no_cluster, setup, words):
    fam, out = setup(tmp_path)
    before = tree(tmp_path)
    refused(capsys, [str(fam), "--out", str(out), "--reports"], f"--out {out}", words)
    assert tree(tmp_path) == before  # nothing written, nothing removed


def test_an_output_that_is_not_written_is_not_refused(tmp_path, capsys, no_cluster):
    """With --no-html the study writes no family.html: a family file of that name is safe."""
    fam, d = _html_is_family(tmp_path)
    with pytest.raises(ClusterStarted):
        main(["family", str(fam), "--out", str(d), "--no-html"])


def test_a_result_name_taken_by_a_folder_is_refused(tmp_path, capsys, no_cluster):
    fam = family_file(tmp_path / "f.toml", '"rotary.speed_rpm" = [2, 5]')
    (tmp_path / "d" / "designs.csv").mkdir(parents=True)
    refused(capsys, [str(fam), "--out", str(tmp_path / "d")], "designs.csv there is not a regular")


# ------------------------------------------------------------------ the size of a study


BIG_AXES = (
    '"rotary.torque_Nm" = { from = 100, to = 2000, steps = 100000 }\n'
    '"rotary.speed_rpm" = { from = 1, to = 10, steps = 100000 }\n'
    '"gearbox.stage_efficiency" = { from = 0.5, to = 0.9, steps = 100 }'
)


def test_a_family_of_a_trillion_variants_is_counted_and_refused_at_once(
    tmp_path, capsys, no_cluster
):
    fam = family_file(tmp_path / "big.toml", BIG_AXES)
    out = tmp_path / "out"
    t0 = time.perf_counter()
    # 100000 × 100000 × 100 = 10^12 variants, against the default limit of 10^6
    refused(
        capsys,
        [str(fam), "--out", str(out)],
        "1,000,000,000,000 variants (100000 × 100000 × 100)",
        "limit of 1,000,000",
        "--max-variants N",
    )
    assert time.perf_counter() - t0 < 2.0  # counted, never built (it took 80 s, then died)
    assert not out.exists()


def test_the_limit_is_an_option(tmp_path, capsys, no_cluster):
    fam = family_file(
        tmp_path / "f.toml", '"rotary.torque_Nm" = [100, 200]\n"rotary.speed_rpm" = [2, 5, 10]'
    )
    # 2 × 3 = 6 variants
    refused(
        capsys,
        [str(fam), "--out", str(tmp_path / "o"), "--max-variants", "5"],
        "6 variants (2 × 3)",
        "limit of 5",
    )
    with pytest.raises(ClusterStarted):
        main(["family", str(fam), "--out", str(tmp_path / "o"), "--max-variants", "6"])
    refused(
        capsys,
        [str(fam), "--out", str(tmp_path / "o"), "--max-variants", "0"],
        "--max-variants = 0: must be at least 1",
    )
    assert not (tmp_path / "o").exists()  # the run that reached the cluster left no empty folder


def test_members_add_up_against_the_limit(tmp_path, capsys, no_cluster):
    fam = tmp_path / "f.toml"
    fam.write_text(
        f"[family]\n[[family.members]]\nname = 'a'\nbase = '{EXAMPLES / 'rudder_actuator.toml'}'\n"
        "[family.members.axes]\n'rotary.torque_Nm' = [100, 200]\n'rotary.speed_rpm' = [2, 5]\n"
        f"[[family.members]]\nname = 'b'\nbase = '{EXAMPLES / 'rudder_actuator.toml'}'\n"
        "[family.members.axes]\n'rotary.speed_rpm' = [2, 5, 10]\n",
        encoding="utf-8",
    )
    # 2 × 2 + 3 = 7
    refused(
        capsys,
        [str(fam), "--out", str(tmp_path / "o"), "--max-variants", "6"],
        "7 variants (2 × 2 + 3)",
    )


# ------------------------------------------------------------------ options: exit 2, not 1


@pytest.mark.parametrize(
    "address",
    [
        "tcp://127.0.0.1:notaport",
        "http://127.0.0.1:8787",
        "inproc://x",
        "tcp://127.0.0.1:0",
        "tcp://127.0.0.1:65536",
        "tcp://:8786",
        "tcp://127.0.0.1:8786/status",
        "127.0.0.1:8786 ",
        "",
    ],
)
def test_a_scheduler_address_of_the_wrong_form_is_refused_before_anything(
    tmp_path, capsys, no_cluster, address
):
    fam = family_file(tmp_path / "f.toml", '"rotary.speed_rpm" = [2, 5]')
    out = tmp_path / "o"
    refused(
        capsys,
        [str(fam), "--out", str(out), "--scheduler", address],
        "--scheduler",
        "tcp://HOST:PORT",
    )
    assert not out.exists()


def test_scheduler_addresses_of_the_right_form_pass():
    for a in ("tcp://127.0.0.1:8786", "tcp://[::1]:1", "tcp://sched-1.example.org:65535"):
        assert family_cli.check_scheduler(a) == a


def test_a_scheduler_that_does_not_answer_leaves_no_folder(tmp_path, capsys, monkeypatch):
    def refused_connection(*args, **kwargs):
        raise OSError("Timed out trying to connect to tcp://127.0.0.1:1 after 20 s")

    monkeypatch.setattr(family_cli, "make_client", refused_connection)
    fam = family_file(tmp_path / "f.toml", '"rotary.speed_rpm" = [2, 5]')
    kept = tmp_path / "kept"  # the user's own empty folder stays
    kept.mkdir()
    out = kept / "new" / "deeper"
    refused(
        capsys, [str(fam), "--out", str(out), "--scheduler", "tcp://127.0.0.1:1"], "cannot connect"
    )
    assert kept.is_dir() and list(kept.iterdir()) == []
    refused(
        capsys, [str(fam), "--out", str(kept), "--scheduler", "tcp://127.0.0.1:1"], "cannot connect"
    )
    assert kept.is_dir()


def test_a_read_only_out_is_refused_before_the_cluster(tmp_path, capsys, no_cluster):
    fam = family_file(tmp_path / "f.toml", '"rotary.speed_rpm" = [2, 5]')
    if os.geteuid() == 0:  # root writes through permission bits: /proc takes no new file
        ro = Path("/proc")
    else:
        ro = tmp_path / "ro"
        ro.mkdir()
        ro.chmod(0o555)
    refused(capsys, [str(fam), "--out", str(ro)], f"--out {ro}: cannot write there")
    refused(capsys, [str(fam), "--out", str(ro / "new")], f"--out {ro / 'new'}: cannot")


def test_a_folder_of_another_study_is_refused_before_the_cluster(tmp_path, capsys, no_cluster):
    fam = family_file(tmp_path / "f.toml", '"rotary.speed_rpm" = [2, 5]')
    (tmp_path / "o" / "chunks").mkdir(parents=True)
    (tmp_path / "o" / "chunks" / "study.json").write_text('{"fingerprint": "0", "chunk_size": 1}')
    refused(capsys, [str(fam), "--out", str(tmp_path / "o")], "holds chunks of another study")


def test_chunks_of_an_older_version_say_what_to_do(tmp_path, capsys):
    """A study written before its manifest carried the catalogs stamp: refused in one line
    (exit 2) that says how to go on, and its chunks are left as they were."""
    _, argv = _small_study(tmp_path)
    assert main([*argv, "--quiet"]) == 0
    out = Path(argv[argv.index("--out") + 1])
    manifest = out / "chunks" / "study.json"
    old = json.loads(manifest.read_text(encoding="utf-8"))
    del old["catalogs"]
    manifest.write_text(json.dumps(old), encoding="utf-8")
    chunks = sorted(p.name for p in (out / "chunks").iterdir())
    line = refused(capsys, argv[1:], "older version", "delete its chunks/", "another --out")
    assert line.startswith(f"advisor: {out}: holds chunks of another study")
    assert sorted(p.name for p in (out / "chunks").iterdir()) == chunks


def test_a_broken_catalog_dir_is_refused_before_the_cluster(tmp_path, capsys, no_cluster):
    fam = family_file(tmp_path / "f.toml", '"rotary.speed_rpm" = [2, 5]')
    refused(
        capsys,
        [str(fam), "--out", str(tmp_path / "o"), "--catalog-dir", str(tmp_path / "none")],
        "catalog directory",
    )
    assert not (tmp_path / "o").exists()


def test_refusals_import_no_dask():
    """In a fresh process: the refusals above never import distributed (so no cluster)."""
    code = f"""
import contextlib, io, sys, tempfile
from pathlib import Path
from advisor.cli import main
d = Path(tempfile.mkdtemp())
base = Path({str(EXAMPLES / "rudder_actuator.toml")!r}).read_text()
(d / "big.toml").write_text("[family]\\n[family.axes]\\n" + {BIG_AXES!r} + "\\n" + base)
(d / "f.toml").write_text("[family]\\n[family.axes]\\n'rotary.speed_rpm' = [2, 5]\\n" + base)
codes = []
with contextlib.redirect_stderr(io.StringIO()):
    codes.append(main(["family", str(d / "big.toml"), "--out", str(d / "o")]))
    codes.append(main(["family", str(d / "f.toml"), "--out", str(d / "o"), "--scheduler", "http://x:1"]))
    codes.append(main(["family", str(d / "f.toml"), "--out", str(d / "f.toml")]))
print([int(c) for c in codes], [m for m in ("dask", "distributed") if m in sys.modules])
"""
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "[2, 2, 2] []"


# ------------------------------------------------------------------ axes


def test_a_log_range_beyond_the_floats_is_finite_and_refused_by_its_field(
    tmp_path, capsys, no_cluster
):
    # log-spaced: exponents -300, -150, 0, 150, 300 (the ratio 1e600 is not a float)
    a = axis_values("k", {"from": 1e-300, "to": 1e300, "steps": 5, "scale": "log"})
    assert a.values == (1e-300, 1e-150, 1.0, 1e150, 1e300)
    # linear: the width 2e308 is not a float; the quarters are
    a = axis_values("k", {"from": -1e308, "to": 1e308, "steps": 5})
    assert a.values == (-1e308, -5e307, 0.0, 5e307, 1e308)
    fam = family_file(
        tmp_path / "f.toml",
        '"rotary.torque_Nm" = { from = 1e-300, to = 1e300, steps = 7, scale = "log" }',
    )
    refused(
        capsys,
        [str(fam), "--out", str(tmp_path / "o")],
        "family axis 'rotary.torque_Nm' value 1e-300",
    )
    assert not (tmp_path / "o").exists()


@pytest.mark.parametrize(
    ("axis", "words"),
    [
        (
            '"application.kind" = ["rotary", "linear"]',
            "'application.kind': the [application] table",
        ),
        (
            '"application" = [{ kind = "rotary" }, { kind = "linear" }]',
            "'application': the [application] table",
        ),
        ('"application.title" = ["a", "b"]', "'application.title': the [application] table"),
        (
            '"rotary.torque_Nm" = [100, 100.0]',
            "'rotary.torque_Nm': 100 and 100.0 are the same value",
        ),
        ('"rotary.speed_rpm" = [2, 5, 2]', "'rotary.speed_rpm': 2 appears twice"),
        (
            '"motor.candidate_speeds_rpm" = [[1500, 3000], [1500.0, 3000]]',
            "[1500, 3000] and [1500.0, 3000] are the same value",
        ),
        (
            '"rotary.torque_Nm" = [100, nan]',
            "'rotary.torque_Nm': value nan: must be a finite number",
        ),
        ('"rotary.torque_Nm" = [100, inf]', "value inf: must be a finite number"),
    ],
)
def test_bad_axes_are_refused_naming_the_axis(tmp_path, capsys, no_cluster, axis, words):
    fam = family_file(tmp_path / "f.toml", axis)
    refused(capsys, [str(fam), "--out", str(tmp_path / "o")], "family axis", words)
    assert not (tmp_path / "o").exists()


# ------------------------------------------------------------------ spreadsheet formulas


def test_cells_that_would_start_a_formula_are_neutralised_and_numbers_are_not():
    hyperlink = '=HYPERLINK("http://x","y")'
    assert cell(hyperlink) == "'" + hyperlink
    assert cell("@SUM(A1)") == "'@SUM(A1)"
    assert [cell(x) for x in ("+1 kN", "-5")] == ["'+1 kN", "'-5"]
    # a tab or a carriage return is written escaped (a control character), so starts nothing
    assert [cell(x) for x in ("\tx", "\rx")] == ["\\tx", "\\rx"]
    assert [cell(x) for x in (-5, -5.5, 0, 1e-7, True, None)] == [
        "-5",
        "-5.5",
        "0",
        "1e-07",
        "true",
        "",
    ]
    assert cell("bldc 3000 rpm") == "bldc 3000 rpm" and cell([-1, 2]) == "[-1, 2]"
    for text in (hyperlink, "@SUM(A1)", "'=x", "''@x", "'plain", "plain", "-5", ""):
        assert uncell(neutral(text)) == text  # the summary reads back exactly what was given


def test_designs_csv_of_hostile_names_and_values(tmp_path):
    """The rows of a study (run in this process, as a worker runs them): every text cell a
    spreadsheet would evaluate starts with a quote; read back, the names are exact."""
    hyperlink = '=HYPERLINK("http://x","y")'
    fam = tmp_path / "f.toml"
    fam.write_text(
        f"[family]\n[[family.members]]\nname = '{hyperlink}'\nbase = '{EXAMPLES / 'linear_screw_actuator.toml'}'\n"
        "[family.members.axes]\n'linear.force_N' = ['+3500 N', 2000]\n"
        f"[[family.members]]\nname = '@SUM(A1)'\nbase = '{EXAMPLES / 'linear_screw_actuator.toml'}'\n"
        "[family.members.axes]\n'linear.travel_time_s' = [5]\n",
        encoding="utf-8",
    )
    family = read_family(fam)
    res = run_chunk(family, 0, 0, family.size, None, False)
    from advisor.family.cells import columns

    text = rows_csv(res.rows, columns(family))
    raw = list(csv.reader(io.StringIO(text)))
    assert [r[1] for r in raw[1:]] == ["'" + hyperlink, "'" + hyperlink, "'@SUM(A1)"]
    # the axis column holds the number the variant was advised with, not the typed string
    assert [r[3] for r in raw[1:]] == ["3500", "2000", ""]
    assert {r[raw[0].index("status")] for r in raw[1:]} == {"design"}
    (tmp_path / "designs.csv").write_text(text, encoding="utf-8")
    rows = read_rows(tmp_path / "designs.csv")
    assert [r["member"] for r in rows] == [hyperlink, hyperlink, "@SUM(A1)"]
    assert rows[0]["linear.force_N"] == "3500"


# ------------------------------------------------------------------ quiet


def _page(tmp_path: Path, name: str, axis: str, values: list) -> tuple[Path, str]:
    from advisor.family.html import plot_points, write_html
    from advisor.family.summary import build_summary

    doc = tomllib.loads(LINEAR)
    doc["family"] = {"axes": {axis: values}}
    fam = parse_family(doc, tmp_path / "f.toml")
    fam = replace(fam, members=(replace(fam.members[0], name=name),))
    from advisor.family.outputs import COLUMNS

    rows = [
        {
            **dict.fromkeys(COLUMNS, ""),
            "variant": str(i),
            "member": name,
            "status": "design",
            "reason": "",
            "mass_kg": str(2.0 + i),
        }
        for i in range(len(values))
    ]
    path = tmp_path / "family.html"
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # any warning that reaches the user fails the test
        doc, pictures = build_summary(fam, rows, {}, [plot_points(m) for m in fam.members])
        write_html(path, fam, doc, pictures)
    return path, path.read_text(encoding="utf-8")


def test_the_page_of_one_text_axis_warns_nothing(tmp_path):
    # one text axis: the outcome map is one row high, and tight_layout warned
    # "Tight layout not applied. The bottom and top margins cannot be made large enough"
    _, page = _page(
        tmp_path,
        "screws",
        "screw.material_pair",
        ["steel_bronze", "steel_steel", "hardened_steel_bronze"],
    )
    assert page.count("<svg") >= 2


def test_a_formula_in_a_member_name_is_drawn_as_text(tmp_path):
    # "$\frac{$" is a broken mathtext formula: matplotlib raised ValueError (exit 1, after
    # the whole study) where it should draw the name
    _, page = _page(tmp_path, r"$\frac{$ <b>", "linear.travel_time_s", [2, 5, 10])
    assert "&lt;b&gt;" in page and "<b>" not in page


def test_dask_log_lines_do_not_reach_the_terminal():
    """What distributed logs after a worker was killed ("Couldn't gather keys", at ERROR)
    is printed without the quieting and not with it."""
    code = """
import logging, sys
import distributed
logging.getLogger("distributed.scheduler").error("Couldn't gather keys: before")
from advisor.family.cli import quiet_dask_logging
quiet_dask_logging()
logging.getLogger("distributed.scheduler").error("Couldn't gather keys: after")
logging.getLogger("distributed.client").warning("Couldn't gather 1 keys, rescheduling: after")
logging.getLogger("tornado.application").error("Exception in callback: after")
logging.getLogger("asyncio").error("Task was destroyed but it is pending: after")
"""
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert "Couldn't gather keys: before" in r.stderr  # the control: Dask does print it
    assert "after" not in r.stderr, r.stderr


def test_an_interrupted_bar_on_a_terminal_ends_its_line():
    from advisor.family.study import Progress

    class Tty(io.StringIO):
        def isatty(self):
            return True

    stream = Tty()
    bar = Progress(10, 100, stream=stream, every_s=0.0)
    bar.update(3, 30)
    assert not stream.getvalue().endswith("\n")  # the bar is redrawn in place
    bar.end_line()  # before "advisor: interrupted; …"
    assert stream.getvalue().endswith("\n") and stream.getvalue().count("\n") == 1
    bar.end_line()  # once only
    assert stream.getvalue().count("\n") == 1


# ------------------------------------------------------------------ unique temporary names


def test_two_writers_of_one_report_never_collide(tmp_path):
    target = tmp_path / "v0000708.report.toml"
    errors = []

    def write(text: str) -> None:
        try:
            for _ in range(300):
                write_replace(target, text)
        except Exception as exc:  # a fixed temporary name: FileNotFoundError
            errors.append(exc)

    threads = [threading.Thread(target=write, args=(t,)) for t in ("a" * 5000, "b" * 5000)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert errors == []
    assert target.read_text() in ("a" * 5000, "b" * 5000)
    assert [p.name for p in tmp_path.iterdir()] == [target.name]  # no temporary file left


# ------------------------------------------------------------------ on a real cluster


HOSTILE_FAMILY = """
[family]
name = "Hostile"

[[family.members]]
name = '=HYPERLINK("http://x","y")'
base = "{linear}"
[family.members.axes]
"linear.force_N" = {{ from = 500, to = 12000, steps = 40, scale = "log" }}
"linear.travel_time_s" = [2, 5, 10]

[[family.members]]
name = "@SUM(A1)"
base = "{linear}"
[family.members.axes]
"screw.material_pair" = ["steel_bronze", "steel_steel", "hardened_steel_bronze"]

[[family.members]]
name = "units"
base = "{linear}"
[family.members.axes]
"linear.force_N" = ["+3500 N", "5 kN"]
"""
HOSTILE_VARIANTS = 40 * 3 + 3 + 2


def _chunks(out: Path) -> int:
    return len(list((out / "chunks").glob("c*.csv")))


def _workers(pid: int) -> list[int]:
    """The Dask worker processes of the study ``pid`` (its children but the resource
    tracker of multiprocessing)."""
    kids: list[str] = []
    for task in os.listdir(f"/proc/{pid}/task"):
        with open(f"/proc/{pid}/task/{task}/children") as fh:
            kids += fh.read().split()
    out = []
    for k in kids:
        try:
            with open(f"/proc/{k}/cmdline", "rb") as fh:
                if b"resource_tracker" not in fh.read():
                    out.append(int(k))
        except OSError:
            pass
    return out


def _wait(cond, timeout: float = 180.0) -> None:
    t0 = time.monotonic()
    while not cond():
        assert time.monotonic() - t0 < timeout, "timed out"
        time.sleep(0.02)


@pytest.mark.skipif(not Path("/proc/self/task").is_dir(), reason="reads /proc to find workers")
def test_killed_worker_then_ctrl_c_then_two_identical_studies_at_once(tmp_path):
    pytest.importorskip("distributed")
    fam = tmp_path / "hostile.toml"
    fam.write_text(HOSTILE_FAMILY.format(linear=EXAMPLES / "linear_screw_actuator.toml"))
    out = tmp_path / "out"
    cmd = [sys.executable, "-m", "advisor", "family", str(fam), "--out", str(out)]
    cmd += ["--chunk-size", "1", "--reports", "--quiet"]
    # another cluster's dashboard port: Dask said "Port 8787 is already in use"
    port = socket.socket()
    with contextlib.suppress(OSError):
        port.bind(("", 8787))
        port.listen()
    try:
        # 1. two workers; one is killed after 2 chunks (the nanny starts another), then
        # ctrl+c reaches the whole process group: exit 130, one line, no worker traceback
        study = subprocess.Popen(
            [*cmd, "--workers", "2"],
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
            start_new_session=True,
        )
        try:
            _wait(lambda: _chunks(out) >= 2)
            os.kill(_workers(study.pid)[0], signal.SIGKILL)
            _wait(lambda: _chunks(out) >= 8)
            os.killpg(study.pid, signal.SIGINT)
            stdout, stderr = study.communicate(timeout=120)
        finally:
            if study.poll() is None:
                os.killpg(study.pid, signal.SIGKILL)
        assert study.returncode == 130, stderr
        assert stderr.splitlines() == [
            f"advisor: interrupted; the chunks written so far are kept in {out}/chunks: run "
            "the same command again to resume"
        ]
        assert 8 <= _chunks(out) < HOSTILE_VARIANTS
        # 2. the same command twice at once, into the same folder: both finish the study
        runs = [
            subprocess.Popen(
                [*cmd, "--workers", "1"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
            )
            for _ in range(2)
        ]
        results = [r.communicate(timeout=300) for r in runs]
    finally:
        port.close()
    for r, (stdout, stderr) in zip(runs, results, strict=True):
        assert r.returncode == 0, stderr
        assert stderr == ""  # no tight_layout warning, no Dask log line, no port notice
        assert f"{HOSTILE_VARIANTS} variants:" in stdout
    assert not list(out.rglob("*.tmp"))
    rows = read_rows(out / "designs.csv")
    assert [int(r["variant"]) for r in rows] == list(range(HOSTILE_VARIANTS))
    designs = [r for r in rows if r["status"] == "design"]
    # a report for every design and every infeasible variant, none for an invalid one
    reported = [r for r in rows if r["status"] in ("design", "infeasible")]
    assert len(list((out / "reports").iterdir())) == len(reported) > len(designs) > 0
    raw = (out / "designs.csv").read_text(encoding="utf-8")
    # the quote goes inside the CSV quoting: the cell is '=HYPERLINK("http://x","y")
    assert '\n0,"\'=HYPERLINK(""http://x"",""y"")",linear,500,2,,' in raw
    assert "\n120,'@SUM(A1),linear,,,steel_bronze," in raw
    assert "\n123,units,linear,3500,,," in raw  # '+3500 N' as the number advised
    summary = tomllib.loads((out / "summary.toml").read_text(encoding="utf-8"))
    assert [m["name"] for m in summary["members"]] == [
        '=HYPERLINK("http://x","y")',
        "@SUM(A1)",
        "units",
    ]


# ------------------------------------------------------------------ hostile review, round 2


def test_an_axis_of_one_value_in_two_spellings_is_refused_naming_the_axis():
    # 1 kN·m = 1000 N·m: converted before the duplicates are looked for (it gave two
    # identical variants); a value that is no quantity of the unit stays for the requirement
    with pytest.raises(InputError) as e:
        axis_values("rotary.torque_Nm", ["1 kN*m", 1000])
    msg = str(e.value)
    assert "family axis 'rotary.torque_Nm'" in msg and "'1 kN*m' and 1000" in msg
    assert axis_values("rotary.torque_Nm", ["1 kN*m", 500]).values == (1000.0, 500)
    assert axis_values("linear.stroke_m", ["200 mm"]).values == (0.2,)
    assert axis_values("output_load.bearing", ["6309", "auto"]).values == ("6309", "auto")


def test_control_characters_of_a_member_name_are_escaped_in_designs_csv(tmp_path):
    fam = tmp_path / "f.toml"
    fam.write_text(
        '[family]\n[[family.members]]\nname = "a\\u001b[2Jb\\u0007"\n'
        f"base = '{EXAMPLES / 'linear_screw_actuator.toml'}'\n"
        "[family.members.axes]\n'linear.travel_time_s' = [5]\n",
        encoding="utf-8",
    )
    family = read_family(fam)
    assert family.members[0].name == "a\x1b[2Jb\x07"
    text = rows_csv(run_chunk(family, 0, 0, 1, None, False).rows)
    assert "\x1b" not in text and "\x07" not in text
    assert next(csv.reader(io.StringIO(text)))[1] == "a\\x1b[2Jb\\x07"
    assert cell("tab\there") == "tab\\there"


def test_workers_above_the_usable_cpus_are_capped_and_said(capsys, monkeypatch):
    monkeypatch.setattr("advisor.many.usable_cpus", lambda: 2)
    assert family_cli.cap_workers(2) == 2 and capsys.readouterr().err == ""
    assert family_cli.cap_workers(100000) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == ["advisor: --workers 100000: capped at 2, the CPUs this process may use"]


def test_a_refused_scheduler_connection_is_said_at_once(tmp_path, capsys):
    """It took about 22 s (Dask's client retried for its 20 s timeout) before exit 2."""
    with socket.socket() as s:  # a port nothing listens on: bound, never listening
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
        fam = family_file(tmp_path / "f.toml", '"rotary.speed_rpm" = [2, 5]')
        t0 = time.monotonic()
        line = refused(
            capsys,
            [str(fam), "--out", str(tmp_path / "o"), "--scheduler", f"tcp://127.0.0.1:{port}"],
            f"--scheduler tcp://127.0.0.1:{port}: nothing answered",
        )
        assert time.monotonic() - t0 < family_cli.CONNECT_TIMEOUT_S, line
    assert not (tmp_path / "o").exists()


def _small_study(tmp_path: Path) -> tuple[Path, list[str]]:
    fam = family_file(tmp_path / "f.toml", "'linear.travel_time_s' = [4, 5, 6, 7]", LINEAR)
    out = tmp_path / "out"
    return out, ["family", str(fam), "--out", str(out), "--workers", "1", "--chunk-size", "2"]


@pytest.mark.parametrize(
    "damage",
    [
        lambda text: "garbage,\n1,2\n",  # a stray file of a chunk's name
        lambda text: text[: len(text) // 2],  # cut short mid-row
        lambda text: text.split("\n", 1)[0] + "\n",  # cut short at a row's end
    ],
)
def test_a_damaged_chunk_is_computed_again(tmp_path, capsys, damage):
    out, argv = _small_study(tmp_path)
    assert main(argv) == 0
    first = (out / "designs.csv").read_bytes()
    chunk = out / "chunks" / "c000001.csv"
    chunk.write_text(damage(chunk.read_text(encoding="utf-8")), encoding="utf-8")
    assert main(argv) == 0
    assert (out / "designs.csv").read_bytes() == first
    assert "1 of 2 chunks computed" in capsys.readouterr().out


def test_a_chunk_damaged_at_the_join_is_refused_and_the_results_kept(tmp_path, capsys, monkeypatch):
    from advisor.family import study

    out, argv = _small_study(tmp_path)
    assert main(argv) == 0
    before = tree(out)
    (out / "chunks" / "c000001.csv").write_text("garbage,\n1,2\n", encoding="utf-8")
    monkeypatch.setattr(study, "drop_damaged", lambda out_dir, family, size, done: done)
    capsys.readouterr()
    assert main([*argv, "--quiet"]) == 2
    err = capsys.readouterr().err
    assert "c000001.csv: damaged chunk" in err and len(err.strip().splitlines()) == 1
    after = tree(out)
    assert {k: v for k, v in after.items() if "chunks" not in k} == {
        k: v for k, v in before.items() if "chunks" not in k
    }
    assert not list(out.glob(".*.tmp"))


def test_designs_csv_gets_the_mode_of_the_other_results(tmp_path):
    out, argv = _small_study(tmp_path)
    old = os.umask(0o022)
    try:
        assert main(argv) == 0
    finally:
        os.umask(old)
    modes = {p.name: p.stat().st_mode & 0o777 for p in out.iterdir() if p.is_file()}
    assert modes == {"designs.csv": 0o644, "summary.toml": 0o644, "family.html": 0o644}


def test_chunks_of_other_catalogs_are_another_study(tmp_path, capsys):
    import shutil

    cat = tmp_path / "cat"
    shutil.copytree(EXAMPLES / "catalogs", cat)
    _, argv = _small_study(tmp_path)
    with_cat = [*argv, "--quiet", "--catalog-dir", str(cat)]
    assert main(with_cat) == 0
    assert main(with_cat) == 0  # the same catalogs: resumed, nothing computed
    assert "0 of 2 chunks computed" in capsys.readouterr().out
    assert main([*argv, "--quiet"]) == 2  # the shipped catalogs alone
    assert "holds chunks of another study" in capsys.readouterr().err
    first = sorted(cat.iterdir())[0]
    first.write_text(first.read_text(encoding="utf-8") + "\n# edited\n", encoding="utf-8")
    assert main(with_cat) == 2  # a user catalog edited
    assert "holds chunks of another study" in capsys.readouterr().err


def _gone(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat") as fh:
            return fh.read().rsplit(")", 1)[1].split()[0] == "Z"
    except OSError:
        return True


@pytest.mark.skipif(not Path("/proc/self/task").is_dir(), reason="reads /proc to find workers")
def test_the_workers_of_a_killed_study_end(tmp_path):
    fam = family_file(
        tmp_path / "f.toml", "'linear.travel_time_s' = {from = 4, to = 8, steps = 400}", LINEAR
    )
    out = tmp_path / "out"
    argv = [str(fam), "--out", str(out), "--workers", "2", "--chunk-size", "2", "--quiet"]
    code = "import sys; from advisor.cli import main; sys.exit(main(['family', *sys.argv[1:]]))"
    proc = subprocess.Popen([sys.executable, "-c", code, *argv])
    try:
        _wait(lambda: (out / "chunks").is_dir() and _chunks(out) >= 2, timeout=60)
        workers = _workers(proc.pid)
        assert len(workers) == 2
    finally:
        proc.kill()
        proc.wait()
    try:
        _wait(lambda: all(_gone(w) for w in workers), timeout=10)
    finally:
        for w in workers:  # never leave an orphan behind a failure
            with contextlib.suppress(OSError):
                os.kill(w, signal.SIGKILL)


def test_control_characters_of_names_are_escaped_in_family_html(tmp_path):
    from advisor.family.html import render

    name = "a\x1b[2Jb\x07\u202e"
    _, page = _page(tmp_path, name, "linear.travel_time_s", [4, 5])
    assert "\x1b" not in page and "\x07" not in page and "\u202e" not in page
    assert "a\\x1b[2Jb\\x07" in page
    doc = tomllib.loads(LINEAR)
    doc["family"] = {"name": name, "axes": {"linear.travel_time_s": [4, 5]}}
    fam = parse_family(doc, tmp_path / "f.toml")
    counts = dict.fromkeys(("design", "infeasible", "invalid", "internal_error"), 0)
    page = render(replace(fam, members=()), {"counts": counts, "members": []}, [])
    assert "\x1b" not in page and "\x07" not in page


def test_a_chunk_whose_worker_keeps_dying_is_said_in_one_line(tmp_path, capsys, monkeypatch):
    from advisor.family import local

    def die(*args, **kwargs):
        os._exit(9)  # as a worker killed by the kernel for its memory

    monkeypatch.setattr(local, "run_chunk", die)
    _, argv = _small_study(tmp_path)
    argv[argv.index("--workers") + 1] = "2"
    assert main([*argv, "--quiet"]) == 4
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "its worker died 3 times" in err[0] and err[0].count("chunk ") >= 1
    assert "internal error" not in err[0]
    assert "4 a chunk's worker died" in family_cli.build_parser().epilog


def test_a_whole_value_given_with_a_unit_is_written_as_a_plain_one():
    values = axis_values("rotary.torque_Nm", ["1.5 kN*m", "200 N*m", 300]).values
    assert [cell(v) for v in values] == ["1500", "200", "300"]
    speed = axis_values("rotary.speed_rpm", ["0.1 rad/s"]).values[0]
    assert speed == pytest.approx(0.954929658551)  # not whole: exact, as the batch reads it


def test_an_interrupted_study_removes_its_own_temporaries_only(tmp_path):
    """A ctrl+c between a temporary file's creation and its writer's cleanup left it in
    chunks/; the interrupted command removes its own (named by its pid), never those of
    another study writing into the same folder at the same time."""
    import os

    from advisor.family.study import remove_own_temporaries

    mine, other = os.getpid(), os.getpid() + 1_000_000
    for folder in ("chunks", "reports"):
        (tmp_path / folder).mkdir()
        (tmp_path / folder / f".c000009.csv.{mine}-49be9ffed3cd.tmp").write_text("x")
        (tmp_path / folder / f".c000009.csv.{other}-49be9ffed3cd.tmp").write_text("x")
        (tmp_path / folder / "c000001.csv").write_text("kept")
    remove_own_temporaries(tmp_path)
    for folder in ("chunks", "reports"):
        left = sorted(p.name for p in (tmp_path / folder).iterdir())
        assert left == [f".c000009.csv.{other}-49be9ffed3cd.tmp", "c000001.csv"]
