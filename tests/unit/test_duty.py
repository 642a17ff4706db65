"""Duty cycles (issue 15): golden cycles worked by hand, the selection under the cycle, and
the messages of an infeasible or incomplete duty."""

import math
import subprocess
import sys

import pytest
from helpers import EXAMPLES

from advisor.applications.positioning.duty import cycle, move_and_rms
from advisor.calc import duty as du
from advisor.calc.motion import Drive, move_time_trapezoidal
from advisor.core.engine import advise
from advisor.core.reading import read_requirements

# Seed 003's load (examples/positioning_drive.toml) and its motor A.
A = Drive(150.0, 0.01, 20.0, 5.0, 100.0)


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
    ph = cycle(A, 10.0, 10.0, 4.0)
    assert [p.name for p in ph] == ["accelerate", "run", "brake", "rest"]
    assert [p.torque_Nm for p in ph] == [20.0, 10.0, -20.0, 0.0]
    assert ph[0].time_s == pytest.approx(0.9)
    assert ph[1].time_s == pytest.approx(10.0 / 150.0)
    assert ph[2].time_s == pytest.approx(0.3)
    move = 0.9 + 0.3 + 10.0 / 150.0
    assert ph[3].time_s == pytest.approx(4.0 - move)
    assert move == pytest.approx(move_time_trapezoidal(A, 10.0, 10.0))
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
    ph = cycle(A, 1.0, 10.0, 2.0)
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
    c = Drive(100.0, 0.03, 45.0, 5.0, 100.0)
    ph = cycle(c, 10.0, d.ratio, 4.0)
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
        assert move_and_rms(c, 10.0, d.min_rms_ratio * k, 4.0)[1] >= d.min_rms_torque_Nm * (
            1 - 1e-9
        )
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


# ------------------------------------------------------------------ linear (induction motor)
VALVE = EXAMPLES / "valve_actuator_duty.toml"


def _linear(tmp_path, duty: str):
    src = VALVE.read_text(encoding="utf-8")
    f = tmp_path / "lin.toml"
    f.write_text(src[: src.index("[duty]")] + duty, encoding="utf-8")
    return f


def test_linear_s3_by_hand(tmp_path):
    """S3 40 %, 10 min, β0 = 0.5: the run at seed 001's 5.085 N·m (paper model, Tr16x2) for
    240 s, rest 360 s at standstill: M_eq = 5.08485·√(240/(240 + 0.5·360)) = 5.08485·√(4/7)
    = 3.8438 N·m against the rated 750 W/(1390 rpm·π/30) = 5.1525 N·m of 4A71B4: 0.7460.
    Beside it SEW's S3 factor at cdf 40 %, K = 1.15 (tests/golden/test_duty_published.py): the
    running 5.08485 N·m against 1.15 × 5.1525 = 5.9254 N·m: 0.8581, the stricter, decides."""
    f = _linear(tmp_path, '[duty]\nduty_type = "S3"\ncyclic_duration_factor = 0.4\n')
    rep = advise(read_requirements(f))
    d = rep.design.duty
    m_l = rep.design.screw.torque_Nm
    assert m_l == pytest.approx(5.08485, abs=1e-5)
    assert d.rms_torque_Nm == pytest.approx(m_l * math.sqrt(4.0 / 7.0))
    assert d.rms_torque_Nm == pytest.approx(3.8438, abs=1e-4)
    assert d.rated_torque_Nm == pytest.approx(750.0 / (1390.0 * math.pi / 30.0))
    assert d.thermal_utilisation == pytest.approx(5.08485 / (1.15 * 5.1525), abs=1e-4)
    assert d.thermal_utilisation == pytest.approx(0.8581, abs=1e-4)
    assert 3.8438 / 5.1525 < d.thermal_utilisation  # the equivalent torque's 0.7460
    assert [p.name for p in d.phases] == ["run", "rest"]
    assert d.cycle_time_s == 600.0 and d.duty_type == "S3"
    assert "DU-07" in {x.id for x in rep.decisions}


