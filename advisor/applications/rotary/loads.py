"""The checks a reviewer of a rotary drive asks for first (issue 26): the reducer under its
load spectrum, the output bearing under an external load, and where the energy the motor
gives back goes. Orchestration only: :mod:`advisor.calc.load_spectrum`,
:mod:`advisor.calc.bearing_life` and :mod:`advisor.calc.regen` compute.

Capacities. Each wave-gear stage is sized by seed 000's eq. (16) for a torque: its rated
torque T_N (the output torque × the service factor at the output stage, that torque's share
M/(q·η) at the stages before it). Against T_N stand the cube-mean torque T_av (the rated
torque is the limit for the mean), the repeated peak of the cycle (limit 98/39 = 2.51·T_N) and
the momentary peak of an emergency stop (limit 186/39 = 4.77·T_N): the ratios of Harmonic
Drive's CSF-25-50 (rated 39, repeated peak 98, momentary peak 186 N·m). Every stage carries
the same share of its T_N (each sized for its share), so the output stage's figures hold for
all; the life differs by the input speed and is computed per stage.

Life model (stated): the rolling elements of a stage live L50 = 35 000 h at T_N and 2000 rpm
input, as Harmonic Drive rates its CSF wave generator bearing (the seed gives eq. (16) no
life), scaled by ISO 281's exponent p (3 balls, 10/3 rollers): L50 = 35 000·(2000/n_in,av)·
(T_N/(f_B·T_av))^p, L10 = L50/5.
"""

import math

from advisor.applications.rotary.report import (
    OutputBearingOut,
    ReducerLoadOut,
    RegenerationOut,
    StageLifeOut,
)
from advisor.calc import bearing_life as bl
from advisor.calc import load_spectrum as ls
from advisor.calc import reducer as rd
from advisor.calc import regen as rg
from advisor.calc.checks import Check
from advisor.calc.duty import Phase
from advisor.calc.service_factor import ServiceFactor
from advisor.core.cite import cite
from advisor.core.errors import InputError

HD_RATIOS = cite("hd-csf-25-50")
HD_LIFE = cite("hd-csd-2a", "§4.1.2, eqs. 20.2, 20.3")
HONPINE = cite("honpine-harmonic", "step 2")
SEED_16 = cite("seed-000", "eq. (16)")
RPM = 30.0 / math.pi


def momentary_torque(req) -> tuple[float, str]:
    """The emergency stop's torque at the output and where it comes from."""
    given = req.rotary.emergency_stop_torque_Nm
    if given is not None:
        return given, "rotary.emergency_stop_torque_Nm (given)"
    return req.rotary.torque_Nm, "not given: rotary.torque_Nm taken as the momentary peak"


