"""Cage induction motor: synchronous speed and the torque–slip characteristic M(s).

References
----------
[1] Seed 001 (001_085658f38eaaea54.txt): motor chosen from the screw speed and torque; the
    M(s) characteristics of the chosen motor and its neighbours (fig. 4).
[2] Kloss formula, M(s) = 2·M_k / (s/s_k + s_k/s), s_k = s_n·(λ + √(λ² − 1)), λ = M_k/M_n
    (any electric-drive text, e.g. Chilikin, «Общий курс электропривода»).
[3] Refined Kloss formula, M(s) = 2·M_k·(1 + ε) / (s/s_k + s_k/s + 2ε), ε = a·s_k with
    a ≈ R1/R2' (same texts). Its extra parameter lets the curve pass through the catalog's
    starting torque, which the simple form misses by a factor of 3…5 for cage motors.
"""

import math
from typing import NamedTuple

from advisor.calc.roots import bisect


def synchronous_speed_rpm(supply_frequency_Hz: float, pole_pairs: int) -> float:
    """Synchronous speed of an induction motor.

    n₀ = 60·f / p

    Parameters
    ----------
    supply_frequency_Hz : float
        Supply frequency f [Hz]
    pole_pairs : int
        Number of pole pairs p [-]

    Returns
    -------
    speed_rpm : float
        Synchronous speed n₀ [rpm]

    Examples
    --------
    >>> synchronous_speed_rpm(50, 2)
    1500.0

    References
    ----------
    Seed 001: the screw speed fixes the pole pairs, n₀ > n [1].
    """
    return 60.0 * supply_frequency_Hz / pole_pairs


def rated_torque(rated_power_W: float, rated_speed_rpm: float) -> float:
    """Rated torque of a motor from its rated power and speed.

    M_n = P / ω,  ω = π·n/30

    Parameters
    ----------
    rated_power_W : float
        Rated (shaft) power P [W]
    rated_speed_rpm : float
        Rated speed n [rpm]

    Returns
    -------
    torque_Nm : float
        Rated torque M_n [N·m]

    Examples
    --------
    The 4A71B4 of seed 001 (0.75 kW, 1390 rpm):

    >>> round(rated_torque(750, 1390), 3)
    5.152

    References
    ----------
    Seed 001, the motor choice by rated power [1].
    """
    return rated_power_W / (rated_speed_rpm * math.pi / 30.0)


def kloss_simple_critical_slip(rated_slip: float, overload_ratio: float) -> float:
    """Critical slip of the simple Kloss formula.

    s_k = s_n·(λ + √(λ² − 1)),  λ = M_k/M_n

    Parameters
    ----------
    rated_slip : float
        Rated slip s_n [-]
    overload_ratio : float
        Breakdown torque over rated torque λ [-], above 1

    Returns
    -------
    slip : float
        Critical slip s_k [-]

    Notes
    -----
    Code on the web often writes λ − √…; that root is the slip *below* s_n on the same
    curve. The simple form misses a cage motor's starting torque; see :func:`fit_kloss`.

    Examples
    --------
    >>> round(kloss_simple_critical_slip(0.05, 2.2), 4)
    0.208

    References
    ----------
    Kloss formula [2].
    """
    return rated_slip * (overload_ratio + math.sqrt(overload_ratio**2 - 1.0))


