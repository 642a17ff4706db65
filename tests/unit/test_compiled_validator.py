"""The compiled validator (advisor/core/compiled_validator.py) against the requirement models
it is compiled from: the same documents accepted, the same values, the same report; and the
batch path free of pydantic."""

import copy
import math
import os
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from advisor.core import compiled_validator
from advisor.core.errors import InputError
from advisor.core.io_safety import read_toml
from advisor.core.reading import compiled_or_none, parse_requirements
from advisor.core.requirement_spec import MODELS, ROOTS
from advisor.core.spec_gen import SPEC_PATH, spec_source


def by_models(data):
    """The models' verdict: the reading path without the compiled validator."""
    return parse_requirements(data, compiled=False)


EXAMPLES = sorted(Path(__file__).parents[2].joinpath("examples").glob("*.toml"))


def _fields_set(obj):
    """Every table's given keys, by path: what advisor.core.ignored reads."""
    out = {}

    def walk(o, where):
        if hasattr(o, "model_fields_set"):
            out[where] = set(o.model_fields_set)
            for k in o.model_dump():
                walk(getattr(o, k), f"{where}.{k}")
        elif isinstance(o, list):
            for i, x in enumerate(o):
                walk(x, f"{where}[{i}]")

    walk(obj, "")
    return out


def _same(rec, model) -> None:
    assert isinstance(rec, compiled_validator.Record)
    assert rec.model_dump() == model.model_dump()
    assert rec.model_dump(exclude_none=True) == model.model_dump(exclude_none=True)
    # the same types too: 5 given for a float field is 5.0 on both sides
    assert repr(rec.model_dump()) == repr(model.model_dump())
    assert _fields_set(rec) == _fields_set(model)


def test_the_committed_spec_is_the_models_compiled():
    """A model changed without `python -m advisor.core.spec_gen` fails here."""
    assert SPEC_PATH.read_text(encoding="utf-8") == spec_source()


def test_every_application_is_compiled():
    from advisor.core.registry import applications

    assert set(ROOTS) == {a.kind for a in applications() if a.requirements.startswith("advisor.")}


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_every_example_is_read_without_the_models_and_equals_them(path):
    data = read_toml(path)
    rec = compiled_or_none(data)
    assert rec is not None, "an example fell back to the pydantic models"
    _same(rec, by_models(data))


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_the_report_is_the_same_from_either(path):
    from advisor.core.engine import advise
    from advisor.core.report import to_toml

    data = read_toml(path)
    assert to_toml(advise(compiled_validator.validate(data))) == to_toml(advise(by_models(data)))


def test_the_rotor_records_give_j_and_h_as_the_model_does():
    data = read_toml(next(p for p in EXAMPLES if p.stem == "gyro_compensator"))
    rec, model = compiled_validator.validate(data), by_models(data)
    assert rec.rotor.inertia == model.rotor.inertia
    assert rec.rotor.angular_momentum == model.rotor.angular_momentum


def test_records_are_read_only():
    rec = compiled_validator.validate(read_toml(EXAMPLES[0]))
    with pytest.raises(AttributeError):
        rec.application = None


def test_a_batch_run_imports_no_pydantic(tmp_path):
    """The batch path of a valid file: no pydantic, no pydantic_core (their model machinery
    costs more than the advice itself)."""
    code = (
        "import sys\n"
        "from advisor.cli import main\n"
        f"rc = main(['--batch', {str(EXAMPLES[0])!r}, '-o', {str(tmp_path / 'r.toml')!r}])\n"
        "bad = sorted(m for m in sys.modules if m.split('.')[0] in "
        "('pydantic', 'pydantic_core', 'annotated_types')\n"
        "             and m != 'pydantic.plugin._loader')\n"
        "print(rc, bad)\n"
    )
    env = {k: v for k, v in os.environ.items() if k != "PYDANTIC_DISABLE_PLUGINS"}
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, env=env, check=True
    ).stdout
    assert out.strip().splitlines()[-1] == "0 []"


