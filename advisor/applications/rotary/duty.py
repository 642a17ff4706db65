"""The rotary actuator's duty: the PM brushless motor and its wave-gear reducer
through a cycle of moves, dwells and holds, or an IEC 60034-1 duty type.

Per phase, the torque the output needs is M_out = J_L·ε_out ± M_L (the load torque against
or with the motion); at the motor it is M_out/(q·η) while the motor drives (M_out > 0) and
M_out·η/q when the load drives back (M_out < 0: braking the load's inertia, a load that
helps), plus J_M·ε_m (:mod:`advisor.calc.duty`, the reflection convention; the back-driven
efficiency of the wave gear is taken equal to its forward one). A one-way device (seed 004)
adds its inertia to the rotor's at the motor side, to the load's at the output side. Holding
at standstill (a hold, a cycle's closing rest, an IEC type's rest after its loaded run) asks
M_L·η/q (friction helps the motor hold), nothing where a one-way device holds.

Thermal: the cycle-averaged losses (copper from each phase's torque, so from the RMS torque;
iron and magnets from the speed profile, averaged over each ramp by Simpson's rule) against
the frame's limit, the same limit as the point check (:mod:`advisor.applications.rotary.motor`).
A first-order model, ΔT' = (P − ΔT/R)/C with τ = R·C stated in the requirement and R set so
the limit losses give the insulation class F rise of 105 K (IEC 60034-1, table of limits of
temperature rise, class 155 (F) by resistance), shows the rise over repeated cycles
(S2: over its one run from cold).
"""

import math
from typing import NamedTuple

from advisor.calc import duty as duty_calc
from advisor.calc import one_way
from advisor.calc.checks import Check
from advisor.core.cite import cite, note
from advisor.core.errors import InfeasibleError, InputError
from advisor.core.rulebook import Trace
from advisor.duty.report import DutyOut, ThermalOut, phases_out
from rules import bldc as bldc_rules
from rules import duty as duty_rules

RPM = 30.0 / math.pi
#: IEC 60034-1: the limit of temperature rise of class 155 (F) insulation, by resistance.
CLASS_F_RISE_K = 105.0


class MotorData(NamedTuple):
    """The rotor inertia and thermal time constant the cycle uses, and where each came from
    (the chosen frame's or catalog motor's unless the requirement overrides)."""

    inertia_kgm2: float
    inertia_basis: str
    time_constant_s: float
    time_constant_basis: str


def motor_data(duty, frame_inertia, frame_tau, frame_words: str) -> MotorData:
    """duty.motor_inertia_kgm2 and duty.thermal_time_constant_s where given, else the
    frame's (None where the frame has none: an imposed [motor.reference] of the user's)."""
    from advisor.core.errors import InputError

    out = []
    for key, own in (("motor_inertia_kgm2", frame_inertia), ("thermal_time_constant_s", frame_tau)):
        given = getattr(duty, key)
        if given is not None:
            out += [given, f"duty.{key} (the requirement)"]
        elif own is not None:
            out += [own, frame_words]
        else:
            raise InputError(
                f"duty.{key}: missing; required with a [motor.reference] of your own (the "
                "frame's rotor inertia and thermal time constant are not known), or set "
                "motor.frame = auto or a frame of the series"
            )
    return MotorData(*out)


class Frame:
    """The frame wound for one speed: its losses at a torque and a speed."""

    def __init__(
        self, ref, iron_at, speed_rpm: float, limit_W: float, data: MotorData | None = None
    ) -> None:
        from advisor.applications.rotary.motor import losses_at

        self.ref, self.iron_at, self.speed_rpm, self.limit_W = ref, iron_at, speed_rpm, limit_W
        self.data = data
        self._losses_at = losses_at
        self.ohmic_ref = ref.conducting_phases * ref.phase_resistance_ohm * ref.current_A**2

    def core(self, rpm: float) -> float:
        """Iron and magnet losses at a speed (0 at standstill)."""
        if rpm <= 0:
            return 0.0
        return self._losses_at(self.ref, self.iron_at(rpm), rpm, 0.0).total

    def copper(self, torque: float) -> float:
        return self.ohmic_ref * (torque / self.ref.torque_Nm) ** 2

    def phase_losses(self, p: duty_calc.Phase) -> tuple[float, float]:
        """(copper, iron + magnets) mean over a phase; a ramp by Simpson's rule on 5 points."""
        a, b = abs(p.speed_start_rad_s) * RPM, abs(p.speed_end_rad_s) * RPM
        if a == b:
            core = self.core(a)
        else:
            pts = [self.core(a + (b - a) * k / 4.0) for k in range(5)]
            core = (pts[0] + 4 * pts[1] + 2 * pts[2] + 4 * pts[3] + pts[4]) / 12.0
        return self.copper(p.torque_Nm), core

    def continuous_torque(self) -> float:
        """The torque at which the losses at the frame's speed reach its limit."""
        room = self.limit_W - self.core(self.speed_rpm)
        return self.ref.torque_Nm * math.sqrt(room / self.ohmic_ref) if room > 0 else 0.0


