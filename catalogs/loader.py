"""Load and validate the catalogs; a bad entry is refused with file, row and field named."""

import math
import tomllib
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import Annotated, Any

from pydantic import BaseModel, ConfigDict, Field, ValidationError, model_validator

from advisor.errors import CatalogError
from catalogs.threads import ThreadProfile, trapezoidal_profile

HERE = Path(__file__).parent

THREADS_FILE = "gost_24738_81_trapezoidal.toml"
POWERS_FILE = "gost_12139_84_powers.toml"
MOTORS_FILE = "induction_4a.toml"
MATERIALS_FILE = "screw_materials.toml"

Positive = Annotated[float, Field(gt=0, allow_inf_nan=False)]


class _Row(BaseModel):
    model_config = ConfigDict(extra="forbid", strict=True, frozen=True)


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

    @property
    def pole_pairs(self) -> int:
        return self.poles // 2

    @property
    def synchronous_speed_rpm(self) -> float:
        return 60.0 * self.supply_frequency_Hz / self.pole_pairs

    @property
    def rated_slip(self) -> float:
        """Slip at the published rated speed (the speed, not the rounded slip, is used)."""
        return 1.0 - self.rated_speed_rpm / self.synchronous_speed_rpm

    @property
    def rated_torque_Nm(self) -> float:
        return self.rated_power_kW * 1e3 / (self.rated_speed_rpm * math.pi / 30.0)


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

    def friction_range(self, lubrication: str) -> tuple[float, float]:
        lo, hi = self.f_oil if lubrication == "oil" else self.f_dry
        return lo, hi


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
    sources: dict[str, str]
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


# ---------------------------------------------------------------- the bundle
@dataclass(frozen=True)
class Catalogs:
    threads: tuple[ThreadProfile, ...]
    threads_source: str
    rated_powers_kW: tuple[float, ...]
    powers_source: str
    motors: tuple[InductionMotor, ...]
    motor_sources: dict[str, str]
    materials: MaterialsFile

    def thread(self, name: str) -> ThreadProfile | None:
        key = name.replace(" ", "").replace("×", "x").lower()
        for t in self.threads:
            if t.name.lower() == key:
                return t
        return None

    def pair(self, name: str) -> FrictionPair:
        return next(p for p in self.materials.pair if p.name == name)

    def steel(self, name: str) -> ScrewSteel:
        return next(s for s in self.materials.steel if s.name == name)

    def motors_with_poles(self, poles: int) -> list[InductionMotor]:
        return sorted((m for m in self.motors if m.poles == poles), key=lambda m: m.rated_power_kW)


def _read(path: Path) -> dict[str, Any]:
    try:
        with path.open("rb") as fh:
            return tomllib.load(fh)
    except OSError as exc:
        raise CatalogError(f"catalog {path}: cannot be read ({exc.strerror})") from None
    except tomllib.TOMLDecodeError as exc:
        raise CatalogError(f"catalog {path}: broken TOML: {exc}") from None


def _fail(path: Path, where: str, exc: ValidationError) -> CatalogError:
    err = exc.errors()[0]
    loc = ".".join(str(p) for p in err["loc"])
    field = f"field {loc} = {err['input']!r}: " if loc else ""
    msg = err["msg"].removeprefix("Value error, ")
    return CatalogError(f"catalog {path}, {where}: {field}{msg}")


def _rows(path: Path, data: dict[str, Any], key: str) -> list[dict[str, Any]]:
    rows = data.get(key)
    if not isinstance(rows, list) or not all(isinstance(r, dict) for r in rows):
        raise CatalogError(f"catalog {path}: expected an array of tables [[{key}]]")
    return rows


def _load_threads(path: Path) -> tuple[list[ThreadProfile], str]:
    data = _read(path)
    out = []
    for i, row in enumerate(_rows(path, data, "thread"), start=1):
        try:
            plan = ThreadPlanRow.model_validate(row)
        except ValidationError as exc:
            raise _fail(path, f"row {i} (d_mm = {row.get('d_mm')!r})", exc) from None
        for p in plan.pitches_mm:
            out.append(
                trapezoidal_profile(
                    plan.d_mm, p, preferred=(p == plan.preferred_mm), series=plan.series
                )
            )
    return out, str(data.get("source", path.name))


