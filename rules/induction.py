"""Rules of the induction motor choice (seed 001, GOST 12139-84)."""

from typing import NamedTuple

from advisor.core.cite import cite
from advisor.core.rulebook import Finding, rule

SEED_001 = cite("seed-001")


class PoleOption(NamedTuple):
    """The best drive with one pole count: its thread, motor and travel time."""

    pole_pairs: int
    synchronous_speed_rpm: float
    thread: str | None  # None: no thread of this pole count is driven by a catalog motor
    motor_model: str | None
    rated_power_kW: float | None
    travel_time_s: float | None


@rule("IM-01", "Number of pole pairs", SEED_001)
def choose_pole_pairs(
    chosen: int, required_speed_rpm: float, options: list[PoleOption]
) -> Finding[int]:
    """The pole count of the drive chosen with the thread (SCR-04): seed 001 lets the screw
    speed fix p; with the pitch (and the starts) free, every pole count gets its own best
    thread, and the one with the smallest motor wins."""
    table = {
        f"p={o.pole_pairs}": (
            f"{o.synchronous_speed_rpm:g} rpm sync: {o.thread} + {o.motor_model} "
            f"({o.rated_power_kW:g} kW, stroke in {o.travel_time_s:.3g} s)"
            if o.motor_model
            else f"{o.synchronous_speed_rpm:g} rpm sync: no motor of this speed drives a "
            "passing thread"
        )
        for o in options
    }
    table["pole_pairs"] = chosen
    best = next(o for o in options if o.pole_pairs == chosen)
    table["synchronous_speed_rpm"] = best.synchronous_speed_rpm
    table["required_speed_rpm"] = required_speed_rpm
    others = [o for o in options if o.motor_model and o.pole_pairs != chosen]
    return Finding(
        chosen,
        f"p = {chosen} ({2 * chosen} poles, synchronous {best.synchronous_speed_rpm:g} rpm).",
        f"The chosen screw must turn at {required_speed_rpm:.4g} rpm to make the stroke in "
        f"time; the {2 * chosen}-pole motor drives it directly with the smallest motor of all "
        "pole counts"
        + (
            " (the others: "
            + "; ".join(f"p={o.pole_pairs} needs {o.rated_power_kW:g} kW" for o in others)
            + ")"
            if others
            else ""
        )
        + ".",
        table,
    )


@rule("IM-02", "Rated power and the design space", cite("gost-12139-84") + SEED_001)
def rated_power_band(
    required_power_kW: float,
    working_power_kW: float,
    rated_power_kW: float,
    series_kW: list[float],
) -> Finding[list[float]]:
    """The rated power of the chosen motor with its lower and higher neighbours of the series:
    the three motors whose characteristics bound the choice (seed 001, fig. 4). The power
    stated is the design's: the load torque at the motor's own working speed."""
    i = series_kW.index(rated_power_kW)
    band = series_kW[max(0, i - 1) : i + 2]
    return Finding(
        band,
        f"Rated power {rated_power_kW:g} kW, with neighbours "
        f"{', '.join(f'{p:g}' for p in band)} kW.",
        f"The screw needs {required_power_kW:.4g} kW at the required speed; coupled directly, "
        f"the motor turns it at its own working speed, where the load takes "
        f"{working_power_kW:.4g} kW. The rated power is that of the smallest catalog motor "
        "that carries the load torque, starts it and reaches the speed. Seed 001 plots the "
        "chosen motor with its lower and higher neighbours to show the design space.",
        {
            "required_power_kW": required_power_kW,
            "working_power_kW": working_power_kW,
            "rated_power_kW": rated_power_kW,
            "band_kW": band,
        },
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
                {
                    "model": o.model,
                    "rated_power_kW": o.rated_power_kW,
                    "rated_torque_margin": o.rated_torque_margin,
                },
            )
    return Finding(
        None,
        "No catalog motor drives the load.",
        "; ".join(
            f"{o.rated_power_kW:g} kW: {', '.join(o.problems) or 'not in catalog'}" for o in options
        ),
    )
