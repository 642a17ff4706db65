"""Rules of the brushless motor choice (seed 000)."""

from advisor.core.rulebook import Finding, rule

SEED_000 = "000_e109c3d4c17eaf1c.txt"


@rule("BL-01", "Type of motor", SEED_000)
def motor_type() -> Finding[str]:
    return Finding(
        "PM brushless, concentrated windings",
        "A permanent-magnet brushless (valve) motor with concentrated tooth windings, "
        "torque (current) controlled.",
        "Seed 000: NdFeB magnets give the highest torque of any motor type; the windings sit "
        "on the stator, which sheds heat into the structure; tooth coils shorten the end "
        "windings, make insulation breakdown less likely and simplify winding.",
    )


@rule("BL-02", "Motor speed", SEED_000)
def choose_speed(
    losses_by_speed: dict[float, float],
    optimum_speed_rpm: float,
    pole_pairs: int,
    over_rating: dict[float, float],
    rated_current_A: float,
) -> Finding[float]:
    """The candidate speed with the smallest total loss (ohmic + iron + magnets) among those
    at which the motor stays within its rated current."""
    allowed = {n: w for n, w in losses_by_speed.items() if n not in over_rating}
    best = min(allowed, key=allowed.__getitem__)
    table = ", ".join(
        f"{n:g} rpm: {w:.0f} W"
        + (f" (needs {over_rating[n]:.3g} A > {rated_current_A:g} A)" if n in over_rating else "")
        for n, w in sorted(losses_by_speed.items())
    )
    faster = [n for n in losses_by_speed if n > best and losses_by_speed[n] > losses_by_speed[best]]
    tail = (
        " Faster is not better: the ohmic loss falls with the square of the reduction, but the "
        "iron and magnet losses rise with the square of the flux frequency and soon dominate."
        if faster
        else ""
    )
    return Finding(
        best,
        f"{best:g} rpm (total loss {losses_by_speed[best]:.0f} W).",
        f"Total losses at the candidate speeds: {table}. The minimum of eq. (10) lies at "
        f"≈ {optimum_speed_rpm:.0f} rpm ({optimum_speed_rpm * pole_pairs / 60:.0f} Hz), where "
        "the ohmic and the core losses are equal; of the candidates the least lossy is taken."
        + tail
        + (" Speeds over the rated current are shown but not chosen." if over_rating else ""),
        {"losses_W": {f"{n:g}": round(w, 2) for n, w in losses_by_speed.items()}},
    )
