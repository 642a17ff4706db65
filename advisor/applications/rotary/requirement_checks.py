"""The rotary requirement's own rules, free of pydantic: the requirement models run them as
validators (:mod:`advisor.applications.rotary.requirements`), and so does the compiled
validator of the batch path (:mod:`advisor.core.compiled_validator`). Each raises ValueError with
the
message the user reads."""

from typing import Any

from advisor.core.ranges import zero_or_from

#: The smallest magnet loss taken as a loss; below it the loss is 0 (none) or a slip: the
#: power law through two points takes the logarithm of their ratio, which a denormal loss
#: makes 0 (a math domain error).
MAGNET_LOSS_MIN_W = 1e-6


def magnet_loss_zero_or_range(v: float) -> float:
    return zero_or_from(v, MAGNET_LOSS_MIN_W, "1e+05 W")  # type: ignore[return-value]


def one_loss_per_speed(ref: Any) -> None:
    speeds = [p.speed_rpm for p in ref.magnet_losses]
    if len(set(speeds)) < len(speeds):
        raise ValueError(
            "motor.reference.magnet_losses: two points at one speed_rpm; give one loss_W per speed"
        )


def each_speed_once(v: list[float]) -> list[float]:
    twice = sorted({x for x in v if v.count(x) > 1})
    if twice:  # the comparison would show one candidate where the list names two
        said = ", ".join(f"{x:g}" for x in twice)
        raise ValueError(f"{said} rpm given more than once: name each speed once")
    return v


def reducer_reduces(req: Any) -> None:
    slowest = min(req.motor.candidate_speeds_rpm)
    if req.rotary.speed_rpm >= slowest:
        raise ValueError(
            f"rotary.speed_rpm = {req.rotary.speed_rpm:g} is not below the slowest "
            f"motor.candidate_speeds_rpm ({slowest:g}): the reducer lowers the speed"
        )


def moment_needs_pair(load: Any) -> None:
    if load.tilting_moment_Nm > 0 and load.bearing_spacing_mm is None:
        raise ValueError(
            f"output_load.tilting_moment_Nm = {load.tilting_moment_Nm:g} needs "
            "output_load.bearing_spacing_mm: a pair of bearings takes a tilting moment"
        )


def bus_rises(drive: Any) -> None:
    if drive.bus_max_voltage_V <= drive.bus_voltage_V:
        raise ValueError(
            f"drive.bus_max_voltage_V = {drive.bus_max_voltage_V:g} is not above "
            f"drive.bus_voltage_V = {drive.bus_voltage_V:g}: the bus absorbs energy only by "
            "rising"
        )
