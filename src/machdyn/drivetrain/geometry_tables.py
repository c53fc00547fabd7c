"""The ``geometry`` tables of ``[drivetrain.clutch]`` and ``[drivetrain.brake]``: a clutch or a brake described by its
friction faces, lever and drum instead of a typed torque, and the brake's heating.

```toml
[drivetrain.clutch.geometry]       # instead of slip_torque
kind = "plate"                     # "plate", "cone" or "centrifugal"
friction = 0.3
force = "4 kN"                     # axial spring force (or max_pressure = "0.3 MPa")
inner_radius = "80 mm"
outer_radius = "125 mm"
surfaces = 2                       # pairs of faces in contact
law = "uniform_wear"               # or "uniform_pressure"

[drivetrain.brake.geometry]        # instead of torque
kind = "block"                     # "block", "double_block", "band", "differential_band", "internal_shoe", "disc"
friction = 0.35
force = "400 N"                    # at the lever's end
drum_radius = "200 mm"
lever = "800 mm"
block = "250 mm"
offset = "30 mm"

[drivetrain.brake.heating]
mass = "25 kg"                     # the drum or disc
specific_heat = "500 J/(kg*K)"
cooling = "30 W/K"                 # lumped h*A
stops_per_hour = 60
max_temperature_rise = "150 K"
```
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Literal

from pydantic import Field, field_validator, model_validator

from ..errors import InputError
from ..problem.fields import (
    Angle,
    HeatTransfer,
    Length,
    NonNegativeForce,
    NonNegativeLength,
    PositiveLength,
    PositiveMass,
    Pressure,
    SpecificHeat,
    TemperatureDifference,
)
from ..problem.schema import Spec
from . import brakes, clutches


class ClutchGeometry(Spec):
    """``[drivetrain.clutch.geometry]``: the clutch's slip torque from its faces or shoes."""

    kind: Literal["plate", "cone", "centrifugal"]
    friction: float = Field(gt=0.0, le=2.0, allow_inf_nan=False)
    law: Literal["uniform_wear", "uniform_pressure"] = "uniform_wear"
    force: NonNegativeForce | None = None
    max_pressure: Pressure | None = None
    inner_radius: NonNegativeLength | None = None
    outer_radius: PositiveLength | None = None
    surfaces: int = Field(2, ge=1)
    cone_angle: Angle | None = None          # semi-cone angle alpha
    shoes: int = Field(4, ge=1)
    shoe_mass: PositiveMass | None = None
    shoe_radius: PositiveLength | None = None
    drum_radius: PositiveLength | None = None
    spring_force: NonNegativeForce = 0.0

    @model_validator(mode="after")
    def _complete(self):
        needs = {"plate": ("inner_radius", "outer_radius"), "cone": ("inner_radius", "outer_radius", "cone_angle"),
                 "centrifugal": ("shoe_mass", "shoe_radius", "drum_radius")}[self.kind]
        missing = [name for name in needs if getattr(self, name) is None]
        if missing:
            raise ValueError(f"a {self.kind} clutch needs {', '.join(missing)}")
        ri, ro, alpha = self.inner_radius or 0.0, self.outer_radius or 0.0, self.cone_angle or 0.0
        if self.kind != "centrifugal":
            if (self.force is None) == (self.max_pressure is None):
                raise ValueError(f"a {self.kind} clutch needs either force or max_pressure, not both nor neither")
            if not ri < ro:
                raise ValueError(f"inner_radius {ri:g} m must be smaller than outer_radius {ro:g} m")
            if self.max_pressure is not None and self.law == "uniform_wear" and not ri > 0:
                raise ValueError("uniform wear with max_pressure needs inner_radius > 0")
        if self.kind == "cone" and not 0.0 < alpha <= 0.5 * math.pi:
            raise ValueError(f"cone_angle (the semi-cone angle) must be > 0 and <= 90 deg; got "
                             f"{math.degrees(alpha):g} deg")
        if self.kind == "centrifugal" and (self.drum_radius or 0.0) < (self.shoe_radius or 0.0):
            raise ValueError(f"drum_radius {self.drum_radius:g} m must be at least shoe_radius "
                             f"{self.shoe_radius:g} m")
        return self


