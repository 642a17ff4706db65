"""Pydantic schemas that validate the catalog files (see :mod:`catalogs.loader`)."""

import inspect
from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

from catalogs import rows

Positive = Annotated[float, Field(gt=0, allow_inf_nan=False)]


def Between(lo: float, hi: float) -> Any:
    """A finite number within the physical range ``lo … hi`` of a catalog field: a datasheet
    value outside it is a copying slip (a unit off by 10³, a missing exponent), and the
    advice computed from it would overflow or divide by a denormal."""
    return Annotated[float, Field(ge=lo, le=hi, allow_inf_nan=False)]


class _Row(BaseModel):
    # defer_build: a run that finds the validated catalogs in the cache never pays for
    # building the validators.
    model_config = ConfigDict(extra="forbid", strict=True, frozen=True, defer_build=True)


def _field(name: str, value: object, why: str) -> ValueError:
    """A row's refusal naming its field: a check across fields has no single location."""
    return ValueError(f"field {name} = {value!r}: {why}")


# ---------------------------------------------------------------- threads (GOST 24738-81)
#: The pitches GOST 24737-81 gives the profile for (its table of ac: 1.5 … 44 mm).
PITCH_RANGE_MM = (1.5, 44.0)
#: |given − computed| allowed for a row's d2_mm / d3_mm: the formulas give the diameters on
#: a 0.05 mm grid, so a value copied from the standard's table agrees to its rounding.
THREAD_DIAMETER_TOLERANCE_MM = 0.01


#: Nominal diameters of a trapezoidal thread, mm: GOST 24738-81 runs from Tr8 to Tr640; a
#: smaller diameter than 2 mm cannot carry the smallest pitch (1.5 mm) of GOST 24737-81.
THREAD_D_RANGE_MM = (2.0, 640.0)


class ThreadPlanRow(_Row):
    d_mm: Between(*THREAD_D_RANGE_MM)
    series: Annotated[int, Field(ge=1, le=2)]
    # a pitch outside PITCH_RANGE_MM is refused by _check_profile, citing the standard
    pitches_mm: Annotated[
        list[Between(1e-3, THREAD_D_RANGE_MM[1])], Field(min_length=1, max_length=20)
    ]
    preferred_mm: Between(1e-3, THREAD_D_RANGE_MM[1])
    #: optional, one per pitch: the diameters as a table prints them, checked against the
    #: profile computed by GOST 24737-81 (never used in its place)
    d2_mm: list[Between(0.0, THREAD_D_RANGE_MM[1])] | None = None
    d3_mm: list[Between(0.0, THREAD_D_RANGE_MM[1])] | None = None

    @model_validator(mode="after")
    def _preferred_is_listed(self) -> "ThreadPlanRow":
        if self.preferred_mm not in self.pitches_mm:
            raise ValueError(f"preferred_mm = {self.preferred_mm} is not among pitches_mm")
        if len(set(self.pitches_mm)) != len(self.pitches_mm):
            raise ValueError("pitches_mm lists a pitch twice")
        for p in self.pitches_mm:
            _check_profile(self.d_mm, p)
        for name in ("d2_mm", "d3_mm"):
            given = getattr(self, name)
            if given is not None:
                _check_given_diameters(name, given, self.d_mm, self.pitches_mm)
        return self


def _check_profile(d: float, p: float) -> None:
    """A pitch the GOST 24737-81 profile is defined for and fits inside the diameter: the
    pitch below d, and d2 = d − 0.5·P, D1 = d − P, d3 = d − 2·h3 (h3 = 0.5·P + ac) all
    positive (d3 is the smallest, so it decides)."""
    from catalogs.threads import trapezoidal_profile

    lo, hi = PITCH_RANGE_MM
    if not lo <= p <= hi:
        raise _field(
            "pitches_mm",
            p,
            f"GOST 24737-81 gives the trapezoidal profile for pitches {lo:g} … {hi:g} mm",
        )
    if not p < d:
        raise _field("pitches_mm", p, f"the pitch must be below the diameter d_mm = {d:g}")
    t = trapezoidal_profile(d, p)
    if not t.d3_mm > 0:
        raise _field(
            "pitches_mm",
            p,
            f"the minor diameter d3 = d − 2·h3 = {d:g} − 2·{t.h3_mm:g} = {t.d3_mm:g} mm "
            "(GOST 24737-81) must be positive",
        )


