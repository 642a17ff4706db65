"""Human labels and units for the keys a datasheet shows.

A requirement field is labelled from its pydantic model, where it is declared once
(``x-label`` or its description, and ``x-unit`` or the unit its key's suffix names: see
:mod:`advisor.core.questions`). A report key is labelled from :data:`REPORT_LABELS` where its
name is a symbol of a standard or a seed (``d2_mm``, ``p15_50_W_kg``, ``C0_kN``), otherwise
from its words and the unit its suffix names (``outer_diameter_mm`` → "outer diameter", mm).
"""

import math
import re
from typing import Any

from advisor.core.questions import UNIT_SUFFIXES
from advisor.core.report import ends_in_tie

#: Units named by the suffixes of report keys: the requirement suffixes and the report's own.
UNITS = {
    **UNIT_SUFFIXES,
    "kW": "kW",
    "kN": "kN",
    "J": "J",
    "K": "K",
    "K_W": "K/W",
    "pct": "%",
    "cm3": "cm³",
    "MPa": "MPa",
    "MPa_m_s": "MPa·m/s",
    "m_s": "m/s",
    "uF": "µF",
    "W_kg": "W/kg",
    "cm3_per_Nm": "cm³/(N·m)",
    "per_hour": "1/h",
    "Mrev": "10⁶ rev",
}

#: Report keys whose name is a symbol: what it means and its unit (GOST 24737-81 for the
#: trapezoidal thread, ISO 281 for the bearing, GOST 21427.2-83 for the electrical steel).
REPORT_LABELS: dict[str, tuple[str, str]] = {
    "p15_50_W_kg": ("specific loss at 1.5 T, 50 Hz", "W/kg"),
    "p10_50_W_kg": ("specific loss at 1.0 T, 50 Hz", "W/kg"),
    "pv_MPa_m_s": ("p·v", "MPa·m/s"),
    "d2_mm": ("pitch diameter of the screw d2", "mm"),
    "d3_mm": ("minor diameter of the screw d3", "mm"),
    "D1_mm": ("minor diameter of the nut D1", "mm"),
    "D2_mm": ("pitch diameter of the nut D2", "mm"),
    "D4_mm": ("major diameter of the nut D4", "mm"),
    "ac_mm": ("crest clearance ac", "mm"),
    "H1_mm": ("thread overlap H1", "mm"),
    "h3_mm": ("thread depth of the screw h3", "mm"),
    "d_mm": ("bore d", "mm"),
    "D_mm": ("outside diameter D", "mm"),
    "B_mm": ("width B", "mm"),
    "C_kN": ("basic dynamic load rating C", "kN"),
    "C0_kN": ("basic static load rating C0", "kN"),
    "factor_X": ("radial load factor X", ""),
    "factor_Y": ("axial load factor Y", ""),
    "life_speed_rpm": ("mean speed the life is counted at", "rpm"),
    "cos_phi": ("power factor cos φ", ""),
    "efficiency_pct": ("efficiency", "%"),
    "kloss_epsilon": ("Kloss formula ε", ""),
    "k_factor": ("factor k (seed 003)", ""),
    "coefficient_A": ("coefficient A (seed 003)", ""),
    "ratio_i0": ("ratio i0 (seed 003)", ""),
    "skf_friction_Nm": ("friction torque, SKF model", "N·m"),
    "resistance_K_W": ("thermal resistance", "K/W"),
    "cycles_per_hour": ("cycles per hour", "1/h"),
    "starts_per_hour": ("starts per hour", "1/h"),
    "allowed_starts_per_hour": ("starts per hour allowed", "1/h"),
    "no_load_starts_per_hour": ("no-load starts per hour allowed", "1/h"),
}


#: Report keys whose meaning depends on the table that holds them, keyed by (table, key):
#: positioning's motion states seed 003's I = J_p/J0 (the load over the motor, the reducer
#: left out), a duty cycle the load reflected to the motor over the motor (the report keys
#: stay the same: they are a stable interface).
REPORT_TABLE_LABELS: dict[tuple[str, str], tuple[str, str]] = {
    ("motion", "inertia_ratio"): ("load/motor inertia I = J_p/J0 (seed 003, no reducer)", ""),
    ("duty", "inertia_ratio"): ("load/motor inertia at the motor J_L/(i²·J_m)", ""),
}


