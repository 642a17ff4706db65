"""The spinning rotor's eq. (5) solved without scipy (importing scipy.optimize costs more than a
cold batch run's budget): the resistance as a polynomial in ω, Gauss–Legendre panels for the
run-up time, Brent's method for the roots."""

import math

import pytest

from advisor.calc.roots import brent
from advisor.calc.rotor import BallSet, G, Rotor, resistance, resisting_torque, run_up_time

# the seed-002 example: SKF 7000 CD, 8 balls of 4.76 mm on a pitch radius of 6.6 mm, 15°
BALLS = BallSet(6.6e-3, 4.76e-3, 8, math.radians(15.0))
OMEGA = 4453.0


def _rotor(slew: float = 0.0765, aero_k: float = 32.15 / OMEGA**2.5) -> Rotor:
    inertia = 1.814 / OMEGA
    return Rotor(inertia, 2, BALLS, 0.028e-3, 0.56 * G / 2, 0.010, aero_k, inertia * slew)


@pytest.mark.parametrize("slewing", [False, True])
def test_the_polynomial_is_the_resistance_term_by_term(slewing):
    rotor = _rotor()
    res = resistance(rotor, slewing)
    for w in (0.0, 1.0, 10.0, 1234.5, OMEGA, 2e4):
        assert res(w) == pytest.approx(resisting_torque(rotor, w, slewing), rel=1e-13)
        assert res.at_root(math.sqrt(w)) == pytest.approx(res(w), rel=1e-13)
    for u in (1e-6, 1.0, OMEGA / 2, OMEGA):
        assert res.drop(OMEGA, u) == pytest.approx(res(OMEGA) - res(OMEGA - u), rel=1e-9)
    h = 1e-3
    assert res.slope(OMEGA) == pytest.approx((res(OMEGA + h) - res(OMEGA - h)) / (2 * h), rel=1e-7)


@pytest.mark.parametrize("gap", [1.0, 1e-3, 1e-9, 1e-12])
def test_run_up_time_against_the_closed_form(gap):
    """Without slew and drag M_res = a0 + a2·ω², and by hand
    t = J/√(c·a2)·artanh(x), c = M − a0, x = ω·√(a2/c); near M = M_res(ω) the integrand peaks
    like 1/(M − M_res), which the log substitution must follow: checked down to a gap of
    1e-12. There 1 − x² = δ/c with δ = M − M_res(ω), so artanh x = ½·ln((1 + x)²·c/δ) keeps
    the closed form itself accurate."""
    rotor = _rotor(slew=0.0, aero_k=0.0)
    res = resistance(rotor, False)
    assert res.a1 == 0.0 and res.k == 0.0
    m = res(OMEGA) * (1.0 + gap)
    c, delta = m - res.a0, m - res(OMEGA)
    x = OMEGA * math.sqrt(res.a2 / c)
    exact = rotor.inertia_kgm2 / math.sqrt(c * res.a2) * 0.5 * math.log((1 + x) ** 2 * c / delta)
    assert run_up_time(rotor, m, OMEGA) == pytest.approx(exact, rel=1e-9)


def test_a_torque_below_the_resistance_never_arrives():
    rotor = _rotor()
    assert run_up_time(rotor, resisting_torque(rotor, OMEGA, False) * 0.999, OMEGA) == (math.inf)


def test_brent_finds_roots_in_few_steps():
    calls = []

    def f(x):
        calls.append(x)
        return x**3 - 2 * x - 5  # Newton's cubic: 2.0945514815423265…

    assert brent(f, 2.0, 3.0) == pytest.approx(2.0945514815423265, abs=1e-13)
    assert len(calls) < 15
    assert brent(lambda x: math.exp(x) - 5.0, -10.0, 10.0) == pytest.approx(math.log(5.0))
    with pytest.raises(ValueError, match="no sign change"):
        brent(lambda x: x * x + 1.0, -1.0, 1.0)


def test_the_advice_path_does_not_import_scipy():
    import subprocess
    import sys

    code = (
        "import sys; from advisor.cli import main; "
        "main(['--batch', 'examples/gyro_compensator.toml']); "
        "sys.stderr.write(str(sorted(m for m in sys.modules if m.split('.')[0] == 'scipy')))"
    )
    from helpers import ROOT

    done = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True
    )
    assert done.stderr.strip() == "[]"
