"""Sizing of the linear chain's parts: a thread evaluated against every check, and a motor
evaluated on its load. Pure functions of numbers and catalog rows; no decisions here."""

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any, NamedTuple, Protocol

from advisor.calc import induction, screw
from advisor.calc.checks import Check as Check  # re-exported: the linear chain's checks
from advisor.calc.checks import factored
from advisor.core.cite import Cite, cite
from catalogs.threads import ThreadProfile

MM = 1e-3
MPA = 1e6
#: Density of the screw steel, for its whirling speed  [kg/m³].
STEEL_DENSITY_KG_M3 = 7850.0


def _margin(value: float, limit: float, factor: float = 1.0) -> float:
    """The margin of a check of the form factor·value ≤ limit: limit / (factor·value)
    (``factor``: the service factor of a strength check)."""
    return math.inf if value <= 0 else limit / (factor * value)


def _upper(
    id: str,
    name: str,
    value: float,
    limit: float,
    unit: str,
    source: Cite,
    factor: float | None = None,
) -> Check:
    """A check of the form factor·value ≤ limit; margin = limit / (factor·value). ``factor``
    None: no service factor applies (a geometric or thermal check, or none given). Under a
    service factor the check states the factored demand f_B·value and says so in its name,
    so that its value, limit and margin agree for a reader: margin = limit / stated value."""
    if factor is None:
        return Check(id, name, value, limit, unit, _margin(value, limit), source)
    return factored_check(id, name, value, limit, unit, source, factor)


def factored_check(
    id: str, name: str, demand: float, limit: float, unit: str, source: Cite, factor: float
) -> Check:
    """A strength check under the service factor f_B, stated as the factored demand.

        value = f_B·demand,   margin = limit / value

    Parameters
    ----------
    id, name : str
        The check's id and its name in words (" × f_B = …" is appended)
    demand : float
        The demand before the factor [unit]
    limit : float
        The capacity [unit]
    unit : str
        The unit of demand and limit
    source : Cite
        Where the check comes from
    factor : float
        The service factor f_B [-], ≥ 1

    Returns
    -------
    Check
        value f_B·demand, margin limit/(f_B·demand) (∞ for no demand); ``factor`` None:
        the factor is already in the value

    References
    ----------
    SEW-EURODRIVE, service factor f_B (``[design] service_factor``).
    """
    return factored(id, f"{name} × f_B = {factor:g}", demand, limit, unit, factor, source)


def _lower(id: str, name: str, value: float, limit: float, unit: str, source: Cite) -> Check:
    """A check of the form value ≥ limit; margin = value / limit."""
    return Check(id, name, value, limit, unit, value / limit, source)


#: Relative tolerance under which a geometric turn count counts as whole (1.2·15/2 is
#: 9.000000000000002 in floating point, and is 9 turns, not 10).
WHOLE_TURN_TOLERANCE = 1e-9


def nut_whole_turns(turns_for_pressure: float, turns_for_height: float) -> int:
    """Engaged turns of the nut, whole.

    z = max(⌈z_p⌉, ⌈ψ_min·d2/P⌉, 1)

    Parameters
    ----------
    turns_for_pressure : float
        Turns the flank pressure needs, z_p = F/(π·d2·H1·[p]) [-]
    turns_for_height : float
        Turns the minimum height ratio needs, ψ_min·d2/P [-]

    Returns
    -------
    turns : int
        Engaged turns of the nut z [-]

    Notes
    -----
    A nut is made with whole turns; rounding up keeps the flank pressure strictly below
    [p] except where z is a whole number exactly, so that a design does not depend on the
    last bit of the force. A height count within :data:`WHOLE_TURN_TOLERANCE` of a whole
    number counts as whole.

    Examples
    --------
    Seed 001's Tr16x2 bronze nut at 3500 N: z = 3500/(π·15·1·10) = 7.43 → 8 for the
    pressure, 1.2·15/2 = 9 for the height: 9 turns.

    >>> nut_whole_turns(7.427, 1.2 * 0.015 / 0.002)
    9
    >>> nut_whole_turns(9.0001, 9.0)
    10

    References
    ----------
    Ivanov, «Детали машин», power screws: z = F/(π·d2·H1·[p]).
    """
    by_height = math.ceil(turns_for_height * (1.0 - WHOLE_TURN_TOLERANCE))
    return max(math.ceil(turns_for_pressure), by_height, 1)


def nut_turns_for_stop(
    turns_rated: int, turns_for_stop_pressure: float, max_turns: int, turns_for_height_max: float
) -> int:
    """Engaged turns of a nut that must also carry an emergency stop's force, whole.

    z = max(z_F, min(⌈z_p,m⌉, z_max, ⌊ψ_max·d2/P⌋))

    Parameters
    ----------
    turns_rated : int
        Turns sized at the rated force, z_F (:func:`nut_whole_turns`) [-]
    turns_for_stop_pressure : float
        Turns the flank pressure needs at the momentary force,
        z_p,m = f_B·max(F, F_stop)/(π·d2·H1·[p]) [-]
    max_turns : int
        Most engaged turns allowed, z_max [-]
    turns_for_height_max : float
        Turns of the highest nut allowed, ψ_max·d2/P [-]

    Returns
    -------
    turns : int
        Engaged turns of the nut z [-]

    Notes
    -----
    The nut is lengthened for the stop only as far as the longest nut allowed (z_max and the
    height ratio ψ_max): where even that nut is overloaded in the stop, its flank-pressure
    check at the stop's force fails and says so, and the rated nut's own checks are left as
    they were. A height count within :data:`WHOLE_TURN_TOLERANCE` of a whole number counts
    as whole.

    Examples
    --------
    Tr24x5 bronze nut, f_B = 1.2, F = 2500 N, F_stop = 9000 N: 6 turns at the rated force
    (the height ratio 1.2·21.5/5 = 5.16 → 6); at the stop z_p = 10800/(π·21.5·2.5·10) = 6.40
    → 7, within z_max = 10 and 2.5·21.5/5 = 10.75:

    >>> nut_turns_for_stop(6, 6.396, 10, 2.5 * 21.5 / 5)
    7
    >>> nut_turns_for_stop(6, 12.4, 10, 10.75)
    10

    References
    ----------
    Ivanov, «Детали машин», power screws: z = F/(π·d2·H1·[p]), H/d2 ≤ ψ_max, z ≤ z_max.
    """
    by_height = math.floor(turns_for_height_max * (1.0 + WHOLE_TURN_TOLERANCE))
    longest = min(max_turns, by_height)
    return max(turns_rated, min(math.ceil(turns_for_stop_pressure), longest))


