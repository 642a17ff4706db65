"""Many requirement files at once: one report each, a summary table, the worst exit code.

``advisor --batch a.toml b.toml dir/ --out-dir reports/ [-j N]``. A bad file does not stop
the run; its line in the summary says why. With ``-j N`` the files are advised in N worker
processes.
"""

import os
import sys
from pathlib import Path
from typing import NamedTuple

from advisor.core.errors import AdvisorError, ExitCode, InfeasibleError, InputError

#: Severity order for "the worst outcome": a bug, then bad input, then infeasibility.
SEVERITY = {
    ExitCode.OK: 0,
    ExitCode.INFEASIBLE: 1,
    ExitCode.INVALID_INPUT: 2,
    ExitCode.INTERNAL_ERROR: 3,
}


def worse(a: int, b: int) -> int:
    """The more severe of two exit codes."""
    return max(a, b, key=lambda c: SEVERITY[ExitCode(c)])


class Outcome(NamedTuple):
    source: str
    code: int
    report: str | None  # path of the written report
    headline: str  # the design in a few words, or the first line of the message
    messages: tuple[str, ...]


class Interrupted(Exception):
    """Ctrl-C during a many-file run: how many reports were written by then."""

    def __init__(self, written: int, total: int) -> None:
        super().__init__(f"{written} of {total} reports written")
        self.written, self.total = written, total


def _toml_files(directory: Path) -> list[Path]:
    """The requirement files of a directory: *.toml, not the advisor's own *.report.toml
    (an --out-dir that is also an input must not be read back as requirements)."""
    from advisor.core.io_safety import show

    try:
        with os.scandir(directory) as it:
            names = [e.name for e in it]
    except OSError as exc:
        raise InputError(
            f"{show(directory, 200)}: the directory cannot be read ({exc.strerror})"
        ) from None
    return sorted(
        directory / n
        for n in names
        # a FIFO or device named *.toml is listed, and refused without being read
        if n.endswith(".toml") and not n.endswith(".report.toml") and not (directory / n).is_dir()
    )


def expand(inputs: list[Path]) -> list[Path]:
    """Files as given; a directory stands for its *.toml files (sorted, not recursive,
    without *.report.toml)."""
    out: list[Path] = []
    for p in inputs:
        if p.is_dir():
            out.extend(_toml_files(p))
        else:
            out.append(p)
    return out


def display_names(files: list[Path]) -> list[str]:
    """How each input is named in the summary: its file name, or its path as given where two
    inputs share a name (``a/r.toml`` and ``b/r.toml``)."""
    from collections import Counter

    count = Counter(f.name for f in files)
    return [f.name if count[f.name] == 1 else str(f) for f in files]


def report_name(source: Path, taken: set[str]) -> str:
    """``name.report.toml``; a second file of the same name gets ``name-2.report.toml``."""
    stem, k = source.stem, 1
    name = f"{stem}.report.toml"
    while name in taken:
        k += 1
        name = f"{stem}-{k}.report.toml"
    taken.add(name)
    return name


class Advised(NamedTuple):
    """One file advised, not yet written: its outcome and, for a design, the report text
    that :func:`write_report` writes at ``outcome.report``."""

    outcome: Outcome
    text: str | None


def advise_one(source: Path, target: Path, catalog_dir: Path | None) -> Advised:
    """Advise one file; every failure becomes an Outcome. Nothing is written here: with
    ``-j N`` this runs in a worker, and a worker can be killed at any instant (the pool kills
    its siblings when one dies), so the files are written by the parent alone
    (:func:`write_report`), which no pool kills in mid-write."""
    from advisor.core.engine import advise
    from advisor.core.io_safety import same_file, show
    from advisor.core.reading import read_requirements
    from advisor.core.registry import headline
    from advisor.core.report import to_toml

    try:
        if same_file(source, target):
            raise InputError(f"{show(target, 200)}: is the input itself; it is not replaced")
        req = read_requirements(source)
        try:
            report = advise(req, catalog_dir)
        except InfeasibleError as exc:  # its report says why, as with -o (exit 3)
            from advisor.infeasible import infeasible_report

            text = to_toml(infeasible_report(req, exc))
            return Advised(
                Outcome(str(source), exc.exit_code, str(target), exc.summary, tuple(exc.reasons)),
                text,
            )
        text = to_toml(report)
        from advisor.core.ignored import IGNORED_PREFIX

        notes = tuple(w for w in report.warnings if w.startswith(IGNORED_PREFIX))
        return Advised(
            Outcome(str(source), ExitCode.OK, str(target), headline(report), notes), text
        )
    except InfeasibleError as exc:
        return Advised(
            Outcome(str(source), exc.exit_code, None, exc.summary, tuple(exc.reasons)), None
        )
    except AdvisorError as exc:
        return Advised(_refused(source, exc), None)
    except RecursionError:
        return Advised(
            Outcome(str(source), ExitCode.INVALID_INPUT, None, "nested too deeply to be read", ()),
            None,
        )
    except Exception as exc:  # a bug in one file must not stop the others
        return Advised(
            Outcome(
                str(source),
                ExitCode.INTERNAL_ERROR,
                None,
                f"internal error ({type(exc).__name__}: {exc})",
                (),
            ),
            None,
        )


