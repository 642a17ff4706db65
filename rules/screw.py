"""Rules of the sliding screw–nut stage (seed 001 and the power-screw design texts)."""

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
            {"given": given, "range": [low, high]},
        )
    mid = round((low + high) / 2.0, 4)
    return Finding(
        mid,
        f"f = {mid:g}, the middle of the catalog range {low:g}…{high:g} "
        f"for {pair} ({lubrication}).",
        "No coefficient was given; the middle of the published range is the expected value, "
        "and the low end is kept for the self-locking check.",
        {"pair": pair, "lubrication": lubrication, "range": [low, high]},
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
        )
    return Finding(
        "standard",
        "Reduced friction tan φ' = f / cos(α/2) with α = 30° (trapezoidal flank angle).",
        "The friction force on a flank inclined at α/2 is raised by 1/cos(α/2); this is the "
        "textbook form for trapezoidal threads. Seed 001 prints cos(ψ/2), a slip.",
    )


class ThreadOption(NamedTuple):
    """What the thread rule needs to know about one candidate."""

    name: str
    d_mm: float
    pitch_mm: float
    preferred: bool
    passed: bool
    failed: tuple[str, ...]
    self_locking_at_low_friction: bool
    motor_torque_Nm: float | None  # rated torque of the motor it needs; None: no motor fits
    motor_model: str | None


@rule(
    "SCR-04",
    "Thread of the screw",
    cite("gost-24738-81", "diameter-pitch plan") + cite("ivanov-dm", "power screws") + SEED_001,
)
def choose_thread(
    options: list[ThreadOption], hold_without_power: bool, imposed: str | None
) -> Finding[str | None]:
    """Smallest diameter with a pitch that passes every check and has a motor; among its
    pitches the one whose motor is smallest (rated torque — an induction motor's size
    follows its torque), or, where holding without power is asked for, the finest pitch that
    stays self-locking at the low end of the friction range."""
    if imposed is not None:
        opt = next((o for o in options if o.name == imposed), None)
        verdict = (
            "passes every check"
            if opt and opt.passed
            else f"fails: {', '.join(opt.failed) if opt else 'not evaluated'}"
        )
        own = _choose(options, hold_without_power)
        own_note = f" Left to itself the advisor would choose {own[0]}." if own else ""
        return Finding(
            imposed,
            f"Thread {imposed}, imposed by the requirement; it {verdict}.",
            "An imposed thread is kept and checked like any other, so its margins are in the "
            "report." + own_note,
            {"imposed": imposed, "advisor_choice": own[0] if own else None},
        )
    chosen = _choose(options, hold_without_power)
    if chosen is None:
        return Finding(
            None,
            "No GOST 24738-81 thread passes every check with a motor that can drive it.",
            "Every diameter up to 100 mm failed a check or needs a screw speed no 50 Hz "
            "induction motor reaches.",
        )
    name, why = chosen
    return Finding(name, f"Thread {name}.", why, {"hold_without_power": hold_without_power})


def _choose(options: list[ThreadOption], hold: bool) -> tuple[str, str] | None:
    by_d: dict[float, list[ThreadOption]] = {}
    for o in options:
        by_d.setdefault(o.d_mm, []).append(o)
    for d in sorted(by_d):
        ok = [o for o in by_d[d] if o.passed and o.motor_torque_Nm is not None]
        if not ok:
            continue
        smaller = [o for dd, os in by_d.items() if dd < d for o in os]
        why_d = (
            f"d = {d:g} mm is the smallest diameter with a pitch that passes every check"
            + (f" (smaller ones fail: {_first_failures(smaller)})" if smaller else "")
            + "."
        )
        if hold:
            locking = [o for o in ok if o.self_locking_at_low_friction]
            pool = locking or ok
            best = min(pool, key=lambda o: o.pitch_mm)
            tail = (
                " It stays self-locking at the low end of the friction range."
                if best.self_locking_at_low_friction
                else " No passing pitch is self-locking at the low end of the friction range: "
                "the load needs a one-way device to be held without power."
            )
            return best.name, (
                why_d + f" Holding without power is required, so the finest pitch "
                f"({best.pitch_mm:g} mm) is taken: the smallest lead angle, the largest "
                "self-locking margin." + tail
            )
        best = min(ok, key=lambda o: (o.motor_torque_Nm, o.pitch_mm))
        others = ", ".join(
            f"{o.name} → {o.motor_model} ({o.motor_torque_Nm:.2f} N·m)" for o in ok if o is not best
        )
        return best.name, (
            why_d + f" Of its pitches, {best.pitch_mm:g} mm needs the smallest motor: "
            f"{best.motor_model} with {best.motor_torque_Nm:.2f} N·m rated torque"
            + (f" (against {others})" if others else "")
            + "; an induction motor's size follows its rated torque."
        )
    return None


def _first_failures(options: list[ThreadOption]) -> str:
    worst = options[-3:]
    return "; ".join(
        f"{o.name}: {', '.join(o.failed) if o.failed else 'no motor reaches its speed'}"
        for o in worst
    )


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
        )
    if self_locking_at_low:
        return Finding(
            True,
            f"{thread} holds the load without power: self-locking even at the low end of the "
            "friction range.",
            "The lead angle stays below the reduced friction angle for every friction "
            "coefficient the material pair may show, so no one-way device is needed.",
        )
    return Finding(
        False,
        f"{thread} cannot be relied on to hold the load without power.",
        "At the low end of the friction range the lead angle exceeds the friction angle: "
        "the load may back-drive the screw. A one-way device (brake or irreversible clutch) is "
        "needed at the motor side.",
    )
