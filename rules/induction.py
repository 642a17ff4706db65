"""Rules of the induction motor choice (seed 001, GOST 12139-84)."""

from typing import NamedTuple

from advisor.core.cite import cite
from advisor.core.rulebook import Finding, rule

SEED_001 = cite("seed-001")


class PoleOption(NamedTuple):
    pole_pairs: int
    synchronous_speed_rpm: float
    motor_model: str | None  # smallest catalog motor of this pole count that covers the power
    rated_speed_rpm: float | None


@rule("IM-01", "Number of pole pairs", SEED_001)
def choose_pole_pairs(required_speed_rpm: float, options: list[PoleOption]) -> Finding[int | None]:
    """The largest p (slowest motor) whose rated speed — synchronous speed less the slip of
    the motor that would be used — still reaches the required speed."""
    fits = [
        o
        for o in options
        if o.rated_speed_rpm is not None and o.rated_speed_rpm >= required_speed_rpm
    ]
    table = {
        f"p={o.pole_pairs}": (
            f"{o.synchronous_speed_rpm:g} rpm sync, {o.motor_model} {o.rated_speed_rpm:g} rpm"
            if o.motor_model
            else f"{o.synchronous_speed_rpm:g} rpm sync, no motor covers the power"
        )
        for o in options
    }
    if not fits:
        return Finding(
            None,
            f"No pole count reaches {required_speed_rpm:.0f} rpm at rated slip.",
            "Even the 2-pole motor's rated speed is below the required screw speed; a coarser "
            "pitch or more thread starts would lower it.",
            table,
        )
    best = max(fits, key=lambda o: o.pole_pairs)
    return Finding(
        best.pole_pairs,
        f"p = {best.pole_pairs} ({2 * best.pole_pairs} poles, synchronous "
        f"{best.synchronous_speed_rpm:g} rpm).",
        f"The screw must turn at {required_speed_rpm:.0f} rpm. With the slip of the candidate "
        f"motor ({best.motor_model}, {best.rated_speed_rpm:g} rpm at rated load) this is the "
        "slowest motor that still reaches it; a slower one cannot, and a faster one would "
        "need more torque margin for nothing and shorten the travel time further.",
        table,
    )


@rule("IM-02", "Rated power and the design space", cite("gost-12139-84") + SEED_001)
def rated_power_band(
    required_power_kW: float, series_kW: list[float]
) -> Finding[tuple[float | None, list[float]]]:
    """The nearest rated power of the series that covers the requirement, with its lower and
    higher neighbours: the three motors whose characteristics bound the choice (seed 001)."""
    above = [p for p in series_kW if p >= required_power_kW - 1e-12]
    if not above:
        return Finding(
            (None, []),
            f"No rated power of GOST 12139-84 reaches {required_power_kW:.3f} kW.",
            "The requirement exceeds the series.",
        )
    nearest = above[0]
    i = series_kW.index(nearest)
    band = series_kW[max(0, i - 1) : i + 2]
    return Finding(
        (nearest, band),
        f"Rated power {nearest:g} kW, with neighbours {', '.join(f'{p:g}' for p in band)} kW.",
        f"The screw needs {required_power_kW:.3f} kW at the required speed (torque × speed, i.e. "
        "the output power through the screw efficiency). The nearest rated power that is not "
        "below it is taken; a lower one could carry the load only overloaded. Seed 001 plots the "
        "chosen motor with its lower and higher neighbours to show the design space.",
        {"required_power_kW": round(required_power_kW, 4)},
    )


class MotorOption(NamedTuple):
    rated_power_kW: float
    model: str | None
    problems: tuple[str, ...]
    rated_torque_margin: float | None


@rule("IM-03", "Motor of the catalog", cite("gost-12139-84") + SEED_001)
def choose_motor(options: list[MotorOption]) -> Finding[str | None]:
    """The smallest rated power (from the nearest one up) whose catalog motor drives the load
    continuously: rated torque ≥ load, starts under load, stable working point."""
    for o in options:
        if o.model is not None and not o.problems:
            skipped = [
                f"{x.rated_power_kW:g} kW ({'; '.join(x.problems) or 'not in catalog'})"
                for x in options
                if x.rated_power_kW < o.rated_power_kW
            ]
            return Finding(
                o.model,
                f"{o.model}, {o.rated_power_kW:g} kW.",
                f"Rated torque covers the load with margin {o.rated_torque_margin:.3f}, it starts "
                "under load and runs on the stable branch of its characteristic"
                + (f"; skipped: {', '.join(skipped)}" if skipped else "")
                + ".",
            )
    return Finding(
        None,
        "No catalog motor drives the load.",
        "; ".join(
            f"{o.rated_power_kW:g} kW: {', '.join(o.problems) or 'not in catalog'}" for o in options
        ),
    )
