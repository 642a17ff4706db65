"""The joint choice of thread and motor, fast: the catalog's threads and motor lines
prepared once per catalog, every thread screened, and the smallest motor of each pole count
that drives it as a drive option (rule SCR-04 ranks them)."""

import math
from bisect import bisect_left
from typing import NamedTuple

from advisor.calc import one_way as one_way_calc
from advisor.calc.sizing import (
    MotorFit,
    ScrewDemand,
    ThreadGeometry,
    ThreadScreen,
    drive_working_speed,
    fit_motor,
    thread_geometry,
)
from advisor.core.reading import Requirements
from catalogs import Catalogs
from rules import screw as screw_rules


class MotorLine(NamedTuple):
    """The catalog's motors of one pole count, in order of rated power, fitted, with the
    running maximum along the line of the smaller of rated and starting torque (``reach``),
    their rated powers, and the fastest synchronous speed of the line."""

    pole_pairs: int
    fits: list[MotorFit]
    reach: list[float]
    powers_kW: list[float]
    #: no motor of the line turns faster: its working speed is n₀·(1 − s) ≤ n₀  [rpm]
    top_speed_rpm: float


def motor_line(pole_pairs: int, fits: list[MotorFit]) -> MotorLine:
    """A motor line with its reach (see :func:`drive_options`)."""
    reach, top = [], -math.inf
    for fit in fits:
        top = max(top, min(fit.rated_torque_Nm, fit.starting_torque_Nm))
        reach.append(top)
    powers = [fit.motor.rated_power_kW for fit in fits]
    return MotorLine(pole_pairs, fits, reach, powers, max(f.synchronous_speed_rpm for f in fits))


class CatalogParts(NamedTuple):
    """What the linear advice derives from a catalog alone, whatever the requirement."""

    threads: list[ThreadGeometry]  # of cat.threads, in order
    fits: dict[int, list[MotorFit]]  # by pole pairs, lines in order of rated power
    lines: list[MotorLine]


#: Catalog parts by ``id`` of the catalog, with the catalog itself kept alive beside them so
#: that its id cannot be reused by another catalog (a user catalog directory is another one).
_PARTS: dict[int, tuple[Catalogs, CatalogParts]] = {}
_PARTS_MAX = 8


def catalog_parts(cat: Catalogs) -> CatalogParts:
    """The thread geometries and fitted motor lines of ``cat``, computed once per catalog:
    they do not depend on the requirement."""
    held = _PARTS.pop(id(cat), None)
    if held is not None and held[0] is cat:
        _PARTS[id(cat)] = held  # the most recently used last: the oldest is dropped first
        return held[1]
    fits = {pp: [fit_motor(m) for m in cat.motors_with_poles(2 * pp)] for pp in (1, 2, 3, 4)}
    fits = {pp: line for pp, line in fits.items() if line}
    parts = CatalogParts(
        [thread_geometry(t) for t in cat.threads],
        fits,
        [motor_line(pp, line) for pp, line in fits.items()],
    )
    if len(_PARTS) >= _PARTS_MAX:
        del _PARTS[next(iter(_PARTS))]
    _PARTS[id(cat)] = (cat, parts)
    return parts


STARTS_FREE = (1, 2, 3, 4)


def line_option(
    ev: ThreadScreen, line: MotorLine, max_power_kW: float = math.inf
) -> screw_rules.DriveOption | None:
    """The smallest motor of ``line`` that drives the thread of ``ev`` directly, as a drive
    option; ``None`` when none does (or none of at most ``max_power_kW``: the line is in
    order of rated power, so the search stops at the first motor above it).

    A motor whose rated or starting torque is below the screw torque cannot drive it (the
    first test of :func:`drive_working_speed`); the line's reach is the running maximum of
    the smaller of the two, and a bisection on it skips those motors at once instead of
    testing them one by one (the joint choice screens every thread, so this runs often).
    A screw faster than the line's fastest synchronous speed has no motor in it."""
    speed = ev.speed_rpm
    if speed > line.top_speed_rpm:
        return None
    torque, fits, powers = ev.motor_torque_Nm, line.fits, line.powers_kW
    for i in range(bisect_left(line.reach, torque), len(fits)):
        if powers[i] > max_power_kW:
            return None
        fit = fits[i]
        n = drive_working_speed(fit, torque, speed)
        if n is None or n > ev.max_speed_rpm:  # too slow, or above the whirling limit
            continue
        m, thread = fit.motor, ev.thread
        return screw_rules.DriveOption(  # positional, in the order of its fields (faster)
            ev.name,  # thread
            thread.d_mm,
            thread.pitch_mm,
            ev.starts,
            ev.self_locking_at_low_friction,
            ev.torque_Nm,  # screw_torque_Nm
            m.model,
            line.pole_pairs,
            m.rated_power_kW,
            fit.rated_torque_Nm,
            60.0 * ev.revolutions / n,  # travel_time_s
        )
    return None


