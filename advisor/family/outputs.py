"""The key outputs of a variant, read from its report (the TOML data of ``advisor --batch``).

Every application fills the same columns (blank where the quantity does not exist for it),
each from its own report's keys in its own package: its registry entry's ``family`` module
gives ``key_outputs(report)`` and ``MEANING`` (what a column means for it; docs/family.md);
an application without one gets its lowest margin only.
The helpers below read the parts every report may have (the checks, a one-way device).
"""

from collections.abc import Callable
from typing import Any

from advisor.core.registry import family_outputs

Row = dict[str, Any]

#: Columns of designs.csv after the axis values, in order.
COLUMNS = (
    "motor",
    "frame",
    "pole_pairs",
    "motor_speed_rpm",
    "ratio",
    "stages",
    "mass_kg",
    "outer_diameter_mm",
    "losses_W",
    "required_torque_Nm",
    "bearing_life_h",
    "screw_thread",
    "one_way",
    "lowest_margin",
    "lowest_margin_check",
)
#: Discrete choices: where they change along an axis is a finding of the summary.
DISCRETE = ("motor", "frame", "pole_pairs", "stages", "screw_thread", "one_way")
#: Numbers plotted against the axes in family.html.
NUMERIC = ("motor_speed_rpm", "ratio", "mass_kg", "outer_diameter_mm", "losses_W", "lowest_margin")


def lowest_margin(report: dict[str, Any]) -> Row:
    """The check with the least margin: its margin and its id (empty without checks)."""
    checks = report.get("checks", [])
    if not checks:
        return {}
    worst = min(checks, key=lambda c: c["margin"])
    return {"lowest_margin": worst["margin"], "lowest_margin_check": worst["id"]}


def one_way(design: dict[str, Any]) -> Row:
    """The one-way device of a design as ``type (location)`` (empty without one)."""
    ow = design.get("one_way")
    if not ow:
        return {}
    return {"one_way": f"{ow['type']} ({ow['location']})"}


def one_way_mass_kg(design: dict[str, Any]) -> float:
    """The mass of a design's one-way device, 0 without one."""
    return (design.get("one_way") or {}).get("mass_kg", 0.0)


def reader(kind: str) -> Callable[[dict[str, Any]], Row]:
    """What reads an application's key outputs from its report: its own ``key_outputs``,
    or the lowest margin alone (the columns it gives; the others are blank)."""
    outputs = family_outputs(kind)
    return outputs.key_outputs if outputs is not None else lowest_margin


def key_outputs(report: dict[str, Any]) -> Row:
    """The key outputs of a report, every column present (None where not applicable)."""
    row = reader(report["report"]["application"])(report)
    return {c: row.get(c) for c in COLUMNS}


def meaning(kind: str) -> dict[str, str]:
    """What a column means for an application, where it needs saying (empty if nothing)."""
    return dict(getattr(family_outputs(kind), "MEANING", {}))
