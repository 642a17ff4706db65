"""Load and validate the catalogs; a bad entry is refused with file, row and field named."""

import itertools
import marshal
import math
import os
import re
import sys
import zlib
from functools import cache
from pathlib import Path
from typing import Any, NamedTuple

from advisor.core.cite import Cite
from advisor.core.errors import CatalogError
from catalogs.rows import (
    Bearing,
    BldcFrame,
    ElectricalSteel,
    FrictionConstants,
    FrictionPair,
    InductionMotor,
    MagnetPoint,
    Materials,
    ScrewSteel,
)
from catalogs.threads import ThreadProfile, trapezoidal_profile

HERE = Path(__file__).parent

THREADS_FILE = "gost_24738_81_trapezoidal.toml"
POWERS_FILE = "gost_12139_84_powers.toml"
MOTORS_FILE = "induction_4a.toml"
MATERIALS_FILE = "screw_materials.toml"
STEELS_FILE = "electrical_steels.toml"
BEARINGS_FILE = "skf_bearings.toml"
BIBLIOGRAPHY_FILE = "bibliography.toml"
FRAMES_FILE = "bldc_frames.toml"
BLDC_MOTORS_FILE = "bldc_motors.toml"  # a user catalog's PM brushless motors (none shipped)

#: A catalog's [sources] entry, resolved: (bibliography id, what the file takes from it).
SourceMap = dict[str, tuple[str, str]]


# ---------------------------------------------------------------- the bundle
class Catalogs(NamedTuple):
    threads: tuple[ThreadProfile, ...]
    threads_source: str
    rated_powers_kW: tuple[float, ...]
    powers_source: str
    motors: tuple[InductionMotor, ...]
    motor_sources: SourceMap
    materials: Materials
    electrical_steels: tuple[ElectricalSteel, ...]
    steel_sources: SourceMap
    bearings: tuple[Bearing, ...] = ()
    bearing_friction: dict[str, FrictionConstants] = {}  # noqa: RUF012 - NamedTuple default
    bearing_sources: SourceMap = {}  # noqa: RUF012
    #: catalogs/bibliography.toml (plus a user directory's): id → entry (fields as written)
    bibliography: dict[str, dict[str, Any]] = {}  # noqa: RUF012
    #: PM brushless motors the rotary advice chooses from: seed 000's scaled frames (the
    #: reference among them) and a user directory's bldc_motors.toml
    bldc_frames: tuple[BldcFrame, ...] = ()
    bldc_sources: SourceMap = {}  # noqa: RUF012

    def bldc_frame(self, name: str) -> BldcFrame | None:
        key = name.strip().lower()
        return next((f for f in self.bldc_frames if f.name.lower() == key), None)

    def cite_rows(self, sources: SourceMap, keys: "str | list[str] | tuple[str, ...]") -> Cite:
        """The citation of a catalog row whose ``source`` names ``keys`` of ``sources``."""
        keys = [keys] if isinstance(keys, str) else keys
        return Cite(tuple((sources[k][0], sources[k][1]) for k in keys))

    def short_names(self) -> dict[str, str]:
        return {i: e["short"] for i, e in self.bibliography.items()}

    def bearing(self, designation: str) -> Bearing | None:
        key = " ".join(designation.split()).upper()
        return next((b for b in self.bearings if b.designation.upper() == key), None)

    def thread(self, name: str) -> ThreadProfile | None:
        key = name.replace(" ", "").replace("×", "x").lower()
        for t in self.threads:
            if t.name.lower() == key:
                return t
        return None

    def pair(self, name: str) -> FrictionPair:
        return next(p for p in self.materials.pair if p.name == name)

    def steel(self, name: str) -> ScrewSteel:
        return next(s for s in self.materials.steel if s.name == name)

    def electrical_steel(self, grade: str, thickness_mm: float) -> ElectricalSteel | None:
        for s in self.electrical_steels:
            if s.grade == grade and math.isclose(s.thickness_mm, thickness_mm):
                return s
        return None

    def motors_with_poles(self, poles: int) -> list[InductionMotor]:
        return sorted((m for m in self.motors if m.poles == poles), key=lambda m: m.rated_power_kW)

    def power_series(self, poles: int) -> list[float]:
        """The rated powers a motor of ``poles`` is placed among (its neighbours, rule IM-02):
        the GOST 12139-84 main series with the powers of the catalog's motors of that pole
        count merged in. A shipped 4A motor is rated on the series (a test checks it), so
        for the shipped catalog this is the series itself; a user's motor off the series
        (100 or 500 kW) gets its neighbours from the catalog in use."""
        return sorted(
            {*self.rated_powers_kW, *(m.rated_power_kW for m in self.motors_with_poles(poles))}
        )


#: A catalog is read whole; one larger than this is not a catalog (``/dev/zero``).
CATALOG_MAX_BYTES = 16 << 20


