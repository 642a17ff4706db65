"""One package and one registration: a toy application (a hoist: a drum lifts a mass through
a reducer, the motor taken from a short list for the duty cycle) is defined and registered
inside this test and gets every face through its registry entry alone — the batch, the HTML
datasheet with its own plot, a family study's rows with its own key outputs, a duty cycle
evaluated with the shared duty equations and rules, and the wizard.

What it uses is the extension API: the requirement base (``StrictModel``,
``number_field``, ``ApplicationReq``), the report base (``ReportTable``), a check
(``advisor.calc.checks.Check``), the duty equations (``advisor.calc.duty``), the duty report
table (``advisor.duty.report``), the duty rules (``rules.duty``) and the datasheet's
``Plot``/``Line``."""

import csv
import math
import tomllib
from types import SimpleNamespace
from typing import Annotated

import pytest

import rules.duty
from advisor.calc import duty as duty_calc
from advisor.calc.checks import Check
from advisor.cli import main
from advisor.core import registry
from advisor.core.report import ReportTable
from advisor.core.requirements import ApplicationReq, StrictModel, number_field
from advisor.duty.report import DutyOut, phases_out

G_M_S2 = 9.80665
RPM = 30.0 / math.pi
#: The toy's motors: (name, rated torque N·m, speed rpm, peak torque N·m, mass kg).
MOTORS = (
    ("H-1", 1.0, 3000.0, 3.0, 2.0),
    ("H-2", 2.5, 3000.0, 7.5, 4.0),
    ("H-5", 5.0, 3000.0, 15.0, 7.0),
)


class HoistReq(StrictModel):
    mass_kg: Annotated[
        float, number_field(gt=0, le=1e4, desc="mass lifted, kg", label="Mass", step=1)
    ]
    speed_m_s: Annotated[
        float, number_field(gt=0, le=5, desc="lifting speed, m/s", label="Speed", step=1)
    ]
    drum_diameter_m: Annotated[
        float,
        number_field(gt=0, le=2, desc="drum diameter, m", label="Drum diameter", step=1),
    ] = 0.2
    lift_time_s: Annotated[
        float, number_field(gt=0, le=1e4, desc="time of one lift, s", label="Lift time", step=4)
    ] = 10.0
    cycle_time_s: Annotated[
        float,
        number_field(gt=0, le=1e5, desc="one lift then rest, s", label="Cycle time", step=4),
    ] = 40.0


class HoistRequirements(StrictModel):
    application: ApplicationReq
    hoist: HoistReq


class HoistOut(ReportTable):
    motor: str
    ratio: float
    drum_torque_Nm: float
    motor_mass_kg: float
    rope_force_curve: dict[str, list[float]]  # the force in the rope against the mass lifted
    duty: DutyOut


def hoist_duty(h: HoistReq, motor: tuple, trace) -> tuple[DutyOut, list[Check]]:
    """The toy's duty model: its cycle as phases at the motor (a lift, then rest), evaluated
    by the shared duty equations (RMS, peak, energy) and verdicts (DU-04, DU-05)."""
    name, rated_Nm, speed_rpm, peak_Nm, _ = motor
    drum_Nm = h.mass_kg * G_M_S2 * h.drum_diameter_m / 2.0
    ratio = speed_rpm / RPM / (2.0 * h.speed_m_s / h.drum_diameter_m)
    w = speed_rpm / RPM
    phases = [duty_calc.Phase("lift", h.lift_time_s, w, w, drum_Nm / ratio)]
    if h.cycle_time_s > h.lift_time_s:
        phases.append(duty_calc.Phase("rest", h.cycle_time_s - h.lift_time_s, 0.0, 0.0, 0.0))
    rms = duty_calc.rms_torque(phases)
    peak = duty_calc.peak_torque(phases)
    delivered, given_back = duty_calc.energies(phases)
    utilisation = trace.apply(rules.duty.thermal, rms / rated_Nm, "RMS torque / rated torque")
    trace.apply(rules.duty.peak, peak, peak_Nm, "the motor's peak torque")
    out = DutyOut.make(
        motor=name,
        ratio=ratio,
        cycle_time_s=duty_calc.cycle_time(phases),
        move_time_s=h.lift_time_s,
        peak_torque_Nm=peak,
        peak_torque_limit_Nm=peak_Nm,
        rms_torque_Nm=rms,
        thermal_utilisation=utilisation,
        thermal_basis="RMS torque against the rated torque",
        inertia_ratio=0.0,
        inertia_ratio_guideline=rules.duty.INERTIA_RATIO_GUIDELINE,
        energy_per_cycle_J=delivered,
        regenerated_per_cycle_J=given_back,
        mean_speed_rpm=duty_calc.mean_speed(phases) * RPM,
        duty_type="S3",
        phases=phases_out(phases),
    )
    checks = [
        Check("duty_rms", "RMS torque of the cycle", rms, rated_Nm, "N·m", rated_Nm / rms, "toy"),
        Check("duty_peak", "peak torque of the cycle", peak, peak_Nm, "N·m", peak_Nm / peak, "toy"),
    ]
    return out, checks