class ThrustFace(NamedTuple):
    """The face that takes the screw's axial force: a plain collar (Shigley,
    eq. (8-6)) or a rolling bearing of the SKF catalog (its friction moment by the SKF model
    of :func:`advisor.calc.bearing_life.skf_friction`, the axial force its only load)."""

    kind: str  # "collar" or "bearing"
    friction_coefficient: float = 0.0  # collar
    mean_diameter_m: float = 0.0  # collar
    bearing: Any = None  # catalogs.rows.Bearing
    constants: Any = None  # catalogs.rows.FrictionConstants
    viscosity_mm2_s: float = 0.0

    def torque_Nm(self, force_N: float, speed_rpm: float) -> float:
        """The friction torque of the face under an axial force at a screw speed.

        collar: T = |F|·f_c·d_c/2;  bearing: the SKF model's total moment, F axial

        Parameters
        ----------
        force_N : float
            Axial force on the face F [N]; its sign is ignored
        speed_rpm : float
            Screw speed n [rpm] (the bearing's speed-dependent terms)

        Returns
        -------
        torque_Nm : float
            Friction torque of the face T [N·m], resisting the motion whichever way F acts

        References
        ----------
        Shigley, «Mechanical Engineering Design», eq. (8-6); SKF General Catalogue, friction.
        """
        force = abs(force_N)
        if self.kind == "collar":
            return screw.collar_torque(force, self.friction_coefficient, self.mean_diameter_m)
        from advisor.calc.bearing_life import skf_friction

        return skf_friction(
            self.bearing, self.constants, 0.0, force, speed_rpm, self.viscosity_mm2_s
        ).total_Nm

    def describe(self) -> str:
        if self.kind == "collar":
            return (
                f"collar, d_c = {self.mean_diameter_m * 1e3:g} mm, f_c = "
                f"{self.friction_coefficient:g}: T = F·f_c·d_c/2 (Shigley, eq. (8-6))"
            )
        return (
            f"rolling bearing {self.bearing.designation}, SKF friction model, lubricant "
            f"{self.viscosity_mm2_s:g} mm²/s"
        )


class ScrewMaterial(NamedTuple):
    friction_coefficient: float
    friction_low: float
    allowable_pressure_Pa: float
    yield_strength_Pa: float
    elastic_modulus_Pa: float
    yield_safety_factor: float
    nut_height_ratio_min: float
    nut_height_ratio_max: float
    nut_max_turns: int


class ThreadEvaluation(NamedTuple):
    thread: ThreadProfile
    starts: int
    friction_model: str
    lead_angle_rad: float
    friction_angle_rad: float
    torque_Nm: float
    torque_standard_Nm: float
    torque_paper_Nm: float
    efficiency: float
    back_driving_efficiency: float
    self_locking: bool
    self_locking_at_low_friction: bool
    revolutions: float
    speed_rpm: float
    nut_height_mm: float
    nut_turns: float
    nut_pressure_Pa: float
    critical_load_N: float
    slenderness: float
    buckling_formula: str
    core_stress_Pa: float
    checks: tuple[Check, ...] = ()
    #: the friction torque of the thrust face at the rated force and the screw speed, and the
    #: face itself (None: not given, its friction left out)
    thrust_torque_Nm: float = 0.0
    thrust: ThrustFace | None = None
    #: the service factor the strength checks multiplied their demand by
    service_factor: float = 1.0
    #: the fastest the screw may turn: a share of its whirling speed
    max_speed_rpm: float = math.inf
    #: the turns the rated force alone gives the nut; fewer than ``nut_turns`` where the
    #: emergency stop's force lengthens it (0: not stated)
    nut_turns_rated: float = 0.0

    @property
    def drive_torque_Nm(self) -> float:
        """The torque that moves the load: the thread's and the thrust face's."""
        return self.torque_Nm + self.thrust_torque_Nm

    @property
    def passed(self) -> bool:
        return all(c.margin >= 1.0 for c in self.checks)  # Check.passed, without its call

    @property
    def failed(self) -> list[Check]:
        return [c for c in self.checks if not c.passed]


class _CheckSources(NamedTuple):
    core_name: str
    core: Cite
    buckling_name: str
    buckling: Cite
    ivanov: Cite