@dataclass(frozen=True)
class ClutchRating:
    """A clutch's slip torque from its geometry [N·m], the axial force [N], the largest face pressure [Pa]
    (plate and cone), and a centrifugal clutch's engagement speed [rad/s] (0.0 where not defined)."""

    torque: float
    force: float = 0.0
    max_pressure: float = 0.0
    engagement_speed: float = 0.0


def rate_clutch(geometry: ClutchGeometry, speed: float) -> ClutchRating:
    """The slip torque of ``geometry`` with its shoe side turning at ``speed`` [rad/s] (centrifugal clutches)."""
    g = geometry
    if g.kind == "centrifugal":
        assert g.shoe_mass is not None and g.shoe_radius is not None and g.drum_radius is not None
        c = clutches.centrifugal_clutch(g.friction, g.shoes, g.shoe_mass, g.shoe_radius, g.drum_radius,
                                        g.spring_force, speed)
        return ClutchRating(c.torque, engagement_speed=c.engagement_speed)
    assert g.inner_radius is not None and g.outer_radius is not None
    if g.force is not None:
        force = g.force
    else:
        assert g.max_pressure is not None
        force = clutches.axial_force(g.max_pressure, g.inner_radius, g.outer_radius, g.law)
    pressure = clutches.max_pressure(force, g.inner_radius, g.outer_radius, g.law) if force > 0 else 0.0
    if g.kind == "cone":
        assert g.cone_angle is not None
        torque = clutches.cone_clutch_torque(g.friction, force, g.inner_radius, g.outer_radius, g.cone_angle, g.law)
    else:
        torque = clutches.plate_clutch_torque(g.friction, force, g.inner_radius, g.outer_radius, g.surfaces, g.law)
    return ClutchRating(torque, force, pressure)


BRAKE_NEEDS = {
    "block": ("force", "drum_radius", "lever", "block"),
    "double_block": ("force", "drum_radius", "lever", "block"),
    "band": ("force", "drum_radius", "lever", "arm", "wrap_angle"),
    "differential_band": ("force", "drum_radius", "lever", "slack_arm", "tight_arm", "wrap_angle"),
    "internal_shoe": ("drum_radius", "width", "shoe_start", "shoe_end", "hinge", "force_arm"),
    "disc": ("force", "inner_radius", "outer_radius"),
}


class BrakeGeometry(Spec):
    """``[drivetrain.brake.geometry]``: the braking torque from the lever, drum, band or pads."""

    kind: Literal["block", "double_block", "band", "differential_band", "internal_shoe", "disc"]
    friction: float = Field(gt=0.0, le=2.0, allow_inf_nan=False)
    force: NonNegativeForce | None = None     # at the lever (block, band), on each shoe or pad
    max_pressure: Pressure | None = None      # internal shoe: instead of force
    drum_radius: PositiveLength | None = None
    lever: PositiveLength | None = None
    block: PositiveLength | None = None
    offset: Length = 0.0
    contact_angle: Angle = 0.0
    arm: PositiveLength | None = None
    lever_on: Literal["slack", "tight"] = "slack"
    slack_arm: PositiveLength | None = None
    tight_arm: NonNegativeLength | None = None
    wrap_angle: Angle | None = None
    blocks: int = Field(0, ge=0)
    block_angle: Angle = 0.0
    width: PositiveLength | None = None
    shoe_start: Angle | None = None
    shoe_end: Angle | None = None
    hinge: PositiveLength | None = None
    force_arm: PositiveLength | None = None
    shoes: Literal[1, 2] = 2
    inner_radius: NonNegativeLength | None = None
    outer_radius: PositiveLength | None = None
    faces: int = Field(2, ge=1)
    law: Literal["uniform_wear", "uniform_pressure"] = "uniform_wear"
    max_allowed_pressure: Pressure | None = None  # internal shoe: the lining's limit p_a (a check)

    @model_validator(mode="after")
    def _complete(self):
        needs = BRAKE_NEEDS[self.kind]
        if self.kind == "internal_shoe" and (self.force is None) == (self.max_pressure is None):
            raise ValueError("an internal_shoe brake needs either force or max_pressure, not both nor neither")
        # a band-and-block brake's tension ratio comes from its blocks: its band's wrap is not needed
        missing = [name for name in needs if getattr(self, name) is None
                   and not (name == "wrap_angle" and self.blocks)]
        if missing:
            raise ValueError(f"a {self.kind} brake needs {', '.join(missing)}")
        ri, ro = self.inner_radius or 0.0, self.outer_radius or 0.0
        if self.kind == "disc" and not ri < ro:
            raise ValueError(f"inner_radius {ri:g} m must be smaller than outer_radius {ro:g} m")
        return self


