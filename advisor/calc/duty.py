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
    """A load inertia reflected to the motor shaft while the motor drives the load.

        J_motor = J_load/(q²·η)

    Parameters
    ----------
    load_inertia_kgm2 : float
        Load inertia at the reducer's output [kg·m²]
    ratio : float
        Reducer ratio q, motor speed over load speed [-], > 0
    efficiency : float
        Reducer efficiency η while the motor drives [-], 0 < η ≤ 1 (1: lossless)

    Returns
    -------
    float
        Inertia the motor sees [kg·m²]

    Notes
    -----
    η = 1 is seed 003's model (J_p/i²). For the load driving the motor back the inertia is
    J_load·η'/q² (module conventions); this function gives the driving case only.

    References
    ----------
    Seed 003, eq. (3) (J0 + J_p/i²); Chilikin, «Общий курс электропривода», ch. 1; Klyuchev,
    «Теория электропривода», §1.2 (reduction of inertias).

    >>> reflected_inertia(5.0, 10.0)
    0.05
    >>> round(reflected_inertia(5.0, 10.0, 0.8), 6)
    0.0625
    """
    return load_inertia_kgm2 / (ratio * ratio * efficiency)


def reflected_torque(
    load_torque_Nm: float, ratio: float, efficiency: float, driving: bool
) -> float:
    """A load torque reflected to the motor shaft, driving or back-driven.

        M_motor = M_load/(q·η)      the motor drives the load
        M_motor = M_load·η'/q       the load drives the motor back, η' = max(η', 0)

    Parameters
    ----------
    load_torque_Nm : float
        Load torque at the reducer's output [N·m]
    ratio : float
        Reducer ratio q, motor speed over load speed [-], > 0
    efficiency : float
        Driving efficiency η [-], 0 < η ≤ 1, when ``driving``; else the back-driven η' [-]
        (≤ 0: self-locking, the load cannot drive the motor and the result is 0)
    driving : bool
        True when the motor drives the load, False when the load drives the motor

    Returns
    -------
    float
        Torque at the motor [N·m], with the sign of ``load_torque_Nm``

    References
    ----------
    Chilikin, «Общий курс электропривода», ch. 1; Klyuchev, «Теория электропривода», §1.2
    (reduction of static torques); seed 004 for the back-driven efficiency of a worm.

    >>> reflected_torque(100.0, 10.0, 0.8, True), reflected_torque(100.0, 10.0, 0.8, False)
    (12.5, 8.0)
    """
    if driving:
        return load_torque_Nm / (ratio * efficiency)
    return load_torque_Nm * max(efficiency, 0.0) / ratio


def cycle_time(phases: list[Phase]) -> float:
    """Duration of a cycle: the sum of its phases' times.

        t_c = Σ t_k

    Parameters
    ----------
    phases : list[Phase]
        The cycle's phases at the motor (times [s] ≥ 0)

    Returns
    -------
    float
        Cycle time t_c [s]; 0 for no phases

    >>> cycle_time([Phase("a", 1.0, 0.0, 10.0, 3.0), Phase("r", 3.0, 0.0, 0.0, 0.0)])
    4.0
    """
    return sum(p.time_s for p in phases)


def peak_torque(phases: list[Phase]) -> float:
    """The largest |M| of the cycle, over phases of non-zero duration.

        M_max = max |M_k|  (t_k > 0)

    Parameters
    ----------
    phases : list[Phase]
        The cycle's phases at the motor (torques [N·m], times [s])

    Returns
    -------
    float
        Peak torque magnitude [N·m]; 0 when no phase has a duration

    Notes
    -----
    A phase of zero time (a ramp the move never takes) does not count.

    >>> peak_torque([Phase("a", 1.0, 0.0, 10.0, 3.0), Phase("b", 1.0, 10.0, 0.0, -5.0)])
    5.0
    """
    return max((abs(p.torque_Nm) for p in phases if p.time_s > 0), default=0.0)


