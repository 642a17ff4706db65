"""What the wizard asks, step by step, for each application: a field is a path into the
requirement document, a label, a unit and how its text is read. Pure data and functions;
no textual here, so the tests and the batch path can use it cheaply."""

import math
from typing import Any, NamedTuple

KINDS = {
    "linear": "Linear actuator — induction motor + sliding screw–nut (seed 001)",
    "rotary": "Rotary actuator — PM brushless motor + wave-gear reducer (seed 000)",
    "positioning": "Positioning drive — ratio for the fastest move (seed 003)",
    "spinning_rotor": "High-speed rotor under gyroscopic load (seed 002)",
}

STEPS = ("Application", "Loads and motion", "Envelope and holding", "Motor preferences", "Review")


class Field(NamedTuple):
    path: tuple[str, ...]
    label: str
    unit: str = ""
    kind: str = "float"  # float | int | str | bool | choice | floats
    choices: tuple[str, ...] = ()
    optional: bool = False
    help: str = ""

    @property
    def id(self) -> str:
        return "f-" + "-".join(self.path).replace("_", "-")

    @property
    def dotted(self) -> str:
        return ".".join(self.path)


ONE_WAY = (
    Field(("application", "hold_without_power"), "Hold the load with the motor off", kind="bool"),
    Field(
        ("one_way", "type"),
        "One-way device",
        kind="choice",
        choices=("auto", "roller_clutch", "em_clutch", "worm", "inverse_gear"),
    ),
    Field(
        ("one_way", "priority"),
        "Automatic choice minimises",
        kind="choice",
        choices=("mass", "inertia", "power"),
    ),
)


def _motors() -> tuple[Field, ...]:
    out = []
    for k in range(3):
        out += [
            Field(
                ("positioning", "motors", str(k), "name"),
                f"Motor {k + 1}: name",
                kind="str",
                optional=True,
            ),
            Field(
                ("positioning", "motors", str(k), "speed_rad_s"),
                f"Motor {k + 1}: speed ω0",
                "rad/s",
                optional=True,
            ),
            Field(
                ("positioning", "motors", str(k), "inertia_kgm2"),
                f"Motor {k + 1}: inertia J0",
                "kg·m²",
                optional=True,
            ),
            Field(
                ("positioning", "motors", str(k), "accel_torque_Nm"),
                f"Motor {k + 1}: start/brake torque M_λ",
                "N·m",
                optional=True,
            ),
        ]
    return tuple(out)


FIELDS: dict[str, dict[int, tuple[Field, ...]]] = {
    "linear": {
        1: (
            Field(("linear", "force_N"), "Axial force", "N"),
            Field(("linear", "stroke_m"), "Stroke", "m"),
            Field(("linear", "travel_time_s"), "Time for the stroke", "s"),
            Field(("linear", "support_span_m"), "Unsupported screw length", "m", optional=True),
        ),
        2: (
            *ONE_WAY,
            Field(("screw", "thread"), "Impose a thread (e.g. Tr16x2)", kind="str", optional=True),
            Field(
                ("screw", "starts"),
                "Thread starts (1 … 4; empty: chosen)",
                kind="int",
                optional=True,
            ),
            Field(
                ("screw", "material_pair"),
                "Screw–nut materials",
                kind="choice",
                choices=("steel_bronze", "hardened_steel_bronze", "steel_cast_iron", "steel_steel"),
            ),
        ),
        3: (
            Field(("motor", "supply_frequency_Hz"), "Supply frequency", "Hz"),
            Field(
                ("screw", "friction_model"),
                "Friction formula",
                kind="choice",
                choices=("standard", "paper"),
            ),
            Field(
                ("screw", "friction_coefficient"), "Thread friction coefficient f", optional=True
            ),
        ),
    },
    "rotary": {
        1: (
            Field(("rotary", "torque_Nm"), "Output torque", "N·m"),
            Field(("rotary", "speed_rpm"), "Output speed", "rpm"),
        ),
        2: (
            Field(
                ("envelope", "max_outer_diameter_mm"),
                "Largest reducer diameter",
                "mm",
                optional=True,
            ),
            Field(("envelope", "max_length_mm"), "Largest reducer length", "mm", optional=True),
            *ONE_WAY,
        ),
        3: (
            Field(
                ("motor", "candidate_speeds_rpm"), "Motor speeds to compare", "rpm", kind="floats"
            ),
            Field(
                ("gearbox", "rolling_body"),
                "Rolling bodies",
                kind="choice",
                choices=("ball", "roller"),
            ),
            Field(("gearbox", "stage_efficiency"), "Efficiency of one stage"),
        ),
    },
    "positioning": {
        1: (
            Field(("positioning", "travel_rad"), "Path of the load shaft", "rad"),
            Field(("positioning", "load_inertia_kgm2"), "Load inertia", "kg·m²"),
            Field(("positioning", "load_torque_Nm"), "Load torque", "N·m"),
            Field(
                ("positioning", "profile"),
                "Speed graph",
                kind="choice",
                choices=("trapezoidal", "triangular"),
            ),
        ),
        2: (),
        3: _motors(),
    },
    "spinning_rotor": {
        1: (
            Field(("rotor", "mass_kg"), "Rotor mass", "kg"),
            Field(("rotor", "angular_momentum_kgm2_s"), "Kinetic moment H", "kg·m²/s"),
            Field(("rotor", "speed_rad_s"), "Design speed", "rad/s"),
            Field(("rotor", "run_up_time_s"), "Required run-up time", "s"),
            Field(("rotor", "slew_rate_rad_s"), "Slew rate of the housing Ω", "rad/s"),
            Field(("rotor", "slew_angle_deg"), "Angle of one slew", "deg", optional=True),
            Field(("rotor", "ball_plane_to_cg_mm"), "Ball plane to centre of mass h", "mm"),
        ),
        2: (
            Field(("rotor", "aero", "loss_W"), "Aerodynamic loss at speed", "W", optional=True),
            Field(
                ("rotor", "aero", "outer_radius_mm"), "…or cup outer radius", "mm", optional=True
            ),
            Field(
                ("rotor", "aero", "outer_length_mm"), "…and cup outer length", "mm", optional=True
            ),
        ),
        3: (
            Field(("rotor", "bearing"), "Bearing (SKF designation)", kind="str"),
            Field(("rotor", "bearing_count"), "Bearings", kind="int"),
            Field(("rotor", "rolling_friction_mm"), "Rolling friction λ", "mm", optional=True),
            Field(
                ("rotor", "contact_angle_deg"),
                "Operating contact angle (deep groove)",
                "deg",
                optional=True,
            ),
            Field(("rotor", "required_life_h"), "Required life L10h", "h", optional=True),
        ),
    },
}

