"""``advisor``: the command line.

``advisor --batch REQ.toml`` prints the report TOML on stdout; with ``-o OUT.toml`` it writes
the report atomically and prints a short summary instead. ``--format json|md|html`` writes
the report as JSON or as a datasheet (:mod:`advisor.datasheet`; matplotlib for html only).
Exit codes: see :class:`advisor.core.errors.ExitCode`. Never a traceback: every failure is one
line per problem on stderr.

The batch path must stay light: it imports neither textual nor rich (the summary of ``-o`` is
plain text) nor scipy; each path imports only the application its file names.
"""

import argparse
import io
import os
import sys
from pathlib import Path
from typing import Any

from advisor import __version__
from advisor.core.errors import AdvisorError, ExitCode, InfeasibleError
from advisor.core.io_safety import LINE_CHARS as LINE_CHARS  # re-exported
from advisor.core.io_safety import PROG
from advisor.core.io_safety import print_error as print_error  # re-exported


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog=PROG,
        description="Rules-based design advisor for electromechanical drives.",
        epilog="Exit codes: 0 design found, 2 invalid input, 3 no feasible design. "
        "`advisor schema` prints the JSON Schema of requirement files. "
        "`advisor diff A.toml B.toml` says what changed between two reports. "
        "Product-family studies: advisor family FAMILY.toml --out DIR (see advisor family -h).",
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
        metavar="DIR",  # a str: Path('') is '.', and an empty DIR must be refused
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


def _silence_stdout() -> None:
    """Point stdout at /dev/null: the reader left (a closed pipe) or the device is full, and
    the interpreter's last flush must not fail again at exit."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except (OSError, ValueError, AttributeError, io.UnsupportedOperation):
        pass


def _stdout_failed(exc: OSError, what: str, after: str = "it is incomplete") -> int:
    _silence_stdout()
    print_error(f"standard output: cannot write {what} ({exc.strerror or exc}); {after}")
    return ExitCode.INVALID_INPUT


def _warn_ignored(warnings: list[str], source: Path | None = None) -> None:
    """Options the design does not use, said on stderr too (they are in the report)."""
    from advisor.core.ignored import IGNORED_PREFIX

    for w in warnings:
        if w.startswith(IGNORED_PREFIX):
            print_error(f"{source}: warning: {w}" if source is not None else f"warning: {w}")


def _check_output(output: Path, req_path: Path) -> None:
    """Refuse a target that would destroy something, before computing."""
    from advisor.core.io_safety import OutputError, check_target, same_file, show

    if same_file(output, req_path):
        raise OutputError(
            f"{show(output, 200)}: is the requirement file itself; the report would "
            "replace it (choose another -o)"
        )
    check_target(output)


def _advise_or_why(req: Any, catalog_dir: Path | None) -> tuple[Any, Any]:
    """(report, None), or (a report saying why, the InfeasibleError) when no design is
    feasible: written where a design's report would be, in every format."""
    from advisor.core.engine import advise

    try:
        return advise(req, catalog_dir), None
    except InfeasibleError as exc:
        from advisor.infeasible import infeasible_report

        return infeasible_report(req, exc), exc


def _text(report: Any, fmt: str) -> str | None:
    """The report in ``fmt``; None (said on stderr) when the format's extra is missing."""
    if fmt == "toml":
        from advisor.core.report import to_toml

        return to_toml(report)
    from advisor.datasheet import MissingExtra, render

    try:
        return render(report, fmt)
    except MissingExtra as exc:
        print_error(str(exc))
        return None


def _to_stdout(text: str, done: int) -> int:
    try:
        sys.stdout.write(text)
        sys.stdout.flush()
    except BrokenPipeError:
        raise
    except OSError as exc:  # /dev/full, a full disk: never exit 0 with half a report
        return _stdout_failed(exc, "the report")
    return done


