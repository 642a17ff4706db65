"""The linear actuator's key outputs in a family study's designs.csv (seed 001): the
catalog motor, its working speed, the screw's thread (its GOST 24739-81 designation with the
starts, so that a change of starts is a change) and the mass.

The columns are the family's (:data:`advisor.family.outputs.COLUMNS`); a column this
application leaves out stays blank."""

from typing import Any

from advisor.core.report import round_sig
from advisor.family.outputs import Row, lowest_margin, one_way, one_way_mass_kg

#: What a column means for this application, where it needs saying (docs/family.md).
MEANING = {
    "motor": "4A catalog model",
    "motor_speed_rpm": "working speed under the load",
    "mass_kg": "catalog motor + one-way device",
}


def key_outputs(report: dict[str, Any]) -> Row:
    """This application's columns of designs.csv, read from a variant's report."""
    d = report["design"]
    s, m = d["screw"], d["motor"]
    return {
        "motor": m["model"],
        "pole_pairs": m["pole_pairs"],
        "motor_speed_rpm": m["working_speed_rpm"],
        "mass_kg": round_sig(m["mass_kg"] + one_way_mass_kg(d)),
        "screw_thread": s["designation"],
        **one_way(d),
        **lowest_margin(report),
    }
