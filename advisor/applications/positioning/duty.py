"""The positioning drive's duty (issue 15): seed 003's move repeated every ``cycle_time_s``.

At ratio i the motor accelerates with M_λ against M_p/i, runs at ω0 with M_p/i and brakes with
M_λ helped by M_p/i, on J0 + J_p/i² (seed 003, eqs. (1)–(4)); then it rests, holding nothing
(seed 003's M_p resists the motion, like friction: at rest it asks no torque). The RMS torque
of that cycle is checked against the motor's continuous (S1) torque; the motor is the one
whose move is fastest among those that pass, each at the fastest ratio that passes.
"""

import math
from functools import lru_cache

from advisor.calc import duty as du
from advisor.calc import motion as mo
from advisor.calc.checks import Check
from advisor.calc.roots import golden_min
from advisor.core.errors import InfeasibleError
from advisor.core.rulebook import Trace
from advisor.duty.report import DutyOut, phases_out
from rules import duty as du_rules
from rules import motion as mo_rules

RPM = 30.0 / math.pi


def cycle(d: mo.Drive, path_rad: float, i: float, cycle_time_s: float) -> list[du.Phase] | None:
    """The phases of one cycle at ratio i (None: the motor cannot move the load, i ≤ m)."""
    load = d.load_torque_Nm / i
    if d.accel_torque_Nm <= load:
        return None
    j = d.inertia_kgm2 + du.reflected_inertia(d.load_inertia_kgm2, i)
    phases = du.trapezoid_phases(
        d.speed_rad_s, d.accel_torque_Nm, d.accel_torque_Nm, load, j, path_rad * i, load, load
    )
    rest = cycle_time_s - du.cycle_time(phases)
    if rest > 0:
        phases.append(du.Phase("rest", rest, 0.0, 0.0, 0.0))
    return phases


@lru_cache(maxsize=8192)
def _eval(d: mo.Drive, path: float, i: float, t_cycle: float) -> tuple[float, float]:
    """(move time, RMS torque over the cycle) at ratio i; inf where the load cannot move.
    Cached within one advice (:func:`advise_duty` clears it first): the fastest passing
    ratio and the least-RMS ratio scan the same grid."""
    ph = cycle(d, path, i, t_cycle)
    if ph is None:
        return math.inf, math.inf
    move = sum(p.time_s for p in ph if p.name != "rest")
    return move, du.rms_torque(ph) if move <= t_cycle else math.inf


def _grid(d: mo.Drive, fastest: float) -> list[float]:
    lo = max(d.torque_ratio * (1.0 + 1e-6), mo.RATIO_MIN, fastest / 1e3)
    hi = min(max(fastest * 1e3, lo * 10.0), mo.RATIO_MAX)
    n = 400
    return [lo * (hi / lo) ** (k / n) for k in range(n + 1)]


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


def fastest_passing(
    d: mo.Drive, path: float, t_cycle: float, rated: float, fastest: float
) -> tuple[float, float] | None:
    """The fastest ratio whose cycle passes (move fits, RMS ≤ rated): (ratio, move time).
    The unconstrained optimum when it passes; otherwise the constraint binds, and the best
    ratio lies on the boundary of the passing set, found by bisection from a grid."""

    def ok(i: float) -> bool:
        t, r = _eval(d, path, i, t_cycle)
        return t <= t_cycle and r <= rated

    if ok(fastest):
        return fastest, _eval(d, path, fastest, t_cycle)[0]
    grid = _grid(d, fastest)
    flags = [ok(i) for i in grid]
    best: tuple[float, float] | None = None
    for k, i in enumerate(grid):
        if not flags[k]:
            continue
        cands = [i]
        if k > 0 and not flags[k - 1]:
            cands.append(_refine(ok, i, grid[k - 1]))
        if k + 1 < len(grid) and not flags[k + 1]:
            cands.append(_refine(ok, i, grid[k + 1]))
        for c in cands:
            t = _eval(d, path, c, t_cycle)[0]
            if best is None or t < best[1]:
                best = (c, t)
    return best


