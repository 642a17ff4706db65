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
    kind: Annotated[
        Literal["linear", "rotary", "positioning", "spinning_rotor"],
        Field(description="the application"),
    ]
    hold_without_power: Annotated[
        bool, Field(description="the drive must hold the load with the motor off")
    ] = False
    title: Annotated[str, Field(max_length=200, description="a label for the report")] = ""


class LinearReq(_Strict):
    """The linear stage. Every number has a physically meaningful range (issue 13): a screw
    actuator of this advisor pushes 1 N … 5 MN over 1 mm … 20 m in 10 ms … about 28 h."""

    force_N: Annotated[float, _num(ge=1, le=5e6, desc="rated axial force, N; 1 N … 5 MN")]
    stroke_m: Annotated[float, _num(ge=1e-3, le=20, desc="stroke, m; 1 mm … 20 m")]
    travel_time_s: Annotated[
        float, _num(ge=0.01, le=1e5, desc="time for the full stroke, s; 0.01 … 100000 s")
    ]
    support_span_m: Annotated[
        float,
        _num(ge=1e-3, le=20, desc="distance between the screw supports, m; 1 mm … 20 m"),
    ]
    end_fixity: Annotated[
        Literal["pinned-pinned", "fixed-pinned", "fixed-fixed", "fixed-free"],
        Field(description="how the screw ends are held, for buckling"),
    ] = "pinned-pinned"
    buckling_safety_factor: Annotated[
        float, _num(ge=1, le=20, desc="required margin against buckling; 1 … 20")
    ] = 3.0

    @model_validator(mode="after")
    def _stroke_fits(self) -> "LinearReq":
        if self.stroke_m > self.support_span_m:
            raise ValueError(
                f"linear.stroke_m = {self.stroke_m:g} is longer than linear.support_span_m = "
                f"{self.support_span_m:g}: the nut must travel between the supports"
            )
        return self


class InductionMotorReq(_Strict):
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
        float | None, _num(ge=0.01, le=0.6, desc="thread friction coefficient f; 0.01 … 0.6")
    ] = None
    starts: Annotated[
        int | None,
        Field(
            ge=1,
            le=4,
            description="number of thread starts, 1 … 4; left out, the advisor chooses it",
        ),
    ] = None
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


class OneWayReq(_Strict):
    """The holding device of a drive with ``hold_without_power`` (seed 004)."""

    type: Annotated[
        Literal["auto", "roller_clutch", "em_clutch", "worm", "inverse_gear"],
        Field(description="one-way device type"),
    ] = "auto"
    rollers: Annotated[int, Field(ge=3, le=12, description="rollers of a roller clutch")] = 6
    priority: Annotated[
        Literal["mass", "inertia", "power"],
        Field(description="what the automatic choice minimises"),
    ] = "mass"


class LinearRequirements(_Strict):
    """A linear actuator: induction motor + sliding screw–nut (seed 001)."""

    application: ApplicationReq
    linear: Annotated[
        LinearReq,
        Field(description="the [linear] table: force_N, stroke_m, travel_time_s, support_span_m"),
    ]
    motor: Annotated[InductionMotorReq, Field(description="the [motor] table: kind = 'induction'")]
    screw: ScrewReq = ScrewReq()
    one_way: OneWayReq = OneWayReq()


class _Head(BaseModel):
    """Only the [application] table, read first to know which model validates the file."""

    model_config = ConfigDict(extra="allow", strict=True)
    application: Annotated[
        ApplicationReq,
        Field(
            description="the [application] table: kind = 'linear', 'rotary', 'positioning' or "
            "'spinning_rotor'"
        ),
    ]


#: What ``parse_requirements`` returns: one model per application kind.
Requirements = Any


def requirements_model(kind: str) -> type[BaseModel]:
    """The requirement model of an application kind (imported only when used: pydantic
    builds a model's validator at import, and the linear batch path must stay light)."""
    if kind == "linear":
        return LinearRequirements
    if kind == "positioning":
        from advisor.models_positioning import PositioningRequirements

        return PositioningRequirements
    if kind == "spinning_rotor":
        from advisor.models_rotor import SpinningRotorRequirements

        return SpinningRotorRequirements
    from advisor.models_rotary import RotaryRequirements

    return RotaryRequirements


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


def _members(ann: Any) -> list[type[BaseModel]]:
    args = getattr(ann, "__args__", ())
    return [a for a in (ann, *args) if isinstance(a, type) and issubclass(a, BaseModel)]


def _literal_kinds(model: type[BaseModel]) -> tuple[Any, ...]:
    f = model.model_fields.get("kind")
    return getattr(f.annotation, "__args__", ()) if f is not None else ()


def _walk(loc: tuple[Any, ...], root: Any) -> tuple[tuple[Any, ...], Any, Any]:
    """Follow a pydantic error location through the requirement models.

    Returns the location without the discriminator tags pydantic inserts
    (``motor.bldc.phases`` → ``motor.phases``), the FieldInfo at its end (for the
    description with units) and the model that holds the last key (for the allowed keys).
    """
    model: Any = root
    holder: Any = None
    info = None
    out: list[Any] = []
    parts = list(loc)
    while parts:
        part = parts.pop(0)
        out.append(part)
        fields = getattr(model, "model_fields", None) if model is not None else None
        holder = model
        if isinstance(part, int) or not fields or part not in fields:
            info = None
            if not isinstance(part, int):
                model = None
            continue
        info = fields[part]
        members = _members(info.annotation)
        if len(members) > 1:
            tagged = [m for m in members if parts and parts[0] in _literal_kinds(m)]
            model = tagged[0] if tagged else None
            if tagged:
                parts.pop(0)
        else:
            model = members[0] if members else None
    return tuple(out), info, holder


def _where(loc: tuple[Any, ...]) -> str:
    """``positioning.motors[1].name``: list items counted from 1, as a reader counts them."""
    out = ""
    for part in loc:
        out += f"[{part + 1}]" if isinstance(part, int) else (f".{part}" if out else str(part))
    return out


def format_validation_error(exc: ValidationError, root: Any) -> list[str]:
    """One line per problem: the field, the value given and what is allowed."""
    lines = []
    for err in exc.errors():
        raw_loc = tuple(err["loc"])
        loc, info, holder = _walk(raw_loc, root)
        where = _where(loc)
        typ = err["type"]
        ctx = err.get("ctx", {}) or {}
        desc = f" ({info.description})" if info is not None and info.description else ""
        if typ == "missing":
            lines.append(f"{where}: missing; required{desc}")
            continue
        if typ == "extra_forbidden":
            allowed = ", ".join(holder.model_fields) if holder is not None else ""
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
    if isinstance(value, float):  # as typed where short, else compact (1e+12, not 1000000000000.0)
        r = repr(value)
        return r if len(r) <= 10 or not math.isfinite(value) else format(value, ".6g")
    if isinstance(value, dict):
        return "{…}"
    if isinstance(value, bool):
        return "true" if value else "false"
    return repr(value)


def parse_requirements(data: dict[str, Any]) -> Requirements:
    """Validate a requirement document: [application] first, then the whole file against the
    model of that application."""
    try:
        kind = _Head.model_validate(data).application.kind
    except ValidationError as exc:
        raise InputError(*format_validation_error(exc, _Head)) from None
    model = requirements_model(kind)
    try:
        return model.model_validate(data)
    except ValidationError as exc:
        raise InputError(*format_validation_error(exc, model)) from None


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
