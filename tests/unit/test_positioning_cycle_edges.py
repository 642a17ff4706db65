"""The positioning duty cycle at its edges, each number by hand (seed 003, eqs. (1)–(4)).

Seed 003's move at ratio i: J = J0 + J_p/i², ε1 = (M_λ − M_p/i)/J, ε2 = (M_λ + M_p/i)/J;
a trapezoid when θ·i ≥ ω0²/(2ε1) + ω0²/(2ε2) (run (θ·i − ramps)/ω0 at ω0), else a triangle
with peak v = √(2θi·ε1ε2/(ε1 + ε2)); accelerate v/ε1, brake v/ε2, then rest at zero torque.
The cycle's equivalent torque M_eq = √(Σ M²·t / Σ β·t): β = 1 throughout for a listed motor,
β0 = 0.5 at rest and 0.75 in the ramps for a catalog (self-ventilated) induction motor
(Klyuchev, §11). Motor C of seed 003's example: ω0 = 100 rad/s, J0 = 0.03 kg·m², M_λ = 45 N·m;
the load 10 rad, 5 kg·m², 100 N·m.
"""

import math

import pytest

from advisor.applications.positioning.report import headline
from advisor.core.engine import advise
from advisor.core.errors import InfeasibleError
from advisor.core.reading import parse_requirements


def _phases(w0, j0, m_l, j_p, m_p, theta, i):
    """(accelerate, run, brake) times [s] of seed 003's move at ratio i, by hand."""
    j = j0 + j_p / i**2
    e1, e2 = (m_l - m_p / i) / j, (m_l + m_p / i) / j
    ramps = w0**2 / (2 * e1) + w0**2 / (2 * e2)
    if theta * i >= ramps:
        return w0 / e1, (theta * i - ramps) / w0, w0 / e2
    v = math.sqrt(2 * theta * i * e1 * e2 / (e1 + e2))
    return v / e1, 0.0, v / e2


def _c(i: float, cycle: float, beta0: float = 1.0) -> tuple[float, float]:
    """Motor C's (move time, equivalent torque) over the cycle at ratio i, by hand."""
    t_a, t_r, t_b = _phases(100.0, 0.03, 45.0, 5.0, 100.0, 10.0, i)
    move = t_a + t_r + t_b
    rest = cycle - move
    num = 45.0**2 * (t_a + t_b) + (100.0 / i) ** 2 * t_r
    return move, math.sqrt(num / ((1 + beta0) / 2 * (t_a + t_b) + t_r + beta0 * rest))


def _motor_c(cycle: float, rated: float) -> dict:
    return {
        "application": {"kind": "positioning"},
        "positioning": {
            "travel_rad": 10.0,
            "load_inertia_kgm2": 5.0,
            "load_torque_Nm": 100.0,
            "motors": [
                {
                    "name": "C",
                    "speed_rad_s": 100.0,
                    "inertia_kgm2": 0.03,
                    "accel_torque_Nm": 45.0,
                    "rated_torque_Nm": rated,
                }
            ],
        },
        "duty": {"cycle_time_s": cycle},
    }


def _hand_least_rms(cycle: float, lo: float, hi: float, n: int = 200_000) -> tuple[float, float]:
    """The least equivalent torque over the ratios whose move fits, by a dense scan."""
    best = (math.inf, math.nan)
    for k in range(n + 1):
        i = lo * (hi / lo) ** (k / n)
        move, rms = _c(i, cycle)
        if move <= cycle and rms < best[0]:
            best = (rms, i)
    return best


