"""The positioning drive's duty: seed 003's move repeated every ``cycle_time_s``.

At ratio i the motor accelerates with M_λ against M_p/i, runs at ω0 with M_p/i and brakes with
M_λ helped by M_p/i, on J0 + J_p/i² (seed 003, eqs. (1)–(4)); then it rests, holding nothing
(seed 003's M_p resists the motion, like friction: at rest it asks no torque). The RMS torque
of that cycle is checked against the motor's continuous (S1) torque. A catalog induction motor
starts direct-on-line and stops electrically once a cycle, and the heat of those starts is not
a torque (the starting current is several times the rated one): its starts per hour are checked
as the linear duty's are (:func:`advisor.calc.duty.allowed_starts_per_hour`). The motor is the
one whose move is fastest among those that pass (or, with a required time, the smallest), each
at the fastest ratio that passes. A catalog motor whose rotor inertia is an estimate is held to
that inertia 30 % higher throughout — move, torques and starts — as MO-05 holds its move.
"""

import math
from collections.abc import Callable
from dataclasses import dataclass

import rules.duty
from advisor.applications.positioning.candidates import (
    Solved,
    decisive_inertia,
    inertia_is_estimate,
)
from advisor.applications.positioning.stated import shown_above, shown_apart, stated_up
from advisor.calc.checks import Check
from advisor.calc.duty import (
    DC_BRAKING_HEAT,
    Phase,
    allowed_starts_per_hour,
    cycle_time,
    energies,
    inertia_factor,
    mean_speed,
    no_load_starts_per_hour,
    peak_torque,
    reflected_inertia,
    rms_torque,
    trapezoid_phases,
)
from advisor.calc.motion import RATIO_MAX, RATIO_MIN, Drive
from advisor.calc.roots import golden_min
from advisor.core.errors import InfeasibleError
from advisor.core.rulebook import Trace
from advisor.duty.report import DutyOut, phases_out
from rules.motion import INERTIA_BAND, SEED_003, CycleFit, Size, smallest_for_cycle

RPM = 30.0 / math.pi
#: β0 of the catalog's self-ventilated (4A, IP44) motors at standstill, the linear duty's
#: default for the same motors: a motor that only starts and stops is cooled by (1 + β0)/2.
STANDSTILL_COOLING = 0.5
#: The seed's move ends with the motor braking at M_λ: an electric (DC-injection) stop, whose
#: heat is taken equal to a start's (k_b = 1; plugging would be 3).
BRAKING_HEAT = DC_BRAKING_HEAT


@dataclass(frozen=True, slots=True)
class StartHeat:
    """What bounds a catalog induction motor's starts (DU-06): its no-load starts per hour z0
    (rated losses over a start's heat J_M·ω0², cooled by (1 + β0)/2), its rotor inertia and
    rated torque, and the starts the cycle asks (one direct-on-line start and one electric
    stop per cycle)."""

    no_load_starts_per_hour: float
    motor_inertia_kgm2: float
    rated_torque_Nm: float
    starts_per_hour: float
    braking_heat: float = BRAKING_HEAT


@dataclass(frozen=True, slots=True)
class StartFigures:
    """The starts a motor allows at one ratio: z = z0·(1 − u²)/(FI·k_L·(1 + k_b))."""

    starts_per_hour: float
    allowed_starts_per_hour: float
    no_load_starts_per_hour: float
    inertia_factor: float
    load_factor: float
    running_utilisation: float
    braking_heat: float


def start_heat(m, cycle_time_s: float, inertia_kgm2: float | None = None) -> StartHeat:
    """A catalog induction motor's start-heat budget: P_loss = P_n·(100/η − 1), z0 =
    3600·P_loss·(1 + β0)/2/(J_M·ω_s²) at the synchronous speed ω_s
    (:func:`advisor.calc.duty.no_load_starts_per_hour`). ``inertia_kgm2``: the rotor inertia
    J_M to count (the catalog's where not given)."""
    j_m = m.inertia_kgm2 if inertia_kgm2 is None else inertia_kgm2
    p_loss = m.rated_power_kW * 1e3 * (100.0 / m.efficiency_pct - 1.0)
    w_sync = m.synchronous_speed_rpm * math.pi / 30.0
    z0 = no_load_starts_per_hour(p_loss, j_m, w_sync, (1.0 + STANDSTILL_COOLING) / 2.0)
    return StartHeat(z0, j_m, m.rated_torque_Nm, 3600.0 / cycle_time_s)


def cooling_at_rest(heat: StartHeat | None) -> float:
    """β0 of the cycle's equivalent torque (:func:`~advisor.calc.duty.rms_torque`): a catalog
    induction motor (one with a start-heat budget) is self-ventilated, cooled by β0 =
    ``STANDSTILL_COOLING`` at rest and (1 + β0)/2 in a ramp, as the linear duty takes the same
    motors (Klyuchev, §11); a listed motor's cooling is not given, and its rated_torque_Nm is
    taken as the continuous torque it holds in this cycle's cooling (β0 = 1)."""
    return 1.0 if heat is None else STANDSTILL_COOLING


