"""The linear actuator's duty: a cage induction motor on 50 Hz driving the screw
through a cycle of moves, dwells and holds, or an IEC 60034-1 duty type.

Per move, at the motor: a direct-on-line start with the motor's mean starting torque
M_m (the mean of its refined Kloss curve between standstill and the working slip, the usual
approximation: Chilikin, «Общий курс электропривода», ch. 2) against the screw torque M_L, on
J_Σ = J_M + J_d + (J_screw + m·(L/2π)²/η)/η_d (a one-way device J_d, η_d at the motor side);
the run at the working point M(s) = M_L; switched off,
the load and the thread friction stop it (motor torque 0). The screw torque is seed 001's
M = F·d2/2·tan(ψ + φ') against the load and F·d2/2·tan(φ' − ψ) with it (negative: the load
drives the motor, which then generates above synchronous speed).

Thermal check: the equivalent torque over the cycle with the reduced cooling of the
self-ventilated motor at standstill (β0, :mod:`advisor.calc.duty`) against the rated torque.
The heat of the starts is not a torque (the starting current is 5–7 times the rated one); it
is counted by the starts per hour: z0 from the catalog's rated losses and rotor inertia, the
inertia factor FI, the load's share of the start heat, and the copper heat the running load
already takes (:func:`advisor.calc.duty.allowed_starts_per_hour`).
"""

import math
from dataclasses import dataclass, replace
from typing import Any, NamedTuple

from advisor.calc import duty as duty_calc
from advisor.calc import one_way as one_way_calc
from advisor.calc.duty import Phase
from advisor.calc.sizing import Check, fit_motor
from advisor.core.cite import cite
from advisor.core.errors import InfeasibleError, InputError
from advisor.core.rulebook import Trace
from advisor.duty.report import DutyOut, phases_out
from rules import duty as duty_rules
from rules.screw import thread_label

RPM = 30.0 / math.pi
STEEL_DENSITY_KG_M3 = 7850.0
#: S5 and S7: the heat of an electric (DC-injection) stop taken equal to that of a start
#: (the same kinetic energy is dissipated in the rotor; Chilikin, ch. 9).
ELECTRIC_BRAKING_HEAT = 1.0


def screw_torque(ev, force_N: float, direction: str, thrust: bool = True) -> float:
    """Seed 001's thread torque at the motor: against the load F·d2/2·tan(ψ + φ'); with the
    load F·d2/2·tan(φ' − ψ), negative when the load drives the screw back. With ``thrust``,
    the friction torque of the thrust face is added: it resists the motion
    whichever way the force acts."""
    half_d2 = ev.thread.d2_mm * 1e-3 / 2.0
    psi, phi = ev.lead_angle_rad, ev.friction_angle_rad
    face = getattr(ev, "thrust", None)
    extra = face.torque_Nm(force_N, ev.speed_rpm) if thrust and face is not None else 0.0
    if direction == "against":
        return force_N * half_d2 * math.tan(psi + phi) + extra
    return force_N * half_d2 * math.tan(phi - psi) + extra


def load_inertia(ev, moving_mass_kg: float, span_m: float) -> tuple[float, str]:
    """The screw's own inertia (a steel rod of the pitch diameter over the support span) and
    the moving mass through the lead, m·(L/2π)²/η, at the motor."""
    d2 = ev.thread.d2_mm * 1e-3
    lead_m = _lead_m(ev)
    j_screw = STEEL_DENSITY_KG_M3 * math.pi * d2**4 / 32.0 * span_m
    j_mass = moving_mass_kg * (lead_m / (2.0 * math.pi)) ** 2 / ev.efficiency
    return j_screw + j_mass, (
        f"screw ρ·π·d2⁴/32·l = {j_screw:.3g} kg·m² (steel, d2 over the support span) + mass "
        f"m·(L/2π)²/η = {j_mass:.3g} kg·m²"
    )


def _lead_m(ev) -> float:
    # revolutions = stroke / lead; tan ψ = lead/(π·d2)
    return math.tan(ev.lead_angle_rad) * math.pi * ev.thread.d2_mm * 1e-3


class MotorModel:
    """One catalog motor's curve, speeds and starts (scalar, no numpy), with what it turns:
    the screw side's inertia ``j_load`` (the screw and the moving mass) behind the one-way
    device ``passage``, whose own inertia ``j_device`` turns with the rotor."""

    def __init__(
        self, m, j_load: float, j_device: float = 0.0, passage=one_way_calc.NO_DEVICE
    ) -> None:
        self.m = m
        self.curve = fit_motor(m).curve  # the fit is cached by the ratings it depends on
        self.w0 = m.synchronous_speed_rpm * math.pi / 30.0
        self.j_rotor = m.inertia_kgm2 + j_device
        self.j_screw = j_load
        self.passage = passage
        #: beside the rotor while the motor drives the load through the device: J_L/η_d + J_d
        self.j_ext = j_load / passage.efficiency + j_device
        self.j = m.inertia_kgm2 + self.j_ext

    def slip(self, torque: float) -> float | None:
        """Working slip under a torque; a generating load (torque < 0) mirrors the curve."""
        if torque == 0:
            return 0.0
        s = self.curve.stable_slip(abs(torque))
        return None if s is None else math.copysign(s, torque)

    def mean_start_torque(self, s_work: float) -> float:
        """Mean of M(s) from standstill to the working slip (Simpson, 64 intervals)."""
        return self.curve.mean_torque(max(s_work, 0.0), 1.0, 64)

    def move(
        self, name: str, path_rad: float, load: float, screw: float | None = None
    ) -> tuple[list[Phase], float, float]:
        """Start, run, coast over a path at the motor: (phases, mean start torque, k_L).
        ``load``: the run's torque at the motor; ``screw``: the screw's own torque behind
        the device (signed, :func:`ramp_accelerations`), ``load`` where no device sits."""
        s = self.slip(load)
        if s is None:
            raise ValueError("stall")
        w = self.w0 * (1.0 - s)
        mm = self.mean_start_torque(max(s, 0.0))
        inertias = (self.j_rotor, self.j_screw)
        e1, e2 = ramp_accelerations(
            mm, load, load if screw is None else screw, inertias, self.passage, self.j
        )
        ramps = w * w / (2.0 * e1) + (w * w / (2.0 * e2) if e2 != math.inf else 0.0)
        if path_rad < ramps:  # a short move: switched off before reaching speed
            w = math.sqrt(2.0 * path_rad / (1.0 / e1 + (1.0 / e2 if e2 != math.inf else 0.0)))
            run = 0.0
        else:
            run = (path_rad - ramps) / w
        out = [Phase(f"{name}: start", w / e1, 0.0, w, mm)]
        if run > 0:
            out.append(Phase(f"{name}: run", run, w, w, load))
        if e2 != math.inf:
            out.append(Phase(f"{name}: coast", w / e2, w, 0.0, 0.0))
        return out, mm, mm / (mm - load) if load > 0 else 1.0


