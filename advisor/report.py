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


class NutOut(_Out):
    height_mm: float
    turns: float
    height_ratio: float
    bearing_pressure_MPa: float
    allowable_pressure_MPa: float


class BucklingOut(_Out):
    formula: str
    end_fixity: str
    effective_length_factor: float
    slenderness: float
    critical_load_N: float
    safety_factor_required: float


class ScrewOut(_Out):
    thread: str
    imposed: bool
    advisor_choice: str | None = None
    nominal_diameter_mm: float
    pitch_mm: float
    preferred_pitch: bool
    starts: int
    lead_mm: float
    d2_mm: float
    d3_mm: float
    D1_mm: float
    D2_mm: float
    D4_mm: float
    ac_mm: float
    H1_mm: float
    h3_mm: float
    material_pair: str
    lubrication: str
    screw_steel: str
    friction_model: str
    friction_coefficient: float
    friction_range: list[float]
    lead_angle_deg: float
    friction_angle_deg: float
    torque_Nm: float
    torque_standard_Nm: float
    torque_paper_Nm: float
    efficiency: float
    back_driving_efficiency: float
    self_locking: bool
    self_locking_at_low_friction: bool
    linear_speed_m_s: float
    revolutions: float
    speed_rpm: float
    output_power_W: float
    nut: NutOut
    buckling: BucklingOut


class CurveOut(_Out):
    slip: list[float]
    speed_rpm: list[float]
    torque_Nm: list[float]


class MotorCandidateOut(_Out):
    role: str
    rated_power_kW: float
    model: str | None = None
    in_catalog: bool
    rated_speed_rpm: float | None = None
    rated_torque_Nm: float | None = None
    max_torque_Nm: float | None = None
    starting_torque_Nm: float | None = None
    critical_slip: float | None = None
    kloss_epsilon: float | None = None
    working_speed_rpm: float | None = None
    torque_at_required_speed_Nm: float | None = None
    rated_torque_margin: float | None = None
    starting_torque_margin: float | None = None
    breakdown_torque_margin: float | None = None
    travel_time_s: float | None = None
    suitable: bool
    problems: list[str] = []
    curve: CurveOut | None = None


class InductionMotorOut(_Out):
    kind: str
    supply_frequency_Hz: float
    speed_rpm: float
    pole_pairs: int
    synchronous_speed_rpm: float
    required_torque_Nm: float
    required_power_kW: float
    rated_power_kW: float
    model: str
    rated_speed_rpm: float
    rated_torque_Nm: float
    working_speed_rpm: float
    working_slip: float
    working_power_kW: float
    travel_time_s: float
    efficiency_pct: float
    cos_phi: float
    starting_current_ratio: float
    inertia_kgm2: float
    mass_kg: float
    estimated: list[str]
    source: str
    candidates: list[MotorCandidateOut]


class LinearDesignOut(_Out):
    screw: ScrewOut
    motor: InductionMotorOut
    one_way: "OneWayOut | None" = None


class ReportHeader(_Out):
    format: int = REPORT_FORMAT
    advisor_version: str
    application: str
    title: str = ""
    status: str = "feasible"


class Report(_Out):
    report: ReportHeader
    requirements: dict[str, Any]
    design: Any  # LinearDesignOut, or RotaryDesignOut from advisor.rotary_report
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


class DeviceOut(_Out):
    type: str
    location: str
    torque_Nm: float
    outer_diameter_mm: float
    length_mm: float
    mass_kg: float
    inertia_kgm2: float
    efficiency: float
    power_W: float
    basis: str


class OneWayOut(_Out):
    type: str
    location: str
    torque_Nm: float
    outer_diameter_mm: float | None = None
    length_mm: float | None = None
    mass_kg: float | None = None
    inertia_kgm2: float | None = None
    efficiency: float | None = None
    power_W: float | None = None
    power_share: float | None = None
    basis: str = ""
    output_side: DeviceOut | None = None
    alternatives: list[DeviceOut] = []
