"""Duty cycles: phase torques at the motor, RMS and peak torque, energy, regeneration, a
first-order thermal model, IEC 60034-1 duty types and the starts an induction motor allows.

Pure functions of SI numbers (rad/s, N·m, kg·m², s, W, J); no numpy (the linear path stays
numpy-free). Conventions, stated once:

- A phase is a time at the motor with a constant torque and a speed that changes linearly
  from ``speed_start`` to ``speed_end`` (a ramp, a run at constant speed, or a rest).
- Torque is positive when it drives in the direction of the motion, negative when the motor
  brakes (generates). Power is torque × speed; its positive part over a cycle is the energy the
  motor delivers, its negative part the energy the load gives back (regeneration).
- **Reflection through a reducer of ratio q and efficiency η** (Chilikin, «Общий курс
  электропривода», ch. 1; Klyuchev, «Теория электропривода», §1.2: the reduction of static
  torques and of inertias): when the motor drives the load, M_motor = M_load/(q·η) and the load
  inertia acts at the motor as J_load/(q²·η); when the load drives the motor back (braking a
  moving load, lowering a weight), M_motor = M_load·η'/q and J_load·η'/q², η' the back-driven
  efficiency (0 or less: the drive is self-locking and the load cannot drive the motor).
- **Equivalent torque with reduced cooling** (Klyuchev, «Теория электропривода», §11 the
  method of equivalent quantities; the same in Chilikin, ch. 9): a self-ventilated motor cools
  worse when it turns slowly, so time at standstill counts β0·t and time in a ramp
  (1 + β0)/2·t in the denominator of the RMS. β0 = 1 for a motor with independent cooling.
"""

import itertools
import math
from typing import NamedTuple


class Phase(NamedTuple):
    """One phase of a cycle at the motor shaft."""

    name: str
    time_s: float
    speed_start_rad_s: float
    speed_end_rad_s: float
    torque_Nm: float

    @property
    def mean_speed_rad_s(self) -> float:
        return (self.speed_start_rad_s + self.speed_end_rad_s) / 2.0

    @property
    def energy_J(self) -> float:
        """∫M·ω dt with ω linear in time and M constant: M·(ω1 + ω2)/2·t."""
        return self.torque_Nm * self.mean_speed_rad_s * self.time_s

    @property
    def at_standstill(self) -> bool:
        return self.speed_start_rad_s == 0.0 and self.speed_end_rad_s == 0.0

    @property
    def ramp(self) -> bool:
        return self.speed_start_rad_s != self.speed_end_rad_s


def reflected_inertia(load_inertia_kgm2: float, ratio: float, efficiency: float = 1.0) -> float:
    """J_load/(q²·η) at the motor while the motor drives the load (η = 1: seed 003's model).

    >>> reflected_inertia(5.0, 10.0)
    0.05
    >>> round(reflected_inertia(5.0, 10.0, 0.8), 6)
    0.0625
    """
    return load_inertia_kgm2 / (ratio * ratio * efficiency)


def reflected_torque(
    load_torque_Nm: float, ratio: float, efficiency: float, driving: bool
) -> float:
    """A load torque at the motor: M/(q·η) when the motor drives it, M·η'/q when the load
    drives the motor back (``efficiency`` is then the back-driven one, floored at 0).

    >>> reflected_torque(100.0, 10.0, 0.8, True), reflected_torque(100.0, 10.0, 0.8, False)
    (12.5, 8.0)
    """
    if driving:
        return load_torque_Nm / (ratio * efficiency)
    return load_torque_Nm * max(efficiency, 0.0) / ratio


def cycle_time(phases: list[Phase]) -> float:
    return sum(p.time_s for p in phases)


def peak_torque(phases: list[Phase]) -> float:
    """The largest |M| of the cycle."""
    return max((abs(p.torque_Nm) for p in phases if p.time_s > 0), default=0.0)


def rms_torque(phases: list[Phase], standstill_factor: float = 1.0) -> float:
    """Equivalent torque √(Σ M²·t / Σ β·t), β = 1 at speed, β0 at standstill, (1 + β0)/2 in a
    ramp (see the module's conventions). With β0 = 1 the plain RMS over the cycle.

    >>> rms_torque([Phase("a", 1, 0, 10, 3.0), Phase("r", 3, 0, 0, 0.0)])
    1.5
    """
    num = sum(p.torque_Nm**2 * p.time_s for p in phases)
    if standstill_factor == 1.0:  # every β is 1: the cycle's time (t·1.0 is t, exactly)
        den = sum(p.time_s for p in phases)
    else:
        den = sum(p.time_s * cooling_weight(p, standstill_factor) for p in phases)
    return math.sqrt(num / den) if den > 0 else 0.0


