"""The positioning drive's datasheet plots (seed 003): move time against the ratio.
Each reads its own keys of the report's plain data; the datasheet draws them
(:mod:`advisor.datasheet.plots`) after the motor's envelope and before the duty cycle's."""

import math

from advisor.datasheet.plots import Line, Plot, at


def move_time(doc: dict) -> Plot | None:
    """Move time against the ratio for the fastest motor, the optimum marked (seed 003)."""
    m = at(doc, "design", "motion")
    curve = at(m, "curve")
    if not isinstance(curve, dict) or not curve.get("ratio"):
        return None
    lines = [Line(f"motor {m.get('motor', '')}".strip(), curve["ratio"], curve["move_time_s"])]
    if "optimal_ratio" in m and "move_time_s" in m:
        lines.append(
            Line(
                f"optimum i = {m['optimal_ratio']:.4g}, {m['move_time_s']:.4g} s",
                [m["optimal_ratio"]],
                [m["move_time_s"]],
                "marker",
            )
        )
    est = m.get("estimated_ratio")
    vlines = [(est, f"graphical estimate i = {est:.4g}")] if est is not None else []
    return Plot(
        "move-time-ratio",
        "Move time against ratio",
        "ratio i",
        "move time, s",
        lines,
        vlines,
        logx=True,
    )


def listed_motor(doc: dict) -> dict | None:
    """The requirement's row of the motor the design chose: the row named so in a list of
    tables of the requirement (``positioning.motors``)."""
    chosen = at(doc, "design", "motion", "motor")
    if not isinstance(chosen, str):
        return None
    for table in (doc.get("requirements") or {}).values():
        for rows in table.values() if isinstance(table, dict) else ():
            for row in rows if isinstance(rows, list) else ():
                if isinstance(row, dict) and row.get("name") == chosen:
                    return row
    return None


def motor_limits(doc: dict) -> tuple[list[Line], list[Line]] | None:
    """The chosen motor's limits for the datasheet's envelope, to its no-load speed ω0:
    continuous its rated torque where the list gives one, peak M_λ (seed 003)."""
    row = listed_motor(doc)
    if not row or "speed_rad_s" not in row:
        return None
    n0 = row["speed_rad_s"] * 30.0 / math.pi
    cont = []
    if "rated_torque_Nm" in row:
        m_r = row["rated_torque_Nm"]
        cont = [Line(f"continuous: rated {m_r:.4g} N·m", [0.0, n0, n0], [m_r, m_r, 0.0])]
    peak = []
    if "accel_torque_Nm" in row:
        m_a = row["accel_torque_Nm"]
        peak = [Line(f"peak: M_λ {m_a:.4g} N·m", [0.0, n0, n0], [m_a, m_a, 0.0])]
    return (cont, peak) if cont or peak else None


#: The datasheet's plots of this application, in the datasheet's order.
DATASHEET_PLOTS = (move_time,)