def ramp_accelerations(
    mean_start_Nm: float,
    load_Nm: float,
    screw_Nm: float,
    inertias: tuple[float, float],
    p: one_way_calc.Passage,
    j_forward: float,
) -> tuple[float, float]:
    """The start's and the coast's acceleration at the motor (magnitudes) of a move through
    the one-way device: M_m = M_dev(J_L·ε + M_s) + J_R·ε (J_R = J_M + J_d; J_L the screw
    side at the motor shaft; M_s the screw torque, signed; M_dev
    :func:`advisor.calc.one_way.motor_torque_through`), as the rotary cycle has it:

        driving (J_L·ε + M_s ≥ 0):    J = J_R + J_L/η_d,
            ε_start = (M_m − M_s/η_d)/J,   ε_coast = M_s/η_d / J
        a load lowered through a self-locking device (M_s < 0, lowering factor k):
            J = J_R − k·J_L,   ε_start = (M_m − k·|M_s|)/J   while J_L·ε ≤ |M_s| (the
            load's torque outweighs its inertia's), else the driving branch;
            ε_coast = k·|M_s|/J: the rotor's energy drives the load down; none (∞, the
            device locks at once) for k = 0 or J ≤ 0

    A back-drivable passage (the electromagnetic clutch, or no device) has η_d = 1.
    Parameters
    ----------
    mean_start_Nm : float
        The motor's mean starting torque M_m [N·m]
    load_Nm : float
        The run's torque at the motor, M_dev(M_s) [N·m]
    screw_Nm : float
        The screw torque M_s behind the device [N·m], < 0 where the load drives
    inertias : tuple[float, float]
        J_R and J_L at the motor shaft [kg·m²]
    p : Passage
        The device's driving efficiency η_d, back-drivability and lowering factor k
    j_forward : float
        J_R + J_L/η_d as the caller sums it [kg·m²]

    Returns
    -------
    tuple[float, float]
        Start and coast accelerations [rad/s²]; the coast's ∞ where it stops at once
    References
    ----------
    Seed 004 (the device's passage); Chilikin, ch. 2; docs/reference/duty.md.
    """
    j_rotor, j_load = inertias
    forward = (
        (mean_start_Nm - load_Nm) / j_forward,
        load_Nm / j_forward if load_Nm > 0 else math.inf,
    )
    if screw_Nm >= 0.0 or p.back_drivable:
        return forward
    k = p.lowering_factor
    j_back = j_rotor - k * j_load
    if j_back <= 0.0:  # the load's inertia outweighs what the device asks: driving branch
        return (mean_start_Nm - screw_Nm / p.efficiency) / j_forward, math.inf
    e_start = (mean_start_Nm - load_Nm) / j_back
    if j_load * e_start > -screw_Nm:
        e_start = (mean_start_Nm - screw_Nm / p.efficiency) / j_forward
    return e_start, load_Nm / j_back if load_Nm > 0 else math.inf


def _screw(ev) -> str:
    """The screw as the report designates it: Tr14x8(P2) for four starts of Tr14x2 (GOST
    24739-81), whose lead, not its pitch, decides whether it holds."""
    return thread_label(ev.thread.name, ev.starts)


def _unheld(ev, n: int, force: float, when: str) -> str:
    return (
        f"segment {n}: {when} the load of {force:g} N back-drives the screw {_screw(ev)} "
        "(not self-locking at the low end of its friction range) and an "
        f"induction motor on the line cannot hold a load at standstill; {UNHELD_REMEDY} for "
        "a one-way device"
    )


class CycleLoads(NamedTuple):
    """One cycle at the motor: its phases, the starts per hour, the worst load factor of a
    start k_L, the largest load torque, what is wrong with it, and the heat of its electric
    stops as a share of a start's (k_b)."""

    phases: list[Phase]
    starts_per_hour: float
    load_factor: float
    peak_load_Nm: float
    problems: list[str]
    braking_heat: float = 0.0


