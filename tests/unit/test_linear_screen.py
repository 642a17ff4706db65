"""The linear advice's fast paths (issue 16) against the full evaluation they replace: the
thread screen gives the same pass verdicts and the same numbers, to the last bit, as
evaluate_thread; the drive options built from it are those a plain scan of every motor of
every line builds from the full evaluations; the per-catalog parts belong to their catalog."""

import itertools

import pytest
from helpers import EXAMPLES
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from advisor.applications.linear.choice import (
    catalog_parts,
    choice_options,
    drive_options,
    first_drive_option,
)
from advisor.calc.sizing import (
    ScrewMaterial,
    drive_working_speed,
    evaluate_thread,
    fit_motor,
    screen_threads,
    thread_geometry,
)
from catalogs import load_catalogs
from catalogs.loader import _load_and_validate
from rules import screw as screw_rules

STARTS = (1, 2, 3, 4)
FIXITIES = ("fixed-fixed", "fixed-pinned", "pinned-pinned", "fixed-free")
finite = dict(allow_nan=False, allow_infinity=False)


def _material(cat, pair: str, steel: str, f: float | None, lubrication: str = "oil"):
    p = cat.pair(pair)
    lo, hi = p.friction_range(lubrication)
    f = (lo + hi) / 2 if f is None else f
    s = cat.steel(steel)
    m = cat.materials
    return ScrewMaterial(
        f,
        min(lo, f),
        p.allowable_pressure_MPa * 1e6,
        s.yield_strength_MPa * 1e6,
        s.elastic_modulus_MPa * 1e6,
        m.strength.yield_safety_factor,
        m.nut.height_ratio_min,
        m.nut.height_ratio_max,
        m.nut.max_turns,
    )


def _reference_options(evaluations, cat):
    """The drive options without any screen: every motor of every line tried in order of
    rated power until one drives the thread, from the full evaluations."""
    out = []
    for ev in evaluations:
        if not ev.passed:
            continue
        for pp in (1, 2, 3, 4):
            for m in cat.motors_with_poles(2 * pp):
                fit = fit_motor(m)
                n = drive_working_speed(fit, ev.torque_Nm, ev.speed_rpm)
                if n is None or n > ev.max_speed_rpm:  # whirling (issue 26)
                    continue
                out.append(
                    screw_rules.DriveOption(
                        thread=ev.thread.name,
                        d_mm=ev.thread.d_mm,
                        pitch_mm=ev.thread.pitch_mm,
                        starts=ev.starts,
                        self_locking_at_low_friction=ev.self_locking_at_low_friction,
                        screw_torque_Nm=ev.torque_Nm,
                        motor_model=m.model,
                        pole_pairs=pp,
                        rated_power_kW=m.rated_power_kW,
                        rated_torque_Nm=fit.rated_torque_Nm,
                        travel_time_s=60.0 * ev.revolutions / n,
                    )
                )
                break
    return out


def _compare(cat, material, model, force_N, stroke_m, travel_time_s, span_m, fixity, bsf):
    case = dict(
        force_N=force_N,
        stroke_m=stroke_m,
        travel_time_s=travel_time_s,
        span_m=span_m,
        end_fixity=fixity,
        buckling_safety_factor=bsf,
        friction_model=model,
        material=material,
    )
    full = [evaluate_thread(t, starts=z, **case) for t in cat.threads for z in STARTS]
    screens = screen_threads([thread_geometry(t) for t in cat.threads], STARTS, **case)
    assert len(screens) == len(full)
    for s, e in zip(screens, full, strict=True):
        assert (s.thread, s.name, s.starts) == (e.thread, e.thread.name, e.starts)
        assert s.passed == e.passed, (s.name, s.starts, [c.id for c in e.failed])
        if e.passed:  # the same floats, not close ones: the choice and the report read them
            assert (s.torque_Nm, s.revolutions, s.speed_rpm) == (
                e.torque_Nm,
                e.revolutions,
                e.speed_rpm,
            )
            assert s.self_locking_at_low_friction == e.self_locking_at_low_friction
    lines = catalog_parts(cat).lines
    options = drive_options(screens, lines)
    assert options == _reference_options(full, cat)
    for hold in (False, True):
        first = min(options, key=lambda o: screw_rules.drive_order(o, hold), default=None)
        assert first_drive_option(screens, lines, hold) == first
    return sum(e.passed for e in full), len(options)


@pytest.mark.slow  # seconds: outside the quick subset
def test_the_screen_agrees_with_the_full_evaluation_on_a_grid():
    cat = load_catalogs()
    seen_pass = seen_fail = seen_options = 0
    grid = itertools.product(
        (50.0, 3500.0, 40000.0, 2e5),  # force, N
        (0.2, 1.5),  # stroke, m
        (0.3, 5.0, 60.0),  # travel time, s
        ("steel_bronze", "steel_steel", "hardened_steel_bronze"),
        ("paper", "standard"),
    )
    for force, stroke, time, pair, model in grid:
        material = _material(cat, pair, "45", None)
        passing, options = _compare(
            cat, material, model, force, stroke, time, 2 * stroke, "pinned-pinned", 3.0
        )
        seen_pass += passing
        seen_fail += len(cat.threads) * len(STARTS) - passing
        seen_options += options
    assert seen_pass and seen_fail and seen_options  # the grid tries both sides of every test


