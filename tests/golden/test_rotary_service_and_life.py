"""The rotary drive as a reviewer checks it: the reducer under its load spectrum, the output
bearing under an external load, the holding device against the emergency stop, the regenerated energy,
and the service factor — each against a published or hand-worked number."""

import math
import tomllib

import pytest
from helpers import EXAMPLES

from advisor.calc import bearing_life, load_spectrum, regen, wavegear
from advisor.calc.duty import Phase
from advisor.cli import main
from advisor.core.engine import advise
from advisor.core.errors import InfeasibleError
from advisor.core.reading import parse_requirements
from catalogs import load_catalogs


def _req(name: str, **tables) -> dict:
    data = tomllib.loads((EXAMPLES / name).read_text(encoding="utf-8"))
    for table, values in tables.items():
        data[table] = {**data.get(table, {}), **values}
    return data


def _advise(data: dict):
    return advise(parse_requirements(data))


def _check(report, check_id: str):
    return next(c for c in report.checks if c.id == check_id)


# ------------------------------------------------------------------ item 2: load spectrum
def test_honpine_fsg25_cube_mean_torque_is_89_Nm():
    """Honpine's FSG-25 example: the revolutions weigh each phase (n·t), so the stop phase
    (0 rpm) counts nothing. By hand:
    Σ n·t·T³ = 10·0.2·150³ + 20·3·82³ + 10·0.3·130³ + 0 = 6 750 000 + 33 082 080 + 6 591 000
             = 46 423 080; Σ n·t = 2 + 60 + 3 = 65; T_av = ∛(714 201.2) = 89.39 N·m (89 printed)."""
    phases = [
        load_spectrum.Load(150, 10, 0.2),
        load_spectrum.Load(82, 20, 3),
        load_spectrum.Load(130, 10, 0.3),
        load_spectrum.Load(0, 0, 0.2),
    ]
    by_hand = (46_423_080 / 65) ** (1 / 3)
    assert load_spectrum.cube_mean_torque(phases) == pytest.approx(by_hand, rel=1e-12)
    assert round(load_spectrum.cube_mean_torque(phases)) == 89
    # the mean output speed over the whole cycle, rest included: 65/3.7 = 17.57 rpm
    assert load_spectrum.mean_speed_rpm(phases) == pytest.approx(65 / 3.7, rel=1e-12)
    assert load_spectrum.max_speed_rpm(phases) == 20
    assert load_spectrum.repeated_peak_torque(phases) == 150
    # weighting by time alone would give a different, wrong mean: ∛((0.2·150³ + 3·82³ +
    # 0.3·130³)/3.7) = 88.0 — the test can tell the two apart
    by_time = ((0.2 * 150**3 + 3 * 82**3 + 0.3 * 130**3) / 3.7) ** (1 / 3)
    assert abs(by_time - by_hand) > 1.0


def test_wave_generator_life_by_harmonic_drives_formula():
    """HD CSD-2A §4.1.2: L50 = 35 000·(2000/n_av)·(T_N/T_av)³; at T_N and 2000 rpm it is 35 000 h;
    at half the torque and 1000 rpm 35 000·2·8 = 560 000 h; rollers take 10/3."""
    assert load_spectrum.rolling_life_h(100.0, 100.0, 2000.0) == pytest.approx(35000.0)
    assert load_spectrum.rolling_life_h(100.0, 50.0, 1000.0) == pytest.approx(560000.0)
    assert load_spectrum.rolling_life_h(
        100.0, 50.0, 2000.0, load_spectrum.LIFE_EXPONENT["roller"]
    ) == pytest.approx(35000.0 * 2 ** (10 / 3))
    assert load_spectrum.L10_PER_L50 == 0.2


def test_peak_allowances_are_csf_25_50s_ratios():
    assert load_spectrum.REPEATED_PEAK_FACTOR == pytest.approx(98 / 39)
    assert load_spectrum.MOMENTARY_PEAK_FACTOR == pytest.approx(186 / 39)


