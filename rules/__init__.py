"""Selection heuristics, one module per domain. Each rule decides and explains; none computes
geometry. Importing this package registers every rule in :data:`advisor.core.rulebook.REGISTRY`."""

from rules import bldc, duty, induction, motion, one_way, rotor, screw, wavegear

__all__ = ["bldc", "duty", "induction", "motion", "one_way", "rotor", "screw", "wavegear"]
