"""Requirements: the input of the advisor, read from TOML and validated strictly.

Units are SI and named in the keys (``force_N``, ``stroke_m``). Unknown keys are refused (a
typo must not be silently ignored), numbers must be finite, and a table that the
application kind needs must be present.
"""

import math
import re
import tomllib
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator, model_validator

from advisor.errors import InputError


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", strict=True, frozen=True, allow_inf_nan=False)


def _num(gt: float | None = None, le: float | None = None, ge: float | None = None, desc: str = ""):
    return Field(gt=gt, le=le, ge=ge, allow_inf_nan=False, description=desc)


class ApplicationReq(_Strict):
    kind: Annotated[Literal["linear"], Field(description="the application")]
    hold_without_power: Annotated[
        bool, Field(description="the drive must hold the load with the motor off")
    ] = False
    title: Annotated[str, Field(max_length=200, description="a label for the report")] = ""


class LinearReq(_Strict):
    force_N: Annotated[float, _num(gt=0, le=5e6, desc="rated axial force, N")]
    stroke_m: Annotated[float, _num(gt=0, le=20, desc="stroke, m")]
    travel_time_s: Annotated[float, _num(gt=0, le=1e5, desc="time for the full stroke, s")]
    support_span_m: Annotated[
        float, _num(gt=0, le=20, desc="distance between the screw supports, m")
    ]
    end_fixity: Annotated[
        Literal["pinned-pinned", "fixed-pinned", "fixed-fixed", "fixed-free"],
        Field(description="how the screw ends are held, for buckling"),
    ] = "pinned-pinned"
    buckling_safety_factor: Annotated[
        float, _num(ge=1, le=20, desc="required margin against buckling")
    ] = 3.0

    @model_validator(mode="after")
    def _stroke_fits(self) -> "LinearReq":
        if self.stroke_m > self.support_span_m:
            raise ValueError(
                f"linear.stroke_m = {self.stroke_m:g} is longer than linear.support_span_m = "
                f"{self.support_span_m:g}: the nut must travel between the supports"
            )
        return self


class MotorReq(_Strict):
    kind: Annotated[Literal["induction"], Field(description="motor type")]
    supply_frequency_Hz: Annotated[float, _num(gt=0, desc="supply frequency, Hz")] = 50.0

    @field_validator("supply_frequency_Hz")
    @classmethod
    def _fifty(cls, v: float) -> float:
        if v != 50.0:
            raise ValueError("must be 50: the induction motor catalog holds 50 Hz ratings")
        return v


THREAD_RE = re.compile(r"^Tr\s*(\d+(?:\.\d+)?)\s*[x×]\s*(\d+(?:\.\d+)?)$", re.IGNORECASE)


class ScrewReq(_Strict):
    friction_coefficient: Annotated[
        float | None, _num(gt=0, le=0.6, desc="thread friction coefficient f")
    ] = None
    starts: Annotated[int, Field(ge=1, le=4, description="number of thread starts")] = 1
    friction_model: Annotated[
        Literal["standard", "paper"], Field(description="reduced friction formula")
    ] = "standard"
    thread: Annotated[str | None, Field(description="imposed thread, e.g. Tr16x2")] = None
    material_pair: Annotated[
        Literal["steel_bronze", "hardened_steel_bronze", "steel_cast_iron", "steel_steel"],
        Field(description="screw and nut materials"),
    ] = "steel_bronze"
    lubrication: Annotated[Literal["oil", "dry"], Field(description="thread lubrication")] = "oil"
    screw_steel: Annotated[Literal["45", "40X"], Field(description="screw steel grade")] = "45"

    @field_validator("thread")
    @classmethod
    def _thread_form(cls, v: str | None) -> str | None:
        if v is None:
            return v
        m = THREAD_RE.match(v.strip())
        if not m:
            raise ValueError("must be a trapezoidal thread written like Tr16x2 (d x P in mm)")
        return f"Tr{float(m.group(1)):g}x{float(m.group(2)):g}"


class Requirements(_Strict):
    application: ApplicationReq
    linear: LinearReq | None = None
    motor: MotorReq
    screw: ScrewReq = ScrewReq()

    @model_validator(mode="after")
    def _tables_for_kind(self) -> "Requirements":
        if self.application.kind == "linear" and self.linear is None:
            raise ValueError("[linear] table is missing; it is required for kind = 'linear'")
        return self


