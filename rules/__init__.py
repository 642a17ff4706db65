"""Selection heuristics, one module per domain. Each rule decides and explains; none computes
geometry. A rule module registers its rules in :data:`advisor.core.rulebook.REGISTRY` when it
is imported; the package itself imports none of them, so that a path imports only the rules
of its application (a batch run pays for no other). :func:`load_all` imports every module:
the whole rule table."""

from importlib import import_module

#: The rule modules, one per domain.
MODULES = ("bldc", "duty", "induction", "motion", "one_way", "rotor", "screw", "wavegear")


def load_all() -> dict:
    """Import every rule module; the registry of all rules, by id."""
    from advisor.core.rulebook import REGISTRY

    for name in MODULES:
        import_module(f"rules.{name}")
    return REGISTRY
