"""The light plugin loader (advisor.core.pydantic_plugins): pydantic still validates, loads
no plugin, and the batch never imports importlib.metadata for it."""

import os
import subprocess
import sys

CODE = """
import sys
from advisor.core import pydantic_plugins
assert pydantic_plugins.disable()
from pydantic import BaseModel, Field, ValidationError
class A(BaseModel):
    x: float = Field(gt=0)
assert A(x=2.0).x == 2.0
try:
    A(x=-1.0)
except ValidationError as exc:
    assert "greater than 0" in str(exc)
else:
    raise SystemExit("not validated")
from pydantic.plugin import _loader
assert list(_loader.get_plugins()) == []
assert _loader.PYDANTIC_ENTRY_POINT_GROUP == "pydantic"  # any other name: the real module
print("importlib.metadata" in sys.modules)
"""


def _run(code: str, **env: str) -> subprocess.CompletedProcess:
    e = {k: v for k, v in os.environ.items() if k != "PYDANTIC_DISABLE_PLUGINS"} | env
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=e)


def test_pydantic_validates_with_the_light_loader():
    out = _run(CODE)
    assert out.returncode == 0, out.stderr
    # the real loader was asked for a constant, so metadata is imported only then
    assert out.stdout.strip() == "True"


def test_no_metadata_import_on_the_batch(tmp_path):
    code = (
        "import sys\n"
        "from advisor.cli import main\n"
        f"rc = main(['--batch', {str(_example())!r}, '-o', {str(tmp_path / 'r.toml')!r}])\n"
        "assert rc == 0, rc\n"
        "print('importlib.metadata' in sys.modules)\n"
    )
    out = _run(code)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip().splitlines()[-1] == "False"


def test_a_users_plugin_choice_is_kept():
    code = (
        "from advisor.core import pydantic_plugins\n"
        "print(pydantic_plugins.disable())\n"
        "import sys; print('pydantic.plugin._loader' in sys.modules)\n"
    )
    out = _run(code, PYDANTIC_DISABLE_PLUGINS="someplugin")
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["False", "False"]


def _example():
    from pathlib import Path

    return Path(__file__).resolve().parents[2] / "examples" / "rudder_actuator.toml"
