"""Cold `advisor --batch` on each example against the bare import of its dependencies.

Paired runs: the floor (``python -c "import numpy, scipy, pydantic, tomli_w"``) and the batch
command run back to back, A B A B …, and each pair gives one ratio; the median ratio and its
spread (interquartile range, min–max) are reported, so load that comes and goes hits both
members of a pair alike instead of shifting one median against the other. Three paths per
example: the report on stdout, the report written with ``-o`` (a file in a temporary
directory, then the summary on stdout), and a first run without the catalog cache (an empty
cache directory per run: the catalogs are validated and the cache written).

The children run with the bytecode cache allowed (``PYTHONDONTWRITEBYTECODE`` removed from
their environment): an installed package has its ``.pyc`` files, and the floor's libraries
have theirs; a run that compiles the project's sources on every start measures the compiler.

Besides wall time, the CPU time (user + system) of each child is read from its resource usage:
on a loaded machine it is the steadier figure, since it does not count the time the process
waited for a core.

    python benchmarks/cold_batch.py [-n 21] [--only NAME] [--paths stdout,-o,no-cache]
"""

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from _results import examples, save

FLOOR = [sys.executable, "-c", "import numpy, scipy, pydantic, tomli_w"]
#: The floor of a program that validates its input with a pydantic model: ``import pydantic``
#: alone imports little (its names load lazily); a model with one constrained field brings
#: pydantic's model machinery (pydantic.main, fields, types, annotated_types, json_schema,
#: the schema generator…). It runs with the advisor's light plugin loader, as the advisor
#: does, so that the floor holds only what no pydantic program can avoid.
PYDANTIC_FLOOR = [
    sys.executable,
    "-c",
    "from advisor.core import pydantic_plugins; pydantic_plugins.disable()\n"
    "import numpy, scipy, tomli_w\n"
    "from pydantic import BaseModel, Field\n"
    "class M(BaseModel):\n"
    "    x: float = Field(gt=0)\n"
    "M(x=1.0)\n",
]
PATHS = ("stdout", "-o", "no-cache")


def advisor_cmd() -> list[str]:
    exe = shutil.which("advisor", path=str(Path(sys.executable).parent)) or shutil.which("advisor")
    return [exe] if exe else [sys.executable, "-m", "advisor"]


#: The children's environment (see the module's docstring).
ENV = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}


def timed(cmd: list[str], env: dict[str, str] | None = None) -> tuple[float, float]:
    """Wall and CPU (user + system) seconds of one run of ``cmd``, its output discarded."""
    env = env or ENV
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} exited {proc.returncode}")
    return wall, usage.ru_utime + usage.ru_stime


def spread(values: list[float]) -> dict[str, float]:
    """Median, quartiles and range of ``values``."""
    q = statistics.quantiles(values, n=4) if len(values) > 1 else [values[0]] * 3
    return {
        "median": statistics.median(values),
        "q1": q[0],
        "q3": q[2],
        "min": min(values),
        "max": max(values),
    }


def paired(batch: list[str], n: int, fresh_cache: bool = False) -> dict:
    """``n`` pairs (floor, batch), alternating which runs first; ratios pair by pair. The
    pydantic floor runs beside each pair, and gives its own ratio to the batch."""
    wall_ratio, cpu_ratio, floor_ms, batch_ms, floor_cpu, batch_cpu = [], [], [], [], [], []
    pyd_ratio, pyd_cpu_ratio, pyd_cpu = [], [], []
    timed(FLOOR), timed(batch), timed(PYDANTIC_FLOOR)  # the OS file cache
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(n):
            env = None
            if fresh_cache:
                cache = Path(tmp) / f"cache{i}"
                env = {**ENV, "XDG_CACHE_HOME": str(cache)}
            if i % 2 == 0:
                f, b, pf = timed(FLOOR), timed(batch, env), timed(PYDANTIC_FLOOR)
            else:
                pf, b, f = timed(PYDANTIC_FLOOR), timed(batch, env), timed(FLOOR)
            pyd_ratio.append(b[0] / pf[0])
            pyd_cpu_ratio.append(b[1] / pf[1])
            pyd_cpu.append(1e3 * pf[1])
            floor_ms.append(1e3 * f[0])
            batch_ms.append(1e3 * b[0])
            floor_cpu.append(1e3 * f[1])
            batch_cpu.append(1e3 * b[1])
            wall_ratio.append(b[0] / f[0])
            cpu_ratio.append(b[1] / f[1])
    return {
        "pairs": n,
        "ratio": spread(wall_ratio),
        "cpu_ratio": spread(cpu_ratio),
        "floor_ms": spread(floor_ms),
        "batch_ms": spread(batch_ms),
        "floor_cpu_ms": spread(floor_cpu),
        "batch_cpu_ms": spread(batch_cpu),
        "pydantic_floor_ratio": spread(pyd_ratio),
        "pydantic_floor_cpu_ratio": spread(pyd_cpu_ratio),
        "pydantic_floor_cpu_ms": spread(pyd_cpu),
    }


def cold(n: int, only: str | None = None, paths: tuple[str, ...] = PATHS) -> dict:
    """Every example on every path: ``{example: {path: paired(...)}}``."""
    adv = advisor_cmd()
    out: dict = {}
    with tempfile.TemporaryDirectory() as tmp:
        target = Path(tmp) / "report.toml"
        for ex in examples():
            if only and only not in ex.name:
                continue
            res = out.setdefault(ex.name, {})
            for path in paths:
                if path == "stdout":
                    res[path] = paired([*adv, "--batch", str(ex)], n)
                elif path == "-o":
                    res[path] = paired([*adv, "--batch", str(ex), "-o", str(target)], n)
                else:
                    res[path] = paired([*adv, "--batch", str(ex)], n, fresh_cache=True)
    return out


def line(name: str, path: str, r: dict) -> str:
    w, c = r["ratio"], r["cpu_ratio"]
    return (
        f"{name:30s} {path:8s} floor {r['floor_ms']['median']:6.1f} ms  batch "
        f"{r['batch_ms']['median']:6.1f} ms  ratio {w['median']:.2f} "
        f"(IQR {w['q1']:.2f}–{w['q3']:.2f}, range {w['min']:.2f}–{w['max']:.2f})  "
        f"CPU ratio {c['median']:.2f} (IQR {c['q1']:.2f}–{c['q3']:.2f}); against the "
        f"pydantic floor: CPU ratio {r['pydantic_floor_cpu_ratio']['median']:.2f}"
    )


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("-n", type=int, default=21, help="pairs per example and path")
    ap.add_argument("--only", help="examples whose name contains this")
    ap.add_argument("--paths", default=",".join(PATHS), help="comma-separated: " + ",".join(PATHS))
    args = ap.parse_args()
    res = cold(args.n, args.only, tuple(args.paths.split(",")))
    for name, per_path in res.items():
        for path, r in per_path.items():
            print(line(name, path, r), flush=True)
    res["load_average"] = os.getloadavg()
    save("cold_batch", res)


if __name__ == "__main__":
    main()