def start_figures(h: StartHeat, d: Drive, path: float, i: float, t_cycle: float) -> StartFigures:
    """The starts the motor allows at ratio i: FI = (J_M + J_p/i²)/J_M, k_L = M_λ/(M_λ − M_p/i)
    (the start at M_λ against M_p/i), u the running copper heat — the RMS over the cycle with
    the start and the stop at zero torque, their heat being what the starts count — over the
    rated torque, cdf 1 (u already averages over the cycle)."""
    load = d.load_torque_Nm / i
    fi = inertia_factor(h.motor_inertia_kgm2, reflected_inertia(d.load_inertia_kgm2, i))
    k_l = d.accel_torque_Nm / (d.accel_torque_Nm - load) if d.accel_torque_Nm > load else math.inf
    phases = cycle(d, path, i, t_cycle) or []
    running = [p if p.name == "run" else p._replace(torque_Nm=0.0) for p in phases]
    u = rms_torque(running, STANDSTILL_COOLING) / h.rated_torque_Nm if running else math.inf
    z = allowed_starts_per_hour(h.no_load_starts_per_hour, fi, k_l, u, 1.0, h.braking_heat)
    return StartFigures(h.starts_per_hour, z, h.no_load_starts_per_hour, fi, k_l, u, h.braking_heat)


def cycle(d: Drive, path_rad: float, i: float, cycle_time_s: float) -> list[Phase] | None:
    """The phases of one cycle at ratio i (None: the motor cannot move the load, i ≤ m)."""
    load = d.load_torque_Nm / i
    if d.accel_torque_Nm <= load:
        return None
    j = d.inertia_kgm2 + reflected_inertia(d.load_inertia_kgm2, i)
    phases = trapezoid_phases(
        d.speed_rad_s, d.accel_torque_Nm, d.accel_torque_Nm, load, j, path_rad * i, load, load
    )
    rest = cycle_time_s - cycle_time(phases)
    if rest > 0:
        phases.append(Phase("rest", rest, 0.0, 0.0, 0.0))
    return phases


def cycle_figures(
    d: Drive, path: float, t_cycle: float, standstill_cooling: float = 1.0
) -> Callable[[float], tuple[float, float]]:
    """(move time [s], RMS torque over the cycle [N·m]) as a function of the ratio i, for one
    drive, path and cycle; the RMS is inf where the move does not fit in the cycle, both are
    inf where the load cannot move (i ≤ m). ``standstill_cooling``: β0 of the equivalent
    torque M_eq = √(Σ M²·t / Σ β·t) (β = β0 at rest, (1 + β0)/2 in a ramp, 1 at speed;
    1: the plain RMS over the cycle).

    The figures of :func:`cycle` and :func:`~advisor.calc.duty.rms_torque` to the last bit
    (the same operations in the same order) without building the phases: the ratio scans
    evaluate about a thousand cycles per advice, so what does not depend on i is read once.
    A term of zero is left out of a sum (x + 0.0 is x): the run when the move is a triangle,
    the rest at zero torque."""
    speed, inertia, torque, load_inertia, load_torque = d
    speed_2, square = speed**2, torque**2
    beta0 = standstill_cooling
    beta_ramp = (1.0 + beta0) / 2.0

    def at(i: float) -> tuple[float, float]:
        load = load_torque / i
        if torque <= load:
            return math.inf, math.inf
        j = inertia + reflected_inertia(load_inertia, i)
        e1, e2 = (torque - load) / j, (torque + load) / j  # trapezoid_phases
        path_i = path * i
        ramps = speed_2 / (2.0 * e1) + speed_2 / (2.0 * e2)
        if path_i >= ramps:
            t_run, v = (path_i - ramps) / speed, speed
        else:
            t_run, v = 0.0, math.sqrt(2.0 * path_i * e1 * e2 / (e1 + e2))
        t_accel, t_brake = v / e1, v / e2
        move = t_accel + t_run + t_brake
        if move > t_cycle:
            return move, math.inf
        num = square * t_accel + load**2 * t_run + square * t_brake
        rest = t_cycle - move
        if beta0 == 1.0:
            den = move + rest if rest > 0 else move  # with the rest, if any
        else:
            den = t_accel * beta_ramp + t_run + t_brake * beta_ramp
            den = den + rest * beta0 if rest > 0 else den
        return move, math.sqrt(num / den)

    return at


def move_and_rms(
    d: Drive, path: float, i: float, t_cycle: float, standstill_cooling: float = 1.0
) -> tuple[float, float]:
    """:func:`cycle_figures` at one ratio i."""
    return cycle_figures(d, path, t_cycle, standstill_cooling)(i)