class Holder(NamedTuple):
    """What holds the load at rest: a one-way device (its passage of torque, where it sits
    and its moment of inertia about its own shaft), or nothing (the motor holds with power
    on)."""

    passage: one_way.Passage | None
    at_output: bool = False
    inertia_kgm2: float = 0.0

    @property
    def device(self) -> bool:
        return self.passage is not None

    @property
    def motor_side_kgm2(self) -> float:
        """The device's inertia turning with the rotor: all of it at the motor side."""
        return 0.0 if self.at_output else self.inertia_kgm2

    @property
    def output_side_kgm2(self) -> float:
        """The device's inertia turning with the load: all of it at the output side."""
        return self.inertia_kgm2 if self.at_output else 0.0

    def words(self) -> str:
        if self.passage is None:
            return "the motor with power on (the wave gear is back-drivable)"
        where = "output" if self.at_output else "motor"
        kind = self.passage.type.replace("_", " ")
        return f"the {kind} at the {where} side"


NO_HOLDER = Holder(None)


def _rotor_inertia(duty, frame) -> float:
    """The requirement's duty.motor_inertia_kgm2, or the frame's."""
    given = getattr(duty, "motor_inertia_kgm2", None)
    return given if given is not None else frame.data.inertia_kgm2


def _through_reducer(m_in: float, q: float, eta: float) -> float:
    return (
        duty_calc.reflected_torque(m_in, q, eta, driving=True)
        if m_in >= 0
        else -(duty_calc.reflected_torque(-m_in, q, eta, driving=False))
    )


def _at_motor(m_out: float, q: float, eta: float, holder: Holder = NO_HOLDER) -> float:
    """The output torque at the motor, through the reducer and the holding device (seed
    004): a device at the motor side passes the reducer's input torque, one at the output
    passes the load's torque to the reducer; a self-locking device passes no torque back and
    the motor drives a helping load down (:func:`advisor.calc.one_way.motor_torque_through`)."""
    p = holder.passage
    if p is None:
        return _through_reducer(m_out, q, eta)
    if holder.at_output:
        return _through_reducer(one_way.motor_torque_through(p, m_out), q, eta)
    return one_way.motor_torque_through(p, _through_reducer(m_out, q, eta))


def _move_phases(
    label: str,
    seg,
    load_Nm: float,
    j_load: float,
    j_motor: float,
    q: float,
    eta: float,
    holder: Holder = NO_HOLDER,
) -> list[duty_calc.Phase]:
    """Accelerate, run, decelerate over the segment's angle in its time (output side).

    Per phase M_m = M_load→motor + (J_m + J_dev,motor)·ε_m: the load's part
    ((J_L + J_dev,output)·ε_out ± M_L through the reducer and the device, seed 004) and the
    inertia turning with the rotor, which the motor accelerates and brakes itself. A
    self-locking device lets no load torque back (its lowering factor keeps the load's part
    ≥ 0); it sits downstream of the rotor, so the rotor's braking torque stays negative."""
    theta = math.radians(seg.angle_deg)
    if seg.profile == "triangular":
        ta, tc = seg.time_s / 2.0, 0.0
    else:
        ta = seg.accel_fraction * seg.time_s
        tc = seg.time_s - 2.0 * ta
    w_out = theta / (ta + tc)
    eps = w_out / ta
    m_l = load_Nm if seg.direction == "against" else -load_Nm
    w_m = w_out * q
    j_load_side = j_load + holder.output_side_kgm2
    j_rotor_side = j_motor + holder.motor_side_kgm2
    out = []
    for name, t, w0, w1, sign in (
        ("accelerate", ta, 0.0, w_m, 1.0),
        ("run", tc, w_m, w_m, 0.0),
        ("decelerate", ta, w_m, 0.0, -1.0),
    ):
        if t <= 0:
            continue
        load_side = j_load_side * eps * sign + m_l
        torque = _at_motor(load_side, q, eta, holder) + j_rotor_side * eps * q * sign
        out.append(duty_calc.Phase(f"{label}: {name}", t, w0, w1, torque))
    return out


