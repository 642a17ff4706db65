"""Reading a requirement file: the one path production and the tests read through.

A valid file of plain numbers — what a batch run nearly always reads — is validated by
:mod:`advisor.core.compiled_validator` without importing pydantic. Anything else (a refusal, a
number with a unit, an application defined outside the shipped ones) is validated by the
requirement models themselves (:func:`advisor.core.requirements.validate_with_models`), which
word every message: a user never reads a message of the compiled validator.

``compiled=False`` skips the compiled validator: the models alone validate, as they do for
every file the compiled validator does not accept (a test compares the two that way).
"""

from pathlib import Path
from typing import Any

from advisor.core.io_safety import read_toml

#: A validated requirement: records of :mod:`advisor.core.compiled_validator`, or the
#: pydantic models.
Requirements = Any


def compiled_or_none(data: dict[str, Any]) -> Requirements | None:
    """The requirement as records of the compiled validator, or None where the models must
    validate it (and word what is wrong): a document the compiled validator does not accept,
    or one that contradicts itself (:func:`advisor.core.ignored.contradictions`)."""
    from advisor.core import compiled_validator
    from advisor.core.ignored import contradictions
    from advisor.core.units import convert_by_spec

    data = convert_by_spec(data)  # "5 kN" → 5000.0 without the models, where the spec can
    req = compiled_validator.validate(data)
    return None if req is None or contradictions(data) else req


def parse_requirements(data: dict[str, Any], *, compiled: bool = True) -> Requirements:
    """Validate a requirement document; every failure is an :class:`InputError` naming the
    field, the value and what is allowed. ``compiled=False``: by the models alone."""
    req = compiled_or_none(data) if compiled else None
    if req is not None:
        return req
    from advisor.core.requirements import validate_with_models

    return validate_with_models(data)


def read_requirements(path: Path, *, compiled: bool = True) -> Requirements:
    """Read and validate a requirement file (reading itself is
    :func:`advisor.core.io_safety.read_toml`: regular files of at most 1 MiB, no deep nesting)."""
    return parse_requirements(read_toml(path), compiled=compiled)
