"""A check of a design: a value against its limit, with the margin (≥ 1 passes).

A design check, not a requirement's: the rules a requirement file must meet are the
``requirement_checks`` modules of the applications. Its own module so that every application
can use it without importing the linear chain's sizing (the induction motor and screw
equations)."""

import math
from typing import TYPE_CHECKING, NamedTuple

if TYPE_CHECKING:  # the citation type; calc imports nothing of the core at run time
    from advisor.core.cite import Cite


class Check(NamedTuple):
    """One strength or function check of a design, in one convention for every check:

        margin = limit/value   (value ≤ limit: a load, a stress, a speed)
        margin = value/limit   (value ≥ limit: a life, a static safety, a ratio)

    Under a service factor f_B a strength check states the factored demand, value =
    f_B·demand, and its name says "× f_B", so value, limit and margin agree for a reader
    (:func:`factored`, which the linear chain's strength checks and the rotary stages' torque
    checks are built by).

    Attributes
    ----------
    id : str
        Stable id of the check (``motor_rated_torque``, ``travel_time`` …)
    name : str
        What is checked, in words
    value : float
        The demand as computed [unit]
    limit : float
        The capacity it is checked against [unit]
    unit : str
        The unit of value and limit (N·m, W, K, h …)
    margin : float
        limit over demand [-]; ≥ 1 passes (:attr:`passed`)
    source : Cite
        The bibliography ids and the place cited
    factor : float or None
        None in every check the advisor makes: a service factor is already in ``value``.
        Kept so that a check built with one still reads (``margin`` is then as given)
    """

    id: str
    name: str
    value: float
    limit: float
    unit: str
    margin: float
    source: "Cite"
    factor: float | None = None

    @property
    def passed(self) -> bool:
        return self.margin >= 1.0


def factored(
    id: str, name: str, demand: float, limit: float, unit: str, factor: float, source: "Cite"
) -> Check:
    """A strength check under the service factor f_B, stated as the factored demand.

        value = f_B·demand,   margin = limit / value   (∞ for no demand)

    Parameters
    ----------
    id, name : str
        The check's id and its name in words (which says "× f_B")
    demand : float
        The demand before the factor [unit]
    limit : float
        The capacity [unit]
    unit : str
        The unit of demand and limit
    factor : float
        The service factor f_B [-], ≥ 1
    source : Cite
        Where the check comes from

    Returns
    -------
    Check
        value f_B·demand, so that value, limit and margin agree for a reader

    References
    ----------
    SEW-EURODRIVE, service factor f_B (``[design] service_factor``).

    Examples
    --------
    >>> c = factored("buckling", "column × f_B", 5000.0, 8691.56, "N", 1.25, None)
    >>> c.value, round(c.margin, 5)
    (6250.0, 1.39065)
    """
    value = factor * demand
    margin = limit / value if value > 0 else math.inf
    return Check(id, name, value, limit, unit, margin, source)
