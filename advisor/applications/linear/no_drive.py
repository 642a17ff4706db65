"""Why no catalog motor drives a thread that passes its checks, where some thread is slow
enough for a motor: the power at the speed a motor would turn the screw, and, where every such
thread needs less than the slowest motor's speed, that speed and a reduction stage."""

import math

from advisor.calc.sizing import ThreadScreen
from catalogs import Catalogs

RAD_S_PER_RPM = math.pi / 30.0


def power_reasons(passing: list[ThreadScreen], cat: Catalogs) -> list[str]:
    """The reasons of the refusal for the threads a catalog motor is fast enough for.

    Coupled directly, the screw turns at a motor's working speed: at least the slowest motor's
    rated speed n_min, and at least the speed the stroke needs, so the power a thread asks is
    P = M·2π·max(n_req, n_min)/60 with M the screw torque at the motor (thrust face and
    holding device included). Where every thread needs less than n_min, the limit is that
    speed, and the motor's rated torque must carry the whole screw torque: that is said, with
    the reduction stage that would remedy it."""
    fastest = max(m.rated_speed_rpm for m in cat.motors)
    slowest = min(m.rated_speed_rpm for m in cat.motors)
    biggest_kw = max(m.rated_power_kW for m in cat.motors)
    reachable = [ev for ev in passing if ev.speed_rpm <= fastest]
    least = min(
        ev.motor_torque_Nm * max(ev.speed_rpm, slowest) * RAD_S_PER_RPM / 1e3 for ev in reachable
    )
    if any(ev.speed_rpm >= slowest for ev in reachable):
        return [
            f"the power needed ({least:.3g} kW or more, at the speed a catalog motor turns the "
            f"screw) exceeds what the catalog's motors give (up to {biggest_kw:g} kW)"
        ]
    need = max(ev.speed_rpm for ev in reachable)
    strongest = max(cat.motors, key=lambda m: m.rated_torque_Nm)
    torque = min(ev.motor_torque_Nm for ev in reachable)
    reasons = [
        f"coupled directly, the screw turns at a motor's speed, at least {slowest:g} rpm (the "
        f"catalog's slowest motor), {slowest / need:.3g} times or more what the threads need; "
        f"there the power is {least:.3g} kW or more, above the catalog's largest "
        f"{biggest_kw:g} kW"
    ]
    if torque > strongest.rated_torque_Nm:
        reasons.append(
            f"the screw torque, {torque:.4g} N·m or more, exceeds the largest rated torque of "
            f"the catalog, {strongest.rated_torque_Nm:.4g} N·m ({strongest.model})"
        )
    reasons.append(
        f"a reduction stage of about {slowest / need:.2g}:1 or more between motor and screw "
        "would bring the motor to the screw's speed and multiply its torque (this advisor "
        "drives the screw directly and does not size one), or a smaller force"
    )
    return reasons
