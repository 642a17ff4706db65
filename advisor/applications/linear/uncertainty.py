"""The linear actuator's checks over samples of its uncertain inputs, the design held fixed
(thread, starts, nut, motor).

Each check's margin is the reported one scaled by how its demand and its limit move with the
inputs: margin(x) = margin(x₀) · [limit(x)/limit(x₀)] · [demand(x₀)/demand(x)]. At the nominal
inputs this is the report's margin exactly; the demand and limit functions are the advisor's
own equations in numpy form (tests hold them equal to the scalar calc functions):

- core stress: σ_eq = √(σ² + 3τ²), σ = 4F/(π·d3²), τ = 16·M/(π·d3³) with the thread torque
  M = F·d2/2·tan(ψ + φ') (seed 001, eq. (1); the core carries the thread's torque alone);
- buckling: P_cr(L)/(S·F), Euler ∝ 1/L², Johnson's parabola below the transition;
- nut flank pressure ∝ F (the nut's turns are fixed); the thrust bearing's static load ∝ F;
- motor rated and starting torque against the drive torque (thread + thrust face);
- travel time and whirling: the motor's working speed on its fitted Kloss curve at that
  torque (the stable slip in closed form), the whirling speed ∝ 1/L².
A check not listed (the duty cycle's, a rule's) is reported as not modelled: its nominal
verdict only.
"""

import math
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import Any, NamedTuple

import numpy as np

#: Inputs this model takes, with the unit their key implies.
INPUTS = {
    "linear.force_N": "N",
    "linear.support_span_m": "m",
    "screw.friction_coefficient": "",
    "screw.thrust.friction_coefficient": "",
}

Margins = Callable[[dict[str, np.ndarray]], dict[str, np.ndarray]]


def thread_torque(force, d2_m: float, psi: float, f, model: str):
    """M = F·d2/2·tan(ψ + φ') with the reduced friction angle of
    :func:`advisor.calc.screw.friction_angle` (numpy)."""
    half = math.radians(15.0) if model == "standard" else psi / 2.0
    phi = np.arctan(np.asarray(f) / math.cos(half))
    return np.asarray(force) * d2_m / 2.0 * np.tan(psi + phi)


def core_stress(force, torque, d3_m: float):
    """von Mises stress of the screw core (:func:`advisor.calc.screw.core_equivalent_stress`)."""
    sigma = 4.0 * np.asarray(force) / (math.pi * d3_m**2)
    tau = 16.0 * np.asarray(torque) / (math.pi * d3_m**3)
    return np.sqrt(sigma**2 + 3.0 * tau**2)


def critical_load(d3_m: float, span, mu: float, e_pa: float, sy_pa: float):
    """P_cr of the core by Euler or Johnson (:func:`advisor.calc.screw.critical_buckling_load`)."""
    span = np.asarray(span, dtype=float)
    area, inertia = math.pi * d3_m**2 / 4.0, math.pi * d3_m**4 / 64.0
    lam = mu * span / (d3_m / 4.0)
    euler = math.pi**2 * e_pa * inertia / (mu * span) ** 2
    johnson = area * (sy_pa - (sy_pa * lam / (2.0 * math.pi)) ** 2 / e_pa)
    return np.where(lam >= math.pi * math.sqrt(2.0 * e_pa / sy_pa), euler, johnson)


def working_slip(curve: Any, torque):
    """The stable slip of a fitted Kloss curve under a load torque
    (:meth:`advisor.calc.induction.KlossCurve.stable_slip`, numpy; NaN where it stalls)."""
    m = np.asarray(torque, dtype=float)
    mk, eps = curve.max_torque_Nm, curve.epsilon
    with np.errstate(divide="ignore", invalid="ignore"):
        c = 2.0 * mk * (1.0 + eps) / m - 2.0 * eps
        x = (c - np.sqrt(np.maximum(c * c - 4.0, 0.0))) / 2.0
    s = x * curve.critical_slip
    s = np.where(m <= 0, 0.0, s)
    return np.where(m > mk, np.nan, s)


def _check(report: Any, cid: str) -> Any:
    return next((c for c in report.checks if c.id == cid), None)


class DemandArrays(NamedTuple):
    """The demands and limits the margins scale with, over samples of the inputs."""

    force: np.ndarray  # axial force  [N]
    core: np.ndarray  # von Mises stress of the core  [Pa]
    pcr: np.ndarray  # critical buckling load  [N]
    drive: np.ndarray  # thread + thrust-face torque  [N·m]
    n_work: np.ndarray  # the motor's working speed  [rpm]; NaN: it stalls
    whirl: np.ndarray  # ∝ the whirling speed: 1/L²  [1/m²]