def _refused(source: Path | str, exc: AdvisorError) -> Outcome:
    lines = [line.removeprefix(f"{source}: ") for line in str(exc).splitlines()]
    return Outcome(str(source), exc.exit_code, None, lines[0], tuple(lines[1:]))


def write_report(advised: Advised) -> Outcome:
    """Write an advised file's report (atomically: a temporary file renamed over the target,
    removed by the writer on any failure, Ctrl-C included); a target that cannot be written
    becomes the file's outcome."""
    from advisor.core.io_safety import show
    from advisor.core.report import write_atomic

    o = advised.outcome
    if advised.text is None or o.report is None:
        return o
    try:
        write_atomic(Path(o.report), advised.text)
    except AdvisorError as exc:  # the target turned into a FIFO or a directory meanwhile
        return _refused(o.source, exc)
    except OSError as exc:
        return Outcome(
            o.source,
            ExitCode.INVALID_INPUT,
            None,
            f"{show(o.report, 200)}: cannot write ({exc.strerror})",
            (),
        )
    return o


def settle(results: list[tuple[int, Advised]], outcomes: dict[int, Outcome]) -> None:
    """Write the reports of advised files and record their outcomes. Ctrl-C is held off
    until the batch is recorded (then raised as usual): a report on disk is always counted
    among those written, and one counted is on disk."""
    with _SigintHeld():
        for i, advised in results:
            outcomes[i] = write_report(advised)


class _SigintHeld:
    """SIGINT noted inside the block and acted on at its end by the handler it replaced
    (Python's raises KeyboardInterrupt). Blocking the signal with ``pthread_sigmask`` would
    not do: it blocks one thread, and the kernel hands the signal to another (the process
    pool's manager thread), whose handler still interrupts the main thread."""

    def __enter__(self) -> None:
        import signal

        self.caught = False
        try:
            self.old = signal.signal(signal.SIGINT, self._note)
        except ValueError:  # not the main thread: signals go to the main thread anyway
            self.old = None

    def _note(self, signum: int, frame: object) -> None:
        self.caught = True

    def __exit__(self, *exc: object) -> None:
        import signal

        if self.old is None:
            return
        signal.signal(signal.SIGINT, self.old)
        if self.caught and callable(self.old):
            self.old(signal.SIGINT, None)


def _identities(paths: list[Path]) -> set[tuple[int, int]]:
    """(device, inode) of the paths that exist, to recognise one file under two names."""
    out = set()
    for p in paths:
        try:
            st = os.stat(p)
        except OSError:
            continue
        out.add((st.st_dev, st.st_ino))
    return out


def _died(source: Path) -> Outcome:
    return Outcome(
        str(source),
        ExitCode.INTERNAL_ERROR,
        None,
        "the worker process advising this file died (killed, or out of memory); no report",
        (),
    )


