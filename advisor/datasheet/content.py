"""What a datasheet says, independent of how it is written (HTML or Markdown): built from
the report's plain data, the same document the TOML archive holds.

Keys keep their meaning and lose their unit suffix to a unit column (``outer_diameter_mm``
→ "outer diameter", mm); numbers are shown to four significant digits (the archive keeps
six); curves are left to the plots.
"""

from dataclasses import dataclass, field
from typing import Any

from advisor.core.report import curve_part, is_curve, margin_text
from advisor.datasheet.labels import UNITS as UNITS  # re-exported
from advisor.datasheet.labels import number as number  # re-exported
from advisor.datasheet.labels import split_key as split_key  # re-exported
from advisor.datasheet.references import readable, references
from advisor.datasheet.review import TIGHT_MARGIN as TIGHT_MARGIN  # re-exported
from advisor.datasheet.review import (
    Bar,
    Cycle,
    Required,
    load_cycle,
    parts,
    project,
    required_vs_achieved,
    status_of,
    utilisation,
)

#: (label, unit) of a requirement field by its path (see
#: :func:`advisor.datasheet.labels.requirement_labels`).
Labels = dict[tuple[str, ...], tuple[str, str]]


@dataclass
class Table:
    title: str
    columns: list[str]
    rows: list[list[str]]


@dataclass
class Block:
    """A component (or part of one): label–value–unit rows, tables of its lists, parts."""

    title: str
    rows: list[tuple[str, str, str]] = field(default_factory=list)
    tables: list[Table] = field(default_factory=list)
    parts: list["Block"] = field(default_factory=list)


@dataclass
class Check:
    id: str
    name: str
    value: str
    limit: str
    unit: str
    margin: str
    status: str  # "fails" | "tight" | "passes"
    source: str


@dataclass
class Decision:
    id: str
    title: str
    decision: str
    rationale: str
    source: str
    inputs: str


@dataclass
class Sheet:
    title: str
    application: str
    status: str
    version: str
    headline: str
    summary: list[tuple[str, str]]
    requirements: list[Block]
    components: list[Block]
    decisions: list[Decision]
    checks: list[Check]
    warnings: list[str]
    references: list[str]
    project: list[tuple[str, str]] = field(default_factory=list)
    required: list[Required] = field(default_factory=list)
    at_default: int = 0  # requirement fields at their defaults, not listed in ``required``
    cycle: Cycle | None = None
    bars: list[Bar] = field(default_factory=list)
    parts: list[list[str]] = field(default_factory=list)
    probability: "Probability | None" = None  # with an [uncertainty] table
    #: What the datasheet says where it has no probability of passing
    no_probability: str = (
        "No [uncertainty] table: every margin above is at the nominal inputs only."
    )


@dataclass
class Probability:
    """The design's probability of passing (the report's ``[uncertainty]``): in words, the
    inputs' laws, each check's P(pass) with its drivers, and the tornado charts to draw."""

    statement: str
    inputs: Table
    checks: Table
    tornadoes: list[Any]  # advisor.uncertainty.drivers.Tornado, the charted checks
    notes: list[str] = field(default_factory=list)


def _law(i: dict) -> str:
    """An input's law in a few words: "normal, σ = 175", "uniform 0.1 … 0.16"."""
    kind = i.get("distribution", "")
    if kind == "normal":
        return f"normal, mean {number(i.get('mean', i['nominal']))}, σ = {number(i['sd'])}"
    if kind == "triangular":
        mode = number(i.get("mode", i["nominal"]))
        return f"triangular {number(i['low'])} … {mode} … {number(i['high'])}"
    if kind == "uniform":
        return f"uniform {number(i['low'])} … {number(i['high'])}"
    return kind


def probability(u: dict | None, labels: Labels) -> Probability | None:
    """The ``[uncertainty]`` section of a report as the datasheet states it (None: none)."""
    if not isinstance(u, dict) or "p_pass" not in u:
        return None
    from advisor.uncertainty.drivers import charted, input_label

    conf = f"{u.get('confidence', 0.95) * 100:g} %"
    statement = (
        f"P(pass) of {u.get('design', 'the design')}: {u['p_pass']:.4f} ({conf} interval "
        f"{u['p_pass_low']:.4f} … {u['p_pass_high']:.4f}), every check in the same sample, over "
        f"{u.get('samples')} samples (seed {u.get('seed')})."
    )
    if u.get("method"):
        statement += f" Method: {u['method']}."
    inputs = Table(
        "Uncertain inputs",
        ["input", "field", "nominal", "law", "basis"],
        [
            [input_label(i["name"], labels), i["name"], number(i["nominal"]), _law(i), i["basis"]]
            for i in u.get("inputs", [])
        ],
    )
    checks = _probability_checks(u, labels, conf)
    return Probability(statement, inputs, checks, charted(u, labels), _probability_notes(u))


