"""The ``[duty]`` table: a cycle the drive repeats. Without it nothing changes.

Positioning repeats seed 003's move: ``cycle_time_s`` (one move of ``positioning.travel_rad``,
then rest until the cycle ends). Linear and rotary drives give either a list of segments
(move, dwell, hold) repeated ``cycles_per_hour`` times, or an IEC 60034-1 duty type with its
parameters.
"""

from typing import Annotated, Literal

from advisor.core.ranges import range_prose
from advisor.core.requirements import StrictModel, after_check, ask, field_check, number_field
from advisor.duty import requirement_checks

STEP = 4  # the wizard step that asks the duty


#: The largest load of a linear segment, N (as linear.force_N), and of a load share (a tenfold
#: overload): each 0 (none) or from its requirement_checks minimum up to this.
SEGMENT_FORCE_MAX_N = 5e6
LOAD_SHARE_MAX = 10.0


class PositioningDutyReq(StrictModel):
    cycle_time_s: Annotated[
        float,
        number_field(
            ge=1e-3,
            le=1e6,
            desc="time of one cycle: one move of positioning.travel_rad, then rest, s",
            label="Cycle time",
            step=STEP,
        ),
    ]


class _Segment(StrictModel):
    kind: Annotated[
        Literal["move", "dwell", "hold"],
        ask(
            "move the load, dwell (no load held), or hold the load at rest",
            label="segment",
            step=STEP,
        ),
    ]
    time_s: Annotated[
        float,
        number_field(
            ge=1e-3,
            le=1e6,
            desc="duration of the segment (a move: the time it may take), s",
            label="time",
            step=STEP,
        ),
    ]


class LinearSegmentReq(_Segment):
    distance_m: Annotated[
        float | None,
        number_field(
            gt=0, le=20, desc="path of a move, m (a move: required)", label="distance", step=STEP
        ),
    ] = None
    direction: Annotated[
        Literal["against", "with"],
        ask(
            "a move against the load force (the motor drives) or with it (the load drives)",
            label="direction",
            step=STEP,
        ),
    ] = "against"
    force_N: Annotated[
        float | None,
        number_field(
            ge=0,
            le=SEGMENT_FORCE_MAX_N,
            desc="axial load of the segment, N: 0 or "
            + range_prose("N", ge=requirement_checks.SEGMENT_FORCE_MIN_N, le=SEGMENT_FORCE_MAX_N)
            + "; default linear.force_N",
            label="force",
            step=STEP,
        ),
    ] = None

    _force_zero_or_range = field_check("force_N", requirement_checks.force_zero_or_range)
    _move_has_distance = after_check(requirement_checks.move_has_distance)


class RotarySegmentReq(_Segment):
    angle_deg: Annotated[
        float | None,
        number_field(
            ge=1e-3,
            le=1e7,
            desc="angle of a move at the output, {range} (a move: required)",
            label="angle",
            step=STEP,
        ),
    ] = None
    profile: Annotated[
        Literal["trapezoidal", "triangular"],
        ask("speed graph of a move", label="speed graph", step=STEP),
    ] = "trapezoidal"
    accel_fraction: Annotated[
        float,
        number_field(
            ge=1e-3,
            lt=0.5,
            desc="share of a trapezoidal move spent accelerating (and braking)",
            label="accelerating share",
            step=STEP,
        ),
    ] = 0.25
    direction: Annotated[
        Literal["against", "with"],
        ask(
            "a move against the load torque (the motor drives) or with it (the load drives)",
            label="direction",
            step=STEP,
        ),
    ] = "against"
    torque_Nm: Annotated[
        float | None,
        number_field(
            ge=0,
            le=1e6,
            desc="output load torque of the segment, N·m; default rotary.torque_Nm",
            label="load torque",
            step=STEP,
        ),
    ] = None

    _move_has_angle = after_check(requirement_checks.move_has_angle)


class LoadShareReq(StrictModel):
    load_share: Annotated[
        float,
        number_field(
            ge=0,
            le=LOAD_SHARE_MAX,
            desc="load as a share of the rated load: 0 (no load) or "
            + range_prose(ge=requirement_checks.LOAD_SHARE_MIN, le=LOAD_SHARE_MAX),
            label="load share",
            step=STEP,
        ),
    ]
    _share_zero_or_range = field_check("load_share", requirement_checks.share_zero_or_range)
    time_share: Annotated[
        float,
        number_field(
            gt=0, le=1, desc="share of the time at that load", label="time share", step=STEP
        ),
    ]


