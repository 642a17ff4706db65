"""The linear actuator's report tables, built from the thread's and the motors'
evaluations: the screw (with its nut, buckling and thrust face) and the motor with its
candidates."""

import math

from advisor.applications.linear.motor import MotorPlan
from advisor.applications.linear.report import (
    BucklingOut,
    CurveOut,
    InductionMotorOut,
    MotorCandidateOut,
    NutOut,
    ScrewOut,
    ThrustOut,
    back_driving_words,
)
from advisor.applications.linear.screw_checks import (
    NutHeat,
    nut_heat,
    thrust_bearing_life,
    whirling_speed_rpm,
)
from advisor.calc import screw as screw_calc
from advisor.calc.induction import synchronous_speed_rpm
from advisor.calc.screw import (
    END_FIXITY_FACTOR,
    NUT_ALLOWED_RISE_K,
    NUT_FILM_COEFFICIENT,
    NUT_OUTER_DIAMETER_RATIO,
)
from advisor.calc.sizing import MotorEvaluation, ScrewMaterial, ThreadEvaluation
from advisor.core.cite import text
from advisor.core.reading import Requirements
from catalogs import Catalogs
from rules import screw as screw_rules


def _buckling_out(ev: ThreadEvaluation, req: Requirements, cat: Catalogs) -> BucklingOut:
    """The buckling table: the formula used and why (the slenderness against Johnson's
    transition), the end fixity and the critical load."""
    lin = req.linear
    steel = cat.steel(req.screw.screw_steel)
    transition = math.pi * math.sqrt(2.0 * steel.elastic_modulus_MPa / steel.yield_strength_MPa)
    why = (
        f"slenderness μL/i = {ev.slenderness:.4g} "
        f"{'≥' if ev.buckling_formula == 'Euler' else '<'} the transition "
        f"π·√(2E/σ_y) = {transition:.4g}: "
        + (
            "a slender column fails elastically (Euler)"
            if ev.buckling_formula == "Euler"
            else "an intermediate column yields before it buckles elastically (Johnson's parabola)"
        )
    )
    return BucklingOut.make(
        formula=ev.buckling_formula,
        why=why,
        end_fixity=lin.end_fixity,
        effective_length_factor=END_FIXITY_FACTOR[lin.end_fixity],
        slenderness=ev.slenderness,
        critical_load_N=ev.critical_load_N,
        safety_factor_required=lin.buckling_safety_factor,
    )


def _thrust_out(ev: ThreadEvaluation, req: Requirements, n_work: float) -> ThrustOut | None:
    """The thrust face's table: its friction torque and the efficiency with it, and a
    rolling bearing's rating life at the screw's mean speed."""
    if ev.thrust is None:
        return None
    lead = ev.thread.pitch_mm * 1e-3 * ev.starts
    life = thrust_bearing_life(req, ev, n_work)
    return ThrustOut.make(
        kind=ev.thrust.kind,
        model=ev.thrust.describe(),
        torque_Nm=ev.thrust_torque_Nm,
        drive_torque_Nm=ev.drive_torque_Nm,
        efficiency=screw_calc.thread_efficiency_with_thrust(
            req.linear.force_N, lead, ev.torque_Nm, ev.thrust_torque_Nm
        ),
        equivalent_load_N=life and life.equivalent_load_N,
        life_L10_Mrev=life and life.life_Mrev,
        life_L10_h=life and life.life_h,
        life_speed_rpm=life and life.speed_rpm,
        life_basis=life and life.basis,
    )


def _turns_basis(ev: ThreadEvaluation, req: Requirements, material: ScrewMaterial) -> str | None:
    """Why the nut has more turns than the rated force gives it: the emergency stop's force
    sizes it (Ivanov, power screws: z = f_B·F_m/(π·d2·H1·[p])); None where the rated force
    or the minimum height sizes it."""
    if ev.nut_turns <= ev.nut_turns_rated:
        return None
    lin = req.linear
    assert lin is not None and lin.emergency_stop_force_N is not None
    return (
        f"{ev.nut_turns:g} turns, sized by the emergency stop's {lin.emergency_stop_force_N:g} N "
        f"× f_B = {ev.service_factor:g}: z = f_B·F_stop/(π·d2·H1·[p]) rounded up, within "
        f"z ≤ {material.nut_max_turns} and H/d2 ≤ {material.nut_height_ratio_max:g} (the rated "
        f"{lin.force_N:g} N alone gives {ev.nut_turns_rated:g}); Ivanov, Детали машин, power "
        "screws"
    )


