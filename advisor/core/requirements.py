"""Requirements: the input of the advisor, read from TOML and validated strictly.

Units are SI and named in the keys (``force_N``, ``stroke_m``); a number may also be written
as a string with a unit (``"5 kN"``), converted to the key's unit by
:mod:`advisor.core.units`. Unknown keys are refused (a
typo must not be silently ignored), numbers must be finite, and a table that the
application kind needs must be present.
"""

import math
from typing import Annotated, Any, Literal

from pydantic import (
    BaseModel,
    ConfigDict,
    Field,
    ValidationError,
    field_validator,
    model_validator,
)
from pydantic_core import PydanticCustomError

from advisor.core.errors import InputError
from advisor.core.io_safety import show, show_repr

#: At most this many unknown keys are listed (50,000 typos are not 50,000 lines) ...
MAX_UNKNOWN_SHOWN = 3
#: ... and at most this many problems in all, the last line saying how many more.
MAX_PROBLEMS_SHOWN = 5

#: Stands for the registered kinds in a description (filled in when a message is written).
_KINDS = "{kinds}"
#: Stands for a number's valid range in its description: filled in when the model is defined,
#: from the field's constraint in the unit its key names (``1 … 10⁵ N·m``), so that the range
#: is declared once, in the constraint.
RANGE = "{range}"


def _bounds(metadata: Any) -> dict[str, float]:
    """The numeric bounds among a field's constraints (a nested FieldInfo's too)."""
    out: dict[str, float] = {}
    for m in metadata:
        out.update(_bounds(m.metadata) if hasattr(m, "metadata") else {})
        out.update({k: getattr(m, k) for k in ("ge", "gt", "le", "lt") if hasattr(m, k)})
    return {k: v for k, v in out.items() if v is not None}


def range_in_words(name: str, info: Any) -> str:
    """The range a field's constraint allows, in the words of
    :func:`advisor.core.ranges.range_prose`; for a list
    of numbers, the range of each item."""
    from typing import get_args

    from advisor.core.questions import field_extra, strip_optional, unit_of
    from advisor.core.ranges import range_prose

    bounds = _bounds(info.metadata)
    if not bounds:  # list[Annotated[float, Field(ge=…)]]: the items' own constraint
        items = get_args(strip_optional(info.annotation))
        bounds = _bounds(getattr(items[0], "__metadata__", ())) if items else {}
    unit = field_extra(info).get("x-unit") or unit_of(name)
    return range_prose(unit, **bounds)


class StrictModel(BaseModel):
    # defer_build: a nested model is validated by its parent's validator, so building one of
    # its own at import (about 1 ms a model) would be wasted; a model used alone builds its
    # validator on first use
    model_config = ConfigDict(
        extra="forbid", strict=True, frozen=True, allow_inf_nan=False, defer_build=True
    )

    @classmethod
    def __pydantic_init_subclass__(cls, **kwargs: Any) -> None:
        super().__pydantic_init_subclass__(**kwargs)
        for name, info in cls.model_fields.items():
            if info.description and RANGE in info.description:
                info.description = info.description.replace(RANGE, range_in_words(name, info))


def _extra(
    label: str | None,
    unit: str | None,
    step: int | None,
    example: Any,
    extra: dict[str, Any],
    unique_items: bool = False,
) -> dict[str, Any] | None:
    """The question metadata of a field, kept in its JSON Schema as ``x-`` keywords (editors
    ignore them; :mod:`advisor.core.questions` reads them)."""
    out = {f"x-{k}": v for k, v in extra.items()}
    if unique_items:  # a standard keyword: editors check it too
        out["uniqueItems"] = True
    if label is not None:
        out["x-label"] = label
    if unit is not None:
        out["x-unit"] = unit
    if step is not None:
        out["x-step"] = step
    if example is not None:
        out["examples"] = [example]
    return out or None


def ask(
    desc: str = "",
    *,
    label: str | None = None,
    unit: str | None = None,
    step: int | None = None,
    example: Any = None,
    extra: dict[str, Any] | None = None,
    unique_items: bool = False,
    **constraints: Any,
) -> Any:
    """A requirement field declared once: ``desc`` is the help text (and the words of its
    error messages), ``label`` the wizard's name for it, ``unit`` its unit (by default the
    one its key's suffix names, see :mod:`advisor.core.questions`), ``step`` the wizard step
    that asks it (none: the file only), ``example`` a value shown where there is no default;
    ``constraints`` are pydantic's (``gt``, ``le``, ``max_length`` …), the valid range;
    ``unique_items`` says in the schema that a list names each value once (the model's own
    validator refuses a repeat)."""
    return Field(
        description=desc,
        json_schema_extra=_extra(label, unit, step, example, extra or {}, unique_items),
        **constraints,
    )


