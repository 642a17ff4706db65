"""The chosen motor's plan: its pole pairs, the band of rated powers shown beside it and
their evaluations on the screw's load (rules IM-02, IM-03)."""

import math
from typing import NamedTuple

from advisor.calc.sizing import MotorEvaluation, ThreadEvaluation, evaluate_motor
from advisor.core.rulebook import Trace
from catalogs import Catalogs
from catalogs.rows import InductionMotor
from rules import induction as induction_rules


class MotorPlan(NamedTuple):
    pole_pairs: int
    required_power_kW: float  # load torque × required screw speed
    band_kW: list[float]
    evaluations: dict[float, MotorEvaluation | None]  # by rated power; None: not in catalog
    selected: InductionMotor


def plan_motor(
    ev: ThreadEvaluation, motor: InductionMotor, cat: Catalogs, trace: Trace
) -> MotorPlan:
    """The chosen motor's pole pairs, its rated-power band and the evaluated neighbours."""
    pp = motor.pole_pairs
    # the band shows one motor per rated power; the chosen one must be the one at its power
    # (a user catalog may hold another motor of the same rating and poles)
    line = {m.rated_power_kW: m for m in cat.motors_with_poles(2 * pp)}
    line[motor.rated_power_kW] = motor

    def evaluate(power: float) -> MotorEvaluation | None:
        m = line.get(power)
        return None if m is None else evaluate_motor(m, ev.torque_Nm, ev.speed_rpm, ev.revolutions)

    sel = evaluate(motor.rated_power_kW)
    assert sel is not None and sel.working_speed_rpm is not None
    series = cat.power_series(2 * pp)  # a user motor may be off the GOST series
    p_req_kW = ev.torque_Nm * ev.speed_rpm * math.pi / 30.0 / 1e3
    p_work_kW = ev.torque_Nm * sel.working_speed_rpm * math.pi / 30.0 / 1e3
    band = trace.apply(
        induction_rules.rated_power_band, p_req_kW, p_work_kW, motor.rated_power_kW, series
    )
    evaluations = {power: evaluate(power) for power in band}
    # IM-03 looks at the line from the lower neighbour up to the chosen motor: the joint
    # choice took the first one that drives the screw, so the rule must agree with it.
    options = []
    for m in sorted(line.values(), key=lambda m: m.rated_power_kW):
        if m.rated_power_kW < band[0] or m.rated_power_kW > motor.rated_power_kW:
            continue
        e = evaluations.get(m.rated_power_kW) or evaluate(m.rated_power_kW)
        assert e is not None
        options.append(
            induction_rules.MotorOption(
                m.rated_power_kW, m.model, tuple(e.problems), e.rated_torque_margin
            )
        )
    model = trace.apply(induction_rules.choose_motor, options)
    assert model == motor.model, (model, motor.model)
    return MotorPlan(pp, p_req_kW, band, evaluations, motor)


def motor_evaluation(motor: InductionMotor, ev: ThreadEvaluation) -> MotorEvaluation:
    return evaluate_motor(motor, ev.torque_Nm, ev.speed_rpm, ev.revolutions)
