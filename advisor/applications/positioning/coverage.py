"""Which checks cover each requirement of the positioning drive: the datasheet's
required-vs-achieved table (registered as ``covers``; :func:`advisor.core.registry.covers`).

Keys are requirement paths or whole tables, values ``fnmatch`` patterns of check ids. A
requirement no check covers is said so on the datasheet: leave it out rather than name a
check that does not test it."""

COVERS: dict[str, tuple[str, ...]] = {
    "positioning.load_torque_Nm": ("ratio_moves_load", "duty_rms_torque"),
    "positioning.motors": ("ratio_moves_load", "duty_rms_torque"),
    "positioning.move_time_s": ("move_time",),
    "positioning.travel_rad": ("duty_move_fits",),
    "positioning.load_inertia_kgm2": ("duty_move_fits", "duty_rms_torque"),
    "duty": ("duty_*",),
}