def _nut_out(
    ev: ThreadEvaluation, req: Requirements, material: ScrewMaterial, heat: NutHeat
) -> NutOut:
    """The nut's table: its proportions (and what sized its turns where the stop did), flank
    pressure, wear and heat."""
    return NutOut.make(
        height_mm=ev.nut_height_mm,
        turns=ev.nut_turns,
        turns_basis=_turns_basis(ev, req, material),
        height_ratio=ev.nut_height_mm / ev.thread.d2_mm,
        bearing_pressure_MPa=ev.nut_pressure_Pa / 1e6,
        allowable_pressure_MPa=material.allowable_pressure_Pa / 1e6,
        sliding_speed_m_s=heat.sliding_speed_m_s,
        safe_pressure_MPa=heat.safe_pressure_Pa / 1e6,
        safe_pressure_basis=f"Shigley, Table 8-4 (as recalled, not verified online): "
        f"{heat.safe_pressure_row}",
        pv_MPa_m_s=heat.pv_MPa_m_s,
        friction_power_W=heat.friction_power_W,
        mean_friction_power_W=heat.mean_friction_power_W,
        mean_friction_basis=heat.mean_basis,
        temperature_rise_K=heat.temperature_rise_K,
        allowed_temperature_rise_K=NUT_ALLOWED_RISE_K,
        heat_model=f"ΔT = P̄_f/(h·A), h = {NUT_FILM_COEFFICIENT:g} W/(m²·K) natural "
        f"convection, A = nut body of {NUT_OUTER_DIAMETER_RATIO:g}·d over its length "
        "and end faces; the screw's cooling neglected",
    )


def screw_out(
    ev: ThreadEvaluation,
    req: Requirements,
    material: ScrewMaterial,
    f_range: tuple[float, float],
    advisor_choice: str | None,
    sel: MotorEvaluation,
    cat: Catalogs,
) -> ScrewOut:
    """The screw's table, from its evaluation at the motor's working speed."""
    t, lin, s = ev.thread, req.linear, req.screw
    assert lin is not None
    heat = nut_heat(req, ev, sel.working_speed_rpm or ev.speed_rpm)
    v = screw_calc.linear_speed(lin.stroke_m, lin.travel_time_s)
    return ScrewOut.make(
        thread=t.name,
        designation=screw_rules.thread_label(t.name, ev.starts),
        imposed=s.thread is not None,
        advisor_choice=advisor_choice,
        nominal_diameter_mm=t.d_mm,
        pitch_mm=t.pitch_mm,
        preferred_pitch=t.preferred,
        starts=ev.starts,
        lead_mm=t.pitch_mm * ev.starts,
        d2_mm=t.d2_mm,
        d3_mm=t.d3_mm,
        D1_mm=t.D1_mm,
        D2_mm=t.D2_mm,
        D4_mm=t.D4_mm,
        ac_mm=t.ac_mm,
        H1_mm=t.H1_mm,
        h3_mm=t.h3_mm,
        material_pair=s.material_pair,
        lubrication=s.lubrication,
        screw_steel=s.screw_steel,
        friction_model=ev.friction_model,
        friction_coefficient=material.friction_coefficient,
        friction_range=list(f_range),
        lead_angle_deg=math.degrees(ev.lead_angle_rad),
        friction_angle_deg=math.degrees(ev.friction_angle_rad),
        torque_Nm=ev.torque_Nm,
        torque_standard_Nm=ev.torque_standard_Nm,
        torque_paper_Nm=ev.torque_paper_Nm,
        efficiency=ev.efficiency,
        back_driving_efficiency=ev.back_driving_efficiency,
        back_driving=back_driving_words(
            ev.back_driving_efficiency, ev.self_locking, ev.self_locking_at_low_friction
        ),
        self_locking=ev.self_locking,
        self_locking_at_low_friction=ev.self_locking_at_low_friction,
        linear_speed_m_s=v,
        revolutions=ev.revolutions,
        speed_rpm=ev.speed_rpm,
        output_power_W=lin.force_N * v,
        nut=_nut_out(ev, req, material, heat),
        buckling=_buckling_out(ev, req, cat),
        thrust=_thrust_out(ev, req, sel.working_speed_rpm or ev.speed_rpm),
        critical_speed_rpm=whirling_speed_rpm(req, t, cat),
        service_factor=ev.service_factor if ev.service_factor != 1.0 else None,
    )