def _search_range(d: Drive, fastest: float) -> tuple[float, float]:
    """The ratios searched: three decades either side of the fastest, above m."""
    lo = max(d.torque_ratio * (1.0 + 1e-6), RATIO_MIN, fastest / 1e3)
    hi = min(max(fastest * 1e3, lo * 10.0), RATIO_MAX)
    return lo, hi


def _log_points(a: float, b: float, n: int = 400) -> list[float]:
    """n + 1 ratios from a to b (both included), spaced evenly on log i."""
    return [a * (b / a) ** (k / n) for k in range(n + 1)]


def _refine(f, a: float, b: float, n: int = 80) -> float:
    """Bisection on the boundary of f(i) ≤ 0 between a (passes) and b (fails)."""
    for _ in range(n):
        c = math.sqrt(a * b)
        if c == a or c == b:  # no float between them: more steps would change nothing
            break
        if f(c):
            a = c
        else:
            b = c
    return a


def fitting_window(
    at: Callable[[float], tuple[float, float]], d: Drive, t_cycle: float, fastest: float
) -> tuple[float, float]:
    """The ratios whose move fits in the cycle, [lo, hi] within the range searched.

    The move time t(i) of seed 003's law is unimodal in i, least at the fastest ratio and
    growing without bound as i → m and as i → ∞ (eqs. (3)–(4); checked on dense grids over six
    decades of every input), so the ratios that fit are one interval around the fastest and
    each end is the root of t(i) = t_cycle on its side, found by bisection on log i. The
    fastest ratio must fit (t(fastest) ≤ t_cycle); an end of the range searched that fits is
    the window's end."""
    lo, hi = _search_range(d, fastest)

    def fits(i: float) -> bool:
        return at(i)[0] <= t_cycle

    a = lo if fits(lo) else _refine(fits, fastest, lo)
    b = hi if fits(hi) else _refine(fits, fastest, hi)
    return a, b


def _nearest_passing(ok, fastest: float, edge: float, seed: float | None = None) -> float | None:
    """The passing ratio nearest the fastest (which fails) between it and ``edge``: the first
    of 200 ratios spaced evenly on log i that passes, walking out from the fastest, then
    bisection back towards it. ``seed``: a ratio known to pass, among the points if it lies on
    this side, so that a passing set narrower than the points' step is not missed."""
    points = _log_points(fastest, edge, 200)[1:]
    if seed is not None and min(fastest, edge) <= seed <= max(fastest, edge):
        points = sorted([*points, seed], key=lambda i: abs(math.log(i / fastest)))
    previous = fastest
    for i in points:
        if ok(i):
            return _refine(ok, i, previous)
        previous = i
    return None


def fastest_passing(
    d: Drive,
    path: float,
    t_cycle: float,
    rated: float,
    fastest: float,
    heat: StartHeat | None = None,
    standstill_cooling: float = 1.0,
) -> tuple[float, float] | None:
    """The fastest ratio whose cycle passes (move fits, RMS ≤ rated, and with a start-heat
    budget the starts per hour within those allowed): (ratio, move time). The unconstrained
    optimum when it passes; otherwise a constraint binds, and since the move time grows on
    each side of the fastest ratio (:func:`fitting_window`), the best ratio is the passing one
    nearest the fastest on one side, on the boundary of the passing set. Where no point of the
    walk passes, the ratio of least RMS torque seeds it (:func:`least_rms`): if that passes,
    a passing ratio exists and is found, however narrow the passing set."""
    at = cycle_figures(d, path, t_cycle, standstill_cooling)

    def starts_ok(i: float) -> bool:
        if heat is None:
            return True
        return (
            heat.starts_per_hour <= start_figures(heat, d, path, i, t_cycle).allowed_starts_per_hour
        )

    def ok(i: float) -> bool:
        t, r = at(i)
        return t <= t_cycle and r <= rated and starts_ok(i)

    if ok(fastest):
        return fastest, at(fastest)[0]
    edges = fitting_window(at, d, t_cycle, fastest)
    found = [_nearest_passing(ok, fastest, e) for e in edges]
    if all(i is None for i in found):
        seed = least_rms(d, path, t_cycle, fastest, standstill_cooling)[0]
        if ok(seed):
            found = [_nearest_passing(ok, fastest, e, seed) for e in edges]
    times = [(at(i)[0], i) for i in found if i is not None]
    if not times:
        return None
    t, i = min(times)
    return i, t


