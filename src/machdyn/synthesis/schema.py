"""The ``[synthesis]`` problem file: a task, its free choices and limits, and how the candidates are ranked.

```toml
[meta]
name = "Compactor plate drive"

[synthesis]
task = "quick_return"          # function | quick_return | slider_quick_return | motion | path
                               # | slotted_lever | whitworth
swing = "45 deg"               # quick_return: the rocker's swing ...
time_ratio = 1.25              # ... and slow stroke / fast stroke
rocker = "300 mm"
candidates = 40                # how many free choices are tried
transmission_limit = "35 deg"

[synthesis.ranking]
by = "peak_torque"             # peak_torque | inertial_shaking_force | frame_force | min_transmission | flywheel_energy
                               # | flywheel_inertia (for speed_fluctuation, default 0.05) | error
speed = "60 rpm"
linear_density = "6 kg/m"
output_torque = "-40 N*m"      # resisting torque on the rocker (or output_force on a slider)
keep = 3                       # the best written as problem files of their own
```

Every task's required fields are checked with the file's other mistakes (:func:`problems`), so ``machdyn check``
and ``machdyn run`` agree.
"""

from __future__ import annotations

import math
from typing import Literal

from pydantic import Field, field_validator

from ..problem.fields import Angle, AngularVelocity, FieldError, Force, Length, LinearDensity, PositiveLength, Torque
from ..problem.schema import Meta, Spec
from .function import undefined_in
from .slotted_task import problems as slotted_problems

TASKS = ("function", "quick_return", "slider_quick_return", "motion", "path", "slotted_lever", "whitworth")
#: Functions a function-generation task may name: y = f(x).
FUNCTIONS = ("log10", "ln", "exp", "sqrt", "square", "cube", "reciprocal", "sin", "cos", "tan")


class RankingSpec(Spec):
    """How candidates are run and ranked (see :mod:`machdyn.synthesis.rank`)."""

    by: Literal["peak_torque", "inertial_shaking_force", "frame_force", "min_transmission", "flywheel_energy",
                "flywheel_inertia", "error"] = "peak_torque"
    speed: AngularVelocity = 10.0
    linear_density: LinearDensity = 1.0
    output_torque: Torque = 0.0
    output_force: Force = 0.0
    gravity: bool = True
    speed_fluctuation: float = Field(0.05, gt=0.0, lt=1.0, allow_inf_nan=False)
    positions: int = Field(121, ge=16, le=3601, strict=True)
    keep: int = Field(3, ge=0, le=20, strict=True)

    @field_validator("speed")
    @classmethod
    def _turning(cls, speed: float) -> float:
        if not speed > 0.0:  # the direction each candidate turns follows from its task
            raise FieldError(f"must be > 0 rad/s (each candidate turns the way its task needs); got {speed:g} rad/s")
        return speed


class SynthesisSpec(Spec):
    """The ``[synthesis]`` table: the task and its data; only the fields of the chosen task are read."""

    task: Literal["function", "quick_return", "slider_quick_return", "motion", "path", "slotted_lever", "whitworth"]
    # function generation
    function: Literal["log10", "ln", "exp", "sqrt", "square", "cube", "reciprocal", "sin", "cos", "tan"] | None = None
    x_range: tuple[float, float] | None = None
    input_range: tuple[Angle, Angle] | None = None
    output_range: tuple[Angle, Angle] | None = None
    precision_points: int = Field(3, ge=3, le=50, strict=True)
    spacing: Literal["chebyshev", "even"] = "chebyshev"
    ground: PositiveLength | None = None
    # quick return (crank-rocker or slider-crank)
    swing: Angle | None = None
    stroke: PositiveLength | None = None
    time_ratio: float = Field(1.0, ge=1.0, le=5.0, allow_inf_nan=False)
    rocker: PositiveLength | None = None
    start: Angle | None = None
    slow_stroke: Literal["out", "back"] = "out"
    # slotted-lever quick returns (stroke and time_ratio above): the ram's connecting rod
    rod: PositiveLength | None = None
    # motion and path generation
    positions: list[tuple[Length, Length, Angle]] = []
    points: list[tuple[Length, Length]] = []
    timing: list[Angle] = []
    crank_pivot: tuple[Length, Length] | None = None
    rocker_pivot: tuple[Length, Length] | None = None
    max_length: PositiveLength | None = None
    # every task
    candidates: int = Field(60, ge=1, le=100_000, strict=True)
    seed: int = Field(0, ge=0, strict=True)
    transmission_limit: Angle = 0.5235987755982988
    full_turn: bool = True
    ranking: RankingSpec = RankingSpec()


