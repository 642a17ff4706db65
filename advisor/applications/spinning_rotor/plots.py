"""The spinning rotor's datasheet plots (seed 002): its run-up and its speed in a slew.
Each reads its own keys of the report's plain data; the datasheet draws them
(:mod:`advisor.datasheet.plots`) after the motor's envelope and before the duty cycle's."""

from advisor.datasheet.plots import Line, Plot, at


def run_up(doc: dict) -> Plot | None:
    """The rotor's run-up at the drive torque to the design speed (seed 002)."""
    up = at(doc, "design", "rotor", "run_up")
    if not isinstance(up, dict) or not up.get("time_s"):
        return None
    target = at(doc, "requirements", "rotor", "speed_rad_s")
    t_req = at(doc, "requirements", "rotor", "run_up_time_s")
    return Plot(
        "run-up",
        "Run-up of the rotor at the drive torque",
        "time, s",
        "speed, rad/s",
        [Line("run-up", up["time_s"], up["speed_rad_s"])],
        [(t_req, f"required {t_req:g} s")] if t_req is not None else [],
        [(target, f"design speed {target:g} rad/s")] if target is not None else [],
    )


def slew(doc: dict) -> Plot | None:
    """The rotor's speed in a sustained slew: at the design's drive torque (which holds it,
    drawn flat) and with a drive limited to the steady torque without the gyroscopic reaction
    (seed 002, fig. 4), each line labelled with its torque."""
    rotor = at(doc, "design", "rotor")
    design, sized = at(rotor, "slew"), at(rotor, "slew_if_sized_without_reaction")
    if not isinstance(design, dict) or not isinstance(sized, dict):
        return None
    curves = [s.get("curve") or {} for s in (design, sized)]
    end = max([c["time_s"][-1] for c in curves if c.get("time_s")], default=0.0)
    if end <= 0.0:
        return None  # neither loses speed: nothing to draw
    names = ("design drive", "drive sized without the reaction")
    lines = [
        Line(f"{who}, {s['drive_torque_Nm']:.4g} N·m", *held_or_curve(s, c, end))
        for s, c, who in zip((design, sized), curves, names, strict=True)
    ]
    settle = sized.get("balance_speed_rad_s")
    return Plot(
        "slew",
        "Rotor speed in a sustained slew, by drive torque",
        "time, s",
        "speed, rad/s",
        lines,
        [],
        [(settle, f"settles at {settle:.4g} rad/s")] if settle is not None else [],
    )


def held_or_curve(slew: dict, curve: dict, end_s: float) -> tuple[list[float], list[float]]:
    """A slew's times and speeds: its curve, or its held speed drawn flat up to ``end_s``."""
    if curve.get("time_s"):
        return list(curve["time_s"]), list(curve["speed_rad_s"])
    held = slew["speed_after_slew_rad_s"]
    return [0.0, end_s], [held, held]


#: The datasheet's plots of this application, in the datasheet's order.
DATASHEET_PLOTS = (
    run_up,
    slew,
)
