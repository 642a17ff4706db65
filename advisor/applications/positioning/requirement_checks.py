"""The positioning requirement's own rules, free of pydantic: run by the requirement models
(:mod:`advisor.applications.positioning.requirements`) and by the compiled validator of the
batch path (:mod:`advisor.core.compiled_validator`). Each raises ValueError with the message the
user reads."""

from typing import Any

from advisor.core.ranges import zero_or_from

#: The smallest non-zero load inertia and load torque taken as a load; below them the value
#: is either 0 (no such load) or a typing error.
LOAD_INERTIA_MIN_KGM2 = 1e-9
LOAD_TORQUE_MIN_NM = 1e-6


def inertia_zero_or_range(v: float) -> float:
    return zero_or_from(v, LOAD_INERTIA_MIN_KGM2, "1e+07 kg·m²")


def torque_zero_or_range(v: float) -> float:
    return zero_or_from(v, LOAD_TORQUE_MIN_NM, "1e+07 N·m")


def unique_names(pos: Any) -> None:
    if pos.load_inertia_kgm2 == 0 and pos.load_torque_Nm == 0:
        raise ValueError(
            "positioning.load_inertia_kgm2 and positioning.load_torque_Nm are both 0: "
            "with no load the fastest ratio tends to zero; give the load's inertia or torque"
        )
    names = [m.name for m in pos.motors]
    dup = {n for n in names if names.count(n) > 1}
    if dup:
        raise ValueError(f"positioning.motors: the name {sorted(dup)[0]!r} is used twice")


def rated_for_duty(req: Any) -> None:
    if req.duty is not None:
        for k, m in enumerate(req.positioning.motors, 1):
            if m.rated_torque_Nm is None:
                raise ValueError(
                    f"positioning.motors[{k}].rated_torque_Nm: missing; required when "
                    "[duty] is given (continuous (S1) torque, N·m)"
                )


def time_or_motors(req: Any) -> None:
    """Without listed motors the catalog is searched for the smallest motor that meets a
    required time (MO-05): a required time is needed, the move's own or the duty cycle's,
    else "the fastest move wins" would crown the largest motor of the catalog."""
    pos = req.positioning
    if not pos.motors and pos.move_time_s is None and req.duty is None:
        raise ValueError(
            "positioning.move_time_s: missing; required without [[positioning.motors]] (the "
            "advisor chooses the smallest catalog motor that moves the load within it), or "
            "list the candidate motors"
        )
