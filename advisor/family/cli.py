"""``advisor family FAMILY.toml --out DIR``: the command of a family study.

Exit codes: 0 the study is complete (whatever the variants' own outcomes: they are in
designs.csv), 2 a bad family file or option (before any work starts), 130 interrupted
(rerun the same command to resume), 1 a variant hit a bug (its row says which).
"""

import argparse
import os
import sys
import time
from pathlib import Path
from typing import Any

from advisor.family.adapter import AdvisorError, ExitCode

PROG = "advisor family"


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog=PROG,
        description="Advise every variant of a product family (the product of its axes) on a "
        "Dask cluster; write designs.csv, summary.toml and family.html.",
        epilog="Exit codes: 0 study complete, 2 invalid family file or option, 130 "
        "interrupted (run the same command again to resume).",
    )
    p.add_argument("family", type=Path, metavar="FAMILY.toml", help="the family file")
    p.add_argument("--out", type=Path, required=True, metavar="DIR", help="results folder")
    p.add_argument(
        "--scheduler",
        metavar="tcp://HOST:PORT",
        help="an existing dask.distributed scheduler (default: a local cluster on this machine)",
    )
    p.add_argument(
        "--workers",
        type=int,
        metavar="N",
        help="worker processes of the local cluster (default: the number of cores)",
    )
    p.add_argument(
        "--chunk-size",
        type=int,
        metavar="N",
        help="variants per task (default: family.chunk_size, else from the cost model)",
    )
    p.add_argument(
        "--reports", action="store_true", help="also write every variant's report to DIR/reports/"
    )
    p.add_argument("--no-html", action="store_true", help="skip family.html (and matplotlib)")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.add_argument("--catalog-dir", type=Path, metavar="DIR", help="a directory of user catalogs")
    return p


def _err(message: str) -> None:
    for line in message.splitlines() or [message]:
        print(f"advisor: {line}", file=sys.stderr)


def make_client(scheduler: str | None, workers: int | None) -> tuple[Any, Any]:
    """A Dask client on the given scheduler, or on a new local cluster (returned too)."""
    import logging

    from dask.distributed import Client, LocalCluster

    if scheduler:
        return Client(scheduler, timeout="20s"), None
    cluster = LocalCluster(
        n_workers=workers or os.cpu_count() or 1,
        threads_per_worker=1,
        processes=True,
        dashboard_address=None,
        silence_logs=logging.ERROR,
    )
    return Client(cluster), cluster


def main(argv: list[str]) -> int:
    try:
        args = build_parser().parse_args(argv)
    except SystemExit as exc:
        return int(exc.code or 0)
    try:
        return _run(args)
    except AdvisorError as exc:
        _err(str(exc))
        return exc.exit_code
    except KeyboardInterrupt:
        _err(
            f"interrupted; the chunks written so far are kept in {args.out}/chunks: run the "
            "same command again to resume"
        )
        return 130
    except Exception as exc:  # a bug: one line, never a traceback
        _err(f"internal error ({type(exc).__name__}: {exc}); please report it with the input")
        return ExitCode.INTERNAL_ERROR


def _run(args: argparse.Namespace) -> int:
    from advisor.family.adapter import InputError
    from advisor.family.spec import read_family

    for flag, v in (("--workers", args.workers), ("--chunk-size", args.chunk_size)):
        if v is not None and v < 1:
            raise InputError(f"{flag} = {v}: must be at least 1")
    if args.scheduler is not None and args.workers is not None:
        raise InputError(
            "--workers sizes the local cluster; with --scheduler the cluster has its own"
        )
    if args.scheduler is not None and not args.scheduler.strip():
        raise InputError("--scheduler: empty address; give tcp://HOST:PORT")
    family = read_family(args.family)  # every input error is raised here, before any work
    out: Path = args.out
    if out.exists() and not out.is_dir():
        raise InputError(f"--out {out}: exists and is not a directory")
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError(f"--out {out}: cannot create ({exc.strerror})") from None
    return run(family, out, args)


def run(family: Any, out: Path, args: argparse.Namespace) -> int:
    from advisor.family.study import (
        Progress,
        auto_chunk_size,
        join_chunks,
        previous_chunk_size,
        run_study,
    )
    from advisor.family.summary import read_rows, summarize, write_summary

    try:
        client, cluster = make_client(args.scheduler, args.workers)
    except (OSError, TimeoutError) as exc:
        from advisor.family.adapter import InputError

        why = (str(exc).splitlines() or [type(exc).__name__])[0]
        raise InputError(f"--scheduler {args.scheduler}: cannot connect ({why})") from None
    try:
        workers = len(client.scheduler_info()["workers"]) or 1
        size = (
            args.chunk_size
            or family.chunk_size
            or previous_chunk_size(out)
            or auto_chunk_size(family.size, workers)
        )
        chunks = -(-family.size // size)
        if not args.quiet:
            print(
                f"{family.name}: {family.size} variants in {chunks} chunks of {size} on "
                f"{workers} workers → {out}",
                file=sys.stderr,
            )
        progress = None if args.quiet else Progress(chunks, family.size)
        t0 = time.perf_counter()
        res = run_study(
            family,
            out,
            client,
            size,
            reports=args.reports,
            catalog_dir=args.catalog_dir,
            progress=progress,
        )
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    designs = join_chunks(family, out, size)
    rows = read_rows(designs)
    doc = summarize(
        family,
        rows,
        {"chunk_size": size, "chunks": res.chunks, "workers": workers},
    )
    write_summary(out / "summary.toml", doc)
    if not args.no_html:
        from advisor.family.html import write_html

        write_html(out / "family.html", family, rows, doc)
    c = doc["counts"]
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
