"""Requirements of the rotary actuator (seed 000): PM brushless motor + wave-gear reducer.

Kept apart from :mod:`advisor.core.requirements` so the linear batch path never builds these
validators.

Every number has a physically meaningful range, stated in its description; a value outside it
is an input error naming the field and the range (exit 2). The ranges span the drives the
seed's model describes — a reducer from about Ø10 mm (1 N·m) to about Ø1 m (10⁵ N·m), a
motor frame from a few watts to hundreds of kilowatts — and keep every quantity the advice
computes finite.
"""

from typing import Annotated, Literal

from pydantic import Field

from advisor.applications.rotary import requirement_checks
from advisor.core.ranges import range_prose
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
from advisor.duty.requirements import RotaryDutyReq


class RotaryReq(StrictModel):
    torque_Nm: Annotated[
        float,
        number_field(
            ge=1,
            le=1e5,
            desc="peak output torque, {range}",
            label="Output torque",
            step=1,
        ),
    ]
    speed_rpm: Annotated[
        float,
        number_field(
            ge=1e-3,
            le=1e4,
            desc="maximum output speed, {range}",
            label="Output speed",
            step=1,
        ),
    ]
    emergency_stop_torque_Nm: Annotated[
        float | None,
        number_field(
            ge=1,
            le=1e6,
            desc="momentary peak torque at the output in an emergency stop or a collision, "
            "{range}; left out: the output torque (the stages and the holding device are "
            "checked against it)",
            label="Emergency-stop torque",
            step=1,
        ),
    ] = None
    emergency_stop_time_s: Annotated[
        float,
        number_field(
            ge=1e-3,
            le=10,
            desc="how long one emergency-stop peak lasts, {range}",
        ),
    ] = 0.15
    emergency_stops: Annotated[
        int | None,
        Field(
            ge=1,
            le=10**7,
            description="emergency stops over the life, {range}; a warning, not a check, "
            "says when it exceeds the count a strain-wave gear's momentary peak allows "
            "(10⁴ flexings in Harmonic Drive's form as quoted; its own text not found)",
        ),
    ] = None


class OutputLoadReq(StrictModel):
    """An external load on the output shaft ([output_load]): its bearing is checked by
    ISO 281 with the SKF catalog."""

    radial_N: Annotated[
        float,
        number_field(
            ge=0, le=1e7, desc="radial force on the output, {range}", label="Radial load", step=2
        ),
    ] = 0.0
    axial_N: Annotated[
        float,
        number_field(
            ge=0, le=1e7, desc="axial force on the output, {range}", label="Axial load", step=2
        ),
    ] = 0.0
    tilting_moment_Nm: Annotated[
        float,
        number_field(
            ge=0,
            le=1e6,
            desc="tilting moment on the output, {range} (taken by a pair of bearings "
            "bearing_spacing_mm apart)",
            label="Tilting moment",
            step=2,
        ),
    ] = 0.0
    speed_rpm: Annotated[
        float | None,
        number_field(
            ge=1e-3,
            le=1e4,
            desc="output speed the bearing's life is counted at, {range} (as "
            "rotary.speed_rpm: slower, the life in hours is not finite); left out: "
            "the mean output speed of the duty cycle, or rotary.speed_rpm",
        ),
    ] = None
    bearing: Annotated[
        str,
        ask(
            "SKF designation of the output bearing (e.g. 6309), or auto: the lightest of the "
            "catalog that gives design.life_h",
            label="Output bearing",
            step=2,
            max_length=40,
        ),
    ] = "auto"
    bearing_spacing_mm: Annotated[
        float | None,
        number_field(
            ge=1,
            le=1e4,
            desc="distance between the two output bearings that take a tilting moment, "
            "{range} (a bearing is wider than 1 mm); left out: one bearing takes the loads "
            "(no tilting moment)",
        ),
    ] = None

    _moment_needs_pair = after_check(requirement_checks.moment_needs_pair)


class DriveReq(StrictModel):
    """The servo drive's DC bus ([drive]): where the energy the motor gives back goes."""

    bus_voltage_V: Annotated[
        float, number_field(ge=12, le=2000, desc="nominal DC-bus voltage, {range}")
    ] = 300.0
    bus_max_voltage_V: Annotated[
        float,
        number_field(
            ge=12,
            le=2500,
            desc="largest DC-bus voltage (the braking chopper's threshold), {range}",
        ),
    ] = 400.0
    bus_capacitance_uF: Annotated[
        float | None,
        number_field(
            gt=0,
            le=1e6,
            desc="the drive's DC-bus capacitance, {range}; left out: the resistor is "
            "sized as if the bus took nothing",
        ),
    ] = None

    _bus_rises = after_check(requirement_checks.bus_rises)


