"""Requirements of the rotary actuator (seed 000): PM brushless motor + wave-gear reducer.

Kept apart from :mod:`advisor.core.requirements` so the linear batch path never builds these
validators.
"""

from typing import Annotated, Literal

from pydantic import Field, model_validator

from advisor.core.requirements import ApplicationReq, OneWayReq, _num, _Strict, ask
from advisor.duty.requirements import RotaryDutyReq


class RotaryReq(_Strict):
    torque_Nm: Annotated[
        float, _num(gt=0, le=1e6, desc="peak output torque, N·m", label="Output torque", step=1)
    ]
    speed_rpm: Annotated[
        float, _num(gt=0, le=1e4, desc="maximum output speed, rpm", label="Output speed", step=1)
    ]


class EnvelopeReq(_Strict):
    max_outer_diameter_mm: Annotated[
        float | None,
        _num(
            gt=0,
            le=1e4,
            desc="largest outer diameter of the reducer, mm",
            label="Largest reducer diameter",
            step=2,
        ),
    ] = None
    max_length_mm: Annotated[
        float | None,
        _num(
            gt=0,
            le=1e5,
            desc="largest length of the reducer, mm",
            label="Largest reducer length",
            step=2,
        ),
    ] = None


class MagnetLossPoint(_Strict):
    speed_rpm: Annotated[float, _num(gt=0, le=2e5, desc="motor speed, rpm")]
    loss_W: Annotated[float, _num(ge=0, le=1e6, desc="eddy-current loss in the magnets, W")]


class ReferenceMotor(_Strict):
    """The design the loss model scales from; the defaults are the seed 000 motor."""

    speed_rpm: Annotated[float, _num(gt=0, le=2e5, desc="speed of the reference design, rpm")] = (
        5000.0
    )
    pole_pairs: Annotated[int, Field(ge=1, le=100, description="electrical reduction p")] = 6
    phase_resistance_ohm: Annotated[float, _num(gt=0, le=1e3, desc="phase resistance, Ω")] = 1.14
    current_A: Annotated[float, _num(gt=0, le=1e4, desc="phase current, A")] = 5.5
    conducting_phases: Annotated[int, Field(ge=1, le=3, description="phases in series")] = 2
    torque_Nm: Annotated[float, _num(gt=0, le=1e4, desc="torque at that current, N·m")] = 2.0
    stator_steel_area_mm2: Annotated[float, _num(gt=0, le=1e7, desc="stator steel area, mm²")] = (
        1200.0
    )
    stack_length_mm: Annotated[float, _num(gt=0, le=1e4, desc="stack length, mm")] = 50.0
    stacking_factor: Annotated[float, _num(gt=0, le=1, desc="steel fill of the stack")] = 0.85
    steel_density_kg_m3: Annotated[float, _num(gt=0, le=2e4, desc="steel density, kg/m³")] = 7800.0
    steel_grade: Annotated[str, Field(description="GOST 21427.2-83 grade, e.g. 2413")] = "2413"
    steel_thickness_mm: Annotated[float, _num(gt=0, le=2, desc="lamination thickness, mm")] = 0.35
    induction_T: Annotated[float, _num(gt=0, le=2.5, desc="peak flux density, T")] = 1.5
    iron_loss_model: Annotated[
        Literal["quadratic", "three_term"], Field(description="form of eq. (5) used")
    ] = "quadratic"
    magnet_losses: Annotated[
        list[MagnetLossPoint], Field(min_length=1, description="magnet losses at given speeds")
    ] = [  # noqa: RUF012 - pydantic copies field defaults
        MagnetLossPoint(speed_rpm=5000.0, loss_W=60.0),
        MagnetLossPoint(speed_rpm=10000.0, loss_W=100.0),
    ]

    @model_validator(mode="after")
    def _one_loss_per_speed(self) -> "ReferenceMotor":
        speeds = [p.speed_rpm for p in self.magnet_losses]
        if len(set(speeds)) < len(speeds):
            raise ValueError(
                "motor.reference.magnet_losses: two points at one speed_rpm; give one loss_W "
                "per speed"
            )
        return self


class BldcMotorReq(_Strict):
    kind: Annotated[Literal["bldc"], Field(description="motor type")]
    candidate_speeds_rpm: Annotated[
        list[Annotated[float, _num(gt=0, le=2e5)]],
        ask(
            "motor speeds to compare, rpm",
            label="Motor speeds to compare",
            step=3,
            min_length=1,
            max_length=20,
        ),
    ] = [5000.0, 10000.0]  # noqa: RUF012 - pydantic copies field defaults
    phases: Annotated[int, Field(ge=3, le=3, description="number of phases")] = 3
    max_losses_W: Annotated[
        float | None,
        _num(
            gt=0,
            le=1e6,
            desc="total losses the motor's cooling carries away, W; by default the reference "
            "motor's own total losses at its rated point (same frame, same cooling)",
        ),
    ] = None
    reference: ReferenceMotor = ReferenceMotor()


class GearboxReq(_Strict):
    rolling_body: Annotated[
        Literal["ball", "roller"], ask("rolling bodies", label="Rolling bodies", step=3)
    ] = "ball"
    stage_efficiency: Annotated[
        float,
        _num(gt=0.3, le=1, desc="efficiency of one stage", label="Efficiency of one stage", step=3),
    ] = 0.9
    density_kg_m3: Annotated[float, _num(gt=0, le=2e4, desc="material density, kg/m³")] = 7800.0
    fill_factor: Annotated[float, _num(gt=0, le=1, desc="k_з of eq. (19)")] = 0.75


class RotaryRequirements(_Strict):
    """A rotary actuator: PM brushless motor + wave-gear reducer with rolling bodies."""

    application: ApplicationReq
    rotary: Annotated[RotaryReq, Field(description="the [rotary] table: torque_Nm, speed_rpm")]
    envelope: EnvelopeReq = EnvelopeReq()
    motor: Annotated[BldcMotorReq, Field(description="the [motor] table: kind = 'bldc'")]
    gearbox: GearboxReq = GearboxReq()
    one_way: OneWayReq = OneWayReq()
    duty: Annotated[
        RotaryDutyReq | None,
        Field(description="the [duty] table: segments with cycles_per_hour, or duty_type"),
    ] = None

    @model_validator(mode="after")
    def _reducer_reduces(self) -> "RotaryRequirements":
        slowest = min(self.motor.candidate_speeds_rpm)
        if self.rotary.speed_rpm >= slowest:
            raise ValueError(
                f"rotary.speed_rpm = {self.rotary.speed_rpm:g} is not below the slowest "
                f"motor.candidate_speeds_rpm ({slowest:g}): the reducer lowers the speed"
            )
        return self