@lru_cache(maxsize=64)
def _check_sources(
    yield_safety_factor: float, formula: str, end_fixity: str, buckling_safety_factor: float
) -> _CheckSources:
    """The names and sources of a thread's checks: the same for every thread of one design
    (the joint choice evaluates about a hundred)."""
    ivanov = cite("ivanov-dm", "power screws")
    return _CheckSources(
        "screw core stress (axial force + torque, von Mises)",
        ivanov.with_note(f"[σ] = σ_y/{yield_safety_factor:g}"),
        f"buckling between supports ({formula}, {end_fixity})",
        cite("shigley", f"ch. 4, {formula} column formula").with_note(
            f"safety factor {buckling_safety_factor:g}"
        ),
        ivanov,
    )


class ThreadGeometry(NamedTuple):
    """A thread's name and the dimensions the checks use, in metres: the same conversions
    as :func:`_thread_numbers` makes, done once per catalog."""

    thread: ThreadProfile
    name: str
    pitch_m: float
    d2_m: float
    d3_m: float
    h1_m: float


def thread_geometry(thread: ThreadProfile) -> ThreadGeometry:
    """A thread's dimensions in metres, converted once per catalog.

    p = P·10⁻³, d2 = d2·10⁻³, d3 = d3·10⁻³, H1 = H1·10⁻³

    Parameters
    ----------
    thread : ThreadProfile
        Trapezoidal thread of GOST 24737-81, dimensions in [mm]

    Returns
    -------
    geometry : ThreadGeometry
        The thread, its name, pitch, pitch and minor diameters and working depth [m]

    Examples
    --------
    >>> from catalogs import load_catalogs
    >>> g = thread_geometry(load_catalogs().thread("Tr16x2"))
    >>> round(g.d2_m, 6), round(g.d3_m, 6)
    (0.015, 0.0135)

    References
    ----------
    GOST 24737-81 / ISO 2904, basic dimensions.
    """
    return ThreadGeometry(
        thread,
        thread.name,
        thread.pitch_mm * MM,
        thread.d2_mm * MM,
        thread.d3_mm * MM,
        thread.H1_mm * MM,
    )


class ThreadScreen(NamedTuple):
    """What the joint choice of thread and motor reads of one thread: whether it passes
    every check, its torque and its speed. The choice screens every thread of the catalog
    with every number of starts (about a hundred per advice); the full
    :class:`ThreadEvaluation`, with its checks and their cited sources, is built only for
    the threads the advice reports. The numbers are those of :func:`evaluate_thread`, to
    the last bit (``tests/unit/test_linear_screen.py`` holds them to it); where ``passed`` is
    false they are nan: nothing reads them."""

    thread: ThreadProfile
    name: str
    starts: int
    passed: bool
    torque_Nm: float
    revolutions: float
    speed_rpm: float
    self_locking_at_low_friction: bool
    #: the driving efficiency of a holding device between the motor and this screw (seed
    #: 004): the motor gives the screw torque divided by it
    device_efficiency: float = 1.0
    #: the friction torque of the thrust face; 0 where none is given
    thrust_torque_Nm: float = 0.0
    #: the fastest the screw may turn: a share of its whirling speed
    max_speed_rpm: float = math.inf

    @property
    def motor_torque_Nm(self) -> float:
        """The motor's torque: the thread's and the thrust face's, through the device."""
        return (self.torque_Nm + self.thrust_torque_Nm) / self.device_efficiency


@dataclass(frozen=True, slots=True)
class ScrewDemand:
    """What one requirement asks of every thread: the load, the stroke and its time, the
    supports, the friction and the factors. The joint choice screens every thread under it
    (:meth:`screen`) and evaluates the few it reports (:meth:`evaluate`); both compute with
    the same functions, so that they see the same floats."""

    force_N: float
    stroke_m: float
    travel_time_s: float
    span_m: float
    end_fixity: str
    buckling_safety_factor: float
    friction_model: screw.FrictionModel
    material: ScrewMaterial
    thrust: ThrustFace | None = None
    service_factor: float = 1.0
    #: the emergency stop's momentary axial force; 0: none given (no stop checks)
    stop_force_N: float = 0.0

    @property
    def momentary_force_N(self) -> float:
        """The force the stop checks take: the stop's, or the rated one where it is larger."""
        return max(self.force_N, self.stop_force_N)

    def evaluate(self, thread: ThreadProfile, starts: int) -> ThreadEvaluation:
        """:func:`evaluate_thread` of one thread with ``starts`` starts under this demand."""
        n = _thread_numbers(thread, starts, self)
        checks = _thread_checks(n, self, thread.d2_mm * MM)
        return _evaluation(thread, starts, self, n, checks)

    def screen(
        self, geometries: list[ThreadGeometry], starts_options: tuple[int, ...]
    ) -> list[ThreadScreen]:
        """:func:`screen_threads` of every thread under this demand."""
        out = []
        shared = _screen_constants(self)
        for g in geometries:
            if not _holds_the_load(g, self, shared):
                nan = math.nan
                out.extend(
                    ThreadScreen(g.thread, g.name, z, False, nan, nan, nan, False)
                    for z in starts_options
                )
                continue
            out += _screen_leads(g, starts_options, self, shared)
        return out


class _ThreadNumbers(NamedTuple):
    """The numbers of one thread under one requirement, from which
    :meth:`ScrewDemand.evaluate` builds its evaluation and its checks."""

    psi: float
    phi: float
    phi_low: float
    phi_std: float
    torque: float
    revs: float
    speed: float
    turns: float
    height: float
    pressure: float
    core: float
    p_cr: float
    slenderness: float
    formula: str
    thrust_torque: float = 0.0
    max_speed: float = math.inf
    #: the core stress and the flank pressure at the emergency stop's force (0: no stop given)
    stop_core: float = 0.0
    stop_pressure: float = 0.0
    turns_rated: float = 0.0


