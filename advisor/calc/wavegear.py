"""Wave gear stages with rolling bodies (ВПТК): geometry, volume and mass.

Every function accepts scalars or numpy arrays (broadcast together), so a design space is
swept in one call. Lengths are in **mm** for a torque in **N·m**, as in the seed's formulas;
volumes in mm³, masses in kg.

References
----------
[1] Seed 000: Baranov, Borisov, Korchagin, Krylov, Samsonovich, Stepanov, «О выборе скорости
    электродвигателя и передаточного числа редуктора привода руля направления транспортного
    самолёта» (000_e109c3d4c17eaf1c.txt), eqs. (11)–(19) and the row inequality after (19).
"""

import numpy as np
from numpy.typing import ArrayLike

#: k_тк of eq. (16): load capacity factor of the rolling body.
ROLLING_BODY_FACTOR = {"ball": 1.0, "roller": 2.0}

#: The smallest ratio for which eq. (14) leaves a bore: 2.06/sin(π/q) > 4.4 ⇔ q > 6.448.
MIN_RATIO_FOR_BORE = float(np.pi / np.arcsin(2.06 / 4.4))


def _a(q: ArrayLike) -> np.ndarray:
    return 2.06 / np.sin(np.pi / np.asarray(q, dtype=float))


def rolling_body_diameter(
    torque_Nm: ArrayLike, q: ArrayLike, rows: ArrayLike, k_rb: ArrayLike = 1.0
) -> np.ndarray:
    """d_тк = ∛(241·M / (n_p·k_тк·(q − 1)) · sin(π/(q − 1)))  [mm]. Seed 000, eq. (16).

    Hand check: ∛(241·1000/(3·19)·sin(π/19)) = ∛(4228.07·0.164595) = ∛695.92 = 8.862 mm.

    Parameters
    ----------
    torque_Nm : float or array
        Torque the stage delivers M [N·m]
    q : float or array
        Stage ratio [-]
    rows : int or array
        Rows of rolling bodies n_p [-]
    k_rb : float or array, optional
        Load capacity factor k_тк: 1 balls, 2 rollers (length = diameter) [-]

    Returns
    -------
    numpy.ndarray
        Rolling body diameter d_тк [mm]

    Notes
    -----
    Valid for q > 2 (sin(π/(q − 1)) > 0); a bore needs q > 6.45 (eq. (14)). Lengths in mm
    for M in N·m, as the seed writes its formulas.

    Examples
    --------
    >>> round(float(rolling_body_diameter(1000.0, 20, 3)), 3)
    8.862
    """
    q = np.asarray(q, dtype=float)
    return np.cbrt(
        241.0
        * np.asarray(torque_Nm, dtype=float)
        / (np.asarray(rows) * np.asarray(k_rb) * (q - 1.0))
        * np.sin(np.pi / (q - 1.0))
    )


def outer_diameter(q: ArrayLike, d_rb: ArrayLike) -> np.ndarray:
    """D_н = (2.06/sin(π/q) + 1.8)·d_тк  [mm]. Seed 000, eq. (13).

    Parameters
    ----------
    q : float or array
        Stage ratio [-]
    d_rb : float or array
        Rolling body diameter d_тк [mm]

    Returns
    -------
    numpy.ndarray
        Outer diameter of the stage D_н [mm]

    Notes
    -----
    Valid for q > 1.
    """
    return (_a(q) + 1.8) * np.asarray(d_rb, dtype=float)


def inner_diameter(q: ArrayLike, d_rb: ArrayLike) -> np.ndarray:
    """d_вн = (2.06/sin(π/q) − 4.4)·d_тк  [mm]. Seed 000, eq. (14); positive for q > 6.45.

    Parameters
    ----------
    q : float or array
        Stage ratio [-]
    d_rb : float or array
        Rolling body diameter d_тк [mm]

    Returns
    -------
    numpy.ndarray
        Bore of the stage d_вн [mm]; negative (no bore) for q < 6.45
    """
    return (_a(q) - 4.4) * np.asarray(d_rb, dtype=float)


def stage_length(rows: ArrayLike, d_rb: ArrayLike) -> np.ndarray:
    """L = (1.2·n_p + 1.8)·d_тк  [mm]. Seed 000, eq. (15).

    Parameters
    ----------
    rows : int or array
        Rows of rolling bodies n_p [-]
    d_rb : float or array
        Rolling body diameter d_тк [mm]

    Returns
    -------
    numpy.ndarray
        Axial length of the stage L [mm]
    """
    return (1.2 * np.asarray(rows, dtype=float) + 1.8) * np.asarray(d_rb, dtype=float)


def hollow_cylinder_volume(D: ArrayLike, d: ArrayLike, L: ArrayLike) -> np.ndarray:
    """W = π/4·(D² − d²)·L  [mm³]. Seed 000, eq. (12).

    Parameters
    ----------
    D : float or array
        Outer diameter [mm]
    d : float or array
        Inner diameter [mm]
    L : float or array
        Length [mm]

    Returns
    -------
    numpy.ndarray
        Volume W [mm³]
    """
    D, d = np.asarray(D, dtype=float), np.asarray(d, dtype=float)
    return np.pi / 4.0 * (D**2 - d**2) * np.asarray(L, dtype=float)