def test_a_refused_file_is_worded_by_the_models():
    data = read_toml(next(p for p in EXAMPLES if p.stem == "rudder_actuator"))
    data["rotary"]["torque_Nm"] = -5.0
    with pytest.raises(InputError) as exc:
        parse_requirements(data)
    assert exc.value.messages[0].startswith("rotary.torque_Nm = -5.0: must be ≥ 1")


def test_a_unit_string_goes_to_the_models_and_is_converted():
    data = read_toml(next(p for p in EXAMPLES if p.stem == "rudder_actuator"))
    data["rotary"]["torque_Nm"] = "1 kN*m"
    assert compiled_validator.validate(data) is None
    assert parse_requirements(data).rotary.torque_Nm == 1000.0


# ------------------------------------------------------------ generated documents
def _tables(data, name, where=()):
    """(path, field spec) of every field of every table present in ``data``."""
    spec = MODELS[name]
    for key, t, _req, _default in spec["fields"]:
        yield (*where, key), t
        v = data.get(key) if isinstance(data, dict) else None
        inner = t[1] if t[0] == "optional" else t
        if inner[0] == "model" and isinstance(v, dict):
            yield from _tables(v, inner[1], (*where, key))
        if inner[0] == "list" and inner[1][0] == "model" and isinstance(v, list):
            for i, item in enumerate(v):
                if isinstance(item, dict):
                    yield from _tables(item, inner[1][1], (*where, key, i))


def _near(x: float) -> list[float]:
    return [x, math.nextafter(x, math.inf), math.nextafter(x, -math.inf), x * 1.5, -x]


def _values(t) -> st.SearchStrategy:
    inner = t[1] if t[0] == "optional" else t
    tag = inner[0]
    wrong = st.sampled_from(
        ["x", "5 kN", "", True, False, [], {}, [1.0, 2.0], math.nan, math.inf, 0, -1]
    )
    if tag in ("float", "int"):
        limits = [v for v in inner[1].values()]
        near = [y for x in limits for y in _near(float(x))]
        special = [1e-10, 1e-7, 5e-7, 2e-6, 49.0, 50.0, 51.0, 1000.0]  # the models' own checks
        nums = st.sampled_from(near + special) | st.floats(allow_nan=False, width=64)
        if tag == "int":
            nums = st.sampled_from([int(x) for x in limits] or [1]) | st.integers(-5, 60)
        return nums | st.integers(-10, 10) | wrong
    if tag == "literal":
        return st.sampled_from(list(inner[1])) | st.sampled_from(["S11", "none", "Bldc"]) | wrong
    if tag == "str":
        threads = [" Tr16x2 ", "tr 16 x 2", "Tr16×2", "Tr16.25x2", "Tr16x2.125", "Tr16x2.00"]
        return (
            st.text(max_size=5)
            | st.sampled_from(["Tr16x2", "Tr10x1.5", "x" * 201, *threads])
            | wrong
        )
    if tag == "list":
        item = inner[1]
        if item[0] == "model":
            return wrong
        twice = _values(item).map(lambda x: [x, x])  # a value given twice
        return st.lists(_values(item), max_size=4) | twice | wrong
    return wrong


def _set(doc, path, value) -> None:
    for p in path[:-1]:
        doc = doc[p]
    doc[path[-1]] = value


def _delete(doc, path) -> None:
    for p in path[:-1]:
        doc = doc[p]
    if isinstance(doc, dict):
        doc.pop(path[-1], None)


