"""One source of truth for the questions: the wizard marks as optional exactly the fields the
requirement model defaults, shows the model's defaults, and asks every field the model
requires. The models are read here directly (``model_fields``), not through
advisor.core.questions, so the wizard is checked against the models themselves."""

import pytest
from textual.containers import Horizontal
from textual.widgets import Input, Label, Select, Switch

from advisor.core import registry
from advisor.core.questions import questions, unit_of
from advisor.tui import fields as F
from advisor.tui.app import DriveAdvisorApp

KINDS = ("linear", "rotary", "positioning", "spinning_rotor")


def _info(model, path):
    """The FieldInfo at a path of the requirement document (list rows: the item's field)."""
    info = None
    for part in path:
        if part.isdigit():
            continue
        info = model.model_fields[part]
        ann = info.annotation
        args = [a for a in getattr(ann, "__args__", ()) if isinstance(a, type)]
        model = next((a for a in (ann, *args) if hasattr(a, "model_fields")), None)
    return info


def _label(app, f) -> str:
    row = next(a for a in app.query_one(f"#{f.id}").ancestors if a.has_class("field"))
    assert isinstance(row, Horizontal)
    return str(row.query_one("Label.name", Label).content)


@pytest.fixture(autouse=True)
def _state(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_STATE_HOME", str(tmp_path / "state"))


@pytest.mark.parametrize("kind", KINDS)
async def test_optional_exactly_where_the_model_defaults_and_its_default_shown(kind):
    model = registry.requirements_model(kind)
    app = DriveAdvisorApp({"application": {"kind": kind}}, save_drafts=False, offer_draft=False)
    async with app.run_test(size=(120, 40)) as pilot:
        await pilot.pause()
        fields = F.all_fields(kind)
        assert fields
        for f in fields:
            info = _info(model, f.path)
            label = _label(app, f)
            assert label.endswith("(optional)") == (not info.is_required()), (f.dotted, label)
            control = app.query_one(f"#{f.id}")
            default = None if info.is_required() else info.get_default(call_default_factory=True)
            if isinstance(control, Switch | Select):
                shown = None if control.value is Select.NULL else control.value  # left blank
                assert shown == default, f.dotted
            elif default not in (None, []):
                assert isinstance(control, Input) and control.value == ""
                shown = (
                    ", ".join(f"{v:g}" for v in default)
                    if isinstance(default, list)
                    else (f"{default:g}" if isinstance(default, float) else str(default))
                )
                assert control.placeholder == f"default {shown}", f.dotted


@pytest.mark.parametrize("kind", KINDS)
def test_the_wizard_asks_every_field_the_model_requires(kind):
    model = registry.requirements_model(kind)
    asked = {f.path for f in F.all_fields(kind)} | {("application", "kind")}
    fixed = set(_fixed(F.starting_doc(kind)))
    for q in questions(model, wizard=True):
        # needed: required, and in tables (or a list) that are required themselves
        needed = all(
            _info(model, q.path[: k + 1]).is_required()
            for k in range(len(q.path))
            if not q.path[k].isdigit()
        )
        if needed and q.path not in fixed:
            assert q.path in asked, q.path


def _fixed(doc, prefix=()):
    for k, v in doc.items():
        if isinstance(v, dict):
            yield from _fixed(v, (*prefix, k))
        else:
            yield (*prefix, k)


async def test_the_three_mismatches_of_issue_11_are_gone():
    # linear: the unsupported screw length is required, and shown so
    f = next(f for f in F.all_fields("linear") if f.path == ("linear", "support_span_m"))
    assert not f.optional and "(optional)" not in f.label
    # rotary: the stage efficiency may stay empty; the engine's 0.9 is shown
    f = next(f for f in F.all_fields("rotary") if f.path == ("gearbox", "stage_efficiency"))
    assert f.optional and f.shown_default == "default 0.9"
    assert F.parse_text(f, "") == (None, None)
    # positioning: M_λ is required in a motor row that is started; no row at all is fine
    # where a move time is required (the catalog's smallest motor that meets it is chosen)
    app = DriveAdvisorApp(
        {
            "application": {"kind": "positioning"},
            "positioning": {
                "travel_rad": 3.0,
                "load_inertia_kgm2": 0.5,
                "load_torque_Nm": 1.0,
                "move_time_s": 1.0,
            },
        },
        save_drafts=False,
        offer_draft=False,
    )
    async with app.run_test(size=(120, 40)) as pilot:
        await pilot.pause()
        torque = next(f for f in F.all_fields("positioning") if f.path[-1] == "accel_torque_Nm")
        assert not _label(app, torque).endswith("(optional)")
        assert app._validate(3)
        app.query_one("#f-positioning-motors-0-name", Input).value = "M1"
        await pilot.pause()
        assert not app._validate(3)
        err = app.query_one("#f-positioning-motors-0-accel-torque-Nm-err", Label)
        assert "missing; required" in str(err.content)


def test_units_come_from_the_key_suffix():
    assert unit_of("force_N") == "N"
    assert unit_of("angular_momentum_kgm2_s") == "kg·m²/s"
    assert unit_of("travel_time_s") == "s"
    assert unit_of("steel_density_kg_m3") == "kg/m³"
    assert unit_of("friction_coefficient") == "" and unit_of("starts") == ""
