"""The datasheet's compiled labels and defaults (advisor/datasheet/compiled_labels.py) are
what the requirement models give: regenerated here, they must equal the committed file."""

import subprocess
import sys
from pathlib import Path

from advisor.core.registry import requirements_model
from advisor.core.requirement_spec import ROOTS
from advisor.datasheet import labels


def test_the_committed_table_is_what_the_models_give():
    committed = (Path(labels.__file__).parent / labels.COMPILED_FILE).read_text(encoding="utf-8")
    assert committed == labels.compiled_text(), (
        "the requirement models changed: run python -m advisor.datasheet.labels"
    )


def test_compiled_labels_and_defaults_equal_the_models_for_every_shipped_application():
    for kind in ROOTS:
        model = requirements_model(kind)
        got_labels, got_defaults = labels.for_application(kind)
        assert got_labels == labels.requirement_labels(model)
        full = labels.requirement_defaults(model)
        # every default is compiled, a list of tables (magnet_losses) as plain tables: a
        # default left out would count its field as given on the datasheet
        assert got_defaults == full


def test_a_datasheet_imports_no_pydantic(tmp_path):
    code = (
        "import sys\n"
        "from advisor.cli import main\n"
        "main(['--batch', sys.argv[1], '--format', 'md', '-o', sys.argv[2]])\n"
        "print(sorted(m for m in sys.modules if m in ('pydantic', 'pydantic.main')))\n"
    )
    example = Path(__file__).parents[2] / "examples" / "rudder_actuator_duty.toml"
    runs = [
        subprocess.run(
            [sys.executable, "-c", code, str(example), str(tmp_path / "r.md")],
            capture_output=True,
            text=True,
            check=True,
        ).stdout
        for _ in range(2)  # the first may validate the catalogs (pydantic) and cache them
    ]
    assert runs[1].splitlines()[-1] == "[]"
