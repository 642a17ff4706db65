"""Rules of the one-way (holding) device (seed 004)."""

from advisor.calc.one_way import Device
from advisor.core.cite import cite
from advisor.core.rulebook import Finding, rule

SEED_004 = cite("seed-004")

NAMES = {
    "roller_clutch": "roller irreversible clutch",
    "em_clutch": "electromagnetic clutch",
    "worm": "self-locking worm",
    "inverse_gear": "gear with braking (inverse) profile",
}


def with_article(kind: str) -> str:
    """A device's name with its indefinite article: "an electromagnetic clutch", "a
    self-locking worm"."""
    name = NAMES[kind]
    return f"{'an' if name[0] in 'aeiou' else 'a'} {name}"


@rule("OW-01", "Place of the one-way device", SEED_004)
def placement(
    output_torque_Nm: float, ratio: float, efficiency: float, asked: str = "motor_side"
) -> Finding[float]:
    """The torque the device holds where it sits: M_out/(q·η) at the motor side (the seed's
    place), M_out at the output when the requirement puts it there (``one_way.location``)."""
    at_motor = output_torque_Nm / (ratio * efficiency)
    if asked == "output_side":
        return Finding(
            output_torque_Nm,
            f"At the output, as the requirement asks (one_way.location): it carries "
            f"M_out = {output_torque_Nm:.4g} N·m, q·η = {ratio * efficiency:.4g} times the "
            f"{at_motor:.4g} N·m it would hold at the motor side.",
            "Seed 004, conclusions 4 and 6 put the device where the torque is least, at the "
            "motor; the requirement overrides the place. The report shows the same device at "
            "the motor side for comparison.",
            {
                "torque_Nm": output_torque_Nm,
                "location": "output side",
                "ratio_times_efficiency": ratio * efficiency,
                "motor_side_torque_Nm": at_motor,
            },
        )
    return Finding(
        at_motor,
        f"Between the motor and the first stage, where it carries M_out/(q·η) = "
        f"{output_torque_Nm:.4g}/({ratio:.4g}·{efficiency:.3g}) = {at_motor:.4g} N·m.",
        "Seed 004, conclusions 4 and 6: every one-way device grows with the torque it holds, "
        "so it goes where the torque is least — at the motor, before the first stage. The "
        "report shows the same device at the output side for comparison.",
        {
            "torque_Nm": at_motor,
            "location": "motor side",
            "output_torque_Nm": output_torque_Nm,
            "ratio": ratio,
            "efficiency": efficiency,
        },
    )


@rule("OW-02", "Type of the one-way device", SEED_004)
def device_type(asked: str, priority: str, options: dict[str, Device]) -> Finding[str]:
    """``options``: type → the device of that type sized for the torque, for each that can
    be built (:func:`advisor.calc.one_way.size`)."""
    if asked != "auto":
        return Finding(
            asked,
            f"{NAMES[asked]}, as asked.",
            "The requirement names the type; the alternatives are shown beside it.",
            {"type": asked},
        )
    clutches = {k: v for k, v in options.items() if k in ("roller_clutch", "em_clutch")}
    em, roller = options.get("em_clutch"), options.get("roller_clutch")
    # seed 004's claim on the em clutch's inertia, and what the sizes computed here give
    here = ""
    if em is not None and roller is not None:
        times = em.inertia_kgm2 / roller.inertia_kgm2
        here = f"; by the proportions assumed here its inertia is {times:.3g}× the roller clutch's"
    key = {"mass": "mass_kg", "inertia": "inertia_kgm2", "power": "power_W"}[priority]
    best = min(clutches, key=lambda k: (getattr(clutches[k], key), clutches[k].mass_kg))
    table = "; ".join(
        f"{NAMES[k]}: {d.mass_kg:.3g} kg, {d.inertia_kgm2:.3g} kg·m², "
        f"η {d.efficiency:.2f}, {d.power_W:.3g} W"
        for k, d in options.items()
    )
    return Finding(
        best,
        f"{NAMES[best]} (least {priority.replace('_', ' ')} of the clutches).",
        "Seed 004: self-locking gears (worm, spiroid, braking profile) drive with η < 0.5 "
        "when self-locking, so they are not rational in a new drive; the roller clutch (no "
        "power, no loss) and the electromagnetic clutch (a few watts; seed 004, fig. 8 and "
        "conclusion 5, finds its inertia the least at the larger torques, the roller clutch's "
        f"growing above 20 N·m{here}) remain, and the one best on the stated priority is "
        "taken. "
        f"Sized for this torque: {table}."
        + "".join(
            f" No {NAMES[k]} of the seed's range carries this torque."
            for k in NAMES
            if k not in options
        ),
        {"priority": priority, "type": best},
    )


@rule("OW-03", "Holding of a screw drive", SEED_004)
def screw_holds(self_locking_with_margin: bool, thread: str, friction_low: float) -> Finding[bool]:
    if self_locking_with_margin:
        return Finding(
            True,
            f"No device: {thread} is self-locking even at the low end of the friction range "
            f"(f = {friction_low:g}).",
            "A sliding screw whose lead angle stays below the friction angle over the material "
            "pair's whole friction range holds the load itself (seeds 001, 004).",
        )
    return Finding(
        False,
        f"A device at the motor side: {thread} is not self-locking at f = {friction_low:g}.",
        "The screw could be back-driven by the load when the friction is low; a one-way "
        "device at the motor side holds it (seed 004's placement rule).",
    )