def split_key(key: str, table: str | None = None) -> tuple[str, str]:
    """A report key as a label and a unit: the table's own from :data:`REPORT_TABLE_LABELS`,
    a symbol from :data:`REPORT_LABELS`, else its words with the longest unit suffix as the
    unit.

    >>> split_key("outer_diameter_mm"), split_key("p15_50_W_kg"), split_key("rows")
    (('outer diameter', 'mm'), ('specific loss at 1.5 T, 50 Hz', 'W/kg'), ('rows', ''))
    """
    if (table, key) in REPORT_TABLE_LABELS:
        return REPORT_TABLE_LABELS[(table, key)]
    if key in REPORT_LABELS:
        return REPORT_LABELS[key]
    parts = key.split("_")
    for k in (3, 2, 1):
        suffix = "_".join(parts[-k:])
        if len(parts) > k and suffix in UNITS:
            return " ".join(parts[:-k]), UNITS[suffix]
    return key.replace("_", " "), ""


#: A description's tail that is its range or its unit: ", 1 … 50 pole pairs", ", N".
_UNIT_TAIL = re.compile(r",\s*(?:[^,;]*[\d…][^,;]*|[^,;\s]{1,6})$")


def short_description(desc: str) -> str:
    """A field's description as a label: the words before its range and unit.

    >>> short_description("rated axial force, N; 1 N … 5 MN")
    'rated axial force'
    >>> short_description("electrical reduction p, 1 … 50 pole pairs")
    'electrical reduction p'
    """
    head = desc.split(";", 1)[0].strip()
    return _UNIT_TAIL.sub("", head)


def requirement_labels(model: Any) -> dict[tuple[str, ...], tuple[str, str]]:
    """(label, unit) of every leaf field of a requirement model by its path; a list of
    tables is keyed by its own path and its items' fields by ``(…, "name[]", field)``."""
    from advisor.core.questions import field_extra, is_model, strip_optional, unit_of

    out: dict[tuple[str, ...], tuple[str, str]] = {}

    def walk(m: Any, prefix: tuple[str, ...]) -> None:
        for name, info in m.model_fields.items():
            ann = strip_optional(info.annotation)
            path = (*prefix, name)
            extra = field_extra(info)
            label = extra.get("x-label") or short_description(info.description or "") or name
            # a unit the parser does not take (µF) is named by the report's suffixes
            unit = extra.get("x-unit") or unit_of(name) or split_key(name)[1]
            args = getattr(ann, "__args__", ())
            if is_model(ann):
                walk(ann, path)
            elif args and is_model(args[0]):  # a list of tables
                out[path] = (extra.get("x-row-label") or label, "")
                walk(args[0], (*prefix, f"{name}[]"))
            else:
                out[path] = (label, unit)

    walk(model, ())
    return out


def _plain(v: Any) -> Any:
    """A default as the report writes it: a model's instance (a row of a list of tables) as
    its table, None fields left out as the report leaves them out."""
    if hasattr(v, "model_dump"):
        return v.model_dump(exclude_none=True)
    if isinstance(v, list | tuple):
        return type(v)(_plain(x) for x in v)
    return v


def requirement_defaults(model: Any) -> dict[tuple[str, ...], Any]:
    """The default of every leaf field of a requirement model that has one, by its path: a
    value equal to it is one the file could have left out (a field with one allowed value,
    the motor's ``kind`` of an application, counts as at its default)."""
    from typing import Literal, get_args, get_origin

    from advisor.core.questions import is_model, strip_optional

    out: dict[tuple[str, ...], Any] = {}

    def walk(m: Any, prefix: tuple[str, ...]) -> None:
        for name, info in m.model_fields.items():
            ann = strip_optional(info.annotation)
            if is_model(ann):
                walk(ann, (*prefix, name))
            elif get_origin(ann) is Literal and len(get_args(ann)) == 1:
                out[(*prefix, name)] = get_args(ann)[0]
            elif not info.is_required():
                out[(*prefix, name)] = _plain(info.get_default(call_default_factory=True))

    walk(model, ())
    return out