class RotaryDesignReq(DesignReq):
    """[design] of the rotary actuator: the shared service factor and the required life."""

    life_h: Annotated[
        float | None,
        number_field(
            ge=1,
            le=1e7,
            desc="required L10 life of the reducer's rolling elements and of the output "
            "bearing, {range}; left out: the lives are reported, not checked",
            label="Required life L10",
            step=1,
        ),
    ] = None


class EnvelopeReq(StrictModel):
    max_outer_diameter_mm: Annotated[
        float | None,
        number_field(
            ge=1,
            le=1e4,
            desc="largest outer diameter of the reducer, {range}",
            label="Largest reducer diameter",
            step=2,
        ),
    ] = None
    max_length_mm: Annotated[
        float | None,
        number_field(
            ge=1,
            le=1e4,
            desc="largest length of the reducer, {range}",
            label="Largest reducer length",
            step=2,
        ),
    ] = None


#: The speeds a candidate motor speed may take, rpm (the reference design's range).
MOTOR_SPEED_RPM = {"ge": 100, "le": 2e5}

#: The largest magnet loss a point may give, W: 0 (none) or from MAGNET_LOSS_MIN_W up to this.
MAGNET_LOSS_MAX_W = 1e5


class MagnetLossPoint(StrictModel):
    speed_rpm: Annotated[float, number_field(ge=1, le=2e5, desc="motor speed, {range}")]
    loss_W: Annotated[
        float,
        number_field(
            ge=0,
            le=MAGNET_LOSS_MAX_W,
            desc="eddy-current loss in the magnets, 0 (none) or "
            + range_prose("W", ge=requirement_checks.MAGNET_LOSS_MIN_W, le=MAGNET_LOSS_MAX_W)
            + " (a power law runs through two losses; below a microwatt its exponent is not "
            "finite)",
        ),
    ]

    _loss_zero_or_range = field_check("loss_W", requirement_checks.magnet_loss_zero_or_range)


class ReferenceMotor(StrictModel):
    """The design the loss model scales from; the defaults are the seed 000 motor."""

    speed_rpm: Annotated[
        float, number_field(ge=100, le=2e5, desc="speed of the reference design, {range}")
    ] = 5000.0
    pole_pairs: Annotated[
        int, Field(ge=1, le=50, description="electrical reduction p, {range} pole pairs")
    ] = 6
    phase_resistance_ohm: Annotated[
        float, number_field(ge=1e-4, le=1e3, desc="phase resistance, {range}")
    ] = 1.14
    current_A: Annotated[float, number_field(ge=0.01, le=1e4, desc="phase current, {range}")] = 5.5
    conducting_phases: Annotated[
        int, Field(ge=1, le=3, description="phases in series, {range}")
    ] = 2
    torque_Nm: Annotated[
        float, number_field(ge=1e-3, le=1e4, desc="torque at that current, {range}")
    ] = 2.0
    stator_steel_area_mm2: Annotated[
        float, number_field(ge=1, le=1e7, desc="stator steel area, {range}")
    ] = 1200.0
    stack_length_mm: Annotated[float, number_field(ge=1, le=1e4, desc="stack length, {range}")] = (
        50.0
    )
    stacking_factor: Annotated[
        float, number_field(ge=0.5, le=1, desc="steel fill of the stack, {range}")
    ] = 0.85
    steel_density_kg_m3: Annotated[
        float, number_field(ge=6000, le=9000, desc="steel density, {range}")
    ] = 7800.0
    steel_grade: Annotated[str, Field(description="GOST 21427.2-83 grade, e.g. 2413")] = "2413"
    steel_thickness_mm: Annotated[
        float, number_field(ge=0.05, le=2, desc="lamination thickness, {range}")
    ] = 0.35
    induction_T: Annotated[
        float, number_field(ge=0.1, le=2.5, desc="peak flux density, {range}")
    ] = 1.5
    iron_loss_model: Annotated[
        Literal["quadratic", "three_term"], Field(description="form of eq. (5) used")
    ] = "quadratic"
    magnet_losses: Annotated[
        list[MagnetLossPoint], Field(min_length=1, description="magnet losses at given speeds")
    ] = [  # noqa: RUF012 - pydantic copies field defaults
        MagnetLossPoint.model_construct(speed_rpm=5000.0, loss_W=60.0),
        MagnetLossPoint.model_construct(speed_rpm=10000.0, loss_W=100.0),
    ]

    _one_loss_per_speed = after_check(requirement_checks.one_loss_per_speed)


