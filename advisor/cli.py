"""``advisor``: the command line.

``advisor --batch REQ.toml`` prints the report TOML on stdout; with ``-o OUT.toml`` it writes
the report atomically and prints a short summary instead. ``--format json|md|html`` writes
the report as JSON or as a datasheet (:mod:`advisor.datasheet`; matplotlib for html only).
Exit codes: see :class:`advisor.core.errors.ExitCode`. Never a traceback: every failure is one
line per problem on stderr.

The batch path must stay light: it imports neither textual nor rich (rich only for the
summary of ``-o``) nor scipy.optimize.
"""

import argparse
import os
import sys
from pathlib import Path

from advisor import __version__
from advisor.core.errors import AdvisorError, ExitCode, InfeasibleError

PROG = "advisor"


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog=PROG,
        description="Rules-based design advisor for electromechanical drives.",
        epilog="Exit codes: 0 design found, 2 invalid input, 3 no feasible design. "
        "`advisor schema` prints the JSON Schema of requirement files.",
    )
    p.add_argument(
        "requirements",
        nargs="?",
        type=Path,
        help="open the terminal wizard prefilled from this requirement file",
    )
    p.add_argument(
        "--batch",
        metavar="REQ.toml",
        type=Path,
        nargs="+",
        help="advise on requirement files (or directories of them), no UI",
    )
    p.add_argument(
        "--out-dir",
        metavar="DIR",
        type=Path,
        help="with several inputs: write one NAME.report.toml per input here, then a summary",
    )
    p.add_argument(
        "-j",
        "--jobs",
        metavar="N",
        type=int,
        default=1,
        help="advise N files at a time in worker processes (with --out-dir)",
    )
    p.add_argument(
        "-o",
        "--output",
        metavar="OUT.toml",
        type=Path,
        help="write the report here (atomically) and print a summary instead",
    )
    p.add_argument(
        "--format",
        choices=("toml", "json", "md", "html"),
        help="the report as TOML (the archive; default), JSON (for tools), Markdown or a "
        "self-contained HTML datasheet with plots (needs the [report] extra); with -o and no "
        "--format, the file's suffix decides",
    )
    p.add_argument(
        "--catalog-dir",
        metavar="DIR",
        type=Path,
        help="a directory of user catalogs added to the shipped ones",
    )
    p.add_argument("--version", action="version", version=f"{PROG} {__version__}")
    return p


def _err(message: str) -> None:
    for line in message.splitlines() or [message]:
        print(f"{PROG}: {line}", file=sys.stderr)


def run_batch(
    req_path: Path, output: Path | None, catalog_dir: Path | None, fmt: str | None = None
) -> int:
    # pydantic scans every installed package's entry points for plugins on its first model
    # (about 7 ms of importlib.metadata); the advisor uses none.
    os.environ.setdefault("PYDANTIC_DISABLE_PLUGINS", "__all__")
    from advisor.core.engine import advise
    from advisor.core.report import write_atomic
    from advisor.core.requirements import read_requirements

    if fmt is None:
        from advisor.datasheet import format_of

        fmt = (format_of(output) if output is not None else None) or "toml"
    req = read_requirements(req_path)
    report = advise(req, catalog_dir)
    if fmt == "toml":
        from advisor.core.report import to_toml

        text = to_toml(report)
    else:
        from advisor.datasheet import MissingExtra, render

        try:
            text = render(report, fmt)
        except MissingExtra as exc:
            _err(str(exc))
            return ExitCode.INVALID_INPUT
    if output is None:
        sys.stdout.write(text)
        return ExitCode.OK
    try:
        write_atomic(output, text)
    except OSError as exc:
        _err(f"{output}: cannot write the report ({exc.strerror}); nothing was written")
        return ExitCode.INVALID_INPUT
    from advisor.summary import print_summary

    print_summary(report, output)
    return ExitCode.OK


