"""The rotary actuator's key outputs in a family study's designs.csv (seed 000): the
motor speed chosen and its frame, the reducer's ratio, stages, mass and diameter, the motor's
losses.

The columns are the family's (:data:`advisor.family.outputs.COLUMNS`); a column this
application leaves out stays blank."""

from typing import Any

from advisor.core.report import round_sig
from advisor.family.outputs import Row, lowest_margin, one_way, one_way_mass_kg

#: What a column means for this application, where it needs saying (docs/family.md).
MEANING = {
    "motor": "'bldc N rpm': the candidate speed chosen (the frame rewound for it)",
    "frame": "the motor frame chosen: a scaled frame BLDDDxLLL or a catalog motor",
    "mass_kg": "wave-gear reducer + one-way device (the motor is not sized by mass)",
    "outer_diameter_mm": "reducer outer diameter",
    "losses_W": "motor losses (ohmic + iron + magnets)",
}


def key_outputs(report: dict[str, Any]) -> Row:
    """This application's columns of designs.csv, read from a variant's report."""
    d = report["design"]
    m, g = d["motor"], d["gearbox"]
    return {
        "motor": f"bldc {m['speed_rpm']:g} rpm",  # the choice among the candidate speeds
        "frame": (m.get("frame") or {}).get("name"),  # the frame chosen
        "pole_pairs": m["pole_pairs"],
        "motor_speed_rpm": m["speed_rpm"],
        "ratio": g["total_ratio"],
        "stages": len(g["stages"]),
        "mass_kg": round_sig(g["mass_kg"] + one_way_mass_kg(d)),
        "outer_diameter_mm": g["outer_diameter_mm"],
        "losses_W": m["losses_W"]["total"],
        **one_way(d),
        **lowest_margin(report),
    }
