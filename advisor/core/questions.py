"""The requirement fields as questions: label, unit, help, wizard step, default and valid
range, read from the pydantic models where each field is declared once. The wizard's
fields, the key tables of docs/reference/keys.md and the published JSON Schema all come
from here, so they cannot disagree with the validation. Pure: no textual, no I/O. pydantic
is imported by the functions that read a model, not with :class:`Question`: the wizard
reads the questions of the shipped applications compiled
(:mod:`advisor.core.requirement_spec`)."""

import types
from typing import TYPE_CHECKING, Any, Literal, NamedTuple, Union, get_args, get_origin

if TYPE_CHECKING:
    from pydantic import BaseModel
    from pydantic.fields import FieldInfo

#: Units named by a key's suffix (``force_N``, ``inertia_kgm2``): the longest suffix wins.
UNIT_SUFFIXES = {
    "N": "N",
    "Nm": "N·m",
    "m": "m",
    "mm": "mm",
    "mm2": "mm²",
    "s": "s",
    "h": "h",
    "rpm": "rpm",
    "Hz": "Hz",
    "kg": "kg",
    "kgm2": "kg·m²",
    "kgm2_s": "kg·m²/s",
    "kg_m3": "kg/m³",
    "m2_s": "m²/s",
    "mm2_s": "mm²/s",
    "rad": "rad",
    "rad_s": "rad/s",
    "deg": "deg",
    "W": "W",
    "A": "A",
    "V": "V",
    "uF": "µF",
    "T": "T",
    "ohm": "Ω",
}

#: How many rows of a list of tables (e.g. candidate motors) the wizard offers.
WIZARD_ROWS = 3


class Question(NamedTuple):
    path: tuple[str, ...]  # into the requirement document; list rows by index ("0", "1", …)
    label: str
    unit: str = ""
    kind: str = "float"  # float | int | str | bool | choice | floats | fixed
    choices: tuple[str, ...] = ()
    optional: bool = False  # the model has a default: the field may be left empty
    default: Any = None  # the model's default (None: none, or "absent")
    help: str = ""
    step: int | None = None  # the wizard step that asks it; None: the file only
    range: str = ""  # "> 0, ≤ 5e+06"
    example: Any = None
    row: tuple[str, ...] | None = None  # the list row it belongs to: asked only if started
    needs: str | None = None  # a table the application must have for it to be asked


def unit_of(name: str) -> str:
    """The unit a key names by its suffix (``support_span_m`` → m), '' for none."""
    parts = name.split("_")
    for k in (2, 1):  # kgm2_s before s
        suffix = "_".join(parts[-k:])
        if len(parts) > k and suffix in UNIT_SUFFIXES:
            return UNIT_SUFFIXES[suffix]
    return ""


def strip_optional(ann: Any) -> Any:
    if get_origin(ann) in (Union, types.UnionType):
        args = [a for a in get_args(ann) if a is not type(None)]
        if len(args) == 1:
            return args[0]
    return ann


def is_model(ann: Any) -> bool:
    from pydantic import BaseModel

    return isinstance(ann, type) and issubclass(ann, BaseModel)


def range_text(info: "FieldInfo") -> str:
    """The valid range from the field's constraints: ``> 0, ≤ 5e+06``."""
    words = []
    for m in info.metadata:
        for attr, sign in (("gt", ">"), ("ge", "≥"), ("lt", "<"), ("le", "≤")):
            v = getattr(m, attr, None)
            if v is not None:
                words.append(f"{sign} {v:g}")
        for attr, what in (("min_length", "at least"), ("max_length", "at most")):
            v = getattr(m, attr, None)
            if v is not None:
                words.append(f"{what} {v}")
    return ", ".join(words)


def field_extra(info: "FieldInfo") -> dict[str, Any]:
    extra = info.json_schema_extra
    return extra if isinstance(extra, dict) else {}


def _kind(ann: Any) -> tuple[str, tuple[str, ...]]:
    if get_origin(ann) is Literal:
        values = tuple(str(v) for v in get_args(ann))
        return ("fixed" if len(values) == 1 else "choice"), values
    if ann is bool:
        return "bool", ()
    if ann is int:
        return "int", ()
    if ann is str:
        return "str", ()
    if get_origin(ann) is list:
        return "floats", ()
    return "float", ()


def _default(info: "FieldInfo") -> Any:
    if info.is_required():
        return None
    value = info.get_default(call_default_factory=True)
    if is_model(type(value)):
        return None
    return value


def questions(
    model: "type[BaseModel]", prefix: tuple[str, ...] = (), wizard: bool = False
) -> list[Question]:
    """Every leaf field of ``model`` (tables followed), in declaration order. With
    ``wizard``, a list of tables is offered as :data:`WIZARD_ROWS` numbered rows; without,
    its fields appear once under ``name[]``."""
    out: list[Question] = []
    for name, info in model.model_fields.items():
        ann = strip_optional(info.annotation)
        path = (*prefix, name)
        extra = field_extra(info)
        if is_model(ann):
            out += questions(ann, path, wizard)
            continue
        if get_origin(ann) is list and is_model(get_args(ann)[0]):
            item = get_args(ann)[0]
            if not wizard:
                out += questions(item, (*prefix, f"{name}[]"), wizard)
                continue
            row_label = extra.get("x-row-label", name)
            for k in range(WIZARD_ROWS):
                row = (*path, str(k))
                for q in questions(item, row, wizard):
                    out.append(q._replace(label=f"{row_label} {k + 1}: {q.label}", row=row))
            continue
        kind, choices = _kind(ann)
        out.append(
            Question(
                path=path,
                label=extra.get("x-label", info.description or name),
                unit=extra.get("x-unit", unit_of(name)),
                kind=kind,
                choices=choices,
                optional=not info.is_required(),
                default=_default(info),
                help=info.description or "",
                step=extra.get("x-step"),
                range=range_text(info),
                example=(extra.get("examples") or [None])[0],
                needs=extra.get("x-with"),
            )
        )
    return out


def wizard_questions(model: "type[BaseModel]") -> list[Question]:
    """The questions the wizard asks for a requirement model, in declaration order: those
    with a step, and only where the model has the table they are asked with
    (``hold_without_power`` with the one-way device), shown beside that table."""
    tables = set(model.model_fields)
    asked = [
        q
        for q in questions(model, wizard=True)
        if q.step is not None and (q.needs is None or q.needs in tables)
    ]
    # a question asked with a table is shown with it, just before its first question
    out = [q for q in asked if q.needs is None]
    for q in (q for q in asked if q.needs is not None):
        at = next((i for i, o in enumerate(out) if o.path[0] == q.needs), len(out))
        out.insert(at, q)
    return out


def fixed_values(model: "type[BaseModel]") -> dict[tuple[str, ...], str]:
    """Fields with one allowed value (the motor ``kind`` of an application): the wizard
    fills them in, nobody has to choose."""
    return {
        q.path: q.choices[0]
        for q in questions(model)
        if q.kind == "fixed" and not q.optional and "[]" not in "".join(q.path)
    }