def _read(path: Path) -> dict[str, Any]:
    """A catalog file read as safely as a requirement (regular file, bounded size, no deep
    nesting; see :mod:`advisor.core.io_safety`)."""
    from advisor.core.errors import InputError
    from advisor.core.io_safety import parse_toml, read_input, show

    try:
        where = f"catalog {show(path, 200)}"
        return parse_toml(read_input(path, CATALOG_MAX_BYTES, what="catalog "), where)
    except CatalogError:
        raise
    except InputError as exc:
        raise CatalogError(str(exc)) from None


#: pydantic's bound errors, worded as the requirement's are (a bound in %g, not 0.0000000001)
_BOUNDS = {
    "greater_than_equal": ("ge", "≥"),
    "greater_than": ("gt", ">"),
    "less_than_equal": ("le", "≤"),
    "less_than": ("lt", "<"),
}


def _bound_text(err: Any) -> str | None:
    kind = _BOUNDS.get(err.get("type", ""))
    bound = (err.get("ctx") or {}).get(kind[0]) if kind else None
    if kind is None or not isinstance(bound, int | float):
        return None
    return f"must be {kind[1]} {bound:g}"


def _fail(path: Path, where: str, exc) -> CatalogError:
    err = exc.errors()[0]
    loc = ".".join(str(p) for p in err["loc"])
    from advisor.core.io_safety import show

    field = f"field {loc} = {show(repr(err['input']))}: " if loc else ""
    msg = _unit_string_text(err) or _bound_text(err) or err["msg"].removeprefix("Value error, ")
    return CatalogError(f"catalog {show(path, 200)}, {where}: {field}{msg}")


#: A plain number as a catalog writes one (ASCII digits), for a refusal's example.
_PLAIN = re.compile(r"[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?", re.ASCII)


def _unit_string_text(err: Any) -> str | None:
    """pydantic's refusal of text where a number belongs ("125 kg"), worded for a catalog:
    unlike a requirement, a catalog converts no unit strings; its numbers are plain, in the
    unit each key names."""
    text = err.get("input")
    if err.get("type") not in ("float_type", "int_type") or not isinstance(text, str):
        return None
    key = next((p for p in reversed(err["loc"]) if isinstance(p, str)), "")
    return _plain_numbers_text(text, key, item=err["loc"][-1:] != (key,))


def _plain_numbers_text(text: str, key: str, item: bool = False) -> str:
    """What a catalog takes instead of ``text`` at ``key`` (or an ``item`` of its array)."""
    number = _as_number(text, key)
    shown = "" if item else f"{key} = "
    example = f"e.g. {shown}1.2" if number is None else f"write {shown}{number}"
    return f"catalogs take plain SI numbers in the unit the key names, no unit strings ({example})"


def _as_number(text: str, key: str) -> str | None:
    """The plain number ``text`` stands for in ``key``'s unit ("125 kg" for mass_kg: 125);
    None where the key's unit or the text cannot be read."""
    from advisor.core.questions import unit_of
    from advisor.core.units import UnitError, to_unit

    if _PLAIN.fullmatch(text.strip(" \t")):
        return text.strip(" \t")
    unit = unit_of(key)
    try:
        return f"{to_unit(text, unit):.12g}" if unit else None
    except UnitError:
        return None


def _rows(path: Path, data: dict[str, Any], key: str) -> list[dict[str, Any]]:
    rows = data.get(key)
    if not isinstance(rows, list) or not all(isinstance(r, dict) for r in rows):
        raise CatalogError(f"catalog {path}: expected an array of tables [[{key}]]")
    return rows


def _key(row: dict[str, Any], key: str) -> str:
    """A row's naming key as a refusal echoes it: short, controls escaped."""
    from advisor.core.io_safety import show

    return show(repr(row.get(key)))


def _text(path: Path, data: dict[str, Any], key: str, default: str) -> str:
    """A file-level text key (``source = "..."``, ``law = "..."``): a string, or refused."""
    v = data.get(key, default)
    if not isinstance(v, str):
        from advisor.core.io_safety import show

        raise CatalogError(f"catalog {path}: {key} = {show(repr(v))}: must be a string")
    return v


def _supply_frequency(path: Path, data: dict[str, Any]) -> float:
    """The file-level ``supply_frequency_Hz`` of an induction motor catalog: a number within
    the range :data:`catalogs.schema.SUPPLY_FREQUENCY_RANGE_HZ` (a unit string is not read
    here: a catalog states its numbers in the units its keys name)."""
    from advisor.core.io_safety import show
    from catalogs.schema import SUPPLY_FREQUENCY_RANGE_HZ

    lo, hi = SUPPLY_FREQUENCY_RANGE_HZ
    v = data.get("supply_frequency_Hz", 50)
    if isinstance(v, str):
        why = _plain_numbers_text(v, "supply_frequency_Hz")
        raise CatalogError(f"catalog {path}: supply_frequency_Hz = {show(repr(v))}: {why}")
    if isinstance(v, bool) or not isinstance(v, int | float) or not lo <= v <= hi:
        raise CatalogError(
            f"catalog {path}: supply_frequency_Hz = {show(repr(v))}: must be a number "
            f"{lo:g} … {hi:g} Hz"
        )
    return float(v)