@pytest.mark.parametrize("cycle", [1.02287, 1.022868, 1.0228675, 1.02288, 1.02289, 1.0229])
def test_a_cycle_just_above_the_fastest_move_is_a_design(cycle):
    """C's fastest move, eq. (4) at i = 6.6232, takes 1.0228672 s; a cycle from there to
    ≈ 1.02294 s leaves a window of fitting ratios narrower than any grid's step. At 6.6232 the
    move fits and M_eq = √((45²·(t_a + t_b) + (100/6.6232)²·t_run)/T) = 38.66 N·m ≤ 40: a
    design (it was an internal error: the least RMS over the window came out inf)."""
    move, rms = _c(6.6232, cycle)
    assert move == pytest.approx(1.0228672, abs=1e-7)
    assert rms == pytest.approx(38.66, abs=0.01)
    duty = advise(parse_requirements(_motor_c(cycle, 40.0))).design.duty
    assert duty.ratio == pytest.approx(6.6232, abs=1e-4)
    assert duty.rms_torque_Nm == pytest.approx(rms, abs=1e-3)
    assert duty.move_time_s <= cycle
    assert math.isfinite(duty.min_rms_torque_Nm)
    assert _c(duty.min_rms_ratio, cycle)[0] <= cycle  # the least-RMS ratio's move fits


def test_the_least_rms_stated_in_a_refusal_is_over_the_ratios_that_fit():
    """Rated 30 N·m, cycle 1.0229 s: the ratios that fit lie between ≈ 6.587 and 6.659 (the
    roots of t(i) = 1.0229 s around 6.6232); the least M_eq over them, by a dense scan by hand,
    is 38.49 N·m at the upper end, above 30: refused, stating that least (it said 'at least
    inf N·m at any ratio (i = 2.222)', i = m, which cannot move the load)."""
    rms_min, i_min = _hand_least_rms(1.0229, 6.5, 6.75)
    assert rms_min == pytest.approx(38.49, abs=0.01)
    assert 6.65 < i_min < 6.67
    with pytest.raises(InfeasibleError) as err:
        advise(parse_requirements(_motor_c(1.0229, 30.0)))
    why = " ".join(err.value.reasons)
    assert "at least 38.49 N·m at any ratio (i = 6.659)" in why
    assert "inf" not in why


def test_a_passing_window_narrower_than_a_step_is_found():
    """Cycle 4 s, rated 9.02 N·m: at i = 39.1246 the move takes 3.98662 s ≤ 4 s and
    M_eq = √((45²·(t_a + t_b) + (100/i)²·t_run)/4) = 9.01999 N·m ≤ 9.02 (the auditor's
    hand_duty.py): a design, at the ratio nearest the fastest where the RMS equals the rated
    torque (it was refused 'at least 9.016 N·m at any ratio ... against 9.02 N·m')."""
    move, rms = _c(39.1246, 4.0)
    assert move == pytest.approx(3.98662, abs=1e-5)
    assert rms == pytest.approx(9.02, abs=1e-4) and rms <= 9.02
    rep = advise(parse_requirements(_motor_c(4.0, 9.02)))
    duty = rep.design.duty
    assert duty.ratio == pytest.approx(39.1246, abs=1e-3)
    assert duty.move_time_s == pytest.approx(move, abs=1e-4)
    assert duty.rms_torque_Nm == pytest.approx(9.02, rel=1e-9)
    check = next(c for c in rep.checks if c.id == "duty_rms_torque")
    assert check.margin >= 1.0


def test_a_passing_window_at_the_cycles_edge_is_found():
    """Cycle 1.0232 s, rated 38.4 N·m: at i = 6.68, by hand, the move takes 1.022951 s ≤ 1.0232
    and M_eq = 38.386 N·m ≤ 38.4, so a design exists; the advisor builds the ratio nearest the
    fastest (6.6232, M_eq 38.66 there) where M_eq = 38.4, which lies below 6.68 (it was
    refused 'at least 38.12 N·m at any ratio (i = 6.737) against its rated 38.4')."""
    move, rms = _c(6.68, 1.0232)
    assert move == pytest.approx(1.022951, abs=1e-6) and rms == pytest.approx(38.386, abs=1e-3)
    assert _c(6.6232, 1.0232)[1] == pytest.approx(38.66, abs=0.01)
    rep = advise(parse_requirements(_motor_c(1.0232, 38.4)))
    duty = rep.design.duty
    assert 6.6232 < duty.ratio <= 6.68
    assert _c(duty.ratio, 1.0232)[1] == pytest.approx(38.4, rel=1e-6)
    assert duty.rms_torque_Nm == pytest.approx(38.4, rel=1e-9)
    # the warning tells the two move times apart: 1.02294 against 1.02287 s, not 1.023 twice
    warning = next(w for w in rep.warnings if w.startswith("duty: the cycle needs"))
    assert "the move 1.02294 s against 1.02287 s" in warning