@st.composite
def documents(draw):
    base = read_toml(draw(st.sampled_from(EXAMPLES)))
    doc = copy.deepcopy(base)
    for _ in range(draw(st.integers(1, 3))):
        app = doc.get("application")
        kind = app.get("kind") if isinstance(app, dict) else None
        root = ROOTS.get(kind) if isinstance(kind, str) else None
        if root is None:
            break
        fields = list(_tables(doc, root))
        path, t = draw(st.sampled_from(fields))
        try:
            op = draw(st.sampled_from(["set", "set", "set", "delete", "unknown"]))
            if op == "set":
                _set(doc, path, draw(_values(t)))
            elif op == "delete":
                _delete(doc, path)
            else:
                _set(doc, (*path[:-1], draw(st.sampled_from(["strok_m", "x", "kind2"]))), 1.0)
        except (KeyError, IndexError, TypeError):
            continue  # a table the path runs through is missing or not a table any more
    return doc


def _models_verdict(doc):
    try:
        return by_models(copy.deepcopy(doc)), None
    except InputError as exc:
        return None, exc.messages


def _has_unit_string(doc) -> bool:
    from advisor.core.units import convert

    try:
        from advisor.core.registry import requirements_model

        model = requirements_model(doc["application"]["kind"])
        return convert(copy.deepcopy(doc), model) != doc
    except Exception:  # no model to convert with: the models refuse anyway
        return False