def _move_phases(ev, mot: MotorModel, n: int, seg, load: float, screw: float | None = None):
    """One move segment at the motor: its start, run and coast and the rest to its time_s,
    the start's load factor k_L (``None``: the motor stalls under the load) and what is
    wrong with it. ``screw``: the screw's torque behind the device (``load`` without one)."""
    label = f"{n} {seg.kind}"
    try:
        path_rad = seg.distance_m / _lead_m(ev) * 2.0 * math.pi
        phases, _, k_l = mot.move(label, path_rad, load, screw)
    except ValueError:
        return (
            [],
            None,
            [
                f"segment {n}: the screw asks {load:.3g} N·m, above the maximum torque "
                f"{mot.curve.max_torque_Nm:.3g} N·m of {mot.m.model}"
            ],
        )
    problems = []
    t = duty_calc.cycle_time(phases)
    if t > seg.time_s * (1 + 1e-9):
        problems.append(
            f"segment {n}: the move of {seg.distance_m:g} m takes {t:.4g} s with "
            f"{mot.m.model}, longer than its time_s = {seg.time_s:g} s"
        )
    if seg.time_s > t:
        phases.append(Phase(f"{label}: rest", seg.time_s - t, 0.0, 0.0, 0.0))
    return phases, k_l, problems


def _segments_cycle(
    req, ev, mot: MotorModel, holder: str | None, passage=one_way_calc.NO_DEVICE
) -> CycleLoads:
    """The cycle of the duty's segments.

    A load stands on the screw from a move or a hold until a dwell takes it off. Where it
    back-drives the screw, something must hold it whenever the motor is off (the stop of a
    move, its rest, a hold, the cycle's closing rest): the self-locking screw, or the one-way
    device; an induction motor on the line holds nothing at standstill. Through the device
    the motor gives the screw torque over its efficiency, and a self-locking device passes
    no torque back (:func:`advisor.calc.one_way.motor_torque_through`)."""
    duty, lin = req.duty, req.linear
    phases: list[Phase] = []
    problems: list[str] = []
    starts, k_l, peak_load = 0, 1.0, 0.0
    standing = 0.0  # the force on the screw at rest
    for n, seg in enumerate(duty.segments, 1):
        force = lin.force_N if seg.force_N is None else seg.force_N
        if seg.kind != "move":
            if seg.kind == "hold" and holder is None and force > 0:
                problems.append(_unheld(ev, n, force, "holding at standstill,"))
            phases.append(Phase(f"{n} {seg.kind}", seg.time_s, 0.0, 0.0, 0.0))
            standing = force if seg.kind == "hold" else 0.0
            continue
        screw = screw_torque(ev, force, seg.direction)
        load = one_way_calc.motor_torque_through(passage, screw) if holder == "one_way" else screw
        peak_load = max(peak_load, abs(load))
        if holder is None and force > 0:
            problems.append(_unheld(ev, n, force, "switched off at the end of the move,"))
        move, k_move, trouble = _move_phases(ev, mot, n, seg, load, screw)
        problems += trouble
        if k_move is None:
            continue
        phases += move
        starts += 1
        k_l = max(k_l, k_move)
        standing = force
    rest = 3600.0 / duty.cycles_per_hour - sum(s.time_s for s in duty.segments)
    if rest > 1e-9:
        if holder is None and standing > 0:
            problems.append(
                _unheld(ev, len(duty.segments), standing, "in the cycle's closing rest")
            )
        phases.append(Phase("rest", rest, 0.0, 0.0, 0.0))
    return CycleLoads(phases, starts * duty.cycles_per_hour, k_l, peak_load, problems)


#: The IEC duty types whose cycle starts and stops the motor: their starts are counted.
START_STOP_TYPES = ("S4", "S5", "S7")


def _start_stop_phases(
    duty_type: str,
    mot: MotorModel,
    load: float,
    w: float,
    mean_start: float,
    period: float,
    on: float,
):
    """S4, S5, S7: a direct-on-line start with the mean starting torque, the run, an electric
    stop (S5, S7) with the same mean torque, and the rest; (phases, k_b, problems)."""
    on = period if duty_type == "S7" else on
    t_start = mot.j * w / (mean_start - load)
    brake = mot.j * w / (mean_start + load) if duty_type in ("S5", "S7") else 0.0
    braking = ELECTRIC_BRAKING_HEAT if brake else 0.0
    run = on - t_start - brake
    problems = []
    if run < 0:
        problems.append(
            f"{duty_type}: the start ({t_start:.3g} s) and the stop ({brake:.3g} s) take longer "
            f"than the time under load, {on:.4g} s"
        )
        run = 0.0
    phases = [Phase("start", t_start, 0.0, w, mean_start), Phase("run", run, w, w, load)]
    if brake:
        phases.append(Phase("electric brake", brake, w, 0.0, -mean_start))
    if period - on > 0:
        phases.append(Phase("rest", period - on, 0.0, 0.0, 0.0))
    return phases, braking, problems


def _shared_load_phases(duty, mot: MotorModel, load: float, period: float):
    """S9, S10: the loads as shares of the rated one; (phases, k_b, problems)."""
    phases, problems = [], []
    for k, x in enumerate(duty.loads, 1):
        slip = mot.slip(x.load_share * load)
        if slip is None:
            problems.append(f"load {k}: {mot.m.model} stalls under {x.load_share:g} × load")
            slip = 0.0
        w = mot.w0 * (1.0 - slip)
        phases.append(Phase(f"load {k}", x.time_share * period, w, w, x.load_share * load))
    return phases, 0.0, problems