def least_rms(
    d: Drive, path: float, t_cycle: float, fastest: float, standstill_cooling: float = 1.0
) -> tuple[float, float]:
    """The ratio of least RMS torque over the cycle among those whose move fits, and that
    RMS: the window of fitting ratios (:func:`fitting_window`, the fastest ratio inside it),
    401 ratios across it, then a golden-section search on log i around the least of them (an
    end of the window is itself a point: a minimum where the move fills the whole cycle is
    found exactly). ``fastest``: the ratio of the fastest move, which must fit."""
    at = cycle_figures(d, path, t_cycle, standstill_cooling)
    grid = _log_points(*fitting_window(at, d, t_cycle, fastest))
    vals = [rms for _, rms in map(at, grid)]
    k = min(range(len(grid)), key=vals.__getitem__)
    best = (grid[k], vals[k])
    a, b = math.log(grid[max(k - 1, 0)]), math.log(grid[min(k + 1, len(grid) - 1)])
    if a < b:
        f = lambda x: at(math.exp(x))[1]  # noqa: E731
        x = golden_min(f, a, b, iterations=100)
        if f(x) < best[1]:
            best = (math.exp(x), f(x))
    return best


@dataclass(frozen=True, slots=True)
class CycleAtRatio:
    """One motor's cycle at one ratio: its phases and the figures the duty checks."""

    motor: str
    drive: Drive
    ratio: float
    phases: list[Phase]
    move_time_s: float
    rms_torque_Nm: float
    rated_torque_Nm: float
    min_rms_ratio: float  # the ratio of least RMS torque whose move fits (DU-02)
    min_rms_torque_Nm: float
    starts: StartFigures | None = None  # a catalog induction motor's starts (DU-06)
    inertia_estimated: bool = False  # the drive's J0 is the catalog's estimate raised (MO-05)
    standstill_cooling: float = 1.0  # β0 of the RMS torque (:func:`cooling_at_rest`)

    @property
    def utilisation(self) -> float:
        return self.rms_torque_Nm / self.rated_torque_Nm

    @property
    def inertia_ratio(self) -> float:
        return reflected_inertia(self.drive.load_inertia_kgm2, self.ratio) / self.drive.inertia_kgm2


def most_starts(
    d: Drive, path: float, t_cycle: float, rated: float, fastest: float, heat: StartHeat
) -> tuple[float, float]:
    """The most starts per hour the motor allows at any of 401 ratios across those whose move
    fits (:func:`fitting_window`) whose RMS torque passes (with the catalog motor's standstill
    cooling β0), and that ratio; (0, fastest) where none."""
    at = cycle_figures(d, path, t_cycle, STANDSTILL_COOLING)
    best = (0.0, fastest)
    for i in _log_points(*fitting_window(at, d, t_cycle, fastest)):
        t, r = at(i)
        if t <= t_cycle and r <= rated:
            z = start_figures(heat, d, path, i, t_cycle).allowed_starts_per_hour
            if z > best[0]:
                best = (z, i)
    return best


def _starts_fail(
    s: Solved, rated: float, path: float, t_cycle: float, heat: StartHeat
) -> tuple[CycleFit, str]:
    """A motor whose torques pass the cycle at some ratio but whose starts do not at any."""
    i_fast = s.solution.ratio
    z, i = most_starts(s.drive, path, t_cycle, rated, i_fast, heat)
    t_fast = move_and_rms(s.drive, path, i_fast, t_cycle, STANDSTILL_COOLING)[0]
    need = heat.starts_per_hour
    return CycleFit(t_fast, i_fast, False, f"{need:.4g} starts/h > {z:.4g} allowed"), (
        f"motor {s.name}: {need:.4g} starts/h (a direct-on-line start and an electric stop "
        f"every {t_cycle:g} s), at most {z:.4g} allowed at any ratio whose RMS torque passes "
        f"(i = {i:.4g}): the heat of its starts overheats it"
    )


def fit_cycle(
    s: Solved,
    rated: float,
    path: float,
    cycle_time_s: float,
    required_s: float | None,
    heat: StartHeat | None = None,
) -> tuple[CycleFit, str | None]:
    """A motor against the cycle: at the fastest ratio whose cycle passes, its move time and
    whether it passes (the move fits, the RMS torque within the rated one, with a start-heat
    budget the starts per hour within those allowed, and with a required time the move meets
    it); where it fails, the reason the infeasible report gives. A catalog induction motor
    (``heat`` given) is self-ventilated: its RMS torque is weighted by β0 at rest
    (:func:`standstill_cooling`)."""
    name, d, i_fast = s.name, s.drive, s.solution.ratio
    beta0 = cooling_at_rest(heat)
    t_fast, rms_fast = move_and_rms(d, path, i_fast, cycle_time_s, beta0)
    if t_fast > cycle_time_s:
        return CycleFit(t_fast, i_fast, False, "the move does not fit in the cycle"), (
            f"motor {name}: its fastest move takes {shown_above(t_fast, cycle_time_s)} s "
            f"(i = {i_fast:.4g}), longer than duty.cycle_time_s = {cycle_time_s:.10g} s"
        )
    found = fastest_passing(d, path, cycle_time_s, rated, i_fast, heat, beta0)
    if (
        found is None
        and heat is not None
        and fastest_passing(d, path, cycle_time_s, rated, i_fast, None, beta0)
    ):
        return _starts_fail(s, rated, path, cycle_time_s, heat)
    if found is None:
        i_min, rms_min = least_rms(d, path, cycle_time_s, i_fast, beta0)
        least, rating = shown_apart(rms_min, rated)  # 15 against 15 reads as passing
        return CycleFit(t_fast, i_fast, False, f"RMS {rms_fast:.4g} > {rated:.4g} N·m"), (
            f"motor {name}: RMS torque {rms_fast:.4g} N·m at its fastest ratio "
            f"{i_fast:.4g}, and at least {least} N·m at any ratio "
            f"(i = {i_min:.4g}), against its rated torque {rating} N·m"
        )
    i, t = found
    if required_s is not None and t > required_s:
        return CycleFit(t, i, False, f"move > {required_s:g} s required"), (
            f"motor {name}: its move at the ratio that passes the cycle, i = "
            f"{i:.4g}, takes {shown_above(t, required_s)} s, longer than the required "
            f"{required_s:.10g} s"
        )
    return CycleFit(t, i, True, ""), None


