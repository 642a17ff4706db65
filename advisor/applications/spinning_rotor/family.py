"""The spinning rotor's key outputs in a family study's designs.csv (seed 002): its
speed and its steady power with the gyroscopic reaction.

The columns are the family's (:data:`advisor.family.outputs.COLUMNS`); a column this
application leaves out stays blank."""

from typing import Any

from advisor.family.outputs import Row, lowest_margin

#: What a column means for this application, where it needs saying (docs/family.md).
MEANING = {
    "losses_W": "steady power with the gyroscopic reaction",
}


def key_outputs(report: dict[str, Any]) -> Row:
    """This application's columns of designs.csv, read from a variant's report."""
    r = report["design"]["rotor"]
    return {
        "motor_speed_rpm": r["speed_rpm"],
        "losses_W": r["steady_power_W"]["with_reaction"],
        **lowest_margin(report),
    }