def number_field(
    gt: float | None = None,
    le: float | None = None,
    ge: float | None = None,
    desc: str = "",
    **question: Any,
) -> Any:
    """A finite number field; ``question`` as for :func:`ask`."""
    return ask(desc, gt=gt, le=le, ge=ge, allow_inf_nan=False, **question)


def import_path(fn: Any) -> str:
    """``module:qualname`` of a pydantic-free function (what the compiled spec names)."""
    return f"{fn.__module__}:{fn.__qualname__}"


def after_check(check: Any) -> Any:
    """A model validator running ``check(model)``: a pure function in a pydantic-free module,
    which raises ValueError with the message. The compiled validator of
    :mod:`advisor.core.compiled_validator` runs the same function, so the rule is written once."""

    def run(self: Any) -> Any:
        check(self)
        return self

    run.__compiled_twin__ = import_path(check)  # type: ignore[attr-defined]
    return model_validator(mode="after")(run)


def field_check(field: str, check: Any) -> Any:
    """A field validator returning ``check(value)`` (pure, pydantic-free; see
    :func:`after_check`)."""

    def run(cls: Any, v: Any) -> Any:
        return check(v)

    run.__compiled_twin__ = import_path(check)  # type: ignore[attr-defined]
    return field_validator(field)(classmethod(run))


def _kind_schema(schema: dict[str, Any]) -> None:
    from advisor.core.registry import kinds

    schema["enum"] = list(kinds())


class ApplicationReq(StrictModel):
    kind: Annotated[str, Field(description="the application", json_schema_extra=_kind_schema)]
    hold_without_power: Annotated[
        bool,
        ask(
            "the drive must hold the load with the motor off",
            label="Hold the load with the motor off",
            step=2,
            extra={"with": "one_way"},  # asked where the application has a one-way device
        ),
    ] = False
    title: Annotated[
        str, ask("a label for the report", label="Title for the report", max_length=200)
    ] = ""

    def _registered(cls, v: str) -> str:
        from advisor.core.registry import expected_text, kinds

        if v not in kinds():
            raise PydanticCustomError(
                "literal_error", "Input should be {expected}", {"expected": expected_text(kinds())}
            )
        return v

    # the compiled validator's twin, advisor.core.registry.registered (the message stays
    # pydantic's: a document the compiled validator refuses is validated again by this model)
    _registered.__compiled_twin__ = "advisor.core.registry:registered"  # type: ignore[attr-defined]
    _registered = field_validator("kind")(classmethod(_registered))  # type: ignore[assignment]


class OneWayReq(StrictModel):
    """The holding device of a drive with ``hold_without_power`` (seed 004)."""

    type: Annotated[
        Literal["auto", "roller_clutch", "em_clutch", "worm", "inverse_gear"],
        ask("one-way device type", label="One-way device", step=2),
    ] = "auto"
    rollers: Annotated[
        int, Field(ge=3, le=12, description="rollers of a roller clutch, {range}")
    ] = 6
    priority: Annotated[
        Literal["mass", "inertia", "power"],
        ask("what the automatic choice minimises", label="Automatic choice minimises", step=2),
    ] = "mass"


def _doc_text(desc: str, label: str, example: str, length: int = 200) -> Any:
    return ask(desc, label=label, example=example, max_length=length)


class ProjectReq(StrictModel):
    """The ``[project]`` table: the header of the datasheet a design review signs. Every
    field is text, copied as written (the date too: the advisor never reads the clock, so
    two runs of one file give the same datasheet)."""

    name: Annotated[str, _doc_text("the project", "Project", "Rudder actuator, batch 2")] = ""
    document_number: Annotated[
        str, _doc_text("the document number", "Document number", "DA-0042", 80)
    ] = ""
    revision: Annotated[str, _doc_text("the revision", "Revision", "B", 40)] = ""
    date: Annotated[str, _doc_text("the date, as text in quotes", "Date", "2025-03-14", 40)] = ""
    author: Annotated[str, _doc_text("who prepared the design", "Author", "A. Engineer")] = ""
    checked_by: Annotated[str, _doc_text("who checked it", "Checked by", "C. Checker")] = ""
    approved_by: Annotated[str, _doc_text("who approved it", "Approved by", "D. Approver")] = ""


#: The optional ``[project]`` table every application's requirement model declares.
ProjectField = Annotated[
    ProjectReq | None,
    Field(description="the [project] table: name, document_number, revision, date, author…"),
]


