"""The linear actuator's holding with the power off, as checks (seed 004): the one-way
device's capacity against the torque the standing load gives it through the screw, or the
screw's own self-locking where it holds the load itself (:mod:`advisor.one_way.holding`)."""

from advisor.calc import screw as screw_calc
from advisor.calc.checks import Check
from advisor.calc.one_way import screw_back_driving_torque
from advisor.calc.service_factor import service_factor
from advisor.calc.sizing import ThreadEvaluation
from advisor.one_way.holding import device_checks, screw_self_locking_check
from rules.one_way import SEED_004
from rules.screw import SEED_001


def holding_checks(req, ev: ThreadEvaluation, device, thread: str, friction_low: float):
    """What holds the load with the power off, checked: the screw's ψ/φ' at the low end of
    the friction range where it is self-locking (``device.type`` "none"); otherwise the
    device's capacity (``device.torque_Nm``, the torque it is sized for) against the
    back-driving torque F·d2/2·tan(ψ − φ') at that friction (the standard reduced friction,
    as the holding judgement takes it; the thrust face's friction, which would help, left
    out), at the rated force or, if larger, the emergency stop's, × f_B — and a gear's
    self-locking."""
    psi = ev.lead_angle_rad
    phi_low = screw_calc.friction_angle(friction_low, "standard", psi)
    if device.type == "none":
        return [screw_self_locking_check(thread, psi, phi_low, friction_low, SEED_001 + SEED_004)]
    lin = req.linear
    force = max(lin.force_N, lin.emergency_stop_force_N or 0.0)
    held = screw_back_driving_torque(force, ev.thread.d2_mm * 1e-3, psi, phi_low)
    how = (
        f"the back-driving torque of {thread}, F·d2/2·tan(ψ − φ') at F = {force:g} N and "
        f"f = {friction_low:g}"
    )
    checks: list[Check] = device_checks(
        device.type, device.torque_Nm, held, service_factor(req.design).value, how
    )
    return checks