def _load_threads(path: Path) -> tuple[list[ThreadProfile], str]:
    from pydantic import ValidationError

    from catalogs.schema import ThreadPlanRow

    data = _read(path)
    out = []
    for i, row in enumerate(_rows(path, data, "thread"), start=1):
        try:
            plan = ThreadPlanRow.model_validate(row)
        except ValidationError as exc:
            raise _fail(path, f"row {i} (d_mm = {_key(row, 'd_mm')})", exc) from None
        for p in plan.pitches_mm:
            out.append(
                trapezoidal_profile(
                    plan.d_mm, p, preferred=(p == plan.preferred_mm), series=plan.series
                )
            )
    return out, _text(path, data, "source", path.name)


def _load_powers(path: Path) -> tuple[list[float], str]:
    from catalogs.schema import MAX_RATED_POWER_KW

    data = _read(path)
    powers = data.get("rated_powers_kW")
    if not isinstance(powers, list) or not powers:
        raise CatalogError(f"catalog {path}: rated_powers_kW must be a non-empty array")
    for i, p in enumerate(powers, start=1):
        if isinstance(p, str):
            why = _plain_numbers_text(p, "rated_powers_kW", item=True)
            from advisor.core.io_safety import show

            raise CatalogError(f"catalog {path}, rated_powers_kW item {i} = {show(repr(p))}: {why}")
        if (
            isinstance(p, bool)
            or not isinstance(p, int | float)
            or not (0 < p <= MAX_RATED_POWER_KW)
        ):
            raise CatalogError(
                f"catalog {path}, rated_powers_kW item {i} = {p!r}: must be > 0 and at most "
                f"{MAX_RATED_POWER_KW:g} kW"
            )
    if sorted(powers) != powers or len(set(powers)) != len(powers):
        raise CatalogError(f"catalog {path}: rated_powers_kW must be strictly increasing")
    return [float(p) for p in powers], _text(path, data, "source", path.name)


def _load_bibliography(path: Path, known: dict[str, dict[str, Any]]) -> dict[str, dict[str, Any]]:
    """The [[source]] entries of a bibliography file, validated, ids unique."""
    from pydantic import ValidationError

    from catalogs.schema import BibEntry

    data = _read(path)
    out = dict(known)
    for i, row in enumerate(_rows(path, data, "source"), start=1):
        where = f"row {i} (id = {_key(row, 'id')})"
        try:
            e = BibEntry.model_validate(row)
        except ValidationError as exc:
            raise _fail(path, where, exc) from None
        if e.id in out:
            raise CatalogError(f"catalog {path}, {where}: id {e.id!r} appears twice")
        out[e.id] = e.model_dump(exclude_none=True)
    return out


def _resolve_sources(path: Path, raw: Any, bib: dict[str, dict[str, Any]]) -> SourceMap:
    """A catalog's [sources] table resolved to bibliography ids: ``key = { id = "...",
    note = "..." }``, or ``key = "note"`` where the key is itself a bibliography id.

    A user catalog may also name a source of its own, ``key = "what it is"``: it joins the
    bibliography (``bib`` is extended) as an entry of that file. A shipped catalog may not."""
    if not isinstance(raw, dict):
        raise CatalogError(f"catalog {path}: [sources] must be a table")
    out: SourceMap = {}
    for key, v in raw.items():
        if isinstance(v, str):
            ref, note = key, v
        elif isinstance(v, dict) and set(v) <= {"id", "note"} and isinstance(v.get("id"), str):
            ref, note = v["id"], str(v.get("note", ""))
        else:
            raise CatalogError(
                f'catalog {path}: [sources] {key} = {v!r}: give {{ id = "<bibliography id>", '
                'note = "..." }'
            )
        if ref not in bib and isinstance(v, str) and path.parent != HERE:
            bib[ref] = {
                "id": ref,
                "short": ref,
                "authors": [],
                "title": v,
                "publisher": f"user catalog {path}",
            }
            note = ""
        if ref not in bib:
            raise CatalogError(
                f"catalog {path}: [sources] {key}: {ref!r} is not an id of the bibliography "
                f"({BIBLIOGRAPHY_FILE})"
            )
        out[key] = (ref, note)
    return out