def _iec_phases(duty, mot: MotorModel, load: float, w: float, mean_start: float, period: float):
    """The phases of one cycle of an IEC 60034-1 duty type; (phases, k_b, problems)."""
    t = duty.duty_type
    on = (duty.cyclic_duration_factor or 1.0) * period
    if t == "S1":
        return [Phase("run", period, w, w, load)], 0.0, []
    if t == "S2":  # one run for the stated time; the rest until cold is not a cycle
        return [Phase("run", duty.duration_min * 60.0, w, w, load)], 0.0, []
    if t == "S3":
        return [Phase("run", on, w, w, load), Phase("rest", period - on, 0.0, 0.0, 0.0)], 0.0, []
    if t == "S6":  # unloaded, the cage motor runs at its synchronous speed (slip 0)
        idle = Phase("no load", period - on, mot.w0, mot.w0, 0.0)
        return [Phase("run", on, w, w, load), idle], 0.0, []
    if t in START_STOP_TYPES:
        return _start_stop_phases(t, mot, load, w, mean_start, period, on)
    return _shared_load_phases(duty, mot, load, period)


def _iec_cycle(req, ev, mot: MotorModel, passage=one_way_calc.NO_DEVICE) -> CycleLoads:
    """One cycle of an IEC 60034-1 duty type at the rated force's screw torque (through the
    holding device's efficiency where one sits at the motor). Starts are counted where the
    duty type starts the motor (S4, S5, S7): in S3 and S6 starting does not significantly
    affect the temperature (IEC 60034-1), and their starts_per_hour is said ignored."""
    duty = req.duty
    load = one_way_calc.motor_torque_through(passage, ev.torque_Nm)
    slip = mot.slip(load)
    if slip is None:
        return CycleLoads([], 0.0, 1.0, load, [f"{mot.m.model} stalls under {load:.3g} N·m"])
    w = mot.w0 * (1.0 - slip)
    starts_h = duty.starts_per_hour or 0.0
    period = 3600.0 / starts_h if duty.duty_type in START_STOP_TYPES else duty.cycle_time_s
    mean_start = mot.mean_start_torque(slip)
    k_l = mean_start / (mean_start - load)
    phases, braking, problems = _iec_phases(duty, mot, load, w, mean_start, period)
    if duty.duty_type not in START_STOP_TYPES:
        starts_h = 0.0
    # the load's torque: the motor's own starting and braking torques are not a demand
    peak = max(
        (abs(p.torque_Nm) for p in phases if "start" not in p.name and "brake" not in p.name),
        default=0.0,
    )
    return CycleLoads(phases, starts_h, k_l, peak, problems, braking)


def _cycle(req, ev, mot: MotorModel, holder: str | None, passage) -> CycleLoads:
    """The cycle of the duty's segments or of its IEC duty type."""
    if req.duty.segments:
        return _segments_cycle(req, ev, mot, holder, passage)
    cycle = _iec_cycle(req, ev, mot, passage)
    if holder is None and req.linear.force_N > 0:  # the same rule as for the segments
        cycle.problems.append(
            f"{req.duty.duty_type}: the load of {req.linear.force_N:g} N back-drives the screw "
            f"{_screw(ev)} (not self-locking at the low end of its friction range) "
            "whenever the motor stops, and an induction motor on the line cannot hold a "
            f"load at standstill; {UNHELD_REMEDY} for a one-way device"
        )
    return cycle


@dataclass(frozen=True, slots=True)
class CycleEvaluation:
    """The cycle with one catalog motor: its phases, the thermal figures, the starts and
    every problem (none: the motor passes)."""

    motor: Any
    phases: list[Phase]
    #: the equivalent torque (the S2 run's torque for S2) and the rated torque  [N·m]
    rms_torque_Nm: float
    rated_torque_Nm: float
    #: the thermal limit of the equivalent torque: K·M_n (K of S2, else 1)  [N·m]
    limit_Nm: float
    s2_factor: float
    #: SEW's S3 factor K and the S3 running torque it is held against  [N·m]
    s3_factor: float
    s3_running_torque_Nm: float
    starts_per_hour: float
    allowed_starts_per_hour: float
    no_load_starts_per_hour: float
    inertia_factor: float
    #: k_L = M_m/(M_m − M_L): the load's share of a start's heat
    load_factor: float
    #: the largest load torque of the cycle and the motor's starting torque  [N·m]
    peak_load_Nm: float
    starting_torque_Nm: float
    mean_starting_torque_Nm: float | None
    braking_heat: float
    problems: list[str]


def _limit_problems(e: CycleEvaluation) -> list[str]:
    """The thermal, starts and starting-torque limits the cycle exceeds, in words."""
    problems, rated, k_s2 = [], e.rated_torque_Nm, e.s2_factor
    if e.rms_torque_Nm > e.limit_Nm:
        problems.append(
            # a product printed multiplies out: 1.2 × 5.1525 = 6.183 (5.152 would not)
            f"RMS torque {e.rms_torque_Nm:.4g} N·m above the rated {rated:.5g} N·m × K = "
            f"{k_s2:g} for S2 = {e.limit_Nm:.4g} N·m"
            if k_s2 != 1.0
            else f"RMS torque {e.rms_torque_Nm:.4g} N·m above the rated {rated:.4g} N·m"
        )
    k_s3, run_s3 = e.s3_factor, e.s3_running_torque_Nm
    if run_s3 > k_s3 * rated:
        problems.append(
            f"S3 running torque {run_s3:.4g} N·m above K·M_n = {k_s3:g} × {rated:.5g} = "
            f"{k_s3 * rated:.4g} N·m (SEW's S3 factor)"
        )
    if e.starts_per_hour > e.allowed_starts_per_hour:
        problems.append(
            f"{e.starts_per_hour:.4g} starts/h above the {e.allowed_starts_per_hour:.4g} it allows"
        )
    if e.peak_load_Nm > e.starting_torque_Nm:
        problems.append(
            f"the load torque {e.peak_load_Nm:.4g} N·m above the starting torque "
            f"{e.starting_torque_Nm:.4g}"
        )
    return problems


