"""The positioning drive's key outputs in a family study's designs.csv (seed 003): the
motor and the ratio to build.

The columns are the family's (:data:`advisor.family.outputs.COLUMNS`); a column this
application leaves out stays blank."""

from typing import Any

from advisor.family.outputs import Row, lowest_margin

#: What a column means for this application, where it needs saying (docs/family.md).
MEANING = {
    "motor": "chosen candidate",
    "ratio": "optimal ratio",
}


def key_outputs(report: dict[str, Any]) -> Row:
    """This application's columns of designs.csv, read from a variant's report."""
    # the drive to build: the duty cycle's ratio where there is one (the fastest may fail it)
    mo, duty = report["design"]["motion"], report["design"].get("duty")
    src = duty if duty is not None else {"motor": mo["motor"], "ratio": mo["optimal_ratio"]}
    return {"motor": src["motor"], "ratio": src["ratio"], **lowest_margin(report)}
