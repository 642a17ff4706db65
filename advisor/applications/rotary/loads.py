"""The checks a reviewer of a rotary drive asks for first: the reducer under its
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
from typing import NamedTuple

from advisor.applications.rotary.report import (
    OutputBearingOut,
    ReducerLoadOut,
    RegenerationOut,
    StageLifeOut,
)
from advisor.calc import bearing_life, checks, load_spectrum, reducer, regen
from advisor.calc.checks import Check
from advisor.calc.duty import Phase
from advisor.calc.load_spectrum import Load
from advisor.calc.service_factor import ServiceFactor
from advisor.core.cite import cite
from advisor.core.errors import InputError

HD_RATIOS = cite("hd-csf-25-50")
HD_LIFE = cite("hd-csd-2a", "§4.1.2, eqs. 20.2, 20.3")
HONPINE = cite("honpine-harmonic", "step 2")
SEED_16 = cite("seed-000", "eq. (16)")
RPM = 30.0 / math.pi


def momentary_torque(req, repeated_peak_Nm: float) -> tuple[float, str]:
    """The emergency stop's torque at the reducer's output and where it comes from.

    The stop's torque at the load (``rotary.emergency_stop_torque_Nm``, or the output torque
    where none is given) reaches the output stage as every torque of the spectrum does:
    through a holding device at the output as its input torque M/η_d (seed 004). A momentary
    peak is at least the repeated peak of the cycle: a smaller one given is raised to it."""
    from advisor.applications.rotary.candidates import device_efficiency, output_stage_torque

    given = req.rotary.emergency_stop_torque_Nm
    at_load = req.rotary.torque_Nm if given is None else given
    basis = (
        "not given: rotary.torque_Nm taken as the momentary peak"
        if given is None
        else "rotary.emergency_stop_torque_Nm (given)"
    )
    torque = output_stage_torque(req, at_load)
    if torque != at_load:
        basis += (
            f", through the {req.one_way.type} at the output: {at_load:g}/η_d = "
            f"{at_load:g}/{device_efficiency(req):.5g} = {torque:.6g} N·m"
        )
    if torque < repeated_peak_Nm:
        basis += (
            f"; {torque:.5g} N·m is below the repeated peak {repeated_peak_Nm:.5g} N·m: a "
            "momentary peak is at least the repeated peak, which is taken"
        )
        torque = repeated_peak_Nm
    return torque, basis


class SpectrumFigures(NamedTuple):
    """The load spectrum's figures at the output and the output stage's limits [N·m, rpm]."""

    mean_torque_Nm: float
    repeated_peak_Nm: float
    momentary_peak_Nm: float
    momentary_basis: str
    mean_speed_rpm: float
    max_speed_rpm: float
    rated_Nm: float  # the output stage's T_N by eq. (16)


def spectrum_figures(req, design: reducer.Reducer, loads: list[Load]) -> SpectrumFigures:
    """Cube-mean, repeated and momentary peak torques and the speeds of the spectrum."""
    t_rep = load_spectrum.repeated_peak_torque(loads)
    t_mom, mom_basis = momentary_torque(req, t_rep)
    return SpectrumFigures(
        load_spectrum.cube_mean_torque(loads),
        t_rep,
        t_mom,
        mom_basis,
        load_spectrum.mean_speed_rpm(loads),
        load_spectrum.max_speed_rpm(loads),
        design.stages[-1].torque_Nm,
    )


def stage_lives(
    design: reducer.Reducer, figures: SpectrumFigures, f: float, p: float
) -> list[StageLifeOut]:
    """Each stage's L50 and L10 (output first): its share of the output torque (each sized
    for its share by eq. (16)) at its own mean input speed."""
    stages, ratio_to_output = [], 1.0
    for s in reversed(design.stages):  # output first
        ratio_to_output *= s.ratio
        share = s.torque_Nm / figures.rated_Nm  # this stage's share of the output torque
        n_in = figures.mean_speed_rpm * ratio_to_output
        l50 = load_spectrum.rolling_life_h(s.torque_Nm, f * figures.mean_torque_Nm * share, n_in, p)
        stages.append(
            StageLifeOut.make(
                position=s.position,
                rated_torque_Nm=s.torque_Nm,
                mean_input_speed_rpm=n_in,
                max_input_speed_rpm=figures.max_speed_rpm * ratio_to_output,
                life_L50_h=l50,
                life_L10_h=l50 * load_spectrum.L10_PER_L50,
            )
        )
    return stages


def factored_stage_check(
    id: str, name: str, demand_Nm: float, limit_Nm: float, f: float, source
) -> Check:
    """A stage's torque check under the service factor: value = f_B·T, margin = limit/value
    (:func:`advisor.calc.checks.factored`; the name says "× f_B"). Harmonic Drive's CSF
    ratings (98/39, 186/39 of T_N); seed 000, eq. (16)."""
    return checks.factored(id, name, demand_Nm, limit_Nm, "N·m", f, source)


def torque_checks(figures: SpectrumFigures, f: float, basis: str) -> list[Check]:
    """The cube-mean torque (over a cycle), the repeated and the momentary peak, each × f_B
    (the value states the factored torque), against the output stage's T_N and its peak
    ratios."""
    rated = figures.rated_Nm
    t_av, t_rep, t_mom = figures.mean_torque_Nm, figures.repeated_peak_Nm, figures.momentary_peak_Nm
    rep_limit = load_spectrum.REPEATED_PEAK_FACTOR * rated
    mom_limit = load_spectrum.MOMENTARY_PEAK_FACTOR * rated
    where = f"output stage, T_N = {rated:.4g} N·m by eq. (16); f_B = {f:g}"
    checks = []
    if basis == "duty cycle":  # at the working point T_av is the sizing torque itself
        checks.append(
            factored_stage_check(
                "stage_average_torque",
                f"cube-mean torque T_av × f_B within the rated torque ({where})",
                t_av,
                rated,
                f,
                HONPINE + SEED_16,
            )
        )
    checks += [
        factored_stage_check(
            "stage_repeated_peak",
            f"repeated peak torque × f_B within 98/39 × T_N ({where})",
            t_rep,
            rep_limit,
            f,
            HD_RATIOS + SEED_16,
        ),
        factored_stage_check(
            "stage_momentary_peak",
            f"emergency-stop torque × f_B within 186/39 × T_N ({where})",
            t_mom,
            mom_limit,
            f,
            (HD_RATIOS + SEED_16).with_note(figures.momentary_basis),
        ),
    ]
    return checks


def life_check(stages: list[StageLifeOut], life_h: float) -> Check:
    """The shortest L10 of the stages' rolling elements against the required life."""
    worst = min(stages, key=lambda s: s.life_L10_h)
    return Check(
        "stage_life",
        f"L10 life of the {worst.position} stage's rolling elements (the shortest) "
        "within the required life",
        worst.life_L10_h,
        life_h,
        "h",
        worst.life_L10_h / life_h,
        HD_LIFE + cite("iso-281", "eq. (1)"),
    )


