"""The key outputs of a variant, read from its report (the TOML data of ``advisor --batch``).

One small function per application, each reading only its own report's keys, so that each
can move into its application's package. Every application fills the same columns (blank
where the quantity does not exist for it); what each column means per application is in
:data:`MEANING` and docs/family.md.
"""

from collections.abc import Callable
from typing import Any

from advisor.family.adapter import round_sig

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
    "screw_thread",
    "one_way",
    "lowest_margin",
    "lowest_margin_check",
)
#: Discrete choices: where they change along an axis is a finding of the summary.
DISCRETE = ("motor", "frame", "pole_pairs", "stages", "screw_thread", "one_way")
#: Numbers plotted against the axes in family.html.
NUMERIC = ("motor_speed_rpm", "ratio", "mass_kg", "outer_diameter_mm", "losses_W", "lowest_margin")

MEANING = {
    "rotary": {
        "motor": "'bldc N rpm': the candidate speed chosen (the frame rewound for it)",
        "frame": "the motor frame chosen (issue 25): a scaled frame BLDDDxLLL or a catalog motor",
        "mass_kg": "wave-gear reducer + one-way device (the motor is not sized by mass)",
        "outer_diameter_mm": "reducer outer diameter",
        "losses_W": "motor losses (ohmic + iron + magnets)",
    },
    "linear": {
        "motor": "4A catalog model",
        "motor_speed_rpm": "working speed under the load",
        "mass_kg": "catalog motor + one-way device",
    },
    "positioning": {"motor": "chosen candidate", "ratio": "optimal ratio"},
    "spinning_rotor": {"losses_W": "steady power with the gyroscopic reaction"},
}


def _lowest_margin(report: dict[str, Any]) -> Row:
    checks = report.get("checks", [])
    if not checks:
        return {}
    worst = min(checks, key=lambda c: c["margin"])
    return {"lowest_margin": worst["margin"], "lowest_margin_check": worst["id"]}


def _one_way(design: dict[str, Any]) -> Row:
    ow = design.get("one_way")
    if not ow:
        return {}
    return {"one_way": f"{ow['type']} ({ow['location']})"}


def _one_way_mass_kg(design: dict[str, Any]) -> float:
    return (design.get("one_way") or {}).get("mass_kg", 0.0)


def rotary_outputs(report: dict[str, Any]) -> Row:
    d = report["design"]
    m, g = d["motor"], d["gearbox"]
    return {
        "motor": f"bldc {m['speed_rpm']:g} rpm",  # the choice among the candidate speeds
        "frame": (m.get("frame") or {}).get("name"),  # the frame chosen (issue 25)
        "pole_pairs": m["pole_pairs"],
        "motor_speed_rpm": m["speed_rpm"],
        "ratio": g["total_ratio"],
        "stages": len(g["stages"]),
        "mass_kg": round_sig(g["mass_kg"] + _one_way_mass_kg(d)),
        "outer_diameter_mm": g["outer_diameter_mm"],
        "losses_W": m["losses_W"]["total"],
        **_one_way(d),
        **_lowest_margin(report),
    }


def linear_outputs(report: dict[str, Any]) -> Row:
    d = report["design"]
    s, m = d["screw"], d["motor"]
    return {
        "motor": m["model"],
        "pole_pairs": m["pole_pairs"],
        "motor_speed_rpm": m["working_speed_rpm"],
        "mass_kg": round_sig(m["mass_kg"] + _one_way_mass_kg(d)),
        "screw_thread": s["thread"],
        **_one_way(d),
        **_lowest_margin(report),
    }


def positioning_outputs(report: dict[str, Any]) -> Row:
    # the drive to build: the duty cycle's ratio where there is one (the fastest may fail it)
    mo, duty = report["design"]["motion"], report["design"].get("duty")
    src = duty if duty is not None else {"motor": mo["motor"], "ratio": mo["optimal_ratio"]}
    return {"motor": src["motor"], "ratio": src["ratio"], **_lowest_margin(report)}


def spinning_rotor_outputs(report: dict[str, Any]) -> Row:
    r = report["design"]["rotor"]
    return {
        "motor_speed_rpm": r["speed_rpm"],
        "losses_W": r["steady_power_W"]["with_reaction"],
        **_lowest_margin(report),
    }


#: The extractor of each application kind (the report's ``report.application``).
EXTRACTORS: dict[str, Callable[[dict[str, Any]], Row]] = {
    "rotary": rotary_outputs,
    "linear": linear_outputs,
    "positioning": positioning_outputs,
    "spinning_rotor": spinning_rotor_outputs,
}


def key_outputs(report: dict[str, Any]) -> Row:
    """The key outputs of a report, every column present (None where not applicable)."""
    row = EXTRACTORS[report["report"]["application"]](report)
    return {c: row.get(c) for c in COLUMNS}
