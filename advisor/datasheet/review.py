"""What a design review reads first: the header from ``[project]``, every requirement beside
what the design achieves and the check that covers it, the load cycle, a utilisation bar per
check and the parts list. Pure functions of the report's plain data (no application is
named here: what differs between applications comes from the registry and the data's shape).
"""

import math
from dataclasses import dataclass
from fnmatch import fnmatchcase
from typing import Any

from advisor.core.report import margin_text
from advisor.datasheet.labels import number, split_key

#: A check whose margin is below this passes, but with little to spare: marked "tight".
TIGHT_MARGIN = 1.1

#: Requirement fields that are no requirement of the design: what it is, its name, the header.
#: The [uncertainty] table's samples, seed and input laws describe the analysis, not the design;
#: its ``target`` is a requirement, met by the design's P(pass) (:func:`_probability_row`).
NOT_REQUIRED = (
    ("application", "kind"),
    ("application", "title"),
    ("project",),
    ("uncertainty", "samples"),
    ("uncertainty", "seed"),
    ("uncertainty", "inputs"),
)

#: The header's fields, in the order a title block lists them.
PROJECT_FIELDS = (
    "name",
    "document_number",
    "revision",
    "date",
    "author",
    "checked_by",
    "approved_by",
)


def status_of(check: dict) -> str:
    """fails | tight | passes, as the checks table marks them."""
    if not check.get("passed", True) or check["margin"] < 1:
        return "fails"
    return "tight" if check["margin"] < TIGHT_MARGIN else "passes"


# ------------------------------------------------------------------------------ header
def project(doc: dict, labels: dict[tuple[str, ...], tuple[str, str]]) -> list[tuple[str, str]]:
    """The header rows: every ``[project]`` field with its label, blank where not given (a
    title block shows the empty boxes a reviewer signs in)."""
    given = doc.get("requirements", {}).get("project") or {}
    return [
        (labels.get(("project", k), (k.replace("_", " "), ""))[0], str(given.get(k, "")))
        for k in PROJECT_FIELDS
    ]


# ------------------------------------------------------------------ required vs achieved
@dataclass
class Required:
    """One requirement field and what the design achieves against it."""

    path: str  # linear.force_N
    label: str
    value: str
    unit: str
    check: str  # the governing check's name, or why there is none
    check_id: str
    achieved: str  # "value against limit unit" of the governing check
    margin: str
    status: str  # fails | tight | passes | none | unreached (no design reached its checks)
    more: int  # other checks that cover it too


def _patterns(path: tuple[str, ...], covers: dict[str, tuple[str, ...]]) -> list[str]:
    """The check-id patterns the application names for a field or a table holding it."""
    return [p for k in range(len(path), 0, -1) for p in covers.get(".".join(path[:k]), ())]


def covering(
    path: tuple[str, ...], covers: dict[str, tuple[str, ...]], ids: list[str]
) -> list[str]:
    """The ids of the checks that cover a requirement field: those the application names for
    the field or for a table holding it (``duty`` covers ``duty.cycle_time_s``), and a check
    named as the field is (``travel_time`` covers ``linear.travel_time_s``)."""
    patterns = _patterns(path, covers)
    stem = split_key(path[-1])[0].replace(" ", "_")
    found = [i for i in ids if any(fnmatchcase(i, p) for p in patterns) or i == stem]
    return found


def _leaves(node: Any, prefix: tuple[str, ...]) -> list[tuple[tuple[str, ...], Any]]:
    out: list[tuple[tuple[str, ...], Any]] = []
    for k, v in node.items():
        path = (*prefix, k)
        if any(path[: len(n)] == n for n in NOT_REQUIRED):
            continue
        if isinstance(v, dict):
            out += _leaves(v, path)
        else:
            out.append((path, v))
    return out


def _value(v: Any) -> str:
    if isinstance(v, list) and v and all(isinstance(x, dict) for x in v):
        return f"{len(v)} rows (see Requirements)"
    if isinstance(v, list) and not v:
        return "none"
    return number(v)


#: What the "covered by" column says where no check covers a requirement, and where the
#: checks that would cover it were never reached because no design exists.
UNCOVERED = "no check covers this requirement"
NOT_REACHED = "not reached: the requirement is infeasible (see why)"


def _covered_row(
    path: tuple[str, ...], label: str, v: Any, unit: str, covering_checks: list
) -> Required:
    """The row of a requirement covered by ``covering_checks``: the least margin governs."""
    c = min(covering_checks, key=lambda c: c["margin"])
    achieved = f"{number(c['value'])} against {number(c['limit'])} {c['unit']}".strip()
    return Required(
        ".".join(path),
        label,
        _value(v),
        unit,
        c["name"],
        c["id"],
        achieved,
        margin_text(c["margin"]),
        status_of(c),
        len(covering_checks) - 1,
    )