def test_linear_s4_starts_by_hand(tmp_path):
    """S4 40 %, 600 starts/h, FI from a 40 kg nut: the starts allowed by hand.
    4A71B4: 0.75 kW, η 72 % (estimated) → P_loss = 750·(100/72 − 1) = 291.67 W; J_M =
    0.0014 kg·m², ω0 = 157.08 rad/s; z0 = 3600·291.67·0.75/(0.0014·157.08²) = 22797 /h.
    FI and k_L as the report states them; u = M_eq/M_n:
    z = z0·(1 − u²)/(FI·k_L)."""
    f = _linear(
        tmp_path,
        '[duty]\nduty_type = "S4"\ncyclic_duration_factor = 0.4\nstarts_per_hour = 600\n'
        "moving_mass_kg = 40\n",
    )
    d = advise(read_requirements(f)).design.duty
    z0 = 3600.0 * 750.0 * (100.0 / 72.0 - 1.0) * 0.75 / (0.0014 * (50.0 * math.pi) ** 2)
    assert z0 == pytest.approx(22797, abs=1)
    assert d.no_load_starts_per_hour == pytest.approx(z0)
    start = d.phases[0]
    assert start.name == "start"
    # k_L = M_m/(M_m − M_L) with the mean starting torque of the phase
    k_l = start.torque_Nm / (start.torque_Nm - d.phases[1].torque_Nm)
    u = d.rms_torque_Nm / d.rated_torque_Nm
    assert d.allowed_starts_per_hour == pytest.approx(z0 * (1 - u * u) / (d.inertia_factor * k_l))
    assert d.starts_per_hour == 600.0
    # the cycle is 3600/600 = 6 s: start, run to 40 % of it, rest
    assert d.cycle_time_s == pytest.approx(6.0)
    assert start.time_s + d.phases[1].time_s == pytest.approx(2.4)


def test_linear_cycle_example(tmp_path):
    rep = advise(read_requirements(VALVE))
    d = rep.design.duty
    assert d.motor == rep.design.motor.model == "4A71B4"
    assert d.starts_per_hour == 40.0  # two moves, 20 cycles an hour
    assert d.cycle_time_s == pytest.approx(180.0)
    # holding: Tr16x2 is self-locking, so the hold asks nothing of the motor
    hold = next(p for p in d.phases if p.name == "2 hold")
    assert hold.torque_Nm == 0.0
    # the equivalent torque from the reported phases, with β0 = 0.5 at rest, 0.75 in ramps
    num = sum(p.torque_Nm**2 * p.time_s for p in d.phases if not p.name.endswith("start"))
    den = sum(
        p.time_s
        * (0.5 if p.speed_rpm == 0 else 0.75 if p.speed_start_rpm != p.speed_end_rpm else 1)
        for p in d.phases
    )
    assert d.rms_torque_Nm == pytest.approx(math.sqrt(num / den), rel=1e-5)
    assert d.regenerated_per_cycle_J == 0.0  # a self-locking screw never drives the motor


def test_linear_cycle_needs_a_larger_motor(tmp_path):
    # S7 at 600 starts/h: the 4A71B4 of the rated point allows 133 (z = z0·(1 − u²)/(FI·k_L·
    # (1 + k_b))), so the next power up (an S9 share above 1 would load the screw beyond
    # linear.force_N and is refused)
    f = _linear(tmp_path, '[duty]\nduty_type = "S7"\nstarts_per_hour = 600\n')
    rep = advise(read_requirements(f))
    assert rep.design.duty.starts_per_hour == 600.0
    assert rep.design.duty.allowed_starts_per_hour >= 600.0
    assert rep.design.duty.motor == rep.design.motor.model != "4A71B4"
    assert any("the cycle needs" in w for w in rep.warnings)


def test_linear_hold_without_self_locking_is_infeasible(tmp_path):
    src = VALVE.read_text(encoding="utf-8").replace('thread = "Tr16x2"', 'thread = "Tr16x4"')
    f = tmp_path / "h.toml"
    f.write_text(src.replace("[screw]", "[screw]\nstarts = 3"), encoding="utf-8")
    r = _run(f)
    assert r.returncode == 3, r.stderr
    assert "cannot hold a load at standstill" in r.stderr


def test_linear_duty_needs_one_form(tmp_path):
    r = _run(_linear(tmp_path, "[duty]\nmoving_mass_kg = 1\n"))
    assert r.returncode == 2
    assert "duty: give segments (move, dwell, hold) or a duty_type (S1…S10)" in r.stderr
    r = _run(_linear(tmp_path, '[duty]\nduty_type = "S4"\ncyclic_duration_factor = 0.4\n'))
    assert r.returncode == 2 and "duty.starts_per_hour: missing" in r.stderr


def test_linear_duty_path_imports_no_numpy():
    code = (
        "import sys, io, contextlib\n"
        "from advisor.cli import main\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n"
        f"    rc = main(['--batch', {str(VALVE)!r}])\n"
        "assert rc == 0\n"
        "print(','.join(m for m in ('textual', 'numpy', 'scipy') if m in sys.modules))\n"
    )
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == ""


