"""The design report: a pydantic model, dumped to TOML with tomli-w and written atomically.

Stable keys (other tools read them) are documented in README.md. Floats are rounded to
six significant digits so that two runs of the same input give byte-identical files and a
changed input shows as a readable diff.
"""

import math
from typing import Any

import tomli_w
from pydantic import BaseModel, ConfigDict

from advisor.io_safety import write_atomic as write_atomic  # re-exported: the report writer

REPORT_FORMAT = 1


class _Out(BaseModel):
    """Report tables. The engine builds them from values it computed, so they are made with
    :meth:`make` (no validation) and dumped by :func:`_plain`; building pydantic's validator
    and serializer for a dozen classes would cost more than the whole advice."""

    model_config = ConfigDict(extra="forbid", defer_build=True)

    @classmethod
    def make(cls, **values: Any):
        unknown = set(values) - set(cls.model_fields)
        if unknown:
            raise TypeError(f"{cls.__name__}: unknown fields {sorted(unknown)}")
        missing = {n for n, f in cls.model_fields.items() if f.is_required() and n not in values}
        if missing:
            raise TypeError(f"{cls.__name__}: missing fields {sorted(missing)}")
        return cls.model_construct(**values)


class CheckOut(_Out):
    id: str
    name: str
    value: float
    limit: float
    unit: str
    margin: float
    passed: bool
    source: str


class DecisionOut(_Out):
    id: str
    title: str
    decision: str
    rationale: str
    source: str
    inputs: dict[str, Any] = {}


class ReportHeader(_Out):
    format: int = REPORT_FORMAT
    advisor_version: str
    application: str
    title: str = ""
    status: str = "feasible"


class Report(_Out):
    report: ReportHeader
    requirements: dict[str, Any]
    design: Any  # LinearDesignOut, or RotaryDesignOut from advisor.applications.rotary.report
    checks: list[CheckOut]
    warnings: list[str] = []
    decisions: list[DecisionOut]


def round_sig(x: float, digits: int = 6) -> float:
    """Round to significant digits, for stable, diffable reports.

    >>> round_sig(5.084934), round_sig(0.000123456789), round_sig(1200.0)
    (5.08493, 0.000123457, 1200.0)
    """
    if x == 0 or not math.isfinite(x):
        return x
    return round(x, digits - 1 - math.floor(math.log10(abs(x))))


def _plain(obj: Any) -> Any:
    """Plain dicts and lists of a report, without None (TOML has no null), floats rounded
    to six significant digits, fields in their declared order."""
    if isinstance(obj, BaseModel):
        return {
            name: _plain(getattr(obj, name))
            for name in type(obj).model_fields
            if getattr(obj, name) is not None
        }
    if isinstance(obj, float):
        return round_sig(obj)
    if isinstance(obj, bool | int | str):
        return obj
    if isinstance(obj, dict):
        return {str(k): _plain(v) for k, v in obj.items() if v is not None}
    if isinstance(obj, list | tuple):
        return [_plain(v) for v in obj if v is not None]
    raise TypeError(f"a report cannot hold {type(obj).__name__}: {obj!r}")


def to_toml(report: Report) -> str:
    """The report as TOML text (no nulls: TOML has none)."""
    return tomli_w.dumps(_plain(report))
