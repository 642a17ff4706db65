"""The linear actuator's duty: a cage induction motor on 50 Hz driving the screw
through a cycle of moves, dwells and holds, or an IEC 60034-1 duty type.

Per move, at the motor: a direct-on-line start with the motor's mean starting torque
M_m (the mean of its refined Kloss curve between standstill and the working slip, the usual
approximation: Chilikin, «Общий курс электропривода», ch. 2) against the screw torque M_L, on
J_Σ = J_M + J_screw + m·(L/2π)²/η; the run at the working point M(s) = M_L; switched off,
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

from advisor.calc import duty as duty_calc
from advisor.calc import one_way as one_way_calc
from advisor.calc.induction import fit_kloss
from advisor.calc.sizing import Check
from advisor.core.cite import cite
from advisor.core.errors import InfeasibleError, InputError
from advisor.core.rulebook import Trace
from advisor.duty.report import DutyOut, phases_out
from rules import duty as duty_rules

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
    """One catalog motor's curve, speeds and starts (scalar, no numpy)."""

    def __init__(self, m, j_load: float) -> None:
        self.m = m
        self.curve = fit_kloss(
            m.rated_torque_Nm, m.rated_slip, m.breakdown_torque_ratio, m.starting_torque_ratio
        )
        self.w0 = m.synchronous_speed_rpm * math.pi / 30.0
        self.j = m.inertia_kgm2 + j_load

    def slip(self, torque: float) -> float | None:
        """Working slip under a torque; a generating load (torque < 0) mirrors the curve."""
        if torque == 0:
            return 0.0
        s = self.curve.stable_slip(abs(torque))
        return None if s is None else math.copysign(s, torque)

    def mean_start_torque(self, s_work: float) -> float:
        """Mean of M(s) from standstill to the working slip (Simpson, 64 intervals)."""
        a, b, n = max(s_work, 0.0), 1.0, 64
        h = (b - a) / n
        tot = self.curve.torque(a) + self.curve.torque(b)
        for k in range(1, n):
            tot += (4 if k % 2 else 2) * self.curve.torque(a + k * h)
        return tot * h / 3.0 / (b - a)

    def move(
        self, name: str, path_rad: float, load: float
    ) -> tuple[list[duty_calc.Phase], float, float]:
        """Start, run, coast over a path at the motor: (phases, mean start torque, k_L)."""
        s = self.slip(load)
        if s is None:
            raise ValueError("stall")
        w = self.w0 * (1.0 - s)
        mm = self.mean_start_torque(max(s, 0.0))
        e1 = (mm - load) / self.j
        e2 = load / self.j if load > 0 else math.inf  # the stop: the load and friction
        ramps = w * w / (2.0 * e1) + (w * w / (2.0 * e2) if e2 != math.inf else 0.0)
        if path_rad < ramps:  # a short move: switched off before reaching speed
            w = math.sqrt(2.0 * path_rad / (1.0 / e1 + (1.0 / e2 if e2 != math.inf else 0.0)))
            run = 0.0
        else:
            run = (path_rad - ramps) / w
        out = [duty_calc.Phase(f"{name}: start", w / e1, 0.0, w, mm)]
        if run > 0:
            out.append(duty_calc.Phase(f"{name}: run", run, w, w, load))
        if e2 != math.inf:
            out.append(duty_calc.Phase(f"{name}: coast", w / e2, w, 0.0, 0.0))
        return out, mm, mm / (mm - load) if load > 0 else 1.0


def _unheld(ev, n: int, force: float, when: str) -> str:
    return (
        f"segment {n}: {when} the load of {force:g} N back-drives the screw "
        f"{ev.thread.name} (not self-locking at the low end of its friction range) and an "
        "induction motor on the line cannot hold a load at standstill; set "
        "application.hold_without_power = true for a one-way device"
    )


