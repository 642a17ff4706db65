"""How the wizard shows a spinning-rotor report: its components and its plots."""

from typing import Any

from advisor.tui.views import PlotData, kv


def components(report) -> list[Any]:
    d = report.design
    parts: list[Any] = []
    r = d.rotor
    parts.append(
        kv(
            "Rotor",
            [
                ("gyroscopic moment", f"{r.gyroscopic_moment_Nm:.4g} N·m"),
                ("preload", f"{r.preload_N:.4g} N"),
                (
                    "steady power",
                    f"{r.steady_power_W.without_reaction:.4g} → "
                    f"{r.steady_power_W.with_reaction:.4g} W with the reaction",
                ),
                ("required torque", f"{r.required_torque_Nm:.4g} N·m"),
                ("run-up", f"{r.run_up_time_s:.3g} s"),
            ],
        )
    )
    b = r.bearing
    parts.append(
        kv(
            "Bearings",
            [
                ("bearing", f"{b.designation} {b.d_mm:g}×{b.D_mm:g}×{b.B_mm:g} mm"),
                ("friction (eq. 4)", f"{r.bearing_friction_Nm.with_reaction:.3g} N·m"),
                ("life L10h", f"{r.bearing_life_h:.3g} h"),
                ("static safety", b.static_safety),
            ],
        )
    )
    return parts


def plots(report) -> list[PlotData]:
    d = report.design
    r = d.rotor
    # each on its own time axis: the run-up takes seconds, a sustained slew can take minutes
    run_up = PlotData(
        "Run-up of the rotor",
        "time, s",
        "speed, rad/s",
        [("run-up", r.run_up.time_s, r.run_up.speed_rad_s)],
    )
    return [run_up, slew_plot(r)]


def slew_plot(r) -> PlotData:
    """A sustained slew at the design's drive torque (held: drawn flat) and with a drive sized on
    the steady power without the reaction (seed 002, fig. 4), each named with its torque."""
    slews = ((r.slew, "design drive"), (r.slew_if_sized_without_reaction, "sized without reaction"))
    end = max((s.curve.time_s[-1] for s, _ in slews if s.curve), default=1.0)
    series = []
    for s, who in slews:
        if s.curve:
            t, w = s.curve.time_s, s.curve.speed_rad_s
        else:
            t, w = [0.0, end], [s.speed_after_slew_rad_s] * 2
        series.append((f"{who}, {s.drive_torque_Nm:.4g} N·m", t, w))
    return PlotData("Speed during a sustained slew", "time, s", "speed, rad/s", series)
