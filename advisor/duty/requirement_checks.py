"""The ``[duty]`` table's own rules, free of pydantic: run by the requirement models
(:mod:`advisor.duty.requirements`) and by the compiled validator of the batch path
(:mod:`advisor.core.compiled_validator`). Each raises ValueError with the message the user reads."""

from typing import Any

from advisor.core.ranges import zero_or_from

#: The smallest load share taken as a load; below it the share is 0 (no load) or a slip.
LOAD_SHARE_MIN = 1e-3


def share_zero_or_range(v: float) -> float:
    return zero_or_from(v, LOAD_SHARE_MIN, "10")


#: The smallest axial force of a segment taken as a load (as linear.force_N); below it the
#: force is 0 (no load) or a slip: the coast after switch-off, braked by the load alone,
#: would not end in finite time.
SEGMENT_FORCE_MIN_N = 1.0


def force_zero_or_range(v: float | None) -> float | None:
    return zero_or_from(v, SEGMENT_FORCE_MIN_N, "5e+06 N")


def move_has_distance(seg: Any) -> None:
    if seg.kind == "move" and seg.distance_m is None:
        raise ValueError("duty.segments: a move needs distance_m (its path, m)")


def move_has_angle(seg: Any) -> None:
    if seg.kind == "move" and seg.angle_deg is None:
        raise ValueError("duty.segments: a move needs angle_deg (its angle at the output)")


#: The keys an IEC 60034-1 duty type needs besides its name.
NEEDS: dict[str, list[str]] = {
    "S2": ["duration_min"],
    "S3": ["cyclic_duration_factor"],
    "S4": ["cyclic_duration_factor", "starts_per_hour"],
    "S5": ["cyclic_duration_factor", "starts_per_hour"],
    "S6": ["cyclic_duration_factor"],
    "S7": ["starts_per_hour"],
    "S9": ["loads"],
    "S10": ["loads"],
}


def one_form(duty: Any) -> None:
    """Segments or a duty type, each with what it needs."""
    segs = getattr(duty, "segments", [])
    t = duty.duty_type
    if t is None and not segs:
        raise ValueError("duty: give segments (move, dwell, hold) or a duty_type (S1…S10)")
    if t is not None and segs:
        raise ValueError("duty: give either segments or duty_type, not both")
    if segs:
        if duty.cycles_per_hour is None:
            raise ValueError("duty.cycles_per_hour: missing; required with segments")
        total = sum(s.time_s for s in segs)
        if total > 3600.0 / duty.cycles_per_hour * (1 + 1e-9):
            raise ValueError(
                f"duty: the segments take {total:g} s, longer than the cycle of "
                f"3600/{duty.cycles_per_hour:g} = {3600.0 / duty.cycles_per_hour:.4g} s"
            )
        if not any(s.kind == "move" for s in segs):
            raise ValueError("duty.segments: the cycle needs at least one move")
        return
    for key in NEEDS.get(t, []):
        if not getattr(duty, key):
            raise ValueError(f"duty.{key}: missing; required for duty_type = {t!r}")
    if t == "S8":
        raise ValueError(
            "duty.duty_type = 'S8': S8 is the duty of a pole-changing motor with related "
            "load and speed changes; give the cycle as segments instead"
        )
    if t in ("S9", "S10") and abs(sum(x.time_share for x in duty.loads) - 1.0) > 1e-6:
        raise ValueError(
            f"duty.loads: the time shares add up to "
            f"{sum(x.time_share for x in duty.loads):g}; they must add up to 1"
        )
