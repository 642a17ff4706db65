"""Rules of the positioning drive (seed 003)."""

from advisor.core.rulebook import Finding, rule

SEED_003 = "003_9e41cc3901572aaa.txt"


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


#: The uncertainty of an estimated rotor inertia (catalogs/induction_4a.toml: ±30 %).
INERTIA_BAND = 0.30


@rule("MO-04", "Motor choice under estimated inertias", SEED_003)
def robust_motor(
    nominal: str, best_case: dict[str, float], worst_case: dict[str, float], band: float
) -> Finding[tuple[str, tuple[str, ...]]]:
    """Estimated inertias may decide only through this rule: a motor the estimate could make
    the fastest is a contender; if the nominal fastest is the only one, it stands; otherwise
    the contender with the least worst-case time (every inertia at the top of its band) is
    taken, and the decision names the contenders."""
    contenders = sorted(
        (
            n
            for n, t in best_case.items()
            if t <= min((w for k, w in worst_case.items() if k != n), default=t)
        ),
        key=worst_case.__getitem__,
    )
    pct = f"{band * 100:.0f} %"
    if contenders == [nominal]:
        return Finding(
            (nominal, (nominal,)),
            f"Motor {nominal} stays the fastest with every estimated inertia anywhere within "
            f"±{pct}.",
            f"Its time is {best_case[nominal]:.4g}…{worst_case[nominal]:.4g} s with its "
            f"inertia from {pct} below to {pct} above the estimate, and no other motor can be "
            "the fastest with its own inertia anywhere in that band: the estimated inertias "
            "do not decide.",
        )
    choice = min(contenders, key=worst_case.__getitem__)
    table = ", ".join(f"{n}: {best_case[n]:.4g}…{worst_case[n]:.4g} s" for n in contenders[:6])
    more = f" and {len(contenders) - 6} more" if len(contenders) > 6 else ""
    return Finding(
        (choice, tuple(contenders)),
        f"Motor {choice}: the estimated inertias (±{pct}) cannot separate "
        f"{len(contenders)} motors; {choice} has the least worst-case time. Confirm the "
        "rotor inertias with the maker's data.",
        f"The rotor inertias of the catalog are estimated values. Move times with each inertia "
        f"from {pct} below to {pct} above its estimate — {table}{more}. Any of these "
        f"could be the fastest; the rule takes the one that is fastest when every inertia is "
        f"at the top of its band (nominal fastest: {nominal}).",
    )
