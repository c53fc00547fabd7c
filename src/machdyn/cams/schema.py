"""The ``[cam]`` problem file: its tables as pydantic models (every quantity an SI float).

```toml
[meta]
name = "Feeder cam"
[cam]
speed = "120 rpm"
base_radius = "40 mm"
[cam.follower]
motion = "translating"        # or "oscillating" (pivot_distance, arm_length)
contact = "roller"            # "knife", "roller" or "flat"
roller_radius = "12 mm"
[[cam.segments]]
motion = "rise"               # "rise", "dwell" or "return"
angle = "100 deg"
lift = "30 mm"                # an oscillating follower's swing: swing = "15 deg"
law = "cycloidal"
[cam.dynamics]                # optional: follower train, spring sizing, contact force and torque
mass = "1.8 kg"
[cam.spring]
preload = "40 N"              # or rate = "2 N/mm"; the other is sized for speed x (1 + margin)
margin = 0.25
```
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from ..problem.fields import (
    Angle,
    AngularVelocity,
    Force,
    Inertia,
    Length,
    LinearDamping,
    NonNegativeLength,
    Point,
    PositiveLength,
    PositiveMass,
    Stiffness,
)
from ..problem.schema import (
    BodySpec,
    CounterweightSpec,
    DyadSpec,
    ForceSpec,
    Gravity,
    Meta,
    Name,
    Spec,
    TorqueSpec,
)
from ..problem.schema import (
    SpringSpec as LinkageSpringSpec,
)


class FollowerSpec(Spec):
    """``[cam.follower]``."""

    motion: Literal["translating", "oscillating"] = "translating"
    contact: Literal["knife", "roller", "flat"] = "roller"
    roller_radius: NonNegativeLength = 0.0
    offset: Length = 0.0
    pivot_distance: NonNegativeLength = 0.0
    arm_length: NonNegativeLength = 0.0


class SegmentSpec(Spec):
    """``[[cam.segments]]``: a rise, dwell or return over ``angle`` of the cam."""

    motion: Literal["rise", "dwell", "return"]
    angle: Angle
    lift: NonNegativeLength | None = None
    swing: Angle | None = None
    law: Literal["uniform", "parabolic", "harmonic", "cycloidal", "poly345", "poly4567", "modified_trapezoid",
                 "modified_sine", "table", "circular_arc", "tangent"] = "cycloidal"
    start: Angle | None = None
    # the "table" law: interior points [fraction of the angle, fraction of the lift] (cams/table_law.py)
    points: list[tuple[float, float]] = []
    # contour laws (cams/geometric.py): the nose radius, and the circular arc's flank radius
    nose_radius: PositiveLength | None = None
    flank_radius: PositiveLength | None = None


class ChecksSpec(Spec):
    """``[cam.checks]``: the pressure-angle limit (default 30 deg translating, 35 deg oscillating), the required
    smallest convex radius of curvature of the pitch curve / roller radius, and a flat face's width and margin."""

    pressure_angle_limit: Angle | None = None
    curvature_factor: float = Field(1.0, ge=1.0, allow_inf_nan=False)
    face_width: PositiveLength | None = None
    face_margin: NonNegativeLength = 0.0


class DynamicsSpec(Spec):
    """``[cam.dynamics]``: the follower train, lumped at the roller (an oscillating follower's arm turns it into
    a moment of inertia m l^2 about the pivot)."""

    mass: PositiveMass
    damping: LinearDamping = 0.0
    load: Force = 0.0
    cam_inertia: Inertia = 0.0
    # the forward simulation of the follower on the cam (seconds; the closed-form jump check stays without it)
    simulate: bool = Field(True, strict=True)


class SpringSpec(Spec):
    """``[cam.spring]``: give the preload (the rate is sized), the rate (the preload is sized) or both (checked);
    sized to keep contact up to speed x (1 + margin)."""

    rate: Stiffness | None = None
    preload: Force | None = None
    margin: float = Field(0.25, ge=0.0, le=10.0, allow_inf_nan=False)


class OutputSpec(Spec):
    """``[cam.output]``: the cutter's or grinder's radius (default the roller's) and whether to write the DXF."""

    cutter_radius: NonNegativeLength | None = None
    dxf: bool = Field(True, strict=True)


class CamBody(Spec):
    """The cam and its follower, without its speed (``[shaft_cam]`` of a linkage file takes the crank's)."""

    base_radius: Length
    rotation: Literal["ccw", "cw"] = "ccw"
    positions: int = Field(720, ge=16, le=100_000, strict=True)
    follower: FollowerSpec = FollowerSpec()
    segments: list[SegmentSpec] = Field(min_length=2)
    checks: ChecksSpec = ChecksSpec()
    dynamics: DynamicsSpec | None = None
    spring: SpringSpec = SpringSpec()
    output: OutputSpec = OutputSpec()


class CamSpec(CamBody):
    """``[cam]``: the cam, its follower and its constant speed."""

    speed: AngularVelocity

    @model_validator(mode="after")
    def _speed(self):
        if not self.speed > 0:
            raise ValueError(f"speed must be > 0 (the cam turns at a constant speed); got {self.speed:g} rad/s")
        return self


class ShaftCamTable(CamBody):
    """``[shaft_cam]`` of a linkage file: a cam on the crank shaft, turning with the crank at ``phase`` ahead
    (cam angle = crank angle + phase); ``[cam.dynamics]`` is required there (the cam loads the shaft)."""

    phase: Angle = 0.0


class FollowerLinkageLoads(Spec):
    """``[follower_linkage.loads]``: the loads on the linkage, as a linkage file's ``[loads]`` (gravity, point
    forces, torques on bodies, springs); an ``active`` window is a range of the cam angle."""

    gravity: Gravity = "on"
    forces: list[ForceSpec] = []
    torques: list[TorqueSpec] = []
    springs: list[LinkageSpringSpec] = []


class FollowerLinkageTable(Spec):
    """``[follower_linkage]``: a linkage driven by the cam's follower, written as the dyad chain of a linkage
    file's custom ``[mechanism]`` (bodies, dyads, ground points, loads, counterweights).

    The follower is the body ``follower``: an oscillating follower's arm, with the points ``pivot`` (on the ground
    point ``ground.pivot``) and ``roller`` (the roller centre) in its frame with x from the pivot to the roller; a
    translating follower's slide, with the point ``roller`` (its pitch point) at the origin of its frame, x along
    its path away from the cam. ``follower_points`` adds points to it. Ground points are in the cam's frame (cam
    centre at the origin, mirrored for a clockwise cam). The follower carries no mass here: its inertia is
    ``[cam.dynamics] mass``. ``output``: the body whose travel is reported (default: the last dyad's second)."""

    name: Name | None = None
    ground: dict[Name, Point] = {}
    follower_points: dict[Name, Point] = {}
    bodies: list[BodySpec] = Field(min_length=1, max_length=130)
    dyads: list[Annotated[DyadSpec, Field(discriminator="type")]] = Field(min_length=1, max_length=64)
    loads: FollowerLinkageLoads = FollowerLinkageLoads()
    counterweights: list[CounterweightSpec] = []
    output: Name | None = None


class CamProblem(Spec):
    """A cam problem file: ``[meta]`` and ``[cam]``; the capability tables (``[flywheel]``) are added to it by
    :func:`machdyn.kinds.problem_model`."""

    meta: Meta = Meta()
    cam: CamSpec
