"""The wizard an engineer can trust (issue 14), driven through textual's Pilot: it never
computes or exports what the screen does not show, every view shows the current result or
says why there is none, a file opened never replaces another draft, every problem a file
can have is fixed inside the wizard, and no key is lost."""

import tomllib

import pytest
from helpers import EXAMPLES
from textual.widgets import Button, Input, Label, RadioSet, Static

from advisor.tui import draft as drafts
from advisor.tui import fixes
from advisor.tui.app import ConfirmScreen, DriveAdvisorApp, ExportScreen

#: the shared Pilot set-up (tests/conftest.py): own drafts, no animation, a temporary cwd
pytestmark = pytest.mark.usefixtures("wizard")

SIZE = (120, 40)
VALVE = EXAMPLES / "valve_actuator_hold.toml"


def _doc(path=VALVE) -> dict:
    return tomllib.loads(path.read_text(encoding="utf-8"))


async def _retype(pilot, app, widget_id: str, text: str) -> None:
    box = app.query_one(f"#{widget_id}", Input)
    box.focus()
    await pilot.pause()
    box.value = ""
    await pilot.press(*text)


# ------------------------------------------------------------------ never compute the unseen
async def test_a_field_in_error_stops_compute_and_the_draft_never_holds_a_half_value(wizard):
    """Torque 8OO (letter O) once computed 8 N·m and the draft held 8.0."""
    app = DriveAdvisorApp(_doc(), VALVE)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+n")
        assert app.step == 1
        await _retype(pilot, app, "f-rotary-torque-Nm", "8OO")
        start = app.results_version
        await pilot.press("ctrl+r")
        await pilot.pause(0.3)
        assert app.results_version == start and app.report is None  # nothing computed
        assert app.query_one("#main").current == "wizard" and app.step == 1
        assert app.focused is app.query_one("#f-rotary-torque-Nm")  # taken to the field
        assert "'8OO': must be a number or a quantity with a unit" in wizard.text(
            app.query_one("#f-rotary-torque-Nm-err", Label)
        )
        saved = drafts.load_draft(VALVE).doc
        # neither 8.0 nor the old 1000: the text as typed, to be fixed when resumed
        assert saved["rotary"]["torque_Nm"] == "8OO"
        assert "torque_Nm" not in app.doc["rotary"]  # and nothing of it is computed
        # ctrl+s refuses the same way
        await pilot.press("ctrl+s")
        await pilot.pause()
        assert not isinstance(app.screen, ExportScreen)