def evaluate(
    req,
    ev,
    m,
    j_load: float,
    holder: str | None,
    passage=one_way_calc.NO_DEVICE,
    j_device: float = 0.0,
) -> CycleEvaluation:
    """The cycle with motor m: phases, RMS, starts and every problem. ``j_load``: the
    screw side's inertia at the motor shaft (the screw and the moving mass), behind the
    device; ``j_device``: a one-way device at the motor side, turning with the rotor;
    ``holder``: what holds the load at standstill ('screw', 'one_way' or None);
    ``passage``: the one-way device's (the motor accelerates J_L through it: J_L/η_d)."""
    passage = passage if holder == "one_way" else one_way_calc.NO_DEVICE
    mot = MotorModel(m, j_load, j_device, passage)
    duty = req.duty
    cycle = _cycle(req, ev, mot, holder, passage)
    phases = cycle.phases
    # a start's heat, the load's share included (k_L), and an electric stop's (k_b) are
    # counted by the starts per hour: in the equivalent torque each counts as a ramp at zero
    # torque, else the heat would be counted twice
    thermal = [p._replace(torque_Nm=0.0) if _counted_by_starts(p) else p for p in phases]
    rms = duty_calc.rms_torque(thermal, duty.standstill_cooling_factor) if phases else 0.0
    rated = m.rated_torque_Nm
    # S2: SEW's power increasing factor K raises the thermal limit to K·M_n (same speed)
    k_s2 = duty_calc.s2_power_factor(duty.duration_min) if duty.duty_type == "S2" else 1.0
    p_loss = m.rated_power_kW * 1e3 * (100.0 / m.efficiency_pct - 1.0)
    ramp = (1.0 + duty.standstill_cooling_factor) / 2.0
    z0 = duty_calc.no_load_starts_per_hour(p_loss, m.inertia_kgm2, mot.w0, ramp)
    fi = duty_calc.inertia_factor(m.inertia_kgm2, mot.j_ext)
    k_l = cycle.load_factor
    s3 = duty.duty_type == "S3"
    # S3: the running torque also against SEW's K·M_n for the cdf (the stricter decides)
    record = CycleEvaluation(
        motor=m,
        phases=phases,
        rms_torque_Nm=rms,
        rated_torque_Nm=rated,
        limit_Nm=k_s2 * rated,
        s2_factor=k_s2,
        s3_factor=duty_calc.s3_factor_for_cycle(duty.cyclic_duration_factor, duty.cycle_time_s)
        if s3
        else 1.0,
        s3_running_torque_Nm=phases[0].torque_Nm if s3 and phases else 0.0,
        starts_per_hour=cycle.starts_per_hour,
        allowed_starts_per_hour=duty_calc.allowed_starts_per_hour(
            z0, fi, k_l, rms / rated, 1.0, cycle.braking_heat
        ),
        no_load_starts_per_hour=z0,
        inertia_factor=fi,
        load_factor=k_l,
        peak_load_Nm=cycle.peak_load_Nm,
        starting_torque_Nm=mot.curve.torque(1.0),
        mean_starting_torque_Nm=_mean_start(phases),
        braking_heat=cycle.braking_heat,
        problems=[],
    )
    return replace(record, problems=[*cycle.problems, *_limit_problems(record)])


def _zero_torque_words(phases: list[Phase]) -> str:
    """Which phases the equivalent torque counts at zero torque, and why, in words."""
    if any(p.name == "electric brake" for p in phases):
        return (
            "A start and an electric stop count at zero torque: their heat, the load's share "
            "included, is counted by the starts per hour (k_b for the stop)."
        )
    return (
        "A start counts at zero torque: its heat, the load's share included, is counted by "
        "the starts per hour."
    )


def _counted_by_starts(p: Phase) -> bool:
    """A start or an electric stop: its heat is counted by the starts per hour."""
    return p.name.endswith("start") or p.name == "electric brake"


def _held_by(ev, holder: str | None, passage) -> str:
    """What holds the load whenever the motor is off, in words for the report."""
    if holder == "screw":
        return f"the screw {_screw(ev)}, self-locking over its whole friction range"
    if holder == "one_way":
        return f"the {passage.type.replace('_', ' ')} at the motor side"
    return "nothing: no load stands on the screw while the motor is off"


def _mean_start(phases: list[Phase]) -> float | None:
    """The motor's mean starting torque where the cycle has a start (the same in every one)."""
    return next((p.torque_Nm for p in phases if p.name.endswith("start")), None)


def segment_loads_within_rating(req) -> None:
    """A segment's force above linear.force_N is refused: the screw, the nut and the holding
    device are sized for the rated force, and a larger one in the cycle would pass unchecked.
    So is an S9 or S10 load share above 1: it loads the screw with share × linear.force_N."""
    rated = req.linear.force_N
    for k, x in enumerate(req.duty.loads or (), 1):
        if req.duty.duty_type in ("S9", "S10") and x.load_share > 1.0:
            raise InputError(
                f"duty.loads[{k}].load_share = {x.load_share:g}: loads the screw with "
                f"{x.load_share * rated:g} N, above linear.force_N = {rated:g}, the force the "
                "screw, nut and holding device are sized for; raise linear.force_N to the "
                "largest force of the cycle and give the shares of it (at most 1)"
            )
    if not req.duty.segments:
        return
    for n, seg in enumerate(req.duty.segments, 1):
        if seg.force_N is not None and seg.force_N > rated:
            raise InputError(
                f"duty.segments[{n}].force_N = {seg.force_N:g}: above linear.force_N = "
                f"{rated:g}, the force the screw, nut and holding device are sized for; raise "
                "linear.force_N to the largest force of the cycle"
            )