def test_rudder_working_point_reports_the_spectrum_and_its_checks():
    """Seed 000's rudder (1620 N·m, 5 rpm, two stages q = 20 × 50 at 5000 rpm): the working
    point is the whole spectrum. Repeated peak 1620 against 2.513·1620 = 4071 N·m; the output
    stage turns its input at 5·20 = 100 rpm, the input stage at 5000 rpm: L50 = 35 000·2000/5000
    = 14 000 h, L10 = 2800 h, the shortest."""
    r = _advise(_req("rudder_actuator.toml"))
    load = r.design.reducer_load
    assert load.basis.startswith("working point")
    assert load.mean_torque_Nm == pytest.approx(1620)
    assert load.rated_torque_Nm == pytest.approx(1620)
    assert _check(r, "stage_repeated_peak").margin == pytest.approx(98 / 39)
    assert _check(r, "stage_momentary_peak").margin == pytest.approx(186 / 39)
    assert not any(c.id == "stage_average_torque" for c in r.checks)  # T_av = T_N by sizing
    out, inp = load.stages[0], load.stages[-1]
    assert (out.position, inp.position) == ("output", "input")
    assert out.mean_input_speed_rpm == pytest.approx(100.0)
    assert inp.mean_input_speed_rpm == pytest.approx(5000.0)
    assert inp.life_L10_h == pytest.approx(35000 * 2000 / 5000 / 5)
    # the new checks leave the seed's design unchanged
    assert r.design.motor.speed_rpm == 5000
    assert r.design.gearbox.total_ratio == pytest.approx(1000)


def test_required_life_is_checked_on_the_shortest_stage():
    r = _advise(_req("rudder_actuator.toml", design={"life_h": 2000}))
    c = _check(r, "stage_life")
    assert c.value == pytest.approx(2800.0)
    assert c.margin == pytest.approx(1.4)
    with pytest.raises(InfeasibleError):
        _advise(_req("rudder_actuator.toml", design={"life_h": 5000}))


def test_rudder_cycle_cube_mean_by_hand():
    """The steering cycle of rudder_actuator_duty: turns of 25° in 1 s with 10 % ramps (output
    speed ω = 0.43633/0.9 = 0.48481 rad/s = 4.6296 rpm, ε = 4.8481 rad/s², J_L·ε = 9.696 N·m).
    Turning phases: 1209.7 and 1190.3 N·m for 0.1 s at 2.3148 rpm, 1200 N·m for 0.8 s at
    4.6296 rpm, twice (with the load, the torques are negative; |T| counts); the hold at
    standstill counts nothing. T_av = ∛(Σ n·t·|T|³/Σ n·t)."""
    r = _advise(_req("rudder_actuator_duty.toml"))
    w = math.radians(25) / 0.9
    n, ja = w * 30 / math.pi, 2.0 * w / 0.1
    ph = [(1200 + ja, n / 2, 0.1), (1200, n, 0.8), (1200 - ja, n / 2, 0.1)] * 2
    t_av = (sum(s * t * T**3 for T, s, t in ph) / sum(s * t for _, s, t in ph)) ** (1 / 3)
    load = r.design.reducer_load
    assert load.mean_torque_Nm == pytest.approx(t_av, rel=1e-9)
    assert load.repeated_peak_torque_Nm == pytest.approx(1620)  # the hold
    c = _check(r, "stage_average_torque")
    assert c.margin == pytest.approx(1620 / t_av, rel=1e-9)


# ------------------------------------------------------------------ item 3: output bearing
def test_skf_calculation_example_1_6309():
    """SKF General Catalogue, calculation example 1: 6309, F_r = 10 kN, 3000 r/min,
    C = 55.3 kN → L10 = (55.3/10)³ = 169 million revolutions, L10h = 940 h."""
    b = next(x for x in load_catalogs(None).bearings if x.designation == "6309")
    assert (b.d_mm, b.D_mm, b.B_mm, b.C_kN, b.C0_kN, b.Pu_kN) == (45, 100, 25, 55.3, 31.5, 1.34)
    eq = bearing_life.equivalent_load(b, 10000.0, 0.0)
    assert eq.load_N == 10000.0
    l10 = bearing_life.rating_life_Mrev(b.C_kN * 1e3, eq.load_N)
    assert round(l10) == 169
    assert bearing_life.hours_from_Mrev(l10, 3000.0) == pytest.approx(940, abs=1)


def test_skf_example_end_to_end_as_the_output_bearing():
    data = _req(
        "rudder_actuator.toml",
        output_load={"radial_N": 10000, "speed_rpm": 3000, "bearing": "6309"},
        design={"life_h": 900},
    )
    r = _advise(data)
    ob = r.design.output_bearing
    assert ob.designation == "6309" and ob.chosen == "given"
    assert ob.life_L10_Mrev == pytest.approx(5.53**3)
    assert ob.life_L10_h == pytest.approx(5.53**3 * 1e6 / (60 * 3000))
    assert round(ob.life_L10_h, -1) == 940
    assert _check(r, "output_bearing_life").margin == pytest.approx(ob.life_L10_h / 900)
    assert _check(r, "output_bearing_static").value == pytest.approx(31.5 / 10)  # C0/Fr


