"""The linear requirement's own rules, free of pydantic: run by the requirement models
(:mod:`advisor.applications.linear.requirements`) and by the compiled validator of the batch
path (:mod:`advisor.core.compiled_validator`). Each raises ValueError with the message the user
reads."""

import re
from typing import Any

THREAD_RE = re.compile(r"^Tr\s*(\d+(?:\.\d+)?)\s*[x×]\s*(\d+(?:\.\d+)?)$", re.IGNORECASE)


def stroke_fits(lin: Any) -> None:
    if lin.stroke_m > lin.support_span_m:
        raise ValueError(
            f"linear.stroke_m = {lin.stroke_m:g} is longer than linear.support_span_m = "
            f"{lin.support_span_m:g}: the nut must travel between the supports"
        )


def fifty(v: float) -> float:
    if v != 50.0:
        raise ValueError("must be 50: the induction motor catalog holds 50 Hz ratings")
    return v


def thread_form(v: str | None) -> str | None:
    if v is None:
        return v
    m = THREAD_RE.match(v.strip())
    if not m:
        raise ValueError("must be a trapezoidal thread written like Tr16x2 (d x P in mm)")
    d, pitch = float(m.group(1)), float(m.group(2))
    if round(d, 2) != d or round(pitch, 2) != pitch:  # GOST 24738 sizes: 2 decimals at most
        raise ValueError(
            "is not a GOST 24738 size: diameter and pitch are whole millimetres or "
            "halves (Tr16x2, Tr10x1.5)"
        )
    return f"Tr{d:g}x{pitch:g}"


def thrust_complete(thrust: Any) -> None:
    """A collar needs its diameter and friction, a bearing its designation; neither may carry
    the other's keys (a typo of kind must not be silently ignored)."""
    need = {"collar": ("mean_diameter_mm", "friction_coefficient"), "bearing": ("bearing",)}
    given = [
        k
        for k in ("mean_diameter_mm", "friction_coefficient", "bearing")
        if getattr(thrust, k) is not None
    ]
    wanted = need.get(thrust.kind, ())
    missing = [k for k in wanted if getattr(thrust, k) is None]
    if missing:
        raise ValueError(f"screw.thrust.kind = {thrust.kind!r} needs screw.thrust.{missing[0]}")
    extra = [k for k in given if k not in wanted]
    if extra:
        raise ValueError(
            f"screw.thrust.{extra[0]} is given but screw.thrust.kind = {thrust.kind!r} does "
            f"not use it (kind = {'collar' if extra[0] != 'bearing' else 'bearing'}?)"
        )
