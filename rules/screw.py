"""Rules of the sliding screw–nut stage (seed 001 and the power-screw design texts)."""

import heapq
import re
from collections.abc import Callable
from operator import attrgetter
from typing import NamedTuple

from advisor.core.cite import cite
from advisor.core.rulebook import Finding, rule

SEED_001 = cite("seed-001")


@rule("SCR-01", "Transmission of the linear stage", SEED_001)
def transmission_type(force_N: float) -> Finding[str]:
    return Finding(
        "sliding screw-nut",
        "A sliding (trapezoidal) screw–nut converts the motor's rotation into the linear stroke.",
        "Seed 001 compares rack, flexible, ball-screw and sliding-screw converters: the sliding "
        "screw–nut carries the largest force for its size, moves smoothly and quietly down to "
        "very low speeds, and can hold the load by self-braking; it is the paper's choice for an "
        "induction motor driving a linear element.",
        {"force_N": force_N},
    )


@rule("SCR-02", "Friction coefficient of the thread", cite("shigley", "table 8-5") + SEED_001)
def friction_coefficient(
    given: float | None, pair: str, lubrication: str, low: float, high: float
) -> Finding[float]:
    if given is not None:
        inside = low <= given <= high
        note = (
            "within"
            if inside
            else "outside — check it: the self-locking verdict depends on the low end"
        )
        return Finding(
            given,
            f"f = {given:g}, as given in the requirement.",
            f"The catalog range for {pair} ({lubrication}) is {low:g}…{high:g}; the given value "
            f"is {note}.",
            {"friction_coefficient": given, "range": [low, high]},
        )
    mid = round((low + high) / 2.0, 4)
    return Finding(
        mid,
        f"f = {mid:g}, the middle of the catalog range {low:g}…{high:g} "
        f"for {pair} ({lubrication}).",
        "No coefficient was given; the middle of the published range is the expected value, "
        "and the low end is kept for the self-locking check.",
        {
            "friction_coefficient": mid,
            "pair": pair,
            "lubrication": lubrication,
            "range": [low, high],
        },
    )


@rule("SCR-03", "Reduced friction formula", cite("gost-24737-81", "α = 30°") + SEED_001)
def friction_model(asked: str) -> Finding[str]:
    if asked == "paper":
        return Finding(
            "paper",
            "Reduced friction tan φ = f / cos(ψ/2), as printed in seed 001 eq. (1).",
            "Asked for in the requirement, to reproduce the paper. The seed's formula halves the "
            "lead angle where the half flank angle belongs; it underestimates the torque of a "
            "trapezoidal thread by about 3 %. The standard-model torque is reported beside it.",
            {"friction_model": "paper"},
        )
    return Finding(
        "standard",
        "Reduced friction tan φ' = f / cos(α/2) with α = 30° (trapezoidal flank angle).",
        "The friction force on a flank inclined at α/2 is raised by 1/cos(α/2); this is the "
        "textbook form for trapezoidal threads. Seed 001 prints cos(ψ/2), a slip.",
        {"friction_model": "standard", "flank_angle_deg": 30.0},
    )


class DriveOption(NamedTuple):
    """One way of making the drive: a thread (with its number of starts) and the smallest
    catalog motor of one pole count that drives it directly."""

    thread: str
    d_mm: float
    pitch_mm: float
    starts: int
    self_locking_at_low_friction: bool
    screw_torque_Nm: float
    motor_model: str
    pole_pairs: int
    rated_power_kW: float
    rated_torque_Nm: float
    travel_time_s: float

    @property
    def label(self) -> str:
        return thread_label(self.thread, self.starts)

    @property
    def motor_size(self) -> tuple[float, float]:
        """The size of the motor: its rated power (the GOST 12139-84 series), then its rated
        torque (the frame of an induction motor follows its torque)."""
        return (self.rated_power_kW, self.rated_torque_Nm)

    @property
    def screw_weight(self) -> tuple[float, int, float, float]:
        """The lightness of the screw: its diameter (mass ∝ d²), then fewer starts (simpler
        to cut), then less torque, then the finer pitch."""
        return (self.d_mm, self.starts, self.screw_torque_Nm, self.pitch_mm)

    def describe(self) -> str:
        return (
            f"{self.label} + {self.motor_model} ({self.rated_power_kW:g} kW, "
            f"{2 * self.pole_pairs}-pole, stroke in {self.travel_time_s:.3g} s)"
        )


