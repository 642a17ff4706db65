"""Catalog rows as the engine uses them: plain named tuples, already validated.

The pydantic schemas that validate the files live in :mod:`catalogs.schema` and are imported
only when a file has to be validated (not when the validated catalogs come from the cache).
"""

from typing import NamedTuple

from advisor.calc.induction import rated_torque


class InductionMotor(NamedTuple):
    model: str
    poles: int
    rated_power_kW: float
    rated_speed_rpm: float
    slip_pct: float
    breakdown_torque_ratio: float
    starting_torque_ratio: float
    efficiency_pct: float
    cos_phi: float
    starting_current_ratio: float
    inertia_kgm2: float
    mass_kg: float
    source: str
    estimated: tuple[str, ...] = ()
    supply_frequency_Hz: float = 50.0

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
        return rated_torque(self.rated_power_kW * 1e3, self.rated_speed_rpm)


class FrictionPair(NamedTuple):
    name: str
    description: str
    f_oil: list[float]
    f_dry: list[float]
    allowable_pressure_MPa: float
    source: list[str]
    estimated: tuple[str, ...] = ()

    def friction_range(self, lubrication: str) -> tuple[float, float]:
        lo, hi = self.f_oil if lubrication == "oil" else self.f_dry
        return lo, hi


class ScrewSteel(NamedTuple):
    name: str
    yield_strength_MPa: float
    elastic_modulus_MPa: float
    source: list[str]


class NutRules(NamedTuple):
    height_ratio_min: float
    height_ratio_max: float
    max_turns: int
    source: list[str]


class StrengthRules(NamedTuple):
    yield_safety_factor: float
    source: list[str]


class Materials(NamedTuple):
    sources: dict[str, tuple[str, str]]  # key → (bibliography id, what is taken from it)
    pair: list[FrictionPair]
    steel: list[ScrewSteel]
    nut: NutRules
    strength: StrengthRules

    def to_dict(self) -> dict:
        return {
            "sources": self.sources,
            "pair": [x._asdict() for x in self.pair],
            "steel": [x._asdict() for x in self.steel],
            "nut": self.nut._asdict(),
            "strength": self.strength._asdict(),
        }

    @classmethod
    def from_dict(cls, d: dict) -> "Materials":
        return cls(
            sources={k: (v[0], v[1]) for k, v in d["sources"].items()},
            pair=[FrictionPair(**x) for x in d["pair"]],
            steel=[ScrewSteel(**x) for x in d["steel"]],
            nut=NutRules(**d["nut"]),
            strength=StrengthRules(**d["strength"]),
        )


class ElectricalSteel(NamedTuple):
    grade: str
    thickness_mm: float
    equivalent: str
    p10_50_W_kg: float
    p15_50_W_kg: float
    p10_400_W_kg: float
    source: list[str]
    estimated: tuple[str, ...] = ()

    @property
    def name(self) -> str:
        return f"{self.grade} {self.thickness_mm:g} mm"


class FrictionConstants(NamedTuple):
    """Geometric constants of the SKF friction model for one bearing series."""

    name: str
    R1: float
    R2: float
    S1: float
    S2: float
    R3: float = 0.0
    S3: float = 0.0
    source: str = ""


class Bearing(NamedTuple):
    designation: str
    type: str  # "angular_contact" | "deep_groove"
    friction: str
    d_mm: float
    D_mm: float
    B_mm: float
    contact_angle_deg: float
    C_kN: float
    C0_kN: float
    ball_count: int
    ball_diameter_mm: float
    pitch_diameter_mm: float
    limiting_speed_rpm: float
    source: list[str]
    estimated: tuple[str, ...] = ()
    Pu_kN: float | None = None
    reference_speed_rpm: float | None = None
    mass_kg: float | None = None
    f0: float | None = None

    @property
    def pitch_radius_mm(self) -> float:
        return self.pitch_diameter_mm / 2.0

    @property
    def inner_raceway_radius_mm(self) -> float:
        """r_B of seed 002, eq. (4): pitch radius less the ball radius."""
        return (self.pitch_diameter_mm - self.ball_diameter_mm) / 2.0


class MagnetPoint(NamedTuple):
    """Magnet eddy losses of a frame at a motor speed (seed 000: 60 W at 5000 rpm)."""

    speed_rpm: float
    loss_W: float


class BldcFrame(NamedTuple):
    """A PM brushless motor the rotary advice can choose: a frame of the series scaled from
    seed 000's reference (``kind = "scaled"``) or a user's catalog motor (``"catalog"``).

    It carries the attributes of seed 000's loss model (those of the requirement's
    ``[motor.reference]``), so the advice computes its losses, its limit (its own losses at
    its own rated point) and its duty exactly as for the reference. A catalog motor has no
    steel area and no magnet losses: its datasheet states no core losses, its copper loss at
    the continuous torque is its limit, and no speed above its rated speed is offered."""

    name: str
    kind: str  # "scaled" | "catalog"
    speed_rpm: float  # rated speed: the point the limit is taken at
    torque_Nm: float  # continuous torque at that speed
    current_A: float
    phase_resistance_ohm: float
    conducting_phases: int
    stator_steel_area_mm2: float
    stack_length_mm: float
    magnet_losses: tuple[MagnetPoint, ...]
    rotor_inertia_kgm2: float
    thermal_time_constant_s: float
    mass_kg: float
    outer_diameter_mm: float
    length_mm: float
    source: tuple[str, ...]
    law: str
    length_scale: float = 1.0
    peak_torque_Nm: float | None = None
    torque_constant_Nm_A: float | None = None
    estimated: tuple[str, ...] = ()
    pole_pairs: int = 6
    stacking_factor: float = 0.85
    steel_density_kg_m3: float = 7800.0
    steel_grade: str = "2413"
    steel_thickness_mm: float = 0.35
    induction_T: float = 1.5
    iron_loss_model: str = "quadratic"

    def as_dict(self) -> dict:
        d = self._asdict()
        d["magnet_losses"] = [list(p) for p in self.magnet_losses]
        return d

    @classmethod
    def from_dict(cls, d: dict) -> "BldcFrame":
        pts = tuple(MagnetPoint(*p) for p in d["magnet_losses"])
        return cls(
            **{
                **d,
                "magnet_losses": pts,
                "source": tuple(d["source"]),
                "estimated": tuple(d["estimated"]),
            }
        )