def _probability_checks(u: dict, labels: Labels, conf: str) -> Table:
    """Each check's P(pass), its interval, its margin's 5th percentile and its ρ per input."""
    from advisor.uncertainty.drivers import input_label

    names = [i["name"] for i in u.get("inputs", [])]
    rows = []
    for c in u.get("checks", []):
        rho = {d["input"]: d["rank_correlation"] for d in c.get("drivers", [])}
        modelled = c.get("modelled", True)
        rows.append(
            [
                c["name"],
                margin_text(c["nominal_margin"]),
                f"{c['p_pass']:.4f}",
                f"{c['p_pass_low']:.4f} … {c['p_pass_high']:.4f}",
                margin_text(c["margin_p05"]),
                *[f"{rho[n]:+.2f}" if modelled and n in rho else "—" for n in names],
            ]
        )
    return Table(
        "P(pass) and drivers of each check",
        [
            "check",
            "nominal margin",
            "P(pass)",
            f"{conf} interval",
            "margin, 5th percentile",
            *[f"ρ {input_label(n, labels)}" for n in names],
        ],
        rows,
    )


def _probability_notes(u: dict) -> list[str]:
    """What ρ means, what is not modelled and the robust choice, when there is one."""
    notes = [
        "ρ is Spearman's rank correlation of the input with the check's margin: −1, the "
        "margin falls whenever the input rises; 0, the input does not move it; — the model "
        "does not vary the check with the inputs (its nominal verdict)."
    ]
    if u.get("not_modelled"):
        notes.append("Not modelled (nominal verdict only): " + ", ".join(u["not_modelled"]) + ".")
    r = u.get("robust")
    if isinstance(r, dict):
        notes.append(
            f"Robust choice for P(pass) ≥ {r['target']:g}: {r['chosen']} "
            f"(P = {r['chosen_p_pass']:.4f}); the nominal rule would have chosen "
            f"{r['nominal_choice']} (P = {r['nominal_p_pass']:.4f})."
        )
    return notes


def _scalar(v: Any) -> bool:
    return isinstance(v, bool | int | float | str) or (
        isinstance(v, list) and all(isinstance(x, bool | int | float | str) for x in v)
    )


def _columns(items: list[dict]) -> list[tuple[str, tuple[str, ...], str]]:
    """(header, path, unit) of every scalar of a list of tables, one level of sub-tables
    flattened (``losses_W.total`` → "losses total")."""
    cols: list[tuple[str, tuple[str, ...], str]] = []
    seen: set[tuple[str, ...]] = set()
    for item in items:
        for k, v in item.items():
            if _scalar(v) and (k,) not in seen:
                seen.add((k,))
                label, unit = split_key(k)
                cols.append((label, (k,), unit))
            elif isinstance(v, dict) and not is_curve(v):
                head, unit = split_key(k)
                for k2, v2 in v.items():
                    if _scalar(v2) and (k, k2) not in seen:
                        seen.add((k, k2))
                        label2, unit2 = split_key(k2)
                        cols.append((f"{head} {label2}", (k, k2), unit2 or unit))
    return cols


def _cell(item: dict, path: tuple[str, ...]) -> str:
    v: Any = item
    for p in path:
        v = v.get(p) if isinstance(v, dict) else None
    return "" if v is None else number(v)


def table(title: str, items: list[dict]) -> Table:
    cols = _columns(items)
    return Table(
        title,
        [f"{h}, {u}" if u else h for h, _, u in cols],
        [[_cell(it, p) for _, p, _ in cols] for it in items],
    )


def block(
    title: str, data: dict, unit: str = "", labels: Labels | None = None, path: tuple = ()
) -> Block:
    """A table of the report as a block: scalars as rows, sub-tables as parts, lists of
    tables as tables; curves left out (they are plotted). ``unit`` is the unit a parent key
    named for children without their own (``losses_W`` → ``ohmic``)."""
    b = Block(title)
    plotted = curve_part(data)
    for k, v in data.items():
        label, own = (labels or {}).get((*path, k)) or split_key(k, path[-1] if path else None)
        if is_curve(v) or k in plotted:
            continue
        if _scalar(v):
            b.rows.append((label, number(v), own or unit))
        elif isinstance(v, dict):
            b.parts.append(block(f"{title} — {label}", v, own or unit, labels, (*path, k)))
        elif isinstance(v, list) and v and all(isinstance(x, dict) for x in v):
            b.tables.append(table(f"{title} — {label}", v))
    return b


def _words(key: str) -> str:
    return key.replace("_", " ")


_status = status_of


#: How many items of a table (or list) in a decision's inputs are shown before "… N more".
INPUT_ITEMS = 8


def _bounded(items: list[str], brackets: str) -> str:
    """``items`` in ``brackets`` ("()" or "[]"), the first :data:`INPUT_ITEMS` of them and
    how many more; "none" for no item."""
    if not items:
        return "none"
    more = len(items) - INPUT_ITEMS
    shown = items[:INPUT_ITEMS] + ([f"… {more} more"] if more > 0 else [])
    return f"{brackets[0]}{', '.join(shown)}{brackets[1]}"