def _ignore_sigint() -> None:
    """Workers leave Ctrl-C to the parent, which stops the run and says what was written."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)


def usable_cpus() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def preload(catalog_dir: Path | None) -> None:
    """Import every application's pipeline and report, the compiled requirement validator with
    its checks, and load the catalogs, in the parent before the workers fork: each worker then
    starts with them instead of importing them again. The pydantic models are not
    imported: a valid file never needs them (:mod:`advisor.core.reading`); a worker that meets
    an invalid one imports them then. A catalog that cannot be read is left to the workers,
    which report it per file."""
    from importlib import import_module

    from advisor.core import compiled_validator, registry

    for module in ("advisor.core.engine", "advisor.core.report", "advisor.core.ignored"):
        import_module(module)
    compiled_validator.prepare()
    for app in registry.applications():
        for path in (app.pipeline, app.headline):
            registry.load(path)
    from catalogs import load_catalogs

    try:
        load_catalogs(catalog_dir)
    except AdvisorError:
        pass
    # what is loaded now lives as long as the run: out of the collector's sight, a worker's
    # collections do not walk it, and so do not copy its pages after the fork (gc.freeze)
    import gc

    gc.collect()
    gc.freeze()


def _pool_context():
    """Workers forked from the parent (where it can fork), so that they inherit what
    :func:`preload` imported."""
    import multiprocessing

    try:
        return multiprocessing.get_context("fork")
    except ValueError:  # no fork on this platform: the default start method
        return None


#: Tasks queued per worker: with one, a worker idles between two tasks for the
#: round trip of its result through the parent.
IN_FLIGHT = 2
#: Files per task at most: a task of several files costs one round trip through the parent
#: instead of one per file (on two cores the parent's wake-ups take time from the workers),
#: while tasks stay small enough that the last ones share out evenly.
CHUNK = 8


def chunk_size(files: int, jobs: int) -> int:
    """Files per task: about eight tasks per worker, at most :data:`CHUNK` files each."""
    return max(1, min(CHUNK, files // (8 * jobs)))


def advise_chunk(
    items: list[tuple[int, Path, Path]], catalog_dir: Path | None
) -> list[tuple[int, Advised]]:
    """:func:`advise_one` for each file of a task, in a worker; the parent writes the
    reports (:func:`settle`)."""
    return [(i, advise_one(f, t, catalog_dir)) for i, f, t in items]


def _run_pool(
    jobs: int,
    todo: list[tuple[int, Path, Path]],
    catalog_dir: Path | None,
    outcomes: dict[int, Outcome],
    size: int | None = None,
) -> tuple[list[tuple[int, Path, Path]], list[tuple[int, Path, Path]]]:
    """Advise ``todo`` with ``jobs`` workers, in tasks of ``size`` files (by default
    :func:`chunk_size`), at most
    ``IN_FLIGHT × jobs`` tasks in flight (a worker finds its next task queued instead of
    waiting for the parent to hear of the last one), recording each outcome as it arrives.
    When a worker dies (the pool is then broken) returns the files in flight and those not
    started; else two empty lists."""
    from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
    from concurrent.futures.process import BrokenProcessPool

    size = size or chunk_size(len(todo), jobs)
    pending = [todo[k : k + size] for k in range(0, len(todo), size)][::-1]
    pool = ProcessPoolExecutor(
        max_workers=jobs, mp_context=_pool_context(), initializer=_ignore_sigint
    )
    flight: dict = {}
    try:
        while pending or flight:
            broken = False
            while pending and len(flight) < IN_FLIGHT * jobs:
                task = pending.pop()
                try:
                    fut = pool.submit(advise_chunk, task, catalog_dir)
                except BrokenProcessPool:  # a worker died before this task was taken
                    flight[None] = task  # held with those in flight: it is run again
                    broken = True
                    break
                flight[fut] = task
            done = [f for f in flight if f is not None and f.done()]
            if not broken:
                done, _ = wait(flight, return_when=FIRST_COMPLETED)
            for fut in done:
                task = flight.pop(fut)
                try:
                    results = fut.result()
                except BrokenProcessPool:
                    flight[fut] = task
                    broken = True
                else:
                    settle(results, outcomes)
            if broken:
                held = [item for task in flight.values() for item in task]
                return held, [item for task in reversed(pending) for item in task]
        return [], []
    except KeyboardInterrupt:  # let the files in progress finish, and count their reports
        pool.shutdown(wait=True, cancel_futures=True)
        for fut in flight:
            if fut is not None and fut.done() and not fut.cancelled() and fut.exception() is None:
                settle(fut.result(), outcomes)
        raise
    finally:
        pool.shutdown(wait=True, cancel_futures=True)


def run_many(
    inputs: list[Path],
    out_dir: Path,
    catalog_dir: Path | None,
    jobs: int = 1,
    notify=None,
) -> tuple[int, list[Outcome]]:
    """Advise every file; the worst exit code and one Outcome per file, in input order.

    ``jobs`` is capped at the number of files and of usable CPUs. A worker that dies (killed,
    out of memory) loses only its own file: the files in flight with it are advised again,
    each in a worker of its own, and a file whose own worker dies again is reported as failed.
    Ctrl-C raises :class:`Interrupted` with the count of reports written.
    """
    files = expand(inputs)
    out_dir.mkdir(parents=True, exist_ok=True)
    taken: set[str] = set()
    targets = [out_dir / report_name(f, taken) for f in files]
    jobs = max(1, min(jobs, len(files), usable_cpus()))
    outcomes: dict[int, Outcome] = {}
    todo = _refuse_clashes(files, targets, outcomes)
    try:
        if jobs > 1:
            _run_parallel(jobs, todo, catalog_dir, outcomes, notify)
        else:
            for i, f, t in todo:
                settle([(i, advise_one(f, t, catalog_dir))], outcomes)
    except KeyboardInterrupt:
        written = sum(o.code == ExitCode.OK for o in outcomes.values())
        raise Interrupted(written, len(files)) from None
    ordered = [outcomes[i] for i in range(len(files))]
    worst = max((o.code for o in ordered), key=lambda c: SEVERITY[ExitCode(c)], default=0)
    return int(worst), ordered


def _refuse_clashes(
    files: list[Path], targets: list[Path], outcomes: dict[int, Outcome]
) -> list[tuple[int, Path, Path]]:
    """The (index, file, target) to advise; a file whose report would replace an input
    (a.toml's report and an input named a.report.toml) gets its refusal in ``outcomes``."""
    from advisor.core.io_safety import show

    todo = []
    given = _identities(files)
    for i, (f, t) in enumerate(zip(files, targets, strict=True)):
        if _identities([t]) & given:
            outcomes[i] = Outcome(
                str(f),
                ExitCode.INVALID_INPUT,
                None,
                f"its report {show(t, 200)} would replace an input file; nothing was written",
                (),
            )
        else:
            todo.append((i, f, t))
    return todo


def _run_parallel(
    jobs: int,
    todo: list[tuple[int, Path, Path]],
    catalog_dir: Path | None,
    outcomes: dict[int, Outcome],
    notify=None,
) -> None:
    """Advise ``todo`` in ``jobs`` workers; the files a dying worker held are run again."""
    preload(catalog_dir)
    while todo:
        held, todo = _run_pool(jobs, todo, catalog_dir, outcomes)
        if not held:
            break
        if notify is not None:
            notify(f"a worker process died; {len(held)} file(s) it may have held are re-run")
        # the files of the tasks in flight, again in the pool but a file a task: only
        # those in flight at a second death are then run alone
        again, rest = _run_pool(jobs, held, catalog_dir, outcomes, size=1)
        for item in again:  # each alone: only the file that kills its worker fails
            if _run_pool(1, [item], catalog_dir, outcomes, size=1)[0]:
                outcomes[item[0]] = _died(item[1])
        todo = rest + todo


#: The result column's words, by exit code.
STATUS = {0: "design", 2: "invalid", 3: "infeasible", 1: "bug"}


def summary_lines(outcomes: list[Outcome], out_dir: Path) -> list[str]:
    """The run's summary: a heading, one aligned line per file (its result, exit code and
    design or reason), then the counts. Plain text: rich's table took 0.4 s to lay out 400
    files, all of it after the workers had finished. User text (file names,
    titles, messages) is shown with its control characters escaped."""
    from advisor.core.io_safety import printable

    names = [
        printable(n, newlines=False) for n in display_names([Path(o.source) for o in outcomes])
    ]
    rows = [
        (name + _renamed(o), STATUS[o.code], str(o.code), printable(o.headline, newlines=False))
        for o, name in zip(outcomes, names, strict=True)
    ]
    head = ("file", "result", "exit", "design or reason")
    w = [max(len(r[k]) for r in [head, *rows]) for k in range(3)]
    counts = {k: sum(o.code == k for o in outcomes) for k in (0, 3, 2, 1)}
    return [
        f"{len(outcomes)} requirement files → {printable(str(out_dir), newlines=False)}",
        *(f"{a:<{w[0]}}  {b:<{w[1]}}  {c:>{w[2]}}  {d}".rstrip() for a, b, c, d in [head, *rows]),
        f"{counts[0]} designs, {counts[3]} infeasible, {counts[2]} invalid"
        + (f", {counts[1]} internal errors" if counts[1] else ""),
    ]


def _renamed(o: Outcome) -> str:
    """`` → name-2.report.toml`` for a file whose report took another name than its own
    (a second input of the same name), so the summary says which report is whose."""
    from advisor.core.io_safety import printable

    if o.report is None or Path(o.report).name == f"{Path(o.source).stem}.report.toml":
        return ""
    return f" → {printable(Path(o.report).name, newlines=False)}"


def print_summary(outcomes: list[Outcome], out_dir: Path) -> None:
    sys.stdout.write("".join(line + "\n" for line in summary_lines(outcomes, out_dir)))