def advise_hoist(req, cat, trace):
    """The lightest motor of the list whose cycle passes its checks."""
    h = req.hoist
    for motor in MOTORS:
        duty, checks = hoist_duty(h, motor, trace)
        if all(c.passed for c in checks):
            break
    masses = [h.mass_kg * k / 4.0 for k in range(5)]
    design = HoistOut.make(
        motor=motor[0],
        ratio=duty.ratio,
        drum_torque_Nm=h.mass_kg * G_M_S2 * h.drum_diameter_m / 2.0,
        motor_mass_kg=motor[4],
        rope_force_curve={"mass_kg": masses, "force_N": [m * G_M_S2 for m in masses]},
        duty=duty,
    )
    return design, checks, []


def hoist_headline(report) -> str:
    d = report.design
    return f"hoist motor {d.motor}, i = {d.ratio:.4g}"


def rope_force(doc: dict):
    """The toy's own datasheet plot, from its report's plain data."""
    from advisor.datasheet.plots import Line, Plot, at

    curve = at(doc, "design", "rope_force_curve")
    if not curve:
        return None
    line = Line("rope force", curve["mass_kg"], curve["force_N"])
    return Plot("hoist-rope-force", "Rope force against the mass", "mass, kg", "force, N", [line])


def hoist_outputs(report: dict) -> dict:
    """The toy's columns of a family's designs.csv."""
    from advisor.family.outputs import lowest_margin

    d = report["design"]
    return {
        "motor": d["motor"],
        "ratio": d["ratio"],
        "mass_kg": d["motor_mass_kg"],
        "motor_speed_rpm": d["duty"]["mean_speed_rpm"],
        **lowest_margin(report),
    }


def hoist_views():
    from advisor.duty.views import plots as duty_plots

    return SimpleNamespace(components=lambda r: [], plots=lambda r: duty_plots(r.design.duty))


HOIST = registry.Application(
    kind="hoist",
    title="Hoist — a toy application registered by a test",
    requirements=HoistRequirements,
    pipeline=advise_hoist,
    headline=hoist_headline,
    views=hoist_views(),
    plots=SimpleNamespace(DATASHEET_PLOTS=(rope_force,)),
    family=SimpleNamespace(key_outputs=hoist_outputs, MEANING={"mass_kg": "the motor's"}),
    steps=("Load and speed", "", "", "Duty cycle"),
)

TOY = """\
[application]
kind = "hoist"
title = "toy hoist"

[hoist]
mass_kg = 100.0
speed_m_s = 0.5
"""


