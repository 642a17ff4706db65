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
                *_frame_lines(m),
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


def _frame_lines(m) -> list[tuple[str, str]]:
    """The frame the design took, as the components show it."""
    f = getattr(m, "frame", None)
    if f is None:
        return []
    kind = {"scaled": "scaled frame", "catalog": "catalog motor"}.get(f.kind, "reference frame")
    size = f" Ø{f.outer_diameter_mm:.4g} mm" if f.outer_diameter_mm else ""
    mass = f", {f.mass_kg:.3g} kg" if f.mass_kg else ""
    return [
        ("frame", f"{f.name} ({kind}, {f.choice}){size}{mass}"),
        ("continuous", f"{f.torque_Nm:.4g} N·m at {f.speed_rpm:.5g} rpm"),
    ]


def loss_curve(report) -> list[dict]:
    """The report's loss curve (``design.motor.loss_curve``: seed 000, eqs. (4), (5), (9),
    computed by the advice as the candidates are) as one dict a speed: speed_rpm, ohmic,
    iron, magnets, total [rpm, W]. Empty for a report without one."""
    curve = getattr(report.design.motor, "loss_curve", None)
    if curve is None:
        return []
    parts = zip(curve.ohmic_W, curve.iron_W, curve.magnets_W, curve.total_W, strict=True)
    return [
        {"speed_rpm": n, "ohmic": o, "iron": i, "magnets": m, "total": t}
        for n, (o, i, m, t) in zip(curve.speed_rpm, parts, strict=True)
    ]


def plots(report) -> list[PlotData]:
    """The motor's losses against speed (the report's curve, the candidates and the working
    point on it, the frame's limit), seed 000's fig. 1, and the duty cycle's plots."""
    d = report.design
    cands = sorted(d.motor.candidates, key=lambda c: c.speed_rpm)
    curve = loss_curve(report) or [
        {"speed_rpm": c.speed_rpm, **c.losses_W.as_dict()} for c in cands
    ]
    speeds = [c["speed_rpm"] for c in curve]
    series = [
        (name, speeds, [c[name] for c in curve]) for name in ("ohmic", "iron", "magnets", "total")
    ]
    series += [
        (f"candidate {c.speed_rpm:g} rpm (total)", [c.speed_rpm], [c.losses_W.total]) for c in cands
    ]
    series.append(("working point", [d.motor.speed_rpm], [d.motor.losses_W.total]))
    series.append(("frame's limit", [speeds[0], speeds[-1]], [d.motor.loss_limit_W] * 2))
    main = PlotData("Motor losses against speed", "motor speed, rpm", "loss, W", series)
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


def compare(report) -> list[Any]:
    """Candidate motor speeds, the rule reducer against the lightest and the slimmest of the
    design space, and the one-way device types."""
    from advisor.tui.compare import one_way

    speeds, reducer = _speeds_section(report), _reducer_section(report)
    return [*_frames_section(report), speeds, reducer, *one_way(report)]


def _speeds_section(report):
    """The candidate speeds (BL-02), each but the chosen one with “Use …” where it passes."""
    from advisor.tui.compare import Option, Section, decision, mark, table

    m = report.design.motor
    t = table("speed rpm", "q_Σ", "stages", "η", "torque N·m", "losses W", "within limit")
    options = []
    for c in sorted(m.candidates, key=lambda c: c.speed_rpm):
        chosen = c.speed_rpm == m.speed_rpm
        t.add_row(
            mark(chosen, f"{c.speed_rpm:g}"),
            f"{c.total_ratio:.4g}",
            str(c.stages),
            f"{c.gearbox_efficiency:.3g}",
            f"{c.torque_Nm:.4g}",
            f"{c.losses_W.total:.4g}",
            "yes" if c.within_loss_limit else "no",
        )
        if not chosen and c.within_loss_limit and c.stages:
            patch = ((("motor", "candidate_speeds_rpm"), [c.speed_rpm]),)
            options.append(Option(f"Use {c.speed_rpm:g} rpm", patch))
    return Section(
        "Motor speed (the reference motor rewound)",
        t,
        decision(report, "BL-02"),
        tuple(options),
        "“Use” keeps that speed alone in motor.candidate_speeds_rpm.",
    )


