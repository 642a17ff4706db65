"""Which motor frames the rotary advice tries: with ``motor.frame = "auto"`` seed
000's scaled series and a catalog's PM brushless motors in order of mass (then diameter);
otherwise the one frame the requirement imposes: ``"reference"`` (the default: the
``[motor.reference]`` frame, seed 000's unless given) or a frame's or a
catalog motor's name. And what the report says of it."""

from typing import Any, NamedTuple

from advisor.core.errors import InputError

#: The name of seed 000's own frame in the series (catalogs/bldc_frames.toml).
SEED_FRAME = "BL074x050"


class Choice(NamedTuple):
    mode: str  # "auto" | "imposed"
    imposed: tuple[Any, Any] | None  # (the frame, its MotorData or None) when imposed
    series: tuple  # the frames tried in order when automatic
    why: str  # how the requirement chose
    tried: tuple = ()
    all_frames: tuple = ()


def _words(frame) -> str:
    if frame.kind == "catalog":
        return f"catalog motor {frame.name}'s datasheet"
    return f"frame {frame.name} (scaled from seed 000's reference by its laws; estimated)"


def frame_data(req, frame):
    """The rotor inertia and time constant of the cycle on ``frame`` (None without a cycle)."""
    if req.duty is None:
        return None
    from advisor.applications.rotary.duty import motor_data

    return motor_data(
        req.duty, frame.rotor_inertia_kgm2, frame.thermal_time_constant_s, _words(frame)
    )


def frame_choice(mot, cat) -> Choice:
    """How the requirement chooses its frame, and the frames to try."""
    ordered = tuple(sorted(cat.bldc_frames, key=lambda f: (f.mass_kg, f.outer_diameter_mm)))
    name = mot.frame.strip()
    if name.lower() == "auto":
        return Choice("auto", None, ordered, "motor.frame = auto", all_frames=ordered)
    if name.lower() == "reference":
        why = (
            "motor.frame = reference"
            if "frame" in mot.model_fields_set
            else "motor.frame left out: the reference frame"
        )
        return Choice("imposed", (mot.reference, "reference"), (), why, all_frames=ordered)
    frame = cat.bldc_frame(name)
    if frame is None:
        known = ", ".join(f.name for f in ordered)
        raise InputError(
            f"motor.frame = {name!r}: not a frame of the series nor a catalog motor; allowed: "
            f"auto, reference, {known}"
        )
    return Choice("imposed", (frame, None), (), f"motor.frame = {frame.name!r}", all_frames=ordered)


def imposed_data(req, choice: Choice, cat):
    """The MotorData of an imposed frame: the requirement's reference takes seed 000's frame's
    estimates unless its [motor.reference] is the user's own (then the duty must give them)."""
    ref, tag = choice.imposed
    if req.duty is None:
        return None
    if tag == "reference":
        from advisor.applications.rotary.duty import motor_data

        own = "reference" in req.motor.model_fields_set
        seed = None if own else cat.bldc_frame(SEED_FRAME)
        return motor_data(
            req.duty,
            None if seed is None else seed.rotor_inertia_kgm2,
            None if seed is None else seed.thermal_time_constant_s,
            "seed 000's reference frame BL074x050 (estimated: rotor inertia and mass "
            "calibrated to the Beckhoff AM3000 series, τ = R_th·C_th)",
        )
    return frame_data(req, ref)


class FrameTried(NamedTuple):
    """A frame of the series (or a catalog motor) as BL-03 weighs it; the fields of the
    report's table of frames tried, in its order."""

    name: str
    kind: str  # "scaled" | "catalog"
    torque_Nm: float  # continuous, at the rated speed
    speed_rpm: float  # rated
    mass_kg: float
    outer_diameter_mm: float
    fits: bool
    why: str  # the best candidate's numbers, or why none passes


def tried_row(frame, fits: bool, why: str) -> FrameTried:
    return FrameTried(
        frame.name,
        frame.kind,
        frame.torque_Nm,
        frame.speed_rpm,
        frame.mass_kg,
        frame.outer_diameter_mm,
        fits,
        why,
    )


def _neighbours(choice: Choice, name: str) -> list[FrameTried]:
    frames = list(choice.all_frames)
    i = next((k for k, f in enumerate(frames) if f.name == name), None)
    if i is None:
        return []
    return [
        tried_row(frames[k], False, "neighbour") for k in (i - 1, i + 1) if 0 <= k < len(frames)
    ]


def frame_out(choice: Choice, ref, data):
    """The report's table of the frame taken."""
    from advisor.applications.rotary.report import FrameOut, FrameTriedOut

    kind = getattr(ref, "kind", "reference")
    if kind == "catalog":
        words = f"datasheet of the catalog motor ({', '.join(ref.source)})"
    elif kind == "scaled":
        words = "scaled frame: seed 000's reference by Budinger's scaling laws"
    else:
        words = "the requirement's [motor.reference] (seed 000's frame unless given)"
    name = getattr(ref, "name", "reference")
    tried = [FrameTriedOut.make(**t._asdict()) for t in choice.tried]
    near = [
        FrameTriedOut.make(**t._asdict())
        for t in _neighbours(choice, name if kind != "reference" else SEED_FRAME)
    ]
    return FrameOut.make(
        name=name,
        kind=kind,
        choice=choice.mode,
        data=f"{words}; {choice.why}",
        torque_Nm=ref.torque_Nm,
        speed_rpm=ref.speed_rpm,
        outer_diameter_mm=getattr(ref, "outer_diameter_mm", None),
        length_mm=getattr(ref, "length_mm", ref.stack_length_mm),
        mass_kg=getattr(ref, "mass_kg", None),
        rotor_inertia_kgm2=getattr(ref, "rotor_inertia_kgm2", None),
        thermal_time_constant_s=getattr(ref, "thermal_time_constant_s", None),
        length_scale=getattr(ref, "length_scale", None),
        law=getattr(ref, "law", "seed 000's model with the requirement's numbers"),
        estimated=list(getattr(ref, "estimated", ())),
        tried=tried,
        neighbours=near,
    )
