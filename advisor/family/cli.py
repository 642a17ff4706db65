"""``advisor family FAMILY.toml --out DIR``: the command of a family study.

Exit codes: 0 the study is complete (whatever the variants' own outcomes: they are in
designs.csv), 2 a bad family file or option (before any work starts), 130 interrupted
(rerun the same command to resume), 1 a variant hit a bug (its row says which).

Everything that can be checked is checked before a cluster starts or a file is written:
the options (a scheduler address of the form ``tcp://HOST:PORT``), the family file (its
size counted, not built), and the results folder (writable, and none of its results is an
input of the study, through symbolic links too).
"""

import argparse
import os
import re
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from advisor.family.adapter import AdvisorError, ExitCode, InputError

PROG = "advisor family"


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog=PROG,
        description="Advise every variant of a product family (the product of its axes) on "
        "this machine's cores or a Dask cluster; write designs.csv, summary.toml and "
        "family.html.",
        epilog="Exit codes: 0 study complete, 1 some variants hit a bug (see designs.csv), "
        "2 invalid family file or option (or a damaged chunk), 4 a chunk's worker died 3 "
        "times (killed, out of memory), 130 interrupted (4 and 130: run the same command "
        "again to resume).",
    )
    p.add_argument("family", type=Path, metavar="FAMILY.toml", help="the family file")
    # a str, made a Path once checked: Path('') is '.', and an empty DIR must be refused
    p.add_argument("--out", required=True, metavar="DIR", help="results folder")
    p.add_argument(
        "--scheduler",
        metavar="tcp://HOST:PORT",
        help="an existing dask.distributed scheduler (default: worker processes on this machine)",
    )
    p.add_argument(
        "--workers",
        type=int,
        metavar="N",
        help="worker processes on this machine (default: the number of cores)",
    )
    p.add_argument(
        "--chunk-size",
        type=int,
        metavar="N",
        help="variants per task (default: family.chunk_size, else from the cost model)",
    )
    p.add_argument(
        "--reports",
        action="store_true",
        help="also write each variant's report to DIR/reports/ (a design's or an infeasible one's, "
        "as --batch --out-dir writes them; an invalid variant has its reason in designs.csv)",
    )
    p.add_argument("--no-html", action="store_true", help="skip family.html")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.add_argument("--catalog-dir", type=Path, metavar="DIR", help="a directory of user catalogs")
    p.add_argument(
        "--max-variants",
        type=int,
        metavar="N",
        help="refuse a family of more variants than this (default: 1000000)",
    )
    return p


def _err(message: str) -> None:
    for line in message.splitlines() or [message]:
        print(f"advisor: {line}", file=sys.stderr)


#: ``tcp://HOST:PORT``: a host name, an IPv4 address or an IPv6 one in brackets.
_ADDRESS = re.compile(r"tcp://(\[[0-9A-Fa-f:.]+\]|[A-Za-z0-9](?:[A-Za-z0-9.-]{0,252}))?:(\d{1,5})")


def check_scheduler(address: str) -> str:
    """A scheduler address as this command connects to it, or an :class:`InputError`.

    Only ``tcp://HOST:PORT`` with PORT 1 to 65535 (what ``dask scheduler`` prints); an
    ``http://`` dashboard address, ``inproc://`` (in-process only) or a port that is not a
    number would fail after a connection attempt, or inside Dask.

    >>> check_scheduler("tcp://127.0.0.1:8786"), check_scheduler("tcp://[::1]:8786")
    ('tcp://127.0.0.1:8786', 'tcp://[::1]:8786')
    """
    from advisor.core.io_safety import show_repr

    m = _ADDRESS.fullmatch(address)
    if m is None or m.group(1) is None or not 1 <= int(m.group(2)) <= 65535:
        raise InputError(
            f"--scheduler {show_repr(address)}: not a scheduler address; "
            "give tcp://HOST:PORT (PORT 1 to 65535), as `dask scheduler` prints it"
        )
    return address


def check_options(args: argparse.Namespace) -> None:
    """The options alone, before the family file is read."""
    for flag, v in (
        ("--workers", args.workers),
        ("--chunk-size", args.chunk_size),
        ("--max-variants", args.max_variants),
    ):
        if v is not None and v < 1:
            raise InputError(f"{flag} = {v}: must be at least 1")
    if args.scheduler is not None and args.workers is not None:
        raise InputError(
            "--workers sets the processes on this machine; with --scheduler the cluster has its own"
        )
    if args.scheduler is not None:
        check_scheduler(args.scheduler)


