"""The validated content of a linkage problem file (pydantic models; every quantity an SI float).

The models mirror the TOML tables one to one (``[mechanism.crank]`` is ``LinkSpec``); unknown keys are
refused (``extra="forbid"``). :mod:`machdyn.problem.build` turns them into the engine's frozen
:class:`~machdyn.linkage.model.Mechanism`.
"""

from __future__ import annotations

import dataclasses
import inspect
from typing import TYPE_CHECKING, Annotated, Any, Literal, Union

from pydantic import BaseModel, BeforeValidator, ConfigDict, Field, create_model, field_validator

from ..linkage.dyad_types import DYAD_TYPES
from ..linkage.standard import STANDARD_MECHANISMS, Part, StandardMechanism
from .fields import (
    Acceleration,
    Angle,
    AngularAcceleration,
    AngularVelocity,
    FieldError,
    Force,
    Inertia,
    Length,
    LinearDensity,
    Mass,
    NonNegativeLength,
    Point,
    PositiveLength,
    Stiffness,
    Torque,
)

#: Bidirectional overrides and isolates: they make a text read differently from what it holds.
_BIDI = frozenset("\u202a\u202b\u202c\u202d\u202e\u2066\u2067\u2068\u2069")


class Spec(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)

    @field_validator("*", mode="after")
    @classmethod
    def _plain_text(cls, value: Any) -> Any:
        """Text of a problem file is plain: no control character (a NUL, an escape; tabs and line breaks are
        fine) and no bidirectional override, which labels, names and file names would carry into the outputs."""
        if isinstance(value, str):
            for ch in value:
                if (ch < " " and ch not in "\t\n\r") or "\x7f" <= ch <= "\x9f" or ch in _BIDI:
                    raise FieldError(f"must be plain text; it contains the control character U+{ord(ch):04X}")
        return value


def _branch(value: Any) -> int:
    names = {"open": 1, "crossed": -1, "+1": 1, "-1": -1}
    if isinstance(value, str) and value.strip().lower() in names:
        return names[value.strip().lower()]
    if isinstance(value, int) and not isinstance(value, bool) and value in (1, -1):
        return value
    raise FieldError(f"must be \"open\" (+1) or \"crossed\" (-1); got {value!r}")


Branch = Annotated[int, BeforeValidator(_branch)]


def _reference(value: Any) -> str:
    if not isinstance(value, str) or value.count(".") != 1 or not all(value.split(".")):
        raise FieldError(f"must name a point as 'body.point' (e.g. 'ground.O', 'coupler.P'); got {value!r}")
    return value


PointRef = Annotated[str, BeforeValidator(_reference)]
Name = Annotated[str, Field(min_length=1, pattern=r"^[A-Za-z_][A-Za-z0-9_]*$")]


class Meta(Spec):
    name: str = "problem"
    description: str = ""


# ------------------------------------------------------------------------------------------------ links


class LinkSpec(Spec):
    """A bar between two joints: length; mass, centroidal inertia and centre of mass (body frame).

    Left out, the mass is that of a uniform bar of the mechanism's ``linear_density``, the inertia m L^2/12
    and the centre of mass mid-length (the builders' defaults)."""

    length: PositiveLength
    mass: Mass | None = None
    inertia: Inertia | None = None
    com: Point | None = None


class OptionalLinkSpec(LinkSpec):
    length: PositiveLength | None = None


class BlockSpec(Spec):
    """A slider or block: mass and centroidal inertia (its centre of mass is at its joint unless given)."""

    mass: Mass | None = None
    inertia: Inertia | None = None
    com: Point | None = None


class GroundSpec(Spec):
    """The fixed link between the two ground pivots: length and direction from the crank pivot."""

    length: PositiveLength
    angle: Angle = 0.0


class GroundLengthSpec(Spec):
    """The fixed link of mechanisms whose ground pivots lie on the x axis: its length only."""

    length: PositiveLength


class DoubleCrankSpec(Spec):
    """The one crank body of a double slider-crank: two pins at radii ``length_1`` (angle 0) and
    ``length_2`` (angle ``phase``)."""

    length_1: PositiveLength
    length_2: PositiveLength
    phase: Angle = STANDARD_MECHANISMS["double_slider_crank"].default("phase")
    mass: Mass | None = None
    inertia: Inertia | None = None
    com: Point | None = None


class _MechanismBase(Spec):
    name: Name | None = None
    linear_density: LinearDensity = 1.0
    #: The machine the mechanism is: "compactor" (a four-bar whose coupler is the compaction plate and whose
    #: coupler point is where it presses) adds the compactor's results (docs/results.md).
    machine: Literal["compactor"] | None = None


