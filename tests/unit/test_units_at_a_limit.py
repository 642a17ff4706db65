"""A speed typed at a catalog limit in rpm meets that limit, as the plain number does.

40000 rpm = 40000·2π/60 rad/s = 4188.790204786391 rad/s (the float of the product). Rounded
to 12 significant digits, as the reader once did, it was 4188.79020479 rad/s = 40000.0000000345
rpm: a 6000 bearing (limiting speed 40000 rpm, SKF General Catalogue) was refused at its own
limit, margin 0.99999999999914. Back from rad/s a speed also lands a unit in the last place
above its rpm figure (22000 rpm → 22000.000000000004), which the rotor's speed check absorbs
by taking the rpm to 12 significant digits."""

import copy
import math
import tomllib

import pytest
from helpers import EXAMPLES

from advisor.core.engine import advise
from advisor.core.reading import parse_requirements
from advisor.core.units import to_unit
from catalogs import load_catalogs


def test_rpm_converts_to_the_float_of_the_product():
    assert to_unit("40000 rpm", "rad/s") == 40000 * (math.pi / 30)
    assert to_unit("40000 rpm", "rad/s") == pytest.approx(4188.790204786391, rel=1e-15)
    # a decimal conversion still reads as typed
    assert to_unit("200 mm", "m") == 0.2
    assert to_unit("1.62 kN*m", "N·m") == 1620.0


def _rotor(speed, bearing: str) -> dict:
    doc = tomllib.loads((EXAMPLES / "gyro_compensator.toml").read_text(encoding="utf-8"))
    doc = copy.deepcopy(doc)
    doc["rotor"]["speed_rad_s"] = speed
    doc["rotor"]["bearing"] = bearing
    doc["rotor"].pop("bearing_choice", None)
    return doc


@pytest.mark.parametrize(
    "bearing", [b.designation for b in load_catalogs().bearings if b.limiting_speed_rpm]
)
def test_every_bearing_runs_at_its_own_limit(bearing):
    """Each shipped bearing at exactly its limiting speed, typed in rpm and as its rad/s:
    the speed check passes with margin 1 (20 of 35 were refused in rpm, 5 in rad/s)."""
    lim = next(b.limiting_speed_rpm for b in load_catalogs().bearings if b.designation == bearing)
    for speed in (f"{lim:g} rpm", lim * math.pi / 30):
        try:
            rep = advise(parse_requirements(_rotor(speed, bearing)))
        except Exception as exc:  # another check may refuse the design: not this one's
            assert "limiting speed" not in str(exc), exc
            continue
        check = next(c for c in rep.checks if c.id == "bearing_speed")
        assert check.value == lim and check.margin == 1.0 and check.passed
