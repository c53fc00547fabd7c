"""The ``[shaft_line]`` problem file: masses, cylinders and bearings on one shaft, with its balancing tables.

Tables: ``[shaft_line]`` (speed, angles, harmonics, the reference plane of the couples), ``[[masses]]``,
``[[cylinders]]``, ``[[bearings]]``, ``[balance]`` (correction planes: one for static, two for dynamic balance),
``[grade]`` (ISO 21940-11 check), ``[locomotive]`` (partial balance of the reciprocating masses in the wheel
planes) and ``[field_balancing]`` (influence coefficients from hand-entered readings). Every quantity carries
its unit; unknown keys are refused.
"""

from __future__ import annotations

from typing import Annotated, Any

from pydantic import Field, PrivateAttr, model_validator

from ..problem.fields import (
    Acceleration,
    Angle,
    AngularVelocity,
    Force,
    Inertia,
    Length,
    LinearDamping,
    Mass,
    NonNegativeLength,
    PositiveLength,
    PositiveMass,
    PositiveStiffness,
    Stiffness,
    written_unit,
)
from ..problem.schema import CounterweightSpec, MechanismSpec, Meta, Name, Spec


class ShaftLineSpec(Spec):
    """The shaft: ``speed`` (service speed), angles per turn, harmonic orders reported and the axial position of
    the plane about which couples are taken."""

    speed: AngularVelocity
    positions: int = Field(360, ge=16, le=100_000, strict=True)
    harmonics: int = Field(6, ge=1, le=40, strict=True)
    reference: Length = 0.0


class MassSpec(Spec):
    name: Name
    mass: Mass
    radius: NonNegativeLength
    angle: Angle
    position: Length


class CylinderSpec(Spec):
    name: Name
    position: Length
    phase: Angle = 0.0
    axis: Angle = 0.0
    crank: PositiveLength
    rod: PositiveLength
    reciprocating_mass: Mass
    rotating_mass: Mass = 0.0


class LinkageSpec(Spec):
    """A planar linkage of machdyn (the ``[mechanism]`` of a linkage file, any type) at an axial ``position``,
    its crank at ``phase`` for shaft angle 0, its x axis turned by ``axis`` about the shaft; its crank pivot must
    be its origin (on the shaft). ``counterweights`` as in a linkage file."""

    name: Name
    position: Length
    phase: Angle = 0.0
    axis: Angle = 0.0
    mechanism: Annotated[MechanismSpec, Field(discriminator="type")]
    counterweights: list[CounterweightSpec] = []


class BearingSpec(Spec):
    name: Name
    position: Length
    stiffness: PositiveStiffness = 1.0e8


class PlaneSpec(Spec):
    name: Name
    position: Length
    radius: PositiveLength
    holes: int = Field(0, ge=0, le=360, strict=True)  # equally spaced fixed positions (0: free angle)
    first_hole: Angle = 0.0


class BalanceSpec(Spec):
    """Correction planes: one (static balance) or two (dynamic balance)."""

    planes: list[PlaneSpec] = Field(min_length=1, max_length=2)
    resolution: PositiveMass | None = None  # the correction masses as fitted: rounded to multiples of this
    # share c of each cylinder's reciprocating mass balanced as if it revolved at its crank pin (1/2: the
    # direct-crank half of every primary force, all of it for a 90 deg V-twin or a radial engine)
    reciprocating_fraction: float = Field(0.0, ge=0.0, le=1.0)
    # "rotating": the rotating masses (and the share above); "first_harmonic": the forward-turning first harmonic
    # of everything on the shaft, linkages included -- all a counterweight turning with the shaft can cancel
    target: str = Field("rotating", pattern="^(rotating|first_harmonic)$")


class GradeSpec(Spec):
    """ISO 21940-11 check: grade G [mm/s] (a plain number, e.g. 6.3), the rotor's mass, the position of its
    centre of mass (default midway between the bearings) and which state is checked."""

    G: float
    rotor_mass: PositiveMass
    centre: Length | None = None
    bearings: tuple[Name, Name] | None = None
    state: str = Field("balanced", pattern="^(balanced|as_given)$")


class LocomotiveSpec(Spec):
    wheel_planes: tuple[Length, Length]
    radius: PositiveLength
    fraction: float = Field(ge=0.0, le=1.0)
    dead_load: Force | None = None


class ReadingSpec(Spec):
    amplitude: float = Field(ge=0.0)
    phase: Angle | None = None


