"""Requirements of the linear actuator (seed 001): induction motor + sliding screw–nut."""

from typing import Annotated, Literal

from pydantic import Field

from advisor.applications.linear import requirement_checks
from advisor.core.requirements import (
    ApplicationReq,
    DesignReq,
    OneWayReq,
    ProjectField,
    StrictModel,
    after_check,
    ask,
    field_check,
    number_field,
)
from advisor.duty.requirements import LinearDutyReq
from advisor.uncertainty.requirements import UncertaintyField


class LinearReq(StrictModel):
    """The linear stage. Every number has a physically meaningful range, so that the advice
    stays finite: a screw actuator of this advisor pushes 1 N … 5 MN over 1 mm … 20 m in
    10 ms … about 28 h."""

    force_N: Annotated[
        float,
        number_field(
            ge=1, le=5e6, desc="rated axial force, N; {range}", label="Axial force", step=1
        ),
    ]
    stroke_m: Annotated[
        float, number_field(ge=1e-3, le=20, desc="stroke, m; {range}", label="Stroke", step=1)
    ]
    travel_time_s: Annotated[
        float,
        number_field(
            ge=0.01,
            le=1e5,
            desc="time for the full stroke, s; {range}",
            label="Time for the stroke",
            step=1,
        ),
    ]
    support_span_m: Annotated[
        float,
        number_field(
            ge=1e-3,
            le=20,
            desc="distance between the screw supports, m; {range}",
            label="Unsupported screw length",
            step=1,
        ),
    ]
    end_fixity: Annotated[
        Literal["pinned-pinned", "fixed-pinned", "fixed-fixed", "fixed-free"],
        ask(
            "how the screw ends are held, for buckling and the whirling speed",
            label="End fixity of the screw",
            step=2,
        ),
    ] = "pinned-pinned"
    buckling_safety_factor: Annotated[
        float, number_field(ge=1, le=20, desc="required margin against buckling; {range}")
    ] = 3.0
    emergency_stop_force_N: Annotated[
        float | None,
        number_field(
            ge=1,
            le=5e6,
            desc="momentary peak axial force in an emergency stop or a collision, {range}; "
            "the screw's core stress, buckling, nut pressure and a thrust bearing's static "
            "load are checked again at the larger of it and the rated force (× f_B), and the "
            "holding device is sized for the larger; left out: the rated force",
            label="Emergency-stop force",
            step=1,
        ),
    ] = None

    _stroke_fits = after_check(requirement_checks.stroke_fits)


class InductionMotorReq(StrictModel):
    kind: Annotated[Literal["induction"], Field(description="motor type")]
    supply_frequency_Hz: Annotated[
        float, number_field(gt=0, desc="supply frequency, Hz", label="Supply frequency", step=3)
    ] = 50.0

    _fifty = field_check("supply_frequency_Hz", requirement_checks.fifty)


class ScrewThrustReq(StrictModel):
    """The face that takes the screw's axial force ([screw.thrust]): a plain collar (its mean
    diameter and friction) or a rolling bearing of the SKF catalog. Its friction torque adds
    to the thread's (Shigley, eq. (8-6)); left as "unknown", the report warns that the motor
    margin leaves it out."""

    kind: Annotated[
        Literal["unknown", "collar", "bearing"],
        ask(
            "what takes the axial force at the driven end: a plain collar, a rolling bearing, "
            "or unknown (its friction left out, with a warning)",
            label="Thrust face",
            step=2,
        ),
    ] = "unknown"
    mean_diameter_mm: Annotated[
        float | None,
        number_field(
            gt=0,
            le=2000,
            desc="mean diameter of the thrust collar, mm (outer + inner)/2; {range}",
            label="Collar mean diameter (collar only)",
            step=2,
        ),
    ] = None
    friction_coefficient: Annotated[
        float | None,
        number_field(
            ge=0.01,
            le=0.6,
            desc="collar friction coefficient f_c; {range} (Shigley Table 8-6: 0.06 … 0.12 "
            "running)",
            label="Collar friction coefficient (collar only)",
            step=2,
        ),
    ] = None
    bearing: Annotated[
        str | None,
        ask(
            "SKF designation of the thrust bearing (bearing only), e.g. 7205 BECBP",
            label="Thrust bearing (bearing only)",
            step=2,
            example="7205 BECBP",
            max_length=40,
        ),
    ] = None
    lubricant_viscosity_mm2_s: Annotated[
        float,
        number_field(
            ge=0.5,
            le=5000,
            desc="kinematic viscosity of the bearing's lubricant at its temperature, mm²/s; "
            "{range}",
        ),
    ] = 68.0

    _complete = after_check(requirement_checks.thrust_complete)


class ScrewReq(StrictModel):
    friction_coefficient: Annotated[
        float | None,
        number_field(
            ge=0.01,
            le=0.6,
            desc="thread friction coefficient f; {range}",
            label="Thread friction coefficient f",
            step=3,
        ),
    ] = None
    starts: Annotated[
        int | None,
        ask(
            "number of thread starts, {range}; left out, the advisor chooses it",
            label="Thread starts (empty: chosen)",
            step=2,
            ge=1,
            le=4,
        ),
    ] = None
    friction_model: Annotated[
        Literal["standard", "paper"],
        ask("reduced friction formula", label="Friction formula", step=3),
    ] = "standard"
    thread: Annotated[
        str | None,
        ask("imposed thread, e.g. Tr16x2", label="Impose a thread", step=2, example="Tr16x2"),
    ] = None
    material_pair: Annotated[
        Literal["steel_bronze", "hardened_steel_bronze", "steel_cast_iron", "steel_steel"],
        ask("screw and nut materials", label="Screw–nut materials", step=2),
    ] = "steel_bronze"
    lubrication: Annotated[Literal["oil", "dry"], Field(description="thread lubrication")] = "oil"
    screw_steel: Annotated[Literal["45", "40X"], Field(description="screw steel grade")] = "45"
    thrust: ScrewThrustReq = ScrewThrustReq.model_construct()

    _thread_form = field_check("thread", requirement_checks.thread_form)


class LinearRequirements(StrictModel):
    """A linear actuator: induction motor + sliding screw–nut (seed 001)."""

    application: ApplicationReq
    project: ProjectField = None  # the datasheet's header (advisor.core.requirements)
    linear: Annotated[
        LinearReq,
        Field(description="the [linear] table: force_N, stroke_m, travel_time_s, support_span_m"),
    ]
    motor: Annotated[InductionMotorReq, Field(description="the [motor] table: kind = 'induction'")]
    # defaults made without validation (they are valid): a nested model builds no validator
    # of its own (defer_build), and validating one here would build it at import (the batch path
    # must stay light)
    screw: ScrewReq = ScrewReq.model_construct()
    one_way: OneWayReq = OneWayReq.model_construct()
    design: DesignReq = DesignReq.model_construct()
    duty: Annotated[
        LinearDutyReq | None,
        Field(description="the [duty] table: segments with cycles_per_hour, or duty_type"),
    ] = None
    uncertainty: UncertaintyField = None  # the probability of passing (advisor.uncertainty)