def test_tilting_moment_goes_to_a_pair_and_the_service_factor_to_the_load():
    """A pair 100 mm apart: F_r/2 + M/a = 2000 + 200/0.1 = 4000 N, × f_B 1.5 = 6000 N on the
    6309, purely radial: L10 = (55.3/6)³ = 782.9 million revolutions."""
    data = _req(
        "rudder_actuator.toml",
        output_load={
            "radial_N": 4000,
            "tilting_moment_Nm": 200,
            "bearing_spacing_mm": 100,
            "bearing": "6309",
        },
        design={"service_factor": 1.5},
    )
    ob = _advise(data).design.output_bearing
    assert ob.radial_N == pytest.approx(6000.0)
    assert ob.life_L10_Mrev == pytest.approx((55.3 / 6) ** 3)
    assert ob.speed_rpm == pytest.approx(5.0)  # rotary.speed_rpm at the working point


def test_automatic_bearing_is_the_lightest_that_lives():
    data = _req(
        "rudder_actuator.toml",
        output_load={"radial_N": 10000, "speed_rpm": 3000},
        design={"life_h": 900},
    )
    ob = _advise(data).design.output_bearing
    assert ob.chosen == "automatic"
    cat = load_catalogs(None)
    chosen = next(b for b in cat.bearings if b.designation == ob.designation)
    for b in cat.bearings:  # no lighter deep-groove bearing reaches 900 h
        if b.type == "deep_groove" and (b.mass_kg or 0) < (chosen.mass_kg or 0):
            assert bearing_life.hours_from_Mrev((b.C_kN * 1e3 / 1e4) ** 3, 3000) < 900
    assert ob.life_L10_h >= 900


def test_a_moment_without_a_pair_is_an_input_error(tmp_path, capsys):
    data = _req("rudder_actuator.toml", output_load={"radial_N": 100, "tilting_moment_Nm": 5})
    text = (EXAMPLES / "rudder_actuator.toml").read_text(encoding="utf-8")
    f = tmp_path / "r.toml"
    f.write_text(text + "\n[output_load]\nradial_N = 100\ntilting_moment_Nm = 5\n")
    assert main(["--batch", str(f), "-o", str(tmp_path / "o.toml")]) == 2
    assert "bearing_spacing_mm" in capsys.readouterr().err
    assert data["output_load"]["tilting_moment_Nm"] == 5


# ------------------------------------------------------------------ item 4: holding device
def test_the_device_holds_the_emergency_stop():
    """Seed 004's valve (1000 N·m, q = 600, η = 0.8 → 2.083 N·m at the motor side): an
    emergency stop of 2500 N·m at the output sizes the device for 2500/480 = 5.208 N·m, and
    its basis says so; the stages take 2500 against 186/39·1000 = 4769 N·m."""
    base = _advise(_req("valve_actuator_hold.toml"))
    q_eta = base.design.gearbox.total_ratio * base.design.gearbox.efficiency
    r = _advise(_req("valve_actuator_hold.toml", rotary={"emergency_stop_torque_Nm": 2500}))
    assert r.design.one_way.torque_Nm == pytest.approx(2500 / q_eta)
    assert "sized for the emergency stop's 2500 N·m" in r.design.one_way.basis
    # the sizing is stated, not restated as a check (it could only say 1.000, a knife edge)
    assert not any(c.id == "one_way_holds_emergency_stop" for c in r.checks)
    # and the placement decision states the device's own torque
    ow1 = next(d for d in r.decisions if d.id == "OW-01")
    assert ow1.inputs["torque_Nm"] == pytest.approx(r.design.one_way.torque_Nm, rel=1e-5)
    assert _check(r, "stage_momentary_peak").margin == pytest.approx(186 / 39 * 1000 / 2500)
    # without an emergency stop the device is the seed's, and no check restates its sizing
    assert base.design.one_way.torque_Nm == pytest.approx(1000 / q_eta)
    assert not any(c.id == "one_way_holds_emergency_stop" for c in base.checks)


