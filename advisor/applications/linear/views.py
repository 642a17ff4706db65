"""How the wizard shows a linear-actuator report: its components and its plots."""

import re
from typing import Any, NamedTuple

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
    the report has them (the inputs of decision SCR-04), and the one-way device types."""
    from advisor.tui.compare import Section, decision, one_way

    imposed = (report.requirements.get("screw") or {}).get("thread")
    note = (
        "The motor follows from the thread and the catalog; the requirement imposes the thread."
        if imposed
        else "The thread and the motor are chosen together (SCR-04); the catalog gives the motor."
    )
    why = " ".join(x for x in (decision(report, "IM-02"), decision(report, "IM-03")) if x)
    out = [Section("Candidate motors", _motors(report.design.motor), why, (), note)]
    runners = _runners_up(report)
    if runners and not imposed:
        out.append(_runners_section(report, runners))
    return out + one_way(report)


def _motors(m) -> Any:
    """The catalog's candidate motors, the chosen one marked."""
    from advisor.tui.compare import mark, table

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
    return t


class RunnerUp(NamedTuple):
    """One runner-up of the thread–motor choice as decision SCR-04 states it."""

    thread: str
    motor: str
    detail: str  # rated power and poles, in the report's words
    travel_time_s: float | None


#: "Tr16x2 + 4A71B4 (0.75 kW, 4-pole, stroke in 4.31 s)", as SCR-04 lists its runners-up.
_RUNNER = re.compile(r"(?P<thread>\S+) \+ (?P<motor>.+?) \((?P<detail>.*)\)")
_STROKE = re.compile(r",? *stroke in (?P<t>[0-9.eE+-]+) s")


def _runners_up(report) -> list[RunnerUp]:
    """The runners-up SCR-04 keeps in its inputs (``runners_up``), read from its text;
    an entry in another form is shown whole as the thread's row."""
    scr04 = next((d for d in report.decisions if d.id == "SCR-04"), None)
    out = []
    for text in (scr04.inputs.get("runners_up") or []) if scr04 is not None else []:
        m = _RUNNER.fullmatch(str(text))
        if m is None:
            out.append(RunnerUp(str(text), "—", "", None))
            continue
        stroke = _STROKE.search(m["detail"])
        detail = _STROKE.sub("", m["detail"]).strip(", ")
        out.append(RunnerUp(m["thread"], m["motor"], detail, stroke and float(stroke["t"])))
    return out


def _runners_section(report, runners: list[RunnerUp]) -> Any:
    """The chosen thread and motor above the runners-up, each runner-up's thread a "Use"."""
    from advisor.tui.compare import Option, Section, decision, mark, table

    s, m = report.design.screw, report.design.motor
    r = table("thread", "motor", "motor rating", "travel s")
    rating = f"{m.rated_power_kW:g} kW, {2 * m.pole_pairs}-pole"
    r.add_row(mark(True, s.designation), m.model, rating, _num(m.travel_time_s))
    options: list[Any] = []
    for x in runners:
        r.add_row(mark(False, x.thread), x.motor, x.detail, _num(x.travel_time_s))
        label = f"Use {x.thread}"
        if x.thread != s.designation and x.motor != "—" and all(o.label != label for o in options):
            options.append(Option(label, _use_thread(x.thread)))
    return Section(
        "Thread and motor: the runners-up",
        r,
        decision(report, "SCR-04"),
        tuple(options),
        "“Use” imposes the thread and its starts (screw.thread, screw.starts); the motor "
        "then follows from them.",
    )


def _use_thread(designation: str) -> tuple[tuple[tuple[str, ...], Any], ...]:
    """The requirement values that impose a runner-up: a designation such as Tr24x20(P5)
    (GOST 24739-81: lead 20, pitch 5) is the thread Tr24x5 with 4 starts; the requirement
    takes the thread as d x P and the starts apart."""
    from rules import screw as screw_rules

    thread, starts = screw_rules.thread_and_starts(designation)
    return ((("screw", "thread"), thread), (("screw", "starts"), starts))


def _num(v) -> str:
    return "—" if v is None else f"{v:.3g}"
