"""Which checks cover each requirement of the rotary actuator: the datasheet's
required-vs-achieved table (registered as ``covers``; :func:`advisor.core.registry.covers`).

Keys are requirement paths or whole tables, values ``fnmatch`` patterns of check ids. A
requirement no check covers is said so on the datasheet: leave it out rather than name a
check that does not test it."""

COVERS: dict[str, tuple[str, ...]] = {
    # the output torque loads the motor (its losses), the stages and their bearings
    "rotary.torque_Nm": ("motor_losses", "duty_peak_torque", "*stage*", "*bearing*"),
    "rotary.speed_rpm": ("motor_losses", "*bearing*"),
    "envelope.max_outer_diameter_mm": ("fits_*", "*envelope*", "*diameter*"),
    "envelope.max_length_mm": ("*envelope*", "*length*"),
    "motor.max_losses_W": ("motor_losses", "duty_losses"),
    "motor.candidate_speeds_rpm": ("motor_losses",),
    "motor.reference": ("motor_losses",),
    "gearbox.stage_efficiency": ("motor_losses",),
    "gearbox.rolling_body": ("bore_*", "fits_*"),
    "gearbox.choice": ("bore_*", "fits_*"),
    "application.hold_without_power": ("*hold*", "one_way*"),
    "one_way": ("one_way*", "*hold*"),
    "duty": ("duty_*",),
    # the stop's torque (through a device at the output) against 186/39 × T_N of the stage
    "rotary.emergency_stop_torque_Nm": ("stage_momentary_peak",),
    # the stages' rolling elements and the output bearing live at least this long
    "design.life_h": ("stage_life", "output_bearing_life"),
    # f_B multiplies the stages' torques (their checks state f_B·T as the value), the life's
    # mean torque and the output bearing's loads
    "design.service_factor": ("stage_*", "output_bearing_static", "output_bearing_life"),
    "output_load": ("output_bearing_*",),
}
