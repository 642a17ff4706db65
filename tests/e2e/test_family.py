"""Product-family studies on a real dask.distributed LocalCluster (issue 18)."""

import contextlib
import io
import os
import signal
import subprocess
import sys
import tomllib

import pytest
from helpers import EXAMPLES

if not os.environ.get("CI"):  # CI installs the [family] extra: there a missing Dask fails
    pytest.importorskip("distributed", reason="install the extra: pip install -e '.[family]'")

from advisor.cli import main
from advisor.family.cells import cell, columns
from advisor.family.outputs import COLUMNS, key_outputs
from advisor.family.spec import axis_values, parse_family, read_family
from advisor.family.study import join_chunks, run_study
from advisor.family.summary import changes, read_rows, summarize

# Two applications, 504 variants: the cheap linear and positioning paths carry the count,
# a small rotary member (≈ 15 ms a variant) shows the third; some variants are infeasible
# (linear: a Tr16x2 steel-steel nut at high force) and some invalid (rotary: output faster
# than the motor's slowest candidate speed).
FAMILY = f"""
[family]
name = "Test range"

[[family.members]]
name = "screw"
base = "{EXAMPLES / "linear_screw_actuator.toml"}"
[family.members.axes]
"linear.force_N" = {{ from = 500, to = 12000, steps = 25, scale = "log" }}
"linear.travel_time_s" = [2, 5, 10, 20, 40]
"screw.material_pair" = ["steel_bronze", "steel_steel", "hardened_steel_bronze"]

[[family.members]]
name = "positioning"
base = "{EXAMPLES / "positioning_drive.toml"}"
[family.members.axes]
"positioning.travel_rad" = {{ from = 1, to = 100, steps = 20, scale = "log" }}
"positioning.load_inertia_kgm2" = [0.5, 1, 2, 5, 10, 20]

[[family.members]]
name = "rudder"
base = "{EXAMPLES / "rudder_actuator.toml"}"
[family.members.axes]
"rotary.torque_Nm" = [200, 1620, 3000]
"rotary.speed_rpm" = [5, 20, 6000]
"""
N_VARIANTS = 25 * 5 * 3 + 20 * 6 + 3 * 3
CHUNK = 25


@pytest.fixture(scope="module")
def client():
    from dask.distributed import Client, LocalCluster

    cluster = LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    )
    c = Client(cluster)
    yield c
    c.close()
    cluster.close()


@pytest.fixture(scope="module")
def family(tmp_path_factory):
    path = tmp_path_factory.mktemp("fam") / "range.toml"
    path.write_text(FAMILY, encoding="utf-8")
    return read_family(path)


