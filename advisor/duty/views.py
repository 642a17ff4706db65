"""The wizard's plots of a duty cycle: torque against time and speed against time."""

from advisor.tui.views import PlotData


def series(duty) -> tuple[list[float], list[float], list[float], list[float]]:
    """(t, torque) as steps and (t, speed) as ramps over one cycle, from the phases."""
    tt, mm, ts, ns = [], [], [], []
    t = 0.0
    for p in duty.phases:
        tt += [t, t + p.time_s]
        mm += [p.torque_Nm, p.torque_Nm]
        ts += [t, t + p.time_s]
        ns += [p.speed_start_rpm, p.speed_end_rpm]
        t += p.time_s
    return tt, mm, ts, ns


def plots(duty) -> list[PlotData]:
    if duty is None:
        return []
    tt, mm, ts, ns = series(duty)
    rms = duty.rms_torque_Nm
    return [
        PlotData(
            f"Torque over the cycle (RMS {rms:.4g} N·m, "
            f"thermal use {duty.thermal_utilisation:.3g})",
            "time, s",
            "motor torque, N·m",
            [("torque", tt, mm), ("RMS", [tt[0], tt[-1]], [rms, rms])],
        ),
        PlotData("Speed over the cycle", "time, s", "motor speed, rpm", [("speed", ts, ns)]),
        *_thermal(duty),
    ]


def _thermal(duty) -> list[PlotData]:
    th = getattr(duty, "thermal", None)
    if th is None:
        return []
    lim = th.limit_rise_K
    over = "one S2 run from cold" if duty.duty_type == "S2" else "repeated cycles"
    return [
        PlotData(
            f"Winding temperature rise over {over} (τ = {th.time_constant_s:g} s)",
            "time, s",
            "rise, K",
            [("rise", th.time_s, th.rise_K), ("limit", [0.0, th.time_s[-1]], [lim, lim])],
        )
    ]
