"""The spinning rotor's key outputs in a family study's designs.csv (seed 002): its
speed, its steady power with the gyroscopic reaction, the drive torque that sizes the drive
and one bearing's life.

The columns are the family's (:data:`advisor.family.outputs.COLUMNS`); a column this
application leaves out stays blank."""

from typing import Any

from advisor.family.outputs import Row, lowest_margin

#: What a column means for this application, where it needs saying (docs/family.md).
MEANING = {
    "losses_W": "steady power with the gyroscopic reaction",
    "required_torque_Nm": "drive torque: the run-up in time, at least the steady torque with "
    "the reaction (RO-02)",
    "bearing_life_h": "basic rating life L10h of one bearing under the gyroscopic load",
}


def key_outputs(report: dict[str, Any]) -> Row:
    """This application's columns of designs.csv, read from a variant's report."""
    r = report["design"]["rotor"]
    return {
        "motor_speed_rpm": r["speed_rpm"],
        "losses_W": r["steady_power_W"]["with_reaction"],
        "required_torque_Nm": r["required_torque_Nm"],
        "bearing_life_h": r["bearing_life_h"],
        **lowest_margin(report),
    }
