"""A check of a design: a value against its limit, with the margin (≥ 1 passes).

Its own module so that every application can use it without importing the linear chain's
sizing (the induction motor and screw equations; issue 16)."""

from typing import TYPE_CHECKING, NamedTuple

if TYPE_CHECKING:  # the citation type; calc imports nothing of the core at run time
    from advisor.core.cite import Cite


class Check(NamedTuple):
    """One strength or function check: ``margin`` ≥ 1 passes. ``value`` is the demand as
    computed, ``limit`` the capacity; a strength check under a service factor states it in
    ``factor`` and its margin is limit / (factor·value)."""

    id: str
    name: str
    value: float
    limit: float
    unit: str
    margin: float
    source: "Cite"  # the bibliography ids and the place cited
    #: the service factor the demand was multiplied by (a strength check under
    #: ``[design] service_factor``): margin = limit / (factor·value); None: none applies
    factor: float | None = None

    @property
    def passed(self) -> bool:
        return self.margin >= 1.0