def cycle(req, q: float, eta: float, speed_rpm: float, frame: Frame, holder: Holder):
    """The phases of one cycle at the motor, and the problems found building it.

    A load stands on the drive from a move or a hold until a dwell takes it off (a dwell
    holds no load); at rest it is held by the holding device, or else by the motor with power
    on through the back-drivable wave gear (M_L·η/q): the cycle's closing rest too."""
    duty, rot = req.duty, req.rotary
    jl, jm = duty.load_inertia_kgm2, _rotor_inertia(duty, frame)
    phases: list[duty_calc.Phase] = []
    problems: list[str] = []
    w_max = speed_rpm / RPM
    if duty.segments:
        standing = 0.0  # the load torque on the drive at rest
        for n, seg in enumerate(duty.segments, 1):
            load = rot.torque_Nm if seg.torque_Nm is None else seg.torque_Nm
            label = f"{n} {seg.kind}"
            if seg.kind == "move":
                ph = _move_phases(label, seg, load, jl, jm, q, eta, holder)
                top = max(p.speed_end_rad_s for p in ph)
                if top > w_max * (1 + 1e-9):
                    problems.append(
                        f"segment {n}: {seg.angle_deg:g}° in {seg.time_s:g} s needs "
                        f"{top * RPM:.0f} rpm at the motor (q = {q:.4g}), above its "
                        f"{speed_rpm:g} rpm"
                    )
                phases += ph
                standing = load
            elif seg.kind == "hold":
                phases.append(
                    duty_calc.Phase(label, seg.time_s, 0.0, 0.0, _held(load, q, eta, holder))
                )
                standing = load
            else:
                phases.append(duty_calc.Phase(label, seg.time_s, 0.0, 0.0, 0.0))
                standing = 0.0
        rest = 3600.0 / duty.cycles_per_hour - sum(s.time_s for s in duty.segments)
        if rest > 1e-9:
            phases.append(duty_calc.Phase("rest", rest, 0.0, 0.0, _held(standing, q, eta, holder)))
        return phases, problems
    return _iec_cycle(req, q, eta, w_max, frame, holder)


def _held(load_Nm: float, q: float, eta: float, holder: Holder) -> float:
    """The motor torque that holds an output load at rest: none where a device holds it,
    M_L·η/q through the back-driven wave gear where the motor holds (friction helps)."""
    return 0.0 if holder.device else load_Nm * eta / q


def _iec_cycle(req, q: float, eta: float, w: float, frame: Frame, holder: Holder):
    """An IEC duty type at the rated point: the output torque at the output speed.

    The rest of S3, S4 and S5 follows a loaded run: the rated load stands on the drive and
    is held as in a cycle's closing rest (:func:`_held`: by the device, or by the motor with
    power on through the back-drivable wave gear, M·η/q), not de-energised as IEC 60034-1
    has it. S6's idle run is at no load."""
    duty, rot = req.duty, req.rotary
    t = duty.duty_type
    run_torque = _at_motor(rot.torque_Nm, q, eta, holder)
    cdf = duty.cyclic_duration_factor or 1.0
    period = 3600.0 / duty.starts_per_hour if t in ("S4", "S5", "S7") else duty.cycle_time_s
    if t == "S2":  # one run of duration_min, checked as S1 (its losses against the limit)
        period = duty.duration_min * 60.0
    on = cdf * period if t != "S7" else period
    rest = duty_calc.Phase("rest", period - on, 0.0, 0.0, _held(rot.torque_Nm, q, eta, holder))
    if t in ("S1", "S2"):
        return [duty_calc.Phase("run", period, w, w, run_torque)], []
    if t == "S3":
        return [duty_calc.Phase("run", on, w, w, run_torque), rest], []
    if t == "S6":
        return [
            duty_calc.Phase("run", on, w, w, run_torque),
            duty_calc.Phase("no load", period - on, w, w, 0),
        ], []
    if t in ("S4", "S5", "S7"):
        return _iec_starts(req, q, eta, w, frame, holder, on, rest)
    return [
        duty_calc.Phase(f"load {k}", x.time_share * period, w, w, x.load_share * run_torque)
        for k, x in enumerate(duty.loads, 1)
    ], []


def _iec_starts(req, q, eta, w, frame: Frame, holder: Holder, on: float, rest):
    """S4, S5 and S7: a start at the peak torque, the run, S5's and S7's stop at the peak
    braking torque, and the rest. The inertia at the motor is
    J = J_m + J_dev,motor + (J_L + J_dev,output)/(q²·η·η_d) while the motor accelerates the
    load (a device turning with the rotor or with the load, seed 004); the electric stop
    takes :func:`_electric_stop_time`. Behind a self-locking device nothing comes back: the
    stop is :func:`_device_stop`'s."""
    duty, t = req.duty, req.duty.duty_type
    jl = duty.load_inertia_kgm2 + holder.output_side_kgm2
    jm = _rotor_inertia(duty, frame) + holder.motor_side_kgm2
    run_torque = _at_motor(req.rotary.torque_Nm, q, eta, holder)
    peak = duty.peak_torque_factor * frame.continuous_torque()
    eta_d = holder.passage.efficiency if holder.passage else 1.0
    j = jm + jl / (q * q * eta * eta_d)
    ta = j * w / (peak - run_torque) if peak > run_torque else math.inf
    back = holder.passage is None or holder.passage.back_drivable
    tb = 0.0
    if t != "S4":
        tb = j * w / (peak + run_torque)
        if back:
            tb = _electric_stop_time(req.rotary.torque_Nm, (jl, jm), q, eta * eta_d, w, peak, tb)
    if ta + tb > on:
        return [], [
            f"{w * RPM:.6g} rpm: {t}: starting at the peak torque {peak:.3g} N·m takes "
            f"{ta:.3g} s, braking {tb:.3g} s: more than the time under load, {on:.4g} s"
        ]
    out = [
        duty_calc.Phase("start", ta, 0.0, w, peak),
        duty_calc.Phase("run", on - ta - tb, w, w, run_torque),
    ]
    if tb:
        out.append(
            duty_calc.Phase("electric brake", tb, w, 0.0, -peak)
            if back
            else _device_stop(req.rotary.torque_Nm, (jl, jm), q, eta, holder, w, tb, peak)
        )
    if rest.time_s > 0:
        out.append(rest)
    return out, []