def _to_file(report: Any, text: str, output: Path, done: int) -> int:
    """Write the report atomically, then its summary on stdout."""
    from advisor.core.io_safety import OutputError, show, write_atomic

    try:
        write_atomic(output, text)
    except OutputError:
        raise
    except OSError as exc:
        print_error(
            f"{show(output, 200)}: cannot write the report ({exc.strerror}); nothing was written"
        )
        return ExitCode.INVALID_INPUT
    from advisor.summary import print_summary

    try:
        print_summary(report, output)
        sys.stdout.flush()
    except BrokenPipeError:  # the reader left
        _silence_stdout()
        return done
    except OSError as exc:
        return _stdout_failed(exc, "the summary", f"the report was written to {show(output, 200)}")
    return done


def run_batch(
    req_path: Path, output: Path | None, catalog_dir: Path | None, fmt: str | None = None
) -> int:
    from advisor.core import pydantic_plugins

    pydantic_plugins.disable()  # the advisor uses no pydantic plugin: no metadata scan
    from advisor.core.reading import read_requirements

    if fmt is None:
        from advisor.datasheet import format_of

        fmt = (format_of(output) if output is not None else None) or "toml"
    if output is not None:
        _check_output(output, req_path)
    req = read_requirements(req_path)
    report, infeasible = _advise_or_why(req, catalog_dir)
    _warn_ignored(report.warnings)
    text = _text(report, fmt)
    if text is None:
        return ExitCode.INVALID_INPUT
    done = ExitCode.OK if infeasible is None else ExitCode.INFEASIBLE
    if infeasible is not None:
        print_error(str(infeasible))
    if output is None:
        return _to_stdout(text, done)
    return _to_file(report, text, output, done)


def run_many(inputs: list[Path], out_dir: Path, catalog_dir: Path | None, jobs: int) -> int:
    from advisor.core import pydantic_plugins

    pydantic_plugins.disable()
    from advisor import many
    from advisor.core.io_safety import show

    missing = [p for p in inputs if not p.exists()]
    if missing:
        print_error(f"{show(missing[0], 200)}: no such file or directory")
        return ExitCode.INVALID_INPUT
    try:
        worst, outcomes = many.run_many(inputs, out_dir, catalog_dir, jobs, notify=print_error)
    except many.Interrupted as exc:
        print_error(
            f"interrupted; {exc.written} of {exc.total} reports were written to "
            f"{show(out_dir, 200)}"
        )
        return 130
    except OSError as exc:
        print_error(f"{show(out_dir, 200)}: cannot write reports there ({exc.strerror})")
        return ExitCode.INVALID_INPUT
    if not outcomes:
        print_error("no requirement files (*.toml) among the inputs")
        return ExitCode.INVALID_INPUT
    try:
        many.print_summary(outcomes, out_dir)
        sys.stdout.flush()
    except (BrokenPipeError, SystemExit):  # the reader left; the exit code still tells
        _silence_stdout()
    except OSError as exc:
        _stdout_failed(exc, "the summary", f"the reports were written to {show(out_dir, 200)}")
        worst = many.worse(worst, ExitCode.INVALID_INPUT)
    names = many.display_names([Path(o.source) for o in outcomes])
    for o, name in zip(outcomes, names, strict=True):
        if o.code != ExitCode.OK:
            for line in (o.headline, *o.messages):
                print_error(f"{name}: {line.strip()}")
        else:
            _warn_ignored(list(o.messages), Path(name))
    return worst


def run_wizard(path: Path | None, catalog_dir: Path | None) -> int:
    """``advisor`` / ``advisor REQ.toml``: the terminal wizard (textual is imported here only)."""
    if path is not None and not path.is_file():
        print_error(f"{path}: no such file" if not path.exists() else f"{path}: not a file")
        return ExitCode.INVALID_INPUT
    if path is not None:  # a file that cannot be read is said first, terminal or not
        from advisor.core.io_safety import read_toml

        read_toml(path)
    if not (_is_terminal(sys.stdin) and _is_terminal(sys.stdout)):
        # a wizard on a pipe would wait for keys that never come (and spin the CPU)
        print_error(
            "the wizard needs a terminal (standard input and output are not one); "
            "for a report without it: advisor --batch REQ.toml"
        )
        return ExitCode.INVALID_INPUT
    from advisor.tui.app import run

    return run(path, catalog_dir)


