"""Pydantic schemas that validate the catalog files (see :mod:`catalogs.loader`)."""

from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

Positive = Annotated[float, Field(gt=0, allow_inf_nan=False)]


class _Row(BaseModel):
    # defer_build: a run that finds the validated catalogs in the cache never pays for
    # building the validators.
    model_config = ConfigDict(extra="forbid", strict=True, frozen=True, defer_build=True)


# ---------------------------------------------------------------- threads (GOST 24738-81)
class ThreadPlanRow(_Row):
    d_mm: Positive
    series: Annotated[int, Field(ge=1, le=2)]
    pitches_mm: list[Positive]
    preferred_mm: Positive

    @model_validator(mode="after")
    def _preferred_is_listed(self) -> "ThreadPlanRow":
        if self.preferred_mm not in self.pitches_mm:
            raise ValueError(f"preferred_mm = {self.preferred_mm} is not among pitches_mm")
        if len(set(self.pitches_mm)) != len(self.pitches_mm):
            raise ValueError("pitches_mm lists a pitch twice")
        return self


# ---------------------------------------------------------------- induction motors
MOTOR_FIELDS = {
    "rated_speed_rpm",
    "slip_pct",
    "breakdown_torque_ratio",
    "starting_torque_ratio",
    "efficiency_pct",
    "cos_phi",
    "starting_current_ratio",
    "inertia_kgm2",
    "mass_kg",
}

#: |n − n₀·(1 − s)| allowed between a row's published speed and slip, as a share of n₀.
SPEED_SLIP_TOLERANCE = 0.015


class InductionMotor(_Row):
    model: Annotated[str, Field(min_length=1)]
    poles: int
    rated_power_kW: Positive
    rated_speed_rpm: Positive
    slip_pct: Annotated[float, Field(gt=0, lt=50, allow_inf_nan=False)]
    breakdown_torque_ratio: Annotated[float, Field(gt=1, le=5, allow_inf_nan=False)]
    starting_torque_ratio: Annotated[float, Field(gt=0, le=5, allow_inf_nan=False)]
    efficiency_pct: Annotated[float, Field(gt=0, lt=100, allow_inf_nan=False)]
    cos_phi: Annotated[float, Field(gt=0, le=1, allow_inf_nan=False)]
    starting_current_ratio: Annotated[float, Field(ge=1, le=15, allow_inf_nan=False)]
    inertia_kgm2: Positive
    mass_kg: Positive
    source: str
    estimated: list[str] = []
    supply_frequency_Hz: float = 50.0

    @model_validator(mode="after")
    def _consistent(self) -> "InductionMotor":
        if self.poles not in (2, 4, 6, 8):
            raise ValueError(f"poles = {self.poles}: allowed 2, 4, 6, 8")
        n0 = 120.0 * self.supply_frequency_Hz / self.poles
        if not self.rated_speed_rpm < n0:
            raise ValueError(
                f"rated_speed_rpm = {self.rated_speed_rpm} is not below the synchronous "
                f"speed {n0:g} rpm"
            )
        from_slip = n0 * (1.0 - self.slip_pct / 100.0)
        if abs(from_slip - self.rated_speed_rpm) > SPEED_SLIP_TOLERANCE * n0:
            raise ValueError(
                f"slip_pct = {self.slip_pct} gives {from_slip:.0f} rpm but rated_speed_rpm = "
                f"{self.rated_speed_rpm:g} (allowed difference {SPEED_SLIP_TOLERANCE:.1%} of "
                f"{n0:g} rpm)"
            )
        if self.starting_torque_ratio > self.breakdown_torque_ratio:
            raise ValueError(
                f"starting_torque_ratio = {self.starting_torque_ratio} exceeds "
                f"breakdown_torque_ratio = {self.breakdown_torque_ratio}"
            )
        unknown = set(self.estimated) - MOTOR_FIELDS
        if unknown:
            raise ValueError(f"estimated names unknown fields {sorted(unknown)}")
        return self


# ---------------------------------------------------------------- screw materials
class FrictionPair(_Row):
    name: str
    description: str
    f_oil: Annotated[list[Annotated[float, Field(gt=0, lt=1)]], Field(min_length=2, max_length=2)]
    f_dry: Annotated[list[Annotated[float, Field(gt=0, lt=1)]], Field(min_length=2, max_length=2)]
    allowable_pressure_MPa: Positive
    source: list[str]
    estimated: list[str] = []

    @model_validator(mode="after")
    def _ranges(self) -> "FrictionPair":
        for name in ("f_oil", "f_dry"):
            lo, hi = getattr(self, name)
            if lo > hi:
                raise ValueError(f"{name} = [{lo}, {hi}]: low end above high end")
        return self


class ScrewSteel(_Row):
    name: str
    yield_strength_MPa: Positive
    elastic_modulus_MPa: Positive
    source: list[str]


class NutRules(_Row):
    height_ratio_min: Positive
    height_ratio_max: Positive
    max_turns: Annotated[int, Field(ge=1)]
    source: list[str]


class StrengthRules(_Row):
    yield_safety_factor: Annotated[float, Field(ge=1)]
    source: list[str]