@dataclass(frozen=True, slots=True)
class DemandModel:
    """One design's demands as numpy functions of the uncertain inputs: the thread, the
    thrust face, the steel, the end fixity and the motor's fitted curve held fixed."""

    d2_m: float
    d3_m: float
    lead_angle_rad: float
    friction_model: str
    thrust: Any  # advisor.calc.sizing.ThrustFace | None
    speed_rpm: float
    fixity_factor: float
    elastic_modulus_Pa: float
    yield_strength_Pa: float
    curve: Any  # advisor.calc.induction.KlossCurve
    synchronous_speed_rpm: float
    #: the motor's torque over the drive torque: the one-way device's 1/η, if any
    at_motor_ratio: float = 1.0

    def thrust_torque(self, force, fc):
        """The thrust face's friction torque: a collar's F·f_c·d_c/2, or a rolling bearing's
        SKF moment on a grid of forces, interpolated; none without a face."""
        thrust = self.thrust
        if thrust is None:
            return np.zeros_like(force)
        if thrust.kind == "collar":
            return np.abs(force) * fc * thrust.mean_diameter_m / 2.0
        grid = np.linspace(float(force.min()), float(force.max()), 33)
        torques = [thrust.torque_Nm(float(f), self.speed_rpm) for f in grid]
        return np.interp(force, grid, torques)

    def __call__(self, x: dict[str, np.ndarray]) -> DemandArrays:
        f_n = x["linear.force_N"]
        psi, model = self.lead_angle_rad, self.friction_model
        m_thread = thread_torque(f_n, self.d2_m, psi, x["screw.friction_coefficient"], model)
        fc = x.get("screw.thrust.friction_coefficient", 0.0)
        drive = m_thread + self.thrust_torque(f_n, fc)
        slip = working_slip(self.curve, drive * self.at_motor_ratio)
        span = x["linear.support_span_m"]
        return DemandArrays(
            force=f_n,
            core=core_stress(f_n, m_thread, self.d3_m),
            pcr=critical_load(
                self.d3_m, span, self.fixity_factor, self.elastic_modulus_Pa, self.yield_strength_Pa
            ),
            drive=drive,
            n_work=self.synchronous_speed_rpm * (1.0 - slip),
            whirl=1.0 / span**2,
        )


def _demand_model(req: Any, report: Any, cat: Any, thrust: Any) -> DemandModel:
    """The demand model of the design in ``report``, the motor's ratio still 1."""
    from advisor.calc.screw import END_FIXITY_FACTOR, lead_angle
    from advisor.calc.sizing import fit_motor

    s = report.design.screw
    thread = cat.thread(s.thread)
    d2 = thread.d2_mm * 1e-3
    steel = cat.steel(req.screw.screw_steel)
    motor = next(m for m in cat.motors if m.model == report.design.motor.model)
    return DemandModel(
        d2_m=d2,
        d3_m=thread.d3_mm * 1e-3,
        lead_angle_rad=lead_angle(thread.pitch_mm * 1e-3, d2, s.starts),
        friction_model=s.friction_model,
        thrust=thrust,
        speed_rpm=s.speed_rpm,
        fixity_factor=END_FIXITY_FACTOR[req.linear.end_fixity],
        elastic_modulus_Pa=steel.elastic_modulus_MPa * 1e6,
        yield_strength_Pa=steel.yield_strength_MPa * 1e6,
        curve=fit_motor(motor).curve,
        synchronous_speed_rpm=motor.synchronous_speed_rpm,
    )


#: How each modelled check's margin scales from its nominal one: f(demands, nominal demands).
SCALE: dict[str, Callable[[DemandArrays, DemandArrays], np.ndarray]] = {
    "core_stress": lambda d, d0: d0.core / d.core,
    "buckling": lambda d, d0: (d.pcr / d0.pcr) * (d0.force / d.force),
    "nut_pressure": lambda d, d0: d0.force / d.force,
    "thrust_bearing_static": lambda d, d0: d0.force / d.force,
    "motor_rated_torque": lambda d, d0: d0.drive / d.drive,
    "motor_starting_torque": lambda d, d0: d0.drive / d.drive,
    "travel_time": lambda d, d0: np.nan_to_num(d.n_work / d0.n_work, nan=0.0),
    "critical_speed": lambda d, d0: np.nan_to_num(
        (d.whirl / d0.whirl) * (d0.n_work / d.n_work), nan=np.inf
    ),
}
#: Checks whose margin does not move with the inputs: the nut is built, its proportions fixed.
CONSTANT = {"nut_height", "nut_turns"}