def reducer_load(
    req, design: rd.Reducer, loads: list[ls.Load], basis: str, sf: ServiceFactor, k_rb: str
) -> tuple[ReducerLoadOut, list[Check], list[str]]:
    """The spectrum's figures at the output, the stages' lives, the checks of item 2."""
    f = sf.value
    out_stage = design.stages[-1]
    rated = out_stage.torque_Nm
    t_av = ls.cube_mean_torque(loads)
    t_rep = ls.repeated_peak_torque(loads)
    t_mom, mom_basis = momentary_torque(req)
    n_av, n_max = ls.mean_speed_rpm(loads), ls.max_speed_rpm(loads)
    p = ls.LIFE_EXPONENT[k_rb]
    stages, ratio_to_output = [], 1.0
    for s in reversed(design.stages):  # output first
        ratio_to_output *= s.ratio
        share = s.torque_Nm / rated  # this stage's share of the output torque (eq. (16))
        n_in = n_av * ratio_to_output
        l50 = ls.rolling_life_h(s.torque_Nm, f * t_av * share, n_in, p)
        stages.append(
            StageLifeOut.make(
                position=s.position,
                rated_torque_Nm=s.torque_Nm,
                mean_input_speed_rpm=n_in,
                max_input_speed_rpm=n_max * ratio_to_output,
                life_L50_h=l50,
                life_L10_h=l50 * ls.L10_PER_L50,
            )
        )
    motor_speed = n_max * ratio_to_output  # the input stage's top speed: the motor's
    stops_allowed = ls.momentary_peak_count_allowed(motor_speed, req.rotary.emergency_stop_time_s)
    avg_limit = rated
    rep_limit = ls.REPEATED_PEAK_FACTOR * rated
    mom_limit = ls.MOMENTARY_PEAK_FACTOR * rated
    where = f"output stage, T_N = {rated:.4g} N·m by eq. (16); f_B = {f:g}"
    checks = []
    if basis == "duty cycle":  # at the working point T_av is the sizing torque itself
        checks.append(
            Check(
                "stage_average_torque",
                f"cube-mean torque T_av × f_B within the rated torque ({where})",
                t_av,
                avg_limit,
                "N·m",
                avg_limit / (f * t_av) if t_av > 0 else math.inf,
                HONPINE + SEED_16,
                f,
            )
        )
    checks += [
        Check(
            "stage_repeated_peak",
            f"repeated peak torque × f_B within 98/39 × T_N ({where})",
            t_rep,
            rep_limit,
            "N·m",
            rep_limit / (f * t_rep) if t_rep > 0 else math.inf,
            HD_RATIOS + SEED_16,
            f,
        ),
        Check(
            "stage_momentary_peak",
            f"emergency-stop torque × f_B within 186/39 × T_N ({where})",
            t_mom,
            mom_limit,
            "N·m",
            mom_limit / (f * t_mom),
            (HD_RATIOS + SEED_16).with_note(mom_basis),
            f,
        ),
    ]
    life_h = req.design.life_h
    warnings = []
    if life_h is not None:
        worst = min(stages, key=lambda s: s.life_L10_h)
        checks.append(
            Check(
                "stage_life",
                f"L10 life of the {worst.position} stage's rolling elements (the shortest) "
                "within the required life",
                worst.life_L10_h,
                life_h,
                "h",
                worst.life_L10_h / life_h,
                HD_LIFE + cite("iso-281", "eq. (1)"),
            )
        )
    stops = req.rotary.emergency_stops
    if stops is not None and stops > stops_allowed:
        warnings.append(
            f"reducer: {stops} emergency stops over the life against about "
            f"{stops_allowed:.3g} a strain-wave gear's momentary peak allows at "
            f"{motor_speed:.4g} rpm input for {req.rotary.emergency_stop_time_s:g} s each "
            "(10⁴ flexings; Harmonic Drive's form as quoted, not verified in its own text)"
        )
    out = ReducerLoadOut.make(
        basis=basis,
        service_factor=f,
        service_factor_basis=sf.basis,
        mean_torque_Nm=t_av,
        mean_output_speed_rpm=n_av,
        max_output_speed_rpm=n_max,
        repeated_peak_torque_Nm=t_rep,
        momentary_peak_torque_Nm=t_mom,
        momentary_peak_basis=mom_basis,
        rated_torque_Nm=rated,
        average_torque_limit_Nm=avg_limit,
        repeated_peak_limit_Nm=rep_limit,
        momentary_peak_limit_Nm=mom_limit,
        emergency_stop_time_s=req.rotary.emergency_stop_time_s,
        emergency_stops=stops,
        emergency_stops_allowed=stops_allowed,
        life_model=(
            f"L50 = 35 000 h·(2000 rpm/n_in,av)·(T_N/(f_B·T_av))^{p:.4g}, L10 = L50/5: "
            "Harmonic Drive's CSF rating of its wave generator bearing, ISO 281's exponent "
            f"for {k_rb}s"
        ),
        required_life_h=life_h,
        stages=stages,
        phases_torque_Nm=[x.torque_Nm for x in loads],
        phases_speed_rpm=[x.speed_rpm for x in loads],
        phases_time_s=[x.time_s for x in loads],
    )
    return out, checks, warnings


