"""The positioning drive advice (seed 003): for each candidate motor the ratio of the fastest
move; then the motor — the fastest of the listed motors (seed 003), or, where a move time is
required, the smallest motor that meets it (MO-05). Orchestration only."""

from advisor.applications.positioning.candidates import (
    CandidateSet,
    Solved,
    candidates,
    held_as_built,
    held_to,
    usable,
)
from advisor.applications.positioning.report import (
    CurveOut,
    MotionCandidateOut,
    MotionOut,
    PositioningDesignOut,
)
from advisor.applications.positioning.stated import stated_up
from advisor.calc import motion
from advisor.calc.checks import Check
from advisor.core.errors import InfeasibleError
from advisor.core.reading import Requirements
from advisor.core.rulebook import Trace
from catalogs import Catalogs
from rules.motion import (
    INERTIA_BAND,
    SEED_003,
    Size,
    Sized,
    fastest_motor,
    profile_check,
    ratio_per_motor,
    smallest_meeting,
)


def required_time(req: Requirements) -> tuple[float, str] | None:
    """The move time the drive must meet and the field that sets it: positioning.move_time_s,
    or, with catalog candidates and a duty cycle, the cycle (the move must fit in it)."""
    pos = req.positioning
    if pos.move_time_s is not None:
        return pos.move_time_s, "positioning.move_time_s"
    if not pos.motors and req.duty is not None:
        return req.duty.cycle_time_s, "duty.cycle_time_s"
    return None


def _smallest_meeting(
    solved: list[Solved],
    held: dict[str, Solved],
    cands: CandidateSet,
    required: tuple[float, str],
    trace: Trace,
) -> str:
    """MO-05: the smallest candidate whose move meets the required time (``held``: each as the
    decision holds it, an estimated inertia at the top of its band); none: no feasible design,
    with the fastest named."""
    t_req, field = required
    band = INERTIA_BAND
    rows = {
        s.name: Sized(
            s.candidate.power_W,
            s.drive.inertia_kgm2,
            s.solution.move_time_s,
            held[s.name].solution.move_time_s,
        )
        for s in solved
    }
    if not any(r.decisive_time_s <= t_req for r in rows.values()):
        fast = min(rows, key=lambda n: rows[n].decisive_time_s)
        i = held[fast].solution.ratio
        estimated = any(s.candidate.inertia_estimated for s in solved if s.name == fast)
        raise InfeasibleError(
            f"no feasible design: no motor moves the load within {field} = {t_req:.10g} s",
            [
                f"the fastest of {len(rows)} candidates, {fast}, takes "
                f"{stated_up(rows[fast].decisive_time_s):g} s at its optimal ratio i = {i:.4g}"
                + (f" (its estimated inertia {band * 100:.0f} % higher)" if estimated else ""),
                f"allow a longer {field}, or list stronger or faster motors in "
                "[[positioning.motors]]",
            ],
        )
    return trace.apply(smallest_meeting, t_req, rows, cands.power_basis, band)


def _choose_motor(
    solved: list[Solved],
    held: dict[str, Solved],
    cands: CandidateSet,
    required: tuple[float, str] | None,
    trace: Trace,
) -> Solved:
    """The motor of the drive: with listed motors and no time, seed 003's rule, the fastest
    move (MO-02); with a required time, the smallest that meets it (MO-05)."""
    if required is None:
        times = {s.name: s.solution.move_time_s for s in solved}
        best = trace.apply(fastest_motor, times)
    else:
        best = _smallest_meeting(solved, held, cands, required, trace)
    return next(s for s in solved if s.name == best)


def _explain_ratio(best: Solved, profile: str, path: float, trace: Trace) -> None:
    """MO-01 and MO-03: the chosen motor's ratio, and the speed graph that happens at it."""
    d, s = best.drive, best.solution
    trace.apply(
        ratio_per_motor,
        best.name,
        s.ratio,
        s.estimated_ratio,
        s.first_step,
        d.torque_ratio,
        s.profile,
        profile,
    )
    trace.apply(profile_check, profile, s.profile, path, motion.transient_path(d, s.ratio))


def _ratio_warnings(best: Solved, solved: list[Solved], profile: str) -> list[str]:
    """What the reader of the ratio must know: a re-optimised law, a ratio at the edge of the
    range searched, candidates whose graphical first step cannot move the load."""
    s = best.solution
    warnings = []
    if s.profile != profile:
        warnings.append(
            f"the move is {s.profile}, not {profile}: the ratio was re-optimised for the "
            f"{s.profile} law ({s.exact_ratio:.4g} → {s.ratio:.4g})"
        )
    if not motion.RATIO_MIN * 1.001 < s.ratio < motion.RATIO_MAX / 1.001:
        warnings.append(
            f"the fastest ratio lies at the edge of the range searched ({motion.RATIO_MIN:g} … "
            f"{motion.RATIO_MAX:g}): the load is negligible or overwhelming against motor "
            f"{best.name}"
        )
    below = [x.name for x in solved if not x.solution.first_step_moves_load]
    if below:
        names = ", ".join(below[:5]) + (f" and {len(below) - 5} more" if len(below) > 5 else "")
        warnings.append(
            "the graphical method's first step K(μ0)·∛A is not above m = M_p/M_λ, a ratio that "
            f"cannot move the load, for {names}: use the fixed point (estimated_ratio)"
        )
    return warnings