# ------------------------------------------------------------------ item 5: service factor
def test_service_factor_sizes_the_stages_not_the_motor():
    """f_B = 1.5: eq. (16) sizes the output stage for 1.5·1620 = 2430 N·m, so its rolling
    bodies grow by ∛1.5 = 1.1447; the motor's torque and losses (thermal) stay."""
    base = _advise(_req("rudder_actuator.toml"))
    r = _advise(_req("rudder_actuator.toml", design={"service_factor": 1.5}))
    s0, s1 = base.design.gearbox.stages[-1], r.design.gearbox.stages[-1]
    assert s1.torque_Nm == pytest.approx(2430)
    assert s1.rolling_body_diameter_mm == pytest.approx(
        float(wavegear.rolling_body_diameter(2430, s1.ratio, s1.rows)), rel=1e-12
    )
    assert s1.rolling_body_diameter_mm / s0.rolling_body_diameter_mm == pytest.approx(
        1.5 ** (1 / 3)
    )
    assert r.design.motor.torque_Nm == pytest.approx(base.design.motor.torque_Nm)
    # the check states the factored torque: value 1.5·1620 = 2430 N·m against
    # 98/39·2430 = 6106.2 N·m, margin = limit/value = 98/39 (value 1620 and a separate
    # factor before, margin limit/(factor·value))
    c = _check(r, "stage_repeated_peak")
    assert (c.value, c.limit) == pytest.approx((1.5 * 1620, 98 / 39 * 2430))
    assert c.margin == pytest.approx(c.limit / c.value) == pytest.approx(98 / 39)
    assert c.factor is None and "× f_B" in c.name and "f_B = 1.5" in c.name


def test_every_rotary_check_states_margin_as_limit_over_value():
    """valve_actuator_hold under f_B = 1.5, an emergency stop of 2500 N·m, a required life
    and an output bearing: each check's margin is limit/value (an upper bound) or
    value/limit (static safety, life: lower bounds), with no per-check factor. By hand the
    momentary peak: value 1.5·2500 = 3750 N·m against 186/39·T_N, T_N = 1.5·1000 = 1500 N·m
    by eq. (16): 7153.85 N·m, margin 7153.85/3750 = 1.90769 (the report said value 2500,
    the same margin, and factor = 1.5)."""
    data = _req(
        "valve_actuator_hold.toml",
        rotary={"emergency_stop_torque_Nm": 2500},
        design={"service_factor": 1.5, "life_h": 3000},
        output_load={"radial_N": 2000, "bearing": "6309"},
    )
    r = _advise(data)
    c = _check(r, "stage_momentary_peak")
    assert c.value == pytest.approx(3750.0)
    assert c.limit == pytest.approx(186 / 39 * 1500)
    assert c.margin == pytest.approx(186 / 39 * 1500 / 3750) == pytest.approx(1.90769, rel=1e-5)
    for c in r.checks:
        assert c.factor is None, c.id
        upper = c.limit / c.value if c.value else math.inf
        lower = c.value / c.limit if c.limit else math.inf
        assert c.margin == pytest.approx(upper, rel=1e-9) or c.margin == pytest.approx(
            lower, rel=1e-9
        ), c.id


def test_the_emergency_stop_passes_a_device_at_the_output():
    """A worm at the output sits between the load and the reducer: the stop's torque at the
    load reaches the output stage as the device's input torque M/η_d, as T_N does
    (seed 004). Rudder at 300 N·m, stop 600 N·m: T_N = 300/η_d, the momentary peak
    600/η_d = 600/0.33112 = 1812.0 N·m, margin = 186/39·(300/η_d)/(600/η_d) = 186/78 =
    2.38462 whatever η_d (the stop raw against T_N gave 186/39·300/(600·η_d) = 7.20)."""
    data = _req(
        "rudder_actuator.toml",
        application={"hold_without_power": True},
        rotary={"torque_Nm": 300, "emergency_stop_torque_Nm": 600},
        motor={"frame": "auto"},
        one_way={"type": "worm", "location": "output_side"},
    )
    r = _advise(data)
    load = r.design.reducer_load
    eta_d = 300 / load.rated_torque_Nm
    assert eta_d == pytest.approx(0.33112, rel=1e-4)  # the worm's driving efficiency
    assert load.momentary_peak_torque_Nm == pytest.approx(600 / eta_d)
    assert load.momentary_peak_torque_Nm == pytest.approx(1812.0, rel=1e-4)
    assert "through the worm at the output" in load.momentary_peak_basis
    c = _check(r, "stage_momentary_peak")
    assert c.value == pytest.approx(600 / eta_d)
    assert c.margin == pytest.approx(186 / 78) == pytest.approx(2.38462, rel=1e-5)


