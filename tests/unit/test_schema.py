"""The published description of requirement files is generated from the models and current:
the JSON Schema (`advisor schema`) and its copy beside the examples, the tables of keys in
docs/reference/keys.md, and every example names the schema and fits it."""

import json
import tomllib
from pathlib import Path

from helpers import EXAMPLES

from advisor.cli import main
from advisor.core import registry
from advisor.core.schema import KEYS_DOC, key_tables, with_key_tables

ROOT = Path(__file__).parents[2]
SHIPPED = EXAMPLES / "requirements.schema.json"


def test_advisor_schema_prints_the_shipped_schema(capsys):
    assert main(["schema"]) == 0
    out = capsys.readouterr().out
    assert out == SHIPPED.read_text(encoding="utf-8"), "regenerate: advisor schema > " + str(
        SHIPPED
    )
    schema = json.loads(out)
    assert [r["$ref"].rsplit("/", 1)[-1] for r in schema["oneOf"]] == [
        registry.requirements_model(k).__name__ for k in registry.kinds()
    ]


def test_the_key_tables_in_the_docs_are_current(capsys):
    assert KEYS_DOC == ROOT / "docs" / "reference" / "keys.md"
    doc = KEYS_DOC.read_text(encoding="utf-8")
    assert with_key_tables(doc) == doc, "regenerate: python -m advisor.core.schema"
    assert main(["schema", "--markdown"]) == 0
    assert capsys.readouterr().out in doc
    assert "requirement-keys:begin" not in (ROOT / "README.md").read_text(encoding="utf-8")
    # one line per key, e.g. the rotary stage efficiency with its default and range
    assert "| `gearbox.stage_efficiency` | number |  | 0.9 | ≥ 0.3, ≤ 1 |" in key_tables()
    assert "| `linear.support_span_m` | number | m | required | ≥ 0.001, ≤ 20 |" in key_tables()


def _resolve(schema: dict, node: dict) -> dict:
    while "$ref" in node or "allOf" in node:
        if "$ref" in node:
            node = schema["$defs"][node["$ref"].rsplit("/", 1)[-1]]
        else:
            node = _resolve(schema, node["allOf"][0])
    return node


def _fits(schema: dict, node: dict, doc: dict, where: str) -> None:
    node = _resolve(schema, node)
    props = node["properties"]
    for key in node.get("required", []):
        assert key in doc, f"{where}{key} is required by the schema"
    for key, value in doc.items():
        assert key in props, f"{where}{key} is not in the schema"
        if isinstance(value, dict):
            _fits(schema, props[key], value, f"{where}{key}.")


def test_every_example_names_the_schema_and_fits_it():
    schema = json.loads(SHIPPED.read_text(encoding="utf-8"))
    apps = {
        _resolve(schema, ref)["properties"]["application"]["allOf"][1]["properties"]["kind"][
            "const"
        ]: ref
        for ref in schema["oneOf"]
    }
    for src in sorted(EXAMPLES.glob("*.toml")):
        text = src.read_text(encoding="utf-8")
        assert text.startswith("#:schema ./requirements.schema.json\n"), src.name
        doc = tomllib.loads(text)
        _fits(schema, apps[doc["application"]["kind"]], doc, "")