def _solution_fields(s: motion.RatioSolution) -> dict:
    """The fields a motor's row and the chosen motor's table share."""
    return {
        "optimal_ratio": s.ratio,
        "estimated_ratio": s.estimated_ratio,
        "estimated_ratio_first_step": s.first_step,
        "first_step_moves_load": s.first_step_moves_load,
        "move_time_s": s.move_time_s,
    }


def candidate_out(s: Solved) -> MotionCandidateOut:
    """A candidate's row of the report: the motor and its fastest move."""
    d = s.drive
    return MotionCandidateOut.make(
        name=s.name,
        speed_rad_s=d.speed_rad_s,
        inertia_kgm2=d.inertia_kgm2,
        accel_torque_Nm=d.accel_torque_Nm,
        profile=s.solution.profile,
        **_solution_fields(s.solution),
    )


def curve_out(d: motion.Drive, path: float, ratio: float) -> CurveOut:
    """Move time against ratio around the optimum, 61 ratios spaced evenly on log i."""
    lo = max(d.torque_ratio * 1.02, ratio / 6.0, motion.RATIO_MIN)
    hi = min(max(ratio * 6.0, lo * 36.0), motion.RATIO_MAX)
    ratios = [lo * (hi / lo) ** (k / 60) for k in range(61)]
    return CurveOut.make(
        ratio=ratios, move_time_s=[motion.move_time(d, path, r)[0] for r in ratios]
    )


def motion_out(
    best: Solved,
    solved: list[Solved],
    held: dict[str, Solved],
    profile: str,
    path: float,
    required: tuple[float, str] | None,
) -> MotionOut:
    """The report's motion table: the chosen motor's move, every candidate's beside it, and
    with a required time the fastest motor by the rule that chooses (MO-05: ``held``, an
    estimated inertia at the top of its band), so that the time it states is one the advisor
    accepts: rounded up at the report's six digits (:func:`stated_up`). The transient time is
    the start and stop of the move that happens: eq. (3)'s to full speed for a trapezoidal
    graph, the whole move for a triangular one (it never reaches ω0)."""
    d, s = best.drive, best.solution
    decisive = {x.name: held[x.name].solution.move_time_s for x in solved}
    fastest = min(solved, key=lambda x: decisive[x.name])
    return MotionOut.make(
        motor=best.name,
        ratio_i0=s.ratio_i0,
        k_factor=s.k_factor,
        coefficient_A=motion.coefficient_a(d, path),
        transient_time_s=s.move_time_s
        if s.profile == "triangular"
        else motion.transient_time(d, s.ratio),
        profile_assumed=profile,
        profile_actual=s.profile,
        inertia_ratio=d.inertia_ratio,
        torque_ratio=d.torque_ratio,
        required_move_time_s=None if required is None else required[0],
        fastest_motor=None if required is None else fastest.name,
        fastest_move_time_s=None if required is None else stated_up(decisive[fastest.name]),
        candidates=[candidate_out(x) for x in sorted(solved, key=lambda x: x.solution.move_time_s)],
        curve=curve_out(d, path, s.ratio),
        **_solution_fields(s),
    )


def _ratio_checks(best: Solved, built_ratio: float | None = None) -> list[Check]:
    """The ratio moves the load: above m = M_p/M_λ, where the torque only balances it
    (seed 003, eq. (3)); margin i/m. ``built_ratio``: the ratio the design is built with
    where a duty cycle chose it (``best`` is then the cycle's motor); the fastest ratio
    without the cycle is named in the note."""
    d = best.drive
    i = best.solution.ratio if built_ratio is None else built_ratio
    if d.torque_ratio <= 0:
        return []
    source = SEED_003.at("eq. (3)")
    if built_ratio is not None:
        source = source.with_note(
            f"at the duty cycle's ratio i = {i:.6g}; the fastest move alone would take "
            f"i = {best.solution.ratio:.6g}"
        )
    return [
        Check(
            "ratio_moves_load",
            "ratio above the one at which the motor's torque only balances the load (i > m)",
            i,
            d.torque_ratio,
            "",
            i / d.torque_ratio,
            source,
        )
    ]