def test_a_stop_below_the_working_torque_is_taken_at_the_repeated_peak():
    """A momentary peak is at least the repeated peak: valve 1000 N·m with a stop of 10 N·m
    is checked at 1000 N·m (f_B = 1.5: value 1500 N·m against 186/39·1500 = 7153.85 N·m,
    margin 186/39 = 4.76923; the 10 N·m gave margin 477), and the basis says why."""
    data = _req(
        "valve_actuator_hold.toml",
        rotary={"emergency_stop_torque_Nm": 10},
        design={"service_factor": 1.5},
    )
    r = _advise(data)
    assert r.design.reducer_load.momentary_peak_torque_Nm == pytest.approx(1000.0)
    assert "below the repeated peak" in r.design.reducer_load.momentary_peak_basis
    c = _check(r, "stage_momentary_peak")
    assert (c.value, c.limit) == pytest.approx((1500.0, 186 / 39 * 1500))
    assert c.margin == pytest.approx(186 / 39) == pytest.approx(4.76923, rel=1e-5)


def test_the_datasheet_names_the_checks_of_the_stop_the_life_and_f_B():
    """The required-and-achieved rows of the emergency-stop torque, the required life, the
    service factor and the output load name the checks that cover them (each said "no check
    covers this requirement"). valve_actuator_hold, f_B = 1.5, stop 2500 N·m, 3000 h: the
    stop's row is stage_momentary_peak, 3750 against 7154 N·m, 1.908 (by hand above)."""
    from advisor.datasheet import render

    data = _req(
        "valve_actuator_hold.toml",
        rotary={"emergency_stop_torque_Nm": 2500},
        design={"service_factor": 1.5, "life_h": 3000},
        output_load={"radial_N": 2000, "bearing": "6309"},
    )
    md = render(_advise(data), "md")
    rows = {
        label: next(x for x in md.splitlines() if x.startswith(f"| {label}"))
        for label in ("Emergency-stop torque", "Required life", "Service factor", "Radial load")
    }
    for label, line in rows.items():
        assert "no check covers this requirement" not in line, label
    assert "| 3750 against 7154 N·m | 1.908 |" in rows["Emergency-stop torque"]


# ------------------------------------------------------------------ item 6: regeneration
def test_bus_and_resistor_by_hand():
    """A 0.1 s braking from 500 rad/s at −2 N·m gives back 2·250·0.1 = 50 J at a peak of
    1000 W; a 2 s cycle. The bus 300 → 400 V takes 50 J with C = 2·50/(400² − 300²) = 1429 µF;
    a 470 µF bus takes ½·470e-6·70 000 = 16.45 J, the resistor the other 33.55 J: 16.78 W on
    average, 1000 W peak, at most 400²/1000 = 160 Ω."""
    phases = [
        Phase("accelerate", 0.1, 0.0, 500.0, 2.0),
        Phase("run", 1.0, 500.0, 500.0, 0.5),
        Phase("brake", 0.1, 500.0, 0.0, -2.0),
        Phase("rest", 0.8, 0.0, 0.0, 0.0),
    ]
    (b,) = regen.brakings(phases)
    assert b.energy_J == pytest.approx(50.0)
    assert b.peak_power_W == pytest.approx(1000.0)
    assert regen.capacitance_for_F(50.0, 300, 400) == pytest.approx(100 / 70000)
    bus = regen.bus_energy_J(470e-6, 300, 400)
    assert bus == pytest.approx(16.45)
    res = regen.braking_resistor([b], 2.0, bus, 400)
    assert res.needed
    assert res.average_power_W == pytest.approx((50 - 16.45) / 2.0)
    assert res.peak_power_W == pytest.approx(1000.0)
    assert res.max_resistance_ohm == pytest.approx(160.0)
    assert not regen.braking_resistor([b], 2.0, 60.0, 400).needed


def test_rudder_cycle_regeneration_matches_the_duty():
    r = _advise(_req("rudder_actuator_duty.toml", drive={"bus_capacitance_uF": 2000}))
    g = r.design.regeneration
    assert g.regenerated_per_cycle_J == pytest.approx(r.design.duty.regenerated_per_cycle_J)
    assert g.bus_energy_J == pytest.approx(0.5 * 2000e-6 * (400**2 - 300**2))
    assert g.capacitance_for_largest_uF == pytest.approx(
        2 * g.largest_braking_J / (400**2 - 300**2) * 1e6
    )
    assert g.resistor_average_power_W == pytest.approx(
        (g.largest_braking_J - g.bus_energy_J) * g.brakings_per_cycle / r.design.duty.cycle_time_s
    )


def test_bus_voltages_must_rise(tmp_path, capsys):
    text = (EXAMPLES / "rudder_actuator_duty.toml").read_text(encoding="utf-8")
    f = tmp_path / "r.toml"
    f.write_text(text + "\n[drive]\nbus_voltage_V = 400\nbus_max_voltage_V = 300\n")
    assert main(["--batch", str(f), "-o", str(tmp_path / "o.toml")]) == 2
    assert "bus_max_voltage_V" in capsys.readouterr().err