def output_bearing(
    req, cat, design: rd.Reducer, speed_rpm: float, sf: ServiceFactor
) -> tuple[OutputBearingOut, list[Check]]:
    """The output bearing under ``[output_load]`` by ISO 281 (item 3), the given one or the
    lightest deep-groove bearing of the catalog that fits within the reducer's outer
    diameter and gives design.life_h."""
    ol = req.output_load
    f = sf.value
    radial, axial = bl.pair_loads(
        ol.radial_N, ol.axial_N, ol.tilting_moment_Nm, ol.bearing_spacing_mm
    )
    radial, axial = f * radial, f * axial
    n = ol.speed_rpm or speed_rpm
    life_h = req.design.life_h
    if ol.bearing == "auto":
        b = _auto_bearing(cat, radial, axial, n, life_h, design.outer_diameter_mm)
        chosen = "automatic"
    else:
        found = [x for x in cat.bearings if x.designation == ol.bearing]
        if not found:
            known = ", ".join(x.designation for x in cat.bearings)
            raise InputError(
                f"output_load.bearing = {ol.bearing!r}: not in the bearing catalog ({known})"
            )
        b, chosen = found[0], "given"
    eq = bl.equivalent_load(b, radial, axial)
    l10 = bl.rating_life_Mrev(b.C_kN * 1e3, eq.load_N)
    l10h = bl.hours_from_Mrev(l10, n)
    s0 = bl.static_safety(b, radial, axial)
    src = cat.cite_rows(cat.bearing_sources, b.source)
    checks = [
        Check(
            "output_bearing_static",
            f"static safety s0 = C0/P0 of the output bearing {b.designation} (loads × f_B)",
            s0,
            1.0,
            "",
            s0,
            cite("iso-76") + src,
        ),
        Check(
            "output_bearing_speed",
            f"output speed within the limiting speed of {b.designation}",
            n,
            b.limiting_speed_rpm,
            "rpm",
            b.limiting_speed_rpm / n,
            src,
        ),
    ]
    if life_h is not None:
        checks.append(
            Check(
                "output_bearing_life",
                f"basic rating life L10h of the output bearing {b.designation} (loads × f_B)",
                l10h,
                life_h,
                "h",
                l10h / life_h,
                cite("iso-281", "eq. (1)") + src,
            )
        )
    out = OutputBearingOut.make(
        designation=b.designation,
        chosen=chosen,
        arrangement="one bearing"
        if ol.bearing_spacing_mm is None
        else f"a pair {ol.bearing_spacing_mm:g} mm apart",
        radial_N=radial,
        axial_N=axial,
        service_factor=f,
        equivalent_load_N=eq.load_N,
        X=eq.X,
        Y=eq.Y,
        C_kN=b.C_kN,
        C0_kN=b.C0_kN,
        speed_rpm=n,
        life_L10_Mrev=l10,
        life_L10_h=l10h,
        required_life_h=life_h,
        static_safety=s0,
        limiting_speed_rpm=b.limiting_speed_rpm,
    )
    return out, checks


def _auto_bearing(cat, radial: float, axial: float, n: float, life_h, d_max: float):
    if life_h is None:
        raise InputError(
            "output_load.bearing = 'auto' needs design.life_h: the automatic choice takes the "
            "lightest bearing that lives that long (or name one, e.g. bearing = '6309')"
        )
    fits = []
    for b in cat.bearings:
        if b.type != "deep_groove" or b.D_mm > d_max:
            continue
        eq = bl.equivalent_load(b, radial, axial)
        life = bl.hours_from_Mrev(bl.rating_life_Mrev(b.C_kN * 1e3, eq.load_N), n)
        if (
            life >= life_h
            and bl.static_safety(b, radial, axial) >= 1.0
            and n <= b.limiting_speed_rpm
        ):
            fits.append(b)
    if not fits:
        from advisor.core.errors import InfeasibleError

        raise InfeasibleError(
            "no feasible design: no deep-groove bearing of the catalog carries the output load",
            [
                f"{radial:.4g} N radial, {axial:.4g} N axial at {n:.4g} rpm for "
                f"{life_h:g} h within Ø{d_max:.4g} mm (the reducer's outer diameter)",
                "name a bearing in output_load.bearing, or spread a pair "
                "(output_load.bearing_spacing_mm)",
            ],
        )
    return min(fits, key=lambda b: (b.mass_kg or math.inf, b.D_mm))


def regeneration(phases: list[Phase], drive) -> RegenerationOut | None:
    """What absorbs the energy the motor gives back (item 6); None if it gives none."""
    events = rg.brakings(phases)
    if not events:
        return None
    t_cycle = sum(p.time_s for p in phases)
    u0, u1 = drive.bus_voltage_V, drive.bus_max_voltage_V
    largest = max(b.energy_J for b in events)
    c_given = drive.bus_capacitance_uF
    bus_J = rg.bus_energy_J(c_given * 1e-6, u0, u1) if c_given is not None else 0.0
    res = rg.braking_resistor(events, t_cycle, bus_J, u1)
    return RegenerationOut.make(
        regenerated_per_cycle_J=sum(b.energy_J for b in events),
        brakings_per_cycle=len(events),
        largest_braking_J=largest,
        peak_power_W=max(b.peak_power_W for b in events),
        bus_voltage_V=u0,
        bus_max_voltage_V=u1,
        capacitance_for_largest_uF=rg.capacitance_for_F(largest, u0, u1) * 1e6,
        bus_capacitance_uF=c_given,
        bus_energy_J=bus_J,
        resistor_needed=res.needed,
        resistor_peak_power_W=res.peak_power_W,
        resistor_average_power_W=res.average_power_W,
        resistor_max_ohm=res.max_resistance_ohm if res.needed else None,
        rule=(
            "the bus takes E = ½·C·(U_max² − U_nom²) of each braking (Servotronix CDHD2); the "
            "resistor the rest, at the braking's peak power −M·ω (R ≤ U_max²/P_peak) and, over "
            "the cycle, the energy beyond the bus's share; the motor's losses neglected"
        ),
    )