def cooling_weight(p: Phase, standstill_factor: float) -> float:
    """β of a phase: 1 at speed, β0 at standstill, (1 + β0)/2 in a ramp."""
    if p.at_standstill:
        return standstill_factor
    if p.ramp:
        return (1.0 + standstill_factor) / 2.0
    return 1.0


def mean_speed(phases: list[Phase]) -> float:
    """Mean |ω| over the cycle (the speed the iron and magnet losses see on average)."""
    t = cycle_time(phases)
    return sum(abs(p.mean_speed_rad_s) * p.time_s for p in phases) / t if t > 0 else 0.0


def energies(phases: list[Phase]) -> tuple[float, float]:
    """(energy the motor delivers, energy the load gives back) per cycle, J."""
    out = sum(max(p.energy_J, 0.0) for p in phases)
    back = sum(max(-p.energy_J, 0.0) for p in phases)
    return out, back


# ------------------------------------------------------------------ trapezoidal moves
def trapezoid_phases(
    speed_rad_s: float,
    accel_torque_Nm: float,
    brake_torque_Nm: float,
    run_torque_Nm: float,
    inertia_kgm2: float,
    path_rad: float,
    accel_load_Nm: float,
    brake_load_Nm: float,
) -> list[Phase]:
    """The move of seed 003 at the motor: accelerate with M_λ against the load M_a, run at ω0
    with the load, brake with M_λ helped by the load M_b; the total inertia J at the motor.

    Acceleration ε₁ = (M_λ − M_a)/J, braking ε₂ = (M_λ + M_b)/J; the motor reaches ω0 when
    the path covered in the ramps, ω0²/(2ε₁) + ω0²/(2ε₂), is within ``path_rad`` (a trapezoid);
    otherwise it turns at the peak speed v = √(2θ·ε₁ε₂/(ε₁ + ε₂)) (a triangle). The braking
    torque is the motor's, negative (it opposes the motion).
    """
    e1 = (accel_torque_Nm - accel_load_Nm) / inertia_kgm2
    e2 = (brake_torque_Nm + brake_load_Nm) / inertia_kgm2
    ramps = speed_rad_s**2 / (2.0 * e1) + speed_rad_s**2 / (2.0 * e2)
    if path_rad >= ramps:
        t_run = (path_rad - ramps) / speed_rad_s
        v = speed_rad_s
    else:
        t_run = 0.0
        v = math.sqrt(2.0 * path_rad * e1 * e2 / (e1 + e2))
    phases = [Phase("accelerate", v / e1, 0.0, v, accel_torque_Nm)]
    if t_run > 0:
        phases.append(Phase("run", t_run, v, v, run_torque_Nm))
    phases.append(Phase("brake", v / e2, v, 0.0, -brake_torque_Nm))
    return phases


# ------------------------------------------------------------------ thermal model
def thermal_rise(
    losses_W: list[tuple[float, float]],
    resistance_K_W: float,
    time_constant_s: float,
    cycles: int,
) -> list[tuple[float, float]]:
    """First-order thermal model C·dΔT/dt = P − ΔT/R (τ = R·C), from cold, over repeated
    cycles of piecewise-constant losses ``[(P, t), …]``: ΔT at the end of each phase,
    ΔT₊ = ΔT·e^(−t/τ) + P·R·(1 − e^(−t/τ)). Returns ``[(time, ΔT), …]`` from (0, 0).

    >>> round(thermal_rise([(100.0, 1e9)], 0.5, 600.0, 1)[-1][1], 6)
    50.0
    """
    out = [(0.0, 0.0)]
    t = dt = 0.0
    for _ in range(cycles):
        for p, d in losses_W:
            a = math.exp(-d / time_constant_s)
            dt = dt * a + p * resistance_K_W * (1.0 - a)
            t += d
            out.append((t, dt))
    return out