@dataclass(frozen=True, slots=True)
class CycleChoice:
    """The cycle's motor and ratio, and with a required time the fastest motor that passes
    the cycle (all its checks, the starts included) with its move there."""

    motor: Solved
    ratio: float
    fastest_motor: str | None = None
    fastest_move_time_s: float | None = None


def choose_for_cycle(
    solved: list[Solved],
    rated: dict[str, float],
    path: float,
    cycle_time_s: float,
    required_s: float | None,
    trace: Trace,
    heats: dict[str, StartHeat] | None = None,
    sizes: dict[str, Size] | None = None,
) -> CycleChoice:
    """The motor and ratio for the cycle: the fastest that passes (DU-01), or with a required
    time the smallest that passes (MO-06), the fastest that passes beside it; none: no
    feasible design. ``heats``: the start-heat budgets of catalog induction motors, whose
    starts per hour must pass too; ``sizes``: what ranks the motors (MO-06; by default the
    power and the inertia of ``solved``)."""
    heats = heats or {}
    rows: dict[str, CycleFit] = {}
    reasons = []
    for s in solved:
        rows[s.name], reason = fit_cycle(
            s, rated[s.name], path, cycle_time_s, required_s, heats.get(s.name)
        )
        if reason is not None:
            reasons.append(reason)
    if not any(r.passes for r in rows.values()):
        if any("starts/h" in r.why_not for r in rows.values()):
            reasons.append(
                "a cage motor started direct-on-line and stopped electrically this often is "
                "limited by the heat of its starts: allow a longer duty.cycle_time_s, or list "
                "motors for frequent starting (servo or inverter-fed) in [[positioning.motors]]"
            )
        raise InfeasibleError("no feasible design: no motor passes the duty cycle", reasons)
    if required_s is None:
        best = trace.apply(rules.duty.motor_for_cycle, rows)
        return CycleChoice(next(s for s in solved if s.name == best), rows[best].ratio)
    if sizes is None:
        sizes = {s.name: Size(s.candidate.power_W, s.drive.inertia_kgm2) for s in solved}
    best = trace.apply(smallest_for_cycle, required_s, rows, sizes)
    fastest = trace.find("MO-06").inputs["fastest_motor"]
    return CycleChoice(
        next(s for s in solved if s.name == best),
        rows[best].ratio,
        fastest,
        rows[fastest].move_time_s,
    )


def cycle_at(
    s: Solved,
    i: float,
    rated: float,
    path: float,
    cycle_time_s: float,
    heat: StartHeat | None = None,
) -> CycleAtRatio:
    """The chosen motor's cycle at ratio ``i``, with the ratio of least RMS torque beside it
    and, with a start-heat budget, its starts."""
    phases = cycle(s.drive, path, i, cycle_time_s)
    assert phases is not None
    beta0 = cooling_at_rest(heat)
    i_min, rms_min = least_rms(s.drive, path, cycle_time_s, s.solution.ratio, beta0)
    return CycleAtRatio(
        motor=s.name,
        drive=s.drive,
        ratio=i,
        phases=phases,
        move_time_s=sum(p.time_s for p in phases if p.name != "rest"),
        rms_torque_Nm=rms_torque(phases, beta0),
        rated_torque_Nm=rated,
        min_rms_ratio=i_min,
        min_rms_torque_Nm=rms_min,
        starts=None if heat is None else start_figures(heat, s.drive, path, i, cycle_time_s),
        inertia_estimated=s.candidate.inertia_estimated,
        standstill_cooling=beta0,
    )


