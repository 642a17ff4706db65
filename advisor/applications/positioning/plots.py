"""The positioning drive's datasheet plots (seed 003): move time against the ratio.
Each reads its own keys of the report's plain data; the datasheet draws them
(:mod:`advisor.datasheet.plots`) after the motor's envelope and before the duty cycle's."""

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


#: The datasheet's plots of this application, in the datasheet's order.
DATASHEET_PLOTS = (move_time,)