def _segments_cycle(req, ev, mot: MotorModel, holder: str | None, passage=one_way_calc.NO_DEVICE):
    """Phases of the segments, the starts per cycle, the worst k_L, and problems.

    A load stands on the screw from a move or a hold until a dwell takes it off. Where it
    back-drives the screw, something must hold it whenever the motor is off (the stop of a
    move, its rest, a hold, the cycle's closing rest): the self-locking screw, or the one-way
    device; an induction motor on the line holds nothing at standstill. Through the device
    the motor gives the screw torque over its efficiency, and a self-locking device passes
    no torque back (:func:`advisor.calc.one_way.motor_torque_through`)."""
    duty, lin = req.duty, req.linear
    lead = _lead_m(ev)
    phases: list[duty_calc.Phase] = []
    problems: list[str] = []
    starts, k_l, peak_load = 0, 1.0, 0.0
    standing = 0.0  # the force on the screw at rest
    for n, seg in enumerate(duty.segments, 1):
        force = lin.force_N if seg.force_N is None else seg.force_N
        label = f"{n} {seg.kind}"
        if seg.kind == "move":
            screw = screw_torque(ev, force, seg.direction)
            load = (
                one_way_calc.motor_torque_through(passage, screw) if holder == "one_way" else screw
            )
            peak_load = max(peak_load, abs(load))
            if holder is None and force > 0:
                problems.append(_unheld(ev, n, force, "switched off at the end of the move,"))
            try:
                ph, _, kl = mot.move(label, seg.distance_m / lead * 2.0 * math.pi, load)
            except ValueError:
                problems.append(
                    f"segment {n}: the screw asks {load:.3g} N·m, above the maximum torque "
                    f"{mot.curve.max_torque_Nm:.3g} N·m of {mot.m.model}"
                )
                continue
            t = duty_calc.cycle_time(ph)
            if t > seg.time_s * (1 + 1e-9):
                problems.append(
                    f"segment {n}: the move of {seg.distance_m:g} m takes {t:.4g} s with "
                    f"{mot.m.model}, longer than its time_s = {seg.time_s:g} s"
                )
            phases += ph
            if seg.time_s > t:
                phases.append(duty_calc.Phase(f"{label}: rest", seg.time_s - t, 0.0, 0.0, 0.0))
            starts += 1
            k_l = max(k_l, kl)
            standing = force
        elif seg.kind == "hold":
            if holder is None and force > 0:
                problems.append(_unheld(ev, n, force, "holding at standstill,"))
            phases.append(duty_calc.Phase(label, seg.time_s, 0.0, 0.0, 0.0))
            standing = force
        else:
            phases.append(duty_calc.Phase(label, seg.time_s, 0.0, 0.0, 0.0))
            standing = 0.0
    rest = 3600.0 / duty.cycles_per_hour - sum(s.time_s for s in duty.segments)
    if rest > 1e-9:
        if holder is None and standing > 0:
            problems.append(
                _unheld(ev, len(duty.segments), standing, "in the cycle's closing rest")
            )
        phases.append(duty_calc.Phase("rest", rest, 0.0, 0.0, 0.0))
    return phases, starts * duty.cycles_per_hour, k_l, peak_load, problems