#: The words of :func:`_unheld`'s remedy, by which a refusal tells its cause.
UNHELD_REMEDY = "set application.hold_without_power = true"


def _no_motor_for_cycle(ev, tried: list) -> InfeasibleError:
    """The refusal when no motor passes the cycle. Where every motor fails because the load
    back-drives an unheld screw (:func:`_unheld`), no motor size or travel time cures it:
    the refusal names that cause and its remedies instead of larger motors."""
    shown = [tried[0], tried[-1]] if len(tried) > 1 else tried
    lines = [f"{e.motor.model}: " + "; ".join(e.problems) for e in shown]
    if all(any(UNHELD_REMEDY in p for p in e.problems) for e in tried):
        return InfeasibleError(
            f"no feasible design: the load back-drives the screw {_screw(ev)} whenever the "
            "motor is off, and nothing holds it",
            [
                *lines,
                "no motor size or travel time cures this: set application.hold_without_power = "
                "true (a one-way device at the motor side holds the load), choose a thread "
                "that is self-locking at the low end of its friction range (fewer starts, a finer "
                "pitch, or a pair of higher friction), or hold it with a brake",
            ],
        )
    return InfeasibleError(
        "no feasible design: no motor of the chosen pole count passes the duty cycle",
        [
            *lines,
            "larger motors of the same pole count were tried; the moves run at the speed "
            "chosen for linear.travel_time_s (a shorter one picks a faster motor)",
        ],
    )


def _motor_for_cycle(req, ev, selected, cat, holder, passage, inertias, j_basis, trace: Trace):
    """The point's motor, or the next larger of its pole count, the first that passes the
    cycle (rule DU-08); infeasible when none does. ``inertias``: the screw side's J_L and
    the device's J_d at the motor shaft."""
    duty = req.duty
    line = [
        m
        for m in cat.motors_with_poles(selected.poles)
        if m.rated_power_kW >= selected.rated_power_kW
    ]
    tried = [evaluate(req, ev, m, inertias[0], holder, passage, inertias[1]) for m in line]
    ok = [e for e in tried if not e.problems]
    if duty.duty_type:
        trace.apply(
            duty_rules.duty_type,
            duty.duty_type,
            duty_calc.IEC_DUTY_TYPES[duty.duty_type],
            _iec_how(duty),
        )
    if not ok:
        raise _no_motor_for_cycle(ev, tried)
    rows = {x.motor.model: (x.motor.rated_power_kW, x.problems) for x in tried}
    trace.apply(duty_rules.motor_for_cycle_linear, rows, selected.model, j_basis)
    return ok[0]


def _thermal_verdict(duty, e: CycleEvaluation, trace: Trace) -> tuple[float, str]:
    """The thermal utilisation of the motor and its basis: the equivalent torque (the run's
    for S2, against SEW's K·M_n) over the rated torque, and for S3 also the running torque
    against SEW's S3 factor, the larger deciding."""
    m, rms, rated, limit = e.motor, e.rms_torque_Nm, e.rated_torque_Nm, e.limit_Nm
    beta0 = duty.standstill_cooling_factor
    util, k_s2, k_s3 = rms / limit, e.s2_factor, e.s3_factor
    if duty.duty_type == "S2":
        trace.apply(duty_rules.power_increasing_factor, "S2", duty.duration_min, k_s2)
        thermal_how = (
            f"Torque of the S2 run {rms:.4g} N·m against K·M_n = {k_s2:g} × "
            f"{rated:.5g} = {limit:.4g} N·m of {m.model} (DU-09: SEW's power "
            "increasing factor for S2, at the same speed a factor on the torque)."
        )
        basis = f"torque of the S2 run over K·M_n (K = {k_s2:g}, SEW's S2 factor)"
    else:
        thermal_how = (
            f"Equivalent torque √(Σ M²·t / Σ β·t) = {rms:.4g} N·m against the rated "
            f"{rated:.4g} N·m of {m.model}; β = 1 at speed, β0 = {beta0:g} at standstill, "
            f"(1 + β0)/2 in a ramp (a self-ventilated motor, IP44). " + _zero_torque_words(e.phases)
        )
        basis = f"equivalent torque (β0 = {beta0:g} at standstill) over the rated torque"
    if duty.duty_type == "S3":
        cdf, run_s3 = duty.cyclic_duration_factor, e.s3_running_torque_Nm
        trace.apply(
            duty_rules.power_increasing_factor, "S3", cdf, k_s3, cdf * duty.cycle_time_s / 60.0
        )
        util_k = run_s3 / (k_s3 * rated)
        thermal_how += (
            f" Beside it SEW's S3 factor (DU-09): the running torque {run_s3:.4g} N·m "
            f"against K·M_n = {k_s3:g} × {rated:.5g} = {k_s3 * rated:.4g} N·m, "
            f"utilisation {util_k:.3g} against {util:.3g} by the equivalent torque; the "
            "larger decides."
        )
        if util_k > util:
            util = util_k
            basis = f"S3 running torque over K·M_n (K = {k_s3:g}, SEW's S3 factor)"
    trace.apply(duty_rules.thermal, util, thermal_how)
    return util, basis


