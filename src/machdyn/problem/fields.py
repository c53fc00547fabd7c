"""Quantity fields of problem files: text with a unit in, an SI float out; each field knows its unit.

``Length`` accepts ``"45 mm"``, ``"0.045 m"`` or ``"1.8 in"`` and stores 0.045 (metres). A bare number is
refused for every dimensional value (angles included: ``30`` could be degrees or radians), so that no value is
ever read in a unit its author did not mean. The SI unit and the positivity rule of a field are kept in its
metadata (:class:`Unit`), which the dumper reads to write the value back with its unit.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Annotated, Any

from pydantic import BeforeValidator

from ..errors import InputError
from ..units import Q_, parse_quantity, unit_of_text


@dataclass(frozen=True)
class Unit:
    """Metadata of a quantity field: its SI ``unit``, the ``kind`` of quantity and its sign rule."""

    unit: str
    kind: str
    rule: str = ""  # "" (any finite value), ">0" or ">=0"


#: Units a dump prefers for each kind, when they give back exactly the same float; SI otherwise.
PREFERRED_UNITS: dict[str, tuple[str, ...]] = {
    "length": ("mm", "m"),
    "angle": ("deg", "rad"),
    "angular_velocity": ("rad/s", "rpm"),
}


class FieldError(InputError):
    """A value of a problem file breaks a rule; the message starts with the rule (the path is added later)."""


def _example(value: Any, unit: str) -> str:
    return f'"{value} {unit}"'


def to_si(value: Any, meta: Unit) -> float:
    """Convert a problem-file value to a float in ``meta.unit``; raise :class:`FieldError` saying why not."""
    if isinstance(value, bool) or not isinstance(value, str | int | float):
        raise FieldError(
            f"must be a quantity with a unit written as text, like {_example(1, _hint(meta))}; "
            f"got {_show(value)}"
        )
    if isinstance(value, int | float) and meta.unit:
        raise FieldError(f"needs a unit, like {_example(value, _hint(meta))}; got the bare number {value!r}")
    if meta.kind == "angular_velocity" and isinstance(value, str) and "hz" in value.lower():
        # pint reads 1 Hz as 1 rad/s, a factor 2 pi off from the revolutions per second a designer means.
        raise FieldError(f"must not be given in Hz, which is ambiguous for a shaft speed (rev/s or rad/s?); "
                         f"write rpm, rev/s or rad/s; got {_show(value)}")
    try:
        si = parse_quantity(value, meta.unit, field="value")
    except InputError as exc:
        text = str(exc)
        for prefix in ("The value ", "the value "):
            if text.startswith(prefix):
                text = text[len(prefix) :]
        raise FieldError(text.rstrip(".")) from None
    if meta.rule == ">0" and not si > 0:
        raise FieldError(f"must be > 0 {meta.unit}; got {_show(value)}")
    if meta.rule == ">=0" and not si >= 0:
        raise FieldError(f"must be >= 0 {meta.unit}; got {_show(value)}")
    return si


def _hint(meta: Unit) -> str:
    return {"angle": "deg", "length": "mm"}.get(meta.kind, meta.unit)


def _show(value: Any) -> str:
    return f"'{value}'" if isinstance(value, str) else repr(value)


def quantity(unit: str, kind: str, rule: str = "") -> Any:
    """An annotated float type for a quantity in ``unit`` (SI), e.g. ``quantity("m", "length", ">0")``."""
    meta = Unit(unit, kind, rule)
    return Annotated[float, BeforeValidator(lambda v: to_si(v, meta)), meta]


Length = quantity("m", "length")
PositiveLength = quantity("m", "length", ">0")
NonNegativeLength = quantity("m", "length", ">=0")
Mass = quantity("kg", "mass", ">=0")
PositiveMass = quantity("kg", "mass", ">0")
Inertia = quantity("kg*m^2", "inertia", ">=0")
Angle = quantity("rad", "angle")
AngularVelocity = quantity("rad/s", "angular_velocity")
AngularAcceleration = quantity("rad/s^2", "angular_acceleration")
Acceleration = quantity("m/s^2", "acceleration")
Force = quantity("N", "force")
Torque = quantity("N*m", "torque")
Stiffness = quantity("N/m", "stiffness", ">=0")
LinearDensity = quantity("kg/m", "linear_density", ">0")
PositiveInertia = quantity("kg*m^2", "inertia", ">0")
PositiveStiffness = quantity("N/m", "stiffness", ">0")
Velocity = quantity("m/s", "velocity")
PositiveVelocity = quantity("m/s", "velocity", ">0")
Power = quantity("W", "power", ">0")
Density = quantity("kg/m^3", "density", ">0")
Pressure = quantity("Pa", "pressure", ">0")
Stress = quantity("Pa", "stress", ">0")
Volume = quantity("m^3", "volume", ">0")
VolumeFlow = quantity("m^3/s", "volume_flow", ">0")
Frequency = quantity("Hz", "frequency", ">=0")
Time = quantity("s", "time", ">0")
Area = quantity("m^2", "area", ">0")
SectionModulus = quantity("m^3", "section_modulus", ">0")
PressureVelocity = quantity("Pa*m/s", "pressure_velocity", ">0")
RotaryDamping = quantity("N*m*s/rad", "rotary_damping", ">=0")
LinearDamping = quantity("N*s/m", "linear_damping", ">=0")
NonNegativeAngle = quantity("rad", "angle", ">=0")
PositiveAngularVelocity = quantity("rad/s", "angular_velocity", ">0")
TwistRate = quantity("rad/m", "twist_rate", ">0")
NonNegativeForce = quantity("N", "force", ">=0")
PositiveTorque = quantity("N*m", "torque", ">0")
SpecificHeat = quantity("J/(kg*K)", "specific_heat", ">0")
HeatTransfer = quantity("W/K", "heat_transfer", ">=0")
TemperatureDifference = quantity("K", "temperature_difference", ">0")
Resistance = quantity("ohm", "resistance", ">0")
Voltage = quantity("V", "voltage", ">0")
PositiveFrequency = quantity("Hz", "frequency", ">0")
TorsionalStiffness = quantity("N*m/rad", "torsional_stiffness", ">0")

Point = tuple[Length, Length]  # type: ignore[valid-type]  # Length is an Annotated alias built at import


def written_unit(value: Any, unit: str) -> str | None:
    """The unit a quantity was written in (``"20 g"`` -> ``"g"``) when it is a plain unit of the same dimension as
    ``unit`` (SI), else None: the unit a user reads results in, where the summary shows values they gave."""
    parts = str(value).strip().split(maxsplit=1) if isinstance(value, str) else []
    if len(parts) != 2:
        return None
    try:
        Q_(1.0, unit).to(unit_of_text(parts[1]))
    except Exception:  # noqa: BLE001 - not a plain unit of this dimension: no display unit from it
        return None
    return parts[1].strip()
