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
    requirement model has a ``[one_way]`` table."""
    from advisor.core.compiled_validator import has_table

    known = has_table(kind, "one_way")  # the compiled spec: no pydantic on the batch path
    if known is not None:
        return known
    from advisor.core.registry import requirements_model

    return "one_way" in requirements_model(kind).model_fields


def contradictions(data: dict[str, Any]) -> list[str]:
    """Refusals for a document whose [application] table is already valid."""
    app = data.get("application", {})
    kind = app.get("kind")
    if app.get("hold_without_power") is True and not holds(kind):
        return [
            f"application.hold_without_power = true: not available for a {kind} drive (a "
            f"holding one-way device is chosen only for {holding_kinds()} actuators, seed 004); "
            "remove it or set it false"
        ]
    return []


def holding_kinds() -> str:
    """The applications whose design can hold the load, as a message names them ("a and b")."""
    from advisor.core.registry import kinds

    names = [k for k in kinds() if holds(k)]
    return ", ".join(names[:-1]) + " and " + names[-1] if len(names) > 1 else "".join(names)


#: The [duty] keys that only some forms of a cycle use (the drives that give segments or a duty
#: type), and which use them: a duty type (IEC 60034-1), or segments (None). An application
#: adds to it through its registry entry (``duty_uses``).
DUTY_KEYS_USED: dict[str, set[str | None]] = {
    "cycles_per_hour": {None},
    "cyclic_duration_factor": {"S3", "S4", "S5", "S6"},
    "starts_per_hour": {"S4", "S5", "S7"},
    "duration_min": {"S2"},
    "cycle_time_s": {"S1", "S3", "S6", "S9", "S10"},
    "loads": {"S9", "S10"},
}


def duty_keys_used(kind: str) -> dict[str, set[str | None]]:
    """:data:`DUTY_KEYS_USED` with the duty types an application also reads a key for (its
    registry entry's ``duty_uses``)."""
    from advisor.core.registry import application

    uses = dict(DUTY_KEYS_USED)
    for key, forms in (application(kind).duty_uses or {}).items():
        uses[key] = uses.get(key, set()) | set(forms)
    return uses


def ignored(req: Any) -> list[str]:
    """Warnings for options of a valid requirement that the design does not use."""
    out = []
    if (
        "one_way" in req.model_fields_set
        and holds(req.application.kind)
        and not req.application.hold_without_power
    ):
        out.append(
            IGNORED_PREFIX + "the [one_way] table, because application.hold_without_power = "
            "false: no holding device is chosen (set it true to choose one)"
        )
    out += _unused_priority(req)
    duty = getattr(req, "duty", None)
    out += _unused_rated_torques(req, duty)
    if duty is not None and hasattr(duty, "duty_type"):
        form = duty.duty_type
        uses = duty_keys_used(req.application.kind)
        unused = [k for k, used in uses.items() if k in duty.model_fields_set and form not in used]
        if unused:
            what = f"duty_type = {form!r}" if form else "a cycle of segments"
            out.append(
                IGNORED_PREFIX
                + ", ".join(f"duty.{k}" for k in unused)
                + f", because {what} does not use "
                + ("it" if len(unused) == 1 else "them")
            )
    return out


def _unused_priority(req: Any) -> list[str]:
    """``one_way.priority`` with a named ``one_way.type``: the priority ranks the devices only
    for the automatic choice (rule OW-02), so a named type leaves it unused."""
    one_way = getattr(req, "one_way", None)
    if (
        one_way is None
        or "priority" not in one_way.model_fields_set
        or getattr(one_way, "type", "auto") == "auto"
        or not req.application.hold_without_power
    ):
        return []
    return [
        IGNORED_PREFIX + f"one_way.priority, because one_way.type = {one_way.type!r} names "
        "the device: the priority ranks the devices only for type = 'auto'"
    ]


def _unused_rated_torques(req: Any, duty: Any) -> list[str]:
    """A listed motor's rated (S1) torque given without a [duty] (a drive whose candidate
    motors carry one): only the cycle's RMS torque is held against it, so without one it
    checks nothing."""
    if duty is not None:
        return []
    out = []
    for table in sorted(req.model_fields_set):
        motors = getattr(getattr(req, table), "motors", None) or ()
        given = [m.name for m in motors if "rated_torque_Nm" in m.model_fields_set]
        if given:
            out.append(
                IGNORED_PREFIX
                + f"{table}.motors[].rated_torque_Nm ({', '.join(given)}), because no [duty] "
                "is given: only a duty cycle's RMS torque is held against it (add [duty] "
                "cycle_time_s)"
            )
    return out