class TrialSpec(Spec):
    plane: int = Field(ge=1, le=2, strict=True)
    mass: PositiveMass
    angle: Angle
    readings: list[ReadingSpec] = Field(min_length=1, max_length=2)
    removed: bool = True


class FieldPlaneSpec(Spec):
    name: Name
    holes: int = Field(0, ge=0, le=360, strict=True)
    first_hole: Angle = 0.0


class FieldSpec(Spec):
    """Hand-entered 1x readings (amplitude in ``unit``, phase from the reference mark in the sense of the
    instrument), the original run and one trial run per plane."""

    unit: str = "mm/s"
    radius: PositiveLength | None = None
    planes: list[FieldPlaneSpec] = Field(min_length=1, max_length=2)
    original: list[ReadingSpec] = Field(min_length=1, max_length=2)
    trials: list[TrialSpec] = Field(min_length=1, max_length=2)


class MountSpec(Spec):
    name: Name
    position: tuple[Length, Length, Length]
    direction: tuple[float, float, float]
    stiffness: Stiffness
    damping: LinearDamping = 0.0


class PointSpec(Spec):
    name: Name
    position: tuple[Length, Length, Length]


class FrameSpec(Spec):
    """The frame in space on its mounts: mass, principal inertias about x, y, z through the centre of mass,
    the centre of mass, where the shaft's axis passes (x, y), the orders of the response, mounts and points, and
    ``gravity`` (a vector in frame axes) for the weight's pendulum term in the rocking stiffness."""

    mass: PositiveMass
    inertia: tuple[Inertia, Inertia, Inertia]
    com: tuple[Length, Length, Length] = (0.0, 0.0, 0.0)
    shaft: tuple[Length, Length] = (0.0, 0.0)
    orders: int = Field(4, ge=1, le=40, strict=True)
    mounts: list[MountSpec] = Field(min_length=1)
    points: list[PointSpec] = []
    # the acceleration of gravity in frame axes (which way is down is the file's to say): adds the weight's
    # pendulum term to the rotations' stiffness; omitted, it is left out
    gravity: tuple[Acceleration, Acceleration, Acceleration] | None = None


class PhaseSearchSpec(Spec):
    """Crank phases of the named cylinders searched on a grid of ``step`` to minimise ``objective`` (the largest
    two-term primary_force, secondary_force, primary_couple, secondary_couple, or all four relative to their
    largest)."""

    cylinders: list[Name] = Field(min_length=1, max_length=6)
    step: Angle = 0.2617993877991494  # 15 deg
    objective: str = Field("all", pattern="^(primary_force|secondary_force|primary_couple|secondary_couple|all)$")


class ShaftLineProblem(Spec):
    """A shaft-line problem."""

    meta: Meta = Meta(name="shaft line")
    shaft_line: ShaftLineSpec
    masses: list[MassSpec] = []
    cylinders: list[CylinderSpec] = []
    linkages: list[LinkageSpec] = []
    bearings: list[BearingSpec] = []
    balance: BalanceSpec | None = None
    grade: GradeSpec | None = None
    locomotive: LocomotiveSpec | None = None
    field_balancing: FieldSpec | None = None
    frame: FrameSpec | None = None
    phase_search: PhaseSearchSpec | None = None
    _mass_unit: str = PrivateAttr("kg")

    @model_validator(mode="wrap")
    @classmethod
    def _keep_mass_unit(cls, data: Any, handler: Any) -> Any:
        """Keep the unit the file writes masses in (the rounding ``resolution`` first, then the masses, then the
        trial masses): the summary and report show the corrections in it."""
        model = handler(data)
        if isinstance(data, dict):
            model._mass_unit = mass_unit_written(data)
        elif isinstance(data, ShaftLineProblem):
            model._mass_unit = data._mass_unit
        return model

    @property
    def mass_unit(self) -> str:
        """The unit the file writes masses in (kg when it writes none)."""
        return self._mass_unit


def mass_unit_written(data: dict) -> str:
    """The unit of the first mass written in a shaft-line file's data (see :class:`ShaftLineProblem`)."""
    def table(name: str) -> dict:
        value = data.get(name)
        return value if isinstance(value, dict) else {}

    def rows(value: Any) -> list:
        return [r for r in value if isinstance(r, dict)] if isinstance(value, list) else []

    texts = [table("balance").get("resolution"), *(r.get("mass") for r in rows(data.get("masses"))),
             *(r.get("mass") for r in rows(table("field_balancing").get("trials"))),
             *(r.get("mass") for r in rows(table("field_records").get("trials")))]
    for text in texts:
        unit = written_unit(text, "kg")
        if unit is not None:
            return unit
    return "kg"