def _uncovered_row(path: tuple[str, ...], label: str, v: Any, unit: str, reached: bool) -> Required:
    """The row of a requirement no check in the report covers: none covers it (``reached``:
    the report has a design), or its checks were not reached (no design)."""
    text, status = (UNCOVERED, "none") if reached else (NOT_REACHED, "unreached")
    return Required(".".join(path), label, _value(v), unit, text, "", "", "", status, 0)


def required_vs_achieved(
    doc: dict,
    labels: dict[tuple[str, ...], tuple[str, str]],
    covers: dict[str, tuple[str, ...]],
    defaults: dict[tuple[str, ...], Any] | None = None,
) -> tuple[list[Required], int]:
    """One row per requirement field the design was made to, in the file's order: the value
    required, and the check that covers it with the least margin (the governing one). A
    field at its model's default (``defaults``) is counted, not listed: the Requirements
    section lists it. An infeasible report's rows name the failing checks it holds; a
    field the application covers by checks that no design reached says so. Returns the rows
    and that count."""
    checks = {c["id"]: c for c in doc.get("checks", [])}
    infeasible = (doc.get("report") or {}).get("status") == "infeasible"
    rows = []
    at_default = 0
    for path, v in _leaves(doc.get("requirements", {}), ()):
        if defaults and path in defaults and _same(defaults[path], v):
            at_default += 1
            continue
        label, unit = labels.get(path) or split_key(path[-1])
        ids = covering(path, covers, list(checks))
        if path == ("uncertainty", "target") and (row := _probability_row(doc, label, v)):
            rows.append(row)
        elif ids:
            rows.append(_covered_row(path, label, v, unit, [checks[i] for i in ids]))
        else:
            reached = not (infeasible and not checks and _patterns(path, covers))
            rows.append(_uncovered_row(path, label, v, unit, reached))
    return rows, at_default


def _probability_row(doc: dict, label: str, target: Any) -> Required | None:
    """The target P(pass) against the design's: the robust choice takes a design whose
    interval's lower end reaches the target, so that end is what is achieved (None: the
    report has no probability of passing, e.g. no design passed)."""
    u = doc.get("uncertainty")
    if not isinstance(u, dict) or "p_pass_low" not in u or not isinstance(target, int | float):
        return None
    low = u["p_pass_low"]
    margin = low / target
    # a probability's margin cannot exceed 1/target: "tight" would say nothing here
    status = "fails" if margin < 1.0 else "passes"
    conf = f"{u.get('confidence', 0.95) * 100:g} %"
    return Required(
        "uncertainty.target",
        label,
        number(target),
        "",
        f"P(pass) of the design, the lower end of its {conf} interval",
        "",
        f"{number(low)} against {number(target)}",
        margin_text(margin),
        status,
        0,
    )


def _same(default: Any, value: Any) -> bool:
    """A report value equal to a model default (a list default compares as a list)."""
    if isinstance(default, tuple):
        default = list(default)
    return (default == value and type(default) is type(value)) or (
        isinstance(default, int | float)
        and isinstance(value, int | float)
        and not isinstance(value, bool)
        and not isinstance(default, bool)
        and float(default) == float(value)
    )


# ------------------------------------------------------------------------- utilisation
@dataclass
class Bar:
    """A check as demand over capacity: 1/margin (the margin is capacity over demand)."""

    id: str
    name: str
    utilisation: float
    status: str


def utilisation(doc: dict) -> list[Bar]:
    return [
        Bar(c["id"], c["name"], 1.0 / c["margin"] if c["margin"] > 0 else math.inf, status_of(c))
        for c in doc.get("checks", [])
    ]


# --------------------------------------------------------------------------- load cycle
@dataclass
class Cycle:
    columns: list[str]
    rows: list[list[str]]
    note: str


def phases_of(doc: dict) -> list[dict] | None:
    """The phases of the design's load cycle: the first list of tables in a design table
    whose rows each have a time (``time_s`` or ``duration_s``) and a ``torque_Nm``."""
    for part in (doc.get("design") or {}).values():
        if not isinstance(part, dict):
            continue
        for v in part.values():
            if (
                isinstance(v, list)
                and v
                and all(
                    isinstance(x, dict)
                    and ("time_s" in x or "duration_s" in x)
                    and "torque_Nm" in x
                    for x in v
                )
            ):
                return v
    return None


def speed_rpm(phase: dict) -> float | None:
    if "speed_rpm" in phase:
        return phase["speed_rpm"]
    if "speed_rad_s" in phase:
        return phase["speed_rad_s"] * 30.0 / math.pi
    return None