def _stops_warning(req, stops_allowed: float, motor_speed: float) -> list[str]:
    stops = req.rotary.emergency_stops
    if stops is None or stops <= stops_allowed:
        return []
    return [
        f"reducer: {stops} emergency stops over the life against about "
        f"{stops_allowed:.3g} a strain-wave gear's momentary peak allows at "
        f"{motor_speed:.4g} rpm input for {req.rotary.emergency_stop_time_s:g} s each "
        "(10⁴ flexings; Harmonic Drive's form as quoted, not verified in its own text)"
    ]


def reducer_load(
    req, design: reducer.Reducer, loads: list[Load], basis: str, sf: ServiceFactor, k_rb: str
) -> tuple[ReducerLoadOut, list[Check], list[str]]:
    """The spectrum's figures at the output, the stages' lives, their checks and warnings."""
    f = sf.value
    p = load_spectrum.LIFE_EXPONENT[k_rb]
    figures = spectrum_figures(req, design, loads)
    stages = stage_lives(design, figures, f, p)
    ratio = math.prod(s.ratio for s in reversed(design.stages))
    motor_speed = figures.max_speed_rpm * ratio  # the input stage's top speed: the motor's
    stops_allowed = load_spectrum.momentary_peak_count_allowed(
        motor_speed, req.rotary.emergency_stop_time_s
    )
    checks = torque_checks(figures, f, basis)
    life_h = req.design.life_h
    if life_h is not None:
        checks.append(life_check(stages, life_h))
    warnings = _stops_warning(req, stops_allowed, motor_speed)
    rated = figures.rated_Nm
    out = ReducerLoadOut.make(
        basis=basis,
        service_factor=f,
        service_factor_basis=sf.basis,
        mean_torque_Nm=figures.mean_torque_Nm,
        mean_output_speed_rpm=figures.mean_speed_rpm,
        max_output_speed_rpm=figures.max_speed_rpm,
        repeated_peak_torque_Nm=figures.repeated_peak_Nm,
        momentary_peak_torque_Nm=figures.momentary_peak_Nm,
        momentary_peak_basis=figures.momentary_basis,
        rated_torque_Nm=rated,
        average_torque_limit_Nm=rated,
        repeated_peak_limit_Nm=load_spectrum.REPEATED_PEAK_FACTOR * rated,
        momentary_peak_limit_Nm=load_spectrum.MOMENTARY_PEAK_FACTOR * rated,
        emergency_stop_time_s=req.rotary.emergency_stop_time_s,
        emergency_stops=req.rotary.emergency_stops,
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


def _given_or_auto(req, cat, radial: float, axial: float, n: float, d_max: float):
    """The bearing ``output_load.bearing`` names, or the automatic choice, and which."""
    ol = req.output_load
    if ol.bearing == "auto":
        return _auto_bearing(cat, radial, axial, n, req.design.life_h, d_max), "automatic"
    found = [x for x in cat.bearings if x.designation == ol.bearing]
    if not found:
        known = ", ".join(x.designation for x in cat.bearings)
        raise InputError(
            f"output_load.bearing = {ol.bearing!r}: not in the bearing catalog ({known})"
        )
    return found[0], "given"


def _bearing_checks(b, s0: float, n: float, l10h: float, life_h, src) -> list[Check]:
    """Static safety (ISO 76), speed, and, with a required life, L10h (ISO 281)."""
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
    return checks


def output_bearing(
    req, cat, design: reducer.Reducer, speed_rpm: float, sf: ServiceFactor
) -> tuple[OutputBearingOut, list[Check]]:
    """The output bearing under ``[output_load]`` by ISO 281, the given one or the lightest
    deep-groove bearing of the catalog that fits within the reducer's outer diameter and
    gives design.life_h."""
    ol = req.output_load
    f = sf.value
    radial, axial = bearing_life.pair_loads(
        ol.radial_N, ol.axial_N, ol.tilting_moment_Nm, ol.bearing_spacing_mm
    )
    radial, axial = f * radial, f * axial
    n = ol.speed_rpm or speed_rpm
    life_h = req.design.life_h
    b, chosen = _given_or_auto(req, cat, radial, axial, n, design.outer_diameter_mm)
    eq = bearing_life.equivalent_load(b, radial, axial)
    l10 = bearing_life.rating_life_Mrev(b.C_kN * 1e3, eq.load_N)
    l10h = bearing_life.hours_from_Mrev(l10, n)
    s0 = bearing_life.static_safety(b, radial, axial)
    src = cat.cite_rows(cat.bearing_sources, b.source)
    checks = _bearing_checks(b, s0, n, l10h, life_h, src)
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
        eq = bearing_life.equivalent_load(b, radial, axial)
        life = bearing_life.hours_from_Mrev(
            bearing_life.rating_life_Mrev(b.C_kN * 1e3, eq.load_N), n
        )
        if (
            life >= life_h
            and bearing_life.static_safety(b, radial, axial) >= 1.0
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
    """What absorbs the energy the motor gives back; None if it gives none."""
    events = regen.brakings(phases)
    if not events:
        return None
    t_cycle = sum(p.time_s for p in phases)
    u0, u1 = drive.bus_voltage_V, drive.bus_max_voltage_V
    largest = max(b.energy_J for b in events)
    c_given = drive.bus_capacitance_uF
    bus_J = regen.bus_energy_J(c_given * 1e-6, u0, u1) if c_given is not None else 0.0
    res = regen.braking_resistor(events, t_cycle, bus_J, u1)
    return RegenerationOut.make(
        regenerated_per_cycle_J=sum(b.energy_J for b in events),
        brakings_per_cycle=len(events),
        largest_braking_J=largest,
        peak_power_W=max(b.peak_power_W for b in events),
        bus_voltage_V=u0,
        bus_max_voltage_V=u1,
        capacitance_for_largest_uF=regen.capacitance_for_F(largest, u0, u1) * 1e6,
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