def _reducer_row(key: str, name: str, s, taken: str, wg6: dict | None) -> tuple[str, ...]:
    """One reducer of the comparison: its figures, or the rule design's as WG-06 states it
    where the design took another, or none where the envelope asks more rows."""
    from advisor.tui.compare import mark

    if s is not None:
        ratios = ", ".join(f"{st.ratio:.4g}" for st in reversed(s.stages))
        return (
            mark(key == taken, name),
            str(len(s.stages)),
            ratios,
            f"{s.outer_diameter_mm:.4g}",
            f"{s.length_mm:.4g}",
            f"{s.mass_kg:.3g}",
            f"{s.efficiency:.3g}",
        )
    if wg6 is not None and "rule_mass_kg" in wg6:  # not taken: as WG-06 states it
        return (
            mark(False, name),
            str(int(wg6["rule_stages"])),
            "see WG-02" if wg6["rule_fits"] else "does not fit the envelope",
            f"{wg6['rule_outer_diameter_mm']:.4g}",
            f"{wg6['rule_length_mm']:.4g}",
            f"{wg6['rule_mass_kg']:.3g}",
            f"{wg6['rule_efficiency']:.3g}",
        )
    return (mark(False, name), "—", "none: the envelope asks more rows", "", "", "", "")


def _reducer_section(report):
    """The rules' reducer against the lightest and the slimmest of the space (WG-04/05/06),
    each not taken nor asked with “Use …”."""
    from advisor.tui.compare import Option, Section, decision, table

    g = report.design.gearbox
    r = table("reducer", "stages", "q (output first)", "Ø mm", "length mm", "mass kg", "η")
    asked = report.requirements.get("gearbox", {}).get("choice", "rules")
    wg6 = next((d.inputs for d in report.decisions if d.id == "WG-06"), None)
    taken = "rules" if wg6 is None else wg6["taken"]
    rows = [
        ("rules", "rules (seed 000)", g if taken == "rules" else None),
        ("lightest", "lightest in the space", g.optimum),
        ("slimmest", "slimmest in the space", g.optimum_min_diameter),
    ]
    options = []
    for key, name, s in rows:
        r.add_row(*_reducer_row(key, name, s, taken, wg6))
        if key not in (taken, asked):  # a button that would change nothing is not offered
            word = "the rules" if key == "rules" else f"the {key}"
            options.append(Option(f"Use {word}", ((("gearbox", "choice"), key),)))
    why = " ".join(x for x in (decision(report, i) for i in ("WG-04", "WG-06", "WG-05")) if x)
    return Section(
        "Reducer: the rules against the design space",
        r,
        why,
        tuple(options),
        "“Use” sets gearbox.choice: the rules' design, or the lightest or the slimmest of "
        "the design space within the envelope.",
    )


def _frames_section(report) -> list[Any]:
    """The frames tried (BL-03) and the neighbours of the one taken, each with “Use …”."""
    from advisor.tui.compare import Option, Section, decision, mark, table

    f = getattr(report.design.motor, "frame", None)
    if f is None:
        return []
    t = table("frame", "kind", "continuous N·m", "at rpm", "Ø mm", "mass kg", "result")
    rows = [(r, r.why if r.why != "neighbour" else "neighbour") for r in (*f.tried, *f.neighbours)]
    shown, options = set(), []
    if f.name not in {r.name for r, _ in rows}:
        t.add_row(
            mark(True, f.name),
            f.kind,
            f"{f.torque_Nm:.4g}",
            f"{f.speed_rpm:.5g}",
            # the reference frame of a [motor.reference] states no outer size or mass
            "—" if f.outer_diameter_mm is None else f"{f.outer_diameter_mm:.4g}",
            "—" if f.mass_kg is None else f"{f.mass_kg:.3g}",
            "taken",
        )
        shown.add(f.name)
    for r, why in rows:
        if r.name in shown:
            continue
        shown.add(r.name)
        taken = r.name == f.name
        t.add_row(
            mark(taken, r.name),
            r.kind,
            f"{r.torque_Nm:.4g}",
            f"{r.speed_rpm:.5g}",
            f"{r.outer_diameter_mm:.4g}",
            f"{r.mass_kg:.3g}",
            "taken" if taken else why,
        )
        if not taken:
            options.append(Option(f"Use {r.name}", ((("motor", "frame"), r.name),)))
    if f.choice != "auto":
        options.append(Option("Use auto", ((("motor", "frame"), "auto"),)))
    return [
        Section(
            "Motor frame (seed 000's scaled series)",
            t,
            decision(report, "BL-03") or f.data,
            tuple(options),
            "“Use” sets motor.frame: a frame of the series, or auto (the smallest that passes).",
        )
    ]
