"""Problem-file tables of the vibration capability: ``[frame]`` (the frame on its mounts, points to watch, a
variant to compare with) and ``[signals]`` (measured records to judge).

Every quantity carries its unit (``"1.5 MN/m"``, ``"3 kN*s/m"``, ``"1800 kg"``); unknown keys are refused.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, field_validator, model_validator

from ..problem.fields import (
    Angle,
    AngularVelocity,
    FieldError,
    Frequency,
    Inertia,
    Length,
    Mass,
    Point,
    PositiveInertia,
    PositiveLength,
    PositiveMass,
    PositiveStiffness,
    Stiffness,
)
from ..problem.fields import LinearDamping as Damping
from ..problem.fields import PositiveVelocity as Velocity
from ..problem.schema import CounterweightSpec, Gravity, Name, Spec, SpringSpec

MachineClass = Literal["I", "II", "III", "IV"]
Standard = Literal["ISO 10816-1", "ISO 20816-1", "ISO 2372"]


class SpringMountSpec(Spec):
    """One spring (and damper) along a line: ``direction`` from the frame's x axis ("90 deg": vertical)."""

    type: Literal["spring"]
    name: Name
    position: Point
    direction: Angle
    stiffness: Stiffness
    damping: Damping = 0.0


class RubberMountSpec(Spec):
    """A rubber mount, stiff vertically and horizontally; damping as a loss factor (turned into viscous
    damping at the crank frequency) and/or viscous dampings."""

    type: Literal["rubber"]
    name: Name
    position: Point
    vertical_stiffness: Stiffness
    horizontal_stiffness: Stiffness
    loss_factor: float = Field(0.0, ge=0.0, le=2.0)
    vertical_damping: Damping = 0.0
    horizontal_damping: Damping = 0.0


class TyreMountSpec(Spec):
    """A pneumatic tyre at its contact point: vertical (radial) and horizontal stiffness and damping."""

    type: Literal["tyre"]
    name: Name
    position: Point
    vertical_stiffness: Stiffness
    horizontal_stiffness: Stiffness
    vertical_damping: Damping = 0.0
    horizontal_damping: Damping = 0.0


class RopeMountSpec(Spec):
    """A hanging rope: a pendulum across it (m g / L for the ``supported_mass`` m) and ``axial_stiffness``
    E A / L along it; ``angle`` is the direction from the frame up to the anchor ("90 deg": hanging straight)."""

    type: Literal["rope"]
    name: Name
    position: Point
    length: PositiveLength
    supported_mass: PositiveMass
    axial_stiffness: PositiveStiffness
    angle: Angle = 1.5707963267948966
    damping: Damping = 0.0


MountSpec = Annotated[SpringMountSpec | RubberMountSpec | TyreMountSpec | RopeMountSpec,
                      Field(discriminator="type")]


class VariantSpec(Spec):
    """The variant compared with the analysed mechanism: the same machine with ``counterweights`` and/or
    ``springs`` added (after balancing; with an energy-storing spring); ``label`` names it in tables and plots."""

    label: str = "after"
    counterweights: list[CounterweightSpec] = Field(default_factory=list)
    springs: list[SpringSpec] = Field(default_factory=list)

    @model_validator(mode="after")
    def _something(self):
        if not self.springs and not self.counterweights:
            raise ValueError("the variant needs at least one counterweight or spring; got neither")
        return self


class FrameTable(Spec):
    """``[frame]``: the machine frame as a rigid planar body on mounts, driven by the mechanism's shaking loads.

    ``mass``, ``inertia`` (centroidal) and ``com`` of everything that moves with the frame; the mechanism's
    origin sits at ``mechanism_origin`` (axes turned by ``mechanism_angle``); ``orders`` harmonics of the
    shaking loads are kept; RMS values are taken along ``direction`` (omit it for the vector magnitude) at the
    named ``points``; the predicted RMS velocity is judged by ``standard`` for ``machine_class``; ``gravity``
    ("on": standard gravity along the frame's -y axis, "off", or a vector in frame axes) adds the weight's
    pendulum term to the rocking stiffness (:mod:`machdyn.vibration.gravity`).
    """

    label: str = "before"
    mass: PositiveMass
    inertia: PositiveInertia
    com: Point = (0.0, 0.0)
    mechanism_origin: Point = (0.0, 0.0)
    mechanism_angle: Angle = 0.0
    orders: int = Field(6, ge=1, le=100, strict=True)
    direction: Angle | None = None
    band: tuple[Frequency, Frequency] = (10.0, 1000.0)
    machine_class: MachineClass = "I"
    standard: Standard = "ISO 10816-1"
    mounts: list[MountSpec] = Field(min_length=1)
    points: dict[Name, Point] = Field(default_factory=lambda: {"origin": (0.0, 0.0)}, min_length=1)
    after: VariantSpec | None = None
    # the weight's pendulum term in the rocking stiffness: "on" (standard gravity along the frame's -y), "off", or
    # a vector in frame axes
    gravity: Gravity = "on"

    @field_validator("mounts")
    @classmethod
    def _unique(cls, mounts):
        names = [m.name for m in mounts]
        dupes = sorted({n for n in names if names.count(n) > 1})
        if dupes:
            raise FieldError(f"mount names must be unique; got {', '.join(dupes)} twice")
        return mounts

    @field_validator("band")
    @classmethod
    def _band(cls, band):
        if not band[0] < band[1]:
            raise FieldError(f"must be (low, high) with low < high; got ({band[0]:g}, {band[1]:g}) Hz")
        return band


class SignalsTable(Spec):
    """``[signals]``: a measured ``record`` (CSV: ``time [s]`` and channels with units) judged by ``standard``
    for ``machine_class`` in ``band``; an optional ``after`` record is compared with it (reduction in %).
    Channels named like a ``[frame.points]`` entry are shown next to the predicted RMS velocity there.

    ``label`` / ``after_label`` name the records in tables and plots (default: the records' file names);
    ``speed`` is the running speed of the machine the records come from, for a file without a machine (a
    machine's own speed is used otherwise): it adds order spectra and a warning when the band leaves out an
    order of it."""

    record: str
    after: str | None = None
    label: str | None = None
    after_label: str | None = None
    speed: AngularVelocity | None = None
    band: tuple[Frequency, Frequency] = (10.0, 1000.0)
    machine_class: MachineClass = "I"
    standard: Standard = "ISO 10816-1"
    boundaries: tuple[Velocity, Velocity, Velocity] | None = None

    @field_validator("speed")
    @classmethod
    def _speed(cls, speed):
        if speed is not None and not speed > 0:
            raise FieldError(f"must be > 0 rad/s (the machine's running speed, e.g. '300 rpm'); got {speed:g} rad/s")
        return speed
    @field_validator("boundaries")
    @classmethod
    def _increasing(cls, boundaries):
        if boundaries is not None and not 0 < boundaries[0] < boundaries[1] < boundaries[2]:
            raise FieldError("must be three increasing velocities > 0 (the A/B, B/C and C/D zone boundaries); got "
                             f"({', '.join(f'{1e3 * b:g}' for b in boundaries)}) mm/s")
        return boundaries

    @field_validator("band")
    @classmethod
    def _band(cls, band):
        if not band[0] < band[1]:
            raise FieldError(f"must be (low, high) with low < high; got ({band[0]:g}, {band[1]:g}) Hz")
        return band


__all__ = ["FrameTable", "SignalsTable", "MountSpec", "VariantSpec", "Mass", "Inertia", "Length"]
