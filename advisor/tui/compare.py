"""The comparison view: the alternatives a design was chosen from, side by side, the chosen
one marked (▶) with the reason it won, and what "Use this" puts in the requirement so that
the next compute is that alternative. Pure functions of a report (no textual)."""

from typing import Any, NamedTuple

from rich.table import Table

CHOSEN = "▶"


class Option(NamedTuple):
    """An alternative the user can take: the button's words and the requirement values
    that impose it (path → value; None removes the key)."""

    label: str
    patch: tuple[tuple[tuple[str, ...], Any], ...]


class Section(NamedTuple):
    title: str
    table: Any  # a rich renderable
    why: str  # why the chosen one won, in the rules' words
    options: tuple[Option, ...] = ()
    note: str = ""  # what cannot be imposed, and why


def decision(report, id_: str) -> str:
    """The decision of rule ``id_`` in the report, '' if it did not apply."""
    return next((f"{d.id}: {d.decision}" for d in report.decisions if d.id == id_), "")


def table(*columns: str) -> Table:
    t = Table(show_edge=True, pad_edge=False)
    for i, c in enumerate(columns):
        t.add_column(c, justify="left" if i == 0 else "right")
    return t


def mark(chosen: bool, text: str) -> Any:
    """A first cell: the chosen one marked ▶; names from users and catalogs as plain text."""
    from advisor.core.io_safety import plain

    return plain(f"{CHOSEN} {text}" if chosen else f"  {text}")


def one_way(report) -> list[Section]:
    """The one-way device types where the device sits, and the chosen type at the other
    side (seed 004). "Use" imposes the type and, where the application's requirement has
    it (``one_way.location``), the place."""
    ow = getattr(report.design, "one_way", None)
    if ow is None or ow.type == "none":
        return []
    placeable = "location" in report.requirements.get("one_way", {})
    t = table("type", "where", "torque N·m", "Ø × L mm", "mass kg", "power W")
    other = ow.output_side or getattr(ow, "motor_side", None)
    rows = [(ow, True), *((o, False) for o in ([other] if other else []))]
    rows += [(o, False) for o in ow.alternatives]
    options = []
    for o, chosen in rows:
        t.add_row(
            mark(chosen, o.type.replace("_", " ")),
            o.location,
            f"{o.torque_Nm:.4g}",
            f"{o.outer_diameter_mm or 0:.3g} × {o.length_mm or 0:.3g}",
            f"{o.mass_kg or 0:.3g}",
            f"{o.power_W or 0:.3g}",
        )
        if chosen:
            continue
        name = o.type.replace("_", " ")
        if placeable:
            label = f"Use {name} at the {o.location}"
            patch = (
                (("one_way", "type"), o.type),
                (("one_way", "location"), o.location.replace(" ", "_")),
            )
        elif o.type != ow.type:
            label, patch = f"Use {name}", ((("one_way", "type"), o.type),)
        else:
            continue
        if all(x.label != label for x in options):
            options.append(Option(label, patch))
    why = " ".join(x for x in (decision(report, "OW-01"), decision(report, "OW-02")) if x)
    note = (
        "“Use” sets one_way.type and one_way.location."
        if placeable
        else "The place follows the rules (OW-01); the requirement imposes the type only."
        if other
        else ""
    )
    return [Section("One-way device", t, why, tuple(options), note)]
