"""A reducer under a load spectrum: the makers' selection method for strain-wave and
rolling-body reducers.

A cycle is a list of :class:`Load` phases at the reducer's output: torque T_i, speed n_i,
time t_i. The method weighs each phase by the revolutions it turns (n·t), because the
rolling elements tire per revolution:

.. math::

    T_{av} = \\left(\\frac{\\sum |n_i| t_i |T_i|^3}{\\sum |n_i| t_i}\\right)^{1/3},\\qquad
    n_{av} = \\frac{\\sum |n_i| t_i}{\\sum t_i}

and the life of the rolling elements follows from T_av and the mean input speed:
L = L_n·(n_N/n_in,av)·(T_N/T_av)^p, p = 3 for balls, 10/3 for rollers (ISO 281's exponents).

References
----------
[1] Honpine, "How to Selection Harmonic Reduction Gear?" (2026): the FSG-25 example,
    150 / 82 / 130 / 0 N·m for 0.2 / 3 / 0.3 / 0.2 s at 10 / 20 / 10 / 0 rpm → T_av = 89 N·m.
[2] Harmonic Drive AG, Engineering data CSD-2A component sets (1019659 11/2014), §4.1.2 "Life
    of the Wave Generator Bearing": L50 = L_n·(n_N/n_in,av)·(T_N/T_av)³, L10 ≈ L50/5,
    L_n = 35 000 h (CSF, CSD, HFUC …), n_N = 2000 rpm.
[3] ISO 281:2007: the life exponent 3 (ball bearings), 10/3 (roller bearings).
"""

import math
from typing import NamedTuple

#: Life exponent of the rolling elements (ISO 281:2007, eq. (1)): balls 3, rollers 10/3.
LIFE_EXPONENT = {"ball": 3.0, "roller": 10.0 / 3.0}
#: [2], table 20.1: the nominal L50 life of the CSF series at rated torque and speed, h ...
RATED_LIFE_L50_H = 35000.0
#: ... at the rated input speed n_N, rpm ([2], §4.1.2) ...
RATED_INPUT_SPEED_RPM = 2000.0
#: ... and L10 ≈ L50/5 ([2], eq. 20.3).
L10_PER_L50 = 0.2
#: Harmonic Drive LLC, CSF-25-50-2UH product page: rated torque 39 N·m, limit for repeated
#: peak torque 98 N·m, limit for momentary peak torque 186 N·m. The allowances over the rated
#: torque of a stage are these ratios.
CSF_25_50_RATED_NM = 39.0
CSF_25_50_REPEATED_PEAK_NM = 98.0
CSF_25_50_MOMENTARY_PEAK_NM = 186.0
REPEATED_PEAK_FACTOR = CSF_25_50_REPEATED_PEAK_NM / CSF_25_50_RATED_NM
MOMENTARY_PEAK_FACTOR = CSF_25_50_MOMENTARY_PEAK_NM / CSF_25_50_RATED_NM


class Load(NamedTuple):
    """One phase of the cycle at the output: torque (N·m), speed (rpm), time (s)."""

    torque_Nm: float
    speed_rpm: float
    time_s: float


def revolutions_weight(phases: list[Load]) -> float:
    """Σ|n|·t (rpm·s): the revolutions turned, times 60.

    Parameters
    ----------
    phases : list of Load
        The cycle at the output: torque [N·m], speed [rpm], time [s] per phase

    Returns
    -------
    float
        Σ|n_i|·t_i [rpm·s]
    """
    return sum(abs(p.speed_rpm) * p.time_s for p in phases)


def cube_mean_torque(phases: list[Load]) -> float:
    """T_av = (Σ|n|·t·|T|³ / Σ|n|·t)^(1/3)  [N·m], [1] step 2, [2] eq. 18.2. A cycle that
    never turns has no revolution-weighted mean: its largest torque is returned (a stage
    held at standstill is loaded statically, not in fatigue).

    Hand check ([1]): (10·0.2·150³ + 20·3·82³ + 10·0.3·130³)/(10·0.2 + 20·3 + 10·0.3)
    = (6 750 000 + 33 082 080 + 6 591 000)/65 = 714 201.2, ∛ = 89.39 N·m.

    Parameters
    ----------
    phases : list of Load
        The cycle at the output: torque [N·m], speed [rpm], time [s] per phase

    Returns
    -------
    float
        Cube-mean torque T_av [N·m]

    Examples
    --------
    >>> round(cube_mean_torque([Load(150, 10, 0.2), Load(82, 20, 3), Load(130, 10, 0.3),
    ...                         Load(0, 0, 0.2)]), 2)
    89.39
    """
    w = revolutions_weight(phases)
    if w <= 0:
        return max((abs(p.torque_Nm) for p in phases), default=0.0)
    return (sum(abs(p.speed_rpm) * p.time_s * abs(p.torque_Nm) ** 3 for p in phases) / w) ** (
        1.0 / 3.0
    )