def least_rms(d: mo.Drive, path: float, t_cycle: float, fastest: float) -> tuple[float, float]:
    """The ratio of least RMS torque over the cycle among those whose move fits: a grid, then
    a golden-section search on log i around the grid's minimum, or, where the minimum lies
    at the edge of the fitting ratios (the move filling the whole cycle), bisection on that
    edge."""
    grid = _grid(d, fastest)
    vals = [_eval(d, path, i, t_cycle)[1] for i in grid]
    k = min(range(len(grid)), key=vals.__getitem__)
    best = (grid[k], vals[k])
    for j in (k - 1, k + 1):
        if 0 <= j < len(grid) and math.isinf(vals[j]):
            edge = _refine(lambda i: _eval(d, path, i, t_cycle)[0] <= t_cycle, grid[k], grid[j])
            r = _eval(d, path, edge, t_cycle)[1]
            if r < best[1]:
                best = (edge, r)
    if 0 < k < len(grid) - 1 and math.isfinite(vals[k - 1]) and math.isfinite(vals[k + 1]):
        a, b = math.log(grid[k - 1]), math.log(grid[k + 1])
        f = lambda x: _eval(d, path, math.exp(x), t_cycle)[1]  # noqa: E731
        x = golden_min(f, a, b, iterations=100)
        if f(x) < best[1]:
            best = (math.exp(x), f(x))
    return best


