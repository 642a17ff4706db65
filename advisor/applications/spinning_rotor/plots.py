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
    """The rotor's speed in a sustained slew with the drive limited to the steady torque
    without the gyroscopic reaction (seed 002)."""
    s = at(doc, "design", "rotor", "slew")
    curve = at(s, "curve")
    if not isinstance(curve, dict) or not curve.get("time_s"):
        return None
    settle = s.get("balance_speed_rad_s")
    return Plot(
        "slew",
        "Rotor speed in a sustained slew at the steady torque",
        "time, s",
        "speed, rad/s",
        [Line("speed", curve["time_s"], curve["speed_rad_s"])],
        [],
        [(settle, f"settles at {settle:.4g} rad/s")] if settle is not None else [],
    )


#: The datasheet's plots of this application, in the datasheet's order.
DATASHEET_PLOTS = (
    run_up,
    slew,
)