def _standard_spec(declaration: StandardMechanism) -> type[Spec]:
    """The table of a standard mechanism, made from its declaration (fields in order, the builder's
    defaults)."""
    fields: dict[str, Any] = {"type": (Literal[declaration.type], ...)}  # type: ignore[valid-type]
    for f in declaration.fields:
        if isinstance(f, Part):
            model, default = _PARTS[f.kind]
            fields[f.name] = (model, ... if default is None else default)
            continue
        value_type = _PARAMETERS[f.kind]
        default = declaration.default(f.name)
        if default is inspect.Parameter.empty:
            fields[f.name] = (value_type, ...)
        elif default is None:
            fields[f.name] = (value_type | None, None)
        else:
            fields[f.name] = (value_type, default)
    name = "".join(word.capitalize() for word in declaration.type.split("_")) + "Spec"
    return create_model(name, __base__=_MechanismBase, __module__=__name__, **fields)  # type: ignore[call-overload]


_PARTS: dict[str, tuple[type[Spec], Spec | None]] = {
    "link": (LinkSpec, None),
    "optional_link": (OptionalLinkSpec, OptionalLinkSpec()),
    "block": (BlockSpec, BlockSpec()),
    "ground": (GroundSpec, None),
    "ground_length": (GroundLengthSpec, None),
    "double_crank": (DoubleCrankSpec, None),
}
_PARAMETERS: dict[str, Any] = {"length": Length, "angle": Angle, "point": Point, "branch": Branch}

#: The table of each standard mechanism by its type.
STANDARD_SPECS: dict[str, type[Spec]] = {t: _standard_spec(m) for t, m in STANDARD_MECHANISMS.items()}
SliderCrankSpec = STANDARD_SPECS["slider_crank"]
FourBarSpec = STANDARD_SPECS["four_bar"]
InvertedSliderCrankSpec = STANDARD_SPECS["inverted_slider_crank"]
SixBarSpec = STANDARD_SPECS["six_bar"]
DoubleSliderCrankSpec = STANDARD_SPECS["double_slider_crank"]


# ----------------------------------------------------------------------------------------------- custom


class BodySpec(Spec):
    name: Name
    points: dict[Name, Point]
    mass: Mass = 0.0
    inertia: Inertia = 0.0
    com: Point = (0.0, 0.0)


class DriverSpec(Spec):
    body: Name
    pivot: PointRef


class GuideSpec(Spec):
    point: PointRef
    angle: Angle = 0.0


class SlideSpec(Spec):
    """The slide line of an RPR dyad: a point of the rocker (its name only) and a direction in its frame."""

    point: Name
    angle: Angle = 0.0


#: The problem-file type of each field of the dyad declarations (:mod:`machdyn.linkage.dyad_types`).
_DYAD_FIELDS: dict[str, Any] = {
    "a": Name, "b": Name, "inner": Name, "pin_a": PointRef, "pin_b": PointRef, "guide": GuideSpec,
    "guide_a": GuideSpec, "guide_b": GuideSpec, "slide": SlideSpec, "branch": Branch,
}


def _dyad_spec(declaration: type) -> type[Spec]:
    """The table of a dyad of a custom mechanism, with the fields of the dyad's declaration."""
    kind = getattr(declaration, "kind")  # noqa: B009  # a class attribute of every dyad declaration
    fields: dict[str, Any] = {"type": (Literal[kind], ...)}
    for f in dataclasses.fields(declaration):
        default = ... if f.default is dataclasses.MISSING else f.default
        fields[f.name] = (_DYAD_FIELDS[f.name], default)
    return create_model(f"{kind}Spec", __base__=Spec, __module__=__name__, **fields)  # type: ignore[call-overload]


DYAD_SPECS: dict[str, type[Spec]] = {kind: _dyad_spec(t) for kind, t in DYAD_TYPES.items()}
RRRSpec, RRPSpec, RPRSpec, PRPSpec = (DYAD_SPECS[k] for k in ("RRR", "RRP", "RPR", "PRP"))
if TYPE_CHECKING:  # made at import time from the declarations: any of the tables above
    DyadSpec = Any
else:
    DyadSpec = Union[tuple(DYAD_SPECS.values())]  # noqa: UP007


class CustomSpec(Spec):
    type: Literal["custom"]
    name: Name | None = None
    ground: dict[Name, Point]
    crank: DriverSpec
    # at most limits.MAX_DYADS = 64 dyads (a planar machine has a handful): more would take minutes to solve
    bodies: list[BodySpec] = Field(min_length=1, max_length=130)
    dyads: list[Annotated[DyadSpec, Field(discriminator="type")]] = Field([], max_length=64)


