"""The family study against a plain loop, and its memory against the number of variants.

    python benchmarks/family_paths.py [--quick] [--pairs N] [--only per_cpu,example,memory]
        [--against CHECKOUT]

Three measurements, each a child process per run (started in a folder of its own), so
that imports and start-up count:

- ``per_cpu`` (and ``per_cpu_rotary``: 6,000 variants of the example's family, about 5 ms
  each): ``advisor family FAMILY --out DIR --no-html --quiet`` (worker processes on
  this machine, the default) paired with a plain loop in one process over the same variants
  (read the family file, then ``advise_one`` per variant: the engine's work and nothing
  else). Runs alternate (A B, B A, …); each pair gives the ratio loop CPU / family CPU, the
  CPU being the child's and its children's user + system time (the workers are waited for,
  so their time counts). At ≥ 5,000 variants the goal is ≥ 0.95.
- ``example``: the 60-variant example as a user runs it (``family.html`` included, the
  default workers) paired with the loop; the goal is a wall time ≤ 2 × the loop's + 1 s.
- ``memory``: the parent's peak RSS (its own VmHWM, the workers apart) at 10³, 10⁴
  and 10⁵ variants (``--no-html --quiet``), and the slope between the last two.

The cheap family is positioning (examples/positioning_drive.toml with three log axes: travel,
load inertia, load torque; about 0.6 ms a variant), where the study's own costs weigh most;
the rotary one is the example's. Writes benchmarks/results/family_paths.json.

``--against CHECKOUT`` (an older commit unpacked with ``git archive``) adds that checkout's
study to every round of ``per_cpu`` and ``example``, the order rotating: its CPU over this
one's, pair by pair, is the change's own effect, which a shared machine's load blurs less
than two separate runs of the ratio to the loop.
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import tomllib
from pathlib import Path
from typing import Any

import tomli_w
from _results import ROOT, save

PY = sys.executable
EXAMPLE = ROOT / "examples" / "families" / "valve_actuators.toml"

#: Runs the study's command in this child and prints what it used: its own peak RSS and CPU,
#: and its children's CPU (the workers). The peak is the kernel's VmHWM of this process: on
#: Linux ``ru_maxrss`` keeps the RSS of the process that started the child (a large
#: ``run_all.py`` showed as 220 MiB at every size).
STUDY = """
import json, resource, sys, time
t0 = time.perf_counter()
from advisor.cli import main
rc = main(["family", *sys.argv[1:]])
wall = time.perf_counter() - t0
me, kids = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
peak = me.ru_maxrss / 1024
try:
    with open("/proc/self/status") as fh:
        peak = next(int(x.split()[1]) / 1024 for x in fh if x.startswith("VmHWM:"))
except (OSError, StopIteration):
    pass
print(json.dumps({"rc": rc, "wall_s": wall, "parent_cpu_s": me.ru_utime + me.ru_stime,
    "workers_cpu_s": kids.ru_utime + kids.ru_stime, "parent_peak_rss_MiB": peak}),
    file=sys.stderr)
"""

#: The plain loop: the family's variants advised one after the other in one process.
LOOP = """
import json, resource, sys, time
t0 = time.perf_counter()
from pathlib import Path
from advisor.family.adapter import advise_one
from advisor.family.spec import read_family
family = read_family(Path(sys.argv[1]))
for i in range(family.size):
    advise_one(family.variant(i)[2])
wall = time.perf_counter() - t0
me = resource.getrusage(resource.RUSAGE_SELF)
print(json.dumps({"wall_s": wall, "cpu_s": me.ru_utime + me.ru_stime,
    "peak_rss_MiB": me.ru_maxrss / 1024}), file=sys.stderr)
"""


def positioning_family(n: int, folder: Path) -> Path:
    """A positioning family of ``n`` variants (``n`` a multiple of 100), written to ``folder``."""
    doc = tomllib.loads((ROOT / "examples" / "positioning_drive.toml").read_text())
    axes = {
        "positioning.travel_rad": {"from": 1, "to": 100, "steps": n // 100, "scale": "log"},
        "positioning.load_inertia_kgm2": {"from": 0.5, "to": 30, "steps": 10, "scale": "log"},
        "positioning.load_torque_Nm": {"from": 10, "to": 200, "steps": 10, "scale": "log"},
    }
    path = folder / f"positioning_{n}.toml"
    path.write_text(tomli_w.dumps({"family": {"name": f"positioning {n}", "axes": axes}, **doc}))
    return path


def valve_family(n: int, folder: Path) -> Path:
    """The example's rotary family with ``n // 3`` torques (× its 3 speeds), in ``folder``."""
    doc = tomllib.loads(EXAMPLE.read_text())
    doc["family"]["axes"]["rotary.torque_Nm"]["steps"] = n // 3
    doc["family"]["name"] = f"valve actuators {n}"
    path = folder / f"valve_{n}.toml"
    path.write_text(tomli_w.dumps(doc))
    return path


