"""The positioning drive advice (seed 003): for each candidate motor the ratio of the fastest
move, and the fastest motor. Orchestration only."""

import math

from advisor.applications.positioning.report import (
    CurveOut,
    MotionCandidateOut,
    MotionOut,
    PositioningDesignOut,
)
from advisor.calc import motion as mo
from advisor.calc.sizing import Check
from advisor.core.errors import InfeasibleError
from advisor.core.requirements import Requirements
from advisor.core.rulebook import Trace
from catalogs import Catalogs
from rules import motion as mo_rules


def _candidates(req: Requirements, cat: Catalogs) -> tuple[list[tuple[str, mo.Drive]], list[str]]:
    pos = req.positioning
    if pos.motors:
        return [
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
        ], []
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
    note = (
        "no [[positioning.motors]] given: candidates are the induction motors of the catalog at "
        "their rated speed with their starting torque; their rotor inertias are estimated values"
    )
    return drives, [note]


def _solve(d: mo.Drive, path: float, asked: str) -> dict:
    """Optimal ratio under the asked time law, then under the law that actually happens."""
    if asked == "trapezoidal":
        i = mo.optimal_ratio_trapezoidal(d, path)
        estimate, i0, k = mo.graphical_estimate(d, path)
    else:
        i = mo.optimal_ratio_triangular(d, path)
        i0, k = mo.graphical_estimate(d, path)[1:]
        estimate = math.sqrt(d.inertia_ratio) if d.inertia_ratio > 0 else i  # inertia match
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
        "i0": i0,
        "k": k,
        "time": t,
        "actual": happened,
    }


def advise_positioning(req: Requirements, cat: Catalogs, trace: Trace):
    pos = req.positioning
    path = pos.travel_rad
    drives, warnings = _candidates(req, cat)
    # A = 0 (eq. (7)) means a load so small against the motor that the time keeps falling as
    # the ratio goes to zero: there is no finite optimum to give
    finite = [(n, d) for n, d in drives if mo.coefficient_a(d, path) > 0]
    if not finite:
        raise InfeasibleError(
            "no feasible design: the load is negligible against every motor",
            [
                f"A of eq. (7) is 0 for {', '.join(n for n, _ in drives)}: the move time falls "
                "without limit as the ratio goes to zero; give the load's inertia and torque"
            ],
        )
    solved = {name: (d, _solve(d, path, pos.profile)) for name, d in finite}
    best = trace.apply(mo_rules.fastest_motor, {n: s["time"] for n, (_, s) in solved.items()})
    d, s = solved[best]
    trace.apply(mo_rules.ratio_per_motor, best, s["ratio"], s["estimate"], s["actual"])
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
    lo = max(d.torque_ratio * 1.02, s["ratio"] / 6.0, mo.RATIO_MIN)
    hi = min(max(s["ratio"] * 6.0, lo * 36.0), mo.RATIO_MAX)
    ratios = [lo * (hi / lo) ** (k / 60) for k in range(61)]
    motion = MotionOut.make(
        motor=best,
        optimal_ratio=s["ratio"],
        estimated_ratio=s["estimate"],
        ratio_i0=s["i0"],
        k_factor=s["k"],
        coefficient_A=mo.coefficient_a(d, path),
        move_time_s=s["time"],
        transient_time_s=mo.transient_time(d, s["ratio"]),
        profile_assumed=pos.profile,
        profile_actual=s["actual"],
        inertia_ratio=d.inertia_ratio,
        torque_ratio=d.torque_ratio,
        candidates=[
            MotionCandidateOut.make(
                name=n,
                speed_rad_s=dd.speed_rad_s,
                inertia_kgm2=dd.inertia_kgm2,
                accel_torque_Nm=dd.accel_torque_Nm,
                optimal_ratio=ss["ratio"],
                estimated_ratio=ss["estimate"],
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
    return PositioningDesignOut.make(motion=motion), checks, warnings