class DesignReq(StrictModel):
    """The [design] table: what the whole design must meet, whatever the application (issue
    26). Shared by the applications that declare it."""

    service_factor: Annotated[
        float | None,
        number_field(
            ge=1,
            le=5,
            desc="service factor f_B multiplying the load of every strength check; {range}; "
            "left out: 1",
            label="Service factor f_B (empty: 1)",
            step=1,
        ),
    ] = None


class RequirementHead(BaseModel):
    """Only the [application] table, read first to know which model validates the file."""

    model_config = ConfigDict(extra="allow", strict=True)
    application: Annotated[
        ApplicationReq, Field(description=f"the [application] table: kind = {_KINDS}")
    ]


#: What ``validate_with_models`` returns: one model per application kind.
Requirements = Any


def requirements_model(kind: str) -> type[BaseModel]:
    """The requirement model of a registered application kind (imported only when used:
    pydantic builds a model's validator at import, and the linear batch path must stay
    light)."""
    from advisor.core.registry import requirements_model as model

    return model(kind)


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
    "list_type": "must be a list in brackets ([a, b, …])",
    "too_short": "must list at least {min_length} item(s)",
    "too_long": "must list at most {max_length} items",
}


def _members(ann: Any) -> list[type[BaseModel]]:
    args = getattr(ann, "__args__", ())
    return [a for a in (ann, *args) if isinstance(a, type) and issubclass(a, BaseModel)]


def _literal_kinds(model: type[BaseModel]) -> tuple[Any, ...]:
    f = model.model_fields.get("kind")
    return getattr(f.annotation, "__args__", ()) if f is not None else ()


def walk_location(loc: tuple[Any, ...], root: Any) -> tuple[tuple[Any, ...], Any, Any]:
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
        if isinstance(part, int):
            continue  # an item of a list: the list's own description tells its range
        if not fields or part not in fields:
            info = None
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


def dotted_location(loc: tuple[Any, ...]) -> str:
    """``positioning.motors[1].name``: list items counted from 1, as a reader counts them."""
    out = ""
    for part in loc:
        out += f"[{part + 1}]" if isinstance(part, int) else (f".{part}" if out else str(part))
    return out


def format_validation_error(exc: ValidationError, root: Any, typed: Any = None) -> list[str]:
    """One line per problem: the field, the value given and what is allowed. ``typed`` is the
    document as written, before its unit strings were converted: a refused value typed as a
    quantity is echoed as typed with its SI value beside it ('3500 µN' (0.0035 N)), so the
    reader finds what they wrote."""
    lines: list[str] = []
    unknown: list[str] = []
    for err in exc.errors():
        raw_loc = tuple(err["loc"])
        loc, info, holder = walk_location(raw_loc, root)
        where = dotted_location(loc)
        typ = err["type"]
        ctx = err.get("ctx", {}) or {}
        desc = f" ({info.description})" if info is not None and info.description else ""
        if _KINDS in desc:
            from advisor.core.registry import expected_text, kinds

            desc = desc.replace(_KINDS, expected_text(kinds()))
        if typ == "missing":
            lines.append(f"{where}: missing; required{desc}")
            continue
        if typ == "extra_forbidden":
            unknown.append(where)
            if len(unknown) <= MAX_UNKNOWN_SHOWN:
                allowed = ", ".join(holder.model_fields) if holder is not None else ""
                lines.append(f"{show(where)}: unknown key; allowed keys here: {allowed}")
            continue
        value = err.get("input")
        shown = _show(value)
        written = _written_at(typed, loc) if typed is not None else None
        if isinstance(written, str) and _is_number(value):
            unit = _field_unit(loc, info) or _row_unit_at(typed, loc)
            shown = _as_written(written, value, unit, ctx)
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
    if len(unknown) > MAX_UNKNOWN_SHOWN:
        lines.append(f"… and {len(unknown) - MAX_UNKNOWN_SHOWN:,} more unknown keys")
    return capped(lines)


def _is_number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def _written_at(doc: Any, loc: tuple[Any, ...]) -> Any:
    """The value at a (tag-free) location of the document as written; None where it has none."""
    node = doc
    for part in loc:
        if isinstance(part, int) and isinstance(node, list) and 0 <= part < len(node):
            node = node[part]
        elif isinstance(part, str) and isinstance(node, dict) and part in node:
            node = node[part]
        else:
            return None
    return node


def _field_unit(loc: tuple[Any, ...], info: Any) -> str:
    """The SI unit a field's quantity strings are converted to ('' where it names none)."""
    from advisor.core.questions import field_extra, unit_of

    names = [p for p in loc if isinstance(p, str)]
    if info is None or not names:
        return ""
    return field_extra(info).get("x-unit") or unit_of(names[-1])