class BldcMotorReq(StrictModel):
    kind: Annotated[Literal["bldc"], Field(description="motor type")]
    frame: Annotated[
        str,
        ask(
            "the motor frame: reference (the [motor.reference] frame, seed 000's unless "
            "given), auto (the smallest of seed 000's scaled series BL037x025 … BL280x189, "
            "or of a catalog's bldc_motors.toml, whose losses and duty pass), or a frame's "
            "name (BL098x066) or a catalog motor's",
            label="Motor frame",
            step=3,
            min_length=1,
            max_length=60,
        ),
    ] = "reference"
    candidate_speeds_rpm: Annotated[
        list[
            Annotated[
                float,
                number_field(
                    **MOTOR_SPEED_RPM,
                    desc="a motor speed, " + range_prose("rpm", **MOTOR_SPEED_RPM),
                ),
            ]
        ],
        ask(
            "motor speeds to compare, {range} each, each once, at most 20",
            label="Motor speeds to compare",
            step=3,
            unique_items=True,
            min_length=1,
            max_length=20,
        ),
    ] = [5000.0, 10000.0]  # noqa: RUF012 - pydantic copies field defaults
    phases: Annotated[int, Field(ge=3, le=3, description="number of phases")] = 3
    max_losses_W: Annotated[
        float | None,
        number_field(
            ge=0.1,
            le=1e6,
            desc="total losses the motor's cooling carries away, {range}; by default the "
            "reference motor's own total losses at its rated point (same frame, same cooling)",
        ),
    ] = None
    reference: ReferenceMotor = ReferenceMotor.model_construct()

    _each_speed_once = field_check("candidate_speeds_rpm", requirement_checks.each_speed_once)


class GearboxReq(StrictModel):
    rolling_body: Annotated[
        Literal["ball", "roller"], ask("rolling bodies", label="Rolling bodies", step=3)
    ] = "ball"
    stage_efficiency: Annotated[
        float,
        number_field(
            ge=0.3,
            le=1,
            desc="efficiency of one stage, {range}",
            label="Efficiency of one stage",
            step=3,
        ),
    ] = 0.9
    density_kg_m3: Annotated[
        float, number_field(ge=1000, le=2e4, desc="material density, {range}")
    ] = 7800.0
    fill_factor: Annotated[float, number_field(ge=0.1, le=1, desc="k_з of eq. (19), {range}")] = (
        0.75
    )
    choice: Annotated[
        Literal["rules", "lightest", "slimmest"],
        ask(
            "the reducer the design takes: the seed's rules (WG-02, WG-03), or the lightest or "
            "the slimmest of the design space within the envelope",
            label="Reducer taken",
            step=3,
        ),
    ] = "rules"


class RotaryOneWayReq(OneWayReq):
    """The holding device of a rotary drive: also where it sits (seed 004)."""

    location: Annotated[
        Literal["motor_side", "output_side"],
        ask(
            "where the one-way device sits: at the motor side, where the torque is least "
            "(rule OW-01), or at the output",
            label="One-way device at",
            step=2,
        ),
    ] = "motor_side"


class RotaryRequirements(StrictModel):
    """A rotary actuator: PM brushless motor + wave-gear reducer with rolling bodies."""

    application: ApplicationReq
    project: ProjectField = None  # the datasheet's header (advisor.core.requirements)
    rotary: Annotated[RotaryReq, Field(description="the [rotary] table: torque_Nm, speed_rpm")]
    # defaults made without validation (they are valid): a nested model builds no validator
    # of its own (defer_build), and validating one here would build it at import (the batch path
    # must stay light)
    envelope: EnvelopeReq = EnvelopeReq.model_construct()
    motor: Annotated[BldcMotorReq, Field(description="the [motor] table: kind = 'bldc'")]
    gearbox: GearboxReq = GearboxReq.model_construct()
    one_way: RotaryOneWayReq = RotaryOneWayReq.model_construct()
    design: RotaryDesignReq = RotaryDesignReq.model_construct()
    output_load: Annotated[
        OutputLoadReq | None,
        Field(description="the [output_load] table: radial_N, axial_N, tilting_moment_Nm"),
    ] = None
    drive: DriveReq = DriveReq.model_construct()
    duty: Annotated[
        RotaryDutyReq | None,
        Field(description="the [duty] table: segments with cycles_per_hour, or duty_type"),
    ] = None

    _reducer_reduces = after_check(requirement_checks.reducer_reduces)