def _load_motors(
    path: Path, bib: dict[str, dict[str, Any]]
) -> tuple[list[InductionMotor], SourceMap]:
    from pydantic import ValidationError

    from advisor.calc.induction import fit_kloss
    from catalogs.schema import InductionMotor as MotorSchema

    data = _read(path)
    sources = _resolve_sources(path, data.get("sources", {}), bib)
    freq = _supply_frequency(path, data)
    out: list[InductionMotor] = []
    for i, row in enumerate(_rows(path, data, "motor"), start=1):
        where = f"row {i} (model = {_key(row, 'model')})"
        try:
            m = InductionMotor(
                **MotorSchema.model_validate({**row, "supply_frequency_Hz": freq}).model_dump(
                    exclude={"rated_torque_Nm"}
                )  # checked, not kept: M_n = P/ω
            )
        except ValidationError as exc:
            raise _fail(path, where, exc) from None
        if m.source not in sources:
            raise CatalogError(f"catalog {path}, {where}: source = {m.source!r} not in [sources]")
        try:
            fit_kloss(
                m.rated_torque_Nm, m.rated_slip, m.breakdown_torque_ratio, m.starting_torque_ratio
            )
        except ValueError as exc:
            raise CatalogError(f"catalog {path}, {where}: {exc}") from None
        out.append(m)
    _check_motor_series(path, out)
    return out, dict(sources)


def _check_motor_series(path: Path, motors: list[InductionMotor]) -> None:
    """Within one pole count, efficiency must not fall as power rises (beyond 1.5 points):
    a row that breaks the trend is usually a copying error."""
    names = {}
    for m in motors:
        if m.model in names:
            raise CatalogError(f"catalog {path}: model {m.model!r} appears twice")
        names[m.model] = m
    for poles in {m.poles for m in motors}:
        line = sorted((m for m in motors if m.poles == poles), key=lambda m: m.rated_power_kW)
        for a, b in itertools.pairwise(line):
            if b.efficiency_pct < a.efficiency_pct - 1.5:
                raise CatalogError(
                    f"catalog {path}, model {b.model!r}: field efficiency_pct = "
                    f"{b.efficiency_pct} falls below the smaller {a.model} "
                    f"({a.efficiency_pct}); efficiency must rise with power"
                )


def _load_materials(path: Path, bib: dict[str, dict[str, Any]]) -> Materials:
    from pydantic import ValidationError

    from catalogs.schema import MaterialsFile

    data = _read(path)
    sources = _resolve_sources(path, data.get("sources", {}), bib)
    try:
        valid = MaterialsFile.model_validate(data).model_dump()
        return Materials.from_dict({**valid, "sources": sources})
    except ValidationError as exc:
        err = exc.errors()[0]
        loc = err["loc"]
        where = (
            f"row {loc[1] + 1} of [[{loc[0]}]]"
            if len(loc) > 1 and isinstance(loc[1], int)
            else "top level"
        )
        raise _fail(path, where, exc) from None


def _replace_materials(path: Path, shipped: Materials, bib: dict[str, dict[str, Any]]) -> Materials:
    """A user materials file replaces the shipped one whole, so it must hold every pair and
    steel a requirement can name (the shipped names)."""
    user = _load_materials(path, bib)
    for what, have, need in (
        ("pair", [p.name for p in user.pair], [p.name for p in shipped.pair]),
        ("steel", [s.name for s in user.steel], [s.name for s in shipped.steel]),
    ):
        missing = [n for n in need if n not in have]
        if missing:
            raise CatalogError(
                f"catalog {path}: [[{what}]] {', '.join(repr(n) for n in missing)} missing; "
                f"a user materials file replaces the shipped one and must hold every {what} a "
                f"requirement can name: {', '.join(need)}"
            )
    return user


#: The catalog files shipped with the advisor, in the order they are stamped.
SHIPPED_FILES = (
    THREADS_FILE,
    POWERS_FILE,
    MOTORS_FILE,
    MATERIALS_FILE,
    STEELS_FILE,
    BEARINGS_FILE,
    BIBLIOGRAPHY_FILE,
    FRAMES_FILE,
)


@cache
def load_catalogs(user_dir: Path | None = None) -> Catalogs:
    """The shipped catalogs, plus the rows of a user catalog directory if given.

    Validated catalogs are cached in the user's cache directory, keyed by the size and
    modification time of every file read; any change to a file validates it again. The cache
    is written with :mod:`marshal`, the interpreter's own serialiser of plain data: nothing to
    import, and read back in a fraction of a millisecond. It is the user's own file, as
    trusted as the catalogs beside it; a truncated or foreign one is ignored and rewritten.
    """
    files = [HERE / f for f in SHIPPED_FILES]
    if user_dir is not None:
        files += [
            user_dir / f
            for f in (
                THREADS_FILE,
                MOTORS_FILE,
                MATERIALS_FILE,
                STEELS_FILE,
                BEARINGS_FILE,
                BIBLIOGRAPHY_FILE,
                BLDC_MOTORS_FILE,
            )
        ]
    cached_at = cache_file(files)
    if cached_at is not None:
        cached = _read_cache(cached_at)
        if cached is not None:
            return cached
    cat = shipped_snapshot(files) if user_dir is None else None
    if cat is None:
        cat = _load_and_validate(user_dir)
    if cached_at is not None:
        _write_cache(cached_at, cat)
    return cat