def _iec_cycle(req, ev, mot: MotorModel, passage=one_way_calc.NO_DEVICE):
    """Phases of one cycle of an IEC 60034-1 duty type at the rated force's screw torque
    (through the holding device's efficiency where one sits at the motor)."""
    duty = req.duty
    t = duty.duty_type
    load = one_way_calc.motor_torque_through(passage, ev.torque_Nm)
    s = mot.slip(load)
    problems: list[str] = []
    if s is None:
        return [], 0.0, 1.0, load, [f"{mot.m.model} stalls under {load:.3g} N·m"], 0.0
    w = mot.w0 * (1.0 - s)
    cdf = duty.cyclic_duration_factor or 1.0
    starts_h = duty.starts_per_hour or 0.0
    period = 3600.0 / starts_h if t in ("S4", "S5", "S7") else duty.cycle_time_s
    mm = mot.mean_start_torque(s)
    t_start = mot.j * w / (mm - load)
    t_brake = mot.j * w / (mm + load)  # electric braking with the same mean torque
    k_l = mm / (mm - load)
    on = cdf * period
    ph: list[duty_calc.Phase] = []
    braking = 0.0
    if t == "S1":
        ph = [duty_calc.Phase("run", period, w, w, load)]
        starts_h = 0.0
    elif t == "S2":  # one run for the stated time; the rest until cold is not a cycle
        ph = [duty_calc.Phase("run", duty.duration_min * 60.0, w, w, load)]
        starts_h = 0.0
    elif t == "S3":
        ph = [
            duty_calc.Phase("run", on, w, w, load),
            duty_calc.Phase("rest", period - on, 0.0, 0.0, 0.0),
        ]
    elif t == "S6":
        ph = [
            duty_calc.Phase("run", on, w, w, load),
            duty_calc.Phase("no load", period - on, w, w, 0.0),
        ]
    elif t in ("S4", "S5", "S7"):
        if t == "S7":
            on = period
        brake = t_brake if t in ("S5", "S7") else 0.0
        braking = ELECTRIC_BRAKING_HEAT if brake else 0.0
        run = on - t_start - brake
        if run < 0:
            problems.append(
                f"{t}: the start ({t_start:.3g} s) and the stop ({brake:.3g} s) take longer "
                f"than the time under load, {on:.4g} s"
            )
            run = 0.0
        ph = [
            duty_calc.Phase("start", t_start, 0.0, w, mm),
            duty_calc.Phase("run", run, w, w, load),
        ]
        if brake:
            ph.append(duty_calc.Phase("electric brake", brake, w, 0.0, -mm))
        if period - on > 0:
            ph.append(duty_calc.Phase("rest", period - on, 0.0, 0.0, 0.0))
    else:  # S9, S10: the loads as shares of the rated one
        for k, x in enumerate(duty.loads, 1):
            sk = mot.slip(x.load_share * load)
            if sk is None:
                problems.append(f"load {k}: {mot.m.model} stalls under {x.load_share:g} × load")
                sk = 0.0
            wk = mot.w0 * (1.0 - sk)
            ph.append(
                duty_calc.Phase(f"load {k}", x.time_share * period, wk, wk, x.load_share * load)
            )
        starts_h = 0.0
    # the load's torque: the motor's own starting and braking torques are not a demand
    peak = max(
        (abs(p.torque_Nm) for p in ph if "start" not in p.name and "brake" not in p.name),
        default=0.0,
    )
    return ph, starts_h, k_l, peak, problems, braking


def evaluate(req, ev, m, j_load: float, holder: str | None, passage=one_way_calc.NO_DEVICE) -> dict:
    """The cycle with motor m: phases, RMS, starts and every problem. ``holder``: what holds
    the load at standstill ('screw', 'one_way' or None); ``passage``: the one-way device's."""
    mot = MotorModel(m, j_load)
    duty = req.duty
    braking = 0.0
    if not holder == "one_way":
        passage = one_way_calc.NO_DEVICE
    if duty.segments:
        phases, starts_h, k_l, peak_load, problems = _segments_cycle(req, ev, mot, holder, passage)
    else:
        phases, starts_h, k_l, peak_load, problems, braking = _iec_cycle(req, ev, mot, passage)
        if holder is None and req.linear.force_N > 0:  # the same rule as for the segments
            problems.append(
                f"{duty.duty_type}: the load of {req.linear.force_N:g} N back-drives the screw "
                f"{ev.thread.name} (not self-locking at the low end of its friction range) "
                "whenever the motor stops, and an induction motor on the line cannot hold a "
                "load at standstill; set application.hold_without_power = true for a one-way "
                "device"
            )
    # a start's heat, the load's share included (k_L), is counted by the starts per hour:
    # in the equivalent torque it counts as a ramp at zero torque
    thermal = [p._replace(torque_Nm=0.0) if p.name.endswith("start") else p for p in phases]
    rms = duty_calc.rms_torque(thermal, duty.standstill_cooling_factor) if phases else 0.0
    rated = m.rated_torque_Nm
    # S2: SEW's power increasing factor K raises the thermal limit to K·M_n (same speed)
    k_s2 = duty_calc.s2_power_factor(duty.duration_min) if duty.duty_type == "S2" else 1.0
    limit = k_s2 * rated
    p_loss = m.rated_power_kW * 1e3 * (100.0 / m.efficiency_pct - 1.0)
    ramp = (1.0 + duty.standstill_cooling_factor) / 2.0
    z0 = duty_calc.no_load_starts_per_hour(p_loss, m.inertia_kgm2, mot.w0, ramp)
    fi = duty_calc.inertia_factor(m.inertia_kgm2, j_load)
    allowed = duty_calc.allowed_starts_per_hour(z0, fi, k_l, rms / rated, 1.0, braking)
    start_torque = mot.curve.torque(1.0)
    if rms > limit:
        problems.append(
            # a product printed multiplies out: 1.2 × 5.1525 = 6.183 (5.152 would not)
            f"RMS torque {rms:.4g} N·m above the rated {rated:.5g} N·m × K = {k_s2:g} for S2 "
            f"= {limit:.4g} N·m"
            if k_s2 != 1.0
            else f"RMS torque {rms:.4g} N·m above the rated {rated:.4g} N·m"
        )
    # S3: the running torque also against SEW's K·M_n for the cdf (the stricter decides)
    k_s3 = (
        duty_calc.s3_factor_for_cycle(duty.cyclic_duration_factor, duty.cycle_time_s)
        if duty.duty_type == "S3"
        else 1.0
    )
    run_s3 = phases[0].torque_Nm if duty.duty_type == "S3" and phases else 0.0
    if run_s3 > k_s3 * rated:
        problems.append(
            f"S3 running torque {run_s3:.4g} N·m above K·M_n = {k_s3:g} × {rated:.5g} = "
            f"{k_s3 * rated:.4g} N·m (SEW's S3 factor)"
        )
    if starts_h > allowed:
        problems.append(f"{starts_h:.4g} starts/h above the {allowed:.4g} it allows")
    if peak_load > start_torque:
        problems.append(
            f"the load torque {peak_load:.4g} N·m above the starting torque {start_torque:.4g}"
        )
    return {
        "motor": m,
        "mot": mot,
        "phases": phases,
        "rms": rms,
        "rated": rated,
        "limit": limit,
        "k_s2": k_s2,
        "k_s3": k_s3,
        "run_s3": run_s3,
        "starts": starts_h,
        "allowed": allowed,
        "z0": z0,
        "fi": fi,
        "k_l": k_l,
        "peak_load": peak_load,
        "start_torque": start_torque,
        "mean_start": _mean_start(phases),
        "braking": braking,
        "problems": problems,
    }