def run_many(inputs: list[Path], out_dir: Path, catalog_dir: Path | None, jobs: int) -> int:
    os.environ.setdefault("PYDANTIC_DISABLE_PLUGINS", "__all__")
    from advisor import many

    missing = [p for p in inputs if not p.exists()]
    if missing:
        _err(f"{missing[0]}: no such file or directory")
        return ExitCode.INVALID_INPUT
    try:
        worst, outcomes = many.run_many(inputs, out_dir, catalog_dir, jobs)
    except OSError as exc:
        _err(f"{out_dir}: cannot write reports there ({exc.strerror})")
        return ExitCode.INVALID_INPUT
    if not outcomes:
        _err("no requirement files (*.toml) among the inputs")
        return ExitCode.INVALID_INPUT
    many.print_summary(outcomes, out_dir)
    for o in outcomes:
        if o.code != ExitCode.OK:
            for line in (o.headline, *o.messages):
                print(f"{PROG}: {o.source}: {line.strip()}", file=sys.stderr)
    return worst


def run_wizard(path: Path | None, catalog_dir: Path | None) -> int:
    """``advisor`` / ``advisor REQ.toml``: the terminal wizard (textual is imported here only)."""
    if path is not None and not path.is_file():
        _err(f"{path}: no such file" if not path.exists() else f"{path}: not a file")
        return ExitCode.INVALID_INPUT
    from advisor.tui.app import run

    try:
        return run(path, catalog_dir)
    except AdvisorError as exc:
        _err(str(exc))
        return exc.exit_code


def run_schema(argv: list[str]) -> int:
    """``advisor schema``: the JSON Schema of requirement files (for editors with TOML schema
    support); ``--markdown``: the README's tables of requirement keys."""
    p = argparse.ArgumentParser(
        prog=f"{PROG} schema",
        description="Print the JSON Schema of requirement files, from the requirement models.",
    )
    p.add_argument(
        "--markdown", action="store_true", help="print the tables of requirement keys instead"
    )
    try:
        args = p.parse_args(argv)
    except SystemExit as exc:
        return int(exc.code or 0)
    from advisor.core import schema

    sys.stdout.write(schema.key_tables() if args.markdown else schema.schema_text())
    return ExitCode.OK


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if argv[:1] == ["schema"]:
        return run_schema(argv[1:])
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # argparse: --help, --version, or a usage error (code 2)
        return int(exc.code or 0)
    inputs = args.batch
    if inputs is None:
        return run_wizard(args.requirements, args.catalog_dir)
    if args.jobs < 1:
        _err(f"-j/--jobs = {args.jobs}: must be at least 1")
        return ExitCode.INVALID_INPUT
    many = len(inputs) > 1 or inputs[0].is_dir() or args.out_dir is not None
    if many:
        if args.output is not None:
            _err("-o/--output takes one input; with several use --out-dir DIR")
            return ExitCode.INVALID_INPUT
        if args.out_dir is None:
            _err("several inputs (or a directory) need --out-dir DIR for their reports")
            return ExitCode.INVALID_INPUT
        if args.format not in (None, "toml"):
            _err(f"--format {args.format} takes one input; with --out-dir the reports are TOML")
            return ExitCode.INVALID_INPUT
        return run_many(inputs, args.out_dir, args.catalog_dir, args.jobs)
    try:
        return run_batch(inputs[0], args.output, args.catalog_dir, args.format)
    except InfeasibleError as exc:
        _err(str(exc))
        return ExitCode.INFEASIBLE
    except AdvisorError as exc:
        _err(str(exc))
        return exc.exit_code
    except BrokenPipeError:  # `advisor --batch r.toml | head`: the reader left; not an error
        try:
            sys.stdout = open(os.devnull, "w")
        except OSError:
            pass
        return ExitCode.OK
    except KeyboardInterrupt:
        _err("interrupted; nothing was written")
        return 130
    except Exception as exc:  # a bug: say so in one line, never a traceback
        _err(f"internal error ({type(exc).__name__}: {exc}); please report it with the input file")
        return ExitCode.INTERNAL_ERROR
