"""Where the energy a braking drive gives back goes: the DC-bus capacitor and the braking
resistor.

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
    """The largest power a phase of a cycle gives back to the drive.

        P = max(0, −M·ω_start, −M·ω_end)

    Parameters
    ----------
    p : Phase
        Motor torque M [N·m] (constant over the phase) and speeds at its start and end
        ω [rad/s] (linear in time between them)

    Returns
    -------
    float
        Peak regenerative power [W], 0 for a phase that gives none back

    Notes
    -----
    −M·ω is linear in time within a phase, so its largest value is at an end.

    References
    ----------
    [2]: a drive takes energy back whenever the motor torque opposes the speed.

    Examples
    --------
    >>> phase_peak_regen_W(Phase("brake", 0.5, 100.0, 0.0, -2.0))
    200.0
    """
    worst = min(p.torque_Nm * p.speed_start_rad_s, p.torque_Nm * p.speed_end_rad_s)
    return max(-worst, 0.0)


def brakings(phases: list[Phase]) -> list[Braking]:
    """The braking events of a cycle: runs of consecutive phases that give energy back.

        E = Σ −M·(ω_start + ω_end)/2·t,   P_peak = max phase_peak_regen_W,   t = Σ t

    Parameters
    ----------
    phases : list[Phase]
        The cycle's phases in order (torque [N·m], speeds [rad/s], durations [s])

    Returns
    -------
    list[Braking]
        Each event's energy given back [J], peak power [W] and duration [s]

    References
    ----------
    [2].

    Examples
    --------
    >>> cycle = [Phase("accelerate", 0.5, 0.0, 100.0, 2.0), Phase("brake", 0.5, 100.0, 0.0, -2.0)]
    >>> brakings(cycle)
    [Braking(energy_J=50.0, peak_power_W=200.0, duration_s=0.5)]
    """
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
    """The energy the DC-bus capacitor takes while its voltage rises from nominal to largest.

        E = ½·C·(U_max² − U_nom²)

    Parameters
    ----------
    capacitance_F : float
        Bus capacitance C [F], ≥ 0
    nominal_V : float
        Nominal bus voltage U_nom [V]
    max_V : float
        Largest bus voltage U_max [V] (the braking chopper's threshold), ≥ U_nom

    Returns
    -------
    float
        Energy the bus takes from one braking [J]

    References
    ----------
    [1].

    Examples
    --------
    >>> bus_energy_J(1e-3, 300.0, 400.0)
    35.0
    """
    return 0.5 * capacitance_F * (max_V**2 - nominal_V**2)


def capacitance_for_F(energy_J: float, nominal_V: float, max_V: float) -> float:
    """The bus capacitance that takes a braking's energy alone, without a resistor.

        C = 2·E/(U_max² − U_nom²)

    Parameters
    ----------
    energy_J : float
        Energy of the braking E [J], ≥ 0
    nominal_V : float
        Nominal bus voltage U_nom [V]
    max_V : float
        Largest bus voltage U_max [V], > U_nom

    Returns
    -------
    float
        Capacitance C [F]

    References
    ----------
    [1].

    Examples
    --------
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
    """The braking resistor for a cycle's braking events, the bus taking part of each.

        P_peak = max P_peak,k,   P_avg = Σ (E_k − E_bus)/T_cycle,   R ≤ U_max²/P_peak
        (over the events with E_k > E_bus)

    Parameters
    ----------
    events : list[Braking]
        The cycle's braking events (:func:`brakings`)
    cycle_time_s : float
        Duration of one cycle T_cycle [s], > 0
    bus_J : float
        Energy the bus takes of each event E_bus [J] (:func:`bus_energy_J`)
    max_V : float
        Largest bus voltage U_max [V]

    Returns
    -------
    Resistor
        Whether one is needed, its peak and average power [W] and its largest resistance
        [Ω] (inf where none is needed)

    Notes
    -----
    The motor's own losses while braking are neglected: the figures err high.

    References
    ----------
    [1].

    Examples
    --------
    >>> events = [Braking(50.0, 200.0, 0.5)]
    >>> braking_resistor(events, 3.0, 20.0, 400.0)
    Resistor(needed=True, peak_power_W=200.0, average_power_W=10.0, max_resistance_ohm=800.0)
    """
    over = [b for b in events if b.energy_J > bus_J]
    if not over:
        return Resistor(False, 0.0, 0.0, float("inf"))
    peak = max(b.peak_power_W for b in over)
    average = sum(b.energy_J - bus_J for b in over) / cycle_time_s
    return Resistor(True, peak, average, max_V**2 / peak if peak > 0 else float("inf"))