def _load_and_validate(user_dir: Path | None) -> Catalogs:
    bib = _load_bibliography(HERE / BIBLIOGRAPHY_FILE, {})
    if user_dir is not None and (user_dir / BIBLIOGRAPHY_FILE).exists():
        bib = _load_bibliography(user_dir / BIBLIOGRAPHY_FILE, bib)
    threads, threads_source = _load_threads(HERE / THREADS_FILE)
    powers, powers_source = _load_powers(HERE / POWERS_FILE)
    motors, motor_sources = _load_motors(HERE / MOTORS_FILE, bib)
    materials = _load_materials(HERE / MATERIALS_FILE, bib)
    steels, steel_sources = _load_steels(HERE / STEELS_FILE, bib)
    bearings, friction, bearing_sources = _load_bearings(HERE / BEARINGS_FILE, bib)
    frames, bldc_sources = _load_frames(HERE / FRAMES_FILE, bib)
    if user_dir is not None:
        if not user_dir.is_dir():
            raise CatalogError(f"catalog directory {user_dir}: not a directory")
        if (user_dir / MOTORS_FILE).exists():
            extra, extra_sources = _load_motors(user_dir / MOTORS_FILE, bib)
            motors = motors + extra
            motor_sources = {**motor_sources, **extra_sources}
            _check_unique(user_dir / MOTORS_FILE, [m.model for m in motors], "model")
        if (user_dir / THREADS_FILE).exists():
            extra_threads, _ = _load_threads(user_dir / THREADS_FILE)
            threads = threads + extra_threads
            _check_unique(user_dir / THREADS_FILE, [t.name for t in threads], "thread")
        if (user_dir / MATERIALS_FILE).exists():
            materials = _replace_materials(user_dir / MATERIALS_FILE, materials, bib)
        if (user_dir / STEELS_FILE).exists():
            extra_steels, extra_sources = _load_steels(user_dir / STEELS_FILE, bib)
            steels = steels + extra_steels
            steel_sources = {**steel_sources, **extra_sources}
            _check_unique(user_dir / STEELS_FILE, [s.name for s in steels], "steel")
        if (user_dir / BEARINGS_FILE).exists():
            extra_b, extra_f, extra_src = _load_bearings(user_dir / BEARINGS_FILE, bib, friction)
            bearings = bearings + extra_b
            friction = {**friction, **extra_f}
            bearing_sources = {**bearing_sources, **extra_src}
            _check_unique(
                user_dir / BEARINGS_FILE, [b.designation.upper() for b in bearings], "bearing"
            )
        if (user_dir / BLDC_MOTORS_FILE).exists():
            extra_f, extra_src = _load_bldc_motors(user_dir / BLDC_MOTORS_FILE, bib)
            frames = frames + extra_f
            bldc_sources = {**bldc_sources, **extra_src}
            _check_unique(user_dir / BLDC_MOTORS_FILE, [f.name.lower() for f in frames], "motor")
    return Catalogs(
        threads=tuple(sorted(threads, key=lambda t: (t.d_mm, -t.pitch_mm))),
        threads_source=threads_source,
        rated_powers_kW=tuple(powers),
        powers_source=powers_source,
        motors=tuple(motors),
        motor_sources=motor_sources,
        materials=materials,
        electrical_steels=tuple(steels),
        steel_sources=steel_sources,
        bearings=tuple(bearings),
        bearing_friction=friction,
        bearing_sources=bearing_sources,
        bibliography=bib,
        bldc_frames=tuple(frames),
        bldc_sources=bldc_sources,
    )


