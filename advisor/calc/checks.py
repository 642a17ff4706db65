"""A check of a design: a value against its limit, with the margin (≥ 1 passes).

A design check, not a requirement's: the rules a requirement file must meet are the
``requirement_checks`` modules of the applications. Its own module so that every application
can use it without importing the linear chain's sizing (the induction motor and screw
equations)."""

from typing import TYPE_CHECKING, NamedTuple

if TYPE_CHECKING:  # the citation type; calc imports nothing of the core at run time
    from advisor.core.cite import Cite


class Check(NamedTuple):
    """One strength or function check of a design, in one convention for every check:

        margin = limit/value   (value ≤ limit: a load, a stress, a speed)
        margin = value/limit   (value ≥ limit: a life, a static safety, a ratio)

    Under a service factor f_B a strength check states the factored demand, value =
    f_B·demand, and its name says "× f_B", so value, limit and margin agree for a reader
    (the linear chain's :func:`advisor.calc.sizing.factored_check`, the rotary stages'
    :func:`advisor.applications.rotary.loads.factored_stage_check`).

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
