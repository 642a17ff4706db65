"""Which checks cover each requirement of the linear actuator: the datasheet's
required-vs-achieved table (registered as ``covers``; :func:`advisor.core.registry.covers`).

Keys are requirement paths or whole tables, values ``fnmatch`` patterns of check ids. A
requirement no check covers is said so on the datasheet: leave it out rather than name a
check that does not test it."""

COVERS: dict[str, tuple[str, ...]] = {
    # the axial force loads the screw core, its buckling, the nut flanks and the motor
    "linear.force_N": (
        "core_stress",
        "buckling",
        "nut_pressure",
        "nut_height",
        "nut_turns",
        "thrust_bearing_static",
        "motor_rated_torque",
        "motor_starting_torque",
    ),
    # the stop's momentary force: core, column, nut flanks and thrust bearing checked again
    "linear.emergency_stop_force_N": ("*_emergency_stop", "one_way*"),
    "linear.stroke_m": ("travel_time",),
    "linear.travel_time_s": ("travel_time",),
    "linear.support_span_m": ("buckling*",),
    "linear.end_fixity": ("buckling*",),
    "linear.buckling_safety_factor": ("buckling*",),
    "motor.supply_frequency_Hz": ("travel_time", "motor_*"),
    "screw.friction_coefficient": ("motor_rated_torque", "motor_starting_torque"),
    "screw.friction_model": ("motor_rated_torque", "motor_starting_torque"),
    "screw.starts": ("travel_time",),
    "screw.thread": ("core_stress*", "buckling*", "nut_*"),
    "screw.material_pair": ("nut_pressure", "nut_pressure_emergency_stop"),
    # the thrust face's friction adds to the motor's torque; a bearing's C0 takes the force
    "screw.thrust": ("thrust_bearing_static*", "motor_rated_torque", "motor_starting_torque"),
    "screw.screw_steel": ("core_stress*",),
    "application.hold_without_power": ("*hold*", "*self_locking*", "one_way*"),
    "one_way": ("one_way*", "*hold*"),
    "duty": ("duty_*",),
    # f_B multiplies the load of every strength check: they state f_B·load as their value
    "design.service_factor": (
        "core_stress*",
        "buckling*",
        "nut_pressure*",
        "thrust_bearing_static*",
    ),
}