def _load_frames(path: Path, bib: dict[str, dict[str, Any]]) -> tuple[list[BldcFrame], SourceMap]:
    """Seed 000's reference frame and the frames scaled from it, each checked against the
    law from the reference (:func:`catalogs.frames.check_row`)."""
    from pydantic import ValidationError

    from catalogs.frames import ORIGIN, check_row
    from catalogs.schema import BldcFrameRow, BldcReferenceRow

    data = _read(path)
    sources = _resolve_sources(path, data.get("sources", {}), bib)
    try:
        ref = BldcReferenceRow.model_validate(data.get("reference")).model_dump()
    except ValidationError as exc:
        raise _fail(path, "[reference]", exc) from None
    law = _text(path, data, "law", "")
    out = []
    for i, row in enumerate(_rows(path, data, "frame"), start=1):
        where = f"row {i} (name = {_key(row, 'name')})"
        try:
            f = BldcFrameRow.model_validate(row).model_dump()
        except ValidationError as exc:
            raise _fail(path, where, exc) from None
        why = check_row(f, ref)
        if why is not None:
            raise CatalogError(f"catalog {path}, {where}: {why}")
        missing = set(f["source"]) - set(sources)
        if missing:
            raise CatalogError(
                f"catalog {path}, {where}: source names {sorted(missing)} not in [sources]"
            )
        is_ref = f["name"] == ref["name"]
        out.append(
            BldcFrame(
                name=f["name"],
                kind="scaled",
                speed_rpm=f["speed_rpm"],
                torque_Nm=f["torque_Nm"],
                current_A=f["current_A"],
                phase_resistance_ohm=f["phase_resistance_ohm"],
                conducting_phases=2,
                stator_steel_area_mm2=f["stator_steel_area_mm2"],
                stack_length_mm=f["stack_length_mm"],
                magnet_losses=tuple(MagnetPoint(n, w) for n, w in f["magnet_losses"]),
                rotor_inertia_kgm2=f["rotor_inertia_kgm2"],
                thermal_time_constant_s=f["thermal_time_constant_s"],
                mass_kg=f["mass_kg"],
                outer_diameter_mm=f["stator_outer_diameter_mm"],
                length_mm=f["stack_length_mm"],
                source=tuple(f["source"]),
                law=("seed 000's reference frame" if is_ref else ORIGIN) + f" ({law})",
                length_scale=f["length_scale"],
                estimated=tuple(ref["estimated"]),
            )
        )
    _check_unique(path, [f.name for f in out], "frame")
    if not any(f.name == ref["name"] for f in out):
        raise CatalogError(f"catalog {path}: the reference {ref['name']!r} is not a [[frame]]")
    return out, dict(sources)


def _load_bldc_motors(
    path: Path, bib: dict[str, dict[str, Any]]
) -> tuple[list[BldcFrame], SourceMap]:
    """A user's PM brushless motors (bldc_motors.toml): datasheet rows as frames whose limit
    is their copper loss at the continuous torque (no core losses are published)."""
    from pydantic import ValidationError

    from catalogs.schema import BldcMotorRow

    data = _read(path)
    sources = _resolve_sources(path, data.get("sources", {}), bib)
    out = []
    for i, row in enumerate(_rows(path, data, "motor"), start=1):
        where = f"row {i} (name = {_key(row, 'name')})"
        try:
            m = BldcMotorRow.model_validate(row)
        except ValidationError as exc:
            raise _fail(path, where, exc) from None
        if m.source not in sources:
            raise CatalogError(f"catalog {path}, {where}: source = {m.source!r} not in [sources]")
        out.append(
            BldcFrame(
                name=m.name,
                kind="catalog",
                speed_rpm=m.rated_speed_rpm,
                torque_Nm=m.continuous_torque_Nm,
                current_A=m.continuous_torque_Nm / m.torque_constant_Nm_A,
                phase_resistance_ohm=m.phase_resistance_ohm,
                conducting_phases=3,  # sinusoidal currents: P = 3·R·I_rms²
                stator_steel_area_mm2=0.0,
                stack_length_mm=m.length_mm,
                magnet_losses=(MagnetPoint(m.rated_speed_rpm, 0.0),),
                rotor_inertia_kgm2=m.rotor_inertia_kgm2,
                thermal_time_constant_s=m.thermal_time_constant_s,
                mass_kg=m.mass_kg,
                outer_diameter_mm=m.outer_diameter_mm,
                length_mm=m.length_mm,
                source=(m.source,),
                law=f"datasheet ({path.name})",
                peak_torque_Nm=m.peak_torque_Nm,
                torque_constant_Nm_A=m.torque_constant_Nm_A,
                estimated=tuple(m.estimated),
                pole_pairs=m.pole_pairs,
            )
        )
    _check_unique(path, [f.name.lower() for f in out], "motor")
    return out, dict(sources)


#: Estimates of ball geometry where a catalog row does not publish it (see skf_bearings.toml).
BALL_DIAMETER_SHARE = 0.3
BALL_FILL = 0.67


def _complete_bearing(row: dict[str, Any]) -> dict[str, Any]:
    """Fill the ball geometry a row does not publish, and say so in ``estimated``."""
    d, big_d = row["d_mm"], row["D_mm"]
    est = list(row["estimated"])
    if row["pitch_diameter_mm"] is None:
        row["pitch_diameter_mm"] = (d + big_d) / 2.0
        est.append("pitch_diameter_mm")
    if row["ball_diameter_mm"] is None:
        row["ball_diameter_mm"] = BALL_DIAMETER_SHARE * (big_d - d)
        est.append("ball_diameter_mm")
    if row["ball_count"] is None:
        row["ball_count"] = round(
            BALL_FILL * math.pi * row["pitch_diameter_mm"] / row["ball_diameter_mm"]
        )
        est.append("ball_count")
    row["estimated"] = tuple(est)
    return row


