"""Requirements of the linear actuator (seed 001): induction motor + sliding screw–nut."""

import re
from typing import Annotated, Literal

from pydantic import Field, field_validator, model_validator

from advisor.core.requirements import ApplicationReq, OneWayReq, _num, _Strict


class LinearReq(_Strict):
    force_N: Annotated[float, _num(gt=0, le=5e6, desc="rated axial force, N")]
    stroke_m: Annotated[float, _num(gt=0, le=20, desc="stroke, m")]
    travel_time_s: Annotated[float, _num(gt=0, le=1e5, desc="time for the full stroke, s")]
    support_span_m: Annotated[
        float, _num(gt=0, le=20, desc="distance between the screw supports, m")
    ]
    end_fixity: Annotated[
        Literal["pinned-pinned", "fixed-pinned", "fixed-fixed", "fixed-free"],
        Field(description="how the screw ends are held, for buckling"),
    ] = "pinned-pinned"
    buckling_safety_factor: Annotated[
        float, _num(ge=1, le=20, desc="required margin against buckling")
    ] = 3.0

    @model_validator(mode="after")
    def _stroke_fits(self) -> "LinearReq":
        if self.stroke_m > self.support_span_m:
            raise ValueError(
                f"linear.stroke_m = {self.stroke_m:g} is longer than linear.support_span_m = "
                f"{self.support_span_m:g}: the nut must travel between the supports"
            )
        return self


class InductionMotorReq(_Strict):
    kind: Annotated[Literal["induction"], Field(description="motor type")]
    supply_frequency_Hz: Annotated[float, _num(gt=0, desc="supply frequency, Hz")] = 50.0

    @field_validator("supply_frequency_Hz")
    @classmethod
    def _fifty(cls, v: float) -> float:
        if v != 50.0:
            raise ValueError("must be 50: the induction motor catalog holds 50 Hz ratings")
        return v


THREAD_RE = re.compile(r"^Tr\s*(\d+(?:\.\d+)?)\s*[x×]\s*(\d+(?:\.\d+)?)$", re.IGNORECASE)


class ScrewReq(_Strict):
    friction_coefficient: Annotated[
        float | None, _num(gt=0, le=0.6, desc="thread friction coefficient f")
    ] = None
    starts: Annotated[int, Field(ge=1, le=4, description="number of thread starts")] = 1
    friction_model: Annotated[
        Literal["standard", "paper"], Field(description="reduced friction formula")
    ] = "standard"
    thread: Annotated[str | None, Field(description="imposed thread, e.g. Tr16x2")] = None
    material_pair: Annotated[
        Literal["steel_bronze", "hardened_steel_bronze", "steel_cast_iron", "steel_steel"],
        Field(description="screw and nut materials"),
    ] = "steel_bronze"
    lubrication: Annotated[Literal["oil", "dry"], Field(description="thread lubrication")] = "oil"
    screw_steel: Annotated[Literal["45", "40X"], Field(description="screw steel grade")] = "45"

    @field_validator("thread")
    @classmethod
    def _thread_form(cls, v: str | None) -> str | None:
        if v is None:
            return v
        m = THREAD_RE.match(v.strip())
        if not m:
            raise ValueError("must be a trapezoidal thread written like Tr16x2 (d x P in mm)")
        return f"Tr{float(m.group(1)):g}x{float(m.group(2)):g}"


class LinearRequirements(_Strict):
    """A linear actuator: induction motor + sliding screw–nut (seed 001)."""

    application: ApplicationReq
    linear: Annotated[
        LinearReq,
        Field(description="the [linear] table: force_N, stroke_m, travel_time_s, support_span_m"),
    ]
    motor: Annotated[InductionMotorReq, Field(description="the [motor] table: kind = 'induction'")]
    screw: ScrewReq = ScrewReq()
    one_way: OneWayReq = OneWayReq()