@pytest.mark.slow  # seconds: outside the quick subset
@settings(max_examples=1000, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(documents())
def test_the_compiled_validator_accepts_what_the_models_accept(doc):
    rec = compiled_or_none(copy.deepcopy(doc))
    model, messages = _models_verdict(doc)
    if rec is not None:
        assert model is not None, f"accepted here, refused by the models: {messages}"
        _same(rec, model)
    elif model is not None:  # refused here, accepted by the models: only a unit to convert
        assert _has_unit_string(doc), "the compiled validator refused a valid document"
    # and what the user gets is the models' verdict, word for word
    try:
        got = parse_requirements(copy.deepcopy(doc))
    except InputError as exc:
        assert messages == exc.messages
    else:
        assert model is not None
        assert got.model_dump() == model.model_dump()


#: Each of the models' own checks, at a value it refuses and at one it lets through (the
#: generated documents above reach these values too seldom to be relied on).
OWN_CHECKS = [
    ("rudder_actuator", ("motor", "candidate_speeds_rpm"), [5000.0, 5000.0]),
    ("rudder_actuator", ("motor", "candidate_speeds_rpm"), [5000.0, 7000.0]),
    ("rudder_actuator", ("rotary", "speed_rpm"), 5000.0),
    ("rudder_actuator", ("rotary", "speed_rpm"), 4999.0),
    ("linear_screw_actuator", ("motor", "supply_frequency_Hz"), 60.0),
    ("linear_screw_actuator", ("motor", "supply_frequency_Hz"), 50),
    ("linear_screw_actuator", ("screw", "thread"), "tr 16 x 2"),
    ("linear_screw_actuator", ("screw", "thread"), "Tr16.125x2"),
    ("linear_screw_actuator", ("screw", "thread"), "M16"),
    ("linear_screw_actuator", ("linear", "stroke_m"), 50.0),
    ("positioning_drive", ("positioning", "load_inertia_kgm2"), 1e-10),
    ("positioning_drive", ("positioning", "load_inertia_kgm2"), 0),
    ("positioning_drive", ("positioning", "load_torque_Nm"), 5e-7),
    ("positioning_drive", ("positioning", "load_torque_Nm"), 1e-6),
    ("gyro_compensator", ("rotor", "slew_rate_rad_s"), 5e-7),
    ("gyro_compensator", ("rotor", "slew_rate_rad_s"), 0.0),
    ("gyro_compensator", ("rotor", "inertia_kgm2"), 0.01),
    ("valve_actuator_duty", ("duty", "duty_type"), "S3"),
    ("rudder_actuator_duty", ("duty", "cycles_per_hour"), 3600.0),
    ("rudder_actuator", ("application", "kind"), "rotor"),
    ("rudder_actuator", ("application", "kind"), "linear"),
    ("rudder_actuator", ("application", "kind"), "Rotary"),
]


@pytest.mark.parametrize(("example", "path", "value"), OWN_CHECKS)
def test_the_models_own_checks_decide_alike(example, path, value):
    doc = read_toml(next(p for p in EXAMPLES if p.stem == example))
    _set(doc, path, value)
    rec = compiled_or_none(copy.deepcopy(doc))
    model, messages = _models_verdict(doc)
    assert (rec is None) == (model is None), messages
    if rec is not None:
        _same(rec, model)


# ------------------------------------------------------------ what the generator refuses
def _refusable_models() -> list:
    """Small models using what spec_gen cannot compile faithfully (a reviewer's list): each
    must stop the generator rather than give a validator that accepts or builds otherwise."""
    from typing import Annotated, Literal

    from pydantic import (
        ConfigDict,
        Field,
        computed_field,
        field_serializer,
        field_validator,
        model_validator,
    )

    from advisor.core.requirements import StrictModel

    class Alias(StrictModel):
        x: Annotated[float, Field(validation_alias="y")] = 1.0

    class LiteralLength(StrictModel):
        x: Annotated[Literal["a", "bb"], Field(max_length=1)] = "a"

    class Star(StrictModel):
        x: float = 1.0

        @field_validator("*")
        @classmethod
        def _any(cls, v):
            return v

    class StrMax(StrictModel):
        model_config = ConfigDict(str_max_length=3)
        x: str = ""

    class Strip(StrictModel):
        model_config = ConfigDict(str_strip_whitespace=True)
        x: str = ""

    class Excluded(StrictModel):
        x: Annotated[float, Field(exclude=True)] = 1.0

    class Computed(StrictModel):
        x: float = 1.0

        @computed_field
        @property
        def twice(self) -> float:
            return 2 * self.x

    class Serialized(StrictModel):
        x: float = 1.0

        @field_serializer("x")
        def _ser(self, v):
            return v

    class ValidateDefault(StrictModel):
        x: Annotated[float, Field(validate_default=True)] = 1.0

    class PostInit(StrictModel):
        x: float = 1.0

        def model_post_init(self, context):
            pass

    class OwnProperty(StrictModel):
        x: float = 1.0

        @property
        def twice(self) -> float:
            return 2 * self.x

    class Mixin:
        @property
        def twice(self) -> float:
            return 2 * self.x

    class UnslottedMixin(Mixin, StrictModel):
        x: float = 1.0

    class Before(StrictModel):
        x: float = 1.0

        @field_validator("x", mode="before")
        @classmethod
        def _b(cls, v):
            return v

    class NoTwin(StrictModel):
        x: float = 1.0

        @model_validator(mode="after")
        def _check(self):
            return self

    return [
        Alias,
        LiteralLength,
        Star,
        StrMax,
        Strip,
        Excluded,
        Computed,
        Serialized,
        ValidateDefault,
        PostInit,
        OwnProperty,
        UnslottedMixin,
        Before,
        NoTwin,
    ]


@pytest.mark.parametrize("model", _refusable_models(), ids=lambda m: m.__name__)
def test_the_generator_refuses_what_it_cannot_compile(model):
    from advisor.core import spec_gen

    with pytest.raises(ValueError):
        spec_gen._compile(model, {})


def test_records_hash_and_pickle_as_the_frozen_models_do():
    import pickle

    data = read_toml(next(p for p in EXAMPLES if p.stem == "gyro_compensator"))
    rec, again = compiled_validator.validate(data), compiled_validator.validate(copy.deepcopy(data))
    assert hash(rec.rotor.aero) == hash(again.rotor.aero)
    back = pickle.loads(pickle.dumps(rec))
    assert back == rec and back.model_fields_set == rec.model_fields_set
    assert back.rotor.inertia == rec.rotor.inertia  # the mixin came back with the class
    rudder = compiled_validator.validate(
        read_toml(next(p for p in EXAMPLES if p.stem == "rudder_actuator"))
    )
    with pytest.raises(TypeError):  # a list inside: unhashable, as for the pydantic model
        hash(rudder.motor)