def _electric_stop_time(
    load_Nm: float,
    inertias: tuple[float, float],
    q: float,
    eta: float,
    w: float,
    peak: float,
    forward_s: float,
) -> float:
    """The time t_b in which the motor brakes from ω_m to rest at exactly −M_peak, with the
    power through the reducer and a back-drivable device flowing one way for both the load's
    torque and its inertia's.

    The output carries T_out = M_L − J_L·ω_m/(q·t_b) (J_L with a device at the output) and
    the motor gives T_out/(q·η) + … while T_out ≥ 0 (the chain runs forward), T_out·η/q + …
    once the load's inertia outweighs its torque and drives the chain back, plus the rotor's
    −(J_m + J_dev,motor)·ω_m/t_b (η with the device's η_d). Set equal to −M_peak:

        t_b = (J_m + J_L/(q²·η))·ω_m/(M_peak + M_L/(q·η))    forward  (T_out ≥ 0)
        t_b = (J_m + J_L·η/q²)·ω_m/(M_peak + M_L·η/q)        back     (T_out < 0)

    The motor torque falls steadily as t_b shortens, so one of the two is consistent: the
    forward one (``forward_s``, the start's J over M_peak + M_run) where its T_out ≥ 0, else
    the back one.

    Parameters
    ----------
    load_Nm : float
        The load torque M_L at the output, against the motion [N·m]
    inertias : tuple[float, float]
        The load side's J_L and the rotor side's J_m [kg·m²]
    q : float
        Reducer ratio [-]
    eta : float
        Efficiency of the reducer and the device, η·η_d [-]
    w : float
        Motor speed ω_m [rad/s]
    peak : float
        The motor's peak torque M_peak [N·m], > 0
    forward_s : float
        The forward flow's t_b [s]

    Returns
    -------
    float
        Braking time t_b [s]

    References
    ----------
    Seed 004 (the device's passage); the reflection convention of :mod:`advisor.calc.duty`.
    """
    j_load, j_rotor = inertias
    if load_Nm - j_load * w / (q * forward_s) >= 0.0:
        return forward_s
    return (j_rotor + j_load * eta / (q * q)) * w / (peak + load_Nm * eta / q)


def _device_stop(
    load_Nm: float,
    inertias: tuple[float, float],
    q: float,
    eta: float,
    holder: Holder,
    w: float,
    tb: float,
    peak: float,
) -> duty_calc.Phase:
    """The stop of S5 or S7 behind a self-locking device, from ω_m to rest in t_b, as a
    move's deceleration: M_m = M_load→motor + (J_m + J_dev,motor)·ε_m with ε_m = −ω_m/t_b and
    the load's part (M_L + (J_L + J_dev,output)·ε_m/q through the reducer and the device,
    seed 004) held at or above zero by the device's lowering factor. The device sits
    downstream of the rotor: the motor still brakes the inertia turning with it. While the
    load's torque outweighs its inertia's the chain runs forward (M_L/(q·η·η_d) helps), so
    t_b = J·ω_m/(M_peak + M_run) with the start's J brakes at exactly the peak torque; where
    the load's inertia outweighs, the device holds it back and the motor brakes less."""
    j_load, j_rotor = inertias
    eps_m = -w / tb
    torque = _at_motor(load_Nm + j_load * eps_m / q, q, eta, holder) + j_rotor * eps_m
    # −M_peak by t_b's choice where the chain runs forward: not beyond it by a rounding
    return duty_calc.Phase("stop by the self-locking device", tb, w, 0.0, max(torque, -peak))


class CycleResult(NamedTuple):
    """The motor over one cycle: its phases, what fails, the cycle-averaged losses [W], the
    peak torque and its limit [N·m], and (losses [W], time [s]) per phase."""

    phases: list
    problems: list[str]
    copper: float = 0.0
    core: float = 0.0
    total: float = 0.0
    peak: float = 0.0
    peak_limit: float = 0.0
    losses: list | tuple = ()  # (losses [W], time [s]) per phase
    #: the winding's highest rise in the settled cycle (first-order model)  [K]
    peak_rise_K: float = 0.0