def mean_speed_rpm(phases: list[Load]) -> float:
    """n_av = Σ|n|·t / Σt  [rpm] over the whole cycle, rests included ([2], eq. 18.5).

    Parameters
    ----------
    phases : list of Load
        The cycle at the output: torque [N·m], speed [rpm], time [s] per phase

    Returns
    -------
    float
        Mean speed n_av [rpm]; 0 for a cycle of no time
    """
    t = sum(p.time_s for p in phases)
    return revolutions_weight(phases) / t if t > 0 else 0.0


def max_speed_rpm(phases: list[Load]) -> float:
    """The cycle's top speed at the output, max |n_i|  [rpm].

    Parameters
    ----------
    phases : list of Load
        The cycle at the output: torque [N·m], speed [rpm], time [s] per phase

    Returns
    -------
    float
        Largest |n_i| [rpm]; 0 for an empty cycle
    """
    return max((abs(p.speed_rpm) for p in phases), default=0.0)


def repeated_peak_torque(phases: list[Load]) -> float:
    """The largest |T| of the normal cycle (acceleration, braking, holding)  [N·m].

    Parameters
    ----------
    phases : list of Load
        The cycle at the output: torque [N·m], speed [rpm], time [s] per phase

    Returns
    -------
    float
        Largest |T_i| of the phases that last [N·m]
    """
    return max((abs(p.torque_Nm) for p in phases if p.time_s > 0), default=0.0)


def rolling_life_h(
    rated_torque_Nm: float,
    mean_torque_Nm: float,
    mean_input_speed_rpm: float,
    exponent: float = 3.0,
    rated_life_h: float = RATED_LIFE_L50_H,
    rated_speed_rpm: float = RATED_INPUT_SPEED_RPM,
) -> float:
    """L = L_n·(n_N/n_in,av)·(T_N/T_av)^p  [h] ([2] eq. 20.2 with ISO 281's exponent p); the
    life at rated torque and speed is L_n. Infinite where the stage does not turn or carries
    no torque.

    Parameters
    ----------
    rated_torque_Nm : float
        Rated torque of the stage T_N [N·m]
    mean_torque_Nm : float
        Cube-mean torque T_av (× the service factor) [N·m]
    mean_input_speed_rpm : float
        Mean input speed n_in,av [rpm]
    exponent : float, optional
        Life exponent p: 3 balls, 10/3 rollers [-]
    rated_life_h : float, optional
        Life at rated torque and speed L_n [h]
    rated_speed_rpm : float, optional
        Rated input speed n_N [rpm]

    Returns
    -------
    float
        L50 life of the rolling elements [h]

    Notes
    -----
    The makers' rating of the wave generator bearing; the seed gives eq. (16) no life.

    Examples
    --------
    >>> round(rolling_life_h(100.0, 50.0, 1000.0))  # 35 000·2·8
    560000
    """
    if mean_input_speed_rpm <= 0 or mean_torque_Nm <= 0:
        return math.inf
    return (
        rated_life_h
        * (rated_speed_rpm / mean_input_speed_rpm)
        * (rated_torque_Nm / mean_torque_Nm) ** exponent
    )


def momentary_peak_count_allowed(input_speed_rpm: float, duration_s: float) -> float:
    """N = 10⁴ / (2·n_in/60·t): the momentary peaks a strain-wave gear takes, 10⁴ flexings of
    the flexspline at the momentary torque, two per wave-generator revolution, while the peak
    lasts t at input speed n_in. The form of Harmonic Drive's selection procedure as a public
    selection script states it (its primary text was not found): shown, never decisive.

    Parameters
    ----------
    input_speed_rpm : float
        Input (wave generator) speed during the peak n_in [rpm]
    duration_s : float
        Duration of one peak t [s]

    Returns
    -------
    float
        Momentary peaks allowed over the life N [-]; infinite at standstill
    """
    turns = 2.0 * input_speed_rpm / 60.0 * duration_s
    return math.inf if turns <= 0 else 1e4 / turns
