"""The one call from a family study into the engine, and requirement validation for axes.

Everything a family study needs from the engine goes through this module, built on the same
functions as ``advisor --batch``: :func:`advisor.core.reading.parse_requirements` (the
TOML reading of the batch path minus the file), :func:`advisor.core.engine.advise` and the
report's TOML conversion. A row of ``designs.csv`` therefore equals what the batch command
gives for that variant alone.

It is also the one module of the family package that knows where the engine's modules live:
the rest imports the errors and the report helpers from here.
"""

from typing import Any, NamedTuple

from advisor.core.errors import AdvisorError, ExitCode, InfeasibleError, InputError
from advisor.core.io_safety import OutputError, show
from advisor.core.report import round_sig, write_atomic

__all__ = [
    "AdvisorError",
    "ExitCode",
    "InfeasibleError",
    "InputError",
    "Outcome",
    "OutputError",
    "advise_one",
    "field_problems",
    "round_sig",
    "show",
    "write_atomic",
]

STATUS = {
    ExitCode.OK: "design",
    ExitCode.INFEASIBLE: "infeasible",
    ExitCode.INVALID_INPUT: "invalid",
    ExitCode.INTERNAL_ERROR: "internal_error",
}


class Outcome(NamedTuple):
    exit_code: int  # as ``advisor --batch`` would exit for this requirement
    status: str  # design, infeasible, invalid or internal_error
    reason: str  # empty for a design; else the batch command's message in one line
    report: dict[str, Any] | None  # the report as TOML data (what the batch TOML parses to)
    #: the report TOML, byte for byte what ``advisor --batch --out-dir`` writes (when asked
    #: for): a design's, or an infeasible variant's; None for an invalid variant (the batch
    #: writes no report for it either)
    text: str | None


def one_line(message: str) -> str:
    """A multi-line message (headline, then ``  - reason`` lines) as one CSV-friendly line."""
    parts = [p.strip().removeprefix("- ") for p in message.splitlines() if p.strip()]
    return "; ".join(parts)


def advise_one(
    requirement: dict[str, Any], catalog_dir: str | None = None, with_text: bool = False
) -> Outcome:
    """Advise one requirement (a TOML document as a dict); every failure becomes an Outcome."""
    from pathlib import Path

    from advisor.core import toml_text
    from advisor.core.engine import advise
    from advisor.core.reading import parse_requirements
    from advisor.core.report import archive, plain_data

    try:
        req = parse_requirements(requirement)
        try:
            report = advise(req, Path(catalog_dir) if catalog_dir else None)
        except InfeasibleError as exc:  # its report says why, as advisor --batch --out-dir
            text = _infeasible_text(req, exc) if with_text else None
            return Outcome(
                exc.exit_code, STATUS[ExitCode.INFEASIBLE], one_line(str(exc)), None, text
            )
        data = plain_data(report)  # what advisor.core.report.to_toml dumps, curves in place
        # = to_toml(report): the same writer, on the data already rounded
        text = toml_text.dumps(archive(data, none_dropped=True)) if with_text else None
        return Outcome(ExitCode.OK, STATUS[ExitCode.OK], "", data, text)
    except InfeasibleError as exc:
        return Outcome(exc.exit_code, STATUS[ExitCode.INFEASIBLE], one_line(str(exc)), None, None)
    except AdvisorError as exc:
        code = ExitCode(exc.exit_code)
        return Outcome(code, STATUS[code], one_line(str(exc)), None, None)
    except Exception as exc:  # a bug in one variant must not stop the study
        return Outcome(
            ExitCode.INTERNAL_ERROR,
            STATUS[ExitCode.INTERNAL_ERROR],
            f"internal error ({type(exc).__name__}: {exc})",
            None,
            None,
        )


def _infeasible_text(req: Any, exc: InfeasibleError) -> str:
    """The report TOML of a variant no design satisfies, as ``advisor --batch --out-dir``
    writes it for the same file (``status = "infeasible"``)."""
    from advisor.core.report import to_toml
    from advisor.infeasible import infeasible_report

    return to_toml(infeasible_report(req, exc))


class FieldProblem(NamedTuple):
    where: str  # ``rotary.torque_Nm``; "" for a problem of the whole requirement
    message: str  # the batch command's one-line message
    cross_field: bool  # raised by a check that relates several fields (a model validator)


def field_problems(requirement: dict[str, Any]) -> list[FieldProblem]:
    """Validation problems of a requirement, located, as the batch command words them."""
    from pydantic import ValidationError

    from advisor.core.requirements import (
        RequirementHead,
        dotted_location,
        format_validation_error,
        requirements_model,
        walk_location,
    )

    written = requirement  # echoed as typed where a refused value was a quantity string
    try:
        kind = RequirementHead.model_validate(requirement).application.kind
        model: Any = requirements_model(kind)
    except ValidationError as exc:
        model, errors = RequirementHead, exc
    else:
        from advisor.core.units import convert

        try:  # "1 kN*m" is read as advisor --batch reads it: units first, then the model
            requirement = convert(requirement, model)
        except InputError as exc:
            return [FieldProblem(m.split(" = ", 1)[0], m, False) for m in exc.messages]
        try:
            model.model_validate(requirement)
            return []
        except ValidationError as exc:
            errors = exc
    out = []
    for err, line in zip(
        errors.errors(), format_validation_error(errors, model, written), strict=True
    ):
        loc, info, _ = walk_location(tuple(err["loc"]), model)
        holds_table = info is not None and hasattr(info.annotation, "model_fields")
        cross = err["type"] == "value_error" and (not loc or holds_table)
        out.append(FieldProblem(dotted_location(loc), line, cross))
    return out


def check_catalogs(catalog_dir: str) -> None:
    """Load the user catalogs once, before a study starts: a missing directory or a broken
    catalog is refused in one line (InputError), not found again in every variant."""
    from pathlib import Path

    from catalogs import load_catalogs

    load_catalogs(Path(catalog_dir))