QUARTER = {"travel_rad": "90 deg", "load_inertia_kgm2": 2, "load_torque_Nm": 5}


def _quarter(**pos) -> dict:
    req = {"application": {"kind": "positioning"}, "positioning": {**QUARTER, **pos}}
    return req


def test_a_catalog_cycle_held_by_its_starts_says_so():
    """The quarter turn (2 kg·m², 5 N·m) in 0.3 s every 2 s with catalog motors: 4A80A4 (1.1 kW,
    1420 rpm, η 75 %, J0 0.0032 estimated, counted 0.00416; M_n = 1100/148.702 = 7.3973 N·m,
    M_λ = 2·M_n). At its fastest ratio 15.619: z0 = 3600·P_n·(100/η − 1)·0.75/(J_M·ω_s²) =
    3600·366.67·0.75/(0.00416·157.080²) = 9645 /h, FI = (0.00416 + 2/15.619²)/0.00416 = 2.971,
    k_L = 14.795/(14.795 − 5/15.619) = 1.0221, z = z0·(1 − u²)/(FI·k_L·2) = 1588 /h < 1800:
    the STARTS fail there (DU-06), while the equivalent torque passes; at i = 17.19 z = 1800.
    The warning names the starts, not the RMS torque, and the change by its size (10.1 %)."""
    w_s, m_n = 1500 * math.pi / 30, 1100 / (1420 * math.pi / 30)
    z0 = 3600 * 1100 * (100 / 75 - 1) * 0.75 / (0.00416 * w_s**2)
    assert z0 == pytest.approx(9645, abs=1)
    i = 15.619
    fi, k_l = (0.00416 + 2 / i**2) / 0.00416, 2 * m_n / (2 * m_n - 5 / i)
    assert (fi, k_l) == (pytest.approx(2.971, abs=1e-3), pytest.approx(1.0221, abs=1e-4))
    assert z0 / (fi * k_l * 2) == pytest.approx(1588, abs=2)  # u² ≈ 0.0003 changes nothing
    rep = advise(parse_requirements({**_quarter(move_time_s=0.3), "duty": {"cycle_time_s": 2}}))
    warning = next(w for w in rep.warnings if w.startswith("duty: the cycle needs"))
    assert "the motor allows 1588 starts/h, fewer than the 1800 the cycle asks (DU-06)" in warning
    assert "starts margin is 1.000 by construction" in warning
    assert "RMS torque" not in warning and "a little larger" not in warning
    assert "the ratio 10.1 % larger" in warning
    margins = {c.id: c.margin for c in rep.checks}
    assert margins["duty_starts_per_hour"] == pytest.approx(1.0, abs=1e-6)


def test_a_ratio_doubled_by_the_starts_is_said_to_double():
    """Travel 0.05 rad, 2 kg·m², 5 N·m, 0.3 s, every 2 s: 4AA56A2's ratio goes from 61.05 to
    121.5 for its starts, 121.5/61.05 = 1.99 times."""
    req = {**_quarter(move_time_s=0.3), "duty": {"cycle_time_s": 2}}
    req["positioning"]["travel_rad"] = 0.05
    rep = advise(parse_requirements(req))
    warning = next(w for w in rep.warnings if w.startswith("duty: the cycle needs"))
    assert "i = 121.5, not the fastest ratio 61.05" in warning
    assert "the ratio 1.99 times the fastest" in warning and "(DU-06)" in warning