MECHANISM_SPECS: dict[str, type[Spec]] = {**STANDARD_SPECS, "custom": CustomSpec}
if TYPE_CHECKING:
    MechanismSpec = Any
else:
    MechanismSpec = Union[tuple(MECHANISM_SPECS.values())]  # noqa: UP007


# ---------------------------------------------------------------------------------------- drive, loads


class DriveSpec(Spec):
    """The crank's motion: speed, angular acceleration and the crank positions analysed.

    Without ``start``/``stop`` the positions divide one full revolution evenly (the last one short of
    360 deg, so harmonics apply); with them, ``positions`` values run from start to stop inclusive."""

    speed: AngularVelocity
    acceleration: AngularAcceleration = 0.0
    positions: int = Field(360, ge=8, le=1_000_000, strict=True)  # fewer cannot show a cycle's extremes
    start: Angle | None = None
    stop: Angle | None = None

    @field_validator("speed")
    @classmethod
    def _moving(cls, speed):
        # Energy rates, reduced quantities and the work balance divide by the crank speed.
        if speed == 0.0:
            raise FieldError("must not be zero (the analysis divides by the crank speed); got 0 rad/s")
        if speed * speed == 0.0:  # e.g. 1e-300 rad/s: the reduced inertia divides by the speed squared
            raise FieldError(f"must be at least 1e-150 rad/s in magnitude (its square must not underflow); got "
                             f"{speed:g} rad/s")
        return speed

    @field_validator("stop")
    @classmethod
    def _stop_after_start(cls, stop, info):
        start = info.data.get("start")
        if stop is not None and start is not None and not stop > start:
            raise FieldError(f"must be greater than start ({start:g} rad); got {stop:g} rad")
        return stop


class ForceSpec(Spec):
    name: Name | None = None
    point: PointRef
    fx: Force = 0.0
    fy: Force = 0.0
    active: tuple[Angle, Angle] | None = None


class StrokeForceSpec(Spec):
    """A force-stroke table: the resistance ``force`` met at ``distance`` before the end of the working stroke
    of the slider carrying ``point`` (see :mod:`machdyn.linkage.stroke_loads`)."""

    name: Name | None = None
    point: PointRef
    distance: list[NonNegativeLength]
    force: list[Force]
    end: Literal["outer", "inner"] = "outer"


class TorqueSpec(Spec):
    name: Name | None = None
    body: Name
    torque: Torque
    active: tuple[Angle, Angle] | None = None


class SpringSpec(Spec):
    name: Name | None = None
    point_1: PointRef
    point_2: PointRef
    stiffness: Stiffness
    free_length: NonNegativeLength = 0.0


def _gravity(value: Any) -> Any:
    if isinstance(value, str):
        word = value.strip().lower()
        if word in ("on", "off"):
            return word
        raise FieldError(f'must be "on", "off" or a vector ["0 m/s^2", "-9.81 m/s^2"]; got {value!r}')
    if not isinstance(value, list | tuple):
        raise FieldError(f'must be "on", "off" or a vector ["0 m/s^2", "-9.81 m/s^2"]; got {value!r}')
    return value


Gravity = Annotated[Literal["on", "off"] | tuple[Acceleration, Acceleration], BeforeValidator(_gravity)]


class LoadsSpec(Spec):
    gravity: Gravity = "on"
    forces: list[ForceSpec] = []
    stroke_forces: list[StrokeForceSpec] = []
    torques: list[TorqueSpec] = []
    springs: list[SpringSpec] = []


class CounterweightSpec(Spec):
    """A point mass on a body at ``radius`` and ``angle`` in the body frame (angle 0 = towards the body's
    second joint, e.g. the crank pin; 180 deg = opposite it)."""

    name: Name | None = None
    body: Name
    mass: Mass
    radius: NonNegativeLength
    angle: Angle
    inertia: Inertia = 0.0


class OutputSpec(Spec):
    shaking_moment_about: Point = (0.0, 0.0)
    harmonics: int = Field(6, ge=1, le=100, strict=True)


class LinkageProblem(Spec):
    """A generic linkage problem: ``[meta]``, ``[mechanism]``, ``[drive]``, ``[loads]``,
    ``[[counterweights]]`` and ``[output]``; the capability tables (``[sweep]`` ...) are added to it by
    :func:`machdyn.kinds.problem_model`."""

    meta: Meta = Meta()
    mechanism: Annotated[MechanismSpec, Field(discriminator="type")]
    drive: DriveSpec
    loads: LoadsSpec = LoadsSpec()
    counterweights: list[CounterweightSpec] = []
    output: OutputSpec = OutputSpec()
