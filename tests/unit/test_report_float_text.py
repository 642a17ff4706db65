"""The TOML report rounds its numbers as it writes them (report.float_text): the same text as
rounding them first (round_sig) and writing them as tomli-w does (repr)."""

import math
import random

import pytest
from helpers import EXAMPLES

from advisor.core import toml_text
from advisor.core.engine import advise
from advisor.core.reading import read_requirements
from advisor.core.report import archive, float_text, plain_data, round_sig, to_toml


def _values() -> list[float]:
    rng = random.Random(29)
    out = [rng.uniform(-1.0, 1.0) * 10 ** rng.uniform(-12, 20) for _ in range(50_000)]
    for k in range(-20, 21):  # around every power of ten, and the ties of the sixth digit
        p = 10.0**k
        out += [p, -p, math.nextafter(p, 0.0), math.nextafter(p, math.inf)]
        out += [p * (1 - 1e-7), p * (1 + 1e-7), 9.999995 * p, 9.9999949999 * p, 1.234565 * p]
    return [*out, 0.0, -0.0, 5.0, 100000.0, 999999.5, 1e16, 1.5e-5, 2.5, 123456789012345678.0]


def test_float_text_is_the_rounded_number_as_repr_writes_it():
    for x in _values():
        assert float_text(x) == repr(round_sig(x)), x


@pytest.mark.parametrize("example", sorted(EXAMPLES.glob("*.toml")), ids=lambda p: p.name)
def test_to_toml_is_the_rounded_report_as_tomli_w_writes_it(example):
    report = advise(read_requirements(example))
    assert to_toml(report) == toml_text.dumps(archive(plain_data(report)))


def test_floats_text_writes_an_array_as_float_text_writes_each_number():
    """The whole-array formatting (one call for a curve) against float_text, item by item:
    around every power of ten, the ties, subnormals, signed zeros and large whole numbers."""
    from advisor.core.report import floats_text

    values = [*_values(), 5e-324, -5e-324, 2.2250738585072014e-308, 1e300, -1e-300]
    sep = ",\n        "
    assert floats_text(values, sep) == sep.join(map(float_text, values))
    for x in values:
        assert floats_text([x], sep) == float_text(x), x
