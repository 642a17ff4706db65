"""The positioning duty's cycle figures computed without phases equal, to the last bit, those
of the phases the report shows (:func:`cycle` and :func:`rms_torque`)."""

import math
import random

from advisor.applications.positioning.duty import cycle, move_and_rms
from advisor.calc.duty import rms_torque
from advisor.calc.motion import Drive


def _from_phases(
    d: Drive, path: float, i: float, t_cycle: float, beta0: float = 1.0
) -> tuple[float, float]:
    ph = cycle(d, path, i, t_cycle)
    if ph is None:
        return math.inf, math.inf
    move = sum(p.time_s for p in ph if p.name != "rest")
    return move, rms_torque(ph, beta0) if move <= t_cycle else math.inf


def test_move_and_rms_bit_identical_to_the_phases():
    rng = random.Random(3)
    for _ in range(20000):
        d = Drive(
            speed_rad_s=10 ** rng.uniform(0, 3),
            inertia_kgm2=10 ** rng.uniform(-4, -1),
            accel_torque_Nm=10 ** rng.uniform(0, 2),
            load_inertia_kgm2=10 ** rng.uniform(-1, 1),
            load_torque_Nm=10 ** rng.uniform(0, 3),
        )
        path, i, t_cycle = (
            10 ** rng.uniform(-1, 2),
            10 ** rng.uniform(0, 3),
            10 ** rng.uniform(-1, 1),
        )
        assert move_and_rms(d, path, i, t_cycle) == _from_phases(d, path, i, t_cycle)
        # a catalog motor's equivalent torque, cooled by β0 = 0.5 at rest, 0.75 in the ramps
        got = move_and_rms(d, path, i, t_cycle, 0.5)
        assert got == _from_phases(d, path, i, t_cycle, 0.5)
