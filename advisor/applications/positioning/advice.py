"""The positioning drive advice (seed 003): for each candidate motor the ratio of the fastest
move; then the motor — the fastest of the listed motors (seed 003), or, where a move time is
required, the smallest motor that meets it (issue 25). Orchestration only."""

import math
from typing import NamedTuple

from advisor.applications.positioning.report import (
    CurveOut,
    MotionCandidateOut,
    MotionOut,
    PositioningDesignOut,
)
from advisor.calc import motion as mo
from advisor.calc.checks import Check
from advisor.core.errors import InfeasibleError
from advisor.core.reading import Requirements
from advisor.core.rulebook import Trace
from catalogs import Catalogs
from rules import motion as mo_rules


class Candidates(NamedTuple):
    drives: list[tuple[str, mo.Drive]]
    warnings: list[str]
    estimated: set[str]  # names whose rotor inertia is an estimate
    power_W: dict[str, float]  # the size that ranks them (MO-05)
    power_basis: str  # what that size is


def _candidates(req: Requirements, cat: Catalogs) -> Candidates:
    """The candidate drives, the warnings about them, the names whose inertia is an estimate,
    and each candidate's size: the rated power, or for listed motors without a rated torque
    the power M_λ·ω0 at their starting torque."""
    pos = req.positioning
    if pos.motors:
        rated = all(m.rated_torque_Nm is not None for m in pos.motors)
        return Candidates(
            [
                (
                    m.name,
                    mo.Drive(
                        m.speed_rad_s,
                        m.inertia_kgm2,
                        m.accel_torque_Nm,
                        pos.load_inertia_kgm2,
                        pos.load_torque_Nm,
                    ),
                )
                for m in pos.motors
            ],
            [],
            set(),
            {
                m.name: (m.rated_torque_Nm if rated else m.accel_torque_Nm) * m.speed_rad_s
                for m in pos.motors
            },
            "rated power M_n·ω0"
            if rated
            else "power at the starting torque M_λ·ω0 (no rated torque listed for every motor)",
        )
    drives = [
        (
            m.model,
            mo.Drive(
                m.rated_speed_rpm * math.pi / 30.0,
                m.inertia_kgm2,
                m.starting_torque_ratio * m.rated_torque_Nm,
                pos.load_inertia_kgm2,
                pos.load_torque_Nm,
            ),
        )
        for m in cat.motors
    ]
    estimated = {m.model for m in cat.motors if "inertia_kgm2" in m.estimated}
    note = (
        "no [[positioning.motors]] given: candidates are the induction motors of the catalog "
        "at their rated speed with their starting torque"
    )
    if estimated:
        note += (
            f"; the rotor inertias of {len(estimated)} of them are estimated values, counted "
            f"{mo_rules.INERTIA_BAND * 100:.0f} % higher where they decide (MO-05)"
        )
    return Candidates(
        drives,
        [note],
        estimated,
        {m.model: m.rated_power_kW * 1e3 for m in cat.motors},
        "rated power of the catalog",
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


def _solve(d: mo.Drive, path: float, asked: str) -> dict:
    """Optimal ratio under the asked time law, then under the law that actually happens; the
    seed's estimate for the asked law and the graphical method's first step beside it."""
    first, i0, _ = mo.graphical_estimate(d, path)
    fp = mo.graphical_fixed_point(d, path)
    if asked == "trapezoidal":
        i = mo.optimal_ratio_trapezoidal(d, path)
        estimate = fp.ratio
    else:
        i = mo.optimal_ratio_triangular(d, path)
        estimate = mo.triangular_ratio(d)
    exact = i
    actual = "trapezoidal" if path >= mo.transient_path(d, i) else "triangular"
    if asked == "triangular" and actual == "trapezoidal":
        # the triangular optimum would pass ω0: the trapezoidal law governs
        if mo.triangular_peak_speed(d, path, i) <= d.speed_rad_s:
            actual = "triangular"
    if actual != asked:
        i = (
            mo.optimal_ratio_trapezoidal(d, path)
            if actual == "trapezoidal"
            else mo.optimal_ratio_triangular(d, path)
        )
    t, happened = mo.move_time(d, path, i)
    return {
        "exact": exact,
        "ratio": i,
        "estimate": estimate,
        "first_step": first,
        "first_step_moves_load": mo.first_step_moves_load(d, first),
        "i0": i0,
        "k": fp.k,
        "time": t,
        "actual": happened,
    }


def _inertia_band(d: mo.Drive, path: float, asked: str, band: float) -> tuple[float, float]:
    """Move times at the motor's optimal ratio with its inertia at the low and the high end of
    the band of an estimate."""
    lo = d._replace(inertia_kgm2=d.inertia_kgm2 * (1.0 - band))
    hi = d._replace(inertia_kgm2=d.inertia_kgm2 * (1.0 + band))
    return _solve(lo, path, asked)["time"], _solve(hi, path, asked)["time"]


def _smallest_meeting(
    solved: dict[str, tuple[mo.Drive, dict]],
    cands: Candidates,
    required: tuple[float, str],
    path: float,
    profile: str,
    trace: Trace,
) -> str:
    """MO-05: the smallest candidate whose move meets the required time (an estimated inertia
    at the top of its band); none: no feasible design, with the fastest named."""
    t_req, field = required
    band = mo_rules.INERTIA_BAND
    rows = {
        n: mo_rules.Sized(
            cands.power_W[n],
            d.inertia_kgm2,
            s["time"],
            _inertia_band(d, path, profile, band)[1] if n in cands.estimated else s["time"],
        )
        for n, (d, s) in solved.items()
    }
    if not any(r.decisive_time_s <= t_req for r in rows.values()):
        fast = min(rows, key=lambda n: rows[n].decisive_time_s)
        i = solved[fast][1]["ratio"]
        raise InfeasibleError(
            f"no feasible design: no motor moves the load within {field} = {t_req:g} s",
            [
                f"the fastest of {len(rows)} candidates, {fast}, takes "
                f"{rows[fast].decisive_time_s:.4g} s at its optimal ratio i = {i:.4g}"
                + (
                    f" (its estimated inertia {band * 100:.0f} % higher)"
                    if fast in cands.estimated
                    else ""
                ),
                f"allow a longer {field}, or list stronger or faster motors in "
                "[[positioning.motors]]",
            ],
        )
    return trace.apply(mo_rules.smallest_meeting, t_req, rows, cands.power_basis, band)


def advise_positioning(req: Requirements, cat: Catalogs, trace: Trace):
    pos = req.positioning
    path = pos.travel_rad
    cands = _candidates(req, cat)
    drives, warnings = cands.drives, cands.warnings
    # A motor whose torque only balances the load near the top of the ratios searched cannot
    # be given a ratio that moves the load with any margin
    usable = [(n, d) for n, d in drives if d.torque_ratio < mo.RATIO_MAX / 2.0]
    if not usable:
        m_min = min(d.torque_ratio for _, d in drives)
        raise InfeasibleError(
            "no feasible design: no motor can move the load through a ratio up to "
            f"{mo.RATIO_MAX:g}",
            [
                f"the least ratio at which a motor balances the load, m = M_p/M_λ, is "
                f"{m_min:.4g} (needs a ratio below {mo.RATIO_MAX / 2:g}); give a stronger motor "
                "or check the load torque"
            ],
        )
    dropped = len(drives) - len(usable)
    if dropped:
        warnings.append(
            f"{dropped} motor(s) left out: each needs a ratio above {mo.RATIO_MAX / 2:g} only to "
            "balance the load torque"
        )
    solved = {name: (d, _solve(d, path, pos.profile)) for name, d in usable}
    times = {n: s["time"] for n, (_, s) in solved.items()}
    fastest = min(times, key=times.__getitem__)
    required = required_time(req)
    if required is None:  # listed motors, no time: seed 003's rule, the fastest move
        best = trace.apply(mo_rules.fastest_motor, times)
    else:
        best = _smallest_meeting(solved, cands, required, path, pos.profile, trace)
    d, s = solved[best]
    trace.apply(
        mo_rules.ratio_per_motor,
        best,
        s["ratio"],
        s["estimate"],
        s["first_step"],
        d.torque_ratio,
        s["actual"],
        pos.profile,
    )
    trace.apply(
        mo_rules.profile_check, pos.profile, s["actual"], path, mo.transient_path(d, s["ratio"])
    )
    if s["actual"] != pos.profile:
        warnings.append(
            f"the move is {s['actual']}, not {pos.profile}: the ratio was re-optimised for the "
            f"{s['actual']} law ({s['exact']:.4g} → {s['ratio']:.4g})"
        )
    if not mo.RATIO_MIN * 1.001 < s["ratio"] < mo.RATIO_MAX / 1.001:
        warnings.append(
            f"the fastest ratio lies at the edge of the range searched ({mo.RATIO_MIN:g} … "
            f"{mo.RATIO_MAX:g}): the load is negligible or overwhelming against motor {best}"
        )
    below = [n for n, (_, ss) in solved.items() if not ss["first_step_moves_load"]]
    if below:
        names = ", ".join(below[:5]) + (f" and {len(below) - 5} more" if len(below) > 5 else "")
        warnings.append(
            "the graphical method's first step K(μ0)·∛A is not above m = M_p/M_λ, a ratio that "
            f"cannot move the load, for {names}: use the fixed point (estimated_ratio)"
        )
    lo = max(d.torque_ratio * 1.02, s["ratio"] / 6.0, mo.RATIO_MIN)
    hi = min(max(s["ratio"] * 6.0, lo * 36.0), mo.RATIO_MAX)
    ratios = [lo * (hi / lo) ** (k / 60) for k in range(61)]
    motion = MotionOut.make(
        motor=best,
        optimal_ratio=s["ratio"],
        estimated_ratio=s["estimate"],
        estimated_ratio_first_step=s["first_step"],
        first_step_moves_load=s["first_step_moves_load"],
        ratio_i0=s["i0"],
        k_factor=s["k"],
        coefficient_A=mo.coefficient_a(d, path),
        move_time_s=s["time"],
        transient_time_s=mo.transient_time(d, s["ratio"]),
        profile_assumed=pos.profile,
        profile_actual=s["actual"],
        inertia_ratio=d.inertia_ratio,
        torque_ratio=d.torque_ratio,
        required_move_time_s=None if required is None else required[0],
        fastest_motor=None if required is None else fastest,
        fastest_move_time_s=None if required is None else times[fastest],
        candidates=[
            MotionCandidateOut.make(
                name=n,
                speed_rad_s=dd.speed_rad_s,
                inertia_kgm2=dd.inertia_kgm2,
                accel_torque_Nm=dd.accel_torque_Nm,
                optimal_ratio=ss["ratio"],
                estimated_ratio=ss["estimate"],
                estimated_ratio_first_step=ss["first_step"],
                first_step_moves_load=ss["first_step_moves_load"],
                move_time_s=ss["time"],
                profile=ss["actual"],
            )
            for n, (dd, ss) in sorted(solved.items(), key=lambda kv: kv[1][1]["time"])
        ],
        curve=CurveOut.make(
            ratio=ratios, move_time_s=[mo.move_time(d, path, r)[0] for r in ratios]
        ),
    )
    checks = []
    if d.torque_ratio > 0:
        checks.append(
            Check(
                "ratio_moves_load",
                "ratio above the one at which the motor's torque only balances the load (i > m)",
                s["ratio"],
                d.torque_ratio,
                "",
                s["ratio"] / d.torque_ratio,
                mo_rules.SEED_003.at("eq. (3)"),
            )
        )
    duty = None
    if req.duty is not None:  # issue 15: the move repeated every cycle_time_s
        from advisor.applications.positioning.duty import advise_duty, rated_torques

        duty, duty_checks, duty_warnings = advise_duty(
            usable,
            rated_torques(req, cat),
            {n: ss["ratio"] for n, (_, ss) in solved.items()},
            path,
            req.duty.cycle_time_s,
            best,
            trace,
            sizing=None
            if required is None
            else (required[0], {n: (cands.power_W[n], dd.inertia_kgm2) for n, dd in usable}),
        )
        checks += duty_checks
        warnings += duty_warnings
    return PositioningDesignOut.make(motion=motion, duty=duty), checks, warnings