def _load_powers(path: Path) -> tuple[list[float], str]:
    data = _read(path)
    powers = data.get("rated_powers_kW")
    if not isinstance(powers, list) or not powers:
        raise CatalogError(f"catalog {path}: rated_powers_kW must be a non-empty array")
    for i, p in enumerate(powers, start=1):
        if isinstance(p, bool) or not isinstance(p, int | float) or not (0 < p < math.inf):
            raise CatalogError(f"catalog {path}, rated_powers_kW item {i} = {p!r}: must be > 0")
    if sorted(powers) != powers or len(set(powers)) != len(powers):
        raise CatalogError(f"catalog {path}: rated_powers_kW must be strictly increasing")
    return [float(p) for p in powers], str(data.get("source", path.name))


def _load_motors(path: Path) -> tuple[list[InductionMotor], dict[str, str]]:
    from advisor.calc.induction import fit_kloss

    data = _read(path)
    sources = data.get("sources", {})
    freq = data.get("supply_frequency_Hz", 50)
    out: list[InductionMotor] = []
    for i, row in enumerate(_rows(path, data, "motor"), start=1):
        where = f"row {i} (model = {row.get('model')!r})"
        try:
            m = InductionMotor.model_validate({**row, "supply_frequency_Hz": float(freq)})
        except ValidationError as exc:
            raise _fail(path, where, exc) from None
        if m.source not in sources:
            raise CatalogError(f"catalog {path}, {where}: source = {m.source!r} not in [sources]")
        try:
            fit_kloss(
                m.rated_torque_Nm, m.rated_slip, m.breakdown_torque_ratio, m.starting_torque_ratio
            )
        except ValueError as exc:
            raise CatalogError(f"catalog {path}, {where}: {exc}") from None
        out.append(m)
    _check_motor_series(path, out)
    return out, dict(sources)


def _check_motor_series(path: Path, motors: list[InductionMotor]) -> None:
    """Within one pole count, efficiency must not fall as power rises (beyond 1.5 points):
    a row that breaks the trend is usually a copying error."""
    names = {}
    for m in motors:
        if m.model in names:
            raise CatalogError(f"catalog {path}: model {m.model!r} appears twice")
        names[m.model] = m
    for poles in {m.poles for m in motors}:
        line = sorted((m for m in motors if m.poles == poles), key=lambda m: m.rated_power_kW)
        for a, b in zip(line, line[1:], strict=False):
            if b.efficiency_pct < a.efficiency_pct - 1.5:
                raise CatalogError(
                    f"catalog {path}, model {b.model!r}: field efficiency_pct = "
                    f"{b.efficiency_pct} falls below the smaller {a.model} "
                    f"({a.efficiency_pct}); efficiency must rise with power"
                )


def _load_materials(path: Path) -> MaterialsFile:
    data = _read(path)
    try:
        return MaterialsFile.model_validate(data)
    except ValidationError as exc:
        err = exc.errors()[0]
        loc = err["loc"]
        where = (
            f"row {loc[1] + 1} of [[{loc[0]}]]"
            if len(loc) > 1 and isinstance(loc[1], int)
            else "top level"
        )
        raise _fail(path, where, exc) from None


@cache
def load_catalogs(user_dir: Path | None = None) -> Catalogs:
    """The shipped catalogs, plus the rows of a user catalog directory if given."""
    threads, threads_source = _load_threads(HERE / THREADS_FILE)
    powers, powers_source = _load_powers(HERE / POWERS_FILE)
    motors, motor_sources = _load_motors(HERE / MOTORS_FILE)
    materials = _load_materials(HERE / MATERIALS_FILE)
    if user_dir is not None:
        if not user_dir.is_dir():
            raise CatalogError(f"catalog directory {user_dir}: not a directory")
        if (user_dir / MOTORS_FILE).exists():
            extra, extra_sources = _load_motors(user_dir / MOTORS_FILE)
            motors = motors + extra
            motor_sources = {**motor_sources, **extra_sources}
            _check_unique(user_dir / MOTORS_FILE, [m.model for m in motors], "model")
        if (user_dir / THREADS_FILE).exists():
            extra_threads, _ = _load_threads(user_dir / THREADS_FILE)
            threads = threads + extra_threads
            _check_unique(user_dir / THREADS_FILE, [t.name for t in threads], "thread")
        if (user_dir / MATERIALS_FILE).exists():
            materials = _load_materials(user_dir / MATERIALS_FILE)
    return Catalogs(
        threads=tuple(sorted(threads, key=lambda t: (t.d_mm, -t.pitch_mm))),
        threads_source=threads_source,
        rated_powers_kW=tuple(powers),
        powers_source=powers_source,
        motors=tuple(motors),
        motor_sources=motor_sources,
        materials=materials,
    )


def _check_unique(path: Path, names: list[str], what: str) -> None:
    seen = set()
    for n in names:
        if n in seen:
            raise CatalogError(f"catalog {path}: {what} {n!r} is already in the shipped catalog")
        seen.add(n)