class KlossCurve(NamedTuple):
    """Refined Kloss characteristic fitted to three catalog points.

    ``M(s_n) = M_n``, ``M(s_k) = M_k`` (its maximum) and ``M(1) = M_start``.
    """

    max_torque_Nm: float
    critical_slip: float
    epsilon: float

    def torque(self, slip: float) -> float:
        """Torque of the refined Kloss characteristic at a slip.

        M(s) = 2·M_k·(1 + ε) / (s/s_k + s_k/s + 2ε),  M(0) = 0

        Parameters
        ----------
        slip : float
            Slip s [-], 0 at synchronous speed, 1 at standstill

        Returns
        -------
        torque_Nm : float
            Motor torque M(s) [N·m]

        Notes
        -----
        Scalar on purpose: a characteristic is 41 points, and the linear batch path stays free
        of numpy's import time. Valid for 0 ≤ s ≤ 1 (motoring).

        Examples
        --------
        >>> c = KlossCurve(22.27, 0.2, 0.1)
        >>> round(c.torque(0.2), 2)
        22.27

        References
        ----------
        Refined Kloss formula [3].
        """
        if slip <= 0.0:
            return 0.0
        sk = self.critical_slip
        return (
            2.0
            * self.max_torque_Nm
            * (1.0 + self.epsilon)
            / (slip / sk + sk / slip + 2.0 * self.epsilon)
        )

    def mean_torque(self, slip_from: float, slip_to: float, intervals: int = 64) -> float:
        """Mean torque of the refined Kloss characteristic between two slips, by Simpson's
        rule.

        M_m = 1/(b − a) · h/3 · [M(a) + 4·M(a + h) + 2·M(a + 2h) + … + M(b)],  h = (b − a)/N

        Parameters
        ----------
        slip_from : float
            Slip a [-] where the mean starts (the working slip of a start)
        slip_to : float
            Slip b [-] where it ends, b > a (1: standstill)
        intervals : int, optional
            Number of Simpson intervals N [-], even

        Returns
        -------
        torque_Nm : float
            Mean motor torque M_m over [a, b] [N·m]

        Notes
        -----
        The torque is :meth:`torque`'s expression written out in the loop, with its constant
        factors computed once: the same floats, about three times faster (a duty cycle asks
        this mean of every motor it tries, for every move).

        Examples
        --------
        >>> c = KlossCurve(22.27, 0.2, 0.1)
        >>> round(c.mean_torque(0.05, 1.0), 2)
        15.37

        References
        ----------
        The mean starting torque of a direct-on-line start (Chilikin, «Общий курс
        электропривода», ch. 2) on the refined Kloss formula [3].
        """
        a, b, n = slip_from, slip_to, intervals
        h = (b - a) / n
        sk = self.critical_slip
        top = 2.0 * self.max_torque_Nm * (1.0 + self.epsilon)
        two_eps = 2.0 * self.epsilon
        total = self.torque(a) + self.torque(b)
        for k in range(1, n):
            s = a + k * h  # > 0: a ≥ 0 and h > 0
            total += (4 if k % 2 else 2) * (top / (s / sk + sk / s + two_eps))
        return total * h / 3.0 / (b - a)

    def stable_slip(self, load_torque_Nm: float) -> float | None:
        """Slip of the steady working point under a load torque, on the stable branch.

        x + 1/x = C,  C = 2·M_k·(1 + ε)/M − 2ε,  s = x·s_k (the smaller root)

        Parameters
        ----------
        load_torque_Nm : float
            Load torque at the motor M [N·m]

        Returns
        -------
        slip : float or None
            Working slip s < s_k [-]; 0 for no load; ``None`` when the load exceeds the maximum
            torque (the motor stalls)

        Examples
        --------
        >>> c = KlossCurve(22.27, 0.2, 0.1)
        >>> round(c.stable_slip(c.torque(0.05)), 6)
        0.05

        References
        ----------
        Refined Kloss formula [3], solved for s.
        """
        if load_torque_Nm <= 0:
            return 0.0
        if load_torque_Nm > self.max_torque_Nm:
            return None
        c = 2.0 * self.max_torque_Nm * (1.0 + self.epsilon) / load_torque_Nm - 2.0 * self.epsilon
        d = c * c - 4.0  # ≥ 0 but for rounding at the maximum; max(d, 0.0) written out (faster)
        x = (c - math.sqrt(0.0 if d < 0.0 else d)) / 2.0
        return x * self.critical_slip


def _check_ratings(rated_slip: float, overload_ratio: float, starting_ratio: float) -> None:
    """The catalog ratings a refined Kloss curve can pass through: 0 < s_n < 1, λ > 1,
    0 < μ ≤ λ; a ValueError names the first one outside."""
    lam, mu, sn = overload_ratio, starting_ratio, rated_slip
    if not (0.0 < sn < 1.0):
        raise ValueError(f"rated slip must be in (0, 1), got {sn}")
    if lam <= 1.0:
        raise ValueError(f"breakdown torque ratio must exceed 1, got {lam}")
    if not (0.0 < mu <= lam):
        raise ValueError(f"starting torque ratio must be in (0, {lam}], got {mu}")


