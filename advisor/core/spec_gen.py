"""Compile the requirement models into plain data: the spec the batch path validates with.

The pydantic models (``advisor/applications/*/requirements.py``) stay the one source of
truth for every field: this module walks them and writes what
:mod:`advisor.core.compiled_validator` needs — each field's type, range, default, and the
model's own checks (pure functions, named by import path) — into
:mod:`advisor.core.requirement_spec`. The batch path then reads a requirement file without
importing pydantic, whose model machinery alone costs more than the advice.
``tests/unit/test_compiled_validator.py`` regenerates the spec and fails when the committed file
differs, so a changed model cannot go unnoticed. After changing a model::

    .venv/bin/python -m advisor.core.spec_gen        # rewrites advisor/core/requirement_spec.py

What it compiles (the generator's limits, in one place): anything else stops it with a
ValueError naming the model and the field, never a validator that accepts or builds otherwise
than pydantic.

- models: ``extra="forbid"``, ``strict=True``, ``allow_inf_nan=False`` (with ``frozen``,
  ``defer_build``, ``title``; no other setting); no serializers, computed fields or
  ``model_post_init``; methods and properties only in a mixin with ``__slots__ = ()``;
- fields: ``float``, ``int``, ``str``, ``bool``, a ``Literal`` of strings, ``X | None``, a
  ``list`` of those or of models, a nested model; constraints ``ge``, ``gt``, ``le``, ``lt``,
  ``min_length``, ``max_length`` (none on a bool, a literal or a table); a default that is
  plain data or a model instance; no aliases, default factories, ``exclude``,
  ``validate_default`` or discriminators;
- validators: ``after`` field and model validators only, each attached with
  :func:`advisor.core.requirements.after_check` / ``field_check`` (or marked with
  ``__compiled_twin__``), so that the compiled validator runs the same pure function.

A model of an application registered outside ``advisor.`` (a test, a plug-in) is not compiled:
pydantic validates its files.
"""

import types
import typing
from pathlib import Path
from typing import Any, Literal, get_args, get_origin

from annotated_types import Ge, Gt, Le, Lt, MaxLen, MinLen
from pydantic import BaseModel
from pydantic.fields import FieldInfo

from advisor.core.registry import application, kinds, load
from advisor.core.requirements import ApplicationReq

SPEC_PATH = Path(__file__).with_name("requirement_spec.py")

_CONSTRAINTS = {Ge: "ge", Gt: "gt", Le: "le", Lt: "lt"}
_LENGTHS = {MinLen: "min_length", MaxLen: "max_length"}


def model_name(model: type) -> str:
    return f"{model.__module__}:{model.__qualname__}"


def _constraints(metadata: list[Any]) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for m in metadata:
        if type(m) in _CONSTRAINTS:
            out[_CONSTRAINTS[type(m)]] = getattr(m, _CONSTRAINTS[type(m)])
        elif type(m) in _LENGTHS:
            out[_LENGTHS[type(m)]] = getattr(m, _LENGTHS[type(m)])
        elif type(m).__name__ == "AllowInfNan" and m.allow_inf_nan is False:
            pass  # every compiled model refuses nan and inf already
        elif type(m).__name__ == "_PydanticGeneralMetadata":
            extra = {k: v for k, v in vars(m).items() if k != "allow_inf_nan"}
            if m.__dict__.get("allow_inf_nan", False) or extra:
                raise ValueError(f"unsupported field metadata {m!r}")
        elif isinstance(m, FieldInfo):
            out.update(_constraints(m.metadata))
        else:
            raise ValueError(f"unsupported field metadata {m!r}")
    return out


def _type(ann: Any, metadata: list[Any], models: dict[str, Any]) -> tuple:
    """The spec of one annotation: ``("float", cons)``, ``("int", cons)``, ``("bool",)``,
    ``("str", cons)``, ``("literal", values)``, ``("optional", t)``, ``("list", t, cons)`` or
    ``("model", name)``; nested models are compiled into ``models`` as they are met."""
    origin = get_origin(ann)
    if origin is typing.Annotated:
        inner, *meta = get_args(ann)
        return _type(inner, [*meta, *metadata], models)
    if origin in (types.UnionType, typing.Union):
        args = [a for a in get_args(ann) if a is not type(None)]
        if len(args) != 1 or len(get_args(ann)) != 2:
            raise ValueError(f"unsupported union {ann!r}")
        return ("optional", _type(args[0], metadata, models))
    if origin is Literal:
        values = get_args(ann)
        if not all(type(v) is str for v in values) or _constraints(metadata):
            raise ValueError(f"unsupported literal or constraint on it {ann!r}")
        return ("literal", values)
    if origin is list:
        (item,) = get_args(ann)
        return ("list", _type(item, [], models), _constraints(metadata))
    if isinstance(ann, type) and issubclass(ann, BaseModel):
        _compile(ann, models)
        if metadata:
            raise ValueError(f"unsupported constraint on a table {ann!r}")
        return ("model", model_name(ann))
    if ann in (float, int, str):
        return (ann.__name__, _constraints(metadata))
    if ann is bool:
        if _constraints(metadata):
            raise ValueError("unsupported constraint on a bool")
        return ("bool",)
    raise ValueError(f"unsupported annotation {ann!r}")