def _row_unit_at(typed: Any, loc: tuple[Any, ...]) -> str:
    """The unit of a field of a row whose numbers are in the unit of the input its ``name``
    names (an ``[[uncertainty.inputs]]`` row's sd of linear.force_N: N)."""
    from advisor.core.units import row_unit

    if len(loc) < 3 or not isinstance(loc[-2], int):
        return ""
    return row_unit(tuple(loc[:-2]), _written_at(typed, loc[:-1]))


def _as_written(text: str, value: float, unit: str, bounds: dict) -> str:
    """A quantity string as typed, with the SI number it was read as where that says more:
    '3500 µN' (0.0035 N); '60 Hz' and '0.99999949 N' (typed in the field's unit) alone."""
    if _reads_as(text, value, unit):
        return _show(text)
    si = f"{_outside_text(value, bounds)} {unit}".strip()
    return _show(text) if " ".join(text.split()) == si else f"{_show(text)} ({si})"


def _reads_as(text: str, value: float, unit: str) -> bool:
    """Whether ``text`` is ``value`` typed in ``unit`` itself ('-5 N', '0.9999999 N')."""
    number, _, typed_unit = " ".join(text.split()).partition(" ")
    try:
        return bool(unit) and typed_unit == unit and float(number) == value
    except ValueError:
        return False


#: Pydantic's bounds of a range refusal, and whether a value lies outside each.
_OUTSIDE = {
    "ge": lambda x, b: x < b,
    "gt": lambda x, b: x <= b,
    "le": lambda x, b: x > b,
    "lt": lambda x, b: x >= b,
}


def _outside_text(v: float, bounds: dict) -> str:
    """``v`` in six significant digits, or as many more as it takes for the shown number to
    lie outside the range it is refused by: 0.9999995 N is not shown '1 N' beside "must be
    ≥ 1" (it shows 0.9999995), 9.549296585 rpm below 100 stays '9.5493'."""
    limits = [(_OUTSIDE[k], b) for k, b in bounds.items() if k in _OUTSIDE and _is_number(b)]
    for digits in range(6, 18):
        text = format(v, f".{digits}g")
        shown = float(text)
        if shown == v or all(outside(shown, b) for outside, b in limits):
            return text
    return repr(v)


def capped(lines: list[str]) -> list[str]:
    """At most :data:`MAX_PROBLEMS_SHOWN` lines, the last saying how many more there are."""
    if len(lines) > MAX_PROBLEMS_SHOWN:
        more = len(lines) - MAX_PROBLEMS_SHOWN + 1
        lines = [*lines[: MAX_PROBLEMS_SHOWN - 1], f"… and {more:,} more problems"]
    return lines


def _num_text(v: Any) -> str:
    return f"{v:g}" if isinstance(v, int | float) and not isinstance(v, bool) else str(v)


def _show(value: Any) -> str:
    """A value as echoed in a message: short, escaped, and never rounded onto a limit."""
    if isinstance(value, float):  # as typed where short, else compact (1e+12, not 1000000000000.0)
        r = repr(value)
        if len(r) <= 10 or not math.isfinite(value):
            return r
        compact = format(value, ".6g")  # only if it is the same number (50.000000000001 ≠ 50)
        return compact if float(compact) == value else r
    if isinstance(value, dict):
        return "{…}"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return show_repr(value)
    if isinstance(value, list) and len(value) > 8:
        return show(repr(value[:8])[:-1] + f", … {len(value):,} items]")
    return show(repr(value))


def validate_with_models(data: dict[str, Any]) -> Requirements:
    """Validate a requirement document by the pydantic models: [application] first, then the
    whole file against the model of that application. Read files through
    :func:`advisor.core.reading.parse_requirements`, which comes here for every document the
    compiled validator does not accept (and with ``compiled=False``)."""
    try:
        kind = RequirementHead.model_validate(data).application.kind
    except ValidationError as exc:
        raise InputError(*format_validation_error(exc, RequirementHead)) from None
    model = requirements_model(kind)
    from advisor.core.ignored import contradictions
    from advisor.core.units import convert

    written = data
    try:
        data = convert(data, model)  # "5 kN" → 5000 by the strict quantity grammar
    except InputError as exc:
        raise InputError(*capped(exc.messages)) from None
    conflicts = contradictions(data)
    try:
        req = model.model_validate(data)
    except ValidationError as exc:
        raise InputError(*conflicts, *format_validation_error(exc, model, written)) from None
    if conflicts:
        raise InputError(*conflicts)
    return req