def test_a_catalog_motors_rms_torque_is_weighted_by_its_standstill_cooling():
    """The same quarter turn every 2 s: 4A80A4 at i = 17.194 (the starts' ratio), J = 0.00416 +
    2/17.194² = 0.0109252 kg·m², M_λ = 14.7946, M_p/i = 0.29080 N·m: accelerate 0.11200 s, run
    0.07182 s, brake 0.10770 s, rest 1.70848 s. With β0 = 0.5 (β 0.75 in the ramps, 0.5 at
    rest, as DU-06 and the linear duty take the same self-ventilated motor): M_eq =
    √(14.7946²·0.21970 + 0.29080²·0.07182)/(0.75·0.21970 + 0.07182 + 0.5·1.70848)) = 6.640 N·m,
    margin 7.3973/6.640 = 1.114 (the plain RMS over 2 s, 4.904 N·m and 1.508, took the motor
    as cooled at speed while it stands)."""
    w0 = 1420 * math.pi / 30
    m_n = 1100 / w0
    i = 17.194
    t_a, t_r, t_b = _phases(w0, 0.00416, 2 * m_n, 2.0, 5.0, math.pi / 2, i)
    assert (t_a, t_r, t_b) == (
        pytest.approx(0.11200, abs=1e-4),
        pytest.approx(0.07182, abs=1e-4),
        pytest.approx(0.10770, abs=1e-4),
    )
    rest = 2.0 - t_a - t_r - t_b
    num = (2 * m_n) ** 2 * (t_a + t_b) + (5 / i) ** 2 * t_r
    m_eq = math.sqrt(num / (0.75 * (t_a + t_b) + t_r + 0.5 * rest))
    assert m_eq == pytest.approx(6.640, abs=1e-3)
    assert math.sqrt(num / 2.0) == pytest.approx(4.904, abs=1e-3)
    rep = advise(parse_requirements({**_quarter(move_time_s=0.3), "duty": {"cycle_time_s": 2}}))
    duty = rep.design.duty
    assert duty.ratio == pytest.approx(i, abs=1e-3)
    assert duty.rms_torque_Nm == pytest.approx(m_eq, rel=1e-4)
    check = next(c for c in rep.checks if c.id == "duty_rms_torque")
    assert check.margin == pytest.approx(1.114, abs=1e-3)
    du04 = next(d for d in rep.decisions if d.id == "DU-04")
    assert "β0 = 0.5" in du04.rationale and "self-ventilated" in du04.rationale


def test_a_listed_motors_rms_torque_takes_it_cooled_at_speed():
    """A listed motor's cooling is not given: β0 = 1, the plain RMS over the cycle (C at 6.6232
    every 1.0229 s: 38.66 N·m, as above), and DU-04 says so."""
    rep = advise(parse_requirements(_motor_c(1.0229, 40.0)))
    assert rep.design.duty.rms_torque_Nm == pytest.approx(_c(6.6232, 1.0229)[1], abs=1e-3)
    du04 = next(d for d in rep.decisions if d.id == "DU-04")
    assert "(β0 = 1)" in du04.rationale and "not given" in du04.rationale


def _motor_a(move_time_s: float) -> dict:
    pos = {"travel_rad": 10.0, "load_inertia_kgm2": 5.0, "load_torque_Nm": 100.0}
    motor = {"name": "A", "speed_rad_s": 150.0, "inertia_kgm2": 0.01, "accel_torque_Nm": 20.0}
    pos |= {"move_time_s": move_time_s, "motors": [motor]}
    return {"application": {"kind": "positioning"}, "positioning": pos}


def test_the_fastest_time_stated_is_rounded_up_to_one_the_advisor_accepts():
    """Motor A alone: its fastest move, eq. (4) at i = 12.00309, takes 1.2058822512 s, which the
    report's six digits would write 1.20588 — a time A does not meet. It is stated 1.20589 (up),
    and asking for exactly that is met with margin 1.20589/1.2058823 > 1; 1.20588 is refused
    naming 1.20589 s."""
    t_a, t_r, t_b = _phases(150.0, 0.01, 20.0, 5.0, 100.0, 10.0, 12.00309)
    t = t_a + t_r + t_b
    assert t == pytest.approx(1.2058822512, abs=1e-9)
    assert f"{t:.6g}" == "1.20588" and 1.20588 < t <= 1.20589
    motion = advise(parse_requirements(_motor_a(1.3))).design.motion
    assert motion.fastest_move_time_s == 1.20589
    met = advise(parse_requirements(_motor_a(1.20589)))
    check = next(c for c in met.checks if c.id == "move_time")
    assert check.margin == pytest.approx(1.20589 / t, rel=1e-6) and check.margin > 1
    with pytest.raises(InfeasibleError) as err:
        advise(parse_requirements(_motor_a(1.20588)))
    assert "A, takes 1.20589 s" in " ".join(err.value.reasons)