def cap_workers(workers: int) -> int:
    """``--workers`` at most the CPUs this process may use, as ``--batch -j`` is capped: more
    worker processes than CPUs only share them, and each holds its own interpreter (100 000
    of them never start and fill the memory). A capped value is said in one line."""
    from advisor.many import usable_cpus

    cpus = usable_cpus()
    if workers <= cpus:
        return workers
    _err(f"--workers {workers}: capped at {cpus}, the CPUs this process may use")
    return cpus


#: Seconds an explicit --scheduler has to answer before the run is refused: a scheduler
#: on the network answers in milliseconds; Dask's own default waits 30 s.
CONNECT_TIMEOUT_S = 5.0


def probe_scheduler(address: str, timeout_s: float = CONNECT_TIMEOUT_S) -> None:
    """Refuse at once (an :class:`InputError`) a scheduler address nothing answers at: a TCP
    connection within ``timeout_s``, before Dask's client retries for its own timeout."""
    import socket

    m = _ADDRESS.fullmatch(address)
    if m is None:  # check_scheduler has refused it already
        return
    host, port = m.group(1).strip("[]"), int(m.group(2))
    try:
        socket.create_connection((host, port), timeout=timeout_s).close()
    except TimeoutError:
        raise InputError(
            f"--scheduler {address}: nothing answered within {timeout_s:g} s"
        ) from None
    except OSError as exc:
        why = exc.strerror or type(exc).__name__
        raise InputError(f"--scheduler {address}: nothing answered ({why})") from None


#: What a study writes into DIR: files, then folders.
RESULT_FILES = ("designs.csv", "summary.toml", "family.html")
RESULT_DIRS = ("chunks", "reports")


def _inside(path: str, folder: str) -> bool:
    return path == folder or path.startswith(folder.rstrip(os.sep) + os.sep)


def results(html: bool = True, reports: bool = True) -> tuple[list[str], list[str]]:
    """The files and the folders a study writes into DIR."""
    files = [f for f in RESULT_FILES if html or f != "family.html"]
    return files, [d for d in RESULT_DIRS if reports or d != "reports"]


def check_not_an_input(
    out: Path, inputs: tuple[str, ...], html: bool = True, reports: bool = True
) -> None:
    """Refuse a DIR where the study would write over one of its own inputs (the family
    file or a member's base): compared by real path, so a symbolic link either way counts,
    and by file identity (a hard link)."""
    from advisor.core.io_safety import same_file, show

    files, folders = results(html, reports)
    for given in inputs:
        real = os.path.realpath(given)
        for name in files:
            target = out / name
            if os.path.realpath(target) == real or same_file(target, Path(given)):
                raise InputError(
                    f"--out {show(out, 200)}: the study writes {name} there, which is its "
                    f"input {show(given, 200)}; choose another --out"
                )
        for name in folders:
            if _inside(real, os.path.realpath(out / name)):
                raise InputError(
                    f"--out {show(out, 200)}: the study writes into {name}/ there, which holds "
                    f"its input {show(given, 200)}; choose another --out"
                )


def check_out(out: Path, inputs: tuple[str, ...], html: bool, reports: bool) -> None:
    """DIR as the study will use it, checked without writing anything."""
    import stat

    from advisor.core.io_safety import show

    if out.exists() and not out.is_dir():
        raise InputError(f"--out {show(out, 200)}: exists and is not a directory")
    check_not_an_input(out, inputs, html, reports)
    files, folders = results(html, reports)
    for name in (*files, *folders):
        try:
            mode = os.stat(out / name).st_mode
        except OSError:
            continue
        want_dir = name in RESULT_DIRS
        if stat.S_ISDIR(mode) != want_dir or not (want_dir or stat.S_ISREG(mode)):
            what = "a folder" if want_dir else "a regular file"
            raise InputError(
                f"--out {show(out, 200)}: {name} there is not {what}; the study writes "
                f"its {name} there (move it away or choose another --out)"
            )


def make_out_dir(out: Path) -> list[Path]:
    """Create DIR (and missing parents); return the folders created, outermost first."""
    from advisor.core.io_safety import show

    missing = []
    p = out.absolute()
    while not p.exists() and p != p.parent:
        missing.append(p)
        p = p.parent
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError(f"--out {show(out, 200)}: cannot create ({exc.strerror})") from None
    return missing[::-1]


def check_writable(folder: Path, what: str) -> None:
    """Create and remove a file in ``folder``: the one sure test (permissions, a read-only
    file system, root's privileges, access lists all answer it)."""
    import tempfile

    from advisor.core.io_safety import show

    try:
        fd, probe = tempfile.mkstemp(prefix=".advisor-probe.", suffix=".tmp", dir=folder)
    except OSError as exc:
        raise InputError(
            f"{what} {show(folder, 200)}: cannot write there ({exc.strerror})"
        ) from None
    os.close(fd)
    os.unlink(probe)