def rate_brake(geometry: BrakeGeometry) -> brakes.BrakeTorque:
    """The braking torque of ``geometry`` (an :class:`InputError` for a brake that locks itself)."""
    g: Any = geometry
    if g.kind in ("block", "double_block"):
        rate = brakes.block_brake if g.kind == "block" else brakes.double_block_brake
        return rate(g.friction, g.force, g.drum_radius, g.lever, g.block, g.offset, g.contact_angle)
    wrap = g.wrap_angle if g.wrap_angle is not None else 0.0  # None only with blocks, which set the ratio
    if g.kind == "band":
        return brakes.band_brake(g.friction, g.force, g.drum_radius, g.lever, g.arm, wrap,
                                 lever_on=g.lever_on, blocks=g.blocks, block_angle=g.block_angle)
    if g.kind == "differential_band":
        return brakes.differential_band_brake(g.friction, g.force, g.drum_radius, g.lever, g.slack_arm,
                                              g.tight_arm, wrap, blocks=g.blocks, block_angle=g.block_angle)
    if g.kind == "internal_shoe":
        moments = brakes.shoe_moments(g.friction, g.drum_radius, g.width, g.shoe_start, g.shoe_end, g.hinge)
        force = g.force if g.force is not None else g.max_pressure * (moments.normal - moments.friction) / g.force_arm
        return brakes.internal_shoe_brake(g.friction, max(force, 0.0), g.drum_radius, g.width, g.shoe_start,
                                          g.shoe_end, g.hinge, g.force_arm, g.shoes)
    return brakes.disc_brake(g.friction, g.force, g.inner_radius, g.outer_radius, g.faces, g.law)


class BrakeHeating(Spec):
    """``[drivetrain.brake.heating]``: the drum or disc that takes a stop's energy and how fast it cools."""

    mass: PositiveMass
    specific_heat: SpecificHeat
    cooling: HeatTransfer = 0.0
    stops_per_hour: float | None = Field(None, gt=0.0, allow_inf_nan=False)
    max_temperature_rise: TemperatureDifference | None = None

    @field_validator("max_temperature_rise", mode="before")
    @classmethod
    def _a_difference(cls, value: Any) -> Any:
        """A rise written in °C or °F would be read as an absolute temperature (20 degC = 293 K)."""
        text = value.lower() if isinstance(value, str) else ""
        if ("degc" in text or "degf" in text) and "delta" not in text:
            raise ValueError(f"is a temperature difference: write it in K or delta_degC, not {value!r} (pint "
                             "reads degC as an absolute temperature)")
        return value

    @model_validator(mode="after")
    def _cools(self):
        if self.stops_per_hour is not None and not self.cooling > 0:
            raise ValueError("repeated stops (stops_per_hour) need cooling > 0 W/K: without it the brake heats "
                             "without bound")
        return self


def heating_of(table: BrakeHeating, energy: float) -> brakes.Heating:
    """The drum's heating by ``energy`` [J] a stop at the table's stop rate."""
    interval = 3600.0 / table.stops_per_hour if table.stops_per_hour is not None else math.inf
    return brakes.temperature_rise(energy, table.mass, table.specific_heat, cooling=table.cooling,
                                   interval=interval)


def problem_of(path: str, exc: InputError) -> tuple[str, str]:
    """A problem-file problem (path, message) from an error of the formulas."""
    return path, str(exc)