def _thermal_basis(c: CycleAtRatio) -> str:
    """DU-04's basis: the equivalent torque of the cycle and the cooling it is weighted by."""
    head = (
        f"the motor's rated (S1) torque {c.rated_torque_Nm:.4g} N·m; the phases M_λ, M_p/i, M_λ "
        "of seed 003, then rest at zero torque (the load resists motion only)."
    )
    if c.standstill_cooling == 1.0:
        return (
            f"RMS torque over the cycle √(Σ M²·t / T) = {c.rms_torque_Nm:.4g} N·m against {head} "
            "A listed motor's cooling is not given: it is taken as at speed throughout (β0 = 1), "
            "rated_torque_Nm being the continuous torque it holds in this cycle's cooling."
        )
    beta0 = c.standstill_cooling
    return (
        f"Equivalent torque over the cycle √(Σ M²·t / Σ β·t) = {c.rms_torque_Nm:.4g} N·m against "
        f"{head} The catalog's induction motor is self-ventilated (IP44): β = {beta0:g} at rest, "
        f"{(1.0 + beta0) / 2.0:g} in the ramps, 1 at speed (β0 = {beta0:g}, as the linear duty "
        "and the starts check take it; Klyuchev, §11)."
    )


def explain_cycle(c: CycleAtRatio, trace: Trace) -> bool:
    """DU-02, DU-04, DU-05, DU-03: least-RMS ratio, thermal verdict, peak torque and inertia
    ratio of the chosen cycle; whether the inertia ratio is within its guideline."""
    trace.apply(
        rules.duty.least_rms_ratio,
        c.motor,
        c.min_rms_ratio,
        c.min_rms_torque_Nm,
        c.ratio,
        c.rms_torque_Nm,
    )
    trace.apply(
        rules.duty.thermal,
        c.utilisation,
        _thermal_basis(c),
    )
    trace.apply(
        rules.duty.peak,
        peak_torque(c.phases),
        c.drive.accel_torque_Nm,
        "Seed 003's move starts and brakes at the motor's M_λ: the peak is M_λ by "
        "construction, the motor's own starting and braking torque.",
    )
    if c.starts is not None:
        z = c.starts
        raised = f" (its estimate {INERTIA_BAND * 100:.0f} % higher, MO-05)"
        trace.apply(
            rules.duty.starts,
            z.starts_per_hour,
            z.allowed_starts_per_hour,
            f"z = z0·(1 − u²)/(FI·k_L·(1 + k_b)) = {z.no_load_starts_per_hour:.4g}·(1 − "
            f"{z.running_utilisation:.3g}²)/({z.inertia_factor:.4g}·{z.load_factor:.4g}·"
            f"(1 + {z.braking_heat:g})): z0 = 3600·P_loss·(1 + β0)/2/(J_M·ω_s²) from the "
            f"catalog's rated losses P_n·(100/η − 1) and rotor inertia J_M = "
            f"{c.drive.inertia_kgm2:.4g} kg·m²{raised if c.inertia_estimated else ''}, β0 = "
            f"{STANDSTILL_COOLING:g} (self-ventilated); FI = (J_M + J_p/i²)/J_M; k_L = "
            "M_λ/(M_λ − M_p/i); u the running torque's RMS over the rated torque (the start "
            "and the stop counted here, not in it); k_b = 1, the seed's braking at M_λ taken "
            "as a DC-injection stop. A start heats rotor and stator by J·ω0²/2 each "
            "(R1/R2' = 1): Chilikin, ch. 9.",
        )
    return trace.apply(rules.duty.inertia_ratio, c.inertia_ratio)


@dataclass(frozen=True, slots=True)
class AtFastest:
    """The chosen motor's cycle at its fastest ratio: what a warning compares the built ratio
    with where the cycle moved it."""

    ratio: float
    move_time_s: float
    rms_torque_Nm: float
    allowed_starts_per_hour: float | None  # a catalog induction motor's (DU-06)


def at_fastest(s: Solved, path: float, cycle_time_s: float, heat: StartHeat | None) -> AtFastest:
    """The motor's move, RMS torque and allowed starts at its fastest ratio."""
    i = s.solution.ratio
    t, rms = move_and_rms(s.drive, path, i, cycle_time_s, cooling_at_rest(heat))
    z = None if heat is None else start_figures(heat, s.drive, path, i, cycle_time_s)
    return AtFastest(i, t, rms, None if z is None else z.allowed_starts_per_hour)