def _child(code: str, args: list[str], checkout: Path | None = None) -> dict[str, Any]:
    """Run ``code`` in a child (from a folder of its own: ``python -c`` puts the current
    folder first on sys.path, where a checkout would hide ``checkout``'s advisor)."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    if checkout is not None:
        env["PYTHONPATH"] = str(checkout)
    with tempfile.TemporaryDirectory() as here:
        r = subprocess.run(
            [PY, "-c", code, *args], capture_output=True, text=True, env=env, cwd=here
        )
    last = r.stderr.strip().splitlines()[-1] if r.stderr.strip() else ""
    if not last.startswith("{"):
        raise RuntimeError(f"{args}: {r.stderr[-2000:]}")
    return json.loads(last)


def run_study(family: Path, *options: str, checkout: Path | None = None) -> dict[str, Any]:
    """One study into a fresh folder (the advisor of ``checkout``, e.g. an older commit's
    ``git archive``, if given); what its process used."""
    with tempfile.TemporaryDirectory() as d:
        m = _child(STUDY, [str(family), "--out", str(Path(d) / "out"), *options], checkout)
    m["cpu_s"] = m["parent_cpu_s"] + m["workers_cpu_s"]
    return m


def run_loop(family: Path) -> dict[str, Any]:
    return _child(LOOP, [str(family)])


def _spread(xs: list[float]) -> dict[str, float]:
    q = statistics.quantiles(xs, n=4) if len(xs) > 1 else [xs[0]] * 3
    return {"median": statistics.median(xs), "q1": q[0], "q3": q[2], "min": min(xs), "max": max(xs)}


def paired(family: Path, pairs: int, *options: str, against: Path | None = None) -> dict[str, Any]:
    """Study and loop in turn (A B, B A, …); the ratios pair by pair. With ``against`` (a
    checkout), its study joins each round (the order rotating) and each round gives its
    CPU over this one's too."""
    runs = [
        ("study", lambda: run_study(family, *options)),
        ("loop", lambda: run_loop(family)),
        *([("against", lambda: run_study(family, *options, checkout=against))] if against else []),
    ]
    got: dict[str, list[dict[str, Any]]] = {name: [] for name, _ in runs}
    for k in range(pairs):
        for name, run in runs[k % len(runs) :] + runs[: k % len(runs)]:
            got[name].append(run())
    studies, loops = got["study"], got["loop"]
    cpu = [lo["cpu_s"] / st["cpu_s"] for st, lo in zip(studies, loops, strict=True)]
    wall = [st["wall_s"] / lo["wall_s"] for st, lo in zip(studies, loops, strict=True)]
    extra = {}
    if against:
        old = got["against"]
        extra = {
            "against": str(against),
            "against_cpu_over_study_cpu": _spread(
                [a["cpu_s"] / st["cpu_s"] for a, st in zip(old, studies, strict=True)]
            ),
            "loop_cpu_over_against_cpu": _spread(
                [lo["cpu_s"] / a["cpu_s"] for a, lo in zip(old, loops, strict=True)]
            ),
            "against_parent_cpu_s": _spread([a["parent_cpu_s"] for a in old]),
        }
    return {
        "pairs": pairs,
        **extra,
        "loop_cpu_over_study_cpu": _spread(cpu),
        "study_wall_over_loop_wall": _spread(wall),
        "study_wall_s": _spread([s["wall_s"] for s in studies]),
        "loop_wall_s": _spread([lo["wall_s"] for lo in loops]),
        "study_cpu_s": _spread([s["cpu_s"] for s in studies]),
        "study_parent_cpu_s": _spread([s["parent_cpu_s"] for s in studies]),
        "loop_cpu_s": _spread([lo["cpu_s"] for lo in loops]),
        "parent_peak_rss_MiB": max(s["parent_peak_rss_MiB"] for s in studies),
        "wall_budget_met": [
            s["wall_s"] <= 2 * lo["wall_s"] + 1.0 for s, lo in zip(studies, loops, strict=True)
        ],
    }


