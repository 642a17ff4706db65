"""A positioning duty cycle with the catalog's induction motors: the heat of the direct-on-line
starts and electric stops bounds the starts per hour (DU-06), as in the linear duty."""

import math
import tomllib

import pytest
from helpers import EXAMPLES

from advisor.applications.positioning.duty import start_figures, start_heat
from advisor.calc.motion import Drive
from advisor.core.engine import advise
from advisor.core.errors import InfeasibleError
from advisor.core.reading import parse_requirements
from catalogs import load_catalogs

# a quarter turn of 2 kg·m² against 5 N·m, every second, no listed motors
QUARTER_TURN = {
    "application": {"kind": "positioning"},
    "positioning": {"travel_rad": math.pi / 2, "load_inertia_kgm2": 2.0, "load_torque_Nm": 5.0},
    "duty": {"cycle_time_s": 1.0},
}


def _motor(model: str):
    return next(m for m in load_catalogs().motors if m.model == model)


def test_start_heat_of_4aa56a2_by_hand():
    """4AA56A2 (catalog: 0.18 kW, η 66 %, J_M 0.00042 kg·m², 2 poles, M_λ = 2·M_n) at
    i = 130.749, the ratio the RMS torque alone chose for a 1 s cycle.

    P_loss = 180·(100/66 − 1) = 92.727 W; ω_s = 2π·50 = 314.159 rad/s;
    z0 = 3600·P_loss·(1 + β0)/2/(J_M·ω_s²) = 3600·92.727·0.75/(0.00042·314.159²) = 6039.8 /h
    (advisor.calc.duty.no_load_starts_per_hour, β0 = 0.5 as the linear duty's default);
    FI = (J_M + J_p/i²)/J_M = (0.00042 + 2/130.749²)/0.00042 = 1.27855;
    M_n = 180/(2760·π/30) = 0.62278 N·m, M_λ = 1.24556, M_p/i = 5/130.749 = 0.038241:
    k_L = M_λ/(M_λ − M_p/i) = 1.24556/1.20732 = 1.03167; DC stop k_b = 1;
    z = z0·(1 − u²)/(FI·k_L·(1 + k_b)) ≤ 6039.8/(1.27855·1.03167·2) = 2289.4 /h (u = 0),
    and with the run's small copper heat (u ≈ 0.051) 2283.5 /h: below the 3600 /h the
    1 s cycle asks (a start and a stop each second)."""
    m = _motor("4AA56A2")
    h = start_heat(m, 1.0)
    p_loss = 180.0 * (100.0 / 66.0 - 1.0)
    z0 = 3600.0 * p_loss * 0.75 / (0.00042 * (2.0 * math.pi * 50.0) ** 2)
    assert h.no_load_starts_per_hour == pytest.approx(z0, rel=1e-12)
    assert z0 == pytest.approx(6039.8, abs=0.05)
    assert h.starts_per_hour == 3600.0
    m_l = 2.0 * 180.0 / (2760.0 * math.pi / 30.0)
    d = Drive(2760.0 * math.pi / 30.0, 0.00042, m_l, 2.0, 5.0)
    z = start_figures(h, d, math.pi / 2, 130.749, 1.0)
    fi = (0.00042 + 2.0 / 130.749**2) / 0.00042
    k_l = m_l / (m_l - 5.0 / 130.749)
    assert z.inertia_factor == pytest.approx(fi, rel=1e-12)
    assert fi == pytest.approx(1.27855, abs=1e-5)
    assert k_l == pytest.approx(1.03167, abs=1e-5)
    assert z.load_factor == pytest.approx(k_l, rel=1e-12)
    upper = z0 / (fi * k_l * 2.0)
    assert upper == pytest.approx(2289.4, abs=0.1)
    u = z.running_utilisation
    assert 0.04 < u < 0.06
    assert z.allowed_starts_per_hour == pytest.approx(upper * (1.0 - u**2), rel=1e-12)
    assert z.allowed_starts_per_hour == pytest.approx(2283.5, abs=0.1)
    assert z.allowed_starts_per_hour < 3600.0


def test_catalog_duty_chooses_a_motor_whose_starts_pass():
    """The 1 s cycle: the motor chosen passes its starts per hour (before, only the RMS torque
    was checked and 4AA56A2 at i = 130.7 passed with 2284 starts/h allowed for 3600)."""
    rep = advise(parse_requirements(QUARTER_TURN))
    assert rep.report.status == "feasible"
    checks = {c.id: c for c in rep.checks}
    starts = checks["duty_starts_per_hour"]
    assert starts.value == 3600.0
    assert starts.limit >= 3600.0 * (1 - 1e-9)
    assert starts.passed
    duty = rep.design.duty
    assert duty.starts_per_hour == 3600.0
    assert duty.allowed_starts_per_hour == pytest.approx(starts.limit)
    assert any(d.id == "DU-06" for d in rep.decisions)


def test_catalog_duty_refuses_when_no_motor_takes_the_starts():
    """Every 0.45 s: 8000 starts/h; no catalog motor whose torques pass takes them."""
    data = {**QUARTER_TURN, "duty": {"cycle_time_s": 0.45}}
    with pytest.raises(InfeasibleError) as err:
        advise(parse_requirements(data))
    text = " ".join(err.value.reasons)
    assert "8000 starts/h" in text
    assert "heat of its starts" in text
    assert "allow a longer duty.cycle_time_s" in text


def test_listed_motors_have_no_start_limit():
    """Listed motors (a servo, an inverter-fed motor) are not limited by DOL start heat."""
    rep = advise(
        parse_requirements(tomllib.loads((EXAMPLES / "indexing_table_duty.toml").read_text()))
    )
    assert "duty_starts_per_hour" not in {c.id for c in rep.checks}
    assert rep.design.duty.starts_per_hour is None