def _default(value: Any) -> Any:
    """A default as data: a model instance becomes ``("record", name, fields_set, values)``."""
    if isinstance(value, BaseModel):
        fields = type(value).model_fields
        return (
            "record",
            model_name(type(value)),
            tuple(sorted(value.model_fields_set)),
            {k: _default(getattr(value, k)) for k in fields},
        )
    if isinstance(value, list):
        return [_default(v) for v in value]
    if value is None or type(value) in (float, int, str, bool):
        return value
    raise ValueError(f"unsupported default {value!r}")


def _twin(fn: Any) -> str:
    """The import path of the pydantic-free function a validator runs (its twin, which the
    compiled validator runs in its place)."""
    for f in (fn, getattr(fn, "__func__", None), getattr(fn, "__wrapped__", None)):
        name = getattr(f, "__compiled_twin__", None)
        if name:
            return name
    raise ValueError(f"validator {fn!r} has no pydantic-free twin (see after_check)")


#: The model settings the compiled validator follows; any other would change what it accepts.
_CONFIG_KNOWN = {"extra", "strict", "frozen", "allow_inf_nan", "defer_build", "title"}


def _refuse_what_changes_values(model: type[BaseModel], name: str) -> None:
    """Anything of a model that changes the values it gives or its dump, which a record would
    not do: serializers, computed fields, a post-init, and methods or properties of its own
    (those belong to a mixin with ``__slots__ = ()``, which records inherit)."""
    decs = model.__pydantic_decorators__
    if decs.field_serializers or decs.model_serializers or model.model_computed_fields:
        raise ValueError(f"{name}: serializers and computed fields are not compiled")
    if model.__pydantic_post_init__ is not None:
        raise ValueError(f"{name}: model_post_init is not compiled")
    for cls in model.__mro__:
        if cls in (BaseModel, object):
            continue
        own = {
            k
            for k in vars(cls)
            if not k.startswith("_") and k not in model.model_fields and k != "model_config"
        }
        if issubclass(cls, BaseModel):
            if own:
                raise ValueError(
                    f"{name}: {sorted(own)} of {cls.__qualname__}: put them in a mixin with "
                    "__slots__ = () (records inherit it)"
                )
        elif own and vars(cls).get("__slots__") != ():
            raise ValueError(f"{name}: mixin {cls.__qualname__} needs __slots__ = ()")


def _check_config(model: type[BaseModel], name: str) -> None:
    """A strict, closed, finite model with no setting the compiled validator does not follow."""
    cfg = model.model_config
    if cfg.get("extra") != "forbid" or not cfg.get("strict") or cfg.get("allow_inf_nan", True):
        raise ValueError(f"{name}: the compiled validator knows strict, closed, finite models")
    unknown_cfg = set(cfg) - _CONFIG_KNOWN
    if unknown_cfg:
        raise ValueError(f"{name}: model_config {sorted(unknown_cfg)} is not compiled")
    _refuse_what_changes_values(model, name)


def _fields(model: type[BaseModel], name: str, models: dict[str, Any]) -> tuple:
    """``(key, type, required, default)`` of every field, in the model's order."""
    fields = []
    for key, info in model.model_fields.items():
        if (
            info.alias
            or info.validation_alias
            or info.serialization_alias
            or info.default_factory is not None
            or info.exclude
            or info.validate_default
            or info.discriminator
        ):
            raise ValueError(
                f"{name}.{key}: aliases, default factories, exclude, validate_default and "
                "discriminators are not compiled"
            )
        required = info.is_required()
        default = None if required else _default(info.default)
        fields.append((key, _type(info.annotation, list(info.metadata), models), required, default))
    return tuple(fields)