def rms_torque(phases: list[Phase], standstill_factor: float = 1.0) -> float:
    """Equivalent (RMS) torque of a cycle, with reduced cooling at low speed.

        M_eq = √(Σ M_k²·t_k / Σ β_k·t_k),   β = 1 at speed, β0 at standstill, (1 + β0)/2 in a ramp

    Parameters
    ----------
    phases : list[Phase]
        The cycle's phases at the motor (torques [N·m], times [s])
    standstill_factor : float
        β0, the cooling at standstill over the cooling at speed [-], 0 < β0 ≤ 1
        (1: independent cooling, the plain RMS over the cycle)

    Returns
    -------
    float
        Equivalent torque M_eq [N·m], to compare with the continuous (S1) torque; 0 for a
        cycle of no time

    References
    ----------
    Klyuchev, «Теория электропривода», §11 (method of equivalent quantities); Chilikin,
    «Общий курс электропривода», ch. 9.

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
    """The cooling weight β of a phase in the equivalent-torque denominator.

        β = β0 at standstill,   (1 + β0)/2 in a ramp,   1 at constant speed

    Parameters
    ----------
    p : Phase
        One phase at the motor
    standstill_factor : float
        β0, the cooling at standstill over the cooling at speed [-], 0 < β0 ≤ 1

    Returns
    -------
    float
        β [-]

    References
    ----------
    Klyuchev, «Теория электропривода», §11; Chilikin, «Общий курс электропривода», ch. 9.

    >>> [cooling_weight(Phase("x", 1.0, w0, w1, 0.0), 0.5) for w0, w1 in ((0, 0), (0, 9), (9, 9))]
    [0.5, 0.75, 1.0]
    """
    if p.at_standstill:
        return standstill_factor
    if p.ramp:
        return (1.0 + standstill_factor) / 2.0
    return 1.0


def mean_speed(phases: list[Phase]) -> float:
    """Time-weighted mean |ω| over the cycle.

        ω_mean = Σ |(ω1,k + ω2,k)/2|·t_k / Σ t_k

    Parameters
    ----------
    phases : list[Phase]
        The cycle's phases at the motor (speeds [rad/s], times [s])

    Returns
    -------
    float
        Mean speed [rad/s] (the speed iron and magnet losses see on average); 0 for a cycle
        of no time

    Notes
    -----
    A phase's mean speed is taken before its absolute value: a ramp through zero speed is not
    expected (each phase keeps one direction).

    >>> mean_speed([Phase("a", 1.0, 0.0, 10.0, 3.0), Phase("r", 3.0, 0.0, 0.0, 0.0)])
    1.25
    """
    t = cycle_time(phases)
    return sum(abs(p.mean_speed_rad_s) * p.time_s for p in phases) / t if t > 0 else 0.0


def energies(phases: list[Phase]) -> tuple[float, float]:
    """Energy the motor delivers and energy the load gives back, per cycle.

        E_out = Σ max(E_k, 0),   E_back = Σ max(−E_k, 0),   E_k = M_k·(ω1,k + ω2,k)/2·t_k

    Parameters
    ----------
    phases : list[Phase]
        The cycle's phases at the motor (torques [N·m], speeds [rad/s], times [s])

    Returns
    -------
    tuple[float, float]
        (E_out [J], E_back [J]), both ≥ 0; E_back is the regeneration a drive must absorb

    >>> energies([Phase("a", 1.0, 0.0, 10.0, 3.0), Phase("b", 1.0, 10.0, 0.0, -3.0)])
    (15.0, 15.0)
    """
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
    """Seed 003's move at the motor: accelerate, run at ω0, brake (or a triangle).

        ε₁ = (M_λ − M_a)/J,  ε₂ = (M_λ + M_b)/J,  θ_ramps = ω0²/(2ε₁) + ω0²/(2ε₂);
        θ ≥ θ_ramps: run θ − θ_ramps at ω0;  else peak v = √(2θ·ε₁ε₂/(ε₁ + ε₂)), no run

    Parameters
    ----------
    speed_rad_s : float
        Motor speed ω0 [rad/s], > 0
    accel_torque_Nm, brake_torque_Nm : float
        Motor torque M_λ accelerating, braking (magnitude; the brake phase is negative) [N·m]
    run_torque_Nm : float
        Motor torque at ω0, the load's [N·m]
    inertia_kgm2 : float
        Total inertia at the motor J [kg·m²], > 0
    path_rad : float
        Motor-shaft path θ [rad], > 0
    accel_load_Nm, brake_load_Nm : float
        Load torque at the motor opposing the ramp up M_a, helping the braking M_b [N·m]

    Returns
    -------
    list[Phase]
        accelerate, run (only if its time > 0), brake

    Notes
    -----
    Valid for ε₁ > 0 and ε₂ > 0. Seed 003, eqs. (1)–(4) (the triangle: the same ramps).

    >>> [p.time_s for p in trapezoid_phases(10.0, 3.0, 3.0, 1.0, 1.0, 100.0, 1.0, 1.0)]
    [5.0, 6.25, 2.5]
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
    """First-order thermal model over repeated cycles, from cold, stepped phase by phase.

        C·dΔT/dt = P − ΔT/R,  τ = R·C;   ΔT₊ = ΔT·e^(−t/τ) + P·R·(1 − e^(−t/τ))

    Parameters
    ----------
    losses_W : list[tuple[float, float]]
        The cycle's phases, (loss P [W], duration t [s]) each, piecewise constant
    resistance_K_W : float
        Thermal resistance R to ambient [K/W]
    time_constant_s : float
        Thermal time constant τ = R·C [s], > 0
    cycles : int
        Number of cycles from cold, ≥ 0

    Returns
    -------
    list[tuple[float, float]]
        (time [s], rise ΔT [K]) at the end of each phase, from (0, 0)

    Notes
    -----
    One body, one time constant: the motor's heating as a homogeneous body, as the method of
    equivalent quantities assumes (Klyuchev §11; Chilikin ch. 9). :func:`thermal_history` gives
    the same points in closed form.

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
    """:func:`thermal_rise` as a report keeps it, each point in closed form.

        ΔT_c = B·(1 − A^c)/(1 − A)   at the start of cycle c, from cold

    Keeps every step-th of the N = cycles·m + 1 points (m phases a cycle), step = max(1, N //
    max_points), and the last. A phase (P, d) maps ΔT ↦ ΔT·a + P·R·(1 − a), a = e^(−d/τ); the
    first j compose to ΔT·A_j + B_j, a cycle to ΔT·A + B; 1 − A^c and 1 − A by ``expm1`` (no
    cancellation for a cycle short against τ). Agrees with :func:`thermal_rise` to ~1e-13 rel.

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

    >>> thermal_history([(9.0, 6.0)], 0.5, 6.0, 1) == thermal_rise([(9.0, 6.0)], 0.5, 6.0, 1)
    True
    """
    m = len(losses_W)
    prefix = _phase_maps(losses_W, resistance_K_W, time_constant_s)
    cycle_s, _, b_cycle = prefix[-1]
    x = cycle_s / time_constant_s  # the cycle's A = e^(−x)
    one_cycle = math.expm1(-x)  # A − 1, the denominator of every cycle's start

    n = cycles * m + 1
    step = max(1, n // max_points)
    kept = list(range(step, n, step))
    if (n - 1) % step:
        kept.append(n - 1)
    times = _clock(losses_W, cycles, prefix, kept)
    out = [(0.0, 0.0)]
    for i, t_i in zip(kept, times, strict=True):  # point i ends phase j of cycle c
        c, j = divmod(i - 1, m)
        _, a_j, b_j = prefix[j + 1]
        start = b_cycle * math.expm1(-c * x) / one_cycle if c and x > 0 else c * b_cycle
        out.append((t_i, start * a_j + b_j))
    return out


#: Up to this many points the clock is summed phase by phase; beyond, c·t_c + t_j.
_SUMMED_CLOCK_POINTS = 200_000


def _clock(losses_W, cycles: int, prefix, kept: list[int]) -> list[float]:
    """The times of the kept points. The durations summed one after another, as thermal_rise
    sums them: c·t_c + t_j differs from that sum in the last bit, which decides a time printed
    to 6 digits. A history of very many points (a cycle short against 5τ) takes c·t_c + t_j,
    so its cost stays with the points kept."""
    m = len(losses_W)
    if cycles * m + 1 <= _SUMMED_CLOCK_POINTS:
        durations = itertools.chain.from_iterable(
            itertools.repeat([d for _, d in losses_W], cycles)
        )
        times = list(itertools.accumulate(durations, initial=0.0))
        return [times[i] for i in kept]
    cycle_s = prefix[-1][0]
    return [c * cycle_s + prefix[j + 1][0] for c, j in (divmod(i - 1, m) for i in kept)]


def periodic_peak_rise(
    losses_W: list[tuple[float, float]], resistance_K_W: float, time_constant_s: float
) -> float:
    """The highest ΔT of a cycle in the periodic steady state (cycles settled).

        ΔT₀ = B/(1 − A),   over one cycle ΔT ↦ A·ΔT + B,
        A = Π e^(−t_k/τ),   B from ΔT ↦ ΔT·e^(−t/τ) + P·R·(1 − e^(−t/τ)) phase by phase

    Parameters
    ----------
    losses_W : list[tuple[float, float]]
        The cycle's phases, (loss P [W], duration t [s]) each
    resistance_K_W : float
        Thermal resistance R to ambient [K/W]
    time_constant_s : float
        Thermal time constant τ [s], > 0

    Returns
    -------
    float
        max ΔT over the phase ends of the settled cycle, ΔT₀ included [K] (ΔT₀ taken as 0
        when A = 1, a cycle of no time)

    Notes
    -----
    The same first-order model as :func:`thermal_rise`. For equal on and off phases of time
    t, ΔT_max = P·R/(1 + e^(−t/τ)):

    >>> round(periodic_peak_rise([(100.0, 600.0), (0.0, 600.0)], 0.5, 600.0), 4)
    36.5529
    """
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
    """SEW's power increasing factor K of an S1 motor run in S2 for a period.

        K = 1.4 / 1.2 / 1.1 for ≤ 10 / 30 / 60 min,   1.0 beyond 60 min (S1)

    Parameters
    ----------
    duration_min : float
        Period of operation of the S2 run [min], ≥ 0

    Returns
    -------
    float
        K [-], the multiple of the rated S1 power the motor may give for that period

    Notes
    -----
    The table (:data:`S2_POWER_FACTOR`) is not interpolated: a period between two rows takes
    the K of the next longer row (the smaller K, on the safe side); a period shorter than
    10 min takes the 10 min row's 1.4 (not extrapolated); rows match within
    :data:`TABLE_REL_TOL`.

    References
    ----------
    SEW-EURODRIVE, «Manual – Gear Units and Gearmotors», §7.5, p. 95, "Power increasing factor
    K"; IEC 60034-1, 4.2.2 (S2).

    >>> s2_power_factor(10), s2_power_factor(30), s2_power_factor(45), s2_power_factor(90)
    (1.4, 1.2, 1.1, 1.0)
    """
    for period, k in S2_POWER_FACTOR:
        if duration_min <= period * (1.0 + TABLE_REL_TOL):
            return k
    return 1.0


def s3_power_factor(cyclic_duration_factor: float) -> float:
    """SEW's power increasing factor K of an S1 motor run in S3 at a cyclic duration factor.

        K = 1.4 / 1.3 / 1.15 / 1.1 for cdf ≤ 15 / 25 / 40 / 60 %,   1.0 beyond 60 % (S1)

    Parameters
    ----------
    cyclic_duration_factor : float
        Cyclic duration factor, on-time over cycle time [-], 0 < cdf ≤ 1

    Returns
    -------
    float
        K [-], the multiple of the rated S1 power allowed while on

    Notes
    -----
    Read as :func:`s2_power_factor` reads its table (:data:`S3_POWER_FACTOR`): a cdf between
    two rows takes the K of the next larger cdf (the smaller K); one under 15 % keeps 1.4. The
    table is for a cycle of about 10 min (:func:`s3_factor_for_cycle` for other lengths).

    References
    ----------
    SEW-EURODRIVE, «Manual – Gear Units and Gearmotors», §7.5, p. 95; IEC 60034-1, 4.2.3 (S3).

    >>> s3_power_factor(0.4), s3_power_factor(0.3), s3_power_factor(0.1), s3_power_factor(0.8)
    (1.15, 1.15, 1.4, 1.0)
    """
    for cdf, k in S3_POWER_FACTOR:
        if cyclic_duration_factor <= cdf * (1.0 + TABLE_REL_TOL):
            return k
    return 1.0


def s3_factor_for_cycle(cyclic_duration_factor: float, cycle_time_s: float) -> float:
    """SEW's S3 factor K over a cycle of any length, held to the S2 factor of the on-time.

        K = min(K_S3(cdf), K_S2(cdf·t_c/60))

    Parameters
    ----------
    cyclic_duration_factor : float
        Cyclic duration factor [-], 0 < cdf ≤ 1
    cycle_time_s : float
        Cycle time t_c [s], > 0

    Returns
    -------
    float
        K [-]

    Notes
    -----
    SEW's S3 table is for a cycle of about 10 min; over a longer cycle the on-time alone can
    heat the motor as far as an S2 run from cold, which never gets more than its S2 factor.

    References
    ----------
    SEW-EURODRIVE, «Manual – Gear Units and Gearmotors», §7.5, p. 95 (both tables);
    IEC 60034-1, 4.2.3 (10 min cycle unless agreed).

    >>> s3_factor_for_cycle(0.15, 600.0), s3_factor_for_cycle(0.15, 6000.0)
    (1.4, 1.2)
    """
    on_time_min = cyclic_duration_factor * cycle_time_s / 60.0
    return min(s3_power_factor(cyclic_duration_factor), s2_power_factor(on_time_min))


def inertia_factor(motor_inertia_kgm2: float, external_inertia_kgm2: float) -> float:
    """Factor of inertia FI of a motor and its load.

        FI = (J_M + J_ext)/J_M

    Parameters
    ----------
    motor_inertia_kgm2 : float
        Rotor inertia J_M [kg·m²], > 0
    external_inertia_kgm2 : float
        External inertia J_ext reflected to the motor shaft [kg·m²], ≥ 0

    Returns
    -------
    float
        FI [-], ≥ 1

    References
    ----------
    IEC 60034-1, 3.18 "factor of inertia"; a parameter of the duty types with starts (4.2).

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
    """Heat of one direct-on-line start of a cage motor from standstill to ω0.

        Q = J·ω0²/2 · M_m/(M_m − M_L) · (1 + R1/R2')

    Parameters
    ----------
    total_inertia_kgm2 : float
        Inertia at the motor shaft, rotor and load [kg·m²]
    synchronous_speed_rad_s : float
        Synchronous speed ω0 [rad/s]
    mean_start_torque_Nm : float
        Mean motor torque M_m during the start [N·m], > M_L
    load_torque_Nm : float
        Load torque at the motor M_L during the start [N·m], < M_m
    stator_to_rotor_resistance : float
        R1/R2' [-], ≥ 0 (1: stator losses equal to rotor losses)

    Returns
    -------
    float
        Heat Q of one start, rotor and stator [J]

    Notes
    -----
    The rotor dissipates J·ω0²/2 while the slip goes 1 → 0; against a load torque the load's
    share grows as M_m/(M_m − M_L); the stator adds R1/R2' times that.

    References
    ----------
    Chilikin, «Общий курс электропривода», ch. 9, losses in transients.

    >>> round(start_energy_J(0.002, 157.08, 10.0, 0.0), 3)  # 0.002·157.08²/2·2
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


#: k_b of an electric (DC-injection) stop: its heat taken equal to a start's, the same kinetic
#: energy being dissipated in the rotor (Chilikin, ch. 9); plugging would be 3.
DC_BRAKING_HEAT = 1.0


def allowed_starts_per_hour(
    no_load_starts_per_hour: float,
    fi: float,
    load_share: float,
    running_utilisation: float,
    cyclic_duration_factor: float,
    braking_energy_factor: float = 0.0,
) -> float:
    """Starts per hour an induction motor allows under a load (S4/S5).

        z = z0·max(1 − u²·cdf, 0)/(FI·k_L·(1 + k_b))

    Parameters
    ----------
    no_load_starts_per_hour : float
        z0, no-load starts per hour of the bare motor [1/h]
    fi : float
        Factor of inertia FI [-], ≥ 1 (:func:`inertia_factor`)
    load_share : float
        k_L = M_m/(M_m − M_L), the load's share of the start heat [-], ≥ 1
    running_utilisation : float
        u, running torque over rated torque [-]; its copper loss takes u²·cdf of the budget
    cyclic_duration_factor : float
        cdf [-], 0 … 1
    braking_energy_factor : float
        k_b, braking heat as a share of a start's [-]: 0 no electric braking (S4), 1 DC
        braking, 3 plugging (S5)

    Returns
    -------
    float
        Allowed starts per hour z [1/h], ≥ 0

    References
    ----------
    The reduction-factor method of IEC 60034-1 S4/S5 practice (makers' permissible switching
    frequency, e.g. Siemens and SEW catalogs); IEC 60034-1, 3.18 (FI), 4.2.4–4.2.5.

    >>> round(allowed_starts_per_hour(1000.0, 2.0, 1.25, 0.5, 0.4), 3)  # 1000·0.9/2.5
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
    """No-load starts per hour z0 of a bare motor, from its heat budget.

        z0 = 3600·P_loss·c/(J_M·ω0²)

    Parameters
    ----------
    rated_losses_W : float
        Rated losses P_loss, what the motor's cooling carries at rated load [W]
    motor_inertia_kgm2 : float
        Rotor inertia J_M [kg·m²], > 0
    synchronous_speed_rad_s : float
        Synchronous speed ω0 [rad/s], > 0
    cooling : float
        c, cooling of a motor that only starts and stops over its cooling at speed [-]:
        (1 + β0)/2 for a self-ventilated one, 1 for independent cooling

    Returns
    -------
    float
        z0 [1/h]

    Notes
    -----
    The heat of one start is :func:`start_energy_J` with J_M, M_L = 0 and R1/R2' = 1, i.e.
    J_M·ω0²; an estimate where the maker's z0 is not given.

    >>> round(no_load_starts_per_hour(200.0, 0.002, 157.08), 1)  # 3600·200/(0.002·157.08²)
    14590.2
    """
    heat = start_energy_J(motor_inertia_kgm2, synchronous_speed_rad_s, 1.0, 0.0)
    return 3600.0 * rated_losses_W * cooling / heat
