"""What rests on a bearing row's estimated fields (seed 002): the warning names the results the
estimates reach, checked against the results that move when the estimate is replaced."""

import math

import pytest

from advisor.applications.spinning_rotor.advice import estimate_warning
from advisor.applications.spinning_rotor.steps import bearing_rating, chosen_bearing, rotor_model
from advisor.calc.rotor import gyroscopic_loads, gyroscopic_moment, steady_torques
from advisor.core.reading import parse_requirements
from catalogs import load_catalogs

SLOW_6200 = {
    "application": {"kind": "spinning_rotor"},
    "rotor": {
        "mass_kg": 0.56,
        "angular_momentum_kgm2_s": 1.814,
        "speed_rad_s": 1000,
        "bearing": "6200",
        "ball_plane_to_cg_mm": 10,
        "slew_rate_rad_s": 0.0765,
        "run_up_time_s": 30,
        "contact_angle_deg": 12,
        "aero": {"loss_W": 32.15},
    },
}


def _results(req, cat, b, angle):
    r = req.rotor
    rotor = rotor_model(req, b, angle)
    moment = gyroscopic_moment(r.angular_momentum, r.slew_rate_rad_s, math.pi / 2)
    loads = gyroscopic_loads(rotor, moment, r.speed_rad_s)
    return loads, steady_torques(rotor, loads, r.speed_rad_s), bearing_rating(req, cat, b, loads)


def test_the_ball_set_moves_eq_4_and_the_drive_not_the_life_or_skf():
    """The 6200 (10×30 mm) has no published ball set: the loader takes D_pw = (d + D)/2 = 20 mm,
    D_w = 0.3·(D − d) = 6.0 mm. Give it 4.762 mm balls (7 of them) at the same pitch instead.
    Eq. (4)'s radial term goes as 1 + 2·r_B/D_w with r_B = r − D_w/2:
    estimated 1 + 2·(10 − 3)/6 = 3.3333, the other set 1 + 2·(10 − 2.381)/4.762 = 4.2000,
    a ratio 1.2600. The life (C and the loads: the pitch radius r of eq. (3) is the same) and the
    SKF friction (d, D, C0 and the loads) do not move; the steady torque does."""
    req, cat = parse_requirements(SLOW_6200), load_catalogs()
    b, angle = chosen_bearing(req, cat)
    assert (b.pitch_diameter_mm, b.ball_diameter_mm) == (20.0, pytest.approx(6.0))
    other = b._replace(ball_diameter_mm=4.762, ball_count=7, estimated=())
    loads, steady, rating = _results(req, cat, b, angle)
    loads2, steady2, rating2 = _results(req, cat, other, angle)
    ratio = loads2.friction_slewing.radial_Nm / loads.friction_slewing.radial_Nm
    assert ratio == pytest.approx(4.2000 / 3.3333, rel=1e-4)
    assert steady2.slewing_Nm > 1.05 * steady.slewing_Nm  # the drive rests on the ball set
    assert rating2.life_h == rating.life_h
    assert rating2.skf_slewing.total_Nm == rating.skf_slewing.total_Nm
    text = estimate_warning(b)
    assert "the eq. (4) friction rests on the ball set" in text
    assert "the steady power and the drive torque" in text
    assert "the life and the SKF friction rest on them" not in text


def test_estimated_ratings_name_the_life_and_the_static_safety():
    """7000 CD's C and C0 are estimated (ISO 281/76 formulas from the seed's geometry): the
    life is 10⁶/(60·n)·(C/P)³ with X/Y read at Fa/C0 (15°), the static safety C0/P0; the SKF
    friction of an angular-contact bearing reads neither, and eq. (4) neither."""
    cat = load_catalogs()
    text = estimate_warning(cat.bearing("7000 CD"))
    assert text.endswith("the life and the static safety rest on C_kN and C0_kN")
    assert "eq. (4)" not in text and "SKF" not in text