# ------------------------------------------------------------------ rotary (PM brushless)
RUDDER = EXAMPLES / "rudder_actuator_duty.toml"


def test_rotary_cycle_by_hand():
    """The rudder cycle at 5000 rpm, q = 1000, two stages η = 0.9² = 0.81, J_L = 2 kg·m²,
    J_M = 1.5e-4 kg·m². Move 25° = 0.436332 rad in 1 s, 0.1 s ramps: ω_out = θ/0.9 s =
    0.484814 rad/s (4629.6 rpm at the motor), ε_out = 4.84814 rad/s², J_M·ε_m = 1.5e-4·4848.14
    = 0.727221 N·m. Against 1200 N·m (the motor drives, /(q·η) = /810):
      accelerate (2·4.84814 + 1200)/810 + 0.727221 = 2.220673; run 1200/810 = 1.481481;
      decelerate (1200 − 9.69628)/810 − 0.727221 = 0.742290.
    Back with the load (the load drives, ·η/q = ·0.81e-3):
      accelerate −1190.304·0.81e-3 + 0.727221 = −0.236925; run −0.972;
      decelerate −1209.696·0.81e-3 − 0.727221 = −1.707075.
    Hold 1620 N·m at rest: 1620·0.81e-3 = 1.3122. Dwell and nothing else: 0."""
    rep = advise(read_requirements(RUDDER))
    d = rep.design.duty
    assert (d.ratio, rep.design.gearbox.efficiency) == pytest.approx((1000.0, 0.81))
    torques = [p.torque_Nm for p in d.phases]
    hand = [2.220673, 1.481481, 0.742290, 1.3122, -0.236925, -0.972, -1.707075, 0.0]
    assert torques == pytest.approx(hand, abs=2e-6)
    times = [p.time_s for p in d.phases]
    assert times == pytest.approx([0.1, 0.8, 0.1, 3.0, 0.1, 0.8, 0.1, 5.0])
    assert d.phases[1].speed_rpm == pytest.approx(0.484814 * 1000 * 30 / math.pi, rel=1e-6)
    rms = math.sqrt(sum(t * t * s for t, s in zip(hand, times, strict=True)) / 10.0)
    assert d.rms_torque_Nm == pytest.approx(rms, rel=1e-5)
    assert d.peak_torque_Nm == pytest.approx(2.220673, abs=2e-6)
    # copper: the seed's 68.97 W at 2 N·m (2·1.14 Ω·5.5² A²), so 68.97·(M_rms/2)² on average
    copper = 68.97 * (rms / 2.0) ** 2
    assert d.losses_W["copper"] == pytest.approx(copper, rel=1e-5)
    # iron (f² model) and magnets (n² below 5000 rpm) both go as n²: 99.45 + 60 W at 5000 rpm
    # times (n/5000)²; a ramp averages n² to n_max²/3 (0.2 s of ramps per move)
    k = (0.484814 * 1000 * 30 / math.pi / 5000.0) ** 2
    core = (99.45 + 60.0) * k * (2 * 0.8 + 2 * 2 * 0.1 / 3.0) / 10.0
    assert d.losses_W["iron_and_magnets"] == pytest.approx(core, rel=1e-5)
    assert d.thermal_utilisation == pytest.approx((copper + core) / 228.42, rel=1e-5)
    # energy: the phases' M·ω_mean·t; what comes back is the braking and the load's help
    w = 484.814
    out = (2.220673 * 0.05 + 1.481481 * 0.8 + 0.742290 * 0.05) * w
    back = (0.236925 * 0.05 + 0.972 * 0.8 + 1.707075 * 0.05) * w
    assert (d.energy_per_cycle_J, d.regenerated_per_cycle_J) == pytest.approx((out, back), rel=1e-5)
    # the thermal model settles at the mean losses' rise: R = 105 K / 228.42 W
    assert d.thermal.steady_rise_K == pytest.approx((copper + core) * 105.0 / 228.42, rel=1e-5)
    assert d.thermal.peak_rise_K >= d.thermal.steady_rise_K
    assert d.thermal.rise_K[-1] == pytest.approx(d.thermal.steady_rise_K, rel=0.02)
    assert d.inertia_ratio == pytest.approx(2.0 / (1000.0**2 * 0.81) / 1.5e-4)