def evaluate(
    req, q: float, eta: float, speed_rpm: float, frame: Frame, holder: Holder
) -> CycleResult:
    """The cycle at the motor behind the reducer (q, η) at ``speed_rpm``: its cycle-averaged
    losses against the frame's limit and its peak torque against the peak the motor gives."""
    phases, problems = cycle(req, q, eta, speed_rpm, frame, holder)
    if not phases:
        return CycleResult([], problems)
    t = duty_calc.cycle_time(phases)
    parts = [(frame.phase_losses(p), p.time_s) for p in phases]
    copper = sum(c * dt for (c, _), dt in parts) / t
    core = sum(k * dt for (_, k), dt in parts) / t
    total = copper + core
    peak = duty_calc.peak_torque(phases)
    peak_limit = req.duty.peak_torque_factor * frame.continuous_torque()
    if not bldc_rules.within_limit(total, frame.limit_W):
        problems.append(
            f"{speed_rpm:g} rpm: cycle-averaged losses {total:.4g} W (copper {copper:.4g}, "
            f"iron and magnets {core:.4g}) above the frame's limit {frame.limit_W:.4g} W "
            f"(+ {bldc_rules.LIMIT_REL_TOL:.1%} allowance)"
        )
    if peak > peak_limit:  # the check's own margin: limit/peak below 1
        problems.append(
            f"{speed_rpm:g} rpm: peak torque {peak:.4g} N·m above {peak_limit:.4g} N·m "
            f"({req.duty.peak_torque_factor:g} × the continuous {frame.continuous_torque():.4g})"
        )
    losses = [(c + k, dt) for (c, k), dt in parts]
    rise = peak_rise(losses, frame)
    if not bldc_rules.within_limit(rise, CLASS_F_RISE_K):
        problems.append(
            f"{speed_rpm:g} rpm: within a cycle the winding peaks at {rise:.4g} K rise "
            f"(first-order model, τ = {frame.data.time_constant_s:g} s), above the "
            f"{CLASS_F_RISE_K:g} K of class F (+ {bldc_rules.LIMIT_REL_TOL:.1%} allowance): "
            "the cycle is long against the motor's time constant, its mean losses do not decide"
        )
    return CycleResult(phases, problems, copper, core, total, peak, peak_limit, losses, rise)


def peak_rise(losses: list | tuple, frame: Frame) -> float:
    """The winding's highest rise over the settled cycle, first-order model.

        R = ΔT_F/P_limit,   ΔT₊ = ΔT·e^(−t/τ) + P·R·(1 − e^(−t/τ)) phase by phase

    The cycle-averaged losses decide only for a cycle short against τ (the method of
    equivalent quantities, Klyuchev §11; Chilikin ch. 9); a phase long against τ heats the
    winding to its own P·R, which this rise shows.

    Parameters
    ----------
    losses : list
        (losses [W], time [s]) per phase of the cycle
    frame : Frame
        Its loss limit P_limit [W] and thermal time constant τ [s]

    Returns
    -------
    float
        Peak rise of the periodic steady state [K] (:func:`advisor.calc.duty.periodic_peak_rise`)

    References
    ----------
    IEC 60034-1, class 155 (F): 105 K by resistance; Klyuchev §11.
    """
    r_th = CLASS_F_RISE_K / frame.limit_W
    return duty_calc.periodic_peak_rise(list(losses), r_th, frame.data.time_constant_s)


def segment_loads_within_rating(req) -> None:
    """A segment's torque above rotary.torque_Nm is refused: the reducer's stages and the
    holding device are sized for the rated torque, and a larger one would pass unchecked."""
    if not req.duty.segments:
        return
    rated = req.rotary.torque_Nm
    for n, seg in enumerate(req.duty.segments, 1):
        if seg.torque_Nm is not None and seg.torque_Nm > rated:
            raise InputError(
                f"duty.segments[{n}].torque_Nm = {seg.torque_Nm:g}: above rotary.torque_Nm = "
                f"{rated:g}, the torque the reducer and the holding device are sized for; raise "
                "rotary.torque_Nm to the largest torque of the cycle"
            )


def passing_speeds(req, cands: list, frame_for, holder_for, limit_W: float) -> list:
    """The candidate speeds (:class:`~advisor.applications.rotary.candidates.SpeedCandidate`)
    whose motor passes the cycle with its rule reducer (and the point check, with the same
    limit and allowance as the checks that report them); exit 3 naming each candidate's
    reason when none does. ``holder_for(candidate)``: what holds the load."""
    segment_loads_within_rating(req)
    ok, reasons = [], []
    for c in cands:
        if not bldc_rules.within_limit(c.losses_W.total, limit_W):
            reasons.append(
                f"{c.speed_rpm:g} rpm: losses at the rated point {c.losses_W.total:.4g} W "
                f"above the frame's limit {limit_W:.4g} W (+ {bldc_rules.LIMIT_REL_TOL:.1%} "
                "allowance)"
            )
            continue
        frame = frame_for(c.speed_rpm)
        e = evaluate(req, c.total_ratio, c.gearbox_efficiency, c.speed_rpm, frame, holder_for(c))
        if e.problems:
            reasons += e.problems
        else:
            ok.append(c)
    if not ok:
        raise InfeasibleError(
            "no feasible design: no candidate motor speed passes the duty cycle",
            [
                *reasons,
                "give a larger frame in [motor.reference], motor.max_losses_W for a better "
                "cooling, or a lighter cycle",
            ],
        )
    return ok