class MaterialsFile(_Row):
    sources: dict[str, Any]  # resolved against the bibliography by the loader
    pair: list[FrictionPair]
    steel: list[ScrewSteel]
    nut: NutRules
    strength: StrengthRules

    @model_validator(mode="after")
    def _sources_known(self) -> "MaterialsFile":
        for group in (self.pair, self.steel, [self.nut, self.strength]):
            for row in group:
                missing = set(row.source) - set(self.sources)
                if missing:
                    raise ValueError(f"source names {sorted(missing)} not in [sources]")
        return self


class ElectricalSteelRow(_Row):
    grade: Annotated[str, Field(pattern=r"^\d{4}$")]
    thickness_mm: Positive
    equivalent: str
    p10_50_W_kg: Positive
    p15_50_W_kg: Positive
    p10_400_W_kg: Positive
    source: list[str]
    estimated: list[str] = []

    @model_validator(mode="after")
    def _losses_consistent(self) -> "ElectricalSteelRow":
        if not self.p10_50_W_kg < self.p15_50_W_kg:
            raise ValueError(
                f"p15_50_W_kg = {self.p15_50_W_kg} must exceed p10_50_W_kg = {self.p10_50_W_kg}"
                " (losses rise with induction)"
            )
        if not self.p10_50_W_kg < self.p10_400_W_kg:
            raise ValueError(
                f"p10_400_W_kg = {self.p10_400_W_kg} must exceed p10_50_W_kg = "
                f"{self.p10_50_W_kg} (losses rise with frequency)"
            )
        unknown = set(self.estimated) - {"p10_50_W_kg", "p15_50_W_kg", "p10_400_W_kg"}
        if unknown:
            raise ValueError(f"estimated names unknown fields {sorted(unknown)}")
        return self


# ---------------------------------------------------------------- rolling bearings
class FrictionRow(_Row):
    R1: Positive
    R2: Positive
    S1: Positive
    S2: Positive
    R3: Annotated[float, Field(ge=0, allow_inf_nan=False)] = 0.0
    S3: Annotated[float, Field(ge=0, allow_inf_nan=False)] = 0.0
    source: str


BEARING_ESTIMABLE = {"C_kN", "C0_kN", "f0", "ball_count", "ball_diameter_mm", "pitch_diameter_mm"}


class BearingRow(_Row):
    designation: Annotated[str, Field(min_length=1, max_length=40)]
    type: Literal["angular_contact", "deep_groove"]
    friction: str
    d_mm: Positive
    D_mm: Positive
    B_mm: Positive
    contact_angle_deg: Annotated[float, Field(ge=0, lt=90, allow_inf_nan=False)]
    C_kN: Positive
    C0_kN: Positive
    Pu_kN: Positive | None = None
    reference_speed_rpm: Positive | None = None
    limiting_speed_rpm: Positive
    mass_kg: Positive | None = None
    f0: Positive | None = None
    ball_count: Annotated[int, Field(ge=3, le=200)] | None = None
    ball_diameter_mm: Positive | None = None
    pitch_diameter_mm: Positive | None = None
    source: list[str]
    estimated: list[str] = []

    @model_validator(mode="after")
    def _consistent(self) -> "BearingRow":
        if not self.d_mm < self.D_mm:
            raise ValueError(f"D_mm = {self.D_mm} must exceed the bore d_mm = {self.d_mm}")
        if self.type == "angular_contact" and self.contact_angle_deg == 0:
            raise ValueError("contact_angle_deg = 0: an angular contact bearing needs its angle")
        if self.type == "deep_groove" and self.f0 is None:
            raise ValueError("f0 is required for a deep groove bearing (ISO 281 factor e)")
        if self.pitch_diameter_mm is not None and not (
            self.d_mm < self.pitch_diameter_mm < self.D_mm
        ):
            raise ValueError(
                f"pitch_diameter_mm = {self.pitch_diameter_mm} must lie between d and D"
            )
        if (
            self.ball_diameter_mm is not None
            and self.ball_diameter_mm >= (self.D_mm - self.d_mm) / 2
        ):
            raise ValueError(
                f"ball_diameter_mm = {self.ball_diameter_mm} does not fit the ring section "
                f"(D − d)/2 = {(self.D_mm - self.d_mm) / 2:g} mm"
            )
        unknown = set(self.estimated) - BEARING_ESTIMABLE
        if unknown:
            raise ValueError(f"estimated names unknown fields {sorted(unknown)}")
        return self


# ---------------------------------------------------------------- the bibliography
class BibEntry(_Row):
    """One source of catalogs/bibliography.toml."""

    id: Annotated[str, Field(pattern=r"^[a-z0-9][a-z0-9.\-]*$", max_length=40)]
    short: Annotated[str, Field(min_length=1)]
    authors: list[Annotated[str, Field(min_length=1)]]
    title: Annotated[str, Field(min_length=1)]
    journal: str | None = None
    volume: str | None = None
    year: Annotated[int, Field(ge=1800, le=2100)] | None = None
    institution: str | None = None
    publisher: str | None = None
    number: str | None = None
    note: str | None = None
    file: str | None = None

    @model_validator(mode="after")
    def _where_published(self) -> "BibEntry":
        if not (self.journal or self.publisher or self.number):
            raise ValueError("give journal, publisher or (for a standard) number")
        return self


class SourceRef(_Row):
    """A [sources] entry of a catalog file: the bibliography id and what the file takes
    from it (a table, a page, a value)."""

    id: str
    note: str = ""
