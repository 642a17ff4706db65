"""Requirements of the positioning drive (seed 003): the fastest move through a reducer."""

from typing import Annotated, Literal

from pydantic import Field, model_validator

from advisor.core.requirements import ApplicationReq, _num, _Strict, ask
from advisor.duty.requirements import PositioningDutyReq


class CandidateMotor(_Strict):
    name: Annotated[
        str, ask("a label for the motor", label="name", step=3, min_length=1, max_length=60)
    ]
    speed_rad_s: Annotated[
        float, _num(gt=0, le=1e5, desc="rated speed ω0, rad/s", label="speed ω0", step=3)
    ]
    inertia_kgm2: Annotated[
        float,
        _num(gt=0, le=1e4, desc="motor and coupling inertia J0, kg·m²", label="inertia J0", step=3),
    ]
    accel_torque_Nm: Annotated[
        float,
        _num(
            gt=0,
            le=1e6,
            desc="starting and braking torque M_λ, N·m",
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
            gt=0,
            le=1e6,
            desc="path of the load shaft α, rad",
            label="Path of the load shaft",
            step=1,
        ),
    ]
    load_inertia_kgm2: Annotated[
        float, _num(ge=0, le=1e7, desc="load inertia J_p, kg·m²", label="Load inertia", step=1)
    ]
    load_torque_Nm: Annotated[
        float, _num(ge=0, le=1e7, desc="load torque M_p, N·m", label="Load torque", step=1)
    ]
    motors: Annotated[
        list[CandidateMotor],
        ask(
            "candidate motors; none: the induction catalog",
            max_length=200,
            extra={"row-label": "Motor"},
        ),
    ] = []  # noqa: RUF012 - pydantic copies field defaults

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