class _NutSize(NamedTuple):
    """The nut of one thread: its turns, its flank pressure at the rated force, and the turns
    the rated force alone gives it."""

    turns: float
    pressure: float
    turns_rated: float


def _nut(d: ScrewDemand, d2: float, p: float, h1: float) -> _NutSize:
    """The nut's whole engaged turns, enough for the flank pressure under the service factor
    at the larger of the rated and the emergency stop's force (up to the longest nut
    allowed) and for the minimum height ratio, and its flank pressure under the rated force."""
    m, sf = d.material, d.service_factor
    turns = nut_whole_turns(
        screw.nut_turns_required(sf * d.force_N, d2, h1, m.allowable_pressure_Pa),
        m.nut_height_ratio_min * d2 / p,
    )
    turns_rated = turns
    if d.stop_force_N > d.force_N:
        z_stop = screw.nut_turns_required(sf * d.stop_force_N, d2, h1, m.allowable_pressure_Pa)
        turns = nut_turns_for_stop(turns, z_stop, m.nut_max_turns, m.nut_height_ratio_max * d2 / p)
    return _NutSize(
        float(turns), screw.nut_bearing_pressure(d.force_N, d2, h1, turns), float(turns_rated)
    )


def _max_speed_rpm(d3: float, span_m: float, end_fixity: str, material: ScrewMaterial) -> float:
    """The fastest the screw may turn: the allowed share of its whirling speed  [rpm]."""
    return screw.WHIRL_ALLOWED_SHARE * screw.critical_speed_rpm(
        d3, span_m, end_fixity, material.elastic_modulus_Pa, STEEL_DENSITY_KG_M3
    )


def _thread_numbers(thread: ThreadProfile, starts: int, d: ScrewDemand) -> _ThreadNumbers:
    """Torque, speed, nut, core stress and buckling of one thread (see
    :func:`evaluate_thread`)."""
    p = thread.pitch_mm * MM
    d2 = thread.d2_mm * MM
    d3 = thread.d3_mm * MM
    force_N, material, model = d.force_N, d.material, d.friction_model
    f = material.friction_coefficient
    psi = screw.lead_angle(p, d2, starts)
    phi = screw.friction_angle(f, model, psi)
    # the torque of both friction models (the report shows the other beside the chosen),
    # with the lead and friction angles computed once: eq. (1), as screw.thread_torque
    phi_std = phi if model == "standard" else screw.friction_angle(f, "standard", psi)
    torque = screw.torque_from_angles(force_N, d2, psi, phi)
    revs = screw.revolutions(d.stroke_m, p, starts)
    speed = screw.screw_speed_rpm(revs, d.travel_time_s)
    nut = _nut(d, d2, p, thread.H1_mm * MM)
    p_cr, slenderness, formula = screw.critical_buckling_load(
        d3, d.span_m, d.end_fixity, material.elastic_modulus_Pa, material.yield_strength_Pa
    )
    return _ThreadNumbers(
        psi=psi,
        phi=phi,
        phi_low=screw.friction_angle(material.friction_low, "standard", psi),
        phi_std=phi_std,
        torque=torque,
        revs=revs,
        speed=speed,
        turns=nut.turns,
        height=nut.turns * p,
        pressure=nut.pressure,
        core=screw.core_equivalent_stress(force_N, torque, d3),
        p_cr=p_cr,
        slenderness=slenderness,
        formula=formula,
        thrust_torque=d.thrust.torque_Nm(force_N, speed) if d.thrust is not None else 0.0,
        max_speed=_max_speed_rpm(d3, d.span_m, d.end_fixity, material),
        stop_core=_stop_core_stress(d, d2, d3, psi, phi) if d.stop_force_N > 0 else 0.0,
        stop_pressure=screw.nut_bearing_pressure(
            d.momentary_force_N, d2, thread.H1_mm * MM, nut.turns
        )
        if d.stop_force_N > 0
        else 0.0,
        turns_rated=nut.turns_rated,
    )


def _stop_core_stress(d: ScrewDemand, d2: float, d3: float, psi: float, phi: float) -> float:
    """The core's equivalent stress at the emergency stop's force, with the thread torque
    that force asks (the motor driving into the stop): σ_eq(F_m, M(F_m))  [Pa]."""
    force = d.momentary_force_N
    return screw.core_equivalent_stress(force, screw.torque_from_angles(force, d2, psi, phi), d3)


def _thread_checks(n: _ThreadNumbers, d: ScrewDemand, d2: float) -> tuple[Check, ...]:
    """The five checks of a thread (see :func:`evaluate_thread`), the first three strength
    checks under the service factor."""
    m = d.material
    src = _check_sources(m.yield_safety_factor, n.formula, d.end_fixity, d.buckling_safety_factor)
    sf = d.service_factor if d.service_factor != 1.0 else None
    allowed_stress = m.yield_strength_Pa / m.yield_safety_factor
    return (
        _upper(
            "core_stress", src.core_name, n.core / MPA, allowed_stress / MPA, "MPa", src.core, sf
        ),
        _upper(
            "buckling",
            src.buckling_name,
            d.force_N,
            n.p_cr / d.buckling_safety_factor,
            "N",
            src.buckling,
            sf,
        ),
        _upper(
            "nut_pressure",
            "nut flank bearing pressure",
            n.pressure / MPA,
            m.allowable_pressure_Pa / MPA,
            "MPa",
            src.ivanov,
            sf,
        ),
        _upper(
            "nut_height",
            "nut height ratio H/d2",
            n.height / d2,
            m.nut_height_ratio_max,
            "",
            src.ivanov,
        ),
        _upper("nut_turns", "engaged nut turns", n.turns, float(m.nut_max_turns), "", src.ivanov),
        *(_stop_checks(n, d, src) if d.stop_force_N > 0 else ()),
    )