def remove_if_empty(created: list[Path]) -> None:
    """Remove the folders this run created (innermost first) that are still empty; in a
    DIR it created, first what a run that wrote no result leaves (:func:`clear_unstarted`)."""
    if created:
        clear_unstarted(created[-1])
    for d in reversed(created):
        try:
            d.rmdir()  # refuses a folder that is not empty
        except OSError:
            return


def clear_unstarted(out: Path) -> None:
    """A DIR's empty ``reports/`` and its ``chunks/`` holding no chunk (the manifest alone
    resumes nothing), removed: only for a DIR this run created, where nothing is another's."""
    from advisor.family.study import MANIFEST

    chunks = out / "chunks"
    try:
        (out / "reports").rmdir()  # refuses a folder holding a report
    except FileNotFoundError:
        pass
    except OSError:
        return
    try:
        if set(os.listdir(chunks)) - {MANIFEST}:
            return  # a chunk: kept for a resume
        (chunks / MANIFEST).unlink(missing_ok=True)
        chunks.rmdir()
    except OSError:
        return


#: Loggers that write to the terminal on their own: Dask's (e.g. "Couldn't gather keys"
#: after a worker died, which the study recovers from), tornado's, asyncio's.
NOISY_LOGGERS = ("distributed", "tornado", "bokeh", "asyncio")


def quiet_dask_logging() -> None:
    """Keep Dask's log lines off the user's terminal in this process: what matters reaches
    the user as an exception, in one line."""
    import logging

    silent = logging.CRITICAL + 1
    for name in NOISY_LOGGERS:
        lg = logging.getLogger(name)
        lg.setLevel(silent)
        for h in lg.handlers:
            h.setLevel(silent)
    # the loggers of Dask's modules carry levels of their own (distributed.client: warning)
    # and propagate to the handler silenced above; the handler decides


def make_client(scheduler: str) -> Any:
    """A Dask client on the given scheduler (refused at once if nothing answers there)."""
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # import-time deprecation notes of Dask's own
        from dask.distributed import Client
    quiet_dask_logging()
    probe_scheduler(scheduler)
    return Client(scheduler, timeout=f"{CONNECT_TIMEOUT_S:g}s")


def make_runner(args: argparse.Namespace) -> tuple[Any, Callable[[], None]]:
    """What runs the chunks, and what closes it: the cluster of ``--scheduler`` (Dask), or
    this machine (this process for one worker, else worker processes forked from it)."""
    if args.scheduler is None:
        from advisor.family.local import ForkPool, InProcess
        from advisor.many import usable_cpus

        workers = args.workers or usable_cpus()
        return (InProcess() if workers == 1 else ForkPool(workers)), lambda: None
    from advisor.family.study import DaskRunner

    try:
        client = make_client(args.scheduler)
    except (OSError, TimeoutError) as exc:
        why = (str(exc).splitlines() or [type(exc).__name__])[0]
        raise InputError(f"--scheduler {args.scheduler}: cannot connect ({why})") from None
    return DaskRunner(client), client.close


def main(argv: list[str]) -> int:
    try:
        args = build_parser().parse_args(argv)
    except SystemExit as exc:
        return int(exc.code or 0)
    if not args.out.strip():  # an unset variable (--out "$OUT") would write into '.'
        blank = "an empty" if args.out == "" else "a blank"
        _err(f"--out: {blank} folder name; give the folder for the results")
        return ExitCode.INVALID_INPUT
    args.out = Path(args.out)
    try:
        return _run(args)
    except AdvisorError as exc:
        _err(str(exc))
        return exc.exit_code
    except KeyboardInterrupt:
        from advisor.family.study import remove_own_temporaries

        remove_own_temporaries(args.out)
        if (args.out / "chunks").is_dir():
            _err(
                f"interrupted; the chunks written so far are kept in {args.out}/chunks: run "
                "the same command again to resume"
            )
        else:
            _err("interrupted before any result was written")
        return 130
    except Exception as exc:  # a bug: one line, never a traceback
        _err(f"internal error ({type(exc).__name__}: {exc}); please report it with the input")
        return ExitCode.INTERNAL_ERROR


