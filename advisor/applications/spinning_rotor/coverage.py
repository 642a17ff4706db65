"""Which checks cover each requirement of the spinning rotor: the datasheet's
required-vs-achieved table (registered as ``covers``; :func:`advisor.core.registry.covers`).

Keys are requirement paths or whole tables, values ``fnmatch`` patterns of check ids. A
requirement no check covers is said so on the datasheet: leave it out rather than name a
check that does not test it."""

COVERS: dict[str, tuple[str, ...]] = {
    "rotor.speed_rad_s": ("bearing_speed", "drive_holds_speed"),
    "rotor.bearing": ("bearing_*",),
    "rotor.bearing_count": ("bearing_static",),
    "rotor.mass_kg": ("bearing_static",),
    "rotor.angular_momentum_kgm2_s": ("bearing_static", "drive_holds_speed"),
    "rotor.inertia_kgm2": ("bearing_static", "drive_holds_speed"),
    "rotor.ball_plane_to_cg_mm": ("bearing_static",),
    "rotor.slew_rate_rad_s": ("bearing_static", "drive_holds_speed"),
    "rotor.axis_angle_deg": ("bearing_static", "drive_holds_speed"),
    "rotor.required_life_h": ("bearing_life*",),
    "rotor.aero": ("drive_holds_speed",),
}
