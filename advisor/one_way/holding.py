"""Whether the holding device (seed 004) holds the load with the power off, as checks: its
capacity against the torque the load gives it at rest, and for a self-locking gear the
self-locking itself (γ/φ below 1). Shared by the linear and rotary actuators.

The capacity is the torque the device is sized for where it sits (the working load or the
emergency stop's, × f_B); the demand is the torque the standing load gives the device there,
which the chain's friction lowers: through a screw that is not self-locking
F·d2/2·tan(ψ − φ') at the low end of the friction range, through the back-driven wave gear
M·η/q. The electromagnetic clutch holds as a clutch-brake: de-energised, its spring presses
the armature against a fixed face with the torque it is sized for."""

from advisor.calc.checks import Check, factored
from advisor.calc.one_way import self_locking_ratio
from advisor.core.cite import Cite
from rules.one_way import NAMES, SEED_004


def holds_check(kind: str, capacity_Nm: float, held_Nm: float, f_b: float, how: str) -> Check:
    """The device's capacity against the torque the standing load gives it, × f_B.

    ``how``: the demand in words (which torque, at which force or torque)."""
    return factored(
        "one_way_holds_load",
        f"{NAMES[kind]} holds the load with the power off: {how} × f_B within the torque it "
        "is sized for",
        held_Nm,
        capacity_Nm,
        "N·m",
        f_b,
        SEED_004,
    )


def self_locking_check(kind: str) -> Check | None:
    """γ/φ of a self-locking gear below 1 (margin φ/γ); None for the clutches."""
    ratio = self_locking_ratio(kind)
    if ratio is None:
        return None
    how = (
        "γ = 0.5·φ, the aviation margin"
        if kind == "worm"
        else "from its estimated η = γ/(γ + φ), small angles"
    )
    return Check(
        "one_way_self_locking",
        f"{NAMES[kind]} cannot be driven back by the load: lead angle over friction angle "
        f"γ/φ below 1 ({how})",
        ratio,
        1.0,
        "-",
        1.0 / ratio,
        SEED_004,
    )


def device_checks(kind: str, capacity_Nm: float, held_Nm: float, f_b: float, how: str):
    """The holding checks of a device: its capacity, and its self-locking where it is a gear."""
    locking = self_locking_check(kind)
    return [holds_check(kind, capacity_Nm, held_Nm, f_b, how), *([locking] if locking else [])]


def screw_self_locking_check(
    thread: str, lead_angle_rad: float, friction_angle_rad: float, friction: float, source: Cite
) -> Check:
    """A screw that holds its load itself: ψ/φ' at the low end of the friction range below 1
    (margin φ'/ψ)."""
    return Check(
        "screw_self_locking",
        f"{thread} self-locking with the power off: lead angle over friction angle ψ/φ' below 1 "
        f"at the low end of the friction range (f = {friction:g})",
        lead_angle_rad / friction_angle_rad,
        1.0,
        "-",
        friction_angle_rad / lead_angle_rad,
        source,
    )
