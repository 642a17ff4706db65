"""Duty cycles (issue 15): golden cycles worked by hand, the selection under the cycle, and
the messages of an infeasible or incomplete duty."""

import math
import subprocess
import sys

import pytest
from helpers import EXAMPLES

from advisor.calc import duty as du
from advisor.calc import motion as mo
from advisor.core.engine import advise
from advisor.core.requirements import read_requirements
from advisor.duty import positioning as dp

# Seed 003's load (examples/positioning_drive.toml) and its motor A.
A = mo.Drive(150.0, 0.01, 20.0, 5.0, 100.0)


def test_positioning_cycle_by_hand():
    """Motor A at i = 10, 10 rad of the load shaft, a 4 s cycle. At the motor:
    J = J0 + J_p/i² = 0.01 + 5/100 = 0.06 kg·m²; M_p/i = 10 N·m.
    accelerate with M_λ = 20 against 10: ε₁ = 10/0.06 = 166.67 rad/s², t₁ = 150/166.67 = 0.9 s;
    brake with 20 helped by 10: ε₂ = 30/0.06 = 500, t₃ = 0.3 s;
    path at the motor 10·10 = 100 rad, ramps 150·0.9/2 + 150·0.3/2 = 90 rad, run 10/150 s;
    move 0.9 + 0.3 + 0.0667 = 1.2667 s — seed 003's eq. (4): 100/150 + 0.075·600/75 = 1.2667.
    RMS = √((20²·1.2 + 10²·0.0667)/4) = √(486.67/4) = 11.030 N·m.
    Energy out 20·75·0.9 + 10·150·0.0667 = 1350 + 100 = 1450 J; back 20·75·0.3 = 450 J
    (= J·ω0²/2 − the friction's 10·22.5 J while braking = 675 − 225)."""
    ph = dp.cycle(A, 10.0, 10.0, 4.0)
    assert [p.name for p in ph] == ["accelerate", "run", "brake", "rest"]
    assert [p.torque_Nm for p in ph] == [20.0, 10.0, -20.0, 0.0]
    assert ph[0].time_s == pytest.approx(0.9)
    assert ph[1].time_s == pytest.approx(10.0 / 150.0)
    assert ph[2].time_s == pytest.approx(0.3)
    move = 0.9 + 0.3 + 10.0 / 150.0
    assert ph[3].time_s == pytest.approx(4.0 - move)
    assert move == pytest.approx(mo.move_time_trapezoidal(A, 10.0, 10.0))
    rms = math.sqrt((20.0**2 * 1.2 + 10.0**2 * (10.0 / 150.0)) / 4.0)
    assert rms == pytest.approx(11.0303, abs=1e-4)
    assert du.rms_torque(ph) == pytest.approx(rms)
    assert du.energies(ph) == pytest.approx((1450.0, 450.0))
    assert du.peak_torque(ph) == 20.0
    # mean |speed|: (75·0.9 + 150·0.0667 + 75·0.3)/4 = (67.5 + 10 + 22.5)/4 = 25 rad/s
    assert du.mean_speed(ph) == pytest.approx(25.0)


def test_triangular_move_by_hand():
    """A short path: 1 rad at i = 10 → 10 rad at the motor, ε₁ = 166.67, ε₂ = 500:
    v = √(2·10·166.67·500/666.67) = √2500 = 50 rad/s < 150; t₁ = 0.3 s, t₃ = 0.1 s."""
    ph = dp.cycle(A, 1.0, 10.0, 2.0)
    assert [p.name for p in ph] == ["accelerate", "brake", "rest"]
    assert ph[0].speed_end_rad_s == pytest.approx(50.0)
    assert (ph[0].time_s, ph[1].time_s) == pytest.approx((0.3, 0.1))


def test_example_chooses_the_fastest_passing_move():
    rep = advise(read_requirements(EXAMPLES / "indexing_table_duty.toml"))
    d = rep.design.duty
    # motor C (ω0 = 100, J0 = 0.03, M_λ = 45, rated 18 N·m): at its fastest ratio 6.623 the
    # RMS is 19.55 N·m > 18, so the cycle moves to the ratio where the RMS is exactly 18
    assert d.motor == "C"
    assert d.rms_torque_Nm == pytest.approx(18.0, rel=1e-6)
    assert d.ratio > rep.design.motion.optimal_ratio
    c = mo.Drive(100.0, 0.03, 45.0, 5.0, 100.0)
    ph = dp.cycle(c, 10.0, d.ratio, 4.0)
    assert du.rms_torque(ph) == pytest.approx(d.rms_torque_Nm)
    # the phases are M_λ, M_p/i, −M_λ, 0; the RMS by hand from the reported phases
    p = d.phases
    assert [x.torque_Nm for x in p] == pytest.approx([45.0, 100.0 / d.ratio, -45.0, 0.0])
    by_hand = math.sqrt(
        (45.0**2 * (p[0].time_s + p[2].time_s) + p[1].torque_Nm ** 2 * p[1].time_s) / 4.0
    )
    assert by_hand == pytest.approx(d.rms_torque_Nm)
    assert sum(x.time_s for x in p) == pytest.approx(4.0)
    # the ratio of least RMS torque is a minimum: its neighbours are no better
    for k in (0.99, 1.01):
        assert dp._eval(c, 10.0, d.min_rms_ratio * k, 4.0)[1] >= d.min_rms_torque_Nm * (1 - 1e-9)
    assert d.thermal_utilisation == pytest.approx(d.rms_torque_Nm / 18.0)
    assert d.inertia_ratio == pytest.approx(5.0 / d.ratio**2 / 0.03)
    ids = {x.id for x in rep.decisions}
    assert {"DU-01", "DU-02", "DU-03", "DU-04", "DU-05"} <= ids
    assert {"duty_move_fits", "duty_rms_torque"} <= {x.id for x in rep.checks}


def _run(path) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "advisor", "--batch", str(path)], capture_output=True, text=True
    )


def test_a_move_longer_than_the_cycle_is_infeasible(tmp_path):
    src = (EXAMPLES / "indexing_table_duty.toml").read_text(encoding="utf-8")
    f = tmp_path / "short.toml"
    f.write_text(src.replace("cycle_time_s = 4.0", "cycle_time_s = 0.9"), encoding="utf-8")
    r = _run(f)
    assert r.returncode == 3, r.stderr
    assert "motor C: its fastest move takes 1.023 s" in r.stderr
    assert "duty.cycle_time_s = 0.9 s" in r.stderr and "Traceback" not in r.stderr


def test_rated_torque_is_required_with_a_duty(tmp_path):
    src = (EXAMPLES / "indexing_table_duty.toml").read_text(encoding="utf-8")
    f = tmp_path / "norated.toml"
    f.write_text(src.replace("rated_torque_Nm = 5\n", ""), encoding="utf-8")
    r = _run(f)
    assert r.returncode == 2
    assert "positioning.motors[2].rated_torque_Nm: missing; required when [duty]" in r.stderr


def test_no_motor_passes_the_rms(tmp_path):
    src = (EXAMPLES / "indexing_table_duty.toml").read_text(encoding="utf-8")
    f = tmp_path / "hot.toml"
    f.write_text(src.replace("cycle_time_s = 4.0", "cycle_time_s = 1.3"), encoding="utf-8")
    r = _run(f)
    assert r.returncode == 3
    assert "against its rated torque" in r.stderr
