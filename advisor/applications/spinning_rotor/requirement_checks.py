"""The spinning rotor's requirement rules and derived values, free of pydantic: used by the
requirement models (:mod:`advisor.applications.spinning_rotor.requirements`) and by the
compiled validator of the batch path (:mod:`advisor.core.compiled_validator`). Each check raises
ValueError with the message the user reads."""

from typing import Any

#: The slowest slew taken as one (Earth's rate is 7.3e-5 rad/s); below it give 0, no slew.
MIN_SLEW_RATE_rad_s = 1e-6


def aero_one_way(aero: Any) -> None:
    geometry = aero.outer_radius_mm is not None or aero.outer_length_mm is not None
    if aero.loss_W is not None and geometry:
        raise ValueError(
            "rotor.aero: give either loss_W or the cup geometry (outer_radius_mm, "
            "outer_length_mm), not both"
        )
    if aero.loss_W is None and (aero.outer_radius_mm is None or aero.outer_length_mm is None):
        raise ValueError(
            "rotor.aero: give loss_W (W at the design speed) or both outer_radius_mm and "
            "outer_length_mm"
        )
    if aero.outer_radius_mm is not None and aero.inner_radius_mm >= aero.outer_radius_mm:
        raise ValueError(
            f"rotor.aero.inner_radius_mm = {aero.inner_radius_mm:g} must be below "
            f"outer_radius_mm = {aero.outer_radius_mm:g}"
        )


def slew_or_none(v: float) -> float:
    if 0.0 < v < MIN_SLEW_RATE_rad_s:
        raise ValueError(
            f"must be 0 (no slew) or at least {MIN_SLEW_RATE_rad_s:g} (Earth's rate is 7.3e-05)"
        )
    return v


def momentum_or_inertia(rotor: Any) -> None:
    if (rotor.angular_momentum_kgm2_s is None) == (rotor.inertia_kgm2 is None):
        raise ValueError(
            "rotor: give exactly one of angular_momentum_kgm2_s (H at speed) and "
            "inertia_kgm2 (J); H = J·ω"
        )


class RotorDerived:
    """What the rotor table gives besides its keys: J and H, whichever was given."""

    __slots__ = ()

    @property
    def inertia(self) -> float:
        if self.inertia_kgm2 is not None:
            return self.inertia_kgm2
        return self.angular_momentum_kgm2_s / self.speed_rad_s

    @property
    def angular_momentum(self) -> float:
        return self.inertia * self.speed_rad_s
