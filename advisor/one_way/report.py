"""Report tables of the one-way (holding) device, shared by the linear and rotary actuators."""

from advisor.calc.one_way import Device
from advisor.core.report import ReportTable, record_fields


class DeviceOut(ReportTable):
    """A sized device (:class:`advisor.calc.one_way.Device`) where it sits: the record's
    fields, its location ("motor side", "output side") after its type."""

    __annotations__ = record_fields(Device, add={"type": {"location": str}})


class OneWayOut(ReportTable):
    type: str
    location: str
    torque_Nm: float
    outer_diameter_mm: float | None = None
    length_mm: float | None = None
    mass_kg: float | None = None
    inertia_kgm2: float | None = None
    efficiency: float | None = None
    power_W: float | None = None
    power_share: float | None = None
    basis: str = ""
    output_side: DeviceOut | None = None  # the same type at the output (device at the motor)
    motor_side: DeviceOut | None = None  # the same type at the motor (device at the output)
    alternatives: list[DeviceOut] = []