def run_schema(argv: list[str]) -> int:
    """``advisor schema``: the JSON Schema of requirement files (for editors with TOML schema
    support); ``--markdown``: the tables of requirement keys (docs/reference/keys.md)."""
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


#: The variables that size numpy's BLAS thread pool (OpenBLAS reads the first, an OpenMP
#: build the second).
BLAS_THREAD_VARIABLES = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS")


def one_blas_thread(environ: Any = os.environ) -> None:
    """One BLAS thread, unless the user sized the pool: OpenBLAS starts a thread per core
    when numpy is imported, and the advisor does no matrix work (its arrays are element by
    element), so the pool only costs CPU at every start. Called before numpy is imported."""
    if not any(name in environ for name in BLAS_THREAD_VARIABLES):
        for name in BLAS_THREAD_VARIABLES:
            environ[name] = "1"


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    one_blas_thread()
    from advisor.core import pydantic_plugins

    pydantic_plugins.disable()  # every path: the advisor uses no pydantic plugin
    sub = _subcommand(argv[0]) if argv else None
    if sub is not None:
        return _run_subcommand(sub, argv[1:])
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # argparse: --help, --version, or a usage error (code 2)
        return int(exc.code or 0)
    try:
        return _dispatch(args)
    except InfeasibleError as exc:
        print_error(str(exc))
        return ExitCode.INFEASIBLE
    except AdvisorError as exc:
        print_error(str(exc))
        return exc.exit_code
    except BrokenPipeError:  # `advisor --batch r.toml | head`: the reader left; not an error
        _silence_stdout()
        return ExitCode.OK
    except KeyboardInterrupt:
        print_error("interrupted; nothing was written")
        return 130
    except RecursionError:  # a guard missed some deep structure: still one line, exit 2
        print_error("the input is nested too deeply to be read")
        return ExitCode.INVALID_INPUT
    except Exception as exc:  # a bug: say so in one line, never a traceback
        print_error(
            f"internal error ({type(exc).__name__}: {exc}); please report it with the input file"
        )
        return ExitCode.INTERNAL_ERROR


def _subcommand(name: str) -> Any:
    """The ``main(argv)`` of a subcommand, each imported only on its own path (family needs
    Dask, verify the whole advisor); None if ``name`` is none."""
    if name == "schema":
        return run_schema
    if name == "diff":  # what changed between two reports (exit 0 same, 1 differ, 2)
        from advisor.diff import main as diff_main

        return diff_main
    if name == "rules":  # the rule table, from the registry of rules
        from advisor.core.rules_table import main as rules_main

        return rules_main
    if name == "verify":  # published worked examples, computed again (exit 0 / 1)
        from advisor.verify import main as verify_main

        return verify_main
    if name == "family":  # product-family studies (Dask): imported only on this path
        from advisor.family.cli import main as family_main

        return family_main
    return None


def _run_subcommand(sub: Any, argv: list[str]) -> int:
    """Run a subcommand under the batch's contract: a reader that leaves (``| head -1``) ends
    it quietly, a full or failing stdout is one line and exit 2, never a traceback."""
    try:
        code = sub(argv)
        sys.stdout.flush()  # a buffered tail fails here, not at the interpreter's exit
        return code
    except BrokenPipeError:  # the reader left: not an error
        _silence_stdout()
        return ExitCode.OK
    except AdvisorError as exc:
        print_error(str(exc))
        return exc.exit_code
    except KeyboardInterrupt:
        print_error("interrupted")
        return 130
    except OSError as exc:
        if exc.filename is None:  # a write to stdout (/dev/full, an I/O error)
            return _stdout_failed(exc, "the output")
        from advisor.core.io_safety import show

        print_error(f"{show(exc.filename, 200)}: {exc.strerror or exc}")
        return ExitCode.INVALID_INPUT
    except Exception as exc:  # a bug: say so in one line, never a traceback
        print_error(
            f"internal error ({type(exc).__name__}: {exc}); please report it with the input file"
        )
        return ExitCode.INTERNAL_ERROR


