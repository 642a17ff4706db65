"""The thermal history in closed form (calc.duty.thermal_history) against the stepping model
(calc.duty.thermal_rise) it replaces in the report: the same points, the same numbers to far
below the report's six significant digits."""

import random

import pytest

from advisor.calc.duty import thermal_history, thermal_rise
from advisor.core.report import round_sig


def _kept(hist: list[tuple[float, float]], max_points: int) -> list[tuple[float, float]]:
    """What the report kept of the stepped history before: every step-th point and the last."""
    step = max(1, len(hist) // max_points)
    return hist[::step] + ([hist[-1]] if (len(hist) - 1) % step else [])


def _cases() -> list[tuple[list[tuple[float, float]], float, float, int]]:
    rng = random.Random(29)
    cases = [
        ([(100.0, 600.0), (0.0, 600.0)], 0.5, 600.0, 1),
        ([(100.0, 1e9)], 0.5, 600.0, 1),
        ([(50.0, 0.05), (10.0, 0.8), (40.0, 0.05), (0.0, 2.0)], 0.46, 1800.0, 2000),
        ([(0.0, 1.0)], 1.0, 10.0, 7),
        ([(5.0, 0.0), (7.0, 3.0)], 2.0, 30.0, 123),
    ]
    for _ in range(60):
        m = rng.randint(1, 6)
        losses = [
            (rng.uniform(0.0, 500.0), rng.choice([0.0, rng.uniform(1e-3, 900.0)])) for _ in range(m)
        ]
        cases.append(
            (losses, rng.uniform(0.01, 3.0), rng.uniform(1.0, 5000.0), rng.randint(1, 300))
        )
    return cases


@pytest.mark.parametrize("max_points", [400, 50, 10**9])
def test_closed_form_history_equals_the_stepped_one(max_points):
    for losses, r, tau, cycles in _cases():
        stepped = _kept(thermal_rise(losses, r, tau, cycles), max_points)
        closed = thermal_history(losses, r, tau, cycles, max_points)
        assert len(closed) == len(stepped)
        for (t0, y0), (t1, y1) in zip(stepped, closed, strict=True):
            assert t1 == pytest.approx(t0, rel=1e-12, abs=1e-12)
            assert y1 == pytest.approx(y0, rel=1e-10, abs=1e-10)
            assert round_sig(t1) == round_sig(t0)
            assert round_sig(y1) == round_sig(y0) or y1 == pytest.approx(y0, abs=1e-12)


def test_the_clock_is_the_stepping_models_clock_to_the_last_bit():
    """The times are the phase durations summed one after another, as the stepping model sums
    them: a product c·t_cycle + t_j differs in the last bit, and where the true time is a tie
    at the 6th digit (0.01 s phases, 1030.005 s) that bit changes the printed report."""
    import random

    from advisor.calc.duty import thermal_history, thermal_rise

    rng = random.Random(7)
    for _ in range(200):
        phases = [
            (rng.uniform(0, 500), rng.choice([0.01, 0.1, 0.2, 1.5, 2.35, 10.0]))
            for _ in range(rng.randint(1, 4))
        ]
        cycles = rng.randint(1, 3000)
        kept = thermal_history(phases, 0.4, 900.0, cycles)
        stepped = dict(thermal_rise(phases, 0.4, 900.0, cycles))
        assert all(t in stepped for t, _ in kept)