def stop_force_words(force_N: float, stop_force_N: float) -> str:
    """The force the emergency-stop checks take, in words.

    F_m = max(F, F_stop): a stop below the rated force cannot load the screw less than its
    work does

    Parameters
    ----------
    force_N : float
        Rated axial force F [N]
    stop_force_N : float
        The emergency stop's momentary axial force F_stop [N]

    Returns
    -------
    words : str
        "the emergency stop's F_stop N", or the rated force with the smaller stop's beside it

    Examples
    --------
    >>> stop_force_words(5000.0, 30000.0)
    "the emergency stop's 30000 N"
    >>> stop_force_words(5000.0, 3000.0)
    "the rated 5000 N (above the emergency stop's 3000 N)"

    References
    ----------
    The key ``linear.emergency_stop_force_N`` (docs/reference/keys.md).
    """
    if stop_force_N >= force_N:
        return f"the emergency stop's {stop_force_N:g} N"
    return f"the rated {force_N:g} N (above the emergency stop's {stop_force_N:g} N)"


def _stop_checks(n: _ThreadNumbers, d: ScrewDemand, src: _CheckSources) -> tuple[Check, ...]:
    """The strength checks at the emergency stop's momentary force F_m = max(F, F_stop), under
    the service factor: the same static formulas and limits as at the rated force (buckling
    keeps its safety factor S_b: an instability is not relieved by a short load; the nut its
    allowable flank pressure, the sources giving no momentary one)."""
    m, sf = d.material, (d.service_factor if d.service_factor != 1.0 else None)
    at = f"at {stop_force_words(d.force_N, d.stop_force_N)}"
    momentary = "momentary force checked statically"
    return (
        _upper(
            "core_stress_emergency_stop",
            f"{src.core_name} {at}",
            n.stop_core / MPA,
            m.yield_strength_Pa / m.yield_safety_factor / MPA,
            "MPa",
            src.core.with_note(f"[σ] = σ_y/{m.yield_safety_factor:g}; {momentary}"),
            sf,
        ),
        _upper(
            "buckling_emergency_stop",
            f"{src.buckling_name} {at}",
            d.momentary_force_N,
            n.p_cr / d.buckling_safety_factor,
            "N",
            src.buckling.with_note(f"safety factor {d.buckling_safety_factor:g}; {momentary}"),
            sf,
        ),
        _upper(
            "nut_pressure_emergency_stop",
            f"nut flank bearing pressure {at}",
            n.stop_pressure / MPA,
            m.allowable_pressure_Pa / MPA,
            "MPa",
            src.ivanov.with_note(f"{_stop_nut_words(m)}; {momentary}"),
            sf,
        ),
    )


def _stop_nut_words(m: ScrewMaterial) -> str:
    """How the nut that the stop's flank-pressure check takes was sized, in words."""
    return (
        "the nut's turns sized for this force, up to the longest nut allowed "
        f"(z ≤ {m.nut_max_turns}, H/d2 ≤ {m.nut_height_ratio_max:g})"
    )


def _evaluation(
    thread: ThreadProfile,
    starts: int,
    d: ScrewDemand,
    n: _ThreadNumbers,
    checks: tuple[Check, ...],
) -> ThreadEvaluation:
    """The evaluation of a thread from its numbers and its checks."""
    psi, phi, torque, d2 = n.psi, n.phi, n.torque, thread.d2_mm * MM
    f, model = d.material.friction_coefficient, d.friction_model
    return ThreadEvaluation(
        thread=thread,
        starts=starts,
        friction_model=model,
        lead_angle_rad=psi,
        friction_angle_rad=phi,
        torque_Nm=torque,
        torque_standard_Nm=torque
        if model == "standard"
        else screw.torque_from_angles(d.force_N, d2, psi, n.phi_std),
        torque_paper_Nm=torque
        if model == "paper"
        else screw.torque_from_angles(d.force_N, d2, psi, screw.friction_angle(f, "paper", psi)),
        efficiency=screw.efficiency(psi, phi),
        back_driving_efficiency=screw.back_driving_efficiency(psi, phi),
        # holding is physics: judged with the standard reduced friction even when the torque
        # follows the paper's f/cos(ψ/2), so it agrees with the low-friction judgement below
        self_locking=screw.is_self_locking(psi, n.phi_std),
        self_locking_at_low_friction=screw.is_self_locking(psi, n.phi_low),
        revolutions=n.revs,
        speed_rpm=n.speed,
        nut_height_mm=n.height / MM,
        nut_turns=n.turns,
        nut_pressure_Pa=n.pressure,
        critical_load_N=n.p_cr,
        slenderness=n.slenderness,
        buckling_formula=n.formula,
        core_stress_Pa=n.core,
        checks=checks,
        thrust_torque_Nm=n.thrust_torque,
        thrust=d.thrust,
        service_factor=d.service_factor,
        max_speed_rpm=n.max_speed,
        nut_turns_rated=n.turns_rated,
    )


class _ScreenConstants(NamedTuple):
    """What the screen of every thread under one demand shares, computed once per screen:
    the allowed core stress, the reduced friction angles that do not depend on the lead
    (the standard model's, and the low end of the friction range's, which is always the
    standard one), and the flank pressure allowed."""

    stress_limit_MPa: float
    pressure_limit_MPa: float
    #: the friction angle of the demand's model where it does not depend on the lead angle
    #: (the standard model); None for the paper's f/cos(ψ/2)
    phi_fixed: float | None
    phi_low: float
    #: the thrust face's torque where it does not depend on the speed (none: 0, a collar);
    #: None for a rolling bearing
    thrust_Nm: float | None