def test_the_screen_agrees_on_seed_001():
    # the worked example: Tr16x2 passes and is driven (a 4-pole 0.75 kW motor among others)
    cat = load_catalogs()
    material = _material(cat, "steel_bronze", "45", 0.15)
    passing, options = _compare(cat, material, "paper", 3500.0, 0.2, 5.0, 0.4, "pinned-pinned", 3)
    assert passing and options


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    force=st.floats(1.0, 5e5, **finite),
    stroke=st.floats(0.001, 3.0, **finite),
    time=st.floats(0.01, 1000.0, **finite),
    span_factor=st.floats(1.0, 5.0, **finite),
    fixity=st.sampled_from(FIXITIES),
    bsf=st.floats(1.0, 6.0, **finite),
    pair=st.sampled_from(
        ["steel_bronze", "hardened_steel_bronze", "steel_cast_iron", "steel_steel"]
    ),
    steel=st.sampled_from(["45", "40X"]),
    f=st.one_of(st.none(), st.floats(0.02, 0.3, **finite)),
    model=st.sampled_from(["paper", "standard"]),
)
def test_the_screen_agrees_with_the_full_evaluation(
    force, stroke, time, span_factor, fixity, bsf, pair, steel, f, model
):
    cat = load_catalogs()
    material = _material(cat, pair, steel, f)
    _compare(cat, material, model, force, stroke, time, stroke * span_factor, fixity, bsf)


def test_catalog_parts_belong_to_their_catalog():
    shipped = load_catalogs()
    user = _load_and_validate(EXAMPLES / "catalogs")  # one more motor, more threads
    a, b = catalog_parts(shipped), catalog_parts(user)
    assert catalog_parts(shipped) is a  # computed once per catalog
    assert [g.thread for g in a.threads] == list(shipped.threads)
    assert [g.thread for g in b.threads] == list(user.threads)
    assert any(g.name == "Tr110x12" for g in b.threads)
    assert not any(g.name == "Tr110x12" for g in a.threads)
    models = {fit.motor.model for line in b.lines for fit in line.fits}
    assert "AIR160M2-example" in models
    assert models == {m.model for m in user.motors}
    # an equal catalog that is another object gets parts of its own
    again = _load_and_validate(None)
    assert catalog_parts(again) is not a
    assert [g.name for g in catalog_parts(again).threads] == [g.name for g in a.threads]


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    force=st.floats(1.0, 2e5, **finite),
    stroke=st.floats(0.001, 3.0, **finite),
    time=st.floats(0.05, 500.0, **finite),
    span_factor=st.floats(1.0, 3.0, **finite),
    pair=st.sampled_from(
        ["steel_bronze", "hardened_steel_bronze", "steel_cast_iron", "steel_steel"]
    ),
    model=st.sampled_from(["paper", "standard"]),
    hold=st.booleans(),
    starts=st.one_of(st.none(), st.integers(1, 4)),
    pick=st.floats(0.0, 1.0, **finite),
)
def test_the_options_read_with_a_thread_imposed_give_the_same_choice(
    force, stroke, time, span_factor, pair, model, hold, starts, pick
):
    """With a thread imposed the joint choice is given the imposed thread's options and the
    advisor's own best, not every option: its finding (choice, words, counts, runners-up,
    the advisor's own choice) and the options per pole count are the same as from all."""
    cat = load_catalogs()
    parts = catalog_parts(cat)
    starts_options = STARTS if starts is None else (starts,)
    screens = screen_threads(
        parts.threads,
        starts_options,
        force_N=force,
        stroke_m=stroke,
        travel_time_s=time,
        span_m=stroke * span_factor,
        end_fixity="pinned-pinned",
        buckling_safety_factor=3.0,
        friction_model=model,
        material=_material(cat, pair, "45", None),
    )
    full = drive_options(screens, parts.lines)
    first = min(full, key=lambda o: screw_rules.drive_order(o, hold), default=None)
    assert first_drive_option(screens, parts.lines, hold) == first
    assert choice_options(screens, parts.lines, None, hold) == full
    # the imposed thread: one with options when there are any, else any thread
    names = sorted({o.thread for o in full}) or [g.name for g in parts.threads]
    imposed = names[min(int(pick * len(names)), len(names) - 1)]
    read = choice_options(screens, parts.lines, imposed, hold)
    assert len(read) <= len(full)
    assert [o for o in read if o.thread == imposed] == [o for o in full if o.thread == imposed]
    assert screw_rules.choose_drive(read, hold, imposed, starts) == screw_rules.choose_drive(
        full, hold, imposed, starts
    )


def test_the_catalog_in_use_keeps_its_parts_while_others_come_and_go():
    """The parts cache drops the least recently used catalog, never the one in use (it was
    cleared whole once full, so a run that met eight catalogs recomputed the one it uses)."""
    shipped = load_catalogs()
    a = catalog_parts(shipped)
    for _ in range(12):
        catalog_parts(_load_and_validate(None))
        assert catalog_parts(shipped) is a
