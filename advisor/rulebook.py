"""The rule engine core: rules with metadata, and the trace of decisions they make.

A rule is a small pure function decorated with :func:`rule`, which gives it a stable id, a
title and a source (a seed file name or a standard). A rule looks at facts and returns a
:class:`Finding`: the value chosen, the decision in words, the rationale an engineer would
accept, and the inputs it looked at. The engine runs rules through a :class:`Trace`, which
records every finding as a :class:`Decision` — the audit trail the report carries as
``[[decisions]]``.
"""

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, Generic, ParamSpec, TypeVar

T = TypeVar("T")
P = ParamSpec("P")


@dataclass(frozen=True)
class Finding(Generic[T]):
    value: T
    decision: str
    rationale: str
    inputs: dict[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class Decision:
    id: str
    title: str
    decision: str
    rationale: str
    source: str
    inputs: dict[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class Rule(Generic[P, T]):
    id: str
    title: str
    source: str
    fn: Callable[P, Finding[T]]

    def __call__(self, *args: P.args, **kwargs: P.kwargs) -> Finding[T]:
        return self.fn(*args, **kwargs)


#: Every rule, by id: the rule table the documentation and the tests read.
REGISTRY: dict[str, Rule[Any, Any]] = {}


def rule(id: str, title: str, source: str) -> Callable[[Callable[P, Finding[T]]], Rule[P, T]]:
    """Register a function as a rule with a stable id, a title and its source."""

    def wrap(fn: Callable[P, Finding[T]]) -> Rule[P, T]:
        if id in REGISTRY:
            raise ValueError(f"rule id {id} registered twice")
        r = Rule(id=id, title=title, source=source, fn=fn)
        REGISTRY[id] = r
        return r

    return wrap


@dataclass
class Trace:
    """The decisions taken for one requirement, in the order they were taken."""

    decisions: list[Decision] = field(default_factory=list)

    def apply(self, r: Rule[P, T], *args: P.args, **kwargs: P.kwargs) -> T:
        """Run a rule, record its finding, return the value it chose."""
        f = r(*args, **kwargs)
        self.decisions.append(
            Decision(r.id, r.title, f.decision, f.rationale, r.source, dict(f.inputs))
        )
        return f.value

    def find(self, id: str) -> Decision:
        """The last decision taken by the rule ``id``."""
        return next(d for d in reversed(self.decisions) if d.id == id)
