"""Where the benchmark scripts write their JSON."""

import json
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def save(name: str, results: dict) -> Path:
    out = ROOT / "benchmarks" / "results"
    out.mkdir(exist_ok=True)
    path = out / f"{name}.json"
    path.write_text(json.dumps(results, indent=2) + "\n")
    return path


def examples() -> list[Path]:
    return sorted((ROOT / "examples").glob("*.toml"))