def load_cycle(doc: dict) -> Cycle | None:
    """The phases as a table: name, time, speed, torque and the shaft power P = M·ω at the
    phase's speed (the report states a ramp's top speed)."""
    phases = phases_of(doc)
    if phases is None:
        return None
    rows = []
    for i, p in enumerate(phases, 1):
        n = speed_rpm(p)
        power = p["torque_Nm"] * n * math.pi / 30.0 if n is not None else None
        rows.append(
            [
                str(p.get("name", i)),
                number(p.get("time_s", p.get("duration_s"))),
                "" if n is None else number(n),
                number(p["torque_Nm"]),
                "" if power is None else number(power),
            ]
        )
    return Cycle(
        ["phase", "time, s", "speed, rpm", "torque, N·m", "power, W"],
        rows,
        "At the motor shaft. Power is torque × the phase's speed (a ramp's top speed: the "
        "phase's peak power); a negative power is the load driving the motor.",
    )


# ------------------------------------------------------------------------------- parts
DESIGNATION = ("model", "designation", "thread", "name")
RATING = (
    "rated_power_kW",
    "rated_torque_Nm",
    "rated_speed_rpm",
    "total_ratio",
    "torque_Nm",
    "speed_rpm",
    "C_kN",
    "C0_kN",
    "limiting_speed_rpm",
    "efficiency",
)
DIMENSIONS = (
    "nominal_diameter_mm",
    "lead_mm",
    "outer_diameter_mm",
    "inner_diameter_mm",
    "length_mm",
    "height_mm",
    "d_mm",
    "D_mm",
    "B_mm",
)


def _pairs(table: dict, keys: tuple[str, ...], limit: int = 3) -> str:
    out = []
    for k in keys:
        v = table.get(k)
        if isinstance(v, int | float) and not isinstance(v, bool):
            label, unit = split_key(k)
            out.append(f"{label} {number(v)} {unit}".strip())
    return "; ".join(out[:limit])


def _designation(table: dict) -> str:
    for k in DESIGNATION:
        if isinstance(table.get(k), str) and table[k]:
            return table[k]
    kind = table.get("kind") or table.get("type")
    return str(kind).replace("_", " ") if isinstance(kind, str) else ""


def _source(table: dict) -> str:
    s = table.get("source")
    if isinstance(s, list):
        s = "; ".join(str(x) for x in s)
    if s:
        return str(s)
    return "sized by the advisor (no catalog row)"


def _is_part(table: dict, top: bool) -> bool:
    """A component: a design table with a designation, a kind or a mass; within one, a
    table with a designation of its own (a bearing, a nut with a thread)."""
    named = any(isinstance(table.get(k), str) for k in DESIGNATION[:3])
    if not top:
        return named
    mass = table.get("mass_kg")
    kind = any(isinstance(table.get(k), str) for k in ("kind", "type"))
    return named or kind or (isinstance(mass, int | float) and not isinstance(mass, bool))


def parts(doc: dict) -> list[list[str]]:
    """One row per component a buyer orders or a shop makes: the design's tables (and their
    sub-tables) that have a designation or a mass; a part chosen from the requirement's own
    list (a candidate motor named by the design) comes with its row there."""
    rows: list[list[str]] = []

    def visit(name: str, table: dict, depth: int) -> None:
        if _is_part(table, depth == 0):
            mass = table.get("mass_kg")
            rows.append(
                [
                    name,
                    _designation(table),
                    _pairs(table, RATING),
                    _pairs(table, DIMENSIONS),
                    "" if mass is None else f"{number(mass)} kg",
                    _source(table),
                ]
            )
        if depth < 1:
            for k, v in table.items():
                if isinstance(v, dict) and _is_part(v, False):
                    visit(f"{name} — {split_key(k)[0]}", v, depth + 1)

    design = doc.get("design") or {}
    listed: set[str] = set()
    for k, v in design.items():
        if isinstance(v, dict):
            visit(split_key(k)[0], v, 0)
            chosen = v.get("motor")
            if isinstance(chosen, str) and chosen not in listed:
                row = _listed(doc.get("requirements", {}), chosen)
                if row is not None:
                    listed.add(chosen)
                    rows.append(
                        [
                            "motor",
                            chosen,
                            _pairs(row, ("rated_torque_Nm", "accel_torque_Nm", "speed_rad_s")),
                            "",
                            "",
                            "the requirement's list of motors",
                        ]
                    )
    return rows


def _listed(req: dict, name: str) -> dict | None:
    """The row of a requirement's list of tables named ``name``, if any."""
    for table in req.values():
        if not isinstance(table, dict):
            continue
        for v in table.values():
            if isinstance(v, list):
                for row in v:
                    if isinstance(row, dict) and row.get("name") == name:
                        return row
    return None