def input_value(v: Any, nested: bool = False) -> str:
    """A decision's input as its line shows it: a number rounded as the datasheet rounds; a
    table as ``(key = value, …)`` and, within one, a list as ``[…]``; each bounded.

    >>> input_value({"A": 1.20588, "B": 1.15159, "C": 1.02287})
    '(A = 1.206, B = 1.152, C = 1.023)'
    >>> input_value({"stages": 2, "ratios": [40.0, 25.0]}), input_value({})
    ('(stages = 2, ratios = [40, 25])', 'none')
    """
    if isinstance(v, dict):
        return _bounded(
            [f"{k} = {input_value(x, True)}" for k, x in v.items() if x is not None], "()"
        )
    if isinstance(v, list) and (nested or not _scalar(v)):
        return _bounded([input_value(x, True) for x in v], "[]")
    return number(v)


def _inputs(inputs: dict) -> str:
    return "; ".join(f"{k} = {input_value(v)}" for k, v in inputs.items() if v is not None)


def _check(c: dict[str, Any]) -> Check:
    """A check of the report as the datasheet shows it."""
    return Check(
        id=c["id"],
        name=c["name"],
        value=number(c["value"]),
        limit=number(c["limit"]),
        unit=c["unit"],
        margin=margin_text(c["margin"]),
        status=_status(c),
        source=readable(c["source"]),
    )


def _decision(d: dict[str, Any]) -> Decision:
    """A decision of the report as the datasheet shows it."""
    return Decision(
        id=d["id"],
        title=d["title"],
        decision=d["decision"],
        rationale=d["rationale"],
        source=readable(d["source"]),
        inputs=_inputs(d.get("inputs", {})),
    )


def sheet(
    doc: dict[str, Any],
    headline: str,
    summary: list[tuple[str, str]],
    labels: Labels | None = None,
    covers: dict[str, tuple[str, ...]] | None = None,
    defaults: dict[tuple[str, ...], Any] | None = None,
) -> Sheet:
    """The datasheet of a report's plain data (:func:`advisor.core.report.plain`);
    ``labels`` name the requirement fields (from the application's model) and ``covers``
    says which checks cover them (from its registry entry)."""
    labels = labels or {}
    required = required_vs_achieved(doc, labels, covers or {}, defaults)
    head = doc["report"]
    checks = [_check(c) for c in doc.get("checks", [])]
    decisions = [_decision(d) for d in doc.get("decisions", [])]
    lowest = min(doc.get("checks", []), key=lambda c: c["margin"], default=None)
    rows = list(summary)
    if lowest is not None:
        rows.append(("lowest margin", f"{lowest['name']}: {margin_text(lowest['margin'])}"))
    rows.append(("checks", _tally(checks)))
    sources = [d["source"] for d in doc.get("decisions", [])] + [
        c["source"] for c in doc.get("checks", [])
    ]
    return Sheet(
        title=head.get("title") or f"{_words(head['application'])} drive",
        application=head["application"],
        status=head["status"],
        version=head["advisor_version"],
        headline=headline,
        summary=rows,
        requirements=[
            block(_words(k), v, "", labels, (k,))
            for k, v in doc["requirements"].items()
            if isinstance(v, dict) and v and k != "project"  # an empty table heads nothing
        ],
        components=[
            block(_words(k), v, "", None, (k,))
            for k, v in doc["design"].items()
            if isinstance(v, dict)
        ],
        decisions=decisions,
        checks=checks,
        warnings=list(doc.get("warnings", [])),
        references=references(doc, sources),
        project=project(doc, labels),
        required=required[0],
        at_default=required[1],
        cycle=load_cycle(doc),
        bars=utilisation(doc),
        parts=parts(doc),
        probability=probability(doc.get("uncertainty"), labels),
        no_probability=no_probability(doc),
    )


def no_checks(status: str) -> str:
    """What the Utilisation and Checks sections say where the report has no check: an
    infeasible one has no design whose checks could be shown."""
    return nothing_to_show("check", status)


def nothing_to_show(what: str, status: str) -> str:
    """The one line of a section with nothing in it (checks, components, decisions), in
    place of a bare table header or an empty heading: an infeasible report reached no
    design, and says why in its Summary."""
    if status == "infeasible":
        return f"No {what}: no design was reached (see why in the Summary)."
    return f"No {what} applies."


def no_probability(doc: dict[str, Any]) -> str:
    """Why a report has no probability of passing: no ``[uncertainty]`` table asked for one,
    or no design passed, and P(pass) is computed for a design only."""
    if isinstance(doc.get("requirements", {}).get("uncertainty"), dict):
        return (
            "The requirement has an [uncertainty] table, but no design passes the checks: "
            "the probability of passing is computed for a design only."
        )
    return "No [uncertainty] table: every margin above is at the nominal inputs only."


def _tally(checks: list[Check]) -> str:
    n = {s: sum(c.status == s for c in checks) for s in ("passes", "tight", "fails")}
    text = f"{len(checks)} checks: {n['passes'] + n['tight']} pass"
    if n["tight"]:
        text += f" ({n['tight']} with a margin below {TIGHT_MARGIN:g})"
    if n["fails"]:
        text += f", {n['fails']} fail"
    return text