def margin_model(req: Any, report: Any, cat: Any) -> tuple[Margins, dict[str, float]]:
    """The margins of the design in ``report`` as functions of the uncertain inputs, and the
    nominal value of every input."""
    from advisor.applications.linear.advice import thrust_face

    s, lin = report.design.screw, req.linear
    thrust = thrust_face(req, cat)
    nominal = {
        "linear.force_N": lin.force_N,
        "linear.support_span_m": lin.support_span_m,
        "screw.friction_coefficient": s.friction_coefficient,
    }
    if thrust is not None and thrust.kind == "collar":
        nominal["screw.thrust.friction_coefficient"] = thrust.friction_coefficient
    # the motor sees the drive torque over the one-way device's efficiency (if any)
    model = _demand_model(req, report, cat, thrust)
    rated = _check(report, "motor_rated_torque")
    at_nominal = {k: np.array([v], dtype=float) for k, v in nominal.items()}
    d0_drive = model(at_nominal).drive[0]
    ratio = rated.value / d0_drive if rated is not None and d0_drive > 0 else 1.0
    model = replace(model, at_motor_ratio=ratio)
    d0 = model(at_nominal)

    def margins(x: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
        n = len(next(iter(x.values())))
        full = {
            k: np.broadcast_to(np.asarray(x.get(k, v), dtype=float), (n,))
            for k, v in nominal.items()
        }
        d = model(full)
        out = {}
        for c in report.checks:
            if c.id in SCALE:
                out[c.id] = c.margin * SCALE[c.id](d, d0)
            elif c.id in CONSTANT:
                out[c.id] = np.full(n, c.margin)
        return out

    return margins, nominal


def candidates(req: Any, cat: Any) -> list[tuple[str, int, int]]:
    """The drive options the advisor's joint choice (rule SCR-04) ranks, in its order of
    preference (:func:`rules.screw.drive_order`): (thread, starts, pole pairs) of each, with
    the smallest motor of that pole count that drives it. Built by the linear advice's own
    functions, so the robust choice looks at exactly the advisor's candidates."""
    from advisor.applications.linear.advice import screw_demand
    from advisor.applications.linear.choice import catalog_parts, drive_options, thread_screens
    from advisor.core.rulebook import Trace
    from rules import screw as screw_rules

    s, hold = req.screw, req.application.hold_without_power
    demand, _ = screw_demand(req, cat, Trace())
    screens = thread_screens(req, cat, demand)
    options = [
        o
        for o in drive_options(screens, catalog_parts(cat).lines)
        if s.thread is None or o.thread == s.thread
    ]
    options.sort(key=lambda o: screw_rules.drive_order(o, hold))
    return [(o.thread, o.starts, o.pole_pairs) for o in options]


def restricted(req: Any, cat: Any, option: tuple[str, int, int]) -> tuple[Any, Any]:
    """The requirement and catalog under which the advisor's own rules choose ``option``: the
    catalog holds its thread and the motors of its pole count, the requirement its starts."""
    thread, starts, pole_pairs = option
    from advisor.uncertainty import replaced

    req2 = replaced(req, screw=replaced(req.screw, starts=starts), uncertainty=None)
    cat2 = cat._replace(
        threads=tuple(t for t in cat.threads if t.name == thread),
        motors=tuple(m for m in cat.motors if m.poles == 2 * pole_pairs),
    )
    return req2, cat2


def default_inputs(req: Any, cat: Any, nominal: dict[str, float], given: set[str]) -> list:
    """The laws the data gives where the ``[uncertainty]`` table gives none: the screw's
    friction coefficient, uniform over its material pair's range for its lubrication (the
    catalog's friction pairs)."""
    from advisor.uncertainty.sampling import Distribution

    name = "screw.friction_coefficient"
    if name in given or name not in nominal:
        return []
    pair, lubrication = req.screw.material_pair, req.screw.lubrication
    lo, hi = cat.pair(pair).friction_range(lubrication)
    basis = f"default: the {pair} pair's friction range ({lubrication})"
    return [Distribution(name, "uniform", nominal[name], lo, hi, basis=basis)]


def design_label(report: Any) -> str:
    """The design in a few words: ``Tr18x4 (1 start) with 4A80A6``."""
    s, m = report.design.screw, report.design.motor
    return f"{s.thread} ({s.starts} start{'s' if s.starts > 1 else ''}) with {m.model}"
