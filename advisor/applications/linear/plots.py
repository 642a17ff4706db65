"""The linear actuator's datasheet plots (seed 001): the candidate motors' M(n).
Each reads its own keys of the report's plain data; the datasheet draws them
(:mod:`advisor.datasheet.plots`) after the motor's envelope and before the duty cycle's."""

from advisor.datasheet.plots import Line, Plot, at, table_at


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


def motor_limits(doc: dict) -> tuple[list[Line], list[Line]] | None:
    """The catalog motor's limits for the datasheet's envelope: continuous up to its rated
    torque at its rated speed, peak its M(n) (seed 001's characteristic)."""
    motor = table_at(doc, "design", "motor")
    model = motor.get("model")
    curve = next(
        (
            c["curve"]
            for c in motor.get("candidates") or []
            if c.get("model") == model and isinstance(at(c, "curve", "speed_rpm"), list)
        ),
        None,
    )
    if curve is None or "rated_torque_Nm" not in motor:
        return None
    n_r, m_r = motor.get("rated_speed_rpm", max(curve["speed_rpm"])), motor["rated_torque_Nm"]
    return (
        [Line(f"continuous: rated {m_r:.4g} N·m", [0.0, n_r, n_r], [m_r, m_r, 0.0])],
        [Line(f"peak: M(n) of {model}", curve["speed_rpm"], curve["torque_Nm"])],
    )


def working_point(doc: dict) -> tuple[float, float] | None:
    """The motor's working speed under the load and the screw's torque, rpm and N·m."""
    motor = table_at(doc, "design", "motor")
    n = motor.get("working_speed_rpm", motor.get("speed_rpm"))
    m = at(doc, "design", "screw", "torque_Nm") or motor.get("torque_Nm")
    return (n, m) if isinstance(n, int | float) and isinstance(m, int | float) else None


#: The datasheet's plots of this application, in the datasheet's order.
DATASHEET_PLOTS = (motor_characteristics,)