def thread_label(thread: str, starts: int) -> str:
    """``Tr20x4`` for one start, ``Tr20x8(P4)`` (GOST 24739-81 notation: lead, then pitch)
    for several."""
    if starts == 1:
        return thread
    d, p = thread[2:].split("x")
    return f"Tr{d}x{float(p) * starts:g}(P{p})"


#: ``Tr20x8(P4)``: diameter, lead, then pitch (GOST 24739-81).
_MULTI_START = re.compile(r"Tr(?P<d>[0-9.]+)x(?P<lead>[0-9.]+)\(P(?P<p>[0-9.]+)\)")


def thread_and_starts(label: str) -> tuple[str, int]:
    """The inverse of :func:`thread_label`: ``Tr20x8(P4)`` → (``Tr20x4``, 2), the thread
    (d x P, GOST 24738-81) and its starts = lead / pitch; a one-start ``Tr20x4`` → (it, 1)."""
    m = _MULTI_START.fullmatch(label)
    if m is None:
        return label, 1
    return f"Tr{m['d']}x{m['p']}", round(float(m["lead"]) / float(m["p"]))


#: :attr:`DriveOption.motor_size`, then :attr:`DriveOption.screw_weight`, as one flat tuple:
#: the same order, built in one call (the joint choice ranks hundreds of options).
_SIZE_THEN_WEIGHT = attrgetter(
    "rated_power_kW", "rated_torque_Nm", "d_mm", "starts", "screw_torque_Nm", "pitch_mm"
)


def drive_order(o: DriveOption, hold: bool) -> tuple:
    """The order of preference: where holding without power is asked, a screw that holds by
    itself first; then the smallest motor; then the lightest screw that it drives."""
    return (not o.self_locking_at_low_friction if hold else False, *_SIZE_THEN_WEIGHT(o))


def drive_order_key(hold: bool) -> Callable[[DriveOption], tuple]:
    """:func:`drive_order` as a sort key. Without holding, every option's first element is
    the same, so the key leaves it out (the same order)."""
    if hold:
        return lambda o: drive_order(o, True)
    return _SIZE_THEN_WEIGHT


#: Runners-up listed in the decision.
RUNNERS_UP = 4


