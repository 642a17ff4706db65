"""The drivers of a check's margin as the data of a tornado chart: one bar per
input, its length and sign Spearman's rank correlation ρ of the input with the margin
(−1 … 1), largest |ρ| first, labelled with the requirement field's own label.

Pure functions of the report's ``[uncertainty]`` section, read alike from its plain data (the
datasheet's) or from the report's tables (the wizard's). A negative ρ is an input whose rise
lowers the margin: friction against the motor's torque margin, force against buckling.
"""

from dataclasses import dataclass
from functools import cache
from typing import Any

#: Charts the datasheet draws at most: the checks that fail in some samples, least probable
#: first; a design with more has the rest in the drivers table.
MAX_CHARTS = 4


@dataclass(frozen=True)
class Bar:
    input: str  # the field's path, "screw.friction_coefficient"
    label: str  # its label, "Thread friction coefficient f"
    rho: float  # Spearman's ρ of the input with the margin


@dataclass(frozen=True)
class Tornado:
    check_id: str
    check_name: str
    p_pass: float
    p_low: float
    p_high: float
    confidence: float
    margin_p05: float
    bars: tuple[Bar, ...]  # largest |ρ| first

    @property
    def probability(self) -> str:
        """P(pass) with its interval, as the chart's title states it.

        >>> Tornado("c", "c", 0.9994, 0.998691, 0.999725, 0.95, 1.1, ()).probability
        'P(pass) = 0.9994 (95 % interval 0.9987 … 0.9997)'
        """
        return (
            f"P(pass) = {self.p_pass:.4f} ({self.confidence * 100:g} % interval "
            f"{self.p_low:.4f} … {self.p_high:.4f})"
        )


def field(x: Any, key: str, default: Any = None) -> Any:
    """``key`` of a report table, a plain dict (the datasheet's) or a table object alike."""
    if isinstance(x, dict):
        return x.get(key, default)
    return getattr(x, key, default)


def input_label(name: str, labels: dict[tuple[str, ...], tuple[str, str]]) -> str:
    """An input's label: its requirement field's (``linear.force_N`` → "Axial force"), else
    its path in words.

    >>> input_label("linear.force_N", {("linear", "force_N"): ("Axial force", "N")})
    'Axial force'
    >>> input_label("screw.thrust.friction_coefficient", {})
    'screw thrust friction coefficient'
    """
    found = labels.get(tuple(name.split(".")))
    return found[0] if found else name.replace(".", " ").replace("_", " ")


def tornado(check: Any, labels: dict, confidence: float = 0.95) -> Tornado | None:
    """The chart of one check; None where the model does not cover it or no input moves its
    margin (every ρ zero: a nut's height ratio, fixed by the thread)."""
    drivers = field(check, "drivers") or []
    if not field(check, "modelled", True) or not any(field(d, "rank_correlation") for d in drivers):
        return None
    bars = sorted(
        (
            Bar(
                field(d, "input"),
                input_label(field(d, "input"), labels),
                field(d, "rank_correlation"),
            )
            for d in drivers
        ),
        key=lambda b: -abs(b.rho),  # stable: the report's order among equals
    )
    return Tornado(
        field(check, "id"),
        field(check, "name"),
        field(check, "p_pass"),
        field(check, "p_pass_low"),
        field(check, "p_pass_high"),
        confidence,
        field(check, "margin_p05"),
        tuple(bars),
    )


def tornadoes(section: Any, labels: dict) -> list[Tornado]:
    """Every check's chart, least probable first (then the lowest 5th-percentile margin:
    among checks that never fail, the one nearest to failing)."""
    confidence = field(section, "confidence", 0.95)
    charts = [t for c in field(section, "checks") or [] if (t := tornado(c, labels, confidence))]
    return sorted(charts, key=lambda t: (t.p_pass, t.margin_p05))


def least_probable(section: Any, labels: dict) -> Tornado | None:
    """The chart of the design's least probable check (None: no check has drivers)."""
    charts = tornadoes(section, labels)
    return charts[0] if charts else None


def charted(section: Any, labels: dict) -> list[Tornado]:
    """The charts a datasheet draws: every check that fails in some samples (up to
    :data:`MAX_CHARTS`), or, where none does, the one nearest to failing."""
    charts = tornadoes(section, labels)
    failing = [t for t in charts if t.p_pass < 1.0][:MAX_CHARTS]
    return failing or charts[:1]


@cache
def labels_of(kind: str) -> dict[tuple[str, ...], tuple[str, str]]:
    """The requirement labels of an application (cached: the wizard asks at every result)."""
    from advisor.core.registry import requirements_model
    from advisor.datasheet.labels import requirement_labels

    return requirement_labels(requirements_model(kind))
