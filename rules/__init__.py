"""Selection heuristics, one module per domain. Each rule decides and explains; none computes
geometry. Importing this package registers every rule in :data:`advisor.rulebook.REGISTRY`."""

from rules import bldc, induction, screw, wavegear

__all__ = ["bldc", "induction", "screw", "wavegear"]