def advise_duty(
    drives: list[tuple[str, mo.Drive]],
    rated: dict[str, float],
    fastest: dict[str, float],
    path: float,
    cycle_time_s: float,
    seed_best: str,
    trace: Trace,
    sizing: tuple[float, dict[str, tuple[float, float]]] | None = None,
) -> tuple[DutyOut, list[Check], list[str]]:
    """Choose motor and ratio for the cycle; the checks and warnings of that choice.

    ``sizing`` — (required move time, name → (power, inertia)): a motor passes only if its
    move at the cycle's ratio also meets the required time, and the smallest that passes is
    chosen (issue 25, decision MO-06); without it, the fastest that passes (DU-01)."""
    _eval.cache_clear()  # one advice's evaluations are shared, never a previous advice's
    rows: dict[str, tuple[float, float, bool, str]] = {}
    reasons = []
    for name, d in drives:
        i_fast = fastest[name]
        t_fast, rms_fast = _eval(d, path, i_fast, cycle_time_s)
        if t_fast > cycle_time_s:
            rows[name] = (t_fast, i_fast, False, "the move does not fit in the cycle")
            reasons.append(
                f"motor {name}: its fastest move takes {t_fast:.4g} s (i = {i_fast:.4g}), "
                f"longer than duty.cycle_time_s = {cycle_time_s:g} s"
            )
            continue
        found = fastest_passing(d, path, cycle_time_s, rated[name], i_fast)
        if found is None:
            i_min, rms_min = least_rms(d, path, cycle_time_s, i_fast)
            rows[name] = (t_fast, i_fast, False, f"RMS {rms_fast:.4g} > {rated[name]:.4g} N·m")
            reasons.append(
                f"motor {name}: RMS torque {rms_fast:.4g} N·m at its fastest ratio "
                f"{i_fast:.4g}, and at least {rms_min:.4g} N·m at any ratio (i = {i_min:.4g}), "
                f"against its rated torque {rated[name]:.4g} N·m"
            )
            continue
        if sizing is not None and found[1] > sizing[0]:
            rows[name] = (found[1], found[0], False, f"move > {sizing[0]:g} s required")
            reasons.append(
                f"motor {name}: its move at the ratio that passes the cycle, i = "
                f"{found[0]:.4g}, takes {found[1]:.4g} s, longer than the required "
                f"{sizing[0]:g} s"
            )
            continue
        rows[name] = (found[1], found[0], True, "")
    if not any(r[2] for r in rows.values()):
        raise InfeasibleError("no feasible design: no motor passes the duty cycle", reasons)
    if sizing is None:
        best = trace.apply(du_rules.motor_for_cycle, rows)
    else:
        best = trace.apply(mo_rules.smallest_for_cycle, sizing[0], rows, sizing[1])
    d = dict(drives)[best]
    i = rows[best][1]
    phases = cycle(d, path, i, cycle_time_s)
    assert phases is not None
    move = sum(p.time_s for p in phases if p.name != "rest")
    rms = du.rms_torque(phases)
    peak = du.peak_torque(phases)
    out_J, back_J = du.energies(phases)
    i_min, rms_min = least_rms(d, path, cycle_time_s, fastest[best])
    trace.apply(du_rules.least_rms_ratio, best, i_min, rms_min, i, rms)
    util = rms / rated[best]
    trace.apply(
        du_rules.thermal,
        util,
        f"RMS torque over the cycle √(Σ M²·t / T) = {rms:.4g} N·m against the motor's rated "
        f"(S1) torque {rated[best]:.4g} N·m; the phases M_λ, M_p/i, M_λ of seed 003, then "
        "rest at zero torque (the load resists motion only). The motor's cooling is taken as "
        "at speed throughout (β0 = 1): rated_torque_Nm is the continuous torque it holds in "
        "this cycle's cooling.",
    )
    trace.apply(
        du_rules.peak,
        peak,
        d.accel_torque_Nm,
        "Seed 003's move starts and brakes at the motor's M_λ: the peak is M_λ by "
        "construction, the motor's own starting and braking torque.",
    )
    ir = du.reflected_inertia(d.load_inertia_kgm2, i) / d.inertia_kgm2
    within = trace.apply(du_rules.inertia_ratio, ir)
    warnings = []
    if not within:
        warnings.append(
            f"duty: the load's inertia at the motor is {ir:.3g} times the motor's (guideline "
            f"{du_rules.INERTIA_RATIO_GUIDELINE:g}): expect a hard-to-tune control loop"
        )
    if best != seed_best:
        single = "the fastest motor" if sizing is None else "the motor"
        warnings.append(
            f"duty: the cycle chooses motor {best}, not {single} of the single move "
            "(design.motion), which does not pass the cycle"
        )
    elif abs(i / fastest[best] - 1.0) > 1e-9:
        warnings.append(
            f"duty: the cycle needs i = {i:.4g}, not the fastest ratio {fastest[best]:.4g}: "
            "there the RMS torque exceeds the rated torque; i is the ratio nearest the fastest "
            "where the RMS torque equals the rated one, so its thermal margin is 1.000 by "
            "construction — a ratio a little larger runs cooler at almost the same move time"
        )
    src = du_rules.KLYUCHEV + du_rules.ISSUE_15
    checks = [
        Check(
            "duty_move_fits",
            "the move fits in the cycle time",
            move,
            cycle_time_s,
            "s",
            cycle_time_s / move,
            du_rules.SEED_003.at("eq. (4)") + du_rules.ISSUE_15,
        ),
        Check(
            "duty_rms_torque",
            "RMS torque over the cycle within the rated (S1) torque",
            rms,
            rated[best],
            "N·m",
            rated[best] / rms if rms > 0 else math.inf,
            src,
        ),
    ]
    duty = DutyOut.make(
        motor=best,
        ratio=i,
        cycle_time_s=cycle_time_s,
        move_time_s=move,
        peak_torque_Nm=peak,
        peak_torque_limit_Nm=d.accel_torque_Nm,
        rms_torque_Nm=rms,
        rated_torque_Nm=rated[best],
        thermal_utilisation=util,
        thermal_basis="RMS torque over the rated (S1) torque",
        inertia_ratio=ir,
        inertia_ratio_guideline=du_rules.INERTIA_RATIO_GUIDELINE,
        energy_per_cycle_J=out_J,
        regenerated_per_cycle_J=back_J,
        mean_speed_rpm=du.mean_speed(phases) * RPM,
        cycles_per_hour=3600.0 / cycle_time_s,
        duty_type="cycle",
        min_rms_ratio=i_min,
        min_rms_torque_Nm=rms_min,
        phases=phases_out(phases),
    )
    return duty, checks, warnings


def rated_torques(req, cat) -> dict[str, float]:
    """Each candidate's continuous (S1) torque: the requirement's, or the catalog motor's
    rated torque P_n/ω_n."""
    if req.positioning.motors:
        return {m.name: m.rated_torque_Nm for m in req.positioning.motors}
    return {m.model: m.rated_torque_Nm for m in cat.motors}