def _validators(model: type[BaseModel], name: str) -> tuple[dict[str, list[str]], tuple]:
    """The twins of the model's field validators (by field) and of its model validators."""
    decs = model.__pydantic_decorators__
    checks: dict[str, list[str]] = {}
    for dec in decs.field_validators.values():
        if dec.info.mode != "after":
            raise ValueError(f"{name}: only 'after' field validators are compiled")
        for f in dec.info.fields:
            if f not in model.model_fields:  # "*" or a name not declared
                raise ValueError(f"{name}: a validator of {f!r} is not compiled")
            checks.setdefault(f, []).append(_twin(dec.func))
    after = []
    for dec in decs.model_validators.values():
        if dec.info.mode != "after":
            raise ValueError(f"{name}: only 'after' model validators are compiled")
        after.append(_twin(dec.func))
    return checks, tuple(after)


def _compile(model: type[BaseModel], models: dict[str, Any]) -> None:
    """Compile ``model`` (and the models its fields hold) into ``models``, or refuse it with a
    ValueError naming what the compiled validator would not do as pydantic does."""
    name = model_name(model)
    if name in models:
        return
    models[name] = None  # a model met again while compiling is not compiled twice
    _check_config(model, name)
    fields = _fields(model, name, models)
    checks, after = _validators(model, name)
    mixins = tuple(
        model_name(b)
        for b in model.__mro__[1:]
        if not issubclass(b, BaseModel) and b is not object and vars(b).get("__slots__") == ()
    )
    models[name] = {"fields": fields, "field_checks": checks, "after": after, "mixins": mixins}


def compile_spec() -> dict[str, Any]:
    """Every registered application's requirement model, and the [application] table."""
    models: dict[str, Any] = {}
    _compile(ApplicationReq, models)
    roots = {}
    for kind in kinds():
        path = application(kind).requirements
        if not (isinstance(path, str) and path.startswith("advisor.")):
            continue  # an application registered by a test or a plug-in: validated by pydantic
        model = load(path)
        _compile(model, models)
        roots[kind] = path
    from advisor.core.questions import fixed_values, questions, wizard_questions

    title = next(q for q in questions(ApplicationReq, ("application",)) if q.path[-1] == "title")
    return {
        "roots": roots,
        "application": model_name(ApplicationReq),
        "models": models,
        # the wizard's questions, so that it asks them without importing pydantic either
        "questions": {k: tuple(map(tuple, wizard_questions(load(p)))) for k, p in roots.items()},
        "fixed": {k: fixed_values(load(p)) for k, p in roots.items()},
        "title": tuple(title),
    }


def spec_source(spec: dict[str, Any] | None = None) -> str:
    """The spec as a Python module: a model a paragraph, a field a line (diffs stay readable)."""
    spec = compile_spec() if spec is None else spec
    out = [
        '"""The requirement models compiled to data: generated by ``python -m '
        "advisor.core.spec_gen``.\n\nDo not edit: change the models (advisor/core/requirements.py, "
        "advisor/applications/*/requirements.py,\nadvisor/duty/requirements.py, "
        "advisor/uncertainty/requirements.py) and regenerate this file from the\n"
        "repository's root:\n\n    .venv/bin/python -m advisor.core.spec_gen\n\n"
        "tests/unit/test_compiled_validator.py fails while it differs from the models. What the "
        "generator\ncompiles and what it refuses: the docstring of "
        'advisor/core/spec_gen.py."""',
        "",
        "# fmt: off",
        "# ruff: noqa: E501",
        f"ROOTS = {spec['roots']!r}",
        f"APPLICATION = {spec['application']!r}",
        "MODELS = {",
    ]
    for name, m in spec["models"].items():
        out.append(f"    {name!r}: {{")
        out.append("        'fields': (")
        out.extend(f"            {f!r}," for f in m["fields"])
        out.append("        ),")
        for key in ("field_checks", "after", "mixins"):
            out.append(f"        {key!r}: {m[key]!r},")
        out.append("    },")
    out.append("}")
    out.append("#: The wizard's questions of each application (advisor.core.questions.Question).")
    out.append("QUESTIONS = {")
    for kind, qs in spec["questions"].items():
        out.append(f"    {kind!r}: (")
        out.extend(f"        {q!r}," for q in qs)
        out.append("    ),")
    out.append("}")
    out.append(f"FIXED = {spec['fixed']!r}")
    out.append(f"TITLE = {spec['title']!r}")
    return "\n".join(out) + "\n"


def main() -> None:
    SPEC_PATH.write_text(spec_source(), encoding="utf-8")
    print(f"wrote {SPEC_PATH}")


if __name__ == "__main__":
    main()
