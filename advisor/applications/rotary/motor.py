"""The PM brushless motor at a working point: its losses, and the limit of its frame.

Rewinding the reference frame for another speed at the same voltage scales the turns and the
torque constant as 1/n and the resistance as 1/n², so at a given torque the copper loss does
not depend on the winding and the current grows as n (seed 000, eqs. (4), (9)). The frame's
limit is thermal: its total losses against what its cooling carries, by default the reference
motor's own total losses at its rated point. Helpers of
:mod:`advisor.applications.rotary.advice`; the physics is in :mod:`advisor.calc.bldc`, the rule
in :mod:`rules.bldc`.
"""

import math
from typing import Any, NamedTuple

from advisor.calc import bldc
from advisor.calc.checks import Check
from advisor.core.cite import Cite
from advisor.core.errors import InfeasibleError
from rules import bldc as bldc_rules


def specific_iron_loss(ref, steel, terms, f: float) -> tuple[float, float]:
    """Specific iron loss at f by the model in use, and by the three-term eq. (5) beside it."""
    spec_quad = (
        bldc.iron_specific_loss_quadratic(steel.p15_50_W_kg, f) * (ref.induction_T / 1.5) ** 2
    )
    spec_three = terms.specific_loss(f, ref.induction_T)
    return (spec_quad if ref.iron_loss_model == "quadratic" else spec_three), spec_three


class Losses(NamedTuple):
    """The losses of the motor at a working point [W]: the fields of the report's
    ``losses_W`` table, in its order."""

    ohmic: float
    iron: float
    magnets: float
    total: float


def losses_at(ref, iron_W: float, n: float, torque: float) -> Losses:
    """Losses of the frame wound for speed n at a motor torque, seed 000 eqs. (4), (5), (9):
    the copper loss depends on the torque alone, whatever the winding."""
    ohmic_ref = ref.conducting_phases * ref.phase_resistance_ohm * ref.current_A**2
    ohmic = bldc.ohmic_loss_at_torque(ohmic_ref, ref.torque_Nm, torque)
    magnets = bldc.magnet_loss([(p.speed_rpm, p.loss_W) for p in ref.magnet_losses], n)
    total = ohmic + iron_W + magnets
    return Losses(float(ohmic), float(iron_W), float(magnets), float(total))


def loss_limit(mot: Any, steel, steel_mass: float, terms, ref: Any = None) -> tuple[float, str]:
    """What the frame's cooling carries: the requirement's own figure, or the frame's own
    total losses at its rated point (same frame, same cooling): the reference motor's, or a
    scaled frame's or a catalog motor's."""
    if mot.max_losses_W is not None:
        return mot.max_losses_W, f"the requirement's motor.max_losses_W = {mot.max_losses_W:g} W"
    ref = ref if ref is not None else mot.reference
    spec, _ = specific_iron_loss(
        ref, steel, terms, bldc.flux_frequency_Hz(ref.speed_rpm, ref.pole_pairs)
    )
    total = losses_at(ref, steel_mass * spec, ref.speed_rpm, ref.torque_Nm).total
    kind = getattr(ref, "kind", None)
    if kind == "catalog":
        return total, (
            f"{ref.name}'s copper loss at its continuous {ref.torque_Nm:g} N·m "
            f"({ref.current_A:.4g} A, datasheet): {total:.4g} W; its datasheet rates it up to "
            f"{ref.speed_rpm:g} rpm and states no core losses"
        )
    if kind == "scaled":
        return total, (
            f"frame {ref.name}'s own total losses at its rated point ({ref.speed_rpm:.5g} rpm, "
            f"{ref.torque_Nm:.5g} N·m at {ref.current_A:.4g} A): {total:.4g} W, same frame, "
            "same cooling"
        )
    return total, (
        f"the reference motor's total losses at its rated point ({ref.speed_rpm:g} rpm, "
        f"{ref.torque_Nm:g} N·m at {ref.current_A:g} A): {total:.4g} W, same frame, same cooling"
    )


def above_rated(cands: list, ref: Any) -> InfeasibleError:
    """A catalog motor none of whose candidate speeds lies within its rated speed."""
    speeds = ", ".join(f"{c.speed_rpm:g}" for c in cands)
    return InfeasibleError(
        f"no feasible design: {ref.name} is rated up to {ref.speed_rpm:g} rpm",
        [
            f"the candidate speeds within its loss limit ({speeds} rpm) lie above its rated "
            f"{ref.speed_rpm:g} rpm; its datasheet gives no losses there"
        ],
    )


def _w(x: float) -> str:
    """A power in W as an engineer writes it: four figures, no exponent."""
    return f"{x:.4g}" if abs(x) < 1e4 else f"{x:.0f}"


def too_lossy(cands: list, limit: float, basis: str, n_opt: float) -> InfeasibleError:
    """No candidate speed within the frame's limit: the three least lossy, in numbers.
    ``cands``: :class:`~advisor.applications.rotary.candidates.SpeedCandidate` records."""
    shown = sorted(cands, key=lambda c: c.losses_W.total)[:3]
    reasons = [
        f"at {c.speed_rpm:g} rpm the reducer (q = {c.total_ratio:.4g}, "
        f"η = {c.gearbox_efficiency:.3g}) asks {c.torque_Nm:.3g} N·m of the motor "
        f"({c.current_A:.3g} A): losses {_w(c.losses_W.total)} W (ohmic "
        f"{_w(c.losses_W.ohmic)}, iron {_w(c.losses_W.iron)}, magnets "
        f"{_w(c.losses_W.magnets)}) against the limit {_w(limit)} W"
        for c in shown
    ]
    if len(cands) > len(shown):
        reasons.append(f"and {len(cands) - len(shown)} more candidate speeds, lossier still")
    reasons.append(
        f"the limit is {basis}; give a larger frame in [motor.reference], motor.max_losses_W "
        "for a better cooling, or a lower rotary.torque_Nm"
        + (f" (eq. (10): least loss near {n_opt:.0f} rpm)" if math.isfinite(n_opt) else "")
    )
    return InfeasibleError(
        "no feasible design: the motor's losses exceed what its frame's cooling carries", reasons
    )


def losses_check(id: str, name: str, losses_W: float, limit_W: float, source: Cite) -> Check:
    """Losses against the frame's limit with the stated allowance
    (:data:`rules.bldc.LIMIT_REL_TOL`): the check carries the limit it really applies, so its
    margin and its verdict agree, and its name states the frame's own figure."""
    allowed_W = limit_W * (1.0 + bldc_rules.LIMIT_REL_TOL)
    margin = allowed_W / losses_W if losses_W > 0 else math.inf
    name = f"{name} ({limit_W:.5g} W + {bldc_rules.LIMIT_REL_TOL:.1%} allowance)"
    return Check(id, name, losses_W, allowed_W, "W", margin, source)
