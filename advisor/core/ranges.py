"""Ranges the requirement models' constraints cannot state alone, free of pydantic (used by
the ``requirement_checks`` modules of the applications and the duty)."""


def zero_or_from(v: float | None, least: float, upto: str) -> float | None:
    """``v`` if it is None, 0 (no such load) or at least ``least``; below that, a ValueError
    worded "must be 0 or from {least} to {upto}" (``upto``: the upper limit with its unit)."""
    if v is not None and 0 < v < least:
        raise ValueError(f"must be 0 or from {least:g} to {upto}")
    return v
