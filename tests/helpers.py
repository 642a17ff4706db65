"""Shared test data."""

from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples"


def seed001_requirement(**screw_overrides) -> dict:
    """Seed 001, table 1: t = 5 s, l = 0.2 m, F = 3500 N, L = 0.4 m."""
    screw = {"friction_coefficient": 0.15, "starts": 1, **screw_overrides}
    return {
        "application": {"kind": "linear", "hold_without_power": False},
        "linear": {"force_N": 3500, "stroke_m": 0.2, "travel_time_s": 5, "support_span_m": 0.4},
        "motor": {"kind": "induction", "supply_frequency_Hz": 50},
        "screw": screw,
    }
