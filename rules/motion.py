"""Rules of the positioning drive (seed 003)."""

from advisor.core.cite import cite
from advisor.core.rulebook import Finding, rule

SEED_003 = cite("seed-003")


@rule("MO-01", "Gear ratio of each motor", SEED_003)
def ratio_per_motor(name: str, exact: float, estimate: float, profile: str) -> Finding[float]:
    return Finding(
        exact,
        f"{name}: i = {exact:.4g} (graphical estimate {estimate:.4g}).",
        f"The ratio that minimises the {profile} move time: the root of eq. (6) found exactly; "
        "the seed's graphical estimate K(μ0)·∛A is reported beside it. Near the optimum the "
        "time curve is flat (seed 003), so a standard ratio close to it costs little.",
    )


@rule("MO-02", "Motor of the drive", SEED_003)
def fastest_motor(times: dict[str, float]) -> Finding[str]:
    best = min(times, key=times.__getitem__)
    table = ", ".join(f"{n}: {t:.4g} s" for n, t in sorted(times.items(), key=lambda kv: kv[1]))
    return Finding(
        best,
        f"Motor {best}, the fastest at its own optimal ratio.",
        f"Seed 003, step 8: compare the move times at each motor's optimal ratio — {table}.",
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
    )