@rule(
    "SCR-04",
    "Thread and motor, chosen together",
    cite("gost-24738-81", "diameter-pitch plan")
    + cite("gost-24739-81", "multi-start")
    + cite("ivanov-dm", "power screws")
    + SEED_001,
)
def choose_drive(
    options: list[DriveOption],
    hold_without_power: bool,
    imposed: str | None,
    imposed_starts: int | None,
) -> Finding[DriveOption | None]:
    """Seed 001 chooses the pitch so that the screw speed suits a speed step of the motor
    (its pole pairs). Over every thread that passes its checks, every number of starts the
    requirement leaves free, and every pole count: the smallest motor first, then the
    lightest screw that it drives. A heavier load can only remove options, so more force
    never gives a smaller motor."""
    free = (
        [o for o in options if o.starts == imposed_starts]
        if imposed_starts is not None
        else options
    )
    pool = [o for o in free if o.thread == imposed] if imposed is not None else free
    # the best and its runners-up only, in the order of a stable sort (nsmallest is
    # sorted(...)[:n]): the first of equals comes first, as min would take it
    ranked = heapq.nsmallest(1 + RUNNERS_UP, pool, key=drive_order_key(hold_without_power))
    best = ranked[0] if ranked else None
    own = best if imposed is None else _best(free, hold_without_power)
    inputs: dict = {
        "hold_without_power": hold_without_power,
        "starts": imposed_starts if imposed_starts is not None else "free (1…4)",
        "options": len(pool),
    }
    if imposed is not None:
        inputs["imposed"] = imposed
        inputs["advisor_choice"] = own.thread if own else None
    if best is None:
        return Finding(
            None,
            "No thread that passes every check can be driven by a catalog motor."
            if imposed is None
            else f"No catalog motor drives the imposed thread {imposed}.",
            "Every thread of GOST 24738-81 up to 100 mm either failed a check or needs a "
            "screw speed or torque that no 50 Hz induction motor of the catalog gives.",
            inputs,
        )
    runners = [o.describe() for o in ranked[1 : 1 + RUNNERS_UP]]
    inputs.update(
        {
            "thread": best.thread,
            "starts_chosen": best.starts,
            "motor": best.motor_model,
            "rated_power_kW": best.rated_power_kW,
            "pole_pairs": best.pole_pairs,
            "runners_up": runners,
        }
    )
    # the count is stated only where holding is asked: without it the best has the
    # smallest motor of all
    smaller = [o for o in pool if o.motor_size < best.motor_size] if hold_without_power else []
    lighter_same_motor = "; it is the lightest screw this motor drives"
    why = (
        (
            f"Thread {imposed}, imposed by the requirement; the smallest motor that drives it "
            f"is {best.motor_model}."
            + (f" Left to itself the advisor would choose {own.describe()}." if own else "")
        )
        if imposed is not None
        else (
            f"{best.motor_model} ({best.rated_power_kW:g} kW, {2 * best.pole_pairs} poles) is "
            "the smallest motor that drives a thread passing every check directly"
            + lighter_same_motor
            + "."
        )
    )
    if hold_without_power:
        why += (
            " Holding without power is asked: only screws self-locking at the low end of the "
            "friction range were considered."
            if best.self_locking_at_low_friction
            else " Holding without power is asked, but no screw that a catalog motor drives is "
            "self-locking at the low end of the friction range: a one-way device holds the load."
        )
    if smaller and hold_without_power:
        why += f" {len(smaller)} option(s) with a smaller motor do not hold by themselves."
    why += (
        " Seed 001 chooses the pitch so that the screw speed suits one of the motor's speed "
        "steps; the motor is the costly part, so it is minimised first (rated power, then "
        "rated torque), and the screw after it (diameter, starts, torque)."
    )
    if runners:
        why += " Runners-up: " + "; ".join(runners) + "."
    return Finding(best, f"Thread {best.label} with {best.motor_model}.", why, inputs)


def _best(options: list[DriveOption], hold: bool) -> DriveOption | None:
    return min(options, key=drive_order_key(hold), default=None)


@rule("SCR-05", "Holding the load without power", cite("ivanov-dm", "power screws") + SEED_001)
def holding(
    hold_without_power: bool, self_locking: bool, self_locking_at_low: bool, thread: str
) -> Finding[bool]:
    if not hold_without_power:
        return Finding(
            self_locking,
            f"Holding without power is not required; {thread} is "
            + ("self-locking." if self_locking else "not self-locking."),
            "Reported for information: a self-locking screw stops the load from back-driving "
            "the motor when it is switched off.",
            {"hold_without_power": False, "self_locking": self_locking},
        )
    if self_locking_at_low:
        return Finding(
            True,
            f"{thread} holds the load without power: self-locking even at the low end of the "
            "friction range.",
            "The lead angle stays below the reduced friction angle for every friction "
            "coefficient the material pair may show, so no one-way device is needed.",
            {"hold_without_power": True, "self_locking_at_low_friction": True},
        )
    return Finding(
        False,
        f"{thread} cannot be relied on to hold the load without power.",
        "At the low end of the friction range the lead angle exceeds the friction angle: "
        "the load may back-drive the screw. A one-way device (brake or irreversible clutch) is "
        "needed at the motor side.",
        {"hold_without_power": True, "self_locking_at_low_friction": False},
    )
