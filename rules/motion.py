"""Rules of the positioning drive (seed 003)."""

from typing import NamedTuple

from advisor.core.cite import cite, note
from advisor.core.rulebook import Finding, rule

SEED_003 = cite("seed-003")
#: Sizing by a required time is the project's own method, not a published source; the note's
#: text is what every report prints as that basis.
REQUIRED_TIME = note(
    "the advisor's sizing by a required move time, docs/reference/requirement-file.md"
)


@rule("MO-01", "Gear ratio of each motor", SEED_003)
def ratio_per_motor(
    name: str,
    exact: float,
    estimate: float,
    first_step: float,
    m: float,
    profile: str,
    asked: str,
) -> Finding[float]:
    if asked == "trapezoidal":
        method = (
            f"graphical method (figs. 4–5): fixed point {estimate:.4g}, first step "
            f"K(μ0)·∛A = {first_step:.4g}"
        )
        if first_step <= m:
            method += f", which is not above m = {m:.4g}: a ratio that cannot move the load"
        why = (
            "the seed's graphical method is the intersection of K = φ(μ) with μ = f(μ0, K), "
            "i.e. the fixed point of i = K(m/i)·∛A, which is the root of eq. (6) itself; its "
            "first step, K read at μ0 = m/∛A, is shown beside it"
        )
    else:
        method = f"closed form of the triangular law {estimate:.4g}"
        why = (
            "for a triangular graph the time is least where i⁴ − (3m² + I)·i² − I·m² = 0 "
            "(the load torque counted; √I only without it)"
        )
    return Finding(
        exact,
        f"{name}: i = {exact:.4g} ({method}).",
        f"The ratio that minimises the {profile} move time: {why}. Near the optimum the "
        "time curve is flat (seed 003), so a standard ratio close to it costs little.",
        {
            "motor": name,
            "ratio": exact,
            "estimated_ratio": estimate,
            "first_step": first_step,
            "torque_ratio": m,
            "profile": profile,
        },
    )


@rule("MO-02", "Motor of the drive", SEED_003)
def fastest_motor(times: dict[str, float]) -> Finding[str]:
    best = min(times, key=times.__getitem__)
    table = ", ".join(f"{n}: {t:.4g} s" for n, t in sorted(times.items(), key=lambda kv: kv[1]))
    return Finding(
        best,
        f"Motor {best}, the fastest at its own optimal ratio.",
        f"Seed 003, step 8: compare the move times at each motor's optimal ratio — {table}.",
        {"motor": best, "move_time_s": times},
    )


@rule("MO-03", "Speed graph that actually happens", SEED_003)
def profile_check(
    asked: str, actual: str, path_rad: float, transient_path_rad: float
) -> Finding[str]:
    if asked == actual:
        return Finding(
            actual,
            f"The move is {actual}, as assumed.",
            f"Path {path_rad:.4g} rad against {transient_path_rad:.4g} rad covered while "
            "starting and stopping at the chosen ratio.",
            {"profile": actual, "path_rad": path_rad, "transient_path_rad": transient_path_rad},
        )
    why = (
        "the path is shorter than the start-and-stop path, so the motor never reaches full speed"
        if actual == "triangular"
        else "the motor would pass its rated speed before braking, so it runs a while at ω0"
    )
    return Finding(
        actual,
        f"The move is {actual}, not {asked} as assumed: {why}.",
        f"Path {path_rad:.4g} rad against {transient_path_rad:.4g} rad of transients; the "
        f"ratio is re-optimised with the {actual} time law, which is the one that happens.",
        {"profile": actual, "path_rad": path_rad, "transient_path_rad": transient_path_rad},
    )


#: The uncertainty of an estimated rotor inertia (catalogs/induction_4a.toml: ±30 %). A
#: catalog motor with an estimated inertia meets a required time only at the top of the band
#: (MO-05): the estimate must not decide that a motor is fast enough.
INERTIA_BAND = 0.30


class Sized(NamedTuple):
    """A candidate of MO-05: its size, its time at its optimal ratio and the time that decides
    (the same, or with an estimated inertia at the top of its band)."""

    power_W: float
    inertia_kgm2: float
    move_time_s: float
    decisive_time_s: float


