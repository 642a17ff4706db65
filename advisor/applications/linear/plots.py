"""The linear actuator's datasheet plots (seed 001): the candidate motors' M(n).
Each reads its own keys of the report's plain data; the datasheet draws them
(:mod:`advisor.datasheet.plots`) after the motor's envelope and before the duty cycle's."""

from advisor.datasheet.plots import Line, Plot, at


def motor_characteristics(doc: dict) -> Plot | None:
    """M(n) of the candidate induction motors with the screw's working point (seed 001)."""
    cands = at(doc, "design", "motor", "candidates") or []
    lines = [
        Line(
            f"{c.get('model') or c.get('role')} {c.get('rated_power_kW', 0):g} kW",
            c["curve"]["speed_rpm"],
            c["curve"]["torque_Nm"],
        )
        for c in cands
        if isinstance(at(c, "curve", "speed_rpm"), list)
    ]
    n, m = (
        at(doc, "design", "motor", "working_speed_rpm"),
        at(doc, "design", "screw", "torque_Nm"),
    )
    if not lines:
        return None
    if n is not None and m is not None:
        lines.append(Line(f"working point {n:.0f} rpm, {m:.4g} N·m", [n], [m], "marker"))
    return Plot(
        "motor-torque-speed",
        "M(n) of the candidate motors and the working point",
        "speed, rpm",
        "torque, N·m",
        lines,
    )


#: The datasheet's plots of this application, in the datasheet's order.
DATASHEET_PLOTS = (motor_characteristics,)
