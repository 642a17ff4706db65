"""The service factor f_B of a drive: what multiplies the load of every strength check.

Shared by the applications: the linear actuator multiplies the axial force
and the screw torque of its strength checks (core stress, buckling, flank pressure, thrust
bearing) by it; the rotary one the reducer's torque. The thermal checks are not multiplied:
the duty cycle covers them.

The factor is given in ``[design] service_factor`` (≥ 1). SEW-EURODRIVE derives it from a
chart of the daily operating time (8, 16, 24 h/d scales) and the cycles per hour (0 … 1400
/h) with one curve per load classification, the classification following the mass
acceleration factor (external inertia at the motor / motor inertia):

- (I) uniform, mass acceleration factor ≤ 0.2;
- (II) moderate shock load, ≤ 3;
- (III) heavy shock load, ≤ 10; above 10, SEW asks to be consulted.

References
----------
[1] SEW-EURODRIVE, «Handbuch – Getriebe und Getriebemotoren», 5.4 Betriebsfaktor, Bild 8
    (p. 50): the three load classifications by the mass acceleration factor.
[2] SEW-EURODRIVE, project planning for gear units, service factor, example (online
    documentation 31964060, page 8993778187): mass acceleration factor 2.5 (load
    classification II), 14 h/d (read at 16 h/d), 300 cycles/h → f_B = 1.5.

Only the chart's axes and the worked example above could be read as text; the curves of
Bild 8 are a figure whose points could not be verified, so this module does not read the
chart: a value of f_B read from it by the engineer is given as ``service_factor``.
"""

from typing import Literal, NamedTuple

LoadClass = Literal["I", "II", "III"]

#: Upper bound of the mass acceleration factor of each load classification [1].
LOAD_CLASS_LIMITS: tuple[tuple[float, LoadClass], ...] = ((0.2, "I"), (3.0, "II"), (10.0, "III"))

#: SEW's published example [2]: (mass acceleration factor, hours per day read, cycles per
#: hour) → f_B. A reference point for a future reading of the chart's curves.
SEW_EXAMPLE = ((2.5, 16.0, 300.0), 1.5)


def load_classification(mass_acceleration_factor: float) -> LoadClass:
    """SEW's load classification of a drive from its mass acceleration factor.

    I: m_a ≤ 0.2,  II: m_a ≤ 3,  III: m_a ≤ 10,  m_a = J_ext / J_motor

    Parameters
    ----------
    mass_acceleration_factor : float
        External inertia at the motor over the motor's inertia m_a [-], 0 to 10

    Returns
    -------
    load_class : str
        'I' (uniform), 'II' (moderate shock) or 'III' (heavy shock)

    Notes
    -----
    Raises ValueError below 0 and above 10, where SEW's chart stops (consult the gear
    maker).

    Examples
    --------
    The published example's factor 2.5 is class II [2]:

    >>> load_classification(2.5)
    'II'
    >>> load_classification(0.2), load_classification(10.0)
    ('I', 'III')

    References
    ----------
    SEW-EURODRIVE, «Handbuch – Getriebe und Getriebemotoren», 5.4, Bild 8 [1].
    """
    if mass_acceleration_factor < 0:
        raise ValueError("the mass acceleration factor is a ratio of inertias, ≥ 0")
    for limit, cls in LOAD_CLASS_LIMITS:
        if mass_acceleration_factor <= limit:
            return cls
    raise ValueError(
        f"a mass acceleration factor of {mass_acceleration_factor:g} is above 10: SEW's chart "
        "stops there (consult the gear maker)"
    )


class ServiceFactor(NamedTuple):
    """The factor every strength check multiplies its demand by, and where it comes from."""

    value: float
    basis: str


#: No factor: the loads as given.
NO_SERVICE_FACTOR = ServiceFactor(1.0, "no service factor given: the loads as stated")


def service_factor(design: object | None) -> ServiceFactor:
    """The service factor of a requirement's ``[design]`` table.

    f_B as given (no factor: 1)

    Parameters
    ----------
    design : object or None
        The ``[design]`` table, with an optional ``service_factor`` f_B [-], at least 1

    Returns
    -------
    factor : ServiceFactor
        The factor f_B [-] and where it comes from, in words

    Notes
    -----
    The factor multiplies the load of every strength check, not the thermal ones. Raises
    ValueError below 1, which would lower the loads.

    Examples
    --------
    >>> class D: service_factor = 1.5
    >>> service_factor(D())
    ServiceFactor(value=1.5, basis='design.service_factor = 1.5 (given)')
    >>> service_factor(None).value
    1.0

    References
    ----------
    SEW-EURODRIVE, project planning for gear units, service factor [2].
    """
    value = getattr(design, "service_factor", None)
    if value is None:
        return NO_SERVICE_FACTOR
    if value < 1.0:
        raise ValueError("a service factor below 1 would lower the loads")
    return ServiceFactor(float(value), f"design.service_factor = {value:g} (given)")
