"""Load and validate the catalogs; a bad entry is refused with file, row and field named."""

import itertools
import json
import math
import os
import zlib
from functools import cache
from pathlib import Path
from typing import Any, NamedTuple

from advisor.core.errors import CatalogError
from catalogs.rows import (
    Bearing,
    ElectricalSteel,
    FrictionConstants,
    FrictionPair,
    InductionMotor,
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


# ---------------------------------------------------------------- the bundle
class Catalogs(NamedTuple):
    threads: tuple[ThreadProfile, ...]
    threads_source: str
    rated_powers_kW: tuple[float, ...]
    powers_source: str
    motors: tuple[InductionMotor, ...]
    motor_sources: dict[str, str]
    materials: Materials
    electrical_steels: tuple[ElectricalSteel, ...]
    steel_sources: dict[str, str]
    bearings: tuple[Bearing, ...] = ()
    bearing_friction: dict[str, FrictionConstants] = {}  # noqa: RUF012 - NamedTuple default
    bearing_sources: dict[str, str] = {}  # noqa: RUF012

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


#: A catalog is read whole; one larger than this is not a catalog (``/dev/zero``).
CATALOG_MAX_BYTES = 16 << 20


def _read(path: Path) -> dict[str, Any]:
    """A catalog file read as safely as a requirement (regular file, bounded size, no deep
    nesting; see :mod:`advisor.io_safety`)."""
    from advisor.core.errors import InputError
    from advisor.io_safety import parse_toml, read_input, show

    try:
        where = f"catalog {show(path, 200)}"
        return parse_toml(read_input(path, CATALOG_MAX_BYTES, what="catalog "), where)
    except CatalogError:
        raise
    except InputError as exc:
        raise CatalogError(str(exc)) from None


def _fail(path: Path, where: str, exc) -> CatalogError:
    err = exc.errors()[0]
    loc = ".".join(str(p) for p in err["loc"])
    from advisor.io_safety import show

    field = f"field {loc} = {show(repr(err['input']))}: " if loc else ""
    msg = err["msg"].removeprefix("Value error, ")
    return CatalogError(f"catalog {path}, {where}: {field}{msg}")


def _rows(path: Path, data: dict[str, Any], key: str) -> list[dict[str, Any]]:
    rows = data.get(key)
    if not isinstance(rows, list) or not all(isinstance(r, dict) for r in rows):
        raise CatalogError(f"catalog {path}: expected an array of tables [[{key}]]")
    return rows


def _load_threads(path: Path) -> tuple[list[ThreadProfile], str]:
    from pydantic import ValidationError

    from catalogs.schema import ThreadPlanRow

    data = _read(path)
    out = []
    for i, row in enumerate(_rows(path, data, "thread"), start=1):
        try:
            plan = ThreadPlanRow.model_validate(row)
        except ValidationError as exc:
            raise _fail(path, f"row {i} (d_mm = {row.get('d_mm')!r})", exc) from None
        for p in plan.pitches_mm:
            out.append(
                trapezoidal_profile(
                    plan.d_mm, p, preferred=(p == plan.preferred_mm), series=plan.series
                )
            )
    return out, str(data.get("source", path.name))


def _load_powers(path: Path) -> tuple[list[float], str]:
    data = _read(path)
    powers = data.get("rated_powers_kW")
    if not isinstance(powers, list) or not powers:
        raise CatalogError(f"catalog {path}: rated_powers_kW must be a non-empty array")
    for i, p in enumerate(powers, start=1):
        if isinstance(p, bool) or not isinstance(p, int | float) or not (0 < p < math.inf):
            raise CatalogError(f"catalog {path}, rated_powers_kW item {i} = {p!r}: must be > 0")
    if sorted(powers) != powers or len(set(powers)) != len(powers):
        raise CatalogError(f"catalog {path}: rated_powers_kW must be strictly increasing")
    return [float(p) for p in powers], str(data.get("source", path.name))


def _load_motors(path: Path) -> tuple[list[InductionMotor], dict[str, str]]:
    from pydantic import ValidationError

    from advisor.calc.induction import fit_kloss
    from catalogs.schema import InductionMotor as MotorSchema

    data = _read(path)
    sources = data.get("sources", {})
    freq = data.get("supply_frequency_Hz", 50)
    out: list[InductionMotor] = []
    for i, row in enumerate(_rows(path, data, "motor"), start=1):
        where = f"row {i} (model = {row.get('model')!r})"
        try:
            m = InductionMotor(
                **MotorSchema.model_validate(
                    {**row, "supply_frequency_Hz": float(freq)}
                ).model_dump()
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


def _load_materials(path: Path) -> Materials:
    from pydantic import ValidationError

    from catalogs.schema import MaterialsFile

    data = _read(path)
    try:
        return Materials.from_dict(MaterialsFile.model_validate(data).model_dump())
    except ValidationError as exc:
        err = exc.errors()[0]
        loc = err["loc"]
        where = (
            f"row {loc[1] + 1} of [[{loc[0]}]]"
            if len(loc) > 1 and isinstance(loc[1], int)
            else "top level"
        )
        raise _fail(path, where, exc) from None


@cache
def load_catalogs(user_dir: Path | None = None) -> Catalogs:
    """The shipped catalogs, plus the rows of a user catalog directory if given.

    Validated catalogs are cached as JSON in the user's cache directory, keyed by the size
    and modification time of every file read; any change to a file validates it again.
    """
    files = [
        HERE / f
        for f in (
            THREADS_FILE,
            POWERS_FILE,
            MOTORS_FILE,
            MATERIALS_FILE,
            STEELS_FILE,
            BEARINGS_FILE,
        )
    ]
    if user_dir is not None:
        files += [
            user_dir / f
            for f in (THREADS_FILE, MOTORS_FILE, MATERIALS_FILE, STEELS_FILE, BEARINGS_FILE)
        ]
    cache_file = _cache_file(files)
    if cache_file is not None:
        cached = _read_cache(cache_file)
        if cached is not None:
            return cached
    cat = _load_and_validate(user_dir)
    if cache_file is not None:
        _write_cache(cache_file, cat)
    return cat


def _load_and_validate(user_dir: Path | None) -> Catalogs:
    threads, threads_source = _load_threads(HERE / THREADS_FILE)
    powers, powers_source = _load_powers(HERE / POWERS_FILE)
    motors, motor_sources = _load_motors(HERE / MOTORS_FILE)
    materials = _load_materials(HERE / MATERIALS_FILE)
    steels, steel_sources = _load_steels(HERE / STEELS_FILE)
    bearings, friction, bearing_sources = _load_bearings(HERE / BEARINGS_FILE)
    if user_dir is not None:
        if not user_dir.is_dir():
            raise CatalogError(f"catalog directory {user_dir}: not a directory")
        if (user_dir / MOTORS_FILE).exists():
            extra, extra_sources = _load_motors(user_dir / MOTORS_FILE)
            motors = motors + extra
            motor_sources = {**motor_sources, **extra_sources}
            _check_unique(user_dir / MOTORS_FILE, [m.model for m in motors], "model")
        if (user_dir / THREADS_FILE).exists():
            extra_threads, _ = _load_threads(user_dir / THREADS_FILE)
            threads = threads + extra_threads
            _check_unique(user_dir / THREADS_FILE, [t.name for t in threads], "thread")
        if (user_dir / MATERIALS_FILE).exists():
            materials = _load_materials(user_dir / MATERIALS_FILE)
        if (user_dir / STEELS_FILE).exists():
            extra_steels, extra_sources = _load_steels(user_dir / STEELS_FILE)
            steels = steels + extra_steels
            steel_sources = {**steel_sources, **extra_sources}
            _check_unique(user_dir / STEELS_FILE, [s.name for s in steels], "steel")
        if (user_dir / BEARINGS_FILE).exists():
            extra_b, extra_f, extra_src = _load_bearings(user_dir / BEARINGS_FILE, friction)
            bearings = bearings + extra_b
            friction = {**friction, **extra_f}
            bearing_sources = {**bearing_sources, **extra_src}
            _check_unique(
                user_dir / BEARINGS_FILE, [b.designation.upper() for b in bearings], "bearing"
            )
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
    )


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
    path: Path, known_friction: dict[str, FrictionConstants] | None = None
) -> tuple[list[Bearing], dict[str, FrictionConstants], dict[str, str]]:
    from pydantic import ValidationError

    from catalogs.schema import BearingRow, FrictionRow

    data = _read(path)
    sources = data.get("sources", {})
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
        where = f"row {i} (designation = {row.get('designation')!r})"
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


