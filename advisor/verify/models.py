"""The direct calculations of the verification set: each one a named function of a case's
``inputs`` (SI unless the case says otherwise) that calls the advisor's own calculation
functions and returns the quantities the published example states.

A case of kind ``"calc"`` names one of these in ``function``; a case of kind
``"requirement"`` runs the whole advisor instead (:mod:`advisor.verify.runner`). Nothing here
computes a number the calculation modules do not: these functions only feed them the
example's inputs and read their results, so a verified number is the number a design uses.
"""

import math
from collections.abc import Callable
from typing import Any

Quantities = dict[str, Any]

#: The registry: function name (as the data writes it) → the function.
MODELS: dict[str, Callable[[dict[str, Any]], Quantities]] = {}


def model(fn: Callable[[dict[str, Any]], Quantities]) -> Callable[[dict[str, Any]], Quantities]:
    MODELS[fn.__name__] = fn
    return fn


@model
def wave_gear_rows(x: dict[str, Any]) -> Quantities:
    """Seed 000, eq. (13) with (16): the outer diameter of a stage with more rows of rolling
    bodies, against two rows, at the same torque and ratio (percent smaller)."""
    from advisor.calc import wavegear as wg

    q, m = x["ratio"], x["torque_Nm"]

    def outer(rows: int) -> float:
        return float(wg.outer_diameter(q, wg.rolling_body_diameter(m, q, rows)))

    two = outer(2)
    return {f"cut_{n}_rows_pct": 100.0 * (1.0 - outer(n) / two) for n in (3, 4)}


@model
def seed002_speed(x: dict[str, Any]) -> Quantities:
    """Seed 002: the rotor speed in rpm from its 4453 rad/s."""
    return {"speed_rpm": x["speed_rad_s"] * 30.0 / math.pi}


@model
def seed003_constants(x: dict[str, Any]) -> Quantities:
    """Seed 003: K = ∛(1/(1 − μ²)²) at the ends of μ = 0…0.6, and the constants of the
    engineering-unit forms (12) and (13) as they follow from eq. (4) with g."""
    from advisor.calc import motion as mo

    return {
        "K_at_mu_0": mo.k_factor(0.0),
        "K_at_mu_0_6": mo.k_factor(0.6),
        "constant_eq12": 3600.0 * mo.G / math.pi,
        "constant_eq13": 120.0 * mo.G / math.pi,
    }


@model
def seed004_worm(x: dict[str, Any]) -> Quantities:
    """Seed 004: driving efficiency tan γ/tan(γ + φ) of a self-locking worm at γ = φ and at
    the aviation margin γ = 0.5·φ (tan φ = f)."""
    from advisor.calc import one_way as ow

    phi = math.atan(x["friction_coefficient"])
    return {
        "efficiency_at_gamma_phi": ow.worm_efficiency(phi, phi)[0],
        "efficiency_at_half_phi": ow.worm_efficiency(0.5 * phi, phi)[0],
    }


@model
def seed004_roller_clutch(x: dict[str, Any]) -> Quantities:
    """Seed 004: the roller clutch's collapsed coefficients (10)–(13) as they follow from the
    paper's geometry (8)–(9): m = k·ρπ·(M/z) and J = k·ρπ·(M/z)^(5/3), M in N·mm, lengths
    in mm (ρ in kg/mm³ → kg, kg·mm²)."""
    from advisor.calc import one_way as ow

    m, z = x["torque_Nm"], x["rollers"]
    g = ow.roller_geometry(m, z, x["wedge_angle_deg"])
    rho_pi = ow.STEEL_DENSITY * 1e-9 * math.pi  # kg/mm³ · π
    per = m * 1e3 / z  # M/z, N·mm
    inertia_scale = rho_pi * per ** (5.0 / 3.0) * 1e-6  # kg·mm² → kg·m²
    return {
        "star_mass_coefficient": g.star_mass_kg / (rho_pi * per),
        "roller_mass_coefficient": g.roller_mass_kg / (rho_pi * per),
        "star_inertia_coefficient": g.star_inertia_kgm2 / inertia_scale,
        "roller_inertia_coefficient": g.roller_inertia_kgm2 / inertia_scale,
    }


@model
def seed004_placement(x: dict[str, Any]) -> Quantities:
    """Seed 004: the torque at the motor side, M_out/(q·η) (rule OW-01), the output power
    at the motor speed, M_out·n_motor/q, and an electromagnetic clutch's power at the motor
    side (eq. (19), the smallest diameter of the paper's range) and its share of that power."""
    from advisor.calc import one_way as ow
    from rules import one_way as rules

    m_out, q = x["output_torque_Nm"], x["ratio"]
    m = rules.placement(m_out, q, x["efficiency"]).value
    p_out = m_out * x["motor_speed_rpm"] / q * math.pi / 30.0
    power, _ = ow.em_clutch_power(m, x["em_clutch_diameter_mm"])
    return {
        "motor_side_torque_Nm": m,
        "output_power_W": p_out,
        "em_clutch_power_W": power,
        "em_clutch_share": power / p_out,
    }