def _load_bearings(
    path: Path,
    bib: dict[str, dict[str, Any]],
    known_friction: dict[str, FrictionConstants] | None = None,
) -> tuple[list[Bearing], dict[str, FrictionConstants], SourceMap]:
    from pydantic import ValidationError

    from catalogs.schema import BearingRow, FrictionRow

    data = _read(path)
    sources = _resolve_sources(path, data.get("sources", {}), bib)
    friction: dict[str, FrictionConstants] = {}
    table = data.get("friction", {})
    if not isinstance(table, dict):
        raise CatalogError(f"catalog {path}: [friction] must be a table of tables")
    for name, row in table.items():
        try:
            f = FrictionRow.model_validate(row)
        except ValidationError as exc:
            raise _fail(path, f"[friction.{name}]", exc) from None
        friction[name] = FrictionConstants(name=name, **f.model_dump())
    usable = {**(known_friction or {}), **friction}
    out = []
    for i, row in enumerate(_rows(path, data, "bearing"), start=1):
        where = f"row {i} (designation = {_key(row, 'designation')})"
        try:
            b = BearingRow.model_validate(row)
        except ValidationError as exc:
            raise _fail(path, where, exc) from None
        missing = set(b.source) - set(sources)
        if missing:
            raise CatalogError(
                f"catalog {path}, {where}: source names {sorted(missing)} not in [sources]"
            )
        if b.friction not in usable:
            raise CatalogError(
                f"catalog {path}, {where}: field friction = {b.friction!r} is not a "
                f"[friction.*] table; known: {', '.join(sorted(usable))}"
            )
        out.append(Bearing(**_complete_bearing(b.model_dump())))
    _check_unique(path, [b.designation.upper() for b in out], "bearing")
    return out, friction, dict(sources)


def _load_steels(
    path: Path, bib: dict[str, dict[str, Any]]
) -> tuple[list[ElectricalSteel], SourceMap]:
    from pydantic import ValidationError

    from catalogs.schema import ElectricalSteelRow

    data = _read(path)
    sources = _resolve_sources(path, data.get("sources", {}), bib)
    out = []
    for i, row in enumerate(_rows(path, data, "steel"), start=1):
        where = f"row {i} (grade = {_key(row, 'grade')})"
        try:
            s = ElectricalSteelRow.model_validate(row)
        except ValidationError as exc:
            raise _fail(path, where, exc) from None
        missing = set(s.source) - set(sources)
        if missing:
            raise CatalogError(
                f"catalog {path}, {where}: source names {sorted(missing)} not in [sources]"
            )
        out.append(ElectricalSteel(**{**s.model_dump(), "estimated": tuple(s.estimated)}))
    return out, dict(sources)


def _check_unique(path: Path, names: list[str], what: str) -> None:
    seen = set()
    for n in names:
        if n in seen:
            raise CatalogError(f"catalog {path}: {what} {n!r} is already in the shipped catalog")
        seen.add(n)


# ---------------------------------------------------------------- cache of validated catalogs
CACHE_VERSION = 6  # 6: PM brushless frames and user motors

#: The modules whose code makes the cached rows (read, validated, derived): the cache is
#: keyed by their source, so an edit to any of them is a new cache without bumping
#: CACHE_VERSION by hand.
CODE_MODULES = ("loader", "rows", "schema", "frames", "threads")


@cache
def code_stamp() -> int:
    """CRC-32 of the catalog code's source (:data:`CODE_MODULES`): about 70 KB read once per
    process, tens of microseconds. A module whose source cannot be read counts by its name
    (an installation without sources keys by CACHE_VERSION alone)."""
    crc = 0
    for name in CODE_MODULES:
        try:
            crc = zlib.crc32((HERE / f"{name}.py").read_bytes(), crc)
        except OSError:
            crc = zlib.crc32(name.encode(), crc)
    return crc


def cache_file(files: list[Path]) -> Path | None:
    if os.environ.get("DRIVE_ADVISOR_NO_CACHE"):
        return None
    # marshal's format may change between Python versions: the version is part of the key
    stamp: list[Any] = [CACHE_VERSION, code_stamp(), marshal.version, list(sys.version_info[:2])]
    for f in files:
        try:
            st = f.stat()
            stamp.append([str(f.resolve()), st.st_mtime_ns, st.st_size])
        except OSError:
            stamp.append([str(f), None, None])
    key = f"{zlib.crc32(repr(stamp).encode()):08x}"
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "drive-advisor" / f"catalogs-{key}.marshal"