def _run(args: argparse.Namespace) -> int:
    from advisor.family.spec import DEFAULT_MAX_VARIANTS, read_family

    check_options(args)
    if args.workers is not None:
        args.workers = cap_workers(args.workers)
    # every error of the family file is raised here, before any work (its size first)
    family = read_family(args.family, args.max_variants or DEFAULT_MAX_VARIANTS)
    if args.catalog_dir is not None:
        from advisor.family.adapter import check_catalogs

        check_catalogs(str(args.catalog_dir))
    out: Path = args.out
    check_out(out, family.inputs, not args.no_html, args.reports)
    from advisor.family.study import precheck_manifest

    size = args.chunk_size or family.chunk_size
    precheck_manifest(out, family, size, args.reports, args.catalog_dir)
    created = make_out_dir(out)
    try:
        check_writable(out, "--out")
        for name in results(reports=args.reports)[1]:
            if (out / name).is_dir():
                check_writable(out / name, "--out")
        return run(family, out, args)
    except BaseException:
        remove_if_empty(created)  # no empty folder left behind by a run that failed
        raise


def chunk_size(args: argparse.Namespace, family: Any, out: Path, workers: int) -> int:
    """Variants per chunk: as given, as the family file says, as the study being resumed
    had it, or from the cost model."""
    from advisor.family.study import auto_chunk_size, previous_chunk_size

    return (
        args.chunk_size
        or family.chunk_size
        or previous_chunk_size(out)
        or auto_chunk_size(family.size, workers)
    )


def compute(family: Any, out: Path, args: argparse.Namespace, summary: Any) -> tuple[Any, int, int]:
    """Run the study's chunks, each merged into ``summary`` (a
    :class:`advisor.family.summary.SummaryBuilder`) as it arrives; (what was done, the
    chunk size, the workers)."""
    from advisor.family.study import Progress, chunk_count, run_study

    runner, close = make_runner(args)
    progress = None
    try:
        workers = runner.workers
        size = chunk_size(args, family, out, workers)
        chunks = chunk_count(family.size, size)
        if not args.quiet:
            print(
                f"{family.name}: {family.size} variants in {chunks} chunks of {size} on "
                f"{workers} workers → {out}",
                file=sys.stderr,
            )
            progress = Progress(chunks, family.size)
        res = run_study(
            family,
            out,
            runner,
            size,
            reports=args.reports,
            catalog_dir=args.catalog_dir,
            progress=progress,
            summary=summary,
        )
    except BaseException:
        if progress is not None:
            progress.end_line()  # the message that follows starts on a line of its own
        raise
    finally:
        close()
    return res, size, workers


def new_summary(family: Any, args: argparse.Namespace) -> Any:
    """The summary the chunks are merged into; it keeps the rows family.html plots."""
    from advisor.family.summary import SummaryBuilder

    keep = None
    if not args.no_html:
        from advisor.family.html import plot_points

        keep = [plot_points(m) for m in family.members]
    return SummaryBuilder(family, keep)


def write_results(
    family: Any, out: Path, args: argparse.Namespace, extra: dict, builder: Any
) -> dict:
    """designs.csv (the chunks joined), then summary.toml and family.html from the summary
    merged chunk by chunk (``builder``; the chunks of an earlier run are merged as they are
    joined); the summary document. Each is built before any is replaced: a damaged chunk or
    a failure leaves the folder's previous results as they were."""
    from advisor.family.adapter import write_atomic
    from advisor.family.study import join_to_temp, writing
    from advisor.family.summary import summary_text

    kept = "the chunks are kept: free space and run the same command again to write the results"
    with writing(out / "designs.csv", kept):
        joined = join_to_temp(family, out, extra["chunk_size"], builder)
    try:
        doc, pictures = builder.finish(extra)
        summary = summary_text(doc)
        page = None
        if not args.no_html:
            from advisor.family.html import render

            page = render(family, doc, pictures)
        os.replace(joined, out / "designs.csv")
    except BaseException:
        joined.unlink(missing_ok=True)
        raise
    with writing(out / "summary.toml", kept):
        write_atomic(out / "summary.toml", summary)
    if page is not None:
        with writing(out / "family.html", kept):
            write_atomic(out / "family.html", page)
    return doc


def run(family: Any, out: Path, args: argparse.Namespace) -> int:
    t0 = time.perf_counter()
    summary = new_summary(family, args)
    res, size, workers = compute(family, out, args, summary)
    extra = {"chunk_size": size, "chunks": res.chunks, "workers": workers}
    c = write_results(family, out, args, extra, summary)["counts"]
    designs = out / "designs.csv"
    print(
        f"{family.size} variants: {c['design']} designs, {c['infeasible']} infeasible, "
        f"{c['invalid']} invalid"
        + (f", {c['internal_error']} internal errors" if c["internal_error"] else "")
        + f"; {res.computed} of {res.chunks} chunks computed in {time.perf_counter() - t0:.1f} s"
        + f" → {designs}"
    )
    if c["internal_error"]:
        _err(f"{c['internal_error']} variants hit a bug; see status internal_error in {designs}")
        return ExitCode.INTERNAL_ERROR
    return ExitCode.OK