def _check_given_diameters(name: str, given: list[float], d: float, pitches: list[float]) -> None:
    from catalogs.threads import trapezoidal_profile

    if len(given) != len(pitches):
        raise _field(name, given, f"give one value per pitch ({len(pitches)}), in their order")
    for p, g in zip(pitches, given, strict=True):
        want = getattr(trapezoidal_profile(d, p), name)
        if abs(g - want) > THREAD_DIAMETER_TOLERANCE_MM:
            raise _field(
                name,
                g,
                f"Tr{d:g}x{p:g} has {name.removesuffix('_mm')} = {want:g} mm by GOST 24737-81 "
                f"(allowed difference {THREAD_DIAMETER_TOLERANCE_MM:g} mm)",
            )


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
#: |M_n − P/ω_n| allowed for a row that states its rated torque, as a share of P/ω_n: a
#: datasheet rounds the speed and the torque to three or four digits, well inside 3 %.
TORQUE_TOLERANCE = 0.03
#: A rating above this is not a motor (refused as non-physical): the largest induction
#: machines built (compressor and pumped-storage drives) are rated in tens of megawatts.
MAX_RATED_POWER_KW = 1e5


#: Supply frequencies of an induction motor's catalog, Hz: mains 50/60 Hz, aircraft 400 Hz,
#: high-speed spindles up to about 1 kHz.
SUPPLY_FREQUENCY_RANGE_HZ = (1.0, 1000.0)


def row_fields(row: type, bounds: dict[str, Any], name: str = "") -> type[_Row]:
    """A schema's fields declared once, in the row of :mod:`catalogs.rows` it validates (a
    NamedTuple): the row's names, types and defaults, each number within its ``bounds``
    (an ``Annotated`` type of the field). A tuple of the row is read as the list TOML gives.
    ``name``: the model's (by default the row's, ``…Fields``, for a schema that subclasses it
    to add its checks)."""
    from pydantic import create_model

    unknown = set(bounds) - set(row._fields)
    if unknown:
        raise TypeError(f"{row.__name__}: bounds of fields it does not have: {sorted(unknown)}")
    fields: dict[str, Any] = {}
    for name, ann in inspect.get_annotations(row).items():
        typ = bounds.get(name, list[str] if ann == tuple[str, ...] else ann)
        default = row._field_defaults.get(name, ...)
        fields[name] = (typ, list(default) if isinstance(default, tuple) else default)
    return create_model(name or f"{row.__name__}Fields", __base__=_Row, **fields)


class InductionMotor(
    row_fields(
        rows.InductionMotor,
        {
            "model": Annotated[str, Field(min_length=1, max_length=60)],
            # 10 W … 100 MW (above: see MAX_RATED_POWER_KW, refused with its own reason)
            "rated_power_kW": Annotated[float, Field(ge=0.01, allow_inf_nan=False)],
            "rated_speed_rpm": Between(1.0, 6e4),
            "slip_pct": Annotated[float, Field(gt=0, lt=50, allow_inf_nan=False)],
            "breakdown_torque_ratio": Annotated[float, Field(gt=1, le=5, allow_inf_nan=False)],
            "starting_torque_ratio": Annotated[float, Field(gt=0, le=5, allow_inf_nan=False)],
            "efficiency_pct": Annotated[float, Field(gt=0, lt=100, allow_inf_nan=False)],
            "cos_phi": Annotated[float, Field(gt=0, le=1, allow_inf_nan=False)],
            "starting_current_ratio": Annotated[float, Field(ge=1, le=15, allow_inf_nan=False)],
            "inertia_kgm2": Between(1e-7, 1e5),
            "mass_kg": Between(0.1, 1e6),
            "supply_frequency_Hz": Between(*SUPPLY_FREQUENCY_RANGE_HZ),
        },
    )
):
    """A row of an induction motor catalog: the fields of :class:`catalogs.rows.InductionMotor`
    within their physical ranges, and the rated torque a datasheet may state."""

    #: optional: the rated torque as the datasheet states it, checked against P/ω_n (the
    #: advisor computes M_n from the power and the speed, never takes it from here)
    rated_torque_Nm: Between(1e-3, 1e7) | None = None

    @model_validator(mode="after")
    def _consistent(self) -> "InductionMotor":
        if self.poles not in (2, 4, 6, 8):
            raise ValueError(f"poles = {self.poles}: allowed 2, 4, 6, 8")
        if self.rated_power_kW > MAX_RATED_POWER_KW:
            raise _field(
                "rated_power_kW",
                self.rated_power_kW,
                f"above {MAX_RATED_POWER_KW:g} kW (100 MW): no induction motor is rated so high",
            )
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
        _check_power_flow(self, n0)
        unknown = set(self.estimated) - MOTOR_FIELDS
        if unknown:
            raise ValueError(f"estimated names unknown fields {sorted(unknown)}")
        return self


