"""The ``[drivetrain]`` table of a mechanism problem file: the stages between motor and crank, a clutch that
engages the flywheel side to the crank, and a brake that stops the crank side.

```toml
[drivetrain]
motor_inertia = "0.02 kg*m^2"     # shaft 0: the motor's rotor and what turns with it

[[drivetrain.stages]]             # from the motor to the crank, one shaft after each stage
kind = "belt"
ratio = 4.0                       # input speed / output speed
efficiency = 0.95
inertia = "1.2 kg*m^2"            # what sits on the stage's output shaft (pulley, flywheel rim, gear)

[[drivetrain.stages]]
kind = "gear"
ratio = 9.0
efficiency = 0.97
inertia = "0.3 kg*m^2"            # the last stage's output shaft is the crank shaft

[drivetrain.clutch]
shaft = 1                         # the clutch joins shaft 1 (and all before it) to the stage after it
slip_torque = "900 N*m"           # on that shaft
strokes_per_minute = 20           # single strokes: for the clutch's heat

[drivetrain.brake]
torque = "2500 N*m"               # on the crank shaft
max_angle = "45 deg"              # a stop longer than this fails the design check (exit 3)
max_time = "0.3 s"
```

With ``[flywheel]`` the flywheel (its inertia reduced to the crank) sits on the clutch's driving side, and the
shaft torques are those at the real speed.
"""

from __future__ import annotations

import math
from typing import Any, Literal

from pydantic import Field, model_validator

from ..dynamics.driveline import CRANK, MOTOR
from ..dynamics.driveline_file import resolve_shaft
from ..problem.fields import Angle, Inertia, RotaryDamping, Time, Torque, TorsionalStiffness
from ..problem.schema import Spec
from .gear_stage import GearTeethTable
from .geometry_tables import BrakeGeometry, BrakeHeating, ClutchGeometry
from .shaft_check import ShaftTable


class StageTable(Spec):
    kind: Literal["gear", "belt", "chain"] = "gear"
    ratio: float = Field(gt=0.0, allow_inf_nan=False)
    efficiency: float = Field(1.0, gt=0.0, le=1.0, allow_inf_nan=False)
    inertia: Inertia = 0.0
    name: str = ""
    shaft: str = ""   # a name for the stage's output shaft (the flywheel, clutch and brake may name it)
    teeth: GearTeethTable | None = None        # a gear stage's teeth: Lewis bending and Hertz contact checks
    # the stage's shafts and coupling as a torsional spring and damper, referred to its output shaft ([transient]
    # integrates each shaft on its own; rigid when not given)
    torsional_stiffness: TorsionalStiffness | None = None
    torsional_damping: RotaryDamping = 0.0

    @model_validator(mode="after")
    def _teeth_on_gears(self):
        if self.teeth is not None and self.kind != "gear":
            raise ValueError(f"teeth belong to a gear stage; this stage is a {self.kind}")
        if self.torsional_damping > 0 and self.torsional_stiffness is None:
            raise ValueError(f"torsional_damping ({self.torsional_damping:g} N*m*s/rad) needs torsional_stiffness: a "
                             "rigid stage has nothing to damp")
        return self


class ClutchTable(Spec):
    shaft: int | str | None = None
    slip_torque: Torque | None = None
    geometry: ClutchGeometry | None = None     # instead of slip_torque: the torque from the faces or shoes
    motor_torque: Torque = 0.0
    strokes_per_minute: float | None = Field(None, gt=0.0, allow_inf_nan=False)


class BrakeTable(Spec):
    torque: Torque | None = None
    geometry: BrakeGeometry | None = None      # instead of torque: the torque from the lever, band or pads
    heating: BrakeHeating | None = None
    shaft: int | str | None = None
    at: list[Angle] = []
    max_angle: Angle | None = None
    max_time: Time | None = None


class SingleStrokeTable(Spec):
    """``[drivetrain.single_stroke]``: simulate one stroke of a press in single-stroke mode."""

    start: Angle                      # the crank angle at rest between strokes (e.g. top dead centre)
    brake_at: Angle | None = None     # where the clutch opens and the brake closes; default: found so that the
                                      # crank comes to rest at ``start`` one turn on


class DriveTrainSpec(Spec):
    """The ``[drivetrain]`` table."""

    motor_inertia: Inertia = 0.0
    stages: list[StageTable] = Field(min_length=1)
    clutch: ClutchTable | None = None
    brake: BrakeTable | None = None
    single_stroke: SingleStrokeTable | None = None
    shafts: list[ShaftTable] = []

    @model_validator(mode="after")
    def _shafts(self):
        last = len(self.stages)
        names = [s.shaft for s in self.stages if s.shaft]
        for name in {n for n in names if names.count(n) > 1 or n in (MOTOR, CRANK)}:
            raise ValueError(f"stages[*].shaft must name each shaft once, and not \"{MOTOR}\" or \"{CRANK}\" "
                             f"(the first and the last shaft's names); got \"{name}\"")
        if self.clutch is not None and self.clutch.shaft is not None:
            try:
                at = resolve_shaft(self.clutch.shaft, self)
            except ValueError as exc:
                raise ValueError(f"clutch.shaft {exc}") from None
            if at >= last:
                raise ValueError(f"clutch.shaft must name a shaft before the crank shaft (0 to {last - 1}); got "
                                 f"{self.clutch.shaft!r}")
        if self.brake is not None and self.brake.shaft is not None:
            try:
                resolve_shaft(self.brake.shaft, self)
            except ValueError as exc:
                raise ValueError(f"brake.shaft {exc}") from None
        for i, s in enumerate(self.shafts):
            if s.shaft > last:
                raise ValueError(f"shafts[{i}].shaft must be 0 to {last} (the crank shaft); got {s.shaft}")
        if self.clutch is not None:
            _one_of("clutch", "slip_torque", self.clutch.slip_torque, self.clutch.geometry)
        if self.brake is not None:
            _one_of("brake", "torque", self.brake.torque, self.brake.geometry)
        if self.single_stroke is not None and (self.clutch is None or self.brake is None):
            raise ValueError("single_stroke needs both a [drivetrain.clutch] and a [drivetrain.brake]")
        stroke = self.single_stroke
        if stroke is not None and stroke.brake_at is not None and not (
                stroke.start < stroke.brake_at < stroke.start + 2 * math.pi):
            raise ValueError(f"single_stroke.brake_at must lie within the stroke, after start "
                             f"({math.degrees(stroke.start):g} deg) and less than a turn later; got "
                             f"{math.degrees(stroke.brake_at):g} deg")
        return self


def _one_of(table: str, field: str, value: float | None, geometry: Any) -> None:
    if (value is None) == (geometry is None):
        raise ValueError(f"{table} needs either {table}.{field} or {table}.geometry, "
                         f"{'not both' if geometry is not None else 'one of them'}")
    if value is not None and not value > 0:
        raise ValueError(f"{table}.{field} must be > 0 N*m; got {value:g} N*m")
