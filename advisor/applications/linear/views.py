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


def compare(report) -> list[Any]:
    """The candidate motors of the catalog, the runners-up of the thread–motor choice where
    the report has them, and the one-way device types."""
    from advisor.tui.compare import Option, Section, decision, mark, one_way, table

    d = report.design
    m = d.motor
    t = table("motor", "kW", "speed rpm", "travel s", "start margin", "suitable")
    for c in m.candidates:
        chosen = c.model == m.model and c.rated_power_kW == m.rated_power_kW
        t.add_row(
            mark(chosen, f"{c.model or c.role}"),
            f"{c.rated_power_kW:g}",
            "—" if c.working_speed_rpm is None else f"{c.working_speed_rpm:.0f}",
            "—" if c.travel_time_s is None else f"{c.travel_time_s:.3g}",
            "—" if c.starting_torque_margin is None else f"{c.starting_torque_margin:.3g}",
            "yes" if c.suitable else "no: " + "; ".join(c.problems)[:40],
        )
    out = [
        Section(
            "Candidate motors",
            t,
            " ".join(x for x in (decision(report, "IM-02"), decision(report, "IM-03")) if x),
            (),
            "The motor follows from the thread and the catalog; the requirement imposes the "
            "thread.",
        )
    ]
    runners = getattr(d, "runners_up", None) or getattr(d.screw, "runners_up", None) or []
    if runners:
        r = table("thread", "motor", "travel s", "why not chosen")
        options = []
        r.add_row(mark(True, d.screw.thread), m.model, f"{m.travel_time_s:.3g}", "chosen")
        for x in runners:
            thread = getattr(x, "thread", "?")
            r.add_row(
                mark(False, str(thread)),
                str(getattr(x, "motor", None) or getattr(x, "model", "") or "—"),
                _num(getattr(x, "travel_time_s", None)),
                str(getattr(x, "reason", None) or getattr(x, "why", "") or ""),
            )
            if thread != d.screw.thread and all(o.label != f"Use {thread}" for o in options):
                options.append(Option(f"Use {thread}", ((("screw", "thread"), thread),)))
        out.append(
            Section(
                "Thread and motor: the runners-up",
                r,
                decision(report, "SCR-04"),
                tuple(options),
                "“Use” imposes the thread (screw.thread).",
            )
        )
    return out + one_way(report)


def _num(v) -> str:
    return "—" if v is None else f"{v:.3g}"
