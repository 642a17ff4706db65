"""The batch path imports only what its application uses (issue 16): a cold run of
``advisor --batch`` is held to 1.3 × the bare import of numpy, scipy, pydantic and tomli-w,
and every library it imports for nothing counts against that."""

import subprocess
import sys

import pytest
from helpers import EXAMPLES

#: Never on the batch path: the wizard's libraries, the family studies' and plotting ones.
NEVER = ("textual", "rich", "pint", "dask", "matplotlib", "pandas", "numpy.ma")
#: Applications whose path needs no numpy at all (their sizes are a few dozen numbers).
NO_NUMPY = {"linear_screw_actuator.toml", "positioning_drive.toml"}
#: Applications whose path still needs scipy (none should: issue 16).
NEEDS_SCIPY: set[str] = set()

EXAMPLE_NAMES = sorted(p.name for p in EXAMPLES.glob("*.toml"))


def _imported(args: list[str]) -> set[str]:
    code = (
        "import sys, io, contextlib\n"
        "from advisor.cli import main\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n"
        f"    rc = main({args!r})\n"
        "assert rc == 0, rc\n"
        "print(' '.join(sorted(sys.modules)))\n"
    )
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return set(r.stdout.split())


def _heavy(example: str, modules: set[str]) -> list[str]:
    banned = list(NEVER)
    if example in NO_NUMPY:
        banned.append("numpy")
    if example in NEEDS_SCIPY:
        banned.remove("numpy.ma")  # scipy imports it
    else:
        banned.append("scipy")
    return sorted(m for m in modules if m in banned or m.split(".")[0] in banned)


@pytest.mark.parametrize("example", EXAMPLE_NAMES)
def test_batch_to_stdout_imports_nothing_it_does_not_use(example):
    assert _heavy(example, _imported(["--batch", str(EXAMPLES / example)])) == []


@pytest.mark.parametrize("example", EXAMPLE_NAMES)
def test_batch_with_output_file_imports_nothing_it_does_not_use(example, tmp_path):
    """The -o path: its summary is plain text (no rich), and it does not load the many-file
    runner or multiprocessing."""
    modules = _imported(["--batch", str(EXAMPLES / example), "-o", str(tmp_path / "r.toml")])
    assert (tmp_path / "r.toml").is_file()
    assert _heavy(example, modules) == []
    assert "advisor.many" not in modules and "multiprocessing" not in modules


@pytest.mark.parametrize("example", EXAMPLE_NAMES)
def test_only_the_application_of_the_file_is_imported(example):
    """Neither the other applications' packages nor their rule modules."""
    import tomllib

    kind = tomllib.loads((EXAMPLES / example).read_text(encoding="utf-8"))["application"]["kind"]
    modules = _imported(["--batch", str(EXAMPLES / example)])
    apps = {m.split(".")[2] for m in modules if m.startswith("advisor.applications.")}
    assert apps == {kind}
    rules = {m.removeprefix("rules.") for m in modules if m.startswith("rules.")}
    assert rules <= OWN_RULES[kind] | SHARED_RULES, rules


#: The rule modules of each application's own domain; a run of one imports no other's.
OWN_RULES = {
    "linear": {"screw", "induction"},
    "rotary": {"wavegear", "bldc"},
    "positioning": {"motion", "induction"},
    "spinning_rotor": {"rotor"},
}
#: Rules any application may use: the duty cycle's and the one-way device's (holding).
SHARED_RULES = {"duty", "one_way"}


def test_load_all_registers_every_rule_module():
    """The rule package imports no module by itself; load_all gives the whole rule table."""
    import rules

    table = rules.load_all()
    assert {r.fn.__module__ for r in table.values()} == {f"rules.{n}" for n in rules.MODULES}
    assert all(r.id == rid for rid, r in table.items())
