"""Requirements of the positioning drive (seed 003): the fastest move through a reducer.

Every number has a physically meaningful range, stated in its description; a value outside it
is an input error naming the field and the range (exit 2). The ranges keep every quantity the
advice computes finite: the ratios searched are 10⁻³ … 10⁶ (advisor/calc/motion.py)."""

from typing import Annotated, Literal

from pydantic import Field, field_validator, model_validator

from advisor.core.requirements import ApplicationReq, _num, _Strict, ask
from advisor.duty.requirements import PositioningDutyReq

#: The smallest non-zero load inertia and load torque taken as a load; below them the value
#: is either 0 (no such load) or a typing error.
LOAD_INERTIA_MIN_KGM2 = 1e-9
LOAD_TORQUE_MIN_NM = 1e-6


class CandidateMotor(_Strict):
    name: Annotated[
        str, ask("a label for the motor", label="name", step=3, min_length=1, max_length=60)
    ]
    speed_rad_s: Annotated[
        float,
        _num(
            ge=0.1,
            le=1e4,
            desc="rated speed ω0, 0.1 … 10⁴ rad/s (about 1 … 95 000 rpm)",
            label="speed ω0",
            step=3,
        ),
    ]
    inertia_kgm2: Annotated[
        float,
        _num(
            ge=1e-9,
            le=1e3,
            desc="motor and coupling inertia J0, 10⁻⁹ … 10³ kg·m²",
            label="inertia J0",
            step=3,
        ),
    ]
    accel_torque_Nm: Annotated[
        float,
        _num(
            ge=1e-5,
            le=1e6,
            desc="starting and braking torque M_λ, 10⁻⁵ … 10⁶ N·m",
            label="start/brake torque M_λ",
            step=3,
        ),
    ]
    rated_torque_Nm: Annotated[
        float | None,
        _num(
            gt=0,
            le=1e6,
            desc="continuous (S1) torque, N·m; required when [duty] is given",
            label="rated torque",
            step=3,
        ),
    ] = None


class PositioningReq(_Strict):
    profile: Annotated[
        Literal["trapezoidal", "triangular"],
        ask("speed graph expected", label="Speed graph", step=1),
    ] = "trapezoidal"
    travel_rad: Annotated[
        float,
        _num(
            ge=1e-4,
            le=1e5,
            desc="path of the load shaft α, 10⁻⁴ … 10⁵ rad (0.006° to about 16 000 turns)",
            label="Path of the load shaft",
            step=1,
        ),
    ]
    load_inertia_kgm2: Annotated[
        float,
        _num(
            ge=0,
            le=1e7,
            desc="load inertia J_p, 0 (none) or 10⁻⁹ … 10⁷ kg·m²",
            label="Load inertia",
            step=1,
        ),
    ]
    load_torque_Nm: Annotated[
        float,
        _num(
            ge=0,
            le=1e7,
            desc="load torque M_p, 0 (none) or 10⁻⁶ … 10⁷ N·m",
            label="Load torque",
            step=1,
        ),
    ]
    motors: Annotated[
        list[CandidateMotor],
        ask(
            "candidate motors; none: the induction catalog",
            max_length=200,
            extra={"row-label": "Motor"},
        ),
    ] = []  # noqa: RUF012 - pydantic copies field defaults

    @field_validator("load_inertia_kgm2")
    @classmethod
    def _inertia_zero_or_range(cls, v: float) -> float:
        if 0 < v < LOAD_INERTIA_MIN_KGM2:
            raise ValueError(f"must be 0 or from {LOAD_INERTIA_MIN_KGM2:g} to 1e+07 kg·m²")
        return v

    @field_validator("load_torque_Nm")
    @classmethod
    def _torque_zero_or_range(cls, v: float) -> float:
        if 0 < v < LOAD_TORQUE_MIN_NM:
            raise ValueError(f"must be 0 or from {LOAD_TORQUE_MIN_NM:g} to 1e+07 N·m")
        return v

    @model_validator(mode="after")
    def _unique_names(self) -> "PositioningReq":
        if self.load_inertia_kgm2 == 0 and self.load_torque_Nm == 0:
            raise ValueError(
                "positioning.load_inertia_kgm2 and positioning.load_torque_Nm are both 0: "
                "with no load the fastest ratio tends to zero; give the load's inertia or torque"
            )
        names = [m.name for m in self.motors]
        dup = {n for n in names if names.count(n) > 1}
        if dup:
            raise ValueError(f"positioning.motors: the name {sorted(dup)[0]!r} is used twice")
        return self


class PositioningRequirements(_Strict):
    """A positioning drive: which motor and which ratio make the move fastest."""

    application: ApplicationReq
    positioning: Annotated[
        PositioningReq,
        Field(description="the [positioning] table: travel_rad, load_inertia_kgm2, load_torque_Nm"),
    ]
    duty: Annotated[
        PositioningDutyReq | None,
        Field(description="the [duty] table: cycle_time_s (optional: the move repeated)"),
    ] = None

    @model_validator(mode="after")
    def _rated_for_duty(self) -> "PositioningRequirements":
        if self.duty is not None:
            for k, m in enumerate(self.positioning.motors, 1):
                if m.rated_torque_Nm is None:
                    raise ValueError(
                        f"positioning.motors[{k}].rated_torque_Nm: missing; required when "
                        "[duty] is given (continuous (S1) torque, N·m)"
                    )
        return self
