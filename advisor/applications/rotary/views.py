"""How the wizard shows a rotary-actuator report: its components and its plots."""

from typing import Any

from rich.table import Table

from advisor.tui.views import PlotData, kv


def components(report) -> list[Any]:
    d = report.design
    parts: list[Any] = []
    m, g = d.motor, d.gearbox
    parts.append(
        kv(
            "Motor",
            [
                ("speed", f"{m.speed_rpm:g} rpm"),
                ("torque", f"{m.torque_Nm:.4g} N·m at {m.current_A:.3g} A"),
                ("losses", f"{m.losses_W.total:.0f} W"),
            ],
        )
    )
    t = Table(title="Reducer stages (motor side first)", title_justify="left")
    for col in ("stage", "q", "rows", "torque N·m", "Ø mm", "length mm", "mass kg"):
        t.add_column(col, justify="right")
    for st in g.stages:
        t.add_row(
            str(st.position),
            f"{st.ratio:.4g}",
            str(st.rows),
            f"{st.torque_Nm:.4g}",
            f"{st.outer_diameter_mm:.4g}",
            f"{st.length_mm:.4g}",
            f"{st.mass_kg:.3g}",
        )
    parts.append(t)
    return parts


def plots(report) -> list[PlotData]:
    d = report.design
    cands = sorted(d.motor.candidates, key=lambda c: c.speed_rpm)
    speeds = [c.speed_rpm for c in cands]
    main = PlotData(
        "Motor losses against speed",
        "motor speed, rpm",
        "loss, W",
        [
            ("ohmic", speeds, [c.losses_W.ohmic for c in cands]),
            ("iron", speeds, [c.losses_W.iron for c in cands]),
            ("magnets", speeds, [c.losses_W.magnets for c in cands]),
            ("total", speeds, [c.losses_W.total for c in cands]),
        ],
    )
    fig = d.gearbox.fig1
    fig1 = PlotData(
        "Reducer stage volume per unit torque against q (seed 000, fig. 1)",
        "stage ratio q",
        "cm³ per N·m",
        [
            (f"{n} rows", fig.q, vols)
            for n, vols in zip(fig.rows, fig.volume_per_torque_cm3_per_Nm, strict=True)
        ],
    )
    from advisor.duty.views import plots as duty_plots

    return [main, fig1, *duty_plots(getattr(d, "duty", None))]
