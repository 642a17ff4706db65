"""Every spinning-rotor requirement inside the documented ranges of
advisor/applications/spinning_rotor/requirements.py ends in a report (exit 0) or a stated
infeasibility (exit 3), never in exit 1, and no report holds nan or inf. The ranges
are read from the model, so the test follows them; each number is drawn at an edge,
uniformly, or log-uniformly across the range."""

import math
import tomllib

import annotated_types as at
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from advisor.applications.spinning_rotor.requirements import (
    AeroReq,
    MIN_SLEW_RATE_rad_s,
    RotorReq,
)
from advisor.cli import main
from advisor.core.requirements import range_in_words


def _bounds(model, name: str) -> tuple[float, float]:
    lo = hi = None
    for m in model.model_fields[name].metadata:
        if isinstance(m, at.Ge | at.Gt):
            lo = m.ge if isinstance(m, at.Ge) else m.gt
        if isinstance(m, at.Le):
            hi = m.le
    assert lo is not None and hi is not None, f"{name} has no documented range"
    desc = model.model_fields[name].description
    words = range_in_words(name, model.model_fields[name]).split(" … ")[-1]  # 0 or 1e-6 … 100
    assert words in desc, f"{name}: the range {words!r} is not in the description {desc!r}"
    return float(lo), float(hi)


def _across(lo: float, hi: float) -> st.SearchStrategy[float]:
    """The edges, uniform values and, for a range of decades, log-uniform values."""
    finite = dict(allow_nan=False, allow_infinity=False)
    parts = [st.sampled_from([lo, hi]), st.floats(lo, hi, **finite)]
    if lo > 0 and hi / lo > 100:
        parts.append(
            st.floats(math.log10(lo), math.log10(hi), **finite).map(
                lambda e: min(hi, max(lo, 10.0**e))
            )
        )
    return st.one_of(parts)


def _field(model, name: str) -> st.SearchStrategy[float]:
    return _across(*_bounds(model, name))


def test_every_number_has_a_range_in_its_description():
    for model in (RotorReq, AeroReq):
        for name, info in model.model_fields.items():
            if info.annotation in (float, float | None) and name != "slew_rate_rad_s":
                _bounds(model, name)
    assert "0 (no slew)" in RotorReq.model_fields["slew_rate_rad_s"].description


@st.composite
def rotor_anywhere(draw):
    from catalogs import load_catalogs

    bearings = load_catalogs().bearings
    b = draw(st.sampled_from(bearings))
    f = lambda name: draw(_field(RotorReq, name))  # noqa: E731
    rotor = {
        "mass_kg": f("mass_kg"),
        "speed_rad_s": f("speed_rad_s"),
        "bearing": b.designation,
        "bearing_count": draw(st.integers(2, 8)),
        "ball_plane_to_cg_mm": f("ball_plane_to_cg_mm"),
        "slew_rate_rad_s": draw(
            st.one_of(
                st.just(0.0), _across(MIN_SLEW_RATE_rad_s, _bounds(RotorReq, "slew_rate_rad_s")[1])
            )
        ),
        "axis_angle_deg": f("axis_angle_deg"),
        "slew_angle_deg": f("slew_angle_deg"),
        "run_up_time_s": f("run_up_time_s"),
        "rolling_friction_mm": f("rolling_friction_mm"),
        "lubricant_viscosity_mm2_s": f("lubricant_viscosity_mm2_s"),
    }
    if b.contact_angle_deg == 0 or draw(st.booleans()):
        rotor["contact_angle_deg"] = f("contact_angle_deg")
    if draw(st.booleans()):
        rotor["required_life_h"] = f("required_life_h")
    if draw(st.booleans()):
        rotor["inertia_kgm2"] = f("inertia_kgm2")
    else:
        rotor["angular_momentum_kgm2_s"] = f("angular_momentum_kgm2_s")
    g = lambda name: draw(_field(AeroReq, name))  # noqa: E731
    if draw(st.booleans()):
        aero = {"loss_W": g("loss_W")}
    else:
        outer = g("outer_radius_mm")
        aero = {
            "outer_radius_mm": outer,
            "outer_length_mm": g("outer_length_mm"),
            # below the outer radius, as the model requires
            "inner_radius_mm": min(g("inner_radius_mm"), outer * draw(st.floats(0.0, 0.999))),
            "inner_length_mm": g("inner_length_mm"),
            "air_density_kg_m3": g("air_density_kg_m3"),
            "air_viscosity_m2_s": g("air_viscosity_m2_s"),
        }
    rotor["aero"] = aero
    return {"application": {"kind": "spinning_rotor"}, "rotor": rotor}


def _finite(value) -> bool:
    if isinstance(value, float):
        return math.isfinite(value)
    if isinstance(value, dict):
        return all(_finite(v) for v in value.values())
    if isinstance(value, list):
        return all(_finite(v) for v in value)
    return True


@pytest.mark.filterwarnings("error")  # no numpy RuntimeWarning either
@settings(
    max_examples=200,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture],
)
@given(data=rotor_anywhere())
def test_any_rotor_in_range_gives_a_report_or_reasons(data, tmp_path, capsys):
    import tomli_w

    path = tmp_path / "r.toml"
    path.write_text(tomli_w.dumps(data), encoding="utf-8")
    rc = main(["--batch", str(path)])
    out, err = capsys.readouterr()
    assert rc in (0, 3), err
    assert "Traceback" not in err and "internal error" not in err
    report = tomllib.loads(out)  # a design's report, or the one saying why there is none
    assert _finite(report), out
    if rc == 3:
        assert err.strip() and report["report"]["status"] == "infeasible"
        return
    assert report["report"]["status"] == "feasible"
    assert len(err.strip().splitlines()) <= 6