def _held_by(ev, holder: str | None, passage) -> str:
    """What holds the load whenever the motor is off, in words for the report."""
    if holder == "screw":
        return f"the screw {ev.thread.name}, self-locking over its whole friction range"
    if holder == "one_way":
        return f"the {passage.type.replace('_', ' ')} at the motor side"
    return "nothing: no load stands on the screw while the motor is off"


def _mean_start(phases: list[duty_calc.Phase]) -> float | None:
    """The motor's mean starting torque where the cycle has a start (the same in every one)."""
    return next((p.torque_Nm for p in phases if p.name.endswith("start")), None)


def segment_loads_within_rating(req) -> None:
    """A segment's force above linear.force_N is refused: the screw, the nut and the holding
    device are sized for the rated force, and a larger one in the cycle would pass unchecked."""
    if not req.duty.segments:
        return
    rated = req.linear.force_N
    for n, seg in enumerate(req.duty.segments, 1):
        if seg.force_N is not None and seg.force_N > rated:
            raise InputError(
                f"duty.segments[{n}].force_N = {seg.force_N:g}: above linear.force_N = "
                f"{rated:g}, the force the screw, nut and holding device are sized for; raise "
                "linear.force_N to the largest force of the cycle"
            )


def advise_duty(
    req, ev, selected, cat, holder: str | None, trace: Trace, passage=one_way_calc.NO_DEVICE
):
    """The motor for the cycle: the point's motor, or the next larger of its pole count that
    passes; the duty table, the checks and the warnings."""
    segment_loads_within_rating(req)
    duty, lin = req.duty, req.linear
    j_load, j_basis = load_inertia(ev, duty.moving_mass_kg, lin.support_span_m)
    line = [
        m
        for m in cat.motors_with_poles(selected.poles)
        if m.rated_power_kW >= selected.rated_power_kW
    ]
    tried = [evaluate(req, ev, m, j_load, holder, passage) for m in line]
    ok = [e for e in tried if not e["problems"]]
    if duty.duty_type:
        trace.apply(
            duty_rules.duty_type,
            duty.duty_type,
            duty_calc.IEC_DUTY_TYPES[duty.duty_type],
            _iec_how(duty),
        )
    if not ok:
        shown = [tried[0], tried[-1]] if len(tried) > 1 else tried
        raise InfeasibleError(
            "no feasible design: no motor of the chosen pole count passes the duty cycle",
            [
                *(f"{e['motor'].model}: " + "; ".join(e["problems"]) for e in shown),
                "larger motors of the same pole count were tried; the moves run at the speed "
                "chosen for linear.travel_time_s (a shorter one picks a faster motor)",
            ],
        )
    e = ok[0]
    m = e["motor"]
    rows = {x["motor"].model: (x["motor"].rated_power_kW, x["problems"]) for x in tried}
    trace.apply(duty_rules.motor_for_cycle_linear, rows, selected.model, j_basis)
    phases = e["phases"]
    out_J, _ = duty_calc.energies(phases)
    # an electric (DC-injection) stop dissipates the kinetic energy in the rotor, below the
    # synchronous speed: nothing of it reaches the supply
    _, back_J = duty_calc.energies([p for p in phases if p.name != "electric brake"])
    beta0 = duty.standstill_cooling_factor
    util = e["rms"] / e["limit"]
    k_s2 = e["k_s2"]
    if duty.duty_type == "S2":
        trace.apply(duty_rules.power_increasing_factor, "S2", duty.duration_min, k_s2)
        thermal_how = (
            f"Torque of the S2 run {e['rms']:.4g} N·m against K·M_n = {k_s2:g} × "
            f"{e['rated']:.5g} = {e['limit']:.4g} N·m of {m.model} (DU-09: SEW's power "
            "increasing factor for S2, at the same speed a factor on the torque)."
        )
        basis = f"torque of the S2 run over K·M_n (K = {k_s2:g}, SEW's S2 factor)"
    else:
        thermal_how = (
            f"Equivalent torque √(Σ M²·t / Σ β·t) = {e['rms']:.4g} N·m against the rated "
            f"{e['rated']:.4g} N·m of {m.model}; β = 1 at speed, β0 = {beta0:g} at standstill, "
            f"(1 + β0)/2 in a ramp (a self-ventilated motor, IP44). A start counts at zero "
            "torque: its heat, the load's share included, is counted by the starts per hour."
        )
        basis = f"equivalent torque (β0 = {beta0:g} at standstill) over the rated torque"
    k_s3 = e["k_s3"]
    if duty.duty_type == "S3":
        cdf = duty.cyclic_duration_factor
        trace.apply(
            duty_rules.power_increasing_factor, "S3", cdf, k_s3, cdf * duty.cycle_time_s / 60.0
        )
        util_k = e["run_s3"] / (k_s3 * e["rated"])
        thermal_how += (
            f" Beside it SEW's S3 factor (DU-09): the running torque {e['run_s3']:.4g} N·m "
            f"against K·M_n = {k_s3:g} × {e['rated']:.5g} = {k_s3 * e['rated']:.4g} N·m, "
            f"utilisation {util_k:.3g} against {util:.3g} by the equivalent torque; the "
            "larger decides."
        )
        if util_k > util:
            util = util_k
            basis = f"S3 running torque over K·M_n (K = {k_s3:g}, SEW's S3 factor)"
    trace.apply(duty_rules.thermal, util, thermal_how)
    peak = duty_calc.peak_torque(phases)
    trace.apply(
        duty_rules.peak,
        e["peak_load"],
        e["start_torque"],
        "The largest load torque of the cycle against the motor's starting torque (from the "
        "catalog's M_start/M_n): the motor must start under it. "
        + (
            f"The peak of the cycle, {peak:.4g} N·m, is the motor's own mean starting torque "
            "in a start."
            if any(p.name.endswith("start") for p in phases)
            else f"No start is counted in this duty: the cycle's peak is the running torque "
            f"{peak:.4g} N·m."
        ),
        peak,
    )
    starts_basis = (
        f"z = z0·(1 − (M_eq/M_n)²)/(FI·k_L·(1 + k_b)): z0 = 3600·P_loss·(1 + β0)/2/(J_M·ω0²)"
        f" = {e['z0']:.4g} no-load starts/h (derived: the catalog gives none) from the rated "
        "losses "
        f"{m.rated_power_kW * 1e3 * (100.0 / m.efficiency_pct - 1.0):.4g} W (its efficiency "
        f"{m.efficiency_pct:g} %, an estimated value) and rotor inertia {m.inertia_kgm2:g} kg·m²; "
        f"FI = {e['fi']:.3g}; k_L = M_m/(M_m − M_L) = {e['k_l']:.3g}; k_b = {e['braking']:g}. "
        "A start heats rotor and stator by J·ω0²/2 each (R1/R2' = 1): Chilikin, ch. 9."
    )
    if e["starts"] > 0:
        trace.apply(duty_rules.starts, e["starts"], e["allowed"], starts_basis)
    ir = j_load / m.inertia_kgm2
    within = trace.apply(duty_rules.inertia_ratio, ir)
    warnings = []
    if not within:
        warnings.append(
            f"duty: the load's inertia at the motor is {ir:.3g} times the motor's (guideline "
            f"{duty_rules.INERTIA_RATIO_GUIDELINE:g})"
        )
    if m.model != selected.model:
        warnings.append(
            f"duty: the cycle needs {m.model} ({m.rated_power_kW:g} kW), larger than "
            f"{selected.model} for the rated point"
        )
    checks = [
        Check(
            "duty_rms_torque",
            f"torque of the S2 run within K·M_n (K = {k_s2:g}, SEW's S2 factor)"
            if duty.duty_type == "S2"
            else "equivalent torque of the cycle within the rated torque",
            e["rms"],
            e["limit"],
            "N·m",
            e["limit"] / e["rms"] if e["rms"] > 0 else math.inf,
            duty_rules.SEW_K + duty_rules.IEC_60034_1
            if duty.duty_type == "S2"
            else duty_rules.KLYUCHEV + duty_rules.ISSUE_15,
        ),
        Check(
            "duty_peak_torque",
            "largest load torque of the cycle within the starting torque",
            e["peak_load"],
            e["start_torque"],
            "N·m",
            e["start_torque"] / e["peak_load"] if e["peak_load"] > 0 else math.inf,
            cite("4a-table", "M_start/M_n") + duty_rules.ISSUE_15,
        ),
    ]
    if duty.duty_type == "S3":
        checks.append(
            Check(
                "duty_s3_factor",
                f"S3 running torque within K·M_n (K = {k_s3:g}, SEW's S3 factor)",
                e["run_s3"],
                k_s3 * e["rated"],
                "N·m",
                k_s3 * e["rated"] / e["run_s3"] if e["run_s3"] > 0 else math.inf,
                duty_rules.SEW_K + duty_rules.IEC_60034_1,
            )
        )
    if e["starts"] > 0:
        checks.append(
            Check(
                "duty_starts_per_hour",
                "starts per hour within what the motor allows",
                e["starts"],
                e["allowed"],
                "1/h",
                e["allowed"] / e["starts"],
                duty_rules.IEC_60034_1,
            )
        )
    move = sum(p.time_s for p in phases if p.speed_start_rad_s or p.speed_end_rad_s)
    t_cycle = duty_calc.cycle_time(phases)
    out = DutyOut.make(
        motor=m.model,
        ratio=2.0 * math.pi / _lead_m(ev),
        cycle_time_s=t_cycle,
        move_time_s=move,
        # the check's demand and capacity: the largest load torque at the motor against the
        # starting torque; the motor's own mean starting torque stated beside them
        peak_torque_Nm=e["peak_load"],
        peak_torque_limit_Nm=e["start_torque"],
        mean_starting_torque_Nm=e["mean_start"],
        rms_torque_Nm=e["rms"],
        rated_torque_Nm=e["rated"],
        thermal_utilisation=util,
        thermal_basis=basis,
        inertia_ratio=ir,
        inertia_ratio_guideline=duty_rules.INERTIA_RATIO_GUIDELINE,
        energy_per_cycle_J=out_J,
        regenerated_per_cycle_J=back_J,
        mean_speed_rpm=duty_calc.mean_speed(phases) * RPM,
        # S2 is one run from cold, not a cycle that repeats
        cycles_per_hour=None if duty.duty_type == "S2" else 3600.0 / t_cycle if t_cycle else 0.0,
        duty_type=duty.duty_type or "cycle",
        held_by=_held_by(ev, holder, passage),
        regenerated_to=(
            "the supply: a motor on the line generates above its synchronous speed straight "
            "into the mains, so there is no DC bus and no braking resistor to size (on an "
            "inverter the bus would take it: see the rotary drive's [drive] table)"
            if back_J > 0
            else None
        ),
        standstill_cooling_factor=beta0,
        starts_per_hour=e["starts"],
        # the starts allowed mean something only where starts are counted (S4, S5, S7, moves)
        allowed_starts_per_hour=e["allowed"] if e["starts"] > 0 else None,
        no_load_starts_per_hour=e["z0"] if e["starts"] > 0 else None,
        inertia_factor=e["fi"],
        phases=phases_out(phases),
    )
    return out, m, checks, warnings


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
