"""How the wizard shows a linear-actuator report: its components and its plots."""

from typing import Any

from advisor.tui.views import PlotData, kv


def components(report) -> list[Any]:
    d = report.design
    parts: list[Any] = []
    s, m = d.screw, d.motor
    parts.append(
        kv(
            "Screw",
            [
                ("thread", s.thread + (" (imposed)" if s.imposed else "")),
                *([("starts", f"{s.starts} (lead {s.lead_mm:g} mm)")] if s.starts > 1 else []),
                ("speed", f"{s.speed_rpm:.0f} rpm"),
                ("torque", f"{s.torque_Nm:.4g} N·m ({s.friction_model})"),
                ("efficiency", s.efficiency),
                ("self-locking", s.self_locking),
            ],
        )
    )
    parts.append(
        kv(
            "Motor",
            [
                ("model", m.model),
                ("rated power", f"{m.rated_power_kW:g} kW"),
                ("pole pairs", m.pole_pairs),
                ("working speed", f"{m.working_speed_rpm:.0f} rpm"),
                ("travel time", f"{m.travel_time_s:.3g} s"),
            ],
        )
    )
    return parts


def plots(report) -> list[PlotData]:
    d = report.design
    series = [
        (f"{c.model or c.role} {c.rated_power_kW:g} kW", c.curve.speed_rpm, c.curve.torque_Nm)
        for c in d.motor.candidates
        if getattr(c, "curve", None) is not None
    ]
    series.append(("screw torque", [d.motor.working_speed_rpm], [d.screw.torque_Nm]))
    main = PlotData(
        "M(n) of the candidate motors and the working point",
        "speed, rpm",
        "torque, N·m",
        series,
    )
    from advisor.duty.views import plots as duty_plots

    return [main, *duty_plots(getattr(d, "duty", None))]