def per_cpu(
    pairs: int, n: int = 10_000, kind: str = "positioning", against: Path | None = None
) -> dict[str, Any]:
    make = positioning_family if kind == "positioning" else valve_family
    with tempfile.TemporaryDirectory() as d:
        out = paired(make(n, Path(d)), pairs, "--no-html", "--quiet", against=against)
    return {"variants": n, "family": kind, **out}


def example(pairs: int, against: Path | None = None) -> dict[str, Any]:
    return {"variants": 60, **paired(EXAMPLE, pairs, "--quiet", against=against)}


def memory(sizes: tuple[int, ...] = (1_000, 10_000, 100_000)) -> dict[str, Any]:
    """The parent's peak RSS against the number of variants."""
    out = {}
    with tempfile.TemporaryDirectory() as d:
        for n in sizes:
            m = run_study(positioning_family(n, Path(d)), "--no-html", "--quiet")
            out[n] = {k: m[k] for k in ("parent_peak_rss_MiB", "wall_s", "cpu_s")}
    a, b = sizes[-2], sizes[-1]
    slope = (out[b]["parent_peak_rss_MiB"] - out[a]["parent_peak_rss_MiB"]) / (b - a)
    return {"by_variants": out, "slope_KiB_per_variant": 1024 * slope}


def _iqr(s: dict[str, float], fmt: str = ".2f") -> str:
    return (
        f"**{s['median']:{fmt}}** (IQR {s['q1']:{fmt}}–{s['q3']:{fmt}}, "
        f"range {s['min']:{fmt}}–{s['max']:{fmt}})"
    )


def run_all(quick: bool) -> list[tuple[str, str, str]]:
    """The rows of ``run_all.py``'s table: (measurement, case, figure)."""
    pairs = 3 if quick else 7
    c, e = per_cpu(pairs), example(pairs)
    rotary = [] if quick else [per_cpu(3, 6_000, "rotary")]
    mem = memory((1_000, 10_000) if quick else (1_000, 10_000, 100_000))
    rss = ", ".join(
        f"{n:,}: {v['parent_peak_rss_MiB']:.1f} MiB" for n, v in mem["by_variants"].items()
    )
    return [
        *(
            (
                "`advisor family` per CPU: loop CPU / study CPU (goal ≥ 0.95)",
                f"{r['family']}, {r['variants']:,} variants, workers = cores",
                f"{_iqr(r['loop_cpu_over_study_cpu'])}; {r['study_cpu_s']['median']:.1f} s vs "
                f"{r['loop_cpu_s']['median']:.1f} s CPU",
            )
            for r in (c, *rotary)
        ),
        (
            "`advisor family` wall / plain loop wall (goal ≤ 2 × loop + 1 s)",
            "valve_actuators.toml (60 variants, family.html)",
            f"{_iqr(e['study_wall_over_loop_wall'])}; {e['study_wall_s']['median']:.2f} s vs "
            f"{e['loop_wall_s']['median']:.2f} s; goal met in {sum(e['wall_budget_met'])} of "
            f"{e['pairs']} pairs",
        ),
        (
            "`advisor family` parent peak RSS",
            "positioning, --no-html",
            f"{rss}; {mem['slope_KiB_per_variant']:.3f} KiB per variant",
        ),
    ]


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--only", help="per_cpu, per_cpu_rotary, example, memory (comma-separated)")
    ap.add_argument("--pairs", type=int, help="runs of each (default: 7, --quick 3)")
    ap.add_argument(
        "--against",
        type=Path,
        metavar="CHECKOUT",
        help="also run the study of another checkout in each round (paired A/B), e.g. "
        "`git archive OLD | tar -x -C /tmp/old`",
    )
    args = ap.parse_args()
    pairs = args.pairs or (3 if args.quick else 7)
    old = args.against.resolve() if args.against else None
    steps = {
        "per_cpu": lambda: per_cpu(pairs, against=old),
        "per_cpu_rotary": lambda: per_cpu(pairs, 6_000, "rotary", against=old),
        "example": lambda: example(pairs, against=old),
        "memory": lambda: memory((1_000, 10_000) if args.quick else (1_000, 10_000, 100_000)),
    }
    names = args.only.split(",") if args.only else list(steps)
    out: dict[str, Any] = {"load_average_before": os.getloadavg()}
    for name in names:
        out[name] = steps[name]()
        print(name, json.dumps(out[name], indent=1), flush=True)
    out["load_average_after"] = os.getloadavg()
    save("family_paths", out)


if __name__ == "__main__":
    main()
