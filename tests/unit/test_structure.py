"""The shape of the code, checked: small functions, no import circle, no private name used
across packages, comments that give reasons in the code's own terms.

Each check reads the sources with :mod:`ast` (nothing is imported), so a failure names the
file, the line and what to change.
"""

import ast
import io
import re
import tokenize
from collections.abc import Iterator
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PACKAGES = ("advisor", "catalogs", "rules")
#: Written by ``python -m advisor.core.spec_gen``: data, not code anyone edits.
GENERATED = {"advisor/core/requirement_spec.py"}
MAX_FUNCTION_LINES = 60


def sources(*packages: str) -> Iterator[tuple[str, ast.Module, str]]:
    """(path relative to the repository, parsed module, text) of every module."""
    for package in packages:
        for path in sorted((ROOT / package).rglob("*.py")):
            rel = path.relative_to(ROOT).as_posix()
            if rel in GENERATED:
                continue
            text = path.read_text(encoding="utf-8")
            yield rel, ast.parse(text, rel), text


def module_name(rel: str) -> str:
    parts = rel.removesuffix(".py").split("/")
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def package_of(rel: str) -> str:
    """The package a module belongs to (a package's ``__init__`` belongs to itself)."""
    parts = rel.removesuffix(".py").split("/")
    return ".".join(parts[:-1])


def test_no_function_is_longer_than_60_lines():
    long = [
        f"{rel}:{node.lineno} {node.name}() is {node.end_lineno - node.lineno + 1} lines"
        for rel, tree, _ in sources("advisor")
        for node in ast.walk(tree)
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef)
        and node.end_lineno - node.lineno + 1 > MAX_FUNCTION_LINES
    ]
    assert not long, "split these into steps of at most 60 lines:\n" + "\n".join(long)


def imports(rel: str, tree: ast.Module) -> set[str]:
    """The project modules a module imports, at its top or inside a function (a deferred
    import keeps the batch path light but is still a dependency), and those it names to
    :func:`importlib.import_module`; ``TYPE_CHECKING`` blocks never run and do not count."""
    found: set[str] = set()
    skipped = {
        id(sub)
        for node in ast.walk(tree)
        if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test)
        for sub in ast.walk(node)
    }
    for sub in ast.walk(tree):
        if id(sub) in skipped:
            continue
        if isinstance(sub, ast.Import):
            found.update(alias.name for alias in sub.names)
        elif isinstance(sub, ast.ImportFrom) and sub.module and sub.level == 0:
            # ``from a import b`` imports the module a.b where there is one, else a name of a
            # (resolved in import_graph); the package's own __init__ is not what it reads
            found.update(f"{sub.module}.{alias.name}" for alias in sub.names)
        elif (
            isinstance(sub, ast.Call)
            and ast.unparse(sub.func).endswith("import_module")
            and sub.args
            and isinstance(sub.args[0], ast.Constant)
            and isinstance(sub.args[0].value, str)
        ):
            found.add(sub.args[0].value)
    return {name for name in found if name.split(".")[0] in PACKAGES}


def import_graph() -> dict[str, set[str]]:
    modules = {module_name(rel): (rel, tree) for rel, tree, _ in sources(*PACKAGES)}
    graph: dict[str, set[str]] = {}
    for name, (rel, tree) in modules.items():
        edges = set()
        for target in imports(rel, tree):
            # ``from a.b import c`` names a module a.b.c or a name in a.b: keep what exists
            while target and target not in modules:
                target = target.rpartition(".")[0]
            if target and target != name:
                edges.add(target)
        graph[name] = edges
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected components of more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def test_the_cycle_finder_finds_a_circle():
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert cycles({"a": {"b"}, "b": set()}) == []


def test_no_import_circle():
    found = cycles(import_graph())
    assert not found, "modules that import each other:\n" + "\n".join(" ↔ ".join(c) for c in found)