def _peak_verdict(e: CycleEvaluation, trace: Trace) -> None:
    """The largest load torque of the cycle against the motor's starting torque."""
    peak = duty_calc.peak_torque(e.phases)
    trace.apply(
        duty_rules.peak,
        e.peak_load_Nm,
        e.starting_torque_Nm,
        "The largest load torque of the cycle against the motor's starting torque (from the "
        "catalog's M_start/M_n): the motor must start under it. "
        + (
            f"The peak of the cycle, {peak:.4g} N·m, is the motor's own mean starting torque "
            "in a start."
            if any(p.name.endswith("start") for p in e.phases)
            else f"No start is counted in this duty: the cycle's peak is the running torque "
            f"{peak:.4g} N·m."
        ),
        peak,
    )


def _starts_basis(e: CycleEvaluation) -> str:
    """How the starts the motor allows per hour are derived, in words."""
    m = e.motor
    return (
        f"z = z0·(1 − (M_eq/M_n)²)/(FI·k_L·(1 + k_b)): z0 = 3600·P_loss·(1 + β0)/2/(J_M·ω0²)"
        f" = {e.no_load_starts_per_hour:.4g} no-load starts/h (derived: the catalog gives "
        "none) from the rated losses "
        f"{m.rated_power_kW * 1e3 * (100.0 / m.efficiency_pct - 1.0):.4g} W (its efficiency "
        f"{m.efficiency_pct:g} %, an estimated value) and rotor inertia {m.inertia_kgm2:g} kg·m²; "
        f"FI = {e.inertia_factor:.3g}; k_L = M_m/(M_m − M_L) = {e.load_factor:.3g}; "
        f"k_b = {e.braking_heat:g}. "
        "A start heats rotor and stator by J·ω0²/2 each (R1/R2' = 1): Chilikin, ch. 9."
    )


def _duty_warnings(inertia_ratio: float, within: bool, m, selected) -> list[str]:
    """The inertia ratio above its guideline, and a motor larger than the point's."""
    warnings = []
    if not within:
        warnings.append(
            f"duty: the load's inertia at the motor is {inertia_ratio:.3g} times the motor's "
            f"(guideline {duty_rules.INERTIA_RATIO_GUIDELINE:g})"
        )
    if m.model != selected.model:
        warnings.append(
            f"duty: the cycle needs {m.model} ({m.rated_power_kW:g} kW), larger than "
            f"{selected.model} for the rated point"
        )
    return warnings


def _upper_check(cid: str, name: str, value: float, limit: float, unit: str, source) -> Check:
    """A check of the form value ≤ limit; margin limit / value (∞ for no demand)."""
    return Check(cid, name, value, limit, unit, limit / value if value > 0 else math.inf, source)


def _duty_checks(duty, e: CycleEvaluation) -> list[Check]:
    """The cycle's checks: equivalent (or S2 run's) torque, peak load torque, the S3 running
    torque and the starts per hour where they apply."""
    s2 = duty.duty_type == "S2"
    checks = [
        _upper_check(
            "duty_rms_torque",
            f"torque of the S2 run within K·M_n (K = {e.s2_factor:g}, SEW's S2 factor)"
            if s2
            else "equivalent torque of the cycle within the rated torque",
            e.rms_torque_Nm,
            e.limit_Nm,
            "N·m",
            duty_rules.SEW_K + duty_rules.IEC_60034_1
            if s2
            else duty_rules.KLYUCHEV + duty_rules.DUTY_METHOD,
        ),
        _upper_check(
            "duty_peak_torque",
            "largest load torque of the cycle within the starting torque",
            e.peak_load_Nm,
            e.starting_torque_Nm,
            "N·m",
            cite("4a-table", "M_start/M_n") + duty_rules.DUTY_METHOD,
        ),
    ]
    if duty.duty_type == "S3":
        checks.append(
            _upper_check(
                "duty_s3_factor",
                f"S3 running torque within K·M_n (K = {e.s3_factor:g}, SEW's S3 factor)",
                e.s3_running_torque_Nm,
                e.s3_factor * e.rated_torque_Nm,
                "N·m",
                duty_rules.SEW_K + duty_rules.IEC_60034_1,
            )
        )
    if e.starts_per_hour > 0:
        checks.append(
            Check(
                "duty_starts_per_hour",
                "starts per hour within what the motor allows",
                e.starts_per_hour,
                e.allowed_starts_per_hour,
                "1/h",
                e.allowed_starts_per_hour / e.starts_per_hour,
                duty_rules.IEC_60034_1,
            )
        )
    return checks


