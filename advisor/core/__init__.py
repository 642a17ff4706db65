"""The core: engine, rule book, errors, the requirement base and report base, the registry."""
