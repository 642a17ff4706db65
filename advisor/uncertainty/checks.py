"""The [uncertainty] table's own rules, free of pydantic (run by the requirement model and by
the compiled validator of the batch path). Each raises ValueError with the message the user
reads."""

from typing import Any


def distribution_complete(d: Any) -> None:
    """Each distribution has the parameters it needs, in order, and no others."""
    need = {"uniform": ("low", "high"), "normal": ("sd",), "triangular": ("low", "high")}
    allowed = {
        "uniform": ("low", "high"),
        "normal": ("sd", "mean"),
        "triangular": ("low", "high", "mode"),
    }
    where = f"uncertainty.inputs ({d.name})"
    missing = [k for k in need[d.distribution] if getattr(d, k) is None]
    if missing:
        raise ValueError(f"{where}: distribution = {d.distribution!r} needs {missing[0]}")
    extra = [
        k
        for k in ("low", "high", "sd", "mean", "mode")
        if getattr(d, k) is not None and k not in allowed[d.distribution]
    ]
    if extra:
        raise ValueError(
            f"{where}: {extra[0]} is given but distribution = {d.distribution!r} does not use it"
        )
    if d.low is not None and d.high is not None and not d.low < d.high:
        raise ValueError(f"{where}: low = {d.low:g} must be below high = {d.high:g}")
    if d.mode is not None and not d.low <= d.mode <= d.high:
        raise ValueError(f"{where}: mode = {d.mode:g} must lie within low … high")


def unique_inputs(u: Any) -> None:
    names = [d.name for d in u.inputs]
    for n in names:
        if names.count(n) > 1:
            raise ValueError(f"uncertainty.inputs: {n} is given twice")
