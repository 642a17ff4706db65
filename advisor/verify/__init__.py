"""``advisor verify``: the advisor checked against published worked examples.

The verification set is data (``cases.toml`` beside this file): each case a requirement or a
direct calculation, the numbers its source prints with their tolerance, where in the source
they stand, how they were confirmed, and, where the advisor departs on purpose, the value it
computes instead and why. :mod:`advisor.verify.runner` runs it, :mod:`advisor.verify.render`
writes the terminal and HTML reports, :func:`main` is the command.

Exit codes of the command: 0 every quantity within its tolerance or a stated departure;
1 some quantity is not; 2 a bad command line or an unknown case.
"""

import argparse
import sys
from pathlib import Path

PROG = "advisor verify"


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog=PROG,
        description="Run the advisor on published worked examples and compare every "
        "printed number with what it computes.",
        epilog="Exit codes: 0 every quantity verified (within tolerance, or a stated "
        "departure), 1 some quantity not verified, 2 a bad command line.",
    )
    p.add_argument("case", nargs="?", help="run only this case (see --list)")
    p.add_argument("--list", action="store_true", help="list the cases and exit")
    p.add_argument("--format", choices=("text", "html"), default="text", help="the report's form")
    p.add_argument("-o", "--output", type=Path, help="write the report here (atomically)")
    p.add_argument(
        "--data", type=Path, help="another verification set (TOML) instead of the shipped one"
    )
    return p


def _short_names() -> dict[str, str]:
    from catalogs import load_catalogs

    return load_catalogs().short_names()


def main(argv: list[str]) -> int:
    from advisor.core.errors import AdvisorError
    from advisor.core.io_safety import print_error
    from advisor.verify.runner import DataError, load_cases

    try:
        args = _parser().parse_args(argv)
    except SystemExit as exc:
        return int(exc.code or 0)
    try:
        if args.output is not None:  # refuse a target that would destroy something, first
            _check_output(args.output, args.data)
        cases = load_cases(args.data)
    except (AdvisorError, DataError) as exc:
        print_error(str(exc))
        return 2
    if args.list:
        for c in cases:
            print(f"{c.id}  {c.title}")
        return 0
    if args.case is not None and args.case not in {c.id for c in cases}:
        print_error(f"no case {args.case!r}; the cases: {', '.join(c.id for c in cases)}")
        return 2
    if args.format == "html" and args.output is None:
        print_error("--format html needs -o FILE.html")
        return 2
    try:
        return _report(args, cases)
    except AdvisorError as exc:  # a target that must not be written (a directory, …)
        print_error(str(exc))
        return exc.exit_code
    except KeyboardInterrupt:
        print_error("interrupted; nothing was written")
        return 130


def _check_output(output: Path, data: Path | None) -> None:
    """Refuse ``-o`` where writing would destroy something: the verification data itself, a
    device, a FIFO or a directory, or a folder that does not exist."""
    from advisor.core.io_safety import OutputError, check_target, same_file, show
    from advisor.verify.runner import data_path

    if same_file(output, data or data_path()):
        raise OutputError(
            f"{show(output, 200)}: is the verification data itself; the report would replace "
            "it (choose another -o)"
        )
    target = check_target(output)
    if not target.parent.is_dir():
        raise OutputError(f"{show(output, 200)}: no such directory {show(target.parent, 200)}")


def _report(args: argparse.Namespace, cases: list) -> int:
    from advisor.verify.render import html_report, text_report
    from advisor.verify.runner import all_verified, run

    outcomes = run(cases, args.case)
    short = _short_names()
    text = (
        html_report(outcomes, short, cases)
        if args.format == "html"
        else text_report(outcomes, short)
    )
    if args.output is not None:
        from advisor.core.io_safety import show, write_atomic

        try:
            write_atomic(args.output, text)
        except OSError as exc:
            from advisor.core.io_safety import OutputError

            raise OutputError(
                f"{show(args.output, 200)}: cannot write the report ({exc.strerror}); "
                "nothing was written"
            ) from None
        print(text_report(outcomes, short).splitlines()[-1] + f" (report: {show(args.output)})")
    else:
        sys.stdout.write(text)
    return 0 if all_verified(outcomes) else 1