async def test_a_cleared_field_is_not_computed_with_its_old_value(wizard):
    app = DriveAdvisorApp(_doc(), VALVE, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+n")
        await _retype(pilot, app, "f-rotary-torque-Nm", "")
        start = app.results_version
        await pilot.press("ctrl+r")
        await pilot.pause(0.3)
        assert app.results_version == start  # not 1000 N·m, the value no longer shown
        assert app.step == 1 and app.focused is app.query_one("#f-rotary-torque-Nm")
        assert "required" in wizard.text(app.query_one("#f-rotary-torque-Nm-err", Label))
        # typed again, it computes exactly what is shown
        await pilot.press(*"800")
        await wizard.compute(pilot)
        assert app.report.requirements["rotary"]["torque_Nm"] == 800.0


async def test_an_error_on_another_step_is_shown_before_computing(wizard):
    app = DriveAdvisorApp(_doc(), VALVE, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+n", "ctrl+n")
        assert app.step == 2
        await _retype(pilot, app, "f-envelope-max-length-mm", "-5")
        await pilot.press("ctrl+n", "ctrl+n")  # the engine's check stops ctrl+n on step 2
        assert app.step == 2
        await pilot.press("ctrl+b", "ctrl+b")
        start = app.results_version
        await pilot.press("ctrl+r")
        await pilot.pause(0.3)
        assert app.results_version == start and app.step == 2
        assert "must be ≥ 1" in wizard.text(app.query_one("#f-envelope-max-length-mm-err", Label))


async def test_an_infeasible_recompute_leaves_no_plot_of_the_previous_design(wizard):
    app = DriveAdvisorApp(_doc(), VALVE, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await wizard.compute(pilot)
        assert app.report is not None
        app.query_one("#result-tabs").active = "tab-plot"  # plots are drawn when shown
        await pilot.pause()
        assert len(app.query_one("#plot-switcher").children) == 1 and len(app.plot_titles) == 2
        await pilot.press("ctrl+e", "ctrl+n", "ctrl+n")
        await _retype(pilot, app, "f-envelope-max-outer-diameter-mm", "20")
        await wizard.compute(pilot)
        assert app.report is None
        assert len(app.query_one("#plot-switcher").children) == 0
        assert "No plot" in wizard.text(app.query_one("#plot-note", Static))
        for name in ("components", "decisions", "checks"):
            assert "No design to show" in wizard.text(app.query_one(f"#view-{name}", Static))
        summary = wizard.text(app.query_one("#view-summary", Static))
        assert summary.count("No feasible design") == 1
        assert "No design" in wizard.text(app.query_one("#result-status", Static))


async def test_results_say_when_the_inputs_changed_since_and_the_report_is_not_saved_stale(wizard):
    app = DriveAdvisorApp(_doc(), VALVE, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await wizard.compute(pilot)
        assert "as they are now" in wizard.text(app.query_one("#result-status", Static))
        await pilot.press("ctrl+e", "ctrl+n")
        await _retype(pilot, app, "f-rotary-torque-Nm", "900")
        assert "changed since this result" in wizard.text(app.query_one("#result-status", Static))
        await pilot.press("ctrl+s")
        await pilot.pause()
        assert isinstance(app.screen, ExportScreen)
        assert app.screen.query_one("#save-report", Button).disabled
        await pilot.press("escape")
        await wizard.compute(pilot)
        summary = wizard.text(app.query_one("#view-summary", Static))
        assert "Changed since the previous result" in summary
        # the lines of advisor diff: the requirement with its unit, then what followed
        assert "requirement rotary.torque_Nm: 1000 N·m → 900 N·m" in summary


async def test_opening_a_file_keeps_the_draft_of_a_new_requirement():
    drafts.save_draft({"application": {"kind": "linear", "title": "unsaved work"}})
    app = DriveAdvisorApp(_doc(), VALVE)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+n")
        await _retype(pilot, app, "f-rotary-torque-Nm", "900")
        await pilot.pause()
    assert drafts.load_draft().doc == {"application": {"kind": "linear", "title": "unsaved work"}}
    assert drafts.load_draft(VALVE).doc["rotary"]["torque_Nm"] == 900.0
    # the file's own draft is offered when the file is opened again
    app = DriveAdvisorApp(_doc(), VALVE)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        assert isinstance(app.screen, ConfirmScreen)
        await pilot.press("y")
        await pilot.pause()
        assert app.query_one("#f-rotary-torque-Nm", Input).value == "900"


# ------------------------------------------------------------------ every file can be fixed
async def test_a_file_without_the_motor_table_gets_its_fixed_values(tmp_path, wizard):
    doc = _doc()
    del doc["motor"]
    app = DriveAdvisorApp(doc, tmp_path / "no_motor.toml", save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        for step in (1, 2, 3, 4):
            await pilot.press("ctrl+n")
            assert app.step == step
        await wizard.compute(pilot)
        assert app.report is not None


async def test_an_unknown_key_is_renamed_to_the_closest_known_key(tmp_path):
    doc = _doc()
    doc["rotary"]["sped_rpm"] = doc["rotary"].pop("speed_rpm")
    app = DriveAdvisorApp(doc, tmp_path / "typo.toml", save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+n", "ctrl+n")
        assert app.step == 1  # refused: the unknown key and the missing speed
        buttons = [str(b.label) for b in app.query(".fix Button")]
        assert buttons == ["Rename to speed_rpm", "Remove sped_rpm"]
        assert app.focused is app.query(".fix Button").first()
        await pilot.press("enter")
        await pilot.pause()
        assert app.doc["rotary"]["speed_rpm"] == doc["rotary"]["sped_rpm"]
        assert "sped_rpm" not in app.doc["rotary"]
        assert app.query_one("#f-rotary-speed-rpm", Input).value != ""
        await pilot.press("ctrl+n")
        assert app.step == 2


async def test_an_unknown_key_can_be_removed(tmp_path, wizard):
    doc = _doc()
    doc["gearbox"]["colour"] = "red"
    app = DriveAdvisorApp(doc, tmp_path / "extra.toml", save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+r")
        await pilot.pause(0.3)
        assert app.step == 3 and app.report is None
        assert [str(b.label) for b in app.query(".fix Button")] == ["Remove colour"]
        await pilot.click(".fix Button")
        await pilot.pause()
        assert "colour" not in app.doc["gearbox"]
        await wizard.compute(pilot)
        assert app.report is not None


async def test_a_wrong_typed_value_is_shown_in_its_field(tmp_path, wizard):
    doc = _doc()
    doc["rotary"]["torque_Nm"] = True
    doc["gearbox"]["rolling_body"] = "cylinder"
    app = DriveAdvisorApp(doc, tmp_path / "types.toml", save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+r")
        await pilot.pause(0.3)
        assert app.step == 1 and app.focused is app.query_one("#f-rotary-torque-Nm")
        assert app.query_one("#f-rotary-torque-Nm", Input).value == "True"
        assert "must be a number or a quantity with a unit" in wizard.text(
            app.query_one("#f-rotary-torque-Nm-err", Label)
        )
        # a choice no list can show is set aside on opening, and said so on the first step
        said = wizard.text(app.query_one("#step-0-error", Static))
        assert "gearbox.rolling_body = 'cylinder': must be one of ball, roller" in said


def test_fixes_for_the_engine_messages():
    doc = {"linear": {"strok_m": 0.2}, "application": {"kind": "linear"}}
    line = "linear.strok_m: unknown key; allowed keys here: force_N, stroke_m, travel_time_s"
    found = fixes.fixes_for(line, doc, "linear")
    assert [f.label for f in found] == ["Rename to stroke_m", "Remove strok_m"]
    fixes.apply(doc, found[0])
    assert doc["linear"] == {"stroke_m": 0.2}
    # a list item named from 1 in messages is index 0 in the document
    assert fixes.message_path("positioning.motors[1].nam: unknown key") == (
        "positioning",
        "motors",
        "0",
        "nam",
    )
    # a value a field shows is fixed in the field, not by a button
    assert fixes.fixes_for("linear.stroke_m = -1: must be > 0", doc, "linear") == []
    # nothing close: only removal
    doc = {"motor": {"zzz": 1}}
    line = "motor.zzz: unknown key; allowed keys here: kind, supply_frequency_Hz"
    assert [f.label for f in fixes.fixes_for(line, doc, "linear")] == ["Remove zzz"]


# ------------------------------------------------------------------ keys and layout
async def test_focus_starts_on_the_first_field_of_each_step_and_no_key_is_lost():
    app = DriveAdvisorApp(save_drafts=False, offer_draft=False)
    async with app.run_test(size=SIZE) as pilot:
        assert app.focused is app.query_one("#kind", RadioSet)
        await pilot.press("down", "enter")  # the second application: rotary
        await pilot.pause()
        assert app.kind == "rotary"
        await pilot.press("ctrl+n", *"750", "enter", *"60")  # typed at once, no click
        assert app.query_one("#f-rotary-torque-Nm", Input).value == "750"
        assert app.query_one("#f-rotary-speed-rpm", Input).value == "60"
        from advisor.tui import fields as F

        after = [f.dotted for f in F.fields_for("rotary", 1)]
        after = after[after.index("rotary.speed_rpm") + 1 :]  # optional ones, left empty
        for _ in after:
            await pilot.press("enter")
            assert app.step == 1
        await pilot.press("enter")  # enter on the last field: the next step
        assert app.step == 2
        assert app.focused is app.query_one("#f-envelope-max-outer-diameter-mm")


async def test_step_names_fit_the_application_and_no_step_is_empty(wizard):
    app = DriveAdvisorApp(
        tomllib.loads((EXAMPLES / "gyro_compensator.toml").read_text()), save_drafts=False
    )
    async with app.run_test(size=(80, 24)) as pilot:
        bar = wizard.text(app.query_one("#steps", Static))
        assert "Aerodynamic drag" in bar or "3" in bar
        await pilot.press("ctrl+n", "ctrl+n")
        assert "Aerodynamic drag" in wizard.text(app.query_one("#steps", Static))
        assert "Review" in wizard.text(app.query_one("#steps", Static))  # named even at 80
    app = DriveAdvisorApp(
        tomllib.loads((EXAMPLES / "positioning_drive.toml").read_text()), save_drafts=False
    )
    async with app.run_test(size=(80, 24)) as pilot:
        await pilot.press("ctrl+n", "ctrl+n")
        assert app.step == 3  # step 2 has no question for a positioning drive: skipped
        assert "Candidate motors" in wizard.text(app.query_one("#steps", Static))
        assert "Review" in wizard.text(app.query_one("#steps", Static))


async def test_export_dialog_path_has_focus_enter_saves_and_keep_keeps_the_path(tmp_path, wizard):
    app = DriveAdvisorApp(_doc(), VALVE, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await wizard.compute(pilot)
        (tmp_path / "taken.report.toml").write_text("keep me")
        await pilot.press("ctrl+s", "ctrl+u", *"taken.report.toml", "enter")
        await pilot.pause()
        assert isinstance(app.screen, ConfirmScreen)
        await pilot.press("n")
        await pilot.pause()
        assert isinstance(app.screen, ExportScreen)
        box = app.screen.query_one("#export-path", Input)
        assert box.value == "taken.report.toml" and app.screen.focused is box
        assert (tmp_path / "taken.report.toml").read_text() == "keep me"
        await pilot.press("ctrl+u", *"fresh.report.toml", "enter")
        await pilot.pause(0.2)
        assert not isinstance(app.screen, ExportScreen)
        assert "[design" in (tmp_path / "fresh.report.toml").read_text()


async def test_export_never_replaces_the_opened_requirement_with_its_report(tmp_path, wizard):
    """The report typed over the requirement file the wizard opened is refused in the dialog
    (as advisor --batch -o refuses it), before any "Replace?" question; so is a directory."""
    src = tmp_path / "valve.toml"
    src.write_text(VALVE.read_text(encoding="utf-8"), encoding="utf-8")
    before = src.read_text(encoding="utf-8")
    (tmp_path / "adir.toml").mkdir()
    app = DriveAdvisorApp(_doc(src), src, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await wizard.compute(pilot)
        await pilot.press("ctrl+s", "ctrl+u", *str(src), "enter")
        await pilot.pause()
        assert isinstance(app.screen, ExportScreen)  # no confirmation asked
        assert "is the requirement file itself" in wizard.text(
            app.screen.query_one("#export-error")
        )
        await pilot.press("ctrl+u", *str(tmp_path / "adir.toml"), "enter")
        await pilot.pause()
        assert isinstance(app.screen, ExportScreen)
        assert "not a regular file" in wizard.text(app.screen.query_one("#export-error"))
    assert src.read_text(encoding="utf-8") == before


async def test_it_shows_that_it_is_computing(monkeypatch, wizard):
    import threading

    from advisor.core import engine

    real = engine.advise
    gate = threading.Event()  # the advice waits until the test has read the screen

    def held(*args, **kwargs):
        gate.wait(30)
        return real(*args, **kwargs)

    monkeypatch.setattr(engine, "advise", held)
    app = DriveAdvisorApp(_doc(), VALVE, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        start = app.results_version
        await pilot.press("ctrl+r")
        for _ in range(500):  # no fixed delay: a loaded machine only takes longer
            if app.computing:
                break
            await pilot.pause(0.02)
        await pilot.pause()
        during = wizard.text(app.query_one("#steps", Static))
        gate.set()
        await wizard.settle(pilot, start)
        assert "Computing" in during
        assert "Computing" not in wizard.text(app.query_one("#steps", Static))


async def test_one_way_device_summary_and_components(wizard):
    app = DriveAdvisorApp(_doc(), VALVE, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await wizard.compute(pilot)
        summary = wizard.text(app.query_one("#view-summary", Static))
        assert "holding: roller clutch at the motor side" in summary
        comps = wizard.text(app.query_one("#view-components", Static))
        assert "where" in comps and "motor side" in comps and "output side" in comps
        assert "em clutch" in comps and "(chosen)" in comps and "basis" in comps


# ------------------------------------------------------------------ compare
async def test_compare_shows_the_alternatives_and_use_this_imposes_one(wizard):
    app = DriveAdvisorApp(_doc(), VALVE, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await wizard.compute(pilot)
        app.query_one("#result-tabs").active = "tab-compare"
        await pilot.pause()
        text = "\n".join(wizard.text(w) for w in app.query("#compare-box Static"))
        assert "▶ rules (seed 000)" in text and "lightest in the space" in text
        assert "slimmest in the space" in text and "▶ roller clutch" in text
        assert "▶ chosen: BL-02" in text and "OW-02" in text
        labels = [str(b.label) for b in app.query("#compare-box Button")]
        assert "Use em clutch at the motor side" in labels
        assert "Use roller clutch at the output side" in labels
        assert "Use the lightest" in labels and "Use the slimmest" in labels
        start = app.results_version
        button = next(b for b in app.query("#compare-box Button") if "em clutch" in str(b.label))
        button.press()
        await wizard.settle(pilot, start)
        assert app.doc["one_way"]["type"] == "em_clutch"
        assert app.report.design.one_way.type == "em_clutch"  # the next compute is that design
        summary = wizard.text(app.query_one("#view-summary", Static))
        assert "requirement one_way.type: auto → em_clutch" in summary  # advisor diff's words


async def test_compare_use_takes_the_lightest_reducer_and_the_device_at_the_output(wizard):
    app = DriveAdvisorApp(_doc(), VALVE, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await wizard.compute(pilot)
        lightest = app.report.design.gearbox.optimum
        app.query_one("#result-tabs").active = "tab-compare"
        await pilot.pause()

        async def use(label: str) -> None:
            start = app.results_version
            button = next(b for b in app.query("#compare-box Button") if str(b.label) == label)
            button.press()
            await wizard.settle(pilot, start)
            app.query_one("#result-tabs").active = "tab-compare"  # the result opens on Summary
            await pilot.pause()

        await use("Use the lightest")
        assert app.doc["gearbox"]["choice"] == "lightest"
        g = app.report.design.gearbox  # the next compute is that reducer
        assert g.mass_kg == lightest.mass_kg and len(g.stages) == len(lightest.stages)
        text = "\n".join(wizard.text(w) for w in app.query("#compare-box Static"))
        assert "▶ lightest in the space" in text and "WG-06" in text
        labels = [str(b.label) for b in app.query("#compare-box Button")]
        assert "Use the rules" in labels and "Use the lightest" not in labels

        await use("Use roller clutch at the output side")
        assert (app.doc["one_way"]["type"], app.doc["one_way"]["location"]) == (
            "roller_clutch",
            "output_side",
        )
        ow = app.report.design.one_way
        assert ow.location == "output side" and ow.torque_Nm == app.doc["rotary"]["torque_Nm"]
        assert ow.motor_side is not None and ow.motor_side.location == "motor side"
        # the field on the wizard's step shows what "Use" set
        assert app.query_one("#f-one-way-location").value == "output_side"


async def test_compare_after_an_infeasible_result_says_why_there_is_nothing(wizard):
    doc = _doc()
    doc.setdefault("envelope", {})["max_outer_diameter_mm"] = 20
    app = DriveAdvisorApp(doc, VALVE, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await wizard.compute(pilot)
        text = "\n".join(wizard.text(w) for w in app.query("#compare-box Static"))
        assert "Nothing to compare: the requirement has no feasible design" in text


def test_plot_markers_tell_series_apart_without_colour():
    from advisor.tui import views

    data = views.PlotData("t", "x", "y", [("a", [1, 2], [1, 2]), ("b", [1, 2], [2, 1])])
    data = data._replace(series=[*data.series, ("working point", [1.5], [1.5])])
    assert views.markers(data) == ["•", "+", "◆"]
    assert views.legend(data) == "• a   + b   ◆ working point"
    assert views.plural(1, "check") == "1 check" and views.plural(2, "check") == "2 checks"


async def test_keys_arriving_in_a_burst_act_in_order(wizard):
    """A loaded machine delivers keys in bursts: ctrl+u then a path, all queued at once.
    textual ran ctrl+u's deletion after the path was typed (and deleted it); here it acts
    first, as typed. The same for backspace in a wizard field."""
    from textual import events

    def burst(app, keys):
        for key in keys:
            char = {"ctrl+u": "\x15", "backspace": "\x7f", "full_stop": "."}.get(key, key)
            app.post_message(events.Key(key, char))

    app = DriveAdvisorApp(_doc(), VALVE, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await wizard.compute(pilot)
        await pilot.press("ctrl+s")
        await pilot.pause()
        burst(app, ["ctrl+u", *"e2e", "full_stop", *"toml"])
        await pilot.pause(0.3)
        assert app.screen.query_one("#export-path", Input).value == "e2e.toml"
        await pilot.press("escape", "ctrl+e", "ctrl+n")
        box = app.query_one("#f-rotary-torque-Nm", Input)
        assert app.focused is box
        burst(app, ["ctrl+u", "8", "backspace", "9", "0", "0"])
        await pilot.pause(0.3)
        assert box.value == "900"


def test_the_loss_curve_passes_through_every_candidate_speed():
    """The curve is computed as the candidates are: at each candidate speed it gives the
    report's own losses (the rudder: 228.42 W at 5000 rpm, the reference point of seed 000
    whose losses are the frame's limit)."""
    from advisor.applications.rotary.views import loss_curve
    from advisor.core.engine import advise
    from advisor.core.reading import read_requirements

    report = advise(read_requirements(EXAMPLES / "rudder_actuator.toml"))
    curve = {round(c["speed_rpm"], 6): c for c in loss_curve(report)}
    assert len(curve) > 30  # a curve, not two points
    for cand in report.design.motor.candidates:
        assert curve[cand.speed_rpm]["total"] == pytest.approx(cand.losses_W.total, rel=1e-12)
    assert curve[5000.0]["total"] == pytest.approx(228.42, abs=0.01)


async def test_a_message_the_engine_no_longer_gives_leaves_its_field(tmp_path, wizard):
    """An S4 duty without starts_per_hour: the empty field says "missing; required for
    duty_type = 'S4'". Once the duty is S3, the engine says nothing of it, and neither may
    the field, while a design computed from the same inputs is shown (a reviewer found the
    old message left in place)."""
    from textual.widgets import Select

    from advisor.tui import fields as F

    doc = _doc(EXAMPLES / "rudder_actuator_duty.toml")
    duty = doc["duty"]
    del duty["segments"], duty["cycles_per_hour"]
    duty |= {"duty_type": "S4", "cyclic_duration_factor": 0.4}
    app = DriveAdvisorApp(doc, source=tmp_path / "r.toml", save_drafts=False, offer_draft=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        await pilot.press("ctrl+r")
        await pilot.pause(0.3)
        ids = [f.id for f in F.fields_for(app.kind, 4)]
        starts = next(i for i in ids if "starts-per-hour" in i)
        kind = next(i for i in ids if "duty-type" in i)
        label = app.query_one(f"#{starts}-err", Label)
        assert "missing; required for duty_type = 'S4'" in wizard.text(label)
        assert app.report is None
        app.query_one(f"#{kind}", Select).value = "S3"
        await pilot.pause()
        await wizard.compute(pilot)
        assert app.report is not None
        assert wizard.text(label).strip() == ""


async def test_a_title_with_terminal_escapes_is_shown_escaped():
    """A title carrying ESC sequences (clear screen, set the window title), BEL and a bidi
    override is shown with them escaped in its box: nothing reaches the terminal raw."""
    doc = _doc()
    doc["application"]["title"] = "A\x1b[2J\x1b]0;pwned\x07B\u202eC"
    app = DriveAdvisorApp(doc, VALVE, save_drafts=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        value = app.query_one("#f-application-title", Input).value
        assert value.isprintable()
        assert "\\x1b[2J" in value and "\\u202e" in value