def _decisions(req, e: CycleResult, frame: Frame, q, eta, speed_rpm, holder: Holder, trace):
    """DU-01 (the IEC duty type, if given), the thermal and the peak decisions and the
    inertia ratio; returns the inertia ratio and whether it is within the guideline."""
    duty = req.duty
    if duty.duty_type:
        trace.apply(
            duty_rules.duty_type,
            duty.duty_type,
            duty_calc.IEC_DUTY_TYPES[duty.duty_type],
            "At the rated point (rotary.torque_Nm at rotary.speed_rpm); S2 taken as S1; S4, "
            "S5 and S7 start (and brake) at the peak torque; S9, S10 as shares of the rated "
            "output torque.",
        )
    rms = duty_calc.rms_torque(e.phases)
    trace.apply(
        duty_rules.thermal,
        e.total / frame.limit_W,
        f"Cycle-averaged losses {e.total:.4g} W (copper {e.copper:.4g} W from the "
        f"phases' torques, i.e. from the RMS torque {rms:.4g} N·m; iron and magnets "
        f"{e.core:.4g} W from the speed profile) against the frame's limit "
        f"{frame.limit_W:.4g} W, the limit of the point check.",
    )
    trace.apply(
        duty_rules.peak,
        e.peak,
        e.peak_limit,
        f"The largest motor torque of the cycle against {duty.peak_torque_factor:g} × the "
        f"continuous torque of the frame at {speed_rpm:g} rpm, "
        f"{frame.continuous_torque():.4g} N·m (duty.peak_torque_factor).",
    )
    ir = inertia_ratio(duty.load_inertia_kgm2, frame.data.inertia_kgm2, q, eta, holder)
    return ir, trace.apply(duty_rules.inertia_ratio, ir)


def inertia_ratio(j_load: float, j_motor: float, q: float, eta: float, holder: Holder) -> float:
    """The load's inertia at the motor over the inertia turning with the rotor.

        ratio = (J_L + J_dev,output)/(q²·η) / (J_m + J_dev,motor)

    Parameters
    ----------
    j_load : float
        Load inertia at the output J_L [kg·m²]
    j_motor : float
        Rotor inertia J_m [kg·m²]
    q : float
        Reducer ratio [-]
    eta : float
        Reducer efficiency η [-]
    holder : Holder
        The one-way device: its inertia J_dev [kg·m²] counts with the rotor at the motor
        side, with the load at the output side

    Returns
    -------
    float
        Inertia ratio [-]

    References
    ----------
    Seed 004 (the device's inertia, its ranking by ``one_way.priority = "inertia"``); the
    reflection J/q² through η of :mod:`advisor.calc.duty`.
    """
    return (j_load + holder.output_side_kgm2) / (q * q * eta) / (j_motor + holder.motor_side_kgm2)


class _Thermal(NamedTuple):
    resistance_K_W: float
    history: list
    peak_rise_K: float


#: Steps a single run's thermal history is drawn with (S2: its rise is a curve, not a line).
RUN_STEPS = 200


def _thermal(e: CycleResult, frame: Frame, t_cycle: float, single_run: bool) -> _Thermal:
    """First-order thermal model, R from the limit and class F. A repeated cycle: enough
    cycles from cold to span 5τ (within 1 − e^(−5) = 99.3 % of the settled rise), thinned to
    about 400 points, its peak that of the settled cycle. ``single_run`` (S2, one run of
    duration_min from cold): that run alone, in :data:`RUN_STEPS` steps, its peak the rise at
    its end, ΔT_ss·(1 − e^(−t/τ)) at constant losses."""
    tau = frame.data.time_constant_s
    r_th = CLASS_F_RISE_K / frame.limit_W
    if single_run:
        steps = [(p, dt / RUN_STEPS) for p, dt in e.losses for _ in range(RUN_STEPS)]
        hist = duty_calc.thermal_history(steps, r_th, tau, 1, max_points=len(steps) + 1)
        return _Thermal(r_th, hist, max(rise for _, rise in hist))
    n = max(1, math.ceil(5.0 * tau / t_cycle))
    hist = duty_calc.thermal_history(e.losses, r_th, tau, n, max_points=400)
    return _Thermal(r_th, hist, e.peak_rise_K)


def _duty_warnings(ir: float, within: bool) -> list[str]:
    warnings = []
    if not within:
        warnings.append(
            f"duty: the load's inertia at the motor is {ir:.3g} times the motor's (guideline "
            f"{duty_rules.INERTIA_RATIO_GUIDELINE:g})"
        )
    return warnings


def _device_inertia_words(holder: Holder) -> str:
    """Where the one-way device's inertia enters the cycle, for the report's basis."""
    if not holder.device or holder.inertia_kgm2 <= 0.0:
        return ""
    kind = holder.passage.type.replace("_", " ")
    if holder.at_output:
        return (
            f"; the {kind}'s {holder.inertia_kgm2:.4g} kg·m² at the output side counts with "
            "the load's inertia"
        )
    return (
        f"; the {kind}'s {holder.inertia_kgm2:.4g} kg·m² at the motor side turns with the rotor "
        "and counts with it (phase torques, inertia ratio)"
    )


