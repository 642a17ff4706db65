"""Reading a requirement file: the compiled validator first, the pydantic models for the rest.

A valid file of plain numbers — what a batch run nearly always reads — is validated by
:mod:`advisor.core.compiled_validator` without importing pydantic. Anything else (a refusal, a
number with
a unit, an application defined outside the shipped ones) is validated by the requirement
models themselves (:func:`advisor.core.requirements.parse_requirements`), which word every
message: a user never reads a message of the compiled validator.
"""

from pathlib import Path
from typing import Any

from advisor.core.io_safety import read_toml

#: A validated requirement: records of :mod:`advisor.core.compiled_validator`, or the
#: pydantic models.
Requirements = Any


def parse_requirements(data: dict[str, Any]) -> Requirements:
    """Validate a requirement document; every failure is an :class:`InputError` naming the
    field, the value and what is allowed."""
    from advisor.core import compiled_validator

    req = compiled_validator.validate(data)
    if req is not None:
        return req
    from advisor.core.requirements import parse_requirements as by_models

    return by_models(data)


def read_requirements(path: Path) -> Requirements:
    """Read and validate a requirement file (reading itself is
    :func:`advisor.core.io_safety.read_toml`: regular files of at most 1 MiB, no deep nesting)."""
    return parse_requirements(read_toml(path))