def test_the_tutorials_shortest_time_is_met_and_a_shorter_one_named_apart():
    """The tutorial's quarter turn: 4A132M4 (11 kW, 1460 rpm, M_λ = 2·M_n) at its built
    i = 7.07141 with J0·1.3 = 0.052 takes
    0.16854364 s (a triangle: t = √(2θi·(ε1 + ε2)/(ε1·ε2)), the time the tutorial names,
    0.168544 s, is met; 0.1685 s is refused, the refusal saying 0.168544 s, not 0.1685 s twice."""
    w0, m_l = 1460 * math.pi / 30, 2.0 * 11000 / (1460 * math.pi / 30)  # M_λ = 2·M_n
    t_a, t_r, t_b = _phases(w0, 0.052, m_l, 2.0, 5.0, math.pi / 2, 7.07141)
    assert t_r == 0.0 and t_a + t_b == pytest.approx(0.1685436, abs=1e-7)
    assert advise(parse_requirements(_quarter(move_time_s=0.168544))).report.status == "feasible"
    with pytest.raises(InfeasibleError) as err:
        advise(parse_requirements(_quarter(move_time_s=0.1685)))
    assert "within positioning.move_time_s = 0.1685 s" in str(err.value)
    assert "4A132M4, takes 0.168544 s" in " ".join(err.value.reasons)


def test_a_triangular_moves_transient_time_is_the_move():
    """Seed 003's three motors over 0.2 rad: C at i = 13.6348 moves in a triangle, peak
    v = √(2θi·ε1ε2/(ε1 + ε2)) = 45.8 rad/s, 46 % of ω0, so it starts and stops for the whole
    move, t = v/ε1 + v/ε2 = 0.119027 s; eq. (3)'s start and stop to full speed, 0.2598 s, never
    happens and is not stated."""
    req = {
        "application": {"kind": "positioning"},
        "positioning": {
            "travel_rad": 0.2,
            "load_inertia_kgm2": 5.0,
            "load_torque_Nm": 100.0,
            "motors": [
                {"name": "A", "speed_rad_s": 150, "inertia_kgm2": 0.01, "accel_torque_Nm": 20},
                {"name": "B", "speed_rad_s": 300, "inertia_kgm2": 0.004, "accel_torque_Nm": 12},
                {"name": "C", "speed_rad_s": 100, "inertia_kgm2": 0.03, "accel_torque_Nm": 45},
            ],
        },
    }
    t_a, t_r, t_b = _phases(100.0, 0.03, 45.0, 5.0, 100.0, 0.2, 13.6348)
    assert t_r == 0.0 and t_a + t_b == pytest.approx(0.119027, abs=1e-6)
    motion = advise(parse_requirements(req)).design.motion
    assert motion.profile_actual == "triangular"
    assert motion.transient_time_s == motion.move_time_s
    assert motion.transient_time_s == pytest.approx(0.119027, abs=1e-6)
    assert "0.119 s" in headline(advise(parse_requirements(req)))


def test_a_least_rms_a_hair_above_the_rating_reads_above_it():
    """Rated 14.99684 N·m, cycle 2 s: the least M_eq over the ratios that fit, by a dense scan
    by hand, is 14.99699 N·m near i = 19.01, above the rating by 1e-5 relative: refused. At
    four digits both read 15, which says 'at least 15 against 15'; the two are written with
    the digits that tell them apart."""
    rms_min, i_min = _hand_least_rms(2.0, 17.0, 21.0)
    assert rms_min == pytest.approx(14.99699, abs=2e-5)
    assert 14.99684 < rms_min and 18.9 < i_min < 19.1
    with pytest.raises(InfeasibleError) as err:
        advise(parse_requirements(_motor_c(2.0, 14.99684)))
    why = " ".join(err.value.reasons)
    assert "at least 14.997 N·m at any ratio" in why
    assert "against its rated torque 14.9968 N·m" in why