def _duty_checks(e: CycleResult, frame: Frame, single_run: bool = False) -> list[Check]:
    from advisor.applications.rotary.motor import losses_check

    return [
        losses_check(
            "duty_losses",
            "cycle-averaged losses of the motor within the frame's limit",
            e.total,
            frame.limit_W,
            cite("seed-000", "eqs. (4), (5), (9)").with_note(
                "the advisor's duty-cycle method, docs/reference/duty.md; "
                "the frame's limit of the point check"
            ),
        ),
        Check(
            "duty_peak_torque",
            "peak motor torque of the cycle within the peak the motor gives",
            e.peak,
            e.peak_limit,
            "N·m",
            e.peak_limit / e.peak if e.peak > 0 else math.inf,
            note(
                "the advisor's duty-cycle method, docs/reference/duty.md; duty.peak_torque_factor"
            ),
        ),
        _peak_rise_check(e.peak_rise_K, single_run),
    ]


def _peak_rise_check(rise_K: float, single_run: bool = False) -> Check:
    """The winding's peak rise of the settled cycle against class F's 105 K, with the
    allowance of the losses' check: R maps the loss limit onto 105 K, so a cycle of constant
    losses passes both or neither. ``single_run`` (S2): checked as S1, the run's losses held
    until the rise settles (its own rise from cold, in the thermal table, is less)."""
    allowed = CLASS_F_RISE_K * (1.0 + bldc_rules.LIMIT_REL_TOL)
    what = "the S2 run held as S1 (continuous)" if single_run else "the cycle"
    return Check(
        "duty_peak_rise",
        f"winding's peak temperature rise of {what} within class F ({CLASS_F_RISE_K:g} K + "
        f"{bldc_rules.LIMIT_REL_TOL:.1%} allowance)",
        rise_K,
        allowed,
        "K",
        allowed / rise_K if rise_K > 0 else math.inf,
        (cite("iec-60034-1", "class 155 (F) by resistance") + duty_rules.KLYUCHEV).with_note(
            "first-order thermal model of the advisor's duty-cycle method, docs/reference/duty.md"
        ),
    )


def advise_duty(
    req, q: float, eta: float, speed_rpm: float, frame: Frame, holder: Holder, trace: Trace
):
    """The duty of the adopted design: the table, the checks and the warnings."""
    segment_loads_within_rating(req)
    duty = req.duty
    e = evaluate(req, q, eta, speed_rpm, frame, holder)
    if e.problems:
        raise InfeasibleError(
            "no feasible design: the adopted drive fails the duty cycle", e.problems
        )
    phases = e.phases
    ir, within = _decisions(req, e, frame, q, eta, speed_rpm, holder, trace)
    t_cycle = duty_calc.cycle_time(phases)
    tau = frame.data.time_constant_s
    single_run = duty.duty_type == "S2"  # one run from cold, checked as S1
    thermal = _thermal(e, frame, t_cycle, single_run)
    warnings = _duty_warnings(ir, within)
    out_J, back_J = duty_calc.energies(phases)
    out = DutyOut.make(
        motor=f"{speed_rpm:g} rpm",
        ratio=q,
        cycle_time_s=t_cycle,
        move_time_s=sum(p.time_s for p in phases if p.speed_start_rad_s or p.speed_end_rad_s),
        peak_torque_Nm=e.peak,
        peak_torque_limit_Nm=e.peak_limit,
        rms_torque_Nm=duty_calc.rms_torque(phases),
        thermal_utilisation=e.total / frame.limit_W,
        thermal_basis="cycle-averaged losses over the frame's limit",
        inertia_ratio=ir,
        motor_inertia_kgm2=frame.data.inertia_kgm2,
        motor_inertia_basis=frame.data.inertia_basis + _device_inertia_words(holder),
        inertia_ratio_guideline=duty_rules.INERTIA_RATIO_GUIDELINE,
        energy_per_cycle_J=out_J,
        regenerated_per_cycle_J=back_J,
        mean_speed_rpm=duty_calc.mean_speed(phases) * RPM,
        # S1 and S2 run without a cycle that repeats
        cycles_per_hour=None if duty.duty_type in ("S1", "S2") else 3600.0 / t_cycle,
        duty_type=duty.duty_type or "cycle",
        held_by=holder.words(),
        losses_W={"copper": e.copper, "iron_and_magnets": e.core, "total": e.total},
        loss_limit_W=frame.limit_W,
        thermal=ThermalOut.make(
            time_constant_s=tau,
            time_constant_basis=frame.data.time_constant_basis,
            resistance_K_W=thermal.resistance_K_W,
            steady_rise_K=e.total * thermal.resistance_K_W,
            peak_rise_K=thermal.peak_rise_K,
            limit_rise_K=CLASS_F_RISE_K,
            time_s=[h[0] for h in thermal.history],
            rise_K=[h[1] for h in thermal.history],
        ),
        phases=phases_out(phases),
    )
    return out, _duty_checks(e, frame, single_run), warnings