def move_time_checks(
    required_s: float | None, move_time_s: float, raised_at: str | None = None
) -> list[Check]:
    """The built drive's move within the required move time (positioning.move_time_s):
    value its move time t_Σ (seed 003, eqs. (3)–(4), the speed graph that happens there),
    limit the required time, margin t_req/t_Σ. ``raised_at``: where the time was taken with
    the catalog's estimated rotor inertia at the top of its band, the inertia the choice
    holds the motor to (MO-05, and the duty cycle's MO-06), so that the margin is the one the
    choice rests on; None: the ratio it is built with, the inertia as given. No time asked,
    no check: a duty cycle's own ``duty_move_fits`` holds the move to the cycle time.

    >>> [round(c.margin, 4) for c in move_time_checks(0.8, 0.305658)]  # 0.8/0.305658
    [2.6173]
    >>> move_time_checks(0.2, 0.194658, "i = 6.79309")[0].name  # the margin 0.2/0.194658 = 1.027
    'move time within the required move time, the estimated rotor inertia 30 % higher'
    """
    if required_s is None:
        return []
    name, source = "move time within the required move time", SEED_003.at("eqs. (3)–(4)")
    if raised_at is not None:
        pct = f"{INERTIA_BAND * 100:.0f} %"
        name += f", the estimated rotor inertia {pct} higher"
        source = source.with_note(
            f"the catalog's estimated rotor inertia {pct} higher, as the choice holds it "
            f"(MO-05), at {raised_at}"
        )
    return [
        Check("move_time", name, move_time_s, required_s, "s", required_s / move_time_s, source)
    ]


def _duty(
    req: Requirements,
    cat: Catalogs,
    solved: list[Solved],
    held: dict[str, Solved],
    best: Solved,
    required: tuple[float, str] | None,
    trace: Trace,
):
    """The move repeated every cycle_time_s: the motor and ratio for the cycle, each
    candidate as the decisions hold it (``held``), ranked by its size as MO-05 ranks it."""
    from advisor.applications.positioning.duty import advise_duty, rated_torques, start_heats

    return advise_duty(
        [held[s.name] for s in solved],
        rated_torques(req, cat),
        req.positioning.travel_rad,
        req.duty.cycle_time_s,
        best.name,
        trace,
        required_s=None if required is None else required[0],
        heats=start_heats(req, cat),
        sizes={s.name: Size(s.candidate.power_W, s.drive.inertia_kgm2) for s in solved},
    )


def _single_move_checks(pos, best: Solved, held: Solved) -> list[Check]:
    """Without a cycle: the ratio moves the load, and the move within the required time as
    MO-05 judged it (an estimated inertia at the top of its band, at the built ratio)."""
    raised = None
    if held is not best:
        raised = f"the built ratio i = {held.solution.ratio:.6g}"
    return _ratio_checks(best) + move_time_checks(
        pos.move_time_s, held.solution.move_time_s, raised
    )


def advise_positioning(req: Requirements, cat: Catalogs, trace: Trace):
    """The candidates; each at its fastest ratio (seed 003); the motor (MO-02 or MO-05); its
    ratio and speed graph explained (MO-01, MO-03); with a [duty] table, the cycle's choice.
    Returns the design's tables, its checks and its warnings."""
    pos = req.positioning
    path = pos.travel_rad
    cands = candidates(req, cat)
    kept, left_out = usable(cands)
    warnings = [*cands.warnings, *left_out]
    solved = [Solved(c, motion.solve_ratio(c.drive, path, pos.profile)) for c in kept]
    # a single move is judged as built; a cycle fits its own ratio with the raised inertia
    held = {s.name: held_as_built(s, path) for s in solved}
    required = required_time(req)
    best = _choose_motor(solved, held, cands, required, trace)
    _explain_ratio(best, pos.profile, path, trace)
    warnings += _ratio_warnings(best, solved, pos.profile)
    motion_table = motion_out(best, solved, held, pos.profile, path, required)
    duty = None
    if req.duty is None:
        checks = _single_move_checks(pos, best, held[best.name])
    else:
        fitted = {s.name: held_to(s, path, pos.profile) for s in solved}
        duty, duty_checks, duty_warnings = _duty(req, cat, solved, fitted, best, required, trace)
        # the design is built at the cycle's motor and ratio: the checks state that design,
        # its move taken with the inertia the cycle was judged with
        built = next(s for s in solved if s.name == duty.motor)
        raised = None
        if fitted[built.name] is not built:
            raised = f"the duty cycle's ratio i = {duty.ratio:.6g}"
        checks = (
            _ratio_checks(built, duty.ratio)
            + move_time_checks(pos.move_time_s, duty.move_time_s, raised)
            + duty_checks
        )
        warnings += duty_warnings
    return PositioningDesignOut.make(motion=motion_table, duty=duty), checks, warnings