def _critical_slip(eps: float, rated_slip: float, overload_ratio: float) -> float:
    """s_k of the refined curve through M(s_n) = M_n, for a given ε: the larger root of
    s_n/s_k + s_k/s_n = 2λ(1 + ε) − 2ε."""
    a = 2.0 * overload_ratio * (1.0 + eps) - 2.0 * eps
    return rated_slip * (a + math.sqrt(a * a - 4.0)) / 2.0


def _fitted_epsilon(rated_slip: float, overload_ratio: float, starting_ratio: float) -> float:
    """ε of the refined curve that also passes through M(1) = M_st (bisection)."""
    lam, mu, sn = overload_ratio, starting_ratio, rated_slip

    def residual(eps: float) -> float:
        sk = _critical_slip(eps, sn, lam)
        b = 2.0 * (lam / mu) * (1.0 + eps) - 2.0 * eps
        return 1.0 / sk + sk - b

    lo, hi = -1.0 + 1e-9, 1.0
    while residual(hi) > 0 and hi < 1e6:
        hi *= 4.0
    try:
        return bisect(residual, lo, hi)
    except ValueError as exc:
        raise ValueError(
            f"no refined Kloss curve passes through s_n = {sn:.4f}, Mmax/Mn = {lam}, Mst/Mn = {mu}"
        ) from exc


def fit_kloss(
    rated_torque_Nm: float,
    rated_slip: float,
    overload_ratio: float,
    starting_ratio: float,
) -> KlossCurve:
    """Fit the refined Kloss curve to a motor's catalog ratings.

    M(s_n) = M_n:  s_n/s_k + s_k/s_n = 2λ(1 + ε) − 2ε  → s_k(ε) in closed form
    M(1) = M_st:   fixes ε (one monotone equation, solved by bisection)

    Parameters
    ----------
    rated_torque_Nm : float
        Rated torque M_n [N·m]
    rated_slip : float
        Rated slip s_n [-], in (0, 1)
    overload_ratio : float
        Breakdown torque over rated torque λ = M_k/M_n [-], above 1
    starting_ratio : float
        Starting torque over rated torque μ = M_st/M_n [-], in (0, λ]

    Returns
    -------
    curve : KlossCurve
        Maximum torque M_k [N·m], critical slip s_k [-] and ε [-]

    Notes
    -----
    When μ = λ the maximum is at standstill: s_k = 1 and ε follows in closed form. Raises
    ValueError for ratings no such curve passes through, or that put the maximum beyond
    standstill.

    Examples
    --------
    The 4A80B4 row (1.5 kW, 1415 rpm, λ = 2.2, μ = 2.0) passes through its three points:

    >>> c = fit_kloss(10.123, 1 - 1415 / 1500, 2.2, 2.0)
    >>> round(c.torque(1 - 1415 / 1500), 3), round(c.torque(1.0), 3)
    (10.123, 20.246)

    References
    ----------
    Refined Kloss formula [3]; seed 001's M(s) characteristics, fig. 4 [1].
    """
    lam, mu, sn = overload_ratio, starting_ratio, rated_slip
    _check_ratings(sn, lam, mu)
    mk = lam * rated_torque_Nm
    if math.isclose(mu, lam, rel_tol=1e-9):
        return KlossCurve(mk, 1.0, (sn + 1.0 / sn - 2.0 * lam) / (2.0 * (lam - 1.0)))
    eps = _fitted_epsilon(sn, lam, mu)
    sk = _critical_slip(eps, sn, lam)
    if sk >= 1.0:
        raise ValueError(
            f"the catalog points s_n = {sn:.4f}, Mmax/Mn = {lam}, Mst/Mn = {mu} put the "
            f"maximum torque beyond standstill (s_k = {sk:.3f})"
        )
    return KlossCurve(mk, sk, eps)


def curve_slips(points: int = 41) -> list[float]:
    """Slips at which a characteristic is tabulated for the report.

    s_i = (i/(N − 1))^1.5,  i = 0 … N − 1

    Parameters
    ----------
    points : int, optional
        Number of points N [-]

    Returns
    -------
    slips : list[float]
        Slips from 0 to 1 [-], denser near s = 0, where the working points lie

    Examples
    --------
    >>> curve_slips(3)[1] == 0.5**1.5
    True

    References
    ----------
    Seed 001, fig. 4: the characteristics of the chosen motor and its neighbours [1].
    """
    return [(i / (points - 1)) ** 1.5 for i in range(points)]
