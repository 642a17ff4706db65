"""Options that a requirement gives but the advisor cannot honour or does not use.

A silently ignored option misleads a designer who checks the report by hand, so:

- ``hold_without_power = true`` on a positioning drive or a spinning rotor is refused: the
  advisor has no holding device for them (seed 004 covers screw and reducer drives only), and a
  design that does not hold must not pass for one that does;
- a ``[one_way]`` table while ``hold_without_power = false`` is reported as ignored, in the
  report's warnings and on stderr: nothing is unsafe (no holding was asked for), and the
  wizard keeps the table's choices while the switch is off, so refusing it would block the
  wizard on a setting the user cannot blank.
"""

from typing import Any

IGNORED_PREFIX = "ignored: "


def holds(kind: str) -> bool:
    """Whether an application's design can include a one-way holding device (seed 004): its
    requirement model has a ``[one_way]`` table (linear and rotary actuators)."""
    from advisor.core.registry import requirements_model

    return "one_way" in requirements_model(kind).model_fields


def contradictions(data: dict[str, Any]) -> list[str]:
    """Refusals for a document whose [application] table is already valid."""
    app = data.get("application", {})
    kind = app.get("kind")
    if app.get("hold_without_power") is True and not holds(kind):
        return [
            f"application.hold_without_power = true: not available for a {kind} drive (a "
            "holding one-way device is chosen only for linear and rotary actuators, seed 004); "
            "remove it or set it false"
        ]
    return []


def ignored(req: Any) -> list[str]:
    """Warnings for options of a valid requirement that the design does not use."""
    if (
        "one_way" in req.model_fields_set
        and holds(req.application.kind)
        and not req.application.hold_without_power
    ):
        return [
            IGNORED_PREFIX + "the [one_way] table, because application.hold_without_power = "
            "false: no holding device is chosen (set it true to choose one)"
        ]
    return []
