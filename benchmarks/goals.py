"""The cold figures of a run beyond the batch's: a file with unit strings, the HTML
datasheet (with its number of plots, and matplotlib's cost of one figure at its least, which
bound what drawing them can cost), numpy's BLAS threads. Each is paired like
``cold_batch.py``: the two commands compared run back to back, their order alternating, one
ratio per pair (wall and CPU).

    python benchmarks/goals.py [-n PAIRS]
"""

import argparse
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

from _results import ROOT, save
from cold_batch import ENV, FLOOR, advisor_cmd, spread, timed

#: The floor of the HTML datasheet: matplotlib's import as the datasheet uses it (Agg, the
#: Figure class; no pyplot).
MPL_FLOOR = [
    sys.executable,
    "-c",
    "import matplotlib; matplotlib.use('Agg'); from matplotlib.figure import Figure",
]

#: matplotlib's CPU for one figure at its least, drawn as a datasheet plot is (three points,
#: a title, axis labels, a legend, ``tight_layout``, ``savefig`` to SVG): milliseconds a
#: figure over 10 figures, the imports and a first figure done before the clock starts.
FIGURE_FLOOR = """
import io, time
import matplotlib; matplotlib.use('Agg'); from matplotlib.figure import Figure
def figure():
    fig = Figure(figsize=(6.4, 3.8)); ax = fig.add_subplot()
    ax.plot([0, 1, 2], [0, 1, 4], label='a'); ax.set_title('t')
    ax.set_xlabel('x'); ax.set_ylabel('y'); ax.legend(); fig.tight_layout()
    fig.savefig(io.StringIO(), format='svg')
figure(); t = time.process_time()
for _ in range(10): figure()
print(1e2 * (time.process_time() - t))
"""

#: How the figure floor runs: in the benchmarks' environment, its output read.
RUN = {"capture_output": True, "text": True, "check": True, "env": ENV}

#: Examples written with unit strings: (example, {key: the same value as a unit string}).
UNIT_FILES = {
    "linear_screw_actuator.toml": {"force_N": '"3.5 kN"', "stroke_m": '"200 mm"'},
    "rudder_actuator.toml": {"torque_Nm": '"1.62 kN*m"', "speed_rpm": '"0.523598776 rad/s"'},
}

#: The datasheets timed: a linear one (two plots), a rotary one with a duty cycle (the most).
HTML_EXAMPLES = ("linear_screw_actuator.toml", "rudder_actuator_duty.toml")


def pair(a: list[str], b: list[str], n: int, env_a=None, env_b=None) -> dict:
    """``n`` pairs of ``b`` against ``a`` (order alternating): b/a per pair, wall and CPU."""
    timed(a, env_a), timed(b, env_b)  # the OS file cache, the bytecode
    wall, cpu, a_ms, b_ms = [], [], [], []
    for i in range(n):
        if i % 2 == 0:
            ra, rb = timed(a, env_a), timed(b, env_b)
        else:
            rb, ra = timed(b, env_b), timed(a, env_a)
        wall.append(rb[0] / ra[0])
        cpu.append(rb[1] / ra[1])
        a_ms.append(1e3 * ra[1])
        b_ms.append(1e3 * rb[1])
    return {
        "pairs": n,
        "ratio": spread(wall),
        "cpu_ratio": spread(cpu),
        "a_cpu_ms": spread(a_ms),
        "b_cpu_ms": spread(b_ms),
    }


def with_units(example: Path, values: dict[str, str], dest: Path) -> Path:
    """``example`` with the keys of ``values`` written as unit strings (the same quantities)."""
    text = example.read_text(encoding="utf-8")
    for key, quantity in values.items():
        text, n = re.subn(rf"(?m)^{key} = .*$", f"{key} = {quantity}", text, count=1)
        assert n == 1, key
    dest.write_text(text, encoding="utf-8")
    return dest


def unit_strings(n: int) -> dict:
    """A file with unit strings against the import floor, and against the same file in
    plain numbers (what the strings cost beyond it)."""
    adv, out = advisor_cmd(), {}
    with tempfile.TemporaryDirectory() as tmp:
        for name, values in UNIT_FILES.items():
            example = ROOT / "examples" / name
            units = with_units(example, values, Path(tmp) / name)
            cmd = [*adv, "--batch", str(units)]
            out[name] = {
                "vs_floor": pair(FLOOR, cmd, n),
                "vs_plain": pair([*adv, "--batch", str(example)], cmd, n),
            }
    return out


def html(n: int) -> dict:
    """``--format html -o FILE`` against matplotlib's import, with the datasheet's number of
    plots and its CPU beyond the import per plot (medians)."""
    adv, out = advisor_cmd(), {}
    with tempfile.TemporaryDirectory() as tmp:
        for name in HTML_EXAMPLES:
            target = Path(tmp) / "sheet.html"
            cmd = [*adv, "--batch", str(ROOT / "examples" / name), "--format", "html"]
            out[name] = pair(MPL_FLOOR, [*cmd, "-o", str(target)], n)
            plots = target.read_text(encoding="utf-8").count('<figure id="plot-')
            beyond = out[name]["b_cpu_ms"]["median"] - out[name]["a_cpu_ms"]["median"]
            out[name] |= {"plots": plots, "beyond_import_per_plot_ms": beyond / max(plots, 1)}
    return out


def figure_floor(n: int) -> dict:
    """matplotlib's CPU for one figure at its least (:data:`FIGURE_FLOOR`), ``n`` runs."""
    runs = [
        float(subprocess.run([sys.executable, "-c", FIGURE_FLOOR], **RUN).stdout) for _ in range(n)
    ]
    return {"runs": n, "cpu_ms_per_figure": spread(runs)}


def blas_threads(n: int) -> dict:
    """The rudder example as the CLI runs it (one BLAS thread unless told) against the same
    run with the pool sized by the user to every core: CPU and wall, paired."""
    cmd = [*advisor_cmd(), "--batch", str(ROOT / "examples" / "rudder_actuator.toml")]
    pool = {**ENV, "OPENBLAS_NUM_THREADS": str(os.cpu_count() or 1)}
    one = {k: v for k, v in ENV.items() if k not in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS")}
    return pair([*cmd], cmd, n, env_a=pool, env_b=one)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("-n", type=int, default=11, help="pairs")
    n = ap.parse_args().n
    res = {
        "unit_strings": unit_strings(n),
        "html": html(n),
        "figure_floor": figure_floor(max(3, n // 3)),
        "blas_threads": blas_threads(n),
    }
    save("goals", res)
    for part, r in res.items():
        print(part, r)


if __name__ == "__main__":
    main()
