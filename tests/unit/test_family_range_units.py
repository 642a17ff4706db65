"""A family range takes its ends as quantity strings, as a list axis takes its values:
``{ from = "100 N*m", to = "2 kN*m", steps = 4, scale = "log" }`` is the range from 100 to
2000 N·m; an end that is no quantity of the key's unit is refused naming that unit."""

import pytest

from advisor.core.errors import InputError
from advisor.family.spec import axis_values

KEY = "rotary.torque_Nm"


def test_a_range_of_quantity_strings_is_the_plain_range():
    typed = axis_values(KEY, {"from": "100 N*m", "to": "2 kN*m", "steps": 4, "scale": "log"})
    plain = axis_values(KEY, {"from": 100, "to": 2000, "steps": 4, "scale": "log"})
    assert typed == plain
    # by hand: 100 · 20^(k/3), k = 0 … 3, to six significant digits
    assert typed.values == pytest.approx((100, 271.442, 736.806, 2000), rel=1e-6)


def test_an_end_of_another_kind_is_refused_naming_the_unit():
    with pytest.raises(InputError) as err:
        axis_values(KEY, {"from": "100 N*m", "to": "2 m", "steps": 4})
    said = str(err.value)
    assert "from = '100 N*m', to = '2 m': must be finite numbers, or quantities in N·m" in said