class SynthesisProblem(Spec):
    """A synthesis problem file: ``[meta]`` and ``[synthesis]``."""

    meta: Meta = Meta()
    synthesis: SynthesisSpec


def problems(spec: SynthesisSpec) -> list[tuple[str, str]]:
    """The task's rules its schema cannot say: which fields it needs and how many positions or points."""
    out: list[tuple[str, str]] = []
    if spec.task in ("slotted_lever", "whitworth"):
        return slotted_problems(spec)
    need = {
        "function": ("function", "x_range", "input_range", "output_range"),
        "quick_return": ("swing", "rocker"),
        "slider_quick_return": ("stroke",),
    }.get(spec.task, ())
    for name in need:
        if getattr(spec, name) is None:
            out.append((f"synthesis.{name}", f"is required by the task '{spec.task}'; it is missing"))
    if spec.task == "function" and spec.x_range is not None and not spec.x_range[1] != spec.x_range[0]:
        out.append(("synthesis.x_range", f"must have two different ends; got {list(spec.x_range)}"))
    if spec.task == "function" and spec.x_range is not None and spec.function is not None:
        undefined = undefined_in(spec.function, *spec.x_range)
        if undefined is not None:
            out.append(("synthesis.x_range", f"the function {spec.function} must be defined and finite over its "
                                             f"whole range: {undefined}"))
    if spec.task == "quick_return" and spec.swing is not None and not 0.0 < spec.swing < math.pi:
        out.append(("synthesis.swing", f"must be between 0 and 180 deg; got {math.degrees(spec.swing):.6g} deg"))
    if spec.task == "motion" and not 2 <= len(spec.positions) <= 5:
        out.append(("synthesis.positions", f"motion generation takes 2 to 5 positions [x, y, angle]; got "
                                           f"{len(spec.positions)}"))
    for name in ("crank_pivot", "rocker_pivot"):
        if getattr(spec, name) is not None and not (spec.task == "motion" and len(spec.positions) == 3):
            out.append((f"synthesis.{name}", f"can be given for a motion task of 3 positions only; the task is "
                                             f"'{spec.task}' with {len(spec.positions)} positions"))
    if spec.task == "motion":
        seen = [(round(x, 12), round(y, 12), round(a, 12)) for x, y, a in spec.positions]
        if len(set(seen)) != len(seen):
            out.append(("synthesis.positions", "must all differ (a repeated position gives no linkage); got "
                                               f"{len(seen) - len(set(seen))} repeated"))
    if spec.task == "path" and spec.points:
        seen2 = [(round(x, 12), round(y, 12)) for x, y in spec.points]
        if len(set(seen2)) != len(seen2):
            out.append(("synthesis.points", "must all differ (a coupler point passes each once); got "
                                            f"{len(seen2) - len(set(seen2))} repeated"))
    if spec.task == "path":
        if len(spec.points) < 3:
            out.append(("synthesis.points", f"path generation needs at least 3 points [x, y]; got "
                                            f"{len(spec.points)}"))
        if spec.timing and len(spec.timing) != len(spec.points) - 1:
            out.append(("synthesis.timing", f"must give the crank's rotation from the first point to each other "
                                            f"point: {max(len(spec.points) - 1, 0)} angles; got {len(spec.timing)}"))
    return out