def volume_per_torque(q: ArrayLike, rows: ArrayLike, k_rb: ArrayLike = 1.0) -> np.ndarray:
    """W/M of one stage  [mm³ per N·m], seed 000 eq. (18) divided by M (the curves of fig. 1):

    W/M = 189·(1.2n + 1.8)/(n·k·(q − 1))·sin(π/(q − 1))·[(a + 1.8)² − (a − 4.4)²],
    a = 2.06/sin(π/q), 189 ≈ 241·π/4.

    Parameters
    ----------
    q : float or array
        Stage ratio [-]
    rows : int or array
        Rows of rolling bodies n [-]
    k_rb : float or array, optional
        Load capacity factor k: 1 balls, 2 rollers [-]

    Returns
    -------
    numpy.ndarray
        Stage volume per unit load torque W/M [mm³/(N·m)]

    Notes
    -----
    Valid for q > 6.45 (a bore, eq. (14)); fig. 1 of the seed spans q = 7…40.
    """
    q = np.asarray(q, dtype=float)
    n = np.asarray(rows, dtype=float)
    a = _a(q)
    return (
        241.0
        * np.pi
        / 4.0
        * (1.2 * n + 1.8)
        / (n * np.asarray(k_rb) * (q - 1.0))
        * np.sin(np.pi / (q - 1.0))
        * ((a + 1.8) ** 2 - (a - 4.4) ** 2)
    )


def rows_for_diameter(
    torque_Nm: ArrayLike, q: ArrayLike, max_outer_diameter_mm: ArrayLike, k_rb: ArrayLike = 1.0
) -> np.ndarray:
    """Rows needed to fit a given outer diameter (the inequality after eq. (19), seed 000):

    n_p ≥ 241·M / (D³·k·(q − 1))·sin(π/(q − 1))·(2.06/sin(π/q) + 1.8)³  — returned unrounded.

    Parameters
    ----------
    torque_Nm : float or array
        Torque the stage delivers M [N·m]
    q : float or array
        Stage ratio [-]
    max_outer_diameter_mm : float or array
        Outer diameter allowed D [mm]
    k_rb : float or array, optional
        Load capacity factor k: 1 balls, 2 rollers [-]

    Returns
    -------
    numpy.ndarray
        Rows needed n_p, unrounded [-]
    """
    q = np.asarray(q, dtype=float)
    return (
        241.0
        * np.asarray(torque_Nm, dtype=float)
        / (np.asarray(max_outer_diameter_mm, dtype=float) ** 3 * np.asarray(k_rb) * (q - 1.0))
        * np.sin(np.pi / (q - 1.0))
        * (_a(q) + 1.8) ** 3
    )


def equal_diameter_length(output_length_mm: ArrayLike, ratio_to_output: ArrayLike) -> np.ndarray:
    """Length of a stage in the equal-diameter layout, seed 000 after eq. (19):
    L2 = L_out·∛(1/q_out), L3 = L_out·∛(1/(q_out·q2)), … — ``ratio_to_output`` is the product
    of the ratios between the stage and the output (1 for the output stage itself).

    Parameters
    ----------
    output_length_mm : float or array
        Length of the output stage L_out [mm]
    ratio_to_output : float or array
        Product of the ratios between the stage and the output [-]

    Returns
    -------
    numpy.ndarray
        Length of the stage [mm]
    """
    return np.asarray(output_length_mm, dtype=float) * np.cbrt(
        1.0 / np.asarray(ratio_to_output, dtype=float)
    )


def mass_kg(volume_mm3: ArrayLike, density_kg_m3: float, fill_factor: float) -> np.ndarray:
    """m = ρ·k_з·W  (W in mm³ → m³). Seed 000, eq. (19).

    Parameters
    ----------
    volume_mm3 : float or array
        Volume W [mm³]
    density_kg_m3 : float
        Density of the material ρ [kg/m³]
    fill_factor : float
        Fill factor k_з, 0.7…0.8 in the seed [-]

    Returns
    -------
    numpy.ndarray
        Mass m [kg]
    """
    return density_kg_m3 * fill_factor * np.asarray(volume_mm3, dtype=float) * 1e-9


def reducer_volume_eq17(output_volume_mm3: ArrayLike, ratios_out_to_in: list) -> np.ndarray:
    """W_ред = W_вых·(1 + 1/q_вых + 1/(q_вых·q2) + …)  [mm³]. Seed 000, eq. (17).

    Each stage after the output carries the torque divided by the ratios between it and the
    output (losses neglected, as in the seed) and, with the same q and rows, a volume in
    proportion (W ∝ M by eq. (18)).

    Parameters
    ----------
    output_volume_mm3 : float or array
        Volume of the output stage W_вых [mm³]
    ratios_out_to_in : list of float
        Stage ratios from the output towards the motor [-]

    Returns
    -------
    numpy.ndarray
        Volume of the reducer W_ред [mm³]
    """
    factor = 1.0
    downstream = 1.0
    for q in ratios_out_to_in[:-1]:
        downstream = downstream * np.asarray(q, dtype=float)
        factor = factor + 1.0 / downstream
    return np.asarray(output_volume_mm3, dtype=float) * factor
