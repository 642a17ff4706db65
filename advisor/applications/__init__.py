"""One package per application (requirements.py, advice.py, report.py, views.py, …), each
named here once by its registry entry: import paths only, so nothing of an application is
imported until a requirement file of its kind is read (the linear batch path stays free of
numpy). Plain data: :mod:`advisor.core.registry` reads :data:`SHIPPED` and registers each
entry as an :class:`advisor.core.registry.Application` (this module imports nothing, so the
registry and the applications do not import each other)."""

#: The shipped applications' registry entries (the fields of ``Application``), in the
#: wizard's order.
SHIPPED = (
    dict(
        kind="linear",
        title="Linear actuator — induction motor + sliding screw–nut (seed 001)",
        requirements="advisor.applications.linear.requirements:LinearRequirements",
        pipeline="advisor.applications.linear.advice:advise_linear",
        headline="advisor.applications.linear.report:headline",
        summary_rows="advisor.applications.linear.report:summary_rows",
        views="advisor.applications.linear.views",
        covers="advisor.applications.linear.coverage:COVERS",
        plots="advisor.applications.linear.plots",
        family="advisor.applications.linear.family",
        uncertainty="advisor.applications.linear.uncertainty",
        steps=("Load and stroke", "Screw and holding", "Motor and friction", "Duty cycle"),
    ),
    dict(
        kind="rotary",
        title="Rotary actuator — PM brushless motor + wave-gear reducer (seed 000)",
        requirements="advisor.applications.rotary.requirements:RotaryRequirements",
        pipeline="advisor.applications.rotary.advice:advise_rotary",
        headline="advisor.applications.rotary.report:headline",
        views="advisor.applications.rotary.views",
        covers="advisor.applications.rotary.coverage:COVERS",
        plots="advisor.applications.rotary.plots",
        family="advisor.applications.rotary.family",
        steps=("Torque and speed", "Envelope and holding", "Motor and reducer", "Duty cycle"),
    ),
    dict(
        kind="positioning",
        title="Positioning drive — ratio for the fastest move (seed 003)",
        requirements="advisor.applications.positioning.requirements:PositioningRequirements",
        pipeline="advisor.applications.positioning.advice:advise_positioning",
        headline="advisor.applications.positioning.report:headline",
        views="advisor.applications.positioning.views",
        covers="advisor.applications.positioning.coverage:COVERS",
        plots="advisor.applications.positioning.plots",
        family="advisor.applications.positioning.family",
        steps=("Move and load", "", "Candidate motors", "Duty cycle"),
    ),
    dict(
        kind="spinning_rotor",
        title="High-speed rotor under gyroscopic load (seed 002)",
        requirements="advisor.applications.spinning_rotor.requirements:SpinningRotorRequirements",
        pipeline="advisor.applications.spinning_rotor.advice:advise_spinning_rotor",
        headline="advisor.applications.spinning_rotor.report:headline",
        views="advisor.applications.spinning_rotor.views",
        covers="advisor.applications.spinning_rotor.coverage:COVERS",
        plots="advisor.applications.spinning_rotor.plots",
        family="advisor.applications.spinning_rotor.family",
        steps=("Rotor and manoeuvre", "Aerodynamic drag", "Bearings", "Duty cycle"),
    ),
)