def frames(ref, steel, steel_mass: float, terms, limit_W: float, data: MotorData | None = None):
    """rpm -> the Frame wound for that speed, with the iron loss model of the point check,
    and the rotor inertia and time constant of the cycle (``data``)."""
    from advisor.applications.rotary.motor import specific_iron_loss
    from advisor.calc import bldc

    def iron_at(rpm: float) -> float:
        f = bldc.flux_frequency_Hz(rpm, ref.pole_pairs)
        return steel_mass * specific_iron_loss(ref, steel, terms, f)[0]

    return lambda rpm: Frame(ref, iron_at, rpm, limit_W, data)


def output_loads(req, q: float, eta: float, speed_rpm: float, frame: Frame, holder: Holder):
    """The cycle at the reducer's output, for its load spectrum: per phase
    the torque the output carries and its mean |speed| (rpm).

    Moves, holds and dwells give the output torque J_L·ε ± M_L themselves (what
    :func:`_move_phases` reflects to the motor); a hold or the closing rest carries the
    standing load at standstill. An IEC duty type's start and stop likewise, from the load
    side: M_out = M_L + J_L·ε_out over the phase (:func:`_iec_output_loads`); the rotor's own
    acceleration torque stays at the motor. A holding device at the output sits between the
    load and the reducer: the reducer carries what the device asks (T/η_d driving, the
    lowering torque through a self-locking one) and nothing at rest."""
    from advisor.calc.load_spectrum import Load

    duty, rot = req.duty, req.rotary
    p_dev = holder.passage

    def carried(m_out: float) -> float:
        """What the reducer's output carries for a load-side torque: the torque itself, or
        through a device at the output its input torque (seed 004: T/η_d while driving, the
        lowering torque of a self-locking one)."""
        if p_dev is None or not holder.at_output:
            return m_out
        return one_way.motor_torque_through(p_dev, m_out)

    # at standstill a device at the output holds the load itself; elsewhere the reducer does
    held = 0.0 if p_dev is not None and holder.at_output else 1.0
    if not duty.segments:
        return _iec_output_loads(req, q, eta, speed_rpm, frame, holder, carried, held)
    jl = duty.load_inertia_kgm2 + holder.output_side_kgm2
    out = []
    standing = 0.0
    for seg in duty.segments:
        load = rot.torque_Nm if seg.torque_Nm is None else seg.torque_Nm
        if seg.kind == "move":
            theta = math.radians(seg.angle_deg)
            if seg.profile == "triangular":
                ta, tc = seg.time_s / 2.0, 0.0
            else:
                ta = seg.accel_fraction * seg.time_s
                tc = seg.time_s - 2.0 * ta
            w_out = theta / (ta + tc)
            m_l = load if seg.direction == "against" else -load
            for t, w_mean, sign in ((ta, w_out / 2, 1.0), (tc, w_out, 0.0), (ta, w_out / 2, -1.0)):
                if t > 0:
                    out.append(Load(carried(jl * w_out / ta * sign + m_l), w_mean * RPM, t))
            standing = load
        elif seg.kind == "hold":
            out.append(Load(load * held, 0.0, seg.time_s))
            standing = load
        else:
            out.append(Load(0.0, 0.0, seg.time_s))
            standing = 0.0
    rest = 3600.0 / duty.cycles_per_hour - sum(s.time_s for s in duty.segments)
    if rest > 1e-9:
        out.append(Load(standing * held, 0.0, rest))
    return out


def _iec_output_loads(req, q, eta, speed_rpm, frame, holder, carried, held) -> list:
    """An IEC duty type at the reducer's output: a run or a load share carries the rated
    output torque (through a device at the output, what it asks), exactly as the stages are
    sized for it; a start or a stop carries the load's torque and the torque that accelerates
    or brakes the load's inertia, M_out = M_L + (J_L + J_dev,output)·ε_out with
    ε_out = Δω_out/t of the phase (negative while braking), as a move's phases do; the
    rotor's inertia (q² times larger at the output) is the motor's own and never reaches the
    output. A rest carries the rated load standing on the reducer (``held`` 0 where a device
    at the output holds it), S6's idle run nothing."""
    from advisor.calc.load_spectrum import Load

    rated = req.rotary.torque_Nm
    jl = req.duty.load_inertia_kgm2 + holder.output_side_kgm2
    shares = {f"load {k}": x.load_share for k, x in enumerate(req.duty.loads or (), 1)}
    out = []
    for p in cycle(req, q, eta, speed_rpm, frame, holder)[0]:
        if p.name == "run" or p.name in shares:
            torque = carried(rated * shares.get(p.name, 1.0))
        elif p.name == "rest":  # the rated load stands, held by the reducer or the device
            torque = rated * held
        elif p.name == "no load":
            torque = 0.0
        else:  # a start or a stop: the load's torque and its inertia's, at the output
            eps_out = (p.speed_end_rad_s - p.speed_start_rad_s) / (q * p.time_s)
            torque = carried(rated + jl * eps_out)
        out.append(Load(torque, abs(p.mean_speed_rad_s) * RPM / q, p.time_s))
    return out


def motor_phases(req, q: float, eta: float, speed_rpm: float, frame: Frame, holder: Holder):
    """The phases of one cycle at the motor (the same as the duty's)."""
    return cycle(req, q, eta, speed_rpm, frame, holder)[0]