def test_first_order_model_by_hand():
    """100 W for τ, then 0 W for τ, R = 0.5 K/W: ΔT(τ) = 50·(1 − e⁻¹) = 31.606 K, then
    31.606·e⁻¹ = 11.627 K. Settled: ΔT₀ = B/(1 − A) with A = e⁻², B = 31.606·e⁻¹ →
    11.627/(1 − 0.135335) = 13.447 K at the cycle's start, peak 13.447·e⁻¹ + 31.606 = 36.553."""
    h = du.thermal_rise([(100.0, 600.0), (0.0, 600.0)], 0.5, 600.0, 1)
    assert [x[1] for x in h] == pytest.approx([0.0, 31.606, 11.627], abs=1e-3)
    assert du.periodic_peak_rise([(100.0, 600.0), (0.0, 600.0)], 0.5, 600.0) == pytest.approx(
        36.553, abs=1e-3
    )


def test_rotary_cycle_too_fast_for_the_motor(tmp_path):
    src = RUDDER.read_text(encoding="utf-8").replace(
        "angle_deg = 25, time_s = 1", "angle_deg = 60, time_s = 1"
    )
    f = tmp_path / "fast.toml"
    f.write_text(src, encoding="utf-8")
    r = _run(f)
    assert r.returncode == 3, r.stderr
    assert "needs 11111 rpm at the motor (q = 1000), above its 5000 rpm" in r.stderr


def test_rotary_s3_by_hand(tmp_path):
    """S3 25 % at the rated point: 2 N·m at 5000 rpm for 150 s of 600 s (the motor torque
    1620/(1000·0.81) = 2 N·m), then 450 s at rest with the load standing, held by the motor
    through the back-driven wave gear (docs/reference/duty.md): 1620·0.81/1000 = 1.3122 N·m,
    copper only, 68.97·(1.3122/2)² = 29.690 W (the point's ohmic 68.97 W at 2 N·m).
    Mean losses 228.42·0.25 + 29.690·0.75 = 79.372 W; RMS √(0.25·2² + 0.75·1.3122²)."""
    src = RUDDER.read_text(encoding="utf-8")
    f = tmp_path / "s3.toml"
    f.write_text(
        src[: src.index("[duty]")]
        + '[duty]\nduty_type = "S3"\ncyclic_duration_factor = 0.25\nmotor_inertia_kgm2 = 1.5e-4\n'
        "thermal_time_constant_s = 900\n",
        encoding="utf-8",
    )
    d = advise(read_requirements(f)).design.duty
    held = 1620.0 * 0.81 / 1000.0
    total = 228.42 * 0.25 + 68.97 * (held / 2.0) ** 2 * 0.75
    assert total == pytest.approx(79.372, abs=1e-3)
    assert d.losses_W["total"] == pytest.approx(total, rel=1e-5)
    assert d.thermal_utilisation == pytest.approx(total / 228.42, rel=1e-5)
    assert d.rms_torque_Nm == pytest.approx(math.sqrt(0.25 * 4.0 + 0.75 * held**2), rel=1e-5)
    assert d.phases[-1].name == "rest" and d.phases[-1].torque_Nm == pytest.approx(held)


def test_wizard_plots_of_the_cycle():
    from advisor.duty.views import plots, series

    rep = advise(read_requirements(RUDDER))
    titles = [p.title for p in plots(rep.design.duty)]
    assert titles[0].startswith("Torque over the cycle") and titles[1] == "Speed over the cycle"
    assert titles[2].startswith("Winding temperature rise")
    tt, mm, _ts, ns = series(rep.design.duty)
    assert tt[-1] == pytest.approx(10.0) and mm[:2] == [mm[0], mm[0]]
    assert max(ns) == pytest.approx(rep.design.duty.phases[1].speed_rpm)
    assert plots(None) == []


def test_the_wizard_asks_the_duty_in_its_own_step():
    from advisor.tui import fields as F

    assert F.STEPS[4] == "Duty cycle" and F.REVIEW == 5
    asked = {k: [f.dotted for f in F.fields_for(k, 4)] for k in ("positioning", "linear", "rotary")}
    assert asked["positioning"] == ["duty.cycle_time_s"]
    assert "positioning.motors.0.rated_torque_Nm" in [
        f.dotted for f in F.fields_for("positioning", 3)
    ]
    assert {"duty.duty_type", "duty.segments.0.distance_m", "duty.moving_mass_kg"} <= set(
        asked["linear"]
    )
    assert {"duty.motor_inertia_kgm2", "duty.segments.0.angle_deg"} <= set(asked["rotary"])
    for k in asked:  # every duty question has its label and help
        assert all(f.label and f.help for f in F.fields_for(k, 4))
