"""The report's ``[uncertainty]`` section: the inputs' laws, P(pass) of each check and of the
design with their intervals, each check's drivers (for a tornado chart), and the robust
choice."""

from typing import Any

from advisor.core.report import ReportTable


class InputOut(ReportTable):
    name: str
    distribution: str
    nominal: float
    basis: str
    low: float | None = None
    high: float | None = None
    sd: float | None = None
    mean: float | None = None
    mode: float | None = None


class DriverOut(ReportTable):
    input: str
    rank_correlation: float  # Spearman's ρ of the input with the margin


class CheckProbabilityOut(ReportTable):
    id: str
    name: str
    nominal_margin: float
    modelled: bool  # False: the check does not depend on the sampled inputs in the model
    p_pass: float
    p_pass_low: float
    p_pass_high: float
    margin_p05: float
    margin_p50: float
    drivers: list[DriverOut] = []


class CandidateOut(ReportTable):
    label: str
    p_pass: float
    p_pass_low: float
    p_pass_high: float


class RobustOut(ReportTable):
    target: float
    nominal_choice: str
    nominal_p_pass: float
    chosen: str
    chosen_p_pass: float
    candidates: list[CandidateOut] = []  # those evaluated, in the advisor's order


class UncertaintyOut(ReportTable):
    method: str
    samples: int
    seed: int
    confidence: float
    design: str
    p_pass: float  # every check passes in the same sample
    p_pass_low: float
    p_pass_high: float
    inputs: list[InputOut] = []
    checks: list[CheckProbabilityOut] = []
    not_modelled: list[str] = []
    robust: Any = None  # RobustOut
