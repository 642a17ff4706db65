"""The one-way (holding) device of a drive that must hold its load with the motor off
(seed 004): chosen, sized at the motor side, compared with the same device at the output and
with the other types. Orchestration only; shared by the linear and rotary pipelines."""

from advisor.calc.one_way import EM_CLUTCH, TYPES, Device, Passage, em_clutch_power, passage, size
from advisor.core.rulebook import Trace
from advisor.one_way.report import DeviceOut, OneWayOut
from rules.one_way import NAMES, device_type


def _out(d: Device, location: str) -> DeviceOut:
    return DeviceOut.make(location=location, **d._asdict())


def _sized(torque_Nm: float, rollers: int) -> dict[str, Device]:
    """Every type that can be built for the torque, sized (seed 004)."""
    out = {}
    for kind in TYPES:
        d = size(kind, torque_Nm, rollers)
        if d is not None:
            out[kind] = d
    return out


def device_passage(
    req_one_way, motor_torque_Nm: float, output_torque_Nm: float, at_output: bool = False
) -> Passage:
    """How the device that :func:`choose_device` would choose passes torque (its driving
    efficiency, whether a load can drive back through it), before the choice is recorded:
    the motor's own choice and the duty cycle must already see it."""
    here = output_torque_Nm if at_output else motor_torque_Nm
    options = _sized(here, req_one_way.rollers)
    chosen = device_type(req_one_way.type, req_one_way.priority, options).value
    return passage(chosen)


def choose_device(
    req_one_way,
    motor_torque_Nm: float,
    output_torque_Nm: float,
    motor_power_W: float,
    trace: Trace,
    at_output: bool = False,
) -> tuple[OneWayOut, list[str]]:
    """Size every type where the device sits (the motor side; the output with
    ``at_output``), pick one by OW-02, and show the same type at the other side."""
    here, there = (
        (output_torque_Nm, motor_torque_Nm) if at_output else (motor_torque_Nm, output_torque_Nm)
    )
    where = "output side" if at_output else "motor side"
    options = _sized(here, req_one_way.rollers)
    chosen = trace.apply(device_type, req_one_way.type, req_one_way.priority, options)
    warnings: list[str] = []
    if chosen not in options:  # only the electromagnetic clutch can fail to exist
        raise _em_clutch_impossible(here, where)
    d = options[chosen]
    other = size(chosen, there, req_one_way.rollers)
    other_out = None if other is None else _out(other, "motor side" if at_output else "output side")
    if d.efficiency < 0.5:
        warnings.append(
            f"the {NAMES[chosen]} drives with η = {d.efficiency:.2f}: the motor must give "
            f"{1 / d.efficiency:.2f}× the torque, and seed 004 judges such devices not rational "
            "in a new drive"
        )
    share = d.power_W / motor_power_W if motor_power_W > 0 else 0.0
    out = OneWayOut.make(
        type=chosen,
        location=where,
        torque_Nm=here,
        outer_diameter_mm=d.outer_diameter_mm,
        length_mm=d.length_mm,
        mass_kg=d.mass_kg,
        inertia_kgm2=d.inertia_kgm2,
        efficiency=d.efficiency,
        power_W=d.power_W,
        power_share=share,
        basis=d.basis,
        output_side=None if at_output else other_out,
        motor_side=other_out if at_output else None,
        alternatives=[_out(x, where) for k, x in options.items() if k != chosen],
    )
    return out, warnings


def _em_clutch_impossible(torque: float, where: str = "motor side"):
    from advisor.core.errors import InfeasibleError

    p = EM_CLUTCH
    _, b = em_clutch_power(torque, max(p.diameters_mm), p)
    return InfeasibleError(
        "no feasible design: no electromagnetic clutch of the seed's range carries the torque",
        [
            f"{torque:.4g} N·m at the {where} needs {b:.2f} T in the poles of a "
            f"{max(p.diameters_mm):g} mm clutch (limit {p.saturation_T:g} T)",
            "choose one_way.type = 'roller_clutch' or 'auto'"
            + (", or one_way.location = 'motor_side'" if where == "output side" else ""),
        ],
    )