def _screen_constants(d: ScrewDemand) -> _ScreenConstants:
    """The constants of :func:`_holds_the_load` and :func:`_screen_leads` under a demand:
    the same expressions as they had inside, so the same floats."""
    m, model = d.material, d.friction_model
    return _ScreenConstants(
        m.yield_strength_Pa / m.yield_safety_factor / MPA,
        m.allowable_pressure_Pa / MPA,
        screw.friction_angle(m.friction_coefficient, model, 0.0) if model == "standard" else None,
        screw.friction_angle(m.friction_low, "standard", 0.0),
        0.0
        if d.thrust is None
        else d.thrust.torque_Nm(d.force_N, 0.0)
        if d.thrust.kind == "collar"
        else None,
    )


def _holds_the_load(g: ThreadGeometry, d: ScrewDemand, k: _ScreenConstants) -> bool:
    """Whether a thread passes the four checks that do not depend on its number of starts:
    buckling, flank pressure, nut height and nut turns (the margins of
    :func:`evaluate_thread`). Buckling first: it needs no nut."""
    m, sf = d.material, d.service_factor
    p_cr_allowed = (
        screw.critical_buckling_load(
            g.d3_m, d.span_m, d.end_fixity, m.elastic_modulus_Pa, m.yield_strength_Pa
        )[0]
        / d.buckling_safety_factor
    )
    if _margin(d.force_N, p_cr_allowed, sf) < 1.0:
        return False
    p, d2 = g.pitch_m, g.d2_m
    turns, pressure, _ = _nut(d, d2, p, g.h1_m)
    holds = (
        _margin(pressure / MPA, k.pressure_limit_MPa, sf) >= 1.0
        and _margin(turns * p / d2, m.nut_height_ratio_max) >= 1.0
        and _margin(turns, float(m.nut_max_turns)) >= 1.0
    )
    if not holds or d.stop_force_N <= 0:
        return holds
    # the emergency stop's momentary force, as :func:`_stop_checks` checks it
    stop_pressure = screw.nut_bearing_pressure(d.momentary_force_N, d2, g.h1_m, turns)
    return (
        _margin(d.momentary_force_N, p_cr_allowed, sf) >= 1.0
        and _margin(stop_pressure / MPA, k.pressure_limit_MPa, sf) >= 1.0
    )


def _screen_leads(
    g: ThreadGeometry, starts_options: tuple[int, ...], d: ScrewDemand, k: _ScreenConstants
) -> list[ThreadScreen]:
    """The screens of a thread that holds the load, one per number of starts: its core
    stress under the torque of that lead decides; a lead that fails it is not driven, and
    its speed is not computed."""
    force_N, sf, p, d2, d3 = d.force_N, d.service_factor, g.pitch_m, g.d2_m, g.d3_m
    max_speed = _max_speed_rpm(d3, d.span_m, d.end_fixity, d.material)
    out = []
    for starts in starts_options:
        psi = screw.lead_angle(p, d2, starts)
        phi = k.phi_fixed
        if phi is None:
            phi = screw.friction_angle(d.material.friction_coefficient, d.friction_model, psi)
        torque = screw.torque_from_angles(force_N, d2, psi, phi)
        core = screw.core_equivalent_stress(force_N, torque, d3)
        passed = _margin(core / MPA, k.stress_limit_MPa, sf) >= 1.0
        if passed and d.stop_force_N > 0:  # the core at the stop's force, as _stop_checks
            stop_core = _stop_core_stress(d, d2, d3, psi, phi)
            passed = _margin(stop_core / MPA, k.stress_limit_MPa, sf) >= 1.0
        if not passed:
            nan = math.nan
            out.append(
                ThreadScreen(
                    g.thread, g.name, starts, False, nan, nan, nan, False, 1.0, 0.0, max_speed
                )
            )
            continue
        revs = screw.revolutions(d.stroke_m, p, starts)
        speed = screw.screw_speed_rpm(revs, d.travel_time_s)
        thrust = k.thrust_Nm if k.thrust_Nm is not None else d.thrust.torque_Nm(force_N, speed)
        locking = screw.is_self_locking(psi, k.phi_low)
        # positional, in the order of its fields (faster)
        out.append(
            ThreadScreen(
                g.thread, g.name, starts, True, torque, revs, speed, locking, 1.0, thrust, max_speed
            )
        )
    return out