def _check_power_flow(m: InductionMotor, n0: float) -> None:
    """Power, torque and speed of the rated point agree (P = M·ω), and the efficiency is
    below what the slip allows: the rotor turns the air-gap power P_δ into mechanical power
    (1 − s)·P_δ and loses s·P_δ in its cage, and the input exceeds P_δ, so
    η = P/P_in < 1 − s = n/n₀ (the energy diagram of the induction machine, as every text
    on electric machines draws it)."""
    import math

    omega = m.rated_speed_rpm * math.pi / 30.0
    torque = m.rated_power_kW * 1e3 / omega
    if (
        m.rated_torque_Nm is not None
        and abs(m.rated_torque_Nm - torque) > TORQUE_TOLERANCE * torque
    ):
        raise _field(
            "rated_torque_Nm",
            m.rated_torque_Nm,
            f"P/ω = {m.rated_power_kW:g} kW at {m.rated_speed_rpm:g} rpm is {torque:.4g} N·m "
            f"(allowed difference {TORQUE_TOLERANCE:.0%})",
        )
    limit = m.rated_speed_rpm / n0
    if m.efficiency_pct / 100.0 >= limit:
        raise _field(
            "efficiency_pct",
            m.efficiency_pct,
            f"must be below n/n₀ = {m.rated_speed_rpm:g}/{n0:g} = {limit:.1%}: the slip's share "
            "of the air-gap power is lost in the rotor",
        )


# ---------------------------------------------------------------- screw materials
#: A friction range [low, high] of a material pair: two coefficients, each within (0, 1).
FrictionRange = Annotated[
    list[Annotated[float, Field(gt=0, lt=1)]], Field(min_length=2, max_length=2)
]


class FrictionPair(
    row_fields(
        rows.FrictionPair,
        {
            "f_oil": FrictionRange,
            "f_dry": FrictionRange,
            "allowable_pressure_MPa": Between(0.1, 1e3),
        },
    )
):
    """A material pair of a screw and its nut (:class:`catalogs.rows.FrictionPair`)."""

    @model_validator(mode="after")
    def _ranges(self) -> "FrictionPair":
        for name in ("f_oil", "f_dry"):
            lo, hi = getattr(self, name)
            if lo > hi:
                raise ValueError(f"{name} = [{lo}, {hi}]: low end above high end")
        return self


ScrewSteel = row_fields(
    rows.ScrewSteel,
    {"yield_strength_MPa": Between(10.0, 1e4), "elastic_modulus_MPa": Between(1e3, 1e6)},
    "ScrewSteel",
)
NutRules = row_fields(
    rows.NutRules,
    {
        "height_ratio_min": Between(0.1, 10.0),
        "height_ratio_max": Between(0.1, 10.0),
        "max_turns": Annotated[int, Field(ge=1, le=100)],
    },
    "NutRules",
)
StrengthRules = row_fields(
    rows.StrengthRules, {"yield_safety_factor": Between(1.0, 20.0)}, "StrengthRules"
)


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


class ElectricalSteelRow(
    row_fields(
        rows.ElectricalSteel,
        {
            "grade": Annotated[str, Field(pattern=r"^\d{4}$")],
            "thickness_mm": Between(0.01, 5.0),
            "p10_50_W_kg": Between(1e-3, 1e3),
            "p15_50_W_kg": Between(1e-3, 1e3),
            "p10_400_W_kg": Between(1e-3, 1e4),
        },
    )
):
    """A grade of electrical steel (:class:`catalogs.rows.ElectricalSteel`)."""

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
    # SKF's constants of the frictional moment run from about 10⁻⁸ (R1) to about 10² (S2)
    R1: Between(1e-12, 1e4)
    R2: Between(1e-12, 1e4)
    S1: Between(1e-12, 1e4)
    S2: Between(1e-12, 1e4)
    R3: Between(0.0, 1e4) = 0.0
    S3: Between(0.0, 1e4) = 0.0
    source: str


#: Density of bearing steel (100Cr6 ≈ 7830 kg/m³, rounded up): a bearing is its rings,
#: balls and cage inside the envelope d × D × B, none of it denser, so never heavier than a
#: solid steel ring of that envelope (the shipped rows weigh 0.65–0.72 of it).
STEEL_DENSITY_KG_M3 = 7850.0

#: The largest outer diameter of a rolling bearing a catalog row may give, mm (SKF's
#: catalog ends near 2 m; slewing rings are not bearings of this table).
BEARING_D_MAX_MM = 2000.0

