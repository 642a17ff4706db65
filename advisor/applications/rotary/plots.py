"""The rotary actuator's datasheet plots (seed 000): the motor's losses against speed, the
reducer's design space and fig. 1. Each reads its own keys of the report's plain data; the
datasheet draws them (:mod:`advisor.datasheet.plots`) after the motor's envelope and before
the duty cycle's."""

from typing import Any

from advisor.datasheet.plots import Line, Plot, at, table_at


def motor_losses(doc: dict) -> Plot | None:
    """The BLDC motor's losses against speed (seed 000): the report's loss curve
    (``design.motor.loss_curve``, the U of eq. (10) the speed choice rests on) as lines,
    the candidate speeds' totals as points, the chosen speed, the loss optimum and the
    frame's limit marked. A report without the curve shows the candidates as points only
    (a straight line between two of them would draw a curve nobody computed)."""
    cands = [c for c in at(doc, "design", "motor", "candidates") or [] if "losses_W" in c]
    if not cands:
        return None
    cands = sorted(cands, key=lambda c: c["speed_rpm"])
    speeds = [c["speed_rpm"] for c in cands]
    curve = at(doc, "design", "motor", "loss_curve") or {}
    if curve.get("speed_rpm"):
        lines = [
            Line(part, curve["speed_rpm"], curve[f"{part}_W"])
            for part in ("ohmic", "iron", "magnets", "total")
            if f"{part}_W" in curve
        ]
        lines.append(
            Line("candidates (total)", speeds, [c["losses_W"]["total"] for c in cands], "points")
        )
    else:
        lines = [
            Line(part, speeds, [c["losses_W"][part] for c in cands], "points")
            for part in ("ohmic", "iron", "magnets", "total")
            if all(part in c["losses_W"] for c in cands)
        ]
    motor = at(doc, "design", "motor") or {}
    chosen, best = motor.get("speed_rpm"), motor.get("optimum_speed_rpm")
    vlines = [(chosen, f"chosen {chosen:g} rpm")] if chosen is not None else []
    if isinstance(best, int | float):
        vlines.append((best, f"loss optimum {best:.4g} rpm"))
    top = curve.get("speed_limit_rpm")
    if isinstance(top, int | float):
        vlines.append((top, f"rated speed {top:.5g} rpm (no losses stated above)"))
    limit = motor.get("loss_limit_W")
    hlines = [(limit, f"frame's limit {limit:.4g} W")] if isinstance(limit, int | float) else []
    return Plot(
        "motor-losses",
        "Motor losses against speed",
        "motor speed, rpm",
        "loss, W",
        lines,
        vlines,
        hlines,
    )


def _point(label: str, g: Any, style: str = "marker") -> Line | None:
    if isinstance(g, dict) and "outer_diameter_mm" in g and "mass_kg" in g:
        return Line(label, [g["outer_diameter_mm"]], [g["mass_kg"]], style)
    return None


def reducer_space(doc: dict) -> Plot | None:
    """The reducer design space as mass against outer diameter: the rule's design, the
    optima of the sweep and, where the report has it, the Pareto front (seed 000)."""
    g = at(doc, "design", "gearbox")
    if not isinstance(g, dict) or "mass_kg" not in g:
        return None
    lines: list[Line] = []
    pareto = g.get("pareto") if isinstance(g.get("pareto"), dict) else {}
    if isinstance(pareto.get("points"), list):  # a front as rows
        rows = [p for p in pareto["points"] if "outer_diameter_mm" in p and "mass_kg" in p]
        xs, ys = [p["outer_diameter_mm"] for p in rows], [p["mass_kg"] for p in rows]
    else:  # a front as columns, like fig1
        xs, ys = pareto.get("outer_diameter_mm"), pareto.get("mass_kg")
    if isinstance(xs, list) and isinstance(ys, list) and xs and len(xs) == len(ys):
        front = sorted(zip(xs, ys, strict=True))
        size = pareto.get("front_size")
        lines.append(
            Line(
                "Pareto front (mass, diameter, length, efficiency)"
                + (f": {len(front)} of {size} designs" if size else ""),
                [x for x, _ in front],
                [y for _, y in front],
                "points",
            )
        )
    by = _point("lightest design that dominates the rule's", pareto.get("dominated_by"))
    for label, part in (
        ("least mass in the design space", g.get("optimum")),
        ("least diameter in the design space", g.get("optimum_min_diameter")),
        ("the rule's design (adopted)", g),
    ):
        line = _point(label, part)
        if line is not None:
            lines.append(line)
    if by is not None:
        lines.append(by)
    d_max = at(doc, "requirements", "envelope", "max_outer_diameter_mm")
    vlines = [(d_max, f"envelope Ø{d_max:g} mm")] if d_max is not None else []
    return Plot(
        "reducer-design-space",
        "Reducer design space: mass against outer diameter",
        "outer diameter, mm",
        "mass, kg",
        lines,
        vlines,
    )


def reducer_fig1(doc: dict) -> Plot | None:
    """Stage volume per unit torque against q for 2…12 rows (seed 000, fig. 1)."""
    f = at(doc, "design", "gearbox", "fig1")
    if not isinstance(f, dict) or not f.get("q"):
        return None
    lines = [
        Line(f"{n} rows", f["q"], vols)
        for n, vols in zip(f["rows"], f["volume_per_torque_cm3_per_Nm"], strict=True)
    ]
    return Plot(
        "reducer-fig1",
        "Stage volume per unit torque against q (seed 000, fig. 1)",
        "stage ratio q",
        "volume per torque, cm³/(N·m)",
        lines,
    )


def motor_limits(doc: dict) -> tuple[list[Line], list[Line]] | None:
    """The frame's limits for the datasheet's envelope: continuous its rated torque up to its
    speed, peak the duty cycle's peak torque limit where the report has a cycle."""
    motor = table_at(doc, "design", "motor")
    if not ("torque_Nm" in motor and "speed_rpm" in motor and "candidates" in motor):
        return None
    n_r, m_r = motor["speed_rpm"], motor["torque_Nm"]
    cont = [Line(f"continuous: {m_r:.4g} N·m to {n_r:.4g} rpm", [0.0, n_r, n_r], [m_r, m_r, 0.0])]
    limit = at(doc, "design", "duty", "peak_torque_limit_Nm")
    peak = []
    if isinstance(limit, int | float):
        peak = [Line(f"peak: {limit:.4g} N·m", [0.0, n_r, n_r], [limit, limit, 0.0])]
    return cont, peak


def working_point(doc: dict) -> tuple[float, float] | None:
    """The motor's speed and torque at the working point, rpm and N·m."""
    motor = table_at(doc, "design", "motor")
    n, m = motor.get("speed_rpm"), motor.get("torque_Nm")
    return (n, m) if isinstance(n, int | float) and isinstance(m, int | float) else None


#: The datasheet's plots of this application, in the datasheet's order.
DATASHEET_PLOTS = (
    motor_losses,
    reducer_space,
    reducer_fig1,
)
