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
    """n₀ = 60·f / p  [rpm].

    >>> synchronous_speed_rpm(50, 2)
    1500.0
    """
    return 60.0 * supply_frequency_Hz / pole_pairs


def rated_torque(rated_power_W: float, rated_speed_rpm: float) -> float:
    """M_n = P / ω  [N·m].

    >>> round(rated_torque(750, 1390), 3)
    5.152
    """
    return rated_power_W / (rated_speed_rpm * math.pi / 30.0)


def kloss_simple_critical_slip(rated_slip: float, overload_ratio: float) -> float:
    """s_k of the simple Kloss formula, s_k = s_n·(λ + √(λ² − 1)) [2].

    (Code on the web often writes λ − √…; that root is the slip *below* s_n on the same curve.)

    >>> round(kloss_simple_critical_slip(0.05, 2.2), 4)
    0.208
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
        """M(s) = 2·M_k·(1 + ε) / (s/s_k + s_k/s + 2ε); M(0) = 0 [3].

        Scalar on purpose: a characteristic is 41 points, and the linear batch path stays
        free of numpy's import time.
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

    def stable_slip(self, load_torque_Nm: float) -> float | None:
        """Slip of the steady working point under a load torque, on the stable branch
        (s < s_k); ``None`` when the load exceeds the maximum torque (the motor stalls).

        With x = s/s_k the curve gives x + 1/x = C, C = 2·M_k(1+ε)/M − 2ε, a quadratic whose
        smaller root is the stable point.
        """
        if load_torque_Nm <= 0:
            return 0.0
        if load_torque_Nm > self.max_torque_Nm:
            return None
        c = 2.0 * self.max_torque_Nm * (1.0 + self.epsilon) / load_torque_Nm - 2.0 * self.epsilon
        x = (c - math.sqrt(max(c * c - 4.0, 0.0))) / 2.0
        return x * self.critical_slip


def fit_kloss(
    rated_torque_Nm: float,
    rated_slip: float,
    overload_ratio: float,
    starting_ratio: float,
) -> KlossCurve:
    """Fit the refined Kloss curve to the catalog's M_n, s_n, λ = M_k/M_n and μ = M_st/M_n.

    From M(s_n) = M_n: s_n/s_k + s_k/s_n = 2λ(1+ε) − 2ε, which gives s_k(ε) in closed form;
    M(1) = M_st then fixes ε (one monotone equation, solved by bisection). When μ = λ the
    maximum is at standstill: s_k = 1 and ε follows in closed form.

    Hand check with the 4A80B4 row (1.5 kW, 1415 rpm, λ = 2.2, μ = 2.0): the fitted curve
    passes through its three points.

    >>> c = fit_kloss(10.123, 1 - 1415 / 1500, 2.2, 2.0)
    >>> round(c.torque(1 - 1415 / 1500), 3), round(c.torque(1.0), 3)
    (10.123, 20.246)
    """
    lam, mu, sn = overload_ratio, starting_ratio, rated_slip
    if not (0.0 < sn < 1.0):
        raise ValueError(f"rated slip must be in (0, 1), got {sn}")
    if lam <= 1.0:
        raise ValueError(f"breakdown torque ratio must exceed 1, got {lam}")
    if not (0.0 < mu <= lam):
        raise ValueError(f"starting torque ratio must be in (0, {lam}], got {mu}")
    mk = lam * rated_torque_Nm

    def critical_slip(eps: float) -> float:
        a = 2.0 * lam * (1.0 + eps) - 2.0 * eps
        return sn * (a + math.sqrt(a * a - 4.0)) / 2.0

    if math.isclose(mu, lam, rel_tol=1e-9):
        eps = (sn + 1.0 / sn - 2.0 * lam) / (2.0 * (lam - 1.0))
        return KlossCurve(mk, 1.0, eps)

    def residual(eps: float) -> float:
        sk = critical_slip(eps)
        b = 2.0 * (lam / mu) * (1.0 + eps) - 2.0 * eps
        return 1.0 / sk + sk - b

    lo, hi = -1.0 + 1e-9, 1.0
    while residual(hi) > 0 and hi < 1e6:
        hi *= 4.0
    try:
        eps = bisect(residual, lo, hi)
    except ValueError as exc:
        raise ValueError(
            f"no refined Kloss curve passes through s_n = {sn:.4f}, Mmax/Mn = {lam}, Mst/Mn = {mu}"
        ) from exc
    sk = critical_slip(eps)
    if sk >= 1.0:
        raise ValueError(
            f"the catalog points s_n = {sn:.4f}, Mmax/Mn = {lam}, Mst/Mn = {mu} put the "
            f"maximum torque beyond standstill (s_k = {sk:.3f})"
        )
    return KlossCurve(mk, sk, eps)


def curve_slips(points: int = 41) -> list[float]:
    """Slips at which a characteristic is tabulated for the report: denser near s = 0, where
    the working points lie."""
    return [(i / (points - 1)) ** 1.5 for i in range(points)]
