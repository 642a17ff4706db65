"""Nothing outside an application's package names its kind: every face asks the registry
entry through a hook (plots, family outputs, margin model, duty keys, views …).

The source is read as Python (:mod:`ast`), not as text, so that prose ("a linear scale",
"the rotary actuator" in a docstring) is not a finding, while a kind used as a kind is:
a string literal compared with a kind, looked up (a dict key, a subscript, ``.get``,
``getattr``, a ``case``) or any literal equal to a kind that is no ordinary word, and an
attribute named after a kind (``req.rotary``, ``report.linear``)."""

import ast
from pathlib import Path

import pytest

from advisor.core import registry

ADVISOR = Path(__file__).resolve().parents[2] / "advisor"
#: Kinds that are also ordinary words of the domain ("linear" scale): a literal of them is
#: a finding only where it is used as a kind.
ORDINARY = {"linear"}
#: Where kinds are named by design: the applications themselves, and the files generated
#: from their requirement models (the compiled validator, the datasheet's field labels).
EXEMPT = ("applications/", "core/requirement_spec.py", "datasheet/compiled_labels.py")


def _kind_context(node: ast.Constant, parent: ast.AST) -> bool:
    """Whether a literal sits where a kind is used as a kind."""
    if isinstance(parent, ast.Dict) and node in parent.keys:
        return True
    if isinstance(parent, ast.Subscript) and parent.slice is node:
        return True
    if isinstance(parent, ast.Compare):
        other = " ".join(ast.unparse(x) for x in (parent.left, *parent.comparators))
        return "kind" in other or "application" in other
    if isinstance(parent, ast.Call) and parent.args and parent.args[0] is node:
        f = parent.func
        return isinstance(f, ast.Attribute) and f.attr in ("get", "pop", "setdefault")
    if isinstance(parent, ast.Call) and len(parent.args) > 1 and parent.args[1] is node:
        return isinstance(parent.func, ast.Name) and parent.func.id in ("getattr", "hasattr")
    return isinstance(parent, ast.MatchValue)


def findings(source: str, kinds: set[str]) -> list[tuple[int, str]]:
    """(line, what) of every use of a kind as a kind in ``source``."""
    tree = ast.parse(source)
    parents = {c: p for p in ast.walk(tree) for c in ast.iter_child_nodes(p)}
    out = []
    for n in ast.walk(tree):
        if isinstance(n, ast.Attribute) and n.attr in kinds:
            out.append((n.lineno, f"attribute .{n.attr}"))
        elif isinstance(n, ast.Constant) and n.value in kinds:
            parent = parents.get(n)
            # a literal inside a tuple or set compared with a kind: ``kind in ("a", "b")``
            if isinstance(parent, ast.Tuple | ast.List | ast.Set):
                parent = parents.get(parent, parent)
            if n.value not in ORDINARY or _kind_context(n, parent):
                out.append((n.lineno, f"literal {n.value!r}"))
    return out


def shipped_kinds() -> set[str]:
    return set(registry.kinds())


def test_the_scan_finds_kinds_used_as_kinds_and_not_ordinary_words():
    kinds = {"linear", "rotary"}
    found = findings(
        'if req.application.kind == "rotary": pass\n'
        'EXTRACTORS = {"linear": f}\n'
        "x = req.rotary\n"
        "y = report.linear\n"
        'z = TABLE["linear"]\n'
        'w = TABLE.get("linear")\n'
        'if kind in ("linear", "x"): pass\n'
        'MODELS = {"rotary": "m"}\n',
        kinds,
    )
    assert sorted(line for line, _ in found) == [1, 2, 3, 4, 5, 6, 7, 8]
    ordinary = (
        'SCALES = ("linear", "log")\n'
        'scale = spec.get("scale", "linear")\n'
        'ok = scale == "linear"\n'
        '"""A linear scale, the rotary actuator."""\n'
    )
    assert findings(ordinary, kinds) == []


@pytest.mark.parametrize(
    "path",
    sorted(
        p for p in ADVISOR.rglob("*.py") if not p.relative_to(ADVISOR).as_posix().startswith(EXEMPT)
    ),
    ids=lambda p: p.relative_to(ADVISOR).as_posix(),
)
def test_no_module_outside_the_applications_names_a_kind(path):
    found = findings(path.read_text(encoding="utf-8"), shipped_kinds())
    assert found == [], f"{path.relative_to(ADVISOR)} names a kind: {found}"