@pytest.fixture(scope="module")
def reference(client, family, tmp_path_factory):
    """The uninterrupted study, with every report written."""
    out = tmp_path_factory.mktemp("ref")
    res = run_study(family, out, client, CHUNK, reports=True)
    assert res.computed == res.chunks == -(-N_VARIANTS // CHUNK)
    join_chunks(family, out, CHUNK)
    return out


def test_family_of_504_variants_over_three_applications(family, reference):
    assert family.size == N_VARIANTS >= 500
    rows = read_rows(reference / "designs.csv")
    assert [int(r["variant"]) for r in rows] == list(range(N_VARIANTS))
    assert {r["application"] for r in rows} == {"linear", "positioning", "rotary"}
    assert list(rows[0]) == columns(family)
    statuses = {r["status"] for r in rows}
    assert statuses == {"design", "infeasible", "invalid"}
    # the rotary member: 6000 rpm at the output is not below the motor speeds: invalid
    rudder = [r for r in rows if r["member"] == "rudder"]
    assert {r["status"] for r in rudder if r["rotary.speed_rpm"] == "6000"} == {"invalid"}
    assert all(r["exit_code"] == "2" for r in rudder if r["rotary.speed_rpm"] == "6000")
    # axes of the other members are blank in a row
    assert all(r["rotary.torque_Nm"] == "" for r in rows if r["member"] != "rudder")
    doc = summarize(family, rows, {})
    assert sum(doc["counts"].values()) == N_VARIANTS
    assert [m["variants"] for m in doc["members"]] == [375, 120, 9]
    # the invalid region of the rudder member: exactly the 6000 rpm column, every torque
    invalid = [g for g in doc["members"][2]["without_design"] if g["status"] == "invalid"]
    assert len(invalid) == 1 and invalid[0]["variants"] == 3
    assert invalid[0]["axes"] == {"rotary.torque_Nm": [200, 1620, 3000], "rotary.speed_rpm": [6000]}
    assert "is not below the slowest motor.candidate_speeds_rpm" in invalid[0]["example"]


def _batch(tmp_path, requirement):
    import tomli_w

    p = tmp_path / "variant.toml"
    p.write_text(tomli_w.dumps(requirement), encoding="utf-8")
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = main(["--batch", str(p)])
    return p, rc, out.getvalue(), err.getvalue()


def test_every_sampled_row_equals_the_batch_command_alone(family, reference, tmp_path):
    rows = read_rows(reference / "designs.csv")
    sample = [
        *range(0, N_VARIANTS, 23),
        next(i for i, r in enumerate(rows) if r["status"] == "infeasible"),
        next(i for i, r in enumerate(rows) if r["status"] == "invalid"),
        N_VARIANTS - 1,
    ]
    seen = set()
    for i in sample:
        req = family.variant(i)[2]
        row = rows[i]
        path, rc, out, err = _batch(tmp_path, req)
        assert row["exit_code"] == str(rc), i
        seen.add(row["status"])
        if rc == 0:
            report = tomllib.loads(out)
            want = key_outputs(report)
            assert [row[c] for c in COLUMNS] == [cell(want[c]) for c in COLUMNS], i
            assert (reference / "reports" / f"v{i:07d}.report.toml").read_text() == out
        else:
            lines = [line.removeprefix("advisor: ").strip() for line in err.splitlines()]
            assert row["reason"] == "; ".join(x.removeprefix("- ") for x in lines), i
            assert all(row[c] == "" for c in COLUMNS)
    assert seen == {"design", "infeasible", "invalid"}
    # and one variant through a separate process, exactly as a user would run it
    j = max(i for i, r in enumerate(rows) if r["status"] == "design" and r["member"] == "rudder")
    req = family.variant(j)[2]
    path, *_ = _batch(tmp_path, req)
    alone = subprocess.run(
        [sys.executable, "-m", "advisor", "--batch", str(path)], capture_output=True, text=True
    )
    assert alone.returncode == 0
    assert (reference / "reports" / f"v{j:07d}.report.toml").read_text() == alone.stdout


def test_resume_after_interruption(client, family, reference, tmp_path):
    out = tmp_path / "study"
    out.mkdir()

    def stop_after_three(n):
        if n == 3:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        run_study(family, out, client, CHUNK, reports=True, on_chunk=stop_after_three)
    written = sorted((out / "chunks").glob("c*.csv"))
    assert len(written) == 3
    res = run_study(family, out, client, CHUNK, reports=True)
    assert res.computed == res.chunks - 3  # the written chunks were not computed again
    join_chunks(family, out, CHUNK)
    assert (out / "designs.csv").read_bytes() == (reference / "designs.csv").read_bytes()
    assert len(list((out / "reports").iterdir())) == len(list((reference / "reports").iterdir()))
    # a third run has nothing left to do
    assert run_study(family, out, client, CHUNK, reports=True).computed == 0


def test_a_different_study_in_the_same_folder_is_refused(client, family, reference):
    from advisor.core.errors import InputError

    with pytest.raises(InputError, match="holds chunks of another study"):
        run_study(family, reference, client, CHUNK + 1, reports=True)


def test_a_worker_killed_mid_study_costs_nothing(client, family, reference, tmp_path):
    out = tmp_path / "killed"
    out.mkdir()
    pids = client.run(os.getpid)
    killed = []

    def kill_one(n):
        if n == 2 and not killed:
            pid = next(iter(pids.values()))
            os.kill(pid, signal.SIGKILL)  # the nanny starts a new worker
            killed.append(pid)

    res = run_study(family, out, client, CHUNK, on_chunk=kill_one)
    assert killed and res.computed == res.chunks
    join_chunks(family, out, CHUNK)
    assert (out / "designs.csv").read_bytes() == (reference / "designs.csv").read_bytes()
    assert not list(out.glob("**/*.tmp"))
    # the cluster is whole again for whatever runs next
    client.wait_for_workers(2, timeout=60)


def test_a_window_of_three_tasks_gives_the_same_study(client, family, reference, tmp_path):
    """The client keeps at most ``window`` chunks on the cluster (never the whole study):
    the scheduler holds no more tasks than that whenever a chunk is written."""
    out = tmp_path / "window"
    out.mkdir()
    held = []

    def count_tasks(n):
        held.append(client.run_on_scheduler(lambda dask_scheduler: len(dask_scheduler.tasks)))

    res = run_study(family, out, client, CHUNK, on_chunk=count_tasks, window=3)
    assert res.computed == res.chunks == len(held) == -(-N_VARIANTS // CHUNK)
    # 3 in flight, and at most the one just released that the scheduler has yet to forget
    assert max(held) <= 4 < res.chunks
    join_chunks(family, out, CHUNK)
    assert (out / "designs.csv").read_bytes() == (reference / "designs.csv").read_bytes()


def test_the_local_runners_give_the_dask_study(family, reference, tmp_path):
    """In this process, and in forked workers of which one is killed mid-study: the same
    designs.csv and reports as on the Dask cluster; an interrupted run resumes."""
    from advisor.family.local import ForkPool, InProcess

    out = tmp_path / "inprocess"
    out.mkdir()

    def stop_after_two(n):
        if n == 2:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        run_study(family, out, InProcess(), CHUNK, reports=True, on_chunk=stop_after_two)
    assert (
        run_study(family, out, InProcess(), CHUNK, reports=True).computed
        == -(-N_VARIANTS // CHUNK) - 2
    )
    join_chunks(family, out, CHUNK)
    assert (out / "designs.csv").read_bytes() == (reference / "designs.csv").read_bytes()

    out = tmp_path / "forked"
    out.mkdir()
    pool = ForkPool(2)
    killed = []

    def kill_one(n):
        import multiprocessing

        kids = multiprocessing.active_children()
        if n == 2 and kids and not killed:
            os.kill(kids[0].pid, signal.SIGKILL)  # its chunk is given to a new worker
            killed.append(kids[0].pid)

    res = run_study(family, out, pool, CHUNK, reports=True, on_chunk=kill_one)
    assert killed and res.computed == res.chunks
    join_chunks(family, out, CHUNK)
    assert (out / "designs.csv").read_bytes() == (reference / "designs.csv").read_bytes()
    assert sorted(p.name for p in (out / "reports").iterdir()) == sorted(
        p.name for p in (reference / "reports").iterdir()
    )
    assert not list(out.glob("**/*.tmp"))


# ------------------------------------------------------------------ axes and summary


def test_log_range_by_hand():
    # 100 → 2000 in 20 log steps: ratio 20^(1/19) = 1.170780; 100·1.170780 = 117.078
    a = axis_values("rotary.torque_Nm", {"from": 100, "to": 2000, "steps": 20, "scale": "log"})
    assert a.values[:3] == (100, 117.078, 137.073) and a.values[-1] == 2000
    assert len(a.values) == 20
    # a whole-number linear range stays whole: 2, 4, 6, 8
    assert axis_values("k", {"from": 2, "to": 8, "steps": 4}).values == (2, 4, 6, 8)


def test_changes_found_along_each_axis(tmp_path):
    doc = tomllib.loads((EXAMPLES / "rudder_actuator.toml").read_text())
    doc["family"] = {"axes": {"rotary.torque_Nm": [100, 200, 300], "rotary.speed_rpm": [2, 5]}}
    fam = parse_family(doc, tmp_path / "f.toml")
    m = fam.members[0]
    # a made-up grid of stage counts, torque × speed (speed fastest):
    #   100: 3 2 | 200: 3 2 | 300: 4 3
    found = changes(m, ["3", "2", "3", "2", "4", "3"])
    assert {(c["axis"], tuple(c["between"]), c["from"], c["to"], c["lines"]) for c in found} == {
        ("rotary.speed_rpm", (2, 5), 3, 2, 2),  # on the lines torque = 100 and 200
        ("rotary.speed_rpm", (2, 5), 4, 3, 1),  # on the line torque = 300
        ("rotary.torque_Nm", (200, 300), 3, 4, 1),  # at speed 2
        ("rotary.torque_Nm", (200, 300), 2, 3, 1),  # at speed 5
    }
    assert all(c["of_lines"] == (3 if c["axis"] == "rotary.speed_rpm" else 2) for c in found)
    # a blank (no design) is not a change of choice
    assert changes(m, ["3", "", "3", "3", "3", "3"]) == []


BAD_AXES = [
    ('"rotary.torqe_Nm" = [1, 2]', "rotary.torqe_Nm: unknown key"),
    ('"rotary.torque_Nm" = []', "empty list"),
    ('"rotary.torque_Nm" = { from = 5, to = 5, steps = 3 }', "empty range"),
    (
        '"rotary.torque_Nm" = [100, 2e6]',
        "value 2000000.0: rotary.torque_Nm = 2000000.0: must be ≤ 100000",
    ),
    (
        '"rotary.torque_Nm" = { from = 0, to = 5, steps = 3, scale = "log" }',
        "log range needs from > 0",
    ),
    ('"rotary.torque_Nm" = { from = 1, to = 5, steps = 3, scale = "cubic" }', "scale = 'cubic'"),
    ('"rotary.torque_Nm" = { from = 1, to = 5 }', "range without 'steps'"),
    ('"motor.kind" = ["bldc", "induction"]', "'motor.kind' value 'induction'"),
]


@pytest.mark.parametrize(("axis", "words"), BAD_AXES)
def test_bad_axis_is_one_line_exit_2_before_any_work(tmp_path, capsys, axis, words):
    base = (EXAMPLES / "rudder_actuator.toml").read_text()
    p = tmp_path / "fam.toml"
    p.write_text(f"[family]\nname = 'x'\n[family.axes]\n{axis}\n\n{base}", encoding="utf-8")
    out = tmp_path / "out"
    assert main(["family", str(p), "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and words in err, err
    assert not out.exists()  # refused before any work: no folder, no cluster


def test_bad_base_and_file_errors(tmp_path, capsys):
    p = tmp_path / "fam.toml"
    base = (
        (EXAMPLES / "rudder_actuator.toml")
        .read_text()
        .replace("stage_efficiency = 0.9", "stage_efficiency = 7")
    )
    p.write_text(f"[family.axes]\n'rotary.speed_rpm' = [5]\n{base}", encoding="utf-8")
    assert main(["family", str(p), "--out", str(tmp_path / "o")]) == 2
    assert "base requirement: gearbox.stage_efficiency = 7" in capsys.readouterr().err
    p.write_text(base)
    assert main(["family", str(p), "--out", str(tmp_path / "o")]) == 2
    assert "no [family] table" in capsys.readouterr().err
    assert main(["family", str(tmp_path / "none.toml"), "--out", str(tmp_path / "o")]) == 2
    assert "no such file" in capsys.readouterr().err
    assert main(["family", str(p)]) == 2  # --out is required
    assert not (tmp_path / "o").exists()


def test_cli_end_to_end_with_its_own_local_cluster_then_a_scheduler(client, tmp_path):
    fam = tmp_path / "fam.toml"
    base = (EXAMPLES / "linear_screw_actuator.toml").read_text()
    fam.write_text(
        "[family]\nname = 'Screw jacks'\nchunk_size = 4\n[family.axes]\n"
        "'linear.force_N' = [1000, 3500, 9000]\n'linear.travel_time_s' = [2, 5, 10]\n\n" + base
    )
    out = tmp_path / "out"
    r = subprocess.run(
        [sys.executable, "-m", "advisor", "family", str(fam), "--out", str(out), "--workers", "1"],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert r.returncode == 0, r.stderr
    assert "9 variants:" in r.stdout and "3 of 3 chunks computed" in r.stdout
    assert "chunks 3/3, variants 9/9" in r.stderr  # the progress bar's last line
    summary = tomllib.loads((out / "summary.toml").read_text())
    assert summary["family"]["variants"] == 9 and sum(summary["counts"].values()) == 9
    page = (out / "family.html").read_text()
    assert page.count("<svg") >= 3 and "Screw jacks" in page
    assert len(read_rows(out / "designs.csv")) == 9
    # a rerun on an existing cluster resumes: nothing left to compute, same results
    before = (out / "designs.csv").read_bytes()
    address = client.scheduler.address
    r2 = subprocess.run(
        [
            sys.executable,
            "-m",
            "advisor",
            "family",
            str(fam),
            "--out",
            str(out),
            "--scheduler",
            address,
            "--quiet",
            "--no-html",
        ],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert r2.returncode == 0 and "0 of 3 chunks computed" in r2.stdout
    assert (out / "designs.csv").read_bytes() == before


def test_a_cluster_gives_the_summary_of_this_machine(client, family, tmp_path):
    """The parts of the summary the workers tally travel back through Dask as through the
    local pipes: on the cluster (2 workers) and on 2 local workers, the same files."""
    outs = {}
    for where, how in (("local", ["--workers", "2"]), ("cluster", ["--scheduler"])):
        if where == "cluster":
            how = [*how, client.scheduler.address]
        outs[where] = tmp_path / where
        argv = ["family", family.source, "--out", str(outs[where]), "--chunk-size", "37"]
        with contextlib.redirect_stdout(io.StringIO()):
            assert main([*argv, "--quiet", "--no-html", *how]) == 0
    for name in ("summary.toml", "designs.csv"):
        assert (outs["local"] / name).read_bytes() == (outs["cluster"] / name).read_bytes()
    doc = tomllib.loads((outs["cluster"] / "summary.toml").read_text(encoding="utf-8"))
    assert sum(doc["counts"].values()) == N_VARIANTS and doc["members"][2]["without_design"]


def test_batch_path_imports_no_dask_or_matplotlib():
    code = (
        "import sys, io, contextlib\n"
        "from advisor.cli import main\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n"
        f"    rc = main(['--batch', {str(EXAMPLES / 'valve_actuator_hold.toml')!r}])\n"
        "assert rc == 0\n"
        "print(','.join(m for m in ('dask', 'distributed', 'matplotlib') if m in sys.modules))\n"
    )
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == ""


def test_key_outputs_of_the_valve_example_by_hand():
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        assert main(["--batch", str(EXAMPLES / "valve_actuator_hold.toml")]) == 0
    row = key_outputs(tomllib.loads(out.getvalue()))
    # the report: reducer 3.47718 kg, roller clutch 0.0728396 kg → 3.5500196 → 3.55002 kg
    assert row["mass_kg"] == 3.55002
    assert (row["motor"], row["pole_pairs"], row["ratio"], row["stages"]) == (
        "bldc 3000 rpm",
        6,
        600.0,
        2,
    )
    assert (row["outer_diameter_mm"], row["losses_W"]) == (132.647, 132.248)
    assert row["one_way"] == "roller_clutch (motor side)" and row["screw_thread"] is None


def test_the_example_family_file():
    fam = read_family(EXAMPLES / "families" / "valve_actuators.toml")
    assert fam.size == 60 and fam.members[0].application == "rotary"
    assert [a.key for a in fam.members[0].axes] == ["rotary.torque_Nm", "rotary.speed_rpm"]


def _one_variant_family(tmp_path, base, axis: str):
    fam = tmp_path / "one.toml"
    fam.write_text(
        f'[family]\nname = "one"\n[[family.members]]\nname = "m"\nbase = "{base}"\n'
        f"[family.members.axes]\n{axis}\n",
        encoding="utf-8",
    )
    out = tmp_path / "study"
    quiet = io.StringIO()
    with contextlib.redirect_stdout(quiet), contextlib.redirect_stderr(quiet):
        assert main(["family", str(fam), "--out", str(out), "--reports", "--workers", "1"]) == 0
        batch = tmp_path / "batch"
        rc = main(["--batch", str(base), "--out-dir", str(batch)])
    return out, batch, rc


@pytest.mark.parametrize("base", sorted((EXAMPLES / "infeasible").glob("*.toml")), ids=str)
def test_an_infeasible_variant_gets_the_report_the_batch_writes(tmp_path, base):
    """--reports writes every variant's report: an infeasible one's is byte for byte what
    ``advisor --batch FILE --out-dir DIR`` writes for the same file (status = infeasible)."""
    doc = tomllib.loads(base.read_text(encoding="utf-8"))
    kind = doc["application"]["kind"]  # one axis of one value: the file's own first number
    key, value = next((k, v) for k, v in doc[kind].items() if isinstance(v, int | float))
    out, batch, rc = _one_variant_family(tmp_path, base, f'"{kind}.{key}" = [{value!r}]')
    assert rc == 3
    assert read_rows(out / "designs.csv")[0]["status"] == "infeasible"
    (alone,) = batch.iterdir()
    report = (out / "reports" / "v0000000.report.toml").read_bytes()
    assert report == alone.read_bytes()
    assert tomllib.loads(report.decode())["report"]["status"] == "infeasible"


def test_an_invalid_variant_gets_no_report_as_the_batch_writes_none(tmp_path):
    # the rudder at 6000 rpm: not below the motor's slowest candidate speed (a cross-field
    # refusal, so the family advises the variant and records it invalid)
    base = tmp_path / "rudder.toml"
    base.write_text(
        (EXAMPLES / "rudder_actuator.toml")
        .read_text()
        .replace("speed_rpm = 5\n", "speed_rpm = 6000\n")
    )
    out, batch, rc = _one_variant_family(tmp_path, base, '"rotary.torque_Nm" = [1620]')
    assert rc == 2
    assert read_rows(out / "designs.csv")[0]["status"] == "invalid"
    assert list((out / "reports").iterdir()) == [] and list(batch.iterdir()) == []