@pytest.fixture(autouse=True)
def hoist(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_STATE_HOME", str(tmp_path / "state"))
    registry.register(HOIST)
    yield
    registry.unregister("hoist")


@pytest.fixture
def toy(tmp_path):
    src = tmp_path / "toy.toml"
    src.write_text(TOY, encoding="utf-8")
    return src


def test_the_batch_advises_the_toy_with_its_duty_cycle(toy, capsys):
    assert main(["--batch", str(toy)]) == 0
    rep = tomllib.loads(capsys.readouterr().out)
    assert rep["report"]["application"] == "hoist"
    d = rep["design"]
    # by hand: 100 kg · g · 0.1 m = 98.07 N·m at the drum; 3000 rpm against 5 rad/s at the
    # drum, i = 62.83; 1.561 N·m at the motor for 10 s of 40: RMS 1.561·√(10/40) = 0.7804
    assert d["drum_torque_Nm"] == pytest.approx(98.0665)
    assert d["ratio"] == pytest.approx(20 * math.pi, rel=1e-5)
    m_lift = 98.0665 / (20 * math.pi)
    assert d["duty"]["rms_torque_Nm"] == pytest.approx(m_lift * 0.5, rel=1e-5)
    assert d["motor"] == "H-1" and d["duty"]["thermal_utilisation"] < 1
    assert [p["name"] for p in d["duty"]["phases"]] == ["lift", "rest"]
    assert {"DU-04", "DU-05"} <= {x["id"] for x in rep["decisions"]}
    assert {c["id"] for c in rep["checks"]} == {"duty_rms", "duty_peak"}


def test_a_longer_lift_takes_the_next_motor(toy, capsys):
    toy.write_text(TOY + "lift_time_s = 39.0\n", encoding="utf-8")
    assert main(["--batch", str(toy)]) == 0
    assert tomllib.loads(capsys.readouterr().out)["design"]["motor"] == "H-2"


def test_the_html_datasheet_draws_the_toys_plot_and_its_duty(toy, capsys):
    pytest.importorskip("matplotlib")
    assert main(["--batch", str(toy), "--format", "html"]) == 0
    html = capsys.readouterr().out
    assert '<figure id="plot-hoist-rope-force">' in html
    assert '<figure id="plot-duty">' in html and "Rope force against the mass" in html


def test_a_family_of_toys_has_its_own_key_outputs(tmp_path, capsys):
    fam = tmp_path / "hoists.toml"
    fam.write_text(
        '[family]\nname = "Hoists"\n[family.axes]\n"hoist.mass_kg" = [50, 100, 200]\n\n' + TOY,
        encoding="utf-8",
    )
    out = tmp_path / "out"
    assert main(["family", str(fam), "--out", str(out), "--workers", "1", "--quiet"]) == 0
    with (out / "designs.csv").open(encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    assert [r["application"] for r in rows] == ["hoist"] * 3
    assert [r["motor"] for r in rows] == ["H-1", "H-1", "H-2"]
    assert [float(r["mass_kg"]) for r in rows] == [2.0, 2.0, 4.0]
    assert all(r["lowest_margin_check"] in ("duty_rms", "duty_peak") for r in rows)
    assert rows[0]["screw_thread"] == "" and float(rows[0]["ratio"]) == pytest.approx(62.8319)


async def test_the_wizard_lists_the_toy_and_shows_its_report():
    from rich.console import Console
    from textual.widgets import Input, Static

    from advisor.tui.app import DriveAdvisorApp

    app = DriveAdvisorApp(save_drafts=False, offer_draft=False)
    async with app.run_test(size=(120, 40)) as pilot:
        await pilot.click("#kind-hoist")
        await pilot.press("ctrl+n")
        for wid, text in (("f-hoist-mass-kg", "100"), ("f-hoist-speed-m-s", "0.5")):
            app.query_one(f"#{wid}", Input).focus()
            await pilot.press(*text)
        start = app.results_version
        await pilot.press("ctrl+r")
        for _ in range(400):
            await pilot.pause(0.02)
            if app.results_version > start:
                break
        console = Console(width=200, record=True, file=open(__import__("os").devnull, "w"))
        console.print(app.query_one("#view-summary", Static).content)
        assert "hoist motor H-1, i = 62.83" in console.export_text()
