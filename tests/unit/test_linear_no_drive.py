"""The linear refusal where the threads that pass are slower than any catalog motor: it names
the speed a motor turns the screw, the power and torque there, and a reduction stage."""

import math

import pytest

from advisor.core.engine import advise
from advisor.core.errors import InfeasibleError
from advisor.core.reading import parse_requirements

SIXTY_KN = {
    "application": {"kind": "linear"},
    "linear": {"force_N": 60000, "stroke_m": 0.3, "travel_time_s": 10, "support_span_m": 0.5},
    "motor": {"kind": "induction"},
}


def _reasons(data) -> str:
    with pytest.raises(InfeasibleError) as err:
        advise(parse_requirements(data))
    return "\n".join(err.value.reasons)


def test_sixty_kN_in_ten_seconds_is_refused_for_speed_not_power():
    """60 kN, 0.3 m in 10 s: the passing threads need 22.5 … 225 rpm; the slowest catalog
    motor runs at 675 rpm (8-pole 4A).

    The least screw torque, Tr52x8 (d2 = 48 mm, P = 8): ψ = atan(8/(π·48)) = 3.037°,
    φ' = atan(0.13/cos 15°) = 7.665°, M = F·d2/2·tan(ψ + φ') = 60000·0.024·tan(10.702°) =
    272.1 N·m; at 675 rpm P = 272.1·675·π/30 = 19.23 kW > 15 kW (the largest motor);
    the largest rated torque, 4A180M8: 15000/(730·π/30) = 196.2 N·m < 272.1. Before, the
    reason was the power at the required speed, '2.6 kW or more … up to 15 kW', which
    contradicted itself."""
    psi = math.atan(8.0 / (math.pi * 48.0))
    phi = math.atan(0.13 / math.cos(math.radians(15.0)))
    torque = 60000.0 * 0.024 * math.tan(psi + phi)
    assert torque == pytest.approx(272.1, abs=0.05)
    power_kW = torque * 675.0 * math.pi / 30.0 / 1e3
    assert power_kW == pytest.approx(19.23, abs=0.01)
    rated = 15000.0 / (730.0 * math.pi / 30.0)
    text = _reasons(SIXTY_KN)
    assert "22.5 … 225 rpm" in text
    assert "at least 675 rpm (the catalog's slowest motor), 3 times or more" in text
    assert f"the power is {power_kW:.3g} kW or more, above the catalog's largest 15 kW" in text
    assert f"the screw torque, {torque:.4g} N·m or more" in text
    assert f"the largest rated torque of the catalog, {rated:.4g} N·m (4A180M8)" in text
    assert "a reduction stage of about 3:1 or more" in text  # 675/225
    assert "2.6 kW" not in text


def test_where_a_motor_is_fast_enough_the_power_is_at_the_motor_speed():
    """In 3.2 s the threads need 70.3 … 703 rpm: some reach a motor's speed, and the power
    stated is at the speed a motor turns the screw (above 15 kW), not the 8.13 kW at the
    required speed that contradicted 'up to 15 kW'."""
    data = {**SIXTY_KN, "linear": {**SIXTY_KN["linear"], "travel_time_s": 3.2}}
    text = _reasons(data)
    assert "at the speed a catalog motor turns the screw" in text
    least = float(text.split("the power needed (")[1].split(" kW")[0])
    assert least > 15.0
