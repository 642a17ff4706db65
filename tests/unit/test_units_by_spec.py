"""Unit strings converted by the compiled spec (units.convert_by_spec): the same values as the
models' conversion (units.convert), and no pydantic imported for a file of a shipped
application; anything in doubt is left to the models, which word every refusal."""

import copy
import subprocess
import sys
import tomllib

import pytest
from helpers import EXAMPLES

from advisor.core import compiled_validator
from advisor.core.reading import parse_requirements
from advisor.core.registry import requirements_model
from advisor.core.units import convert, convert_by_spec


def _doc(name: str) -> dict:
    return tomllib.loads((EXAMPLES / name).read_text(encoding="utf-8"))


def _typed() -> list[dict]:
    linear = _doc("linear_screw_actuator.toml")
    linear["linear"] |= {"force_N": "3.5 kN", "stroke_m": "200 mm", "support_span_m": "40 cm"}
    rotary = _doc("rudder_actuator.toml")
    rotary["motor"]["candidate_speeds_rpm"] = ["5000 rpm", "1047.19755 rad/s"]
    rotary["rotary"]["torque_Nm"] = "1.62 kN*m"
    pos = _doc("positioning_drive.toml")
    pos["positioning"]["motors"][0]["speed_rad_s"] = "1432.394 rpm"
    pos["positioning"]["travel_rad"] = "572.9578 deg"
    return [linear, rotary, pos]


@pytest.mark.parametrize("doc", _typed(), ids=["linear", "rotary lists", "positioning rows"])
def test_the_spec_converts_as_the_models_do(doc):
    before = copy.deepcopy(doc)
    by_spec = convert_by_spec(doc)
    assert doc == before  # the document itself is not changed
    assert by_spec != doc
    assert by_spec == convert(doc, requirements_model(doc["application"]["kind"]))
    assert compiled_validator.validate(by_spec) is not None  # read without the models


def test_a_document_in_doubt_is_left_to_the_models():
    doc = _doc("linear_screw_actuator.toml")
    assert convert_by_spec(doc) is doc  # plain numbers: not walked
    doc["linear"]["force_N"] = "5 m"  # a length where a force goes
    assert convert_by_spec(doc) is doc
    doc["linear"]["force_N"] = "3.5 kN"
    doc["application"]["kind"] = "nothing registered"
    assert convert_by_spec(doc) is doc
    assert convert_by_spec(["5 kN"]) == ["5 kN"]


def test_values_read_by_the_spec_equal_the_models():
    for doc in _typed():
        by_models = parse_requirements(doc, compiled=False)
        assert parse_requirements(doc).model_dump() == by_models.model_dump()


def test_a_file_with_unit_strings_imports_no_pydantic(tmp_path):
    typed = tmp_path / "typed.toml"
    text = (EXAMPLES / "rudder_actuator.toml").read_text(encoding="utf-8")
    typed.write_text(text.replace("torque_Nm = 1620", 'torque_Nm = "1.62 kN*m"'), "utf-8")
    code = (
        "import sys\n"
        "from advisor.core.reading import read_requirements\n"
        "read_requirements(sys.argv[1])\n"
        "print('pydantic.main' in sys.modules)\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code, str(typed)], capture_output=True, text=True, check=True
    )
    assert out.stdout.split() == ["False"]