@rule("MO-05", "Smallest motor that meets the required move time", SEED_003 + REQUIRED_TIME)
def smallest_meeting(
    required_s: float, rows: dict[str, Sized], power_basis: str, band: float
) -> Finding[str]:
    """The smallest motor (power, then inertia) whose move at its own optimal ratio (seed 003,
    eq. (4) or the triangular law) takes no longer than the requirement; a motor with an
    estimated inertia must meet it with that inertia at the top of its band. The fastest
    motor is stated beside it, by the same rule (an estimated inertia at the top of its band:
    the time a requirement would be held to): faster is not the requirement, and costs size."""
    ok = {n: r for n, r in rows.items() if r.decisive_time_s <= required_s}
    order = sorted(rows, key=lambda n: (rows[n].power_W, rows[n].inertia_kgm2, n))
    best = min(ok, key=lambda n: (ok[n].power_W, ok[n].inertia_kgm2, n))
    fastest = min(rows, key=lambda n: rows[n].decisive_time_s)
    smaller = [n for n in order[: order.index(best)]][-3:]
    r = rows[best]

    def time_of(n: str) -> str:
        x = rows[n]
        t = f"{x.move_time_s:.4g} s"
        if x.decisive_time_s != x.move_time_s:
            t += f" ({x.decisive_time_s:.4g} s with its inertia {band * 100:.0f} % higher)"
        return t

    def show(n: str) -> str:
        x = rows[n]
        return f"{n} ({x.power_W / 1e3:.4g} kW, J0 = {x.inertia_kgm2:.3g} kg·m²): {time_of(n)}"

    fails = "; ".join(show(n) for n in smaller) or "none: it is the smallest candidate"
    return Finding(
        best,
        f"Motor {best}, the smallest that moves the load within {required_s:g} s "
        f"({r.move_time_s:.4g} s at its optimal ratio); the fastest, {fastest}, takes "
        f"{time_of(fastest)}.",
        f"Candidates ranked by {power_basis}, then rotor inertia; each at its own optimal "
        f"ratio (seed 003). The motor chosen — {show(best)}. The next smaller ones fail the "
        f"time — {fails}. {len(ok)} of {len(rows)} candidates meet it; an estimated inertia "
        f"counts at the top of its ±{band * 100:.0f} % band.",
        {
            "motor": best,
            "required_move_time_s": required_s,
            "move_time_s": r.move_time_s,
            "decisive_move_time_s": r.decisive_time_s,
            "power_W": r.power_W,
            "inertia_kgm2": r.inertia_kgm2,
            "smaller_failing": {n: rows[n].decisive_time_s for n in smaller},
            "fastest_motor": fastest,
            "fastest_move_time_s": rows[fastest].decisive_time_s,
            "meeting": len(ok),
        },
    )


class CycleFit(NamedTuple):
    """A motor against the duty cycle (DU-01, MO-06): its move time at the ratio that passes
    (or its fastest), that ratio, whether it passes, and why not."""

    move_time_s: float
    ratio: float
    passes: bool
    why_not: str


class Size(NamedTuple):
    """The size that ranks a motor (MO-05, MO-06): power, then rotor inertia."""

    power_W: float
    inertia_kgm2: float


@rule("MO-06", "Smallest motor for the cycle", SEED_003.at("the move") + REQUIRED_TIME)
def smallest_for_cycle(
    required_s: float, rows: dict[str, CycleFit], size: dict[str, Size]
) -> Finding[str]:
    """The smallest motor that passes the cycle and the required time, as MO-05 for the single
    move: a motor with an estimated inertia passes them with that inertia at the top of its
    band. The fastest motor that passes the cycle is stated beside it."""
    ok = [n for n, r in rows.items() if r.passes]
    best = min(ok, key=lambda n: (*size[n], n))
    fastest = min(ok, key=lambda n: (rows[n].move_time_s, n))
    order = sorted(rows, key=lambda n: (*size[n], n))
    smaller = order[: order.index(best)][-3:]
    why = "; ".join(
        f"{n} ({size[n].power_W / 1e3:.4g} kW): {rows[n].move_time_s:.4g} s at "
        f"i = {rows[n].ratio:.4g}" + ("" if rows[n].passes else f" ({rows[n].why_not})")
        for n in smaller
    )
    return Finding(
        best,
        f"Motor {best} at i = {rows[best].ratio:.4g}: the smallest that passes the cycle and "
        f"moves the load within {required_s:g} s ({rows[best].move_time_s:.4g} s); the "
        f"fastest that passes the cycle, {fastest}, takes {rows[fastest].move_time_s:.4g} s "
        f"at i = {rows[fastest].ratio:.4g}.",
        "Each motor at the fastest ratio where its RMS torque over the cycle stays within its "
        "rated torque and the move fits (a catalog induction motor's starts per hour within "
        "those it allows, DU-06, too), a catalog motor's estimated rotor inertia counted "
        f"{INERTIA_BAND * 100:.0f} % higher in all of them; ranked by power, then inertia. The "
        f"next smaller ones fail — {why or 'none: it is the smallest candidate'}.",
        {
            "motor": best,
            "ratio": rows[best].ratio,
            "move_time_s": rows[best].move_time_s,
            "required_move_time_s": required_s,
            "fastest_motor": fastest,
            "fastest_move_time_s": rows[fastest].move_time_s,
        },
    )
