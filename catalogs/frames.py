"""The BLDC frame series scaled from seed 000's reference frame, and its checks.

``catalogs/bldc_frames.toml`` holds the reference frame (seed 000's 74 mm × 50 mm motor) and
the frames derived from it by geometric similarity with the scaling laws of
:data:`advisor.calc.bldc.SCALING_EXPONENTS` (Budinger et al. 2012, 2014). The file is data:
each row states its numbers, and the loader checks every number against the law from the
reference at the row's length scale l* = D/D_ref (:func:`check_row`), so a row edited by hand
that breaks the similarity is refused. The file is written by this module::

    python -m catalogs.frames > catalogs/bldc_frames.toml
"""

from typing import Any

from advisor.calc import bldc

#: Stator outer diameters of the series, mm: steps of about 15 % (1.63 times the torque),
#: from 37 mm (0.18 N·m) to 280 mm (211 N·m), seed 000's 74 mm among them.
DIAMETERS_MM = (37, 42, 48, 55, 63, 74, 85, 98, 112, 130, 150, 170, 195, 225, 250, 280)
#: What every scaled row says it is, and the sources of its numbers.
ORIGIN = "scaled from seed 000's reference frame by the file's law"
FRAME_SOURCES = ("seed-000", "budinger-2012", "budinger-course", "sizinglab-notebooks")
#: |row − law| allowed, as a share of the law's value: the rows are written to 5 figures.
LAW_TOLERANCE = 2e-4
#: The quantities a scaled row states, each by its law; magnet losses are checked per point.
SCALED = (
    "torque_Nm",
    "speed_rpm",
    "stack_length_mm",
    "stator_steel_area_mm2",
    "phase_resistance_ohm",
    "current_A",
    "rotor_inertia_kgm2",
    "mass_kg",
    "thermal_time_constant_s",
)


def frame_name(diameter_mm: float, stack_mm: float) -> str:
    """BL074x050: stator outer diameter × stack length, mm."""
    return f"BL{round(diameter_mm):03d}x{round(stack_mm):03d}"


def _sig(x: float, n: int = 5) -> float:
    return float(f"{x:.{n}g}")


def scaled_row(ref: dict[str, Any], diameter_mm: float) -> dict[str, Any]:
    """The frame of stator diameter ``diameter_mm`` scaled from the reference table."""
    k = diameter_mm / ref["stator_outer_diameter_mm"]
    row: dict[str, Any] = {"length_scale": _sig(k, 6), "stator_outer_diameter_mm": diameter_mm}
    for q in SCALED:
        row[q] = _sig(bldc.scaled(q, ref[q], k))
    row["name"] = frame_name(diameter_mm, row["stack_length_mm"])
    row["magnet_losses"] = [
        [n, _sig(bldc.scaled("magnet_loss_W", w, k))] for n, w in ref["magnet_losses"]
    ]
    return row


def check_row(row: dict[str, Any], ref: dict[str, Any]) -> str | None:
    """Why a scaled row breaks the law from the reference, or None: every quantity of
    :data:`SCALED` and each magnet loss within :data:`LAW_TOLERANCE` of the law at
    l* = D/D_ref."""
    k = row["stator_outer_diameter_mm"] / ref["stator_outer_diameter_mm"]
    for q in SCALED:
        want = bldc.scaled(q, ref[q], k)
        if abs(row[q] - want) > LAW_TOLERANCE * abs(want):
            e = bldc.SCALING_EXPONENTS[q]
            return (
                f"field {q} = {row[q]!r}: the law gives {want:.5g} (reference {ref[q]:g} × "
                f"l*^{e:g}, l* = {row['stator_outer_diameter_mm']:g}/"
                f"{ref['stator_outer_diameter_mm']:g} = {k:.5g})"
            )
    ref_pts = {n: w for n, w in ref["magnet_losses"]}
    for n, w in row["magnet_losses"]:
        if n not in ref_pts:
            return f"field magnet_losses: {n:g} rpm is not a speed of the reference's"
        want = bldc.scaled("magnet_loss_W", ref_pts[n], k)
        if abs(w - want) > LAW_TOLERANCE * max(abs(want), 1e-9):
            return f"field magnet_losses = {w!r} W at {n:g} rpm: the law gives {want:.5g} W (l*³)"
    return None


def _toml_value(v: Any) -> str:
    if isinstance(v, str):
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(v, list):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    if isinstance(v, float) and v.is_integer() and abs(v) < 1e15:
        return f"{v:.1f}"
    return repr(v)


def render(header: str, reference: dict[str, Any], sources: dict[str, str]) -> str:
    """The TOML text of the series from its reference table (see the module's docstring)."""
    out = [header.rstrip(), "", f"law = {_toml_value(bldc.SCALING_LAW)}", "", "[sources]"]
    out += [f"{k} = {_toml_value(v)}" for k, v in sources.items()]
    out += ["", "[reference]"]
    out += [f"{k} = {_toml_value(v)}" for k, v in reference.items()]
    for d in DIAMETERS_MM:
        row = scaled_row(reference, float(d))
        out += ["", "[[frame]]"]
        for key in ("name", "length_scale", "stator_outer_diameter_mm", *SCALED):
            out.append(f"{key} = {_toml_value(row[key])}")
        out.append(f"magnet_losses = {_toml_value(row['magnet_losses'])}")
        out.append(f"origin = {_toml_value(ORIGIN)}")
        out.append(f"source = {_toml_value(list(FRAME_SOURCES))}")
    return "\n".join(out) + "\n"


if __name__ == "__main__":  # regenerate the file from its own reference table and header
    import tomllib
    from pathlib import Path

    path = Path(__file__).with_name("bldc_frames.toml")
    text = path.read_text(encoding="utf-8")
    data = tomllib.loads(text)
    lines = text.splitlines()
    head = "\n".join(lines[: next(i for i, ln in enumerate(lines) if not ln.startswith("#"))])
    print(render(head, data["reference"], data["sources"]), end="")