# ---------------------------------------------------------------- snapshot of the shipped ones
#: The shipped catalogs, validated, as data (written by ``python -m catalogs.loader``), so
#: that a first run reads them without pydantic; used only while its stamp matches.
SNAPSHOT_MODULE = "validated"


def snapshot_stamp(files: list[Path]) -> int:
    """CRC-32 of the catalog code (:func:`code_stamp`) and of the files' contents (not their
    times: an installation writes the files anew)."""
    crc = zlib.crc32(code_stamp().to_bytes(4, "little"))
    for f in files:
        crc = zlib.crc32(f.read_bytes(), crc)
    return crc


def shipped_snapshot(files: list[Path]) -> Catalogs | None:
    """The shipped catalogs from the snapshot, or None when it is absent or does not match
    the files and the code (they are then validated)."""
    try:
        from catalogs import validated

        if validated.STAMP != snapshot_stamp(files):
            return None
        return _from_data(validated.DATA)
    except (ImportError, OSError, AttributeError, KeyError, TypeError, ValueError):
        return None


def snapshot_text() -> str:
    """The source of :mod:`catalogs.validated`: the shipped catalogs validated now."""
    files = [HERE / f for f in SHIPPED_FILES]
    data = _data(_load_and_validate(None))
    return (
        '"""The shipped catalogs, validated, as plain data: a first run reads them without\n'
        "pydantic while STAMP matches the catalog files and code (catalogs.loader). Do not\n"
        'edit: python -m catalogs.loader writes it."""\n'
        "\n# fmt: off\n# ruff: noqa: E501\n"
        f"STAMP = {snapshot_stamp(files)}\n"
        f"DATA = {data!r}\n"
    )


def _read_cache(path: Path) -> Catalogs | None:
    try:
        return _from_data(marshal.loads(path.read_bytes()))
    except (OSError, ValueError, EOFError, KeyError, TypeError):
        return None  # absent, truncated or stale format: validate the files again


def _from_data(data: dict[str, Any]) -> Catalogs:
    """The catalogs of the plain data :func:`_data` makes (the cache's, the snapshot's)."""
    mat = data["materials"]
    return Catalogs(
        threads=tuple(ThreadProfile(**t) for t in data["threads"]),
        threads_source=data["threads_source"],
        rated_powers_kW=tuple(data["rated_powers_kW"]),
        powers_source=data["powers_source"],
        motors=tuple(InductionMotor(**m) for m in data["motors"]),
        motor_sources=_source_map(data["motor_sources"]),
        materials=Materials.from_dict(mat),
        electrical_steels=tuple(ElectricalSteel(**x) for x in data["electrical_steels"]),
        steel_sources=_source_map(data["steel_sources"]),
        bearings=tuple(Bearing(**b) for b in data["bearings"]),
        bearing_friction={k: FrictionConstants(**v) for k, v in data["bearing_friction"].items()},
        bearing_sources=_source_map(data["bearing_sources"]),
        bibliography=data["bibliography"],
        bldc_frames=tuple(BldcFrame.from_dict(f) for f in data["bldc_frames"]),
        bldc_sources=_source_map(data["bldc_sources"]),
    )


def _source_map(d: dict[str, list[str]]) -> SourceMap:
    return {k: (v[0], v[1]) for k, v in d.items()}


def _write_cache(path: Path, cat: Catalogs) -> None:
    data = _data(cat)
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_suffix(f".{os.getpid()}.tmp")
        tmp.write_bytes(marshal.dumps(data))
        os.replace(tmp, path)
    except OSError:
        pass  # a read-only home only costs the validation time on the next run


def _data(cat: Catalogs) -> dict[str, Any]:
    """The validated catalogs as plain data (what the cache and the snapshot hold)."""
    return {
        "threads": [t._asdict() for t in cat.threads],
        "threads_source": cat.threads_source,
        "rated_powers_kW": list(cat.rated_powers_kW),
        "powers_source": cat.powers_source,
        "motors": [m._asdict() for m in cat.motors],
        "motor_sources": cat.motor_sources,
        "materials": cat.materials.to_dict(),
        "electrical_steels": [x._asdict() for x in cat.electrical_steels],
        "steel_sources": cat.steel_sources,
        "bearings": [b._asdict() for b in cat.bearings],
        "bearing_friction": {k: v._asdict() for k, v in cat.bearing_friction.items()},
        "bearing_sources": cat.bearing_sources,
        "bibliography": cat.bibliography,
        "bldc_frames": [f.as_dict() for f in cat.bldc_frames],
        "bldc_sources": cat.bldc_sources,
    }


if __name__ == "__main__":
    (HERE / f"{SNAPSHOT_MODULE}.py").write_text(snapshot_text(), encoding="utf-8")