def drive_options(
    screens: list[ThreadScreen], lines: list[MotorLine]
) -> list[screw_rules.DriveOption]:
    """Every (thread, starts) that passes its checks, with the smallest motor of each pole
    count that drives it directly (:func:`line_option`)."""
    out = []
    for ev in screens:
        if ev.passed:
            for line in lines:
                option = line_option(ev, line)
                if option is not None:
                    out.append(option)
    return out


def first_drive_option(
    screens: list[ThreadScreen], lines: list[MotorLine], hold: bool
) -> screw_rules.DriveOption | None:
    """The option of :func:`drive_options` that comes first in the order of
    :func:`rules.screw.drive_order` (the first of equals, as ``min`` takes it), found
    without building most of the others.

    Exact: the order compares the holding flag, then the motor's rated power, first. The
    option of a thread on a line uses a motor at or after the line's bisection index, and a
    line is in order of rated power, so that motor's rated power is at least the one at the
    index. A (thread, line) whose flag and least possible rated power already compare above
    the best option found cannot come first, and is skipped; with the same flag, the search
    along the line stops above the best one's rated power for the same reason. Every other
    option is built by :func:`line_option` and compared by the full order, in the order of
    :func:`drive_options`, a later one replacing the best only when it comes strictly
    first."""
    best, best_key = None, None
    best_flag, best_power = True, math.inf  # (flag, power) ≤ these: every option so far
    for ev in screens:
        if not ev.passed:
            continue
        flag = not ev.self_locking_at_low_friction if hold else False
        if flag > best_flag:
            continue  # (flag, any power) compares above the best option's
        torque = ev.motor_torque_Nm
        for line in lines:
            i = bisect_left(line.reach, torque)
            if i == len(line.reach):
                continue  # no motor of the line drives it
            cap = math.inf
            if best_key is not None and flag == best_flag:
                if line.powers_kW[i] > best_power:
                    continue
                cap = best_power
            option = line_option(ev, line, cap)
            if option is None:
                continue
            key = screw_rules.drive_order(option, hold)
            if best_key is None or key < best_key:
                best, best_key = option, key
                best_flag, best_power = key[0], key[1]
    return best


def choice_options(
    screens: list[ThreadScreen], lines: list[MotorLine], imposed: str | None, hold: bool
) -> list[screw_rules.DriveOption]:
    """The drive options the joint choice (rule SCR-04) reads. With the thread free, all of
    them (it counts them and ranks them all). With a thread imposed, the imposed thread's
    options, and of the others only the one the advisor would choose itself
    (:func:`first_drive_option`): the rule ranks, counts and lists the imposed thread's
    options only, and names the best of all as the advisor's own choice."""
    if imposed is None:
        return drive_options(screens, lines)
    options = drive_options([ev for ev in screens if ev.name == imposed], lines)
    own = first_drive_option(screens, lines, hold)
    if own is not None and own.thread != imposed:
        options.append(own)
    return options


def device_efficiency(req: Requirements) -> float:
    """The driving efficiency of the one-way device the requirement asks for, known before
    the thread and the motor are chosen: the motor's choice must see it. 'auto' chooses
    between the two clutches (OW-02), both of η = 1."""
    kind = req.one_way.type
    return 1.0 if kind == "auto" else one_way_calc.passage(kind).efficiency


def through_device(screens: list[ThreadScreen], efficiency: float) -> list[ThreadScreen]:
    """The screens with the device's efficiency on every thread that needs the device (one
    not self-locking at the low end of its friction range): their motor gives 1/η times the
    screw torque."""
    if efficiency == 1.0:
        return screens
    return [
        screen._replace(device_efficiency=efficiency)
        if not screen.self_locking_at_low_friction
        else screen
        for screen in screens
    ]


def thread_screens(req: Requirements, cat: Catalogs, demand: ScrewDemand) -> list[ThreadScreen]:
    """Every thread of the catalog with every number of starts allowed, screened under the
    demand; where the load must hold, through the one-way device on every thread that needs
    one."""
    s = req.screw
    starts_options = (s.starts,) if s.starts is not None else STARTS_FREE
    device_eta = device_efficiency(req) if req.application.hold_without_power else 1.0
    return through_device(demand.screen(catalog_parts(cat).threads, starts_options), device_eta)