DEFAULTS: dict[str, dict[str, Any]] = {
    "linear": {"motor": {"kind": "induction", "supply_frequency_Hz": 50.0}},
    "rotary": {"motor": {"kind": "bldc", "candidate_speeds_rpm": [5000.0, 10000.0]}},
    "positioning": {"positioning": {"profile": "trapezoidal"}},
    "spinning_rotor": {"rotor": {"bearing": "7000 CD", "bearing_count": 2, "aero": {}}},
}


def fields_for(kind: str, step: int) -> tuple[Field, ...]:
    return FIELDS.get(kind, {}).get(step, ())


def all_fields(kind: str) -> list[Field]:
    return [f for step in (1, 2, 3) for f in fields_for(kind, step)]


# ------------------------------------------------------------------ the draft document
def get(doc: dict, path: tuple[str, ...]) -> Any:
    node: Any = doc
    for key in path:
        if isinstance(node, list):
            i = int(key)
            node = node[i] if i < len(node) else None
        elif isinstance(node, dict):
            node = node.get(key)
        else:
            return None
        if node is None:
            return None
    return node


def put(doc: dict, path: tuple[str, ...], value: Any) -> None:
    """Set (or, with None, remove) a value; lists of tables grow as needed."""
    node: Any = doc
    for i, key in enumerate(path[:-1]):
        nxt = path[i + 1]
        if isinstance(node, list):
            k = int(key)
            while len(node) <= k:
                node.append({})
            node = node[k]
            continue
        if key not in node or node[key] is None:
            if value is None:
                return
            node[key] = [] if nxt.isdigit() else {}
        node = node[key]
    last = path[-1]
    if isinstance(node, list):
        k = int(last)
        while len(node) <= k:
            node.append({})
        node[k] = value
    elif value is None:
        node.pop(last, None)
    else:
        node[last] = value


def prune(doc: Any) -> Any:
    """The draft without empty tables and without blank rows of arrays of tables."""
    if isinstance(doc, dict):
        out = {k: prune(v) for k, v in doc.items()}
        return {k: v for k, v in out.items() if v not in ({}, [], None)}
    if isinstance(doc, list):
        items = [prune(v) for v in doc]
        return [v for v in items if v not in ({}, None)]
    return doc


def to_text(field: Field, value: Any) -> str:
    if value is None:
        return ""
    if field.kind == "floats":
        return ", ".join(f"{v:g}" for v in value)
    if isinstance(value, float):
        return f"{value:g}"
    return str(value)


def parse_text(field: Field, text: str) -> tuple[Any, str | None]:
    """The value of a field's text, or None with a message written for the user."""
    text = text.strip()
    if not text:
        return None, None if field.optional else "required"
    if field.kind == "str":
        return text, None
    if field.kind == "int":
        try:
            return int(text), None
        except ValueError:
            return None, f"{text!r} is not a whole number"
    if field.kind == "floats":
        try:
            values = [float(x) for x in text.replace(";", ",").split(",") if x.strip()]
        except ValueError:
            return None, f"{text!r}: numbers separated by commas, e.g. 5000, 10000"
        if not values or not all(math.isfinite(v) for v in values):
            return None, "numbers separated by commas, each finite"
        return values, None
    try:
        value = float(text.replace(",", "."))
    except ValueError:
        return None, f"{text!r} is not a number" + (f" ({field.unit})" if field.unit else "")
    if not math.isfinite(value):
        return None, "must be a finite number"
    return value, None


def error_owner(line: str, kind: str, upto_step: int) -> str | None:
    """Which field (dotted path) an engine message belongs to, '' for the step as a whole,
    None when it concerns a later step only."""
    head = line.split(" ", 1)[0].split(":", 1)[0].split("=", 1)[0]
    head = head.replace("[", ".").replace("]", "")
    # list items are numbered from 1 in messages, from 0 in paths
    parts = head.split(".")
    parts = [str(int(p) - 1) if p.isdigit() else p for p in parts]
    dotted = ".".join(parts)
    seen = [f for s in range(1, upto_step + 1) for f in fields_for(kind, s)]
    later = [f for s in range(upto_step + 1, 4) for f in fields_for(kind, s)]
    for f in seen:
        if f.dotted == dotted:
            return dotted
    if any(f.dotted.startswith(dotted) for f in seen) or not any(
        f.dotted.startswith(dotted) for f in later
    ):
        return ""
    return None