BEARING_ESTIMABLE = {"C_kN", "C0_kN", "f0", "ball_count", "ball_diameter_mm", "pitch_diameter_mm"}


class BearingRow(_Row):
    designation: Annotated[str, Field(min_length=1, max_length=40)]
    type: Literal["angular_contact", "deep_groove"]
    friction: str
    # from miniature bearings (bore 0.6 mm) to the largest of a catalog (D about 2 m)
    d_mm: Between(0.5, BEARING_D_MAX_MM)
    D_mm: Between(1.0, BEARING_D_MAX_MM)
    B_mm: Between(0.1, 1e3)
    contact_angle_deg: Annotated[float, Field(ge=0, lt=90, allow_inf_nan=False)]
    C_kN: Between(1e-3, 1e5)
    C0_kN: Between(1e-3, 1e5)
    Pu_kN: Between(1e-5, 1e5) | None = None
    reference_speed_rpm: Between(1.0, 1e6) | None = None
    limiting_speed_rpm: Between(1.0, 1e6)
    mass_kg: Between(1e-5, 1e4) | None = None
    f0: Between(1.0, 100.0) | None = None
    ball_count: Annotated[int, Field(ge=3, le=200)] | None = None
    ball_diameter_mm: Between(0.1, BEARING_D_MAX_MM) | None = None
    pitch_diameter_mm: Between(0.5, BEARING_D_MAX_MM) | None = None
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
        if self.Pu_kN is not None and not self.Pu_kN < self.C0_kN:
            raise _field(
                "Pu_kN",
                self.Pu_kN,
                f"the fatigue load limit must be below the static rating C0_kN = {self.C0_kN:g} "
                "(the fatigue load limit, Cu of ISO 281, is a small share of C0)",
            )
        if self.mass_kg is not None:
            import math

            solid = STEEL_DENSITY_KG_M3 * math.pi / 4 * (self.D_mm**2 - self.d_mm**2) * self.B_mm
            solid *= 1e-9  # mm³ → m³
            if self.mass_kg > solid:
                raise _field(
                    "mass_kg",
                    self.mass_kg,
                    f"heavier than a solid steel ring of the bearing's envelope "
                    f"(d {self.d_mm:g}, D {self.D_mm:g}, B {self.B_mm:g} mm: {solid:.3g} kg)",
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


# ---------------------------------------------------------------- PM brushless motors
class BldcReferenceRow(_Row):
    """[reference] of catalogs/bldc_frames.toml: seed 000's frame and its estimates."""

    name: str
    stator_outer_diameter_mm: Between(1.0, 1e4)
    stack_length_mm: Between(1.0, 1e4)
    torque_Nm: Between(1e-4, 1e5)
    speed_rpm: Between(1.0, 2e5)
    stator_steel_area_mm2: Between(1.0, 1e8)
    phase_resistance_ohm: Between(1e-5, 1e4)
    current_A: Between(1e-3, 1e5)
    magnet_losses: list[
        Annotated[
            list[Between(0.0, 2e5)],  # [speed rpm, loss W]
            Field(min_length=2, max_length=2),
        ]
    ]
    rotor_inertia_kgm2: Between(1e-10, 1e4)
    mass_kg: Between(1e-3, 1e5)
    thermal_time_constant_s: Between(1.0, 1e6)
    estimated: list[str] = []
    source: list[str]

    @model_validator(mode="after")
    def _steel_fits(self) -> "BldcReferenceRow":
        _check_steel_fits(self.stator_steel_area_mm2, self.stator_outer_diameter_mm)
        return self


def _check_steel_fits(area_mm2: float, diameter_mm: float) -> None:
    """The stator steel's cross-section within the stator's outer circle."""
    import math

    disc = math.pi / 4 * diameter_mm**2
    if area_mm2 >= disc:
        raise _field(
            "stator_steel_area_mm2",
            area_mm2,
            f"must be below the stator's outer disc π/4·D² = {disc:.5g} mm² (D = {diameter_mm:g})",
        )


class BldcFrameRow(_Row):
    """A [[frame]] of catalogs/bldc_frames.toml (checked against the law by the loader)."""

    name: Annotated[str, Field(pattern=r"^BL\d{3}x\d{3}$")]
    length_scale: Between(1e-3, 1e3)
    stator_outer_diameter_mm: Between(1.0, 1e4)
    torque_Nm: Between(1e-4, 1e5)
    speed_rpm: Between(1.0, 2e5)
    stack_length_mm: Between(1.0, 1e4)
    stator_steel_area_mm2: Between(1.0, 1e8)
    phase_resistance_ohm: Between(1e-5, 1e4)
    current_A: Between(1e-3, 1e5)
    rotor_inertia_kgm2: Between(1e-10, 1e4)
    mass_kg: Between(1e-3, 1e5)
    thermal_time_constant_s: Between(1.0, 1e6)
    magnet_losses: list[
        Annotated[
            list[Between(0.0, 2e5)],  # [speed rpm, loss W]
            Field(min_length=2, max_length=2),
        ]
    ]
    origin: Literal["scaled from seed 000's reference frame by the file's law"]
    source: list[str]

    @model_validator(mode="after")
    def _steel_fits(self) -> "BldcFrameRow":
        _check_steel_fits(self.stator_steel_area_mm2, self.stator_outer_diameter_mm)
        return self


#: Density bound of a motor: nothing in it is denser than copper (8960 kg/m³), so a motor is
#: never heavier than a solid copper cylinder of its envelope.
COPPER_DENSITY_KG_M3 = 8960.0
#: The largest air-gap tangential stress of any cooled machine, Pa: direct liquid cooling
#: (Pyrhönen, Jokinen, Hrabovcová, «Design of Rotating Electrical Machines», 2008, table 6.3,
#: up to about 130 kPa). A torque T over a rotor inside the envelope asks σ = T/(2·V_rotor) >
#: T/(2·V_envelope); a row whose continuous torque needs more than this over its whole
#: envelope is not a motor.
MAX_SHEAR_STRESS_PA = 130e3
BLDC_ESTIMABLE = {
    "peak_torque_Nm",
    "phase_resistance_ohm",
    "torque_constant_Nm_A",
    "rotor_inertia_kgm2",
    "mass_kg",
    "thermal_time_constant_s",
}


class BldcMotorRow(_Row):
    """A [[motor]] of a user's bldc_motors.toml: a datasheet's PM brushless motor."""

    name: Annotated[str, Field(min_length=1, max_length=60)]
    continuous_torque_Nm: Between(1e-4, 1e5)
    peak_torque_Nm: Between(1e-4, 1e6)
    rated_speed_rpm: Between(1.0, 2e5)
    phase_resistance_ohm: Between(1e-5, 1e4)
    torque_constant_Nm_A: Between(1e-4, 1e3)
    rotor_inertia_kgm2: Between(1e-10, 1e4)
    mass_kg: Between(1e-3, 1e5)
    outer_diameter_mm: Between(1.0, 1e4)
    length_mm: Between(1.0, 1e4)
    thermal_time_constant_s: Between(1.0, 1e6)
    pole_pairs: Annotated[int, Field(ge=1, le=100)] = 4
    source: str
    estimated: list[str] = []

    @model_validator(mode="after")
    def _consistent(self) -> "BldcMotorRow":
        import math

        if self.peak_torque_Nm < self.continuous_torque_Nm:
            raise _field(
                "peak_torque_Nm",
                self.peak_torque_Nm,
                f"below the continuous torque continuous_torque_Nm = {self.continuous_torque_Nm:g}",
            )
        d, length = self.outer_diameter_mm * 1e-3, self.length_mm * 1e-3
        volume = math.pi / 4 * d * d * length
        if self.mass_kg > COPPER_DENSITY_KG_M3 * volume:
            raise _field(
                "mass_kg",
                self.mass_kg,
                f"heavier than solid copper in the envelope Ø{self.outer_diameter_mm:g} × "
                f"{self.length_mm:g} mm ({COPPER_DENSITY_KG_M3 * volume:.4g} kg)",
            )
        ring = self.mass_kg * (d / 2) ** 2
        if self.rotor_inertia_kgm2 >= ring:
            raise _field(
                "rotor_inertia_kgm2",
                self.rotor_inertia_kgm2,
                f"not below the whole mass on the outer radius, m·(D/2)² = {ring:.4g} kg·m²",
            )
        stress = self.continuous_torque_Nm / (2 * volume)
        if stress > MAX_SHEAR_STRESS_PA:
            raise _field(
                "continuous_torque_Nm",
                self.continuous_torque_Nm,
                f"asks an air-gap shear stress T/(2·V) = {stress / 1e3:.4g} kPa over the whole "
                f"envelope, above the {MAX_SHEAR_STRESS_PA / 1e3:g} kPa of direct liquid "
                "cooling (Pyrhönen et al. 2008, table 6.3)",
            )
        unknown = set(self.estimated) - BLDC_ESTIMABLE
        if unknown:
            raise ValueError(f"estimated names unknown fields {sorted(unknown)}")
        return self
