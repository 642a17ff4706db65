"""Duty cycles: the motor sized for the whole cycle, shared by the applications that
move a load (positioning, linear, rotary). The equations are in :mod:`advisor.calc.duty`, the
rules in :mod:`rules.duty`; this package holds the requirement tables, the report tables and
the orchestration of each application's cycle."""
