"""Where the energy a braking drive gives back goes: the DC-bus capacitor and the braking
resistor (issue 26, item 6).

While the motor brakes (its torque opposes its speed) the load's energy flows back into the
drive's DC bus and charges its capacitor from the nominal voltage U_nom towards the largest
voltage the bus stands, U_max. The capacitor takes

.. math::  E_{bus} = \\tfrac{1}{2} C (U_{max}^2 - U_{nom}^2)

of each braking; what it cannot take goes into the braking resistor, which the chopper
switches across the bus at U_max. The resistor must take the peak regenerative power
(so its resistance is at most U_max²/P_peak) and, on average over the cycle, the energy the
capacitor could not hold. The motor's own losses while braking are neglected: the figures
err high.

References
----------
[1] Servotronix, CDHD2 servo drive user manual, "Regenerative resistor": E_BUS =
    ½·C·(V_M² − V_NOM²); a resistor is needed when the energy of a deceleration exceeds it;
    then its resistance and its average power follow from the motion profile.
[2] Schneider Electric, Lexium 17S servo drive manual, "Regen resistor": the drive absorbs
    energy whenever the sign of the motor torque is opposite to that of its speed.
"""

from typing import NamedTuple

from advisor.calc.duty import Phase


class Braking(NamedTuple):
    """One braking event: consecutive phases in which the motor gives energy back."""

    energy_J: float
    peak_power_W: float
    duration_s: float


def phase_peak_regen_W(p: Phase) -> float:
    """The largest power a phase gives back, W (0 if it gives none): −M·ω at the end of the
    ramp where |ω| is largest (M is constant over a phase, ω linear)."""
    worst = min(p.torque_Nm * p.speed_start_rad_s, p.torque_Nm * p.speed_end_rad_s)
    return max(-worst, 0.0)


def brakings(phases: list[Phase]) -> list[Braking]:
    """The braking events of a cycle: runs of consecutive phases that give energy back ([2])."""
    out: list[Braking] = []
    e = pk = dt = 0.0
    for p in [*phases, Phase("", 0.0, 0.0, 0.0, 0.0)]:
        if p.energy_J < 0:
            e, pk, dt = e - p.energy_J, max(pk, phase_peak_regen_W(p)), dt + p.time_s
        elif e > 0:
            out.append(Braking(e, pk, dt))
            e = pk = dt = 0.0
    return out


def bus_energy_J(capacitance_F: float, nominal_V: float, max_V: float) -> float:
    """E = ½·C·(U_max² − U_nom²)  [J], [1].

    >>> bus_energy_J(1e-3, 300.0, 400.0)
    35.0
    """
    return 0.5 * capacitance_F * (max_V**2 - nominal_V**2)


def capacitance_for_F(energy_J: float, nominal_V: float, max_V: float) -> float:
    """C = 2E/(U_max² − U_nom²)  [F]: the capacitance that takes ``energy_J`` alone, [1].

    >>> round(capacitance_for_F(35.0, 300.0, 400.0) * 1e3, 6)
    1.0
    """
    return 2.0 * energy_J / (max_V**2 - nominal_V**2)


class Resistor(NamedTuple):
    needed: bool
    peak_power_W: float
    average_power_W: float
    max_resistance_ohm: float  # at most this resistance dumps the peak power at U_max


def braking_resistor(
    events: list[Braking], cycle_time_s: float, bus_J: float, max_V: float
) -> Resistor:
    """The resistor for the events of a cycle, the bus taking ``bus_J`` of each ([1]): every
    event whose energy exceeds it needs the resistor at that event's peak power; on average
    the resistor dissipates the energy beyond the bus's share over the cycle."""
    over = [b for b in events if b.energy_J > bus_J]
    if not over:
        return Resistor(False, 0.0, 0.0, float("inf"))
    peak = max(b.peak_power_W for b in over)
    average = sum(b.energy_J - bus_J for b in over) / cycle_time_s
    return Resistor(True, peak, average, max_V**2 / peak if peak > 0 else float("inf"))