def evaluate_thread(
    thread: ThreadProfile,
    *,
    force_N: float,
    stroke_m: float,
    travel_time_s: float,
    span_m: float,
    end_fixity: str,
    buckling_safety_factor: float,
    starts: int,
    friction_model: screw.FrictionModel,
    material: ScrewMaterial,
    thrust: ThrustFace | None = None,
    service_factor: float = 1.0,
    stop_force_N: float = 0.0,
) -> ThreadEvaluation:
    """Torque, efficiency, self-locking and the five checks of one thread.

    M = F·d2/2·tan(ψ + φ');  f_B·σ_eq ≤ σ_y/S,  f_B·F ≤ P_cr/S_b,  f_B·p ≤ [p],
    H/d2 ≤ ψ_max,  z ≤ z_max  (each margin = allowed / actual). The nut has
    :func:`nut_whole_turns` turns for f_B·F, lengthened by :func:`nut_turns_for_stop` for
    f_B·F_stop where the stop's force is the larger, H = z·P; the core between the nut and the
    thrust face carries the thread torque alone. Seed 001, eq. (1); Ivanov, «Детали
    машин», power screws.

    Parameters
    ----------
    thread : ThreadProfile
        Trapezoidal thread of GOST 24737-81, dimensions in [mm]
    force_N, stroke_m, travel_time_s : float
        Rated axial force [N], stroke [m] and its travel time [s]
    span_m, end_fixity : float, str
        Length between the supports [m] and their fixity (a column's end conditions)
    buckling_safety_factor, service_factor, stop_force_N : float
        Safety factor S_b on buckling [-]; service factor f_B on the strength checks [-];
        emergency stop's force F_stop [N] (0: none), the first three checked again at it
    starts : int
        Number of thread starts [-]
    friction_model : str
        'standard' or 'paper' (:func:`advisor.calc.screw.friction_angle`)
    material : ScrewMaterial
        Friction, allowable pressure [Pa], steel [Pa] and nut proportions of the pair
    thrust : ThrustFace or None
        The face that takes the axial force; its friction adds to the thread's torque

    Returns
    -------
    evaluation : ThreadEvaluation
        Angles [rad], torques [N·m], efficiencies [-], speed [rpm], nut, checks
    """
    column = (force_N, stroke_m, travel_time_s, span_m, end_fixity, buckling_safety_factor)
    demand = ScrewDemand(*column, friction_model, material, thrust, service_factor, stop_force_N)
    return demand.evaluate(thread, starts)


def screen_threads(
    geometries: list[ThreadGeometry],
    starts_options: tuple[int, ...],
    *,
    force_N: float,
    stroke_m: float,
    travel_time_s: float,
    span_m: float,
    end_fixity: str,
    buckling_safety_factor: float,
    friction_model: screw.FrictionModel,
    material: ScrewMaterial,
    thrust: ThrustFace | None = None,
    service_factor: float = 1.0,
    stop_force_N: float = 0.0,
) -> list[ThreadScreen]:
    """Pass or fail of every thread with every number of starts, its torque and speed.

    passed ⇔ every margin of :func:`evaluate_thread` ≥ 1

    Parameters
    ----------
    geometries : list[ThreadGeometry]
        The catalog's threads, dimensions in [m] (:func:`thread_geometry`)
    starts_options : tuple[int, ...]
        Numbers of thread starts to screen [-]
    force_N, stroke_m, travel_time_s, span_m, end_fixity, buckling_safety_factor
        As for :func:`evaluate_thread` [N], [m], [s], [m], -, [-]
    friction_model, material, thrust, service_factor, stop_force_N
        As for :func:`evaluate_thread`

    Returns
    -------
    screens : list[ThreadScreen]
        Thread by thread, starts within; torque [N·m], revolutions, speed [rpm]

    Notes
    -----
    Exact: the same functions on the same arguments as :func:`evaluate_thread`, each margin
    the same quotient. Buckling, flank pressure, nut height and turns do not depend on the
    starts: a thread that fails one fails with every number of starts, and its torque is
    not computed. Seed 001, eq. (1); Ivanov, «Детали машин», power screws.
    """
    column = (force_N, stroke_m, travel_time_s, span_m, end_fixity, buckling_safety_factor)
    demand = ScrewDemand(*column, friction_model, material, thrust, service_factor, stop_force_N)
    return demand.screen(geometries, starts_options)


class MotorRow(Protocol):
    model: str
    rated_power_kW: float
    rated_speed_rpm: float
    breakdown_torque_ratio: float
    starting_torque_ratio: float

    @property
    def synchronous_speed_rpm(self) -> float: ...

    @property
    def rated_slip(self) -> float: ...

    @property
    def rated_torque_Nm(self) -> float: ...


class MotorEvaluation(NamedTuple):
    motor: MotorRow
    curve: induction.KlossCurve
    rated_torque_Nm: float
    max_torque_Nm: float
    starting_torque_Nm: float
    working_slip: float | None
    working_speed_rpm: float | None
    torque_at_required_speed_Nm: float
    rated_torque_margin: float
    starting_torque_margin: float
    breakdown_torque_margin: float
    travel_time_s: float | None
    required_speed_rpm: float
    slips: list[float]
    torques_Nm: list[float]

    @property
    def problems(self) -> list[str]:
        """Why this motor cannot drive the load continuously at the required speed."""
        out = []
        if self.rated_torque_margin < 1:
            out.append(
                f"rated torque {self.rated_torque_Nm:.3f} N·m is below the load "
                f"{self.rated_torque_Nm / self.rated_torque_margin:.3f} N·m"
            )
        if self.starting_torque_margin < 1:
            out.append(f"starting torque {self.starting_torque_Nm:.3f} N·m cannot start the load")
        if self.working_slip is None:
            out.append("the load exceeds the maximum torque: the motor stalls")
        elif (
            self.working_speed_rpm is not None and self.working_speed_rpm < self.required_speed_rpm
        ):
            out.append(
                f"runs at {self.working_speed_rpm:.0f} rpm under the load, below the required "
                f"{self.required_speed_rpm:.0f} rpm"
            )
        return out

    @property
    def suitable(self) -> bool:
        return not self.problems