DutyType = Literal["S1", "S2", "S3", "S4", "S5", "S6", "S7", "S8", "S9", "S10"]


class _CycleDuty(StrictModel):
    duty_type: Annotated[
        DutyType | None,
        ask(
            "IEC 60034-1 duty type S1…S10 instead of segments",
            label="IEC duty type",
            step=STEP,
            example="S3",
        ),
    ] = None
    cycles_per_hour: Annotated[
        float | None,
        number_field(
            ge=1e-3,
            le=36000,
            desc="how often the segments repeat, 1/h",
            label="Cycles per hour",
            step=STEP,
        ),
    ] = None
    cyclic_duration_factor: Annotated[
        float | None,
        number_field(
            gt=0,
            le=1,
            desc="share of the cycle under load (S3–S6), e.g. 0.4",
            label="Cyclic duration factor",
            step=STEP,
        ),
    ] = None
    starts_per_hour: Annotated[
        float | None,
        number_field(
            ge=1e-3,
            le=36000,
            desc="starts per hour (S4, S5, S7)",
            label="Starts per hour",
            step=STEP,
        ),
    ] = None
    duration_min: Annotated[
        float | None,
        number_field(
            gt=0,
            le=1e4,
            desc="time under load of an S2 duty, min",
            label="S2 time under load",
            unit="min",
            step=STEP,
        ),
    ] = None
    cycle_time_s: Annotated[
        float,
        number_field(
            ge=1e-3,
            le=1e6,
            desc="cycle time of an S3–S6 duty, s (IEC: 10 min)",
            label="Cycle time (S3, S6, S9, S10)",
            step=STEP,
        ),
    ] = 600.0
    loads: Annotated[
        list[LoadShareReq],
        ask("S9, S10: the loads as shares of the rated load with their time shares", max_length=20),
    ] = []  # noqa: RUF012 - pydantic copies field defaults

    _one_form = after_check(requirement_checks.one_form)


class LinearDutyReq(_CycleDuty):
    segments: Annotated[
        list[LinearSegmentReq],
        ask(
            "the cycle: moves, dwells and holds in order",
            max_length=100,
            extra={"row-label": "Segment"},
        ),
    ] = []  # noqa: RUF012 - pydantic copies field defaults
    moving_mass_kg: Annotated[
        float,
        number_field(ge=0, le=1e6, desc="mass the nut moves, kg", label="Moving mass", step=STEP),
    ] = 0.0
    standstill_cooling_factor: Annotated[
        float,
        number_field(
            gt=0,
            le=1,
            desc="β0: cooling of the self-ventilated motor at standstill against at speed",
            label="Cooling at standstill β0",
            step=STEP,
        ),
    ] = 0.5


class RotaryDutyReq(_CycleDuty):
    segments: Annotated[
        list[RotarySegmentReq],
        ask(
            "the cycle: moves, dwells and holds in order",
            max_length=100,
            extra={"row-label": "Segment"},
        ),
    ] = []  # noqa: RUF012 - pydantic copies field defaults
    load_inertia_kgm2: Annotated[
        float,
        number_field(
            ge=0,
            le=1e7,
            desc="inertia of the load at the output, kg·m²",
            label="Load inertia",
            step=STEP,
        ),
    ] = 0.0
    motor_inertia_kgm2: Annotated[
        float | None,
        number_field(
            ge=1e-11,
            le=1e3,
            desc="rotor inertia of the motor, kg·m²; left out: the chosen frame's or catalog "
            "motor's",
            label="Motor inertia",
            step=STEP,
        ),
    ] = None
    thermal_time_constant_s: Annotated[
        float | None,
        number_field(
            gt=0,
            le=1e5,
            desc="thermal time constant of the motor, s; left out: the chosen frame's or "
            "catalog motor's",
            label="Thermal time constant",
            step=STEP,
        ),
    ] = None
    peak_torque_factor: Annotated[
        float,
        number_field(
            ge=1,
            le=10,
            desc="peak torque the motor and drive give, as a multiple of the torque at the "
            "frame's loss limit (servo catalogs: about 3)",
            label="Peak/continuous torque",
            step=STEP,
        ),
    ] = 3.0