def _ratio_moved(c: CycleAtRatio, fast: AtFastest) -> str:
    """Why the cycle's ratio is not the fastest: the checks that fail at the fastest, the one
    at its limit at the built ratio (the lowest margin: the limit that moved it), and the size
    of the change, in ratio and in move time."""
    rms_margin = c.rated_torque_Nm / c.rms_torque_Nm if c.rms_torque_Nm > 0 else math.inf
    z = c.starts
    starts_margin = math.inf if z is None else z.allowed_starts_per_hour / z.starts_per_hour
    there = []
    if fast.rms_torque_Nm > c.rated_torque_Nm:
        there.append(
            f"the RMS torque {fast.rms_torque_Nm:.4g} N·m exceeds the rated "
            f"{c.rated_torque_Nm:.4g} N·m (DU-04)"
        )
    if z is not None and fast.allowed_starts_per_hour < z.starts_per_hour:
        there.append(
            f"the motor allows {fast.allowed_starts_per_hour:.4g} starts/h, fewer than the "
            f"{z.starts_per_hour:.4g} the cycle asks (DU-06)"
        )
    if starts_margin < rms_margin:
        limit = (
            f"the starts it allows equal those asked, so its starts margin is {starts_margin:.3f}"
        )
    else:
        limit = f"the RMS torque equals the rated one, so its thermal margin is {rms_margin:.3f}"
    r = c.ratio / fast.ratio
    if abs(r - 1.0) < 0.5:
        ratio = f"the ratio {abs(r - 1.0) * 100:.3g} % {'larger' if r > 1 else 'smaller'}"
    else:
        ratio = f"the ratio {r:.3g} times the fastest"
    slower = (c.move_time_s / fast.move_time_s - 1.0) * 100
    move, move_fast = shown_apart(c.move_time_s, fast.move_time_s)
    return (
        f"there {' and '.join(there) or 'the cycle does not pass'}; i is the ratio nearest the "
        f"fastest where {limit} by construction — {ratio}, the move {move} s against "
        f"{move_fast} s ({slower:+.3g} %)"
    )


def cycle_warnings(
    c: CycleAtRatio, within: bool, seed_best: str, fast: AtFastest, sized: bool
) -> list[str]:
    """What the reader of the cycle must know: a hard-to-tune inertia ratio, a motor or a
    ratio other than the single move's (``fast``: the chosen motor at its fastest ratio)."""
    warnings = []
    if not within:
        warnings.append(
            f"duty: the load's inertia at the motor is {c.inertia_ratio:.3g} times the motor's "
            f"(guideline {rules.duty.INERTIA_RATIO_GUIDELINE:g}): expect a hard-to-tune "
            "control loop"
        )
    if c.motor != seed_best:
        single = "the motor" if sized else "the fastest motor"
        warnings.append(
            f"duty: the cycle chooses motor {c.motor}, not {single} of the single move "
            "(design.motion), which does not pass the cycle"
        )
    elif abs(c.ratio / fast.ratio - 1.0) > 1e-9:
        raised = f" (its estimated inertia {INERTIA_BAND * 100:.0f} % higher)"
        warnings.append(
            f"duty: the cycle needs i = {c.ratio:.4g}, not the fastest ratio "
            f"{fast.ratio:.4g}{raised if c.inertia_estimated else ''}: {_ratio_moved(c, fast)}"
        )
    return warnings


def cycle_checks(c: CycleAtRatio, cycle_time_s: float) -> list[Check]:
    """The move fits in the cycle; the RMS torque within the rated (S1) torque."""
    rms, rated = c.rms_torque_Nm, c.rated_torque_Nm
    return [
        Check(
            "duty_move_fits",
            "the move fits in the cycle time",
            c.move_time_s,
            cycle_time_s,
            "s",
            cycle_time_s / c.move_time_s,
            SEED_003.at("eq. (4)") + rules.duty.DUTY_METHOD,
        ),
        Check(
            "duty_rms_torque",
            "RMS torque over the cycle within the rated (S1) torque",
            rms,
            rated,
            "N·m",
            rated / rms if rms > 0 else math.inf,
            rules.duty.KLYUCHEV + rules.duty.DUTY_METHOD,
        ),
        *_starts_checks(c),
    ]


def _starts_checks(c: CycleAtRatio) -> list[Check]:
    """A catalog induction motor's starts per hour within those it allows."""
    if c.starts is None:
        return []
    z = c.starts
    return [
        Check(
            "duty_starts_per_hour",
            "starts per hour within what the motor allows",
            z.starts_per_hour,
            z.allowed_starts_per_hour,
            "1/h",
            z.allowed_starts_per_hour / z.starts_per_hour,
            rules.duty.IEC_60034_1 + rules.duty.DUTY_METHOD,
        )
    ]