# ------------------------------------------------------------------ compiled for the batch
#: Where :func:`write_compiled` puts the labels and defaults of the shipped applications.
COMPILED_FILE = "compiled_labels.py"


def literal_default(v: Any) -> bool:
    """A default written as a Python literal: a number, a string, None, and lists and tables
    of them (a model's instance is one after :func:`requirement_defaults` made it plain)."""
    if v is None or type(v) in (str, int, float, bool):
        return True
    if isinstance(v, dict):
        return all(type(k) is str and literal_default(x) for k, x in v.items())
    return isinstance(v, list | tuple) and all(literal_default(x) for x in v)


def compiled_text() -> str:
    """The source of :mod:`advisor.datasheet.compiled_labels`: :func:`requirement_labels`
    and :func:`requirement_defaults` of each shipped application's model, as data."""
    from advisor.core.registry import requirements_model
    from advisor.core.requirement_spec import ROOTS

    labels, defaults = {}, {}
    for kind in ROOTS:
        model = requirements_model(kind)
        labels[kind] = requirement_labels(model)
        defaults[kind] = {
            k: v for k, v in requirement_defaults(model).items() if literal_default(v)
        }
    return (
        '"""The datasheet\'s labels and defaults of the requirement fields of the shipped\n'
        "applications, read from their models by ``python -m advisor.datasheet.labels`` (so\n"
        'that a datasheet imports no pydantic). Do not edit: change the models and regenerate."""\n'
        "\n# fmt: off\n# ruff: noqa: E501\n"
        f"LABELS = {labels!r}\n"
        f"DEFAULTS = {defaults!r}\n"
    )


def for_application(kind: str) -> tuple[dict, dict]:
    """(labels, defaults) of the requirement fields of ``kind``: compiled for a shipped
    application (no pydantic), from its model for any other."""
    from advisor.core.compiled_validator import compiled

    if compiled(kind):
        from advisor.datasheet.compiled_labels import DEFAULTS, LABELS

        return LABELS[kind], DEFAULTS[kind]
    from advisor.core.registry import requirements_model

    model = requirements_model(kind)
    return requirement_labels(model), requirement_defaults(model)


def write_compiled() -> None:
    from pathlib import Path

    (Path(__file__).parent / COMPILED_FILE).write_text(compiled_text(), encoding="utf-8")


if __name__ == "__main__":
    write_compiled()


def number(x: Any) -> str:
    """A value as a reader wants it: four significant digits, no exponent between 0.001 and
    a million, yes/no for booleans.

    >>> number(5.08485), number(21120.4), number(442937), number(1.5e-05), number(True)
    ('5.085', '21120', '442937', '1.5e-05', 'yes')

    A value the report rounded to a tie at the shown digit (10282.5 of 10282.524) keeps the
    digit: rounding it again would say 10282 (half to even) where the value is 10283.

    >>> number(10282.5), number(5.1525), number(2.5)
    ('10282.5', '5.1525', '2.5')
    """
    if isinstance(x, bool):
        return "yes" if x else "no"
    if isinstance(x, int):
        return str(x)
    if isinstance(x, float):
        if x == 0 or not math.isfinite(x):
            return f"{x:g}"
        if 1e-3 <= abs(x) < 1e6:
            decimals = max(0, 3 - math.floor(math.log10(abs(x))))
            if ends_in_tie(x, decimals):  # the report's own rounding made it one: say it unrounded
                decimals += 1
            text = f"{x:.{decimals}f}"
            return text.rstrip("0").rstrip(".") if "." in text else text
        return f"{x:.4g}"
    if isinstance(x, list):
        return ", ".join(number(v) for v in x)
    return str(x)