def _screw_torques(f_n: float, d_m: float, lead: float, f: float, half_angle_deg: float):
    """Raising and lowering torque of a thread by Shigley's eqs. (8-1)/(8-5) and (8-2):
    through the calc module's M = F·d/2·tan(ψ ± φ'), tan φ' = f·sec α (α the half thread
    angle; 0 for a square thread)."""
    from advisor.calc import screw as sc

    psi = math.atan(lead / (math.pi * d_m))
    phi = math.atan(f / math.cos(math.radians(half_angle_deg)))
    return sc.torque_from_angles(f_n, d_m, psi, phi), sc.torque_from_angles(f_n, d_m, -psi, phi)


@model
def power_screw_with_collar(x: dict[str, Any]) -> Quantities:
    """A power screw with a thrust collar (Shigley, eqs. (8-1), (8-2), (8-4), (8-5), (8-6)):
    raising and lowering torque of the thread, collar torque, totals and efficiency. Any
    consistent units (the example's own)."""
    from advisor.calc import screw as sc

    f_n, d_m, lead = x["force"], x["mean_diameter"], x["lead"]
    raise_t, lower_t = _screw_torques(
        f_n, d_m, lead, x["friction_coefficient"], x.get("half_thread_angle_deg", 0.0)
    )
    collar = sc.collar_torque(f_n, x["collar_friction_coefficient"], x["collar_diameter"])
    return {
        "thread_raise_torque": raise_t,
        "thread_lower_torque": lower_t,
        "collar_torque": collar,
        "raise_torque": raise_t + collar,
        "lower_torque": lower_t + collar,
        "efficiency": sc.thread_efficiency_with_thrust(f_n, lead, raise_t, collar),
    }


@model
def trapezoidal_screw_with_collar(x: dict[str, Any]) -> Quantities:
    """A GOST/ISO trapezoidal thread of the catalog (d2 from GOST 24737-81) with a thrust
    collar at a speed: thread torque by the advisor's standard friction form, collar torque,
    power and overall efficiency (Bhandari's Ex. 6.6 procedure)."""
    from advisor.calc import screw as sc
    from catalogs import load_catalogs

    t = load_catalogs().thread(x["thread"])
    if t is None:
        raise ValueError(f"thread {x['thread']!r} is not in the catalog")
    f_n, d2, lead = x["force_N"], t.d2_mm * 1e-3, t.pitch_mm * 1e-3
    thread = sc.thread_torque(f_n, d2, lead, x["friction_coefficient"], "standard")
    collar = sc.collar_torque(
        f_n, x["collar_friction_coefficient"], (x["collar_outer_mm"] + x["collar_inner_mm"]) / 2e3
    )
    return {
        "mean_diameter_mm": t.d2_mm,
        "thread_torque_Nm": thread,
        "collar_torque_Nm": collar,
        "power_kW": (thread + collar) * x["speed_rpm"] * math.pi / 30.0 / 1e3,
        "efficiency_pct": 100.0 * sc.thread_efficiency_with_thrust(f_n, lead, thread, collar),
    }


@model
def bearing_rating_life(x: dict[str, Any]) -> Quantities:
    """ISO 281 basic rating life of a catalog bearing under a purely radial load."""
    from advisor.calc import bearing_life as bl
    from catalogs import load_catalogs

    b = load_catalogs().bearing(x["bearing"])
    if b is None:
        raise ValueError(f"bearing {x['bearing']!r} is not in the catalog")
    p = bl.equivalent_load(b, x["radial_N"], x.get("axial_N", 0.0)).load_N
    l10 = bl.rating_life_Mrev(b.C_kN * 1e3, p)
    return {
        "C_kN": b.C_kN,
        "L10_Mrev": l10,
        "L10h_h": bl.hours_from_Mrev(l10, x["speed_rpm"]),
    }


@model
def cube_mean_torque(x: dict[str, Any]) -> Quantities:
    """The strain-wave maker's average load torque T_av = (Σ n·t·|T|³ / Σ n·t)^(1/3)."""
    from advisor.calc import load_spectrum as ls

    phases = [
        ls.Load(t, n, s)
        for t, n, s in zip(x["torques_Nm"], x["speeds_rpm"], x["times_s"], strict=True)
    ]
    return {"average_torque_Nm": ls.cube_mean_torque(phases)}


@model
def sew_load_classification(x: dict[str, Any]) -> Quantities:
    """SEW's load classification from the mass acceleration factor."""
    from advisor.calc.service_factor import load_classification

    return {"load_classification": load_classification(x["mass_acceleration_factor"])}
