"""Requirements of the positioning drive (seed 003): the move through a reducer, the fastest
among listed motors, or the smallest motor that meets a required move time.

Every number has a physically meaningful range, stated in its description; a value outside it
is an input error naming the field and the range (exit 2). The ranges keep every quantity the
advice computes finite: the ratios searched are 10⁻³ … 10⁶ (advisor/calc/motion.py)."""

from typing import Annotated, Literal

from pydantic import Field

from advisor.applications.positioning import requirement_checks
from advisor.core.ranges import range_prose
from advisor.core.requirements import (
    ApplicationReq,
    ProjectField,
    StrictModel,
    after_check,
    ask,
    field_check,
    number_field,
)
from advisor.duty.requirements import PositioningDutyReq


class CandidateMotor(StrictModel):
    name: Annotated[
        str, ask("a label for the motor", label="name", step=3, min_length=1, max_length=60)
    ]
    speed_rad_s: Annotated[
        float,
        number_field(
            ge=0.1,
            le=1e4,
            desc="rated speed ω0, {range} (about 1 … 95 000 rpm)",
            label="speed ω0",
            step=3,
        ),
    ]
    inertia_kgm2: Annotated[
        float,
        number_field(
            ge=1e-9,
            le=1e3,
            desc="motor and coupling inertia J0, {range}",
            label="inertia J0",
            step=3,
        ),
    ]
    accel_torque_Nm: Annotated[
        float,
        number_field(
            ge=1e-5,
            le=1e6,
            desc="starting and braking torque M_λ, {range}",
            label="start/brake torque M_λ",
            step=3,
        ),
    ]
    rated_torque_Nm: Annotated[
        float | None,
        number_field(
            gt=0,
            le=1e6,
            desc="continuous (S1) torque, N·m; required when [duty] is given",
            label="rated torque",
            step=3,
        ),
    ] = None


#: The largest load inertia (kg·m²) and load torque (N·m) a positioning drive may be given:
#: each 0 (none) or from its requirement_checks minimum up to this.
LOAD_MAX = 1e7


class PositioningReq(StrictModel):
    profile: Annotated[
        Literal["trapezoidal", "triangular"],
        ask("speed graph expected", label="Speed graph", step=1),
    ] = "trapezoidal"
    travel_rad: Annotated[
        float,
        number_field(
            ge=1e-4,
            le=1e5,
            desc="path of the load shaft α, {range} (0.006° to about 16 000 turns)",
            label="Path of the load shaft",
            step=1,
        ),
    ]
    load_inertia_kgm2: Annotated[
        float,
        number_field(
            ge=0,
            le=LOAD_MAX,
            desc="load inertia J_p, 0 (none) or "
            + range_prose("kg·m²", ge=requirement_checks.LOAD_INERTIA_MIN_KGM2, le=LOAD_MAX),
            label="Load inertia",
            step=1,
        ),
    ]
    load_torque_Nm: Annotated[
        float,
        number_field(
            ge=0,
            le=LOAD_MAX,
            desc="load torque M_p, 0 (none) or "
            + range_prose("N·m", ge=requirement_checks.LOAD_TORQUE_MIN_NM, le=LOAD_MAX),
            label="Load torque",
            step=1,
        ),
    ]
    move_time_s: Annotated[
        float | None,
        number_field(
            ge=1e-4,
            le=1e6,
            desc=(
                "required move time, {range}: the smallest motor that moves the load "
                "within it is chosen; required without candidate motors (or a [duty] cycle)"
            ),
            label="Required move time",
            step=1,
        ),
    ] = None
    motors: Annotated[
        list[CandidateMotor],
        ask(
            "candidate motors; none: the induction catalog",
            max_length=200,
            extra={"row-label": "Motor"},
        ),
    ] = []  # noqa: RUF012 - pydantic copies field defaults

    _inertia_zero_or_range = field_check(
        "load_inertia_kgm2", requirement_checks.inertia_zero_or_range
    )

    _torque_zero_or_range = field_check("load_torque_Nm", requirement_checks.torque_zero_or_range)

    _unique_names = after_check(requirement_checks.unique_names)


class PositioningRequirements(StrictModel):
    """A positioning drive: which motor and which ratio make the move fastest."""

    application: ApplicationReq
    project: ProjectField = None  # the datasheet's header (advisor.core.requirements)
    positioning: Annotated[
        PositioningReq,
        Field(description="the [positioning] table: travel_rad, load_inertia_kgm2, load_torque_Nm"),
    ]
    duty: Annotated[
        PositioningDutyReq | None,
        Field(description="the [duty] table: cycle_time_s (optional: the move repeated)"),
    ] = None

    _rated_for_duty = after_check(requirement_checks.rated_for_duty)

    _time_or_motors = after_check(requirement_checks.time_or_motors)