def _load_steels(path: Path) -> tuple[list[ElectricalSteel], dict[str, str]]:
    from pydantic import ValidationError

    from catalogs.schema import ElectricalSteelRow

    data = _read(path)
    sources = data.get("sources", {})
    out = []
    for i, row in enumerate(_rows(path, data, "steel"), start=1):
        where = f"row {i} (grade = {row.get('grade')!r})"
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
CACHE_VERSION = 3


def _cache_file(files: list[Path]) -> Path | None:
    if os.environ.get("DRIVE_ADVISOR_NO_CACHE"):
        return None
    stamp = [CACHE_VERSION]
    for f in files:
        try:
            st = f.stat()
            stamp.append([str(f.resolve()), st.st_mtime_ns, st.st_size])
        except OSError:
            stamp.append([str(f), None, None])
    key = f"{zlib.crc32(json.dumps(stamp).encode()):08x}"
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "drive-advisor" / f"catalogs-{key}.json"


def _read_cache(path: Path) -> Catalogs | None:
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
        mat = data["materials"]
        return Catalogs(
            threads=tuple(ThreadProfile(**t) for t in data["threads"]),
            threads_source=data["threads_source"],
            rated_powers_kW=tuple(data["rated_powers_kW"]),
            powers_source=data["powers_source"],
            motors=tuple(InductionMotor(**m) for m in data["motors"]),
            motor_sources=data["motor_sources"],
            materials=Materials.from_dict(mat),
            electrical_steels=tuple(ElectricalSteel(**x) for x in data["electrical_steels"]),
            steel_sources=data["steel_sources"],
            bearings=tuple(Bearing(**b) for b in data["bearings"]),
            bearing_friction={
                k: FrictionConstants(**v) for k, v in data["bearing_friction"].items()
            },
            bearing_sources=data["bearing_sources"],
        )
    except (OSError, ValueError, KeyError, TypeError):
        return None  # absent or stale format: validate the files again


def _write_cache(path: Path, cat: Catalogs) -> None:
    data = {
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
    }
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_suffix(f".{os.getpid()}.tmp")
        tmp.write_text(json.dumps(data), encoding="utf-8")
        os.replace(tmp, path)
    except OSError:
        pass  # a read-only home only costs the validation time on the next run
