"""The rule engine core: rules with metadata, and the trace of decisions they make.

A rule is a small pure function decorated with :func:`rule`, which gives it a stable id, a
title and its sources (a :class:`~advisor.core.cite.Cite` of bibliography ids). A rule looks
at facts and returns a :class:`Finding`: the value chosen, the decision in words, the
rationale an engineer would accept, and the inputs it looked at. The engine runs rules through
a :class:`Trace`, which records every finding as a :class:`Decision` — the audit trail the
report carries as ``[[decisions]]``.

(Records are NamedTuples rather than dataclasses: a dataclass compiles its methods at import,
about 0.3 ms each, and the cold batch run has a budget of a few tens of milliseconds.)
"""

from collections.abc import Callable
from typing import Any, Generic, NamedTuple, TypeVar

from advisor.core.cite import Cite

T = TypeVar("T")


class Finding(NamedTuple, Generic[T]):
    value: T
    decision: str
    rationale: str
    inputs: dict[str, Any] | None = None


class Decision(NamedTuple):
    id: str
    title: str
    decision: str
    rationale: str
    source: Cite
    inputs: dict[str, Any]


class Rule(Generic[T]):
    """A registered rule: call it like the function it wraps."""

    __slots__ = ("fn", "id", "source", "title")

    def __init__(self, id: str, title: str, source: Cite, fn: Callable[..., Finding[T]]) -> None:
        self.id, self.title, self.source, self.fn = id, title, source, fn

    def __call__(self, *args: Any, **kwargs: Any) -> Finding[T]:
        return self.fn(*args, **kwargs)

    def __repr__(self) -> str:
        return f"Rule({self.id!r}, {self.title!r})"


#: Every rule, by id: the rule table the documentation and the tests read.
REGISTRY: dict[str, Rule[Any]] = {}


def rule(id: str, title: str, source: Cite) -> Callable[[Callable[..., Finding[T]]], Rule[T]]:
    """Register a function as a rule with a stable id, a title and its sources."""
    if not isinstance(source, Cite) or not source.refs:
        raise TypeError(f"rule {id}: its source must cite the bibliography (a Cite)")

    def wrap(fn: Callable[..., Finding[T]]) -> Rule[T]:
        if id in REGISTRY:
            raise ValueError(f"rule id {id} registered twice")
        r = Rule(id, title, source, fn)
        REGISTRY[id] = r
        return r

    return wrap


class Trace:
    """The decisions taken for one requirement, in the order they were taken."""

    __slots__ = ("decisions",)

    def __init__(self) -> None:
        self.decisions: list[Decision] = []

    def apply(self, r: Rule[T], *args: Any, **kwargs: Any) -> T:
        """Run a rule, record its finding, return the value it chose."""
        f = r(*args, **kwargs)
        self.decisions.append(
            Decision(r.id, r.title, f.decision, f.rationale, r.source, dict(f.inputs or {}))
        )
        return f.value

    def find(self, id: str) -> Decision:
        """The last decision taken by the rule ``id``."""
        return next(d for d in reversed(self.decisions) if d.id == id)