def _phase_maps(
    losses_W: list[tuple[float, float]], resistance_K_W: float, time_constant_s: float
) -> list[tuple[float, float, float]]:
    """(time, A_j, B_j) after the first j phases of a cycle, j = 0 … m: ΔT ↦ ΔT·A_j + B_j."""
    prefix = [(0.0, 1.0, 0.0)]
    for p, d in losses_W:
        a = math.exp(-d / time_constant_s)
        t, a_j, b_j = prefix[-1]
        prefix.append((t + d, a_j * a, b_j * a + p * resistance_K_W * (1.0 - a)))
    return prefix


def thermal_history(
    losses_W: list[tuple[float, float]],
    resistance_K_W: float,
    time_constant_s: float,
    cycles: int,
    max_points: int = 400,
) -> list[tuple[float, float]]:
    """:func:`thermal_rise` as a report keeps it: of its N = cycles·m + 1 points (m phases a
    cycle), every ``step``-th one, step = max(1, N // max_points), and the last; each point in
    closed form instead of stepping through every cycle before it.

    One phase of loss P for a time d maps ΔT to ΔT·a + b, a = e^(−d/τ), b = P·R·(1 − a); the
    first j phases of a cycle compose to ΔT·A_j + B_j, the whole cycle to ΔT·A + B, so the
    rise at the start of cycle c, from cold, is the geometric sum
    ΔT_c = B·(1 − A^c)/(1 − A) (1 − A^c and 1 − A taken by ``expm1``: no cancellation when
    the cycle is short against τ). The same first-order model as :func:`thermal_rise`;
    the two agree to about 1e-13 relative (``tests/test_duty.py``).

    Parameters
    ----------
    losses_W : list[tuple[float, float]]
        The cycle's phases, (loss [W], duration [s]) each
    resistance_K_W : float
        Thermal resistance R to ambient [K/W]
    time_constant_s : float
        Thermal time constant τ = R·C [s], > 0
    cycles : int
        Number of cycles from cold, ≥ 1
    max_points : int
        About the most points kept (the step is N // max_points)

    Returns
    -------
    list[tuple[float, float]]
        (time [s], rise ΔT [K]) from (0, 0)

    >>> thermal_history([(100.0, 600.0), (0.0, 600.0)], 0.5, 600.0, 1)[-1] == (
    ...     thermal_rise([(100.0, 600.0), (0.0, 600.0)], 0.5, 600.0, 1)[-1])
    True
    """
    m = len(losses_W)
    prefix = _phase_maps(losses_W, resistance_K_W, time_constant_s)
    cycle_s, _, b_cycle = prefix[-1]
    x = cycle_s / time_constant_s  # the cycle's A = e^(−x)

    def rise(i: int) -> float:
        if i == 0:
            return 0.0
        c, j = divmod(i - 1, m)
        _, a_j, b_j = prefix[j + 1]
        start = b_cycle * math.expm1(-c * x) / math.expm1(-x) if c and x > 0 else c * b_cycle
        return start * a_j + b_j

    n = cycles * m + 1
    step = max(1, n // max_points)
    kept = list(range(0, n, step))
    if (n - 1) % step:
        kept.append(n - 1)
    # The clock is the durations summed one after another, as thermal_rise sums them: c·t_c + t_j
    # differs from that sum in the last bit, which decides a time printed to 6 digits.
    durations = itertools.chain.from_iterable(itertools.repeat([d for _, d in losses_W], cycles))
    times = list(itertools.accumulate(durations, initial=0.0))
    return [(times[i], rise(i)) for i in kept]


def periodic_peak_rise(
    losses_W: list[tuple[float, float]], resistance_K_W: float, time_constant_s: float
) -> float:
    """The highest ΔT of the cycle once the cycles have settled (the periodic steady state):
    the start value ΔT₀ solves ΔT₀ = A·ΔT₀ + B over one cycle, ΔT₀ = B/(1 − A)."""
    a_total, b = 1.0, 0.0
    for p, d in losses_W:
        a = math.exp(-d / time_constant_s)
        a_total *= a
        b = b * a + p * resistance_K_W * (1.0 - a)
    start = b / (1.0 - a_total) if a_total < 1.0 else 0.0
    peak, dt = start, start
    for p, d in losses_W:
        a = math.exp(-d / time_constant_s)
        dt = dt * a + p * resistance_K_W * (1.0 - a)
        peak = max(peak, dt)
    return peak


# ------------------------------------------------------------------ IEC 60034-1 duty types
#: The duty types of IEC 60034-1 (GOST IEC 60034-1-2014), clause 4.2: what each one is and
#: the parameters that define it.
IEC_DUTY_TYPES: dict[str, str] = {
    "S1": "continuous running duty: constant load long enough to reach thermal equilibrium",
    "S2": "short-time duty: constant load for a time shorter than thermal equilibrium, then rest "
    "until the motor is at ambient temperature (parameter: the time, e.g. S2 30 min)",
    "S3": "intermittent periodic duty: identical cycles of constant load and rest, starting "
    "not heating the motor (parameter: the cyclic duration factor, e.g. S3 25 %)",
    "S4": "intermittent periodic duty with starting: start, constant load, rest (parameters: "
    "cyclic duration factor, starts per hour, inertia factor FI)",
    "S5": "intermittent periodic duty with electric braking: start, load, electric braking, "
    "rest (parameters as S4)",
    "S6": "continuous operation periodic duty: constant load and no-load running, no rest "
    "(parameter: the cyclic duration factor)",
    "S7": "continuous operation periodic duty with electric braking: start, load, electric "
    "braking, no rest (parameters: starts per hour, FI)",
    "S8": "continuous operation periodic duty with related load/speed changes (pole-changing "
    "motors; parameters per speed)",
    "S9": "duty with non-periodic load and speed variations (overloads above the reference "
    "load; the equivalent is S1)",
    "S10": "duty with discrete constant loads and speeds: a few loads, each for a share of "
    "the time (parameters: the loads as shares of the reference load and their time shares)",
}

#: IEC 60034-1 (clause 4.2.3): an S3…S6 cycle is 10 min unless agreed otherwise.
IEC_DEFAULT_CYCLE_S = 600.0

#: SEW-EURODRIVE, «Manual – Gear Units and Gearmotors», §7.5 Thermal characteristics, p. 95,
#: table "Power increasing factor K": a motor rated for S1 (100 % cdf) may give K times its
#: rated power in S2 for the period of operation (min) …
S2_POWER_FACTOR: tuple[tuple[float, float], ...] = ((10.0, 1.4), (30.0, 1.2), (60.0, 1.1))
#: … and in S3 at the cyclic duration factor (same table; cdf as a fraction).
S3_POWER_FACTOR: tuple[tuple[float, float], ...] = (
    (0.15, 1.4),
    (0.25, 1.3),
    (0.40, 1.15),
    (0.60, 1.1),
)


#: A value within this relative distance of a table's row is read as that row: a cdf typed
#: as 0.25 or computed as 0.25·(1 + 1e-9) is the 25 % row, as the stage limits of the wave
#: gear read a ratio (rules.wavegear.RATIO_REL_TOL); no knife edge at a row.
TABLE_REL_TOL = 1e-6


def s2_power_factor(duration_min: float) -> float:
    """SEW's power increasing factor K of an S1 motor run in S2 for ``duration_min``
    (:data:`S2_POWER_FACTOR`). The table is not interpolated: a period between two rows takes
    the K of the next longer row (the smaller K, on the safe side); a period shorter than
    10 min takes the 10 min row's 1.4 (not extrapolated); one longer than 60 min takes 1.0,
    continuous running (S1).

    >>> s2_power_factor(10), s2_power_factor(30), s2_power_factor(45), s2_power_factor(90)
    (1.4, 1.2, 1.1, 1.0)
    """
    for period, k in S2_POWER_FACTOR:
        if duration_min <= period * (1.0 + TABLE_REL_TOL):
            return k
    return 1.0


def s3_power_factor(cyclic_duration_factor: float) -> float:
    """SEW's power increasing factor K of an S1 motor run in S3 at a cyclic duration factor
    (:data:`S3_POWER_FACTOR`), read as :func:`s2_power_factor` reads its table: a cdf between
    two rows takes the K of the next larger cdf (the smaller K), one under 15 % keeps 1.4,
    one over 60 % takes 1.0 (S1).

    >>> s3_power_factor(0.4), s3_power_factor(0.3), s3_power_factor(0.1), s3_power_factor(0.8)
    (1.15, 1.15, 1.4, 1.0)
    """
    for cdf, k in S3_POWER_FACTOR:
        if cyclic_duration_factor <= cdf * (1.0 + TABLE_REL_TOL):
            return k
    return 1.0


def s3_factor_for_cycle(cyclic_duration_factor: float, cycle_time_s: float) -> float:
    """K for S3 over a cycle of any length: SEW's S3 row (:func:`s3_power_factor`), held to
    at most the S2 factor of one run as long as the cycle's on-time (:func:`s2_power_factor`).
    SEW's S3 table is for a cycle of about 10 min; over a longer cycle the on-time alone can
    heat the motor as far as an S2 run from cold, which never gets more than its S2 factor.

    >>> s3_factor_for_cycle(0.15, 600.0), s3_factor_for_cycle(0.15, 6000.0)
    (1.4, 1.2)
    """
    on_time_min = cyclic_duration_factor * cycle_time_s / 60.0
    return min(s3_power_factor(cyclic_duration_factor), s2_power_factor(on_time_min))


def inertia_factor(motor_inertia_kgm2: float, external_inertia_kgm2: float) -> float:
    """FI = (J_M + J_ext)/J_M, J_ext reflected to the motor shaft (IEC 60034-1, 3.18 "factor
    of inertia").

    >>> inertia_factor(0.002, 0.004)
    3.0
    """
    return (motor_inertia_kgm2 + external_inertia_kgm2) / motor_inertia_kgm2


def start_energy_J(
    total_inertia_kgm2: float,
    synchronous_speed_rad_s: float,
    mean_start_torque_Nm: float,
    load_torque_Nm: float,
    stator_to_rotor_resistance: float = 1.0,
) -> float:
    """Heat of one direct-on-line start of a cage motor from standstill to speed: the rotor
    dissipates J·ω0²/2·M_m/(M_m − M_L) (slip 1 → 0 against a load torque M_L, the load's
    share grows as M_m/(M_m − M_L)), the stator the same times R1/R2' (Chilikin, «Общий курс
    электропривода», ch. 9, losses in transients). ``stator_to_rotor_resistance`` = R1/R2'.

    >>> round(start_energy_J(0.002, 157.08, 10.0, 0.0), 3)
    49.348
    """
    load_share = mean_start_torque_Nm / (mean_start_torque_Nm - load_torque_Nm)
    return (
        total_inertia_kgm2
        * synchronous_speed_rad_s**2
        / 2.0
        * load_share
        * (1.0 + stator_to_rotor_resistance)
    )


def allowed_starts_per_hour(
    no_load_starts_per_hour: float,
    fi: float,
    load_share: float,
    running_utilisation: float,
    cyclic_duration_factor: float,
    braking_energy_factor: float = 0.0,
) -> float:
    """Starts per hour an induction motor allows under a load (the reduction-factor method
    of IEC 60034-1 S4/S5 practice, e.g. Siemens/SEW catalogs' permissible switching
    frequency): z = z0·(1 − u²·cdf)/(FI·k_L·(1 + k_b)).

    z0 the no-load starts per hour of the bare motor; FI the inertia factor; k_L =
    M_m/(M_m − M_L) the load's share of the start heat; u the running torque over the rated
    torque (its copper loss takes u²·cdf of the motor's heat budget); k_b the braking heat as
    a share of a start's (0: no electric braking, S4; 3 for plugging, 1 for DC braking, S5).

    >>> round(allowed_starts_per_hour(1000.0, 2.0, 1.25, 0.5, 0.4), 3)
    360.0
    """
    headroom = max(1.0 - running_utilisation**2 * cyclic_duration_factor, 0.0)
    return no_load_starts_per_hour * headroom / (fi * load_share * (1.0 + braking_energy_factor))


def no_load_starts_per_hour(
    rated_losses_W: float,
    motor_inertia_kgm2: float,
    synchronous_speed_rad_s: float,
    cooling: float = 1.0,
) -> float:
    """z0 from the motor's heat budget: the losses its cooling carries, rated losses × the
    cooling of a motor that only starts and stops (``cooling``, (1 + β0)/2 for a
    self-ventilated one), over the heat of one no-load start of the bare rotor
    (:func:`start_energy_J` with J_M, M_L = 0, R1/R2' = 1): z0 = 3600·P_loss·c/(J_M·ω0²).

    >>> round(no_load_starts_per_hour(200.0, 0.002, 157.08), 1)  # 3600·200/(0.002·157.08²)
    14590.2
    """
    heat = start_energy_J(motor_inertia_kgm2, synchronous_speed_rad_s, 1.0, 0.0)
    return 3600.0 * rated_losses_W * cooling / heat