def test_no_private_name_is_imported_across_packages():
    crossing = []
    for rel, tree, _ in sources(*PACKAGES):
        here = package_of(rel)
        for node in ast.walk(tree):
            if not (isinstance(node, ast.ImportFrom) and node.module and node.level == 0):
                continue
            if node.module.split(".")[0] not in PACKAGES:
                continue
            source_package = node.module.rpartition(".")[0]
            for alias in node.names:
                private = alias.name.startswith("_") and not alias.name.startswith("__")
                if private and here not in (node.module, source_package):
                    crossing.append(f"{rel}:{node.lineno} imports {node.module}.{alias.name}")
    assert not crossing, "publish these under a public name:\n" + "\n".join(crossing)


#: A named tuple's public methods begin with an underscore so as not to clash with its fields.
NAMEDTUPLE_API = {"_replace", "_asdict", "_fields", "_make", "_field_defaults"}


def test_no_private_attribute_of_another_module_is_used():
    """``advice._steel(...)`` through a module imported from another package is the same
    reach into private code as importing the name."""
    reaching = []
    for rel, tree, _ in sources(*PACKAGES):
        here = package_of(rel)
        modules = {}
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
                for alias in node.names:
                    modules[alias.asname or alias.name] = f"{node.module}.{alias.name}"
            elif isinstance(node, ast.Import):
                for alias in node.names:
                    if alias.asname:
                        modules[alias.asname] = alias.name
        for node in ast.walk(tree):
            if (
                isinstance(node, ast.Attribute)
                and isinstance(node.value, ast.Name)
                and node.value.id in modules
                and node.attr.startswith("_")
                and not node.attr.startswith("__")
                and node.attr not in NAMEDTUPLE_API
            ):
                target = modules[node.value.id]
                if target.split(".")[0] in PACKAGES and target.rpartition(".")[0] != here:
                    reaching.append(f"{rel}:{node.lineno} uses {target}.{node.attr}")
    assert not reaching, "publish these under a public name:\n" + "\n".join(reaching)


ISSUE_NUMBER = re.compile(r"\b[Ii]ssues? #?\d+|\(#\d+\)")


def comments_and_docstrings(tree: ast.Module, text: str) -> Iterator[tuple[int, str]]:
    """(line, text) of every comment and docstring of a module: the words written for the
    reader of the code (string values a report prints are the report's, checked by its
    golden files)."""
    for token in tokenize.generate_tokens(io.StringIO(text).readline):
        if token.type == tokenize.COMMENT:
            yield token.start[0], token.string
    for node in ast.walk(tree):
        if isinstance(node, ast.Module | ast.ClassDef | ast.FunctionDef | ast.AsyncFunctionDef):
            doc = ast.get_docstring(node, clean=False)
            if doc and node.body:
                yield node.body[0].lineno, doc


@pytest.mark.parametrize("package", PACKAGES)
def test_comments_give_reasons_not_issue_numbers(package):
    """An issue number means nothing inside the repository: the code says the reason."""
    cited = [
        f"{rel}:{line}: {ISSUE_NUMBER.search(words).group(0)}"
        for rel, tree, text in sources(package)
        for line, words in comments_and_docstrings(tree, text)
        if ISSUE_NUMBER.search(words)
    ]
    assert not cited, "say the reason instead of the issue number:\n" + "\n".join(cited)


def test_every_public_calculation_is_documented_with_its_units():
    """Every public function of ``advisor/calc`` says, as fluids does, its parameters and
    what it returns (units in brackets) and where the equation comes from."""
    undocumented = []
    for rel, tree, _ in sources("advisor"):
        if not rel.startswith("advisor/calc/"):
            continue
        for node in tree.body:
            if isinstance(node, ast.FunctionDef) and not node.name.startswith("_"):
                doc = ast.get_docstring(node) or ""
                missing = [s for s in ("Parameters", "Returns", "[") if s not in doc]
                if missing:
                    undocumented.append(f"{rel}:{node.lineno} {node.name}() lacks {missing}")
    assert not undocumented, "\n".join(undocumented)