# ------------------------------------------------------------------ reading and messages
_FRIENDLY = {
    "greater_than": "must be > {gt}",
    "greater_than_equal": "must be ≥ {ge}",
    "less_than": "must be < {lt}",
    "less_than_equal": "must be ≤ {le}",
    "finite_number": "must be a finite number (nan and inf are not allowed)",
    "float_type": "must be a number",
    "int_type": "must be a whole number",
    "bool_type": "must be true or false",
    "string_type": "must be a string in quotes",
    "model_type": "must be a table",
    "model_attributes_type": "must be a table",
    "string_too_long": "is too long (at most {max_length} characters)",
}


def _field_info(loc: tuple[Any, ...]):
    """The pydantic FieldInfo at a location, to quote its description (units)."""
    model: Any = Requirements
    info = None
    for part in loc:
        fields = getattr(model, "model_fields", None)
        if not fields or part not in fields:
            return None
        info = fields[part]
        ann = info.annotation
        args = getattr(ann, "__args__", ())
        model = next(
            (a for a in (ann, *args) if isinstance(a, type) and issubclass(a, BaseModel)), None
        )
    return info


def _allowed_keys(loc: tuple[Any, ...]) -> list[str]:
    model: Any = Requirements
    for part in loc[:-1]:
        info = model.model_fields.get(part)
        if info is None:
            return []
        ann = info.annotation
        args = getattr(ann, "__args__", ())
        model = next(
            (a for a in (ann, *args) if isinstance(a, type) and issubclass(a, BaseModel)), None
        )
        if model is None:
            return []
    return list(model.model_fields)


def format_validation_error(exc: ValidationError) -> list[str]:
    """One line per problem: the field, the value given and what is allowed."""
    lines = []
    for err in exc.errors():
        loc = tuple(err["loc"])
        where = ".".join(str(p) for p in loc)
        typ = err["type"]
        ctx = err.get("ctx", {}) or {}
        info = _field_info(loc)
        desc = f" ({info.description})" if info is not None and info.description else ""
        if typ == "missing":
            lines.append(f"{where}: missing; required{desc}")
            continue
        if typ == "extra_forbidden":
            allowed = ", ".join(_allowed_keys(loc))
            lines.append(f"{where}: unknown key; allowed keys here: {allowed}")
            continue
        value = err.get("input")
        shown = _show(value)
        if typ == "literal_error":
            what = f"must be one of {ctx.get('expected')}"
        elif typ in _FRIENDLY:
            what = _FRIENDLY[typ].format(**{k: _num_text(v) for k, v in ctx.items()})
        else:
            what = err["msg"].removeprefix("Value error, ")
        if typ == "value_error" and where == "":
            lines.append(what)
        elif typ == "value_error" and what.startswith(where):
            lines.append(what)
        else:
            lines.append(f"{where} = {shown}: {what}{desc}")
    return lines


def _num_text(v: Any) -> str:
    return f"{v:g}" if isinstance(v, int | float) and not isinstance(v, bool) else str(v)


def _show(value: Any) -> str:
    if isinstance(value, float) and not math.isfinite(value):
        return str(value)
    if isinstance(value, dict):
        return "{…}"
    if isinstance(value, bool):
        return "true" if value else "false"
    return repr(value)


def parse_requirements(data: dict[str, Any]) -> Requirements:
    try:
        return Requirements.model_validate(data)
    except ValidationError as exc:
        raise InputError(*format_validation_error(exc)) from None


def read_requirements(path: Path) -> Requirements:
    """Read and validate a requirement file; every failure is an :class:`InputError`."""
    try:
        raw = path.read_bytes()
    except FileNotFoundError:
        raise InputError(f"{path}: no such file") from None
    except IsADirectoryError:
        raise InputError(f"{path}: is a directory, expected a requirement file (.toml)") from None
    except OSError as exc:
        raise InputError(f"{path}: cannot be read ({exc.strerror})") from None
    try:
        data = tomllib.loads(raw.decode("utf-8"))
    except UnicodeDecodeError:
        raise InputError(f"{path}: not a UTF-8 text file") from None
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"{path}: broken TOML: {exc}") from None
    return parse_requirements(data)
