"""Rules of the brushless motor choice (seed 000)."""

import math

from advisor.core.cite import cite
from advisor.core.rulebook import Finding, rule

SEED_000 = cite("seed-000")


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
    loss_limit_W: float,
    limit_basis: str,
    current_by_speed: dict[float, float],
) -> Finding[float]:
    """The candidate speed with the smallest total loss (ohmic + iron + magnets) among those
    whose losses the frame's cooling carries (``loss_limit_W``). The caller guarantees that
    at least one candidate is within the limit.

    The limit is thermal (seed 000: the permissible load of the drive is set by the motor's
    temperature, and a faster winding with less copper loss may carry more current). The
    current of the winding rewound for each speed grows as n at a given torque; it is
    reported for the drive electronics and is not a limit of the motor.
    """
    allowed = {n: w for n, w in losses_by_speed.items() if within_limit(w, loss_limit_W)}
    best = min(allowed, key=allowed.__getitem__)
    table = ", ".join(
        f"{n:g} rpm: {w:.4g} W at {current_by_speed[n]:.3g} A"
        + ("" if n in allowed else f" (over the {loss_limit_W:.4g} W limit)")
        for n, w in sorted(losses_by_speed.items())
    )
    faster = [n for n in losses_by_speed if n > best and losses_by_speed[n] > losses_by_speed[best]]
    tail = (
        " Faster is not better: the ohmic loss falls with the square of the reduction, but the "
        "iron and magnet losses rise with the square of the flux frequency and soon dominate."
        if faster
        else ""
    )
    over = len(allowed) < len(losses_by_speed)
    return Finding(
        best,
        f"{best:g} rpm (total loss {losses_by_speed[best]:.4g} W of the {loss_limit_W:.4g} W "
        "the frame carries).",
        f"Total losses at the candidate speeds: {table}. The limit is thermal: {limit_basis}. "
        "The current is that of the winding rewound for each speed (turns and torque constant "
        "∝ 1/n, so at a given torque the current grows as n while the copper loss stays); "
        "it sizes the drive electronics and is not a limit of the motor. "
        + (
            f"The minimum of eq. (10) lies at ≈ {optimum_speed_rpm:.0f} rpm "
            f"({optimum_speed_rpm * pole_pairs / 60:.0f} Hz), where the ohmic and the core "
            "losses are equal; of the candidates the least lossy is taken."
            if math.isfinite(optimum_speed_rpm)
            else "Eq. (10) has no minimum here: the motor states no core losses, so its losses "
            "fall with speed; of the candidates the least lossy is taken."
        )
        + tail
        + (" Speeds over the loss limit are shown but not chosen." if over else ""),
        {
            "speed_rpm": best,
            "total_loss_W": losses_by_speed[best],
            "losses_W": {f"{n:g}": w for n, w in losses_by_speed.items()},
            "loss_limit_W": loss_limit_W,
            "current_A": {f"{n:g}": a for n, a in current_by_speed.items()},
        },
    )


#: Relative tolerance of the loss limit, a stated design allowance: the loss model's inputs
#: (phase resistance, steel loss figures, magnet losses) are known to three significant
#: figures, so a frame within 0.1 % of its reference losses is at its rating. A frame run at
#: its own reference point (the seed 000 rudder) is exactly at the limit; without this band a
#: requirement perturbed by 1e-9 would flip from a design to none (a knife edge).
LIMIT_REL_TOL = 1e-3


def within_limit(losses_W: float, limit_W: float) -> bool:
    """Losses within the limit, up to the stated allowance :data:`LIMIT_REL_TOL`."""
    return losses_W <= limit_W * (1.0 + LIMIT_REL_TOL)


@rule("BL-03", "Motor frame", SEED_000 + cite("budinger-2012") + cite("budinger-course"))
def choose_frame(tried: list) -> Finding[str]:
    """The smallest frame (by mass, then stator diameter) for which some candidate speed
    passes the loss limit and the duty cycle: a drive engineer sizing a product range takes
    the lightest motor that does the job, and a larger one only where the smaller fails.

    ``tried``: the frames in that order up to the first that fits, each a record (a
    NamedTuple) with ``name``, ``kind`` ("scaled" | "catalog"), ``torque_Nm`` (continuous),
    ``speed_rpm`` (rated), ``mass_kg``, ``outer_diameter_mm``, ``fits`` and ``why`` (the best
    candidate's numbers). The caller guarantees the last one fits."""
    chosen = tried[-1]
    kind = {"scaled": "scaled frame", "catalog": "catalog motor (datasheet)"}[chosen.kind]
    smaller = tried[-2] if len(tried) > 1 else None
    why_smaller = (
        f" The next smaller, {smaller.name} ({smaller.torque_Nm:.4g} N·m, "
        f"{smaller.mass_kg:.3g} kg), fails: {smaller.why}."
        if smaller
        else " It is the smallest of the series."
    )
    return Finding(
        chosen.name,
        f"{chosen.name}, {kind}: {chosen.torque_Nm:.4g} N·m continuous at "
        f"{chosen.speed_rpm:.5g} rpm, Ø{chosen.outer_diameter_mm:.4g} mm, "
        f"{chosen.mass_kg:.3g} kg; {chosen.why}.{why_smaller}",
        "The frames are tried from the lightest (then the slimmest) up; the first for which "
        "some candidate speed keeps its total losses (seed 000's model with the frame's own "
        "numbers) within its own limit, and passes the duty cycle, is taken. A scaled frame's "
        "numbers follow seed 000's reference by geometric similarity (Budinger et al.: "
        "T ∝ l^3.5, J ∝ l⁵, m ∝ l³); a catalog motor's are its datasheet's.",
        {"frame": chosen.name, "kind": chosen.kind, "tried": [t._asdict() for t in tried]},
    )
