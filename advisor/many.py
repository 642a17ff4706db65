"""Many requirement files at once: one report each, a summary table, the worst exit code.

``advisor --batch a.toml b.toml dir/ --out-dir reports/ [-j N]``. A bad file does not stop
the run; its line in the summary says why. With ``-j N`` the files are advised in N worker
processes.
"""

import sys
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path
from typing import NamedTuple

from advisor.core.errors import AdvisorError, ExitCode, InfeasibleError

#: Severity order for "the worst outcome": a bug, then bad input, then infeasibility.
SEVERITY = {
    ExitCode.OK: 0,
    ExitCode.INFEASIBLE: 1,
    ExitCode.INVALID_INPUT: 2,
    ExitCode.INTERNAL_ERROR: 3,
}


class Outcome(NamedTuple):
    source: str
    code: int
    report: str | None  # path of the written report
    headline: str  # the design in a few words, or the first line of the message
    messages: tuple[str, ...]


def expand(inputs: list[Path]) -> list[Path]:
    """Files as given; a directory stands for its *.toml files (sorted, not recursive)."""
    out: list[Path] = []
    for p in inputs:
        if p.is_dir():
            out.extend(sorted(q for q in p.glob("*.toml") if q.is_file()))
        else:
            out.append(p)
    return out


def report_name(source: Path, taken: set[str]) -> str:
    """``name.report.toml``; a second file of the same name gets ``name-2.report.toml``."""
    stem, k = source.stem, 1
    name = f"{stem}.report.toml"
    while name in taken:
        k += 1
        name = f"{stem}-{k}.report.toml"
    taken.add(name)
    return name


def advise_one(source: Path, target: Path, catalog_dir: Path | None) -> Outcome:
    """Advise one file and write its report; every failure becomes an Outcome."""
    from advisor.core.engine import advise
    from advisor.core.registry import headline
    from advisor.core.report import to_toml, write_atomic
    from advisor.core.requirements import read_requirements

    try:
        report = advise(read_requirements(source), catalog_dir)
        write_atomic(target, to_toml(report))
        return Outcome(str(source), ExitCode.OK, str(target), headline(report), ())
    except InfeasibleError as exc:
        return Outcome(str(source), exc.exit_code, None, exc.summary, tuple(exc.reasons))
    except AdvisorError as exc:
        lines = [line.removeprefix(f"{source}: ") for line in str(exc).splitlines()]
        return Outcome(str(source), exc.exit_code, None, lines[0], tuple(lines[1:]))
    except OSError as exc:
        return Outcome(
            str(source),
            ExitCode.INVALID_INPUT,
            None,
            f"{target}: cannot write ({exc.strerror})",
            (),
        )
    except Exception as exc:  # a bug in one file must not stop the others
        return Outcome(
            str(source),
            ExitCode.INTERNAL_ERROR,
            None,
            f"internal error ({type(exc).__name__}: {exc})",
            (),
        )


def run_many(
    inputs: list[Path], out_dir: Path, catalog_dir: Path | None, jobs: int = 1
) -> tuple[int, list[Outcome]]:
    files = expand(inputs)
    out_dir.mkdir(parents=True, exist_ok=True)
    taken: set[str] = set()
    targets = [out_dir / report_name(f, taken) for f in files]
    if jobs > 1 and len(files) > 1:
        with ProcessPoolExecutor(max_workers=jobs) as pool:
            outcomes = list(
                pool.map(advise_one, files, targets, [catalog_dir] * len(files), chunksize=4)
            )
    else:
        outcomes = [advise_one(f, t, catalog_dir) for f, t in zip(files, targets, strict=True)]
    worst = max((o.code for o in outcomes), key=lambda c: SEVERITY[ExitCode(c)], default=0)
    return int(worst), outcomes


def print_summary(outcomes: list[Outcome], out_dir: Path) -> None:
    from rich.console import Console
    from rich.table import Table

    status = {
        0: "[green]design[/]",
        2: "[red]invalid[/]",
        3: "[yellow]infeasible[/]",
        1: "[red]bug[/]",
    }
    t = Table(title=f"{len(outcomes)} requirement files → {out_dir}", title_justify="left")
    t.add_column("file")
    t.add_column("result")
    t.add_column("exit", justify="right")
    t.add_column("design or reason")
    for o in outcomes:
        t.add_row(Path(o.source).name, status[o.code], str(o.code), o.headline)
    console = Console(file=sys.stdout)
    console.print(t)
    counts = {k: sum(o.code == k for o in outcomes) for k in (0, 3, 2, 1)}
    console.print(
        f"{counts[0]} designs, {counts[3]} infeasible, {counts[2]} invalid"
        + (f", {counts[1]} internal errors" if counts[1] else "")
    )
