"""Requirements of the spinning-rotor drive (seed 002): an idling high-speed rotor whose
bearings carry the gyroscopic reaction when its housing is turned."""

from typing import Annotated, Any

from pydantic import Field

from advisor.applications.spinning_rotor import requirement_checks
from advisor.applications.spinning_rotor.requirement_checks import (
    MIN_SLEW_RATE_rad_s,
    RotorDerived,
)
from advisor.core.ranges import range_prose
from advisor.core.requirements import (
    RANGE,
    ApplicationReq,
    ProjectField,
    StrictModel,
    after_check,
    ask,
    field_check,
    number_field,
)


def _rng(lo: float, hi: float, desc: str, **question: Any) -> Any:
    """A number in [lo, hi], the range stated in the description (in the words of its
    constraint, :data:`advisor.core.requirements.RANGE`) so that an error names it: the ranges
    bound what the advisor treats as a physical rotor. ``question``: the wizard's metadata, as
    for :func:`advisor.core.requirements.ask`."""
    return number_field(ge=lo, le=hi, desc=f"{desc}; {RANGE}", **question)


#: The fastest slew of the housing, rad/s (its slowest but none: MIN_SLEW_RATE_rad_s).
MAX_SLEW_RATE_rad_s = 100.0


class AeroReq(StrictModel):
    """Aerodynamic drag of eq. (5): either the cup geometry or a known loss at the speed."""

    loss_W: Annotated[
        float | None,
        _rng(
            0,
            1e6,
            "aerodynamic loss at the design speed, W",
            label="Aerodynamic loss at speed",
            step=2,
        ),
    ] = None
    outer_radius_mm: Annotated[
        float | None,
        _rng(
            1, 2000, "outer radius of the rotor cup R_o, mm", label="…or cup outer radius", step=2
        ),
    ] = None
    outer_length_mm: Annotated[
        float | None,
        _rng(
            0,
            5000,
            "length of the cup's outer surface l_o, mm",
            label="…and cup outer length",
            step=2,
        ),
    ] = None
    inner_radius_mm: Annotated[float, _rng(0, 2000, "inner radius of the cup R_i, mm")] = 0.0
    inner_length_mm: Annotated[
        float, _rng(0, 5000, "length of the cup's inner surface l_i, mm")
    ] = 0.0
    air_density_kg_m3: Annotated[
        float, _rng(1e-3, 50, "density of the gas around the rotor ρ, kg/m³")
    ] = 1.204
    air_viscosity_m2_s: Annotated[
        float, _rng(1e-6, 0.1, "kinematic viscosity of that gas ν, m²/s")
    ] = 1.516e-5

    _one_way = after_check(requirement_checks.aero_one_way)


class RotorReq(RotorDerived, StrictModel):
    mass_kg: Annotated[float, _rng(1e-3, 1e4, "rotor mass, kg", label="Rotor mass", step=1)]
    angular_momentum_kgm2_s: Annotated[
        float | None,
        _rng(1e-6, 1e6, "kinetic moment H at speed, kg·m²/s", label="Kinetic moment H", step=1),
    ] = None
    inertia_kgm2: Annotated[
        float | None,
        _rng(1e-9, 1e4, "axial moment of inertia J, kg·m²", label="…or axial inertia J", step=1),
    ] = None
    speed_rad_s: Annotated[
        float, _rng(10, 2e4, "design speed ω, rad/s", label="Design speed", step=1)
    ]
    bearing: Annotated[
        str,
        ask(
            "bearing designation, e.g. 7000 CD",
            label="Bearing (SKF designation)",
            step=3,
            example="7000 CD",
            min_length=1,
            max_length=40,
        ),
    ]
    bearing_count: Annotated[
        int,
        ask(f"bearings carrying the rotor; {RANGE}", label="Bearings", step=3, ge=2, le=8),
    ] = 2
    ball_plane_to_cg_mm: Annotated[
        float,
        _rng(
            0.1,
            2000,
            "distance h from the ball plane to the centre of mass, mm",
            label="Ball plane to centre of mass h",
            step=1,
        ),
    ]
    slew_rate_rad_s: Annotated[
        float,
        number_field(
            ge=0,
            le=MAX_SLEW_RATE_rad_s,
            desc="external angular velocity Ω of the housing, rad/s; 0 (no slew) or "
            + range_prose("rad/s", ge=MIN_SLEW_RATE_rad_s, le=MAX_SLEW_RATE_rad_s),
            label="Slew rate of the housing Ω",
            step=1,
        ),
    ]
    axis_angle_deg: Annotated[float, _rng(0, 180, "angle α between H and Ω, degrees")] = 90.0
    slew_angle_deg: Annotated[
        float,
        _rng(
            0.01,
            36000,
            "angle the housing turns through in one slew, degrees",
            label="Angle of one slew",
            step=1,
        ),
    ] = 90.0
    run_up_time_s: Annotated[
        float,
        _rng(0.1, 1e5, "required time to reach speed, s", label="Required run-up time", step=1),
    ]
    rolling_friction_mm: Annotated[
        float,
        _rng(
            1e-3,
            1,
            "rolling friction coefficient λ of eq. (4), mm",
            label="Rolling friction λ",
            step=3,
        ),
    ] = 0.028
    contact_angle_deg: Annotated[
        float | None,
        _rng(
            5,
            45,
            "operating contact angle β under preload, degrees",
            label="Operating contact angle (deep groove)",
            step=3,
        ),
    ] = None
    lubricant_viscosity_mm2_s: Annotated[
        float, _rng(0.5, 5000, "oil viscosity at operating temperature, mm²/s")
    ] = 10.0
    required_life_h: Annotated[
        float | None,
        _rng(1, 1e7, "required basic rating life L10h, h", label="Required life L10h", step=3),
    ] = None
    aero: Annotated[AeroReq, Field(description="the [rotor.aero] table: loss_W or cup geometry")]

    _slew_or_none = field_check("slew_rate_rad_s", requirement_checks.slew_or_none)

    _momentum_or_inertia = after_check(requirement_checks.momentum_or_inertia)


class SpinningRotorRequirements(StrictModel):
    """An idling high-speed rotor: bearing losses under the gyroscopic reaction and the drive
    torque that brings it to speed in time."""

    application: ApplicationReq
    project: ProjectField = None  # the datasheet's header (advisor.core.requirements)
    rotor: Annotated[
        RotorReq,
        Field(
            description="the [rotor] table: mass_kg, speed_rad_s, bearing, "
            "ball_plane_to_cg_mm, slew_rate_rad_s, run_up_time_s, [rotor.aero]"
        ),
    ]