def _is_terminal(stream) -> bool:
    try:
        return stream is not None and stream.isatty()
    except (ValueError, OSError):  # a closed stream
        return False


def _output_problem(output: str | None, out_dir_text: str | None) -> str | None:
    """What is wrong with the outputs asked for, said before anything is read: both -o and
    --out-dir, an empty or blank -o or --out-dir (a Path of '' is '.': the reports would land
    in the current folder, or a file be named by blanks, where the typical cause is an unset
    variable, ``--out-dir "$OUT"``), an --out-dir that exists and is no folder."""
    from advisor.core.io_safety import show

    if output is not None and out_dir_text is not None:
        return (
            "-o/--output and --out-dir exclude each other: -o writes one input's report to "
            "a file, --out-dir one report per input into a folder"
        )
    if output is not None and not output.strip():
        return f"-o/--output: {_blank(output)} output path; give the report's file name"
    if out_dir_text is not None and not out_dir_text.strip():
        return f"--out-dir: {_blank(out_dir_text)} folder name; give the folder for the reports"
    out_dir = Path(out_dir_text) if out_dir_text is not None else None
    if out_dir is not None and out_dir.exists() and not out_dir.is_dir():
        what = "a file, not a directory" if out_dir.is_file() else "not a directory"
        return f"--out-dir {show(out_dir, 200)}: is {what}; give a folder for the reports"
    return None


def _blank(text: str) -> str:
    """'an empty' for '', 'a blank' for a name of spaces or tabs alone."""
    return "an empty" if text == "" else "a blank"


def _dispatch(args: argparse.Namespace) -> int:
    inputs = args.batch
    if inputs is None:
        batch_only = [
            flag
            for flag, given in (
                ("-o/--output", args.output is not None),
                ("--out-dir", args.out_dir is not None),
                ("--format", args.format is not None),
                ("-j/--jobs", args.jobs != 1),
            )
            if given
        ]
        if batch_only:  # without --batch the wizard would open and the option do nothing
            name = args.requirements if args.requirements is not None else "REQ.toml"
            print_error(
                f"{', '.join(batch_only)}: only with --batch (advisor --batch {name} …); "
                "without --batch the wizard opens"
            )
            return ExitCode.INVALID_INPUT
        return run_wizard(args.requirements, args.catalog_dir)
    if args.jobs < 1:
        print_error(f"-j/--jobs = {args.jobs}: must be at least 1")
        return ExitCode.INVALID_INPUT
    wrong = _output_problem(args.output, args.out_dir)
    if wrong is not None:
        print_error(wrong)
        return ExitCode.INVALID_INPUT
    many = len(inputs) > 1 or inputs[0].is_dir() or args.out_dir is not None
    if many:
        if args.output is not None:
            print_error("-o/--output takes one input; with several use --out-dir DIR")
            return ExitCode.INVALID_INPUT
        if args.out_dir is None:
            print_error("several inputs (or a directory) need --out-dir DIR for their reports")
            return ExitCode.INVALID_INPUT
        if args.format not in (None, "toml"):
            print_error(
                f"--format {args.format} takes one input; with --out-dir the reports are TOML"
            )
            return ExitCode.INVALID_INPUT
        return run_many(inputs, Path(args.out_dir), args.catalog_dir, args.jobs)
    output = Path(args.output) if args.output is not None else None
    return run_batch(inputs[0], output, args.catalog_dir, args.format)