def evaluate_motor(
    motor: MotorRow, load_torque_Nm: float, required_speed_rpm: float, revolutions: float
) -> MotorEvaluation:
    """A catalog motor's refined Kloss curve, its working point under the load and its margins.

    M(s_w) = M_load (stable branch),  n_w = n₀·(1 − s_w),  t = 60·N / n_w; margins
    M_n/M_load, M(1)/M_load, M_k/M_load; M(s_req), s_req = 1 − n_req/n₀, as in fig. 4

    Parameters
    ----------
    motor : MotorRow
        Catalog row: rated power, speed and torque, breakdown and starting ratios
    load_torque_Nm : float
        Load torque at the motor [N·m]
    required_speed_rpm : float
        Screw speed that makes the stroke in the travel time [rpm]
    revolutions : float
        Revolutions of the screw over the stroke N [-]

    Returns
    -------
    evaluation : MotorEvaluation
        Curve, torques [N·m], working slip [-], speed [rpm], margins [-], travel time [s]

    Examples
    --------
    >>> from catalogs import load_catalogs
    >>> m = next(m for m in load_catalogs().motors if m.model == "4A71B4")
    >>> round(evaluate_motor(m, 5.085, 1200.0, 100.0).working_speed_rpm)
    1392

    References
    ----------
    Seed 001, the motor's M(s) against the screw torque (fig. 4); refined Kloss formula.
    """
    mn = motor.rated_torque_Nm
    curve = _fit(mn, motor.rated_slip, motor.breakdown_torque_ratio, motor.starting_torque_ratio)
    n0 = motor.synchronous_speed_rpm
    s_work = curve.stable_slip(load_torque_Nm)
    n_work = None if s_work is None else n0 * (1.0 - s_work)
    s_req = 1.0 - required_speed_rpm / n0
    at_req = curve.torque(s_req) if 0.0 < s_req <= 1.0 else 0.0
    slips = induction.curve_slips()
    return MotorEvaluation(
        motor=motor,
        curve=curve,
        rated_torque_Nm=mn,
        max_torque_Nm=curve.max_torque_Nm,
        starting_torque_Nm=curve.torque(1.0),
        working_slip=s_work,
        working_speed_rpm=n_work,
        torque_at_required_speed_Nm=at_req,
        rated_torque_margin=mn / load_torque_Nm,
        starting_torque_margin=curve.torque(1.0) / load_torque_Nm,
        breakdown_torque_margin=curve.max_torque_Nm / load_torque_Nm,
        travel_time_s=None if not n_work else 60.0 * revolutions / n_work,
        required_speed_rpm=required_speed_rpm,
        slips=slips,
        torques_Nm=[curve.torque(x) for x in slips],
    )


class MotorFit(NamedTuple):
    """A catalog motor with its fitted characteristic, for screening many loads quickly."""

    motor: MotorRow
    curve: induction.KlossCurve
    rated_torque_Nm: float
    starting_torque_Nm: float
    synchronous_speed_rpm: float


def fit_motor(motor: MotorRow) -> MotorFit:
    """The refined Kloss curve of a catalog motor, for screening many loads quickly.

    M(s) fitted through M(s_n) = M_n, max M = λ·M_n, M(1) = μ·M_n

    Parameters
    ----------
    motor : MotorRow
        Catalog row: rated torque and slip, breakdown and starting ratios

    Returns
    -------
    fit : MotorFit
        The motor, its curve, rated and starting torque [N·m], synchronous speed [rpm]

    Notes
    -----
    The fit (a bisection) is cached by the ratings it depends on.

    Examples
    --------
    >>> from catalogs import load_catalogs
    >>> m = next(m for m in load_catalogs().motors if m.model == "4A71B4")
    >>> round(fit_motor(m).rated_torque_Nm, 3)
    5.152

    References
    ----------
    :func:`advisor.calc.induction.fit_kloss`; seed 001, fig. 4.
    """
    curve = _fit(
        motor.rated_torque_Nm,
        motor.rated_slip,
        motor.breakdown_torque_ratio,
        motor.starting_torque_ratio,
    )
    return MotorFit(
        motor, curve, motor.rated_torque_Nm, curve.torque(1.0), motor.synchronous_speed_rpm
    )


_fit = lru_cache(maxsize=1024)(induction.fit_kloss)


def drive_working_speed(
    fit: MotorFit, load_torque_Nm: float, required_speed_rpm: float
) -> float | None:
    """The working speed of a motor driving the load directly, if it can.

    n_w = n₀·(1 − s_w),  M(s_w) = M_load;  None unless M_n ≥ M_load, M(1) ≥ M_load
    and n_w ≥ n_req

    Parameters
    ----------
    fit : MotorFit
        The motor with its fitted curve (:func:`fit_motor`)
    load_torque_Nm : float
        Load torque at the motor [N·m]
    required_speed_rpm : float
        Screw speed that makes the stroke in the travel time [rpm]

    Returns
    -------
    speed_rpm : float or None
        Working speed n_w [rpm]; None when the motor cannot drive the load continuously

    Notes
    -----
    The same tests as :attr:`MotorEvaluation.problems`.

    Examples
    --------
    4A71B4 (0.75 kW, 1390 rpm) on seed 001's 5.085 N·m at 1200 rpm: rated torque
    5.152 N·m ≥ 5.085, so it drives the screw at a little above 1390 rpm.

    >>> from catalogs import load_catalogs
    >>> m = next(m for m in load_catalogs().motors if m.model == "4A71B4")
    >>> round(drive_working_speed(fit_motor(m), 5.085, 1200.0))
    1392
    >>> drive_working_speed(fit_motor(m), 5.2, 1200.0) is None
    True

    References
    ----------
    Seed 001: the motor drives the screw at its working point.
    """
    if fit.rated_torque_Nm / load_torque_Nm < 1.0 or fit.starting_torque_Nm / load_torque_Nm < 1.0:
        return None
    s = fit.curve.stable_slip(load_torque_Nm)
    if s is None:
        return None
    n = fit.synchronous_speed_rpm * (1.0 - s)
    return n if n >= required_speed_rpm else None