def motor_out(
    plan: MotorPlan, ev: ThreadEvaluation, cat: Catalogs, freq: float
) -> InductionMotorOut:
    m = plan.selected
    assert m is not None and plan.pole_pairs is not None
    sel = plan.evaluations[m.rated_power_kW]
    assert sel is not None and sel.working_speed_rpm is not None and sel.working_slip is not None
    candidates = []
    for power in plan.band_kW:
        e = plan.evaluations.get(power)
        role = (
            "selected"
            if power == m.rated_power_kW
            else ("lower" if power < m.rated_power_kW else "higher")
        )
        candidates.append(_candidate_out(role, power, e))
    return InductionMotorOut.make(
        kind="induction",
        supply_frequency_Hz=freq,
        speed_rpm=ev.speed_rpm,
        pole_pairs=plan.pole_pairs,
        synchronous_speed_rpm=synchronous_speed_rpm(freq, plan.pole_pairs),
        required_torque_Nm=ev.torque_Nm,
        required_power_kW=plan.required_power_kW,
        rated_power_kW=m.rated_power_kW,
        model=m.model,
        rated_speed_rpm=m.rated_speed_rpm,
        rated_torque_Nm=m.rated_torque_Nm,
        working_speed_rpm=sel.working_speed_rpm,
        working_slip=sel.working_slip,
        working_power_kW=ev.torque_Nm * sel.working_speed_rpm * math.pi / 30.0 / 1e3,
        travel_time_s=sel.travel_time_s or math.inf,
        efficiency_pct=m.efficiency_pct,
        cos_phi=m.cos_phi,
        starting_current_ratio=m.starting_current_ratio,
        inertia_kgm2=m.inertia_kgm2,
        mass_kg=m.mass_kg,
        estimated=list(m.estimated),
        source=text(cat.cite_rows(cat.motor_sources, m.source), cat.short_names()),
        candidates=candidates,
    )


def _candidate_out(role: str, power: float, e: MotorEvaluation | None) -> MotorCandidateOut:
    if e is None:
        return MotorCandidateOut.make(
            role=role,
            rated_power_kW=power,
            in_catalog=False,
            suitable=False,
            problems=["no motor of this power and pole count in the catalog"],
        )
    n0 = e.motor.synchronous_speed_rpm
    return MotorCandidateOut.make(
        role=role,
        rated_power_kW=power,
        model=e.motor.model,
        in_catalog=True,
        rated_speed_rpm=e.motor.rated_speed_rpm,
        rated_torque_Nm=e.rated_torque_Nm,
        max_torque_Nm=e.max_torque_Nm,
        starting_torque_Nm=e.starting_torque_Nm,
        critical_slip=e.curve.critical_slip,
        kloss_epsilon=e.curve.epsilon,
        working_speed_rpm=e.working_speed_rpm,
        torque_at_required_speed_Nm=e.torque_at_required_speed_Nm,
        rated_torque_margin=e.rated_torque_margin,
        starting_torque_margin=e.starting_torque_margin,
        breakdown_torque_margin=e.breakdown_torque_margin,
        travel_time_s=e.travel_time_s,
        suitable=e.suitable,
        problems=e.problems,
        curve=CurveOut.make(
            slip=[float(x) for x in e.slips],
            speed_rpm=[float(n0 * (1.0 - x)) for x in e.slips],
            torque_Nm=[float(x) for x in e.torques_Nm],
        ),
    )