def _duty_out(duty, ev, e: CycleEvaluation, thermal, inertia_ratio: float, held_by: str):
    """The duty table of the report, from the cycle of the chosen motor."""
    phases = e.phases
    out_J, _ = duty_calc.energies(phases)
    # an electric (DC-injection) stop dissipates the kinetic energy in the rotor, below the
    # synchronous speed: nothing of it reaches the supply
    _, back_J = duty_calc.energies([p for p in phases if p.name != "electric brake"])
    t_cycle = duty_calc.cycle_time(phases)
    counted = e.starts_per_hour > 0  # allowed starts mean something only where counted
    # S1 runs continuously and S2 is one run from cold: no cycle that repeats
    per_hour = None if duty.duty_type in ("S1", "S2") else 3600.0 / t_cycle if t_cycle else 0.0
    return DutyOut.make(
        motor=e.motor.model,
        ratio=2.0 * math.pi / _lead_m(ev),
        cycle_time_s=t_cycle,
        move_time_s=sum(p.time_s for p in phases if p.speed_start_rad_s or p.speed_end_rad_s),
        # the check's demand and capacity: the largest load torque at the motor against the
        # starting torque; the motor's own mean starting torque stated beside them
        peak_torque_Nm=e.peak_load_Nm,
        peak_torque_limit_Nm=e.starting_torque_Nm,
        mean_starting_torque_Nm=e.mean_starting_torque_Nm,
        rms_torque_Nm=e.rms_torque_Nm,
        rated_torque_Nm=e.rated_torque_Nm,
        thermal_utilisation=thermal[0],
        thermal_basis=thermal[1],
        inertia_ratio=inertia_ratio,
        inertia_ratio_guideline=duty_rules.INERTIA_RATIO_GUIDELINE,
        energy_per_cycle_J=out_J,
        regenerated_per_cycle_J=back_J,
        mean_speed_rpm=duty_calc.mean_speed(phases) * RPM,
        cycles_per_hour=per_hour,
        duty_type=duty.duty_type or "cycle",
        held_by=held_by,
        regenerated_to=REGENERATED_TO if back_J > 0 else None,
        standstill_cooling_factor=duty.standstill_cooling_factor,
        starts_per_hour=e.starts_per_hour,
        allowed_starts_per_hour=e.allowed_starts_per_hour if counted else None,
        no_load_starts_per_hour=e.no_load_starts_per_hour if counted else None,
        inertia_factor=e.inertia_factor,
        phases=phases_out(phases),
    )


#: Where the energy a generating motor gives back goes, on the line.
REGENERATED_TO = (
    "the supply: a motor on the line generates above its synchronous speed straight "
    "into the mains, so there is no DC bus and no braking resistor to size (on an "
    "inverter the bus would take it: see the rotary drive's [drive] table)"
)


def advise_duty(
    req,
    ev,
    selected,
    cat,
    holder: str | None,
    trace: Trace,
    passage=one_way_calc.NO_DEVICE,
    device_inertia_kgm2: float = 0.0,
):
    """The motor for the cycle: the point's motor, or the next larger of its pole count that
    passes; the duty table, the motor, the checks and the warnings.

    ``device_inertia_kgm2``: the one-way device at the motor side turns with the rotor (a
    1:1 element): its inertia J_d adds to the motor side's, and the motor accelerates the
    screw side through it as it drives the load, J_Σ = J_M + J_d + J_load/η_d, in every
    start, stop and start count (FI) (a load lowered through a self-locking device:
    :func:`ramp_accelerations`); the inertia ratio is J_load/(J_M + J_d), the rotary's
    without η_d."""
    segment_loads_within_rating(req)
    duty = req.duty
    j_load, j_basis = load_inertia(ev, duty.moving_mass_kg, req.linear.support_span_m)
    j_dev = device_inertia_kgm2 if holder == "one_way" else 0.0
    if j_dev > 0:
        j_basis += f" + the {passage.type.replace('_', ' ')} at the motor side {j_dev:.3g} kg·m²"
    if j_dev > 0 and passage.efficiency < 1.0:
        j_basis += (
            f"; the motor accelerates the screw side through the {passage.type.replace('_', ' ')}"
            f": J_L/η_d = {j_load:.3g}/{passage.efficiency:.5g} = "
            f"{j_load / passage.efficiency:.3g} kg·m² in its starts and stops"
        )
    inertias = (j_load, j_dev)
    e = _motor_for_cycle(req, ev, selected, cat, holder, passage, inertias, j_basis, trace)
    m = e.motor
    thermal = _thermal_verdict(duty, e, trace)
    _peak_verdict(e, trace)
    if e.starts_per_hour > 0:
        trace.apply(
            duty_rules.starts, e.starts_per_hour, e.allowed_starts_per_hour, _starts_basis(e)
        )
    inertia_ratio = j_load / (m.inertia_kgm2 + j_dev)
    within = trace.apply(duty_rules.inertia_ratio, inertia_ratio)
    warnings = _duty_warnings(inertia_ratio, within, m, selected)
    out = _duty_out(duty, ev, e, thermal, inertia_ratio, _held_by(ev, holder, passage))
    return out, m, _duty_checks(duty, e), warnings


def _iec_how(duty) -> str:
    t = duty.duty_type
    if t == "S1":
        return f"One run at the rated force's screw torque for {duty.cycle_time_s:g} s."
    if t == "S2":
        return (
            f"One run at the rated force's screw torque for duration_min = "
            f"{duty.duration_min:g} min, then rest until the motor is cold (not part of the "
            "cycle); the limit is K·M_n with SEW's S2 factor K (DU-09)."
        )
    if t in ("S3", "S6"):
        return (
            f"Run at the rated force for cdf = {duty.cyclic_duration_factor:g} of a "
            f"{duty.cycle_time_s:g} s cycle, then "
            + (
                "rest at standstill; the running torque is also checked against SEW's S3 "
                "factor (DU-09)."
                if t == "S3"
                else "run without load."
            )
        )
    if t in ("S4", "S5", "S7"):
        return (
            f"{duty.starts_per_hour:g} cycles per hour of 3600/{duty.starts_per_hour:g} s: a "
            "direct-on-line start with the mean starting torque, the run at the rated force"
            + (", an electric (DC-injection) stop" if t != "S4" else "")
            + ("" if t == "S7" else f", rest for 1 − cdf = {1 - duty.cyclic_duration_factor:g}")
            + "."
        )
    return f"The loads as shares of the rated force's torque over a {duty.cycle_time_s:g} s cycle."