def duty_out(c: CycleAtRatio, cycle_time_s: float, choice: CycleChoice | None = None) -> DutyOut:
    """The report's duty table of the chosen cycle; with ``choice`` of a required time, the
    fastest motor that passes the cycle beside it."""
    out_J, back_J = energies(c.phases)
    fastest = {}
    if choice is not None and choice.fastest_motor is not None:
        fastest = {
            "fastest_motor": choice.fastest_motor,
            "fastest_move_time_s": stated_up(choice.fastest_move_time_s),
        }
    return DutyOut.make(
        motor=c.motor,
        ratio=c.ratio,
        cycle_time_s=cycle_time_s,
        move_time_s=c.move_time_s,
        peak_torque_Nm=peak_torque(c.phases),
        peak_torque_limit_Nm=c.drive.accel_torque_Nm,
        rms_torque_Nm=c.rms_torque_Nm,
        rated_torque_Nm=c.rated_torque_Nm,
        thermal_utilisation=c.utilisation,
        thermal_basis="RMS torque over the rated (S1) torque",
        inertia_ratio=c.inertia_ratio,
        inertia_ratio_guideline=rules.duty.INERTIA_RATIO_GUIDELINE,
        energy_per_cycle_J=out_J,
        regenerated_per_cycle_J=back_J,
        mean_speed_rpm=mean_speed(c.phases) * RPM,
        cycles_per_hour=3600.0 / cycle_time_s,
        duty_type="cycle",
        min_rms_ratio=c.min_rms_ratio,
        min_rms_torque_Nm=c.min_rms_torque_Nm,
        **_starts_fields(c.starts),
        **_inertia_fields(c),
        **fastest,
        phases=phases_out(c.phases),
    )


def _inertia_fields(c: CycleAtRatio) -> dict:
    """The rotor inertia the cycle used, where it is not the one given: the catalog's
    estimate at the top of its band (MO-05)."""
    if not c.inertia_estimated:
        return {}
    j = c.drive.inertia_kgm2
    pct = f"{INERTIA_BAND * 100:.0f} %"
    return {
        "motor_inertia_kgm2": j,
        "motor_inertia_basis": (
            f"the catalog's estimated rotor inertia {j / (1.0 + INERTIA_BAND):.4g} kg·m², "
            f"counted {pct} higher (MO-05): the move, the torques and the starts of the cycle "
            "are taken with it"
        ),
    }


def _starts_fields(z: StartFigures | None) -> dict:
    """The duty table's starts, where they are counted."""
    if z is None:
        return {}
    return {
        "starts_per_hour": z.starts_per_hour,
        "allowed_starts_per_hour": z.allowed_starts_per_hour,
        "no_load_starts_per_hour": z.no_load_starts_per_hour,
        "inertia_factor": z.inertia_factor,
        "standstill_cooling_factor": STANDSTILL_COOLING,
    }


def advise_duty(
    solved: list[Solved],
    rated: dict[str, float],
    path: float,
    cycle_time_s: float,
    seed_best: str,
    trace: Trace,
    required_s: float | None = None,
    heats: dict[str, StartHeat] | None = None,
    sizes: dict[str, Size] | None = None,
) -> tuple[DutyOut, list[Check], list[str]]:
    """Choose motor and ratio for the cycle; the checks and warnings of that choice.

    ``solved`` — the candidates as the decisions hold them
    (:func:`~advisor.applications.positioning.candidates.held_to`: an estimated inertia at the
    top of its band, its fastest ratio there), so that the move, the torques and the starts
    are judged with the inertia MO-05 judges the move with. ``required_s`` — a required move
    time: a motor passes only if its move at the cycle's ratio also meets it, and the
    smallest that passes is chosen (MO-06), ranked by ``sizes``; without it, the fastest that
    passes (DU-01). ``heats`` — the catalog induction motors' start-heat budgets (at the same
    inertia): their starts per hour must pass too (DU-06)."""
    heats = heats or {}
    choice = choose_for_cycle(solved, rated, path, cycle_time_s, required_s, trace, heats, sizes)
    best, i = choice.motor, choice.ratio
    c = cycle_at(best, i, rated[best.name], path, cycle_time_s, heats.get(best.name))
    within = explain_cycle(c, trace)
    fast = at_fastest(best, path, cycle_time_s, heats.get(best.name))
    warnings = cycle_warnings(c, within, seed_best, fast, required_s is not None)
    return duty_out(c, cycle_time_s, choice), cycle_checks(c, cycle_time_s), warnings


def rated_torques(req, cat) -> dict[str, float]:
    """Each candidate's continuous (S1) torque: the requirement's, or the catalog motor's
    rated torque P_n/ω_n."""
    if req.positioning.motors:
        return {m.name: m.rated_torque_Nm for m in req.positioning.motors}
    return {m.model: m.rated_torque_Nm for m in cat.motors}


def start_heats(req, cat) -> dict[str, StartHeat]:
    """The start-heat budgets of the catalog's induction motors (none for listed motors, whose
    kind and losses are not given: a servo or an inverter-fed motor is not limited so), each
    at the rotor inertia the decisions hold it to: an estimated one at the top of its band
    (MO-05), since a larger J_M means fewer starts."""
    if req.positioning.motors:
        return {}
    return {
        m.model: start_heat(
            m, req.duty.cycle_time_s, decisive_inertia(m.inertia_kgm2, inertia_is_estimate(m))
        )
        for m in cat.motors
    }
