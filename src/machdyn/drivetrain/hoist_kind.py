"""The ``[hoist]`` problem kind: a motor driving a tree of shafts with rope drums, cages, counterweights and
friction torques; the torque to accelerate it all and what the motor sees of it (:mod:`.hoist`).

```toml
[meta]
name = "Mine hoist"

[hoist]
cage_acceleration = "0.8 m/s^2"  # one of: cage_acceleration (of `drum`), motor_acceleration, motor_torque
drum = "cage"                    # the drum whose cage has that acceleration (default: the first drum)
motor_speed = "980 rpm"          # optional: the power at this speed

[[hoist.shafts]]
name = "motor"
inertia = "1.2 kg*m^2"

[[hoist.shafts]]
name = "drum shaft"
driven_by = "motor"              # the parent shaft
ratio = 20                       # omega_parent / omega_this
efficiency = 0.9
inertia = "150 kg*m^2"
friction = "250 N*m"             # opposing the motion

[[hoist.shafts.drums]]
name = "cage"
radius = "0.6 m"
cage = "1500 kg"
counterweight = "900 kg"
rope = "120 kg"
```

Results: ``hoist.motor_torque``, ``hoist.steady_torque`` (at zero acceleration), ``hoist.motor_acceleration``,
``hoist.equivalent_inertia`` and ``hoist.load_torque`` at the motor, ``hoist.loss_torque``, ``hoist.power`` (with
``motor_speed``), and per drum ``hoist.<drum>.cage_acceleration`` and ``hoist.<drum>.rope_tension`` (the cage's
side: m_c (g + a)). A rope that would go slack (a cage falling faster than g) is a failed design check.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from pydantic import Field

from ..constants import STANDARD_GRAVITY
from ..errors import InputError
from ..pipeline import Outcome, ProblemKind, Step
from ..problem.fields import (
    Acceleration,
    AngularAcceleration,
    AngularVelocity,
    Inertia,
    Mass,
    PositiveLength,
    Torque,
)
from ..problem.schema import Meta, Spec
from ..results.labels import Label
from .hoist import Drum, HoistResult, Shaft, acceleration, hoist


@dataclass(frozen=True)
class HoistRun:
    """The train at the asked acceleration and at steady speed (the same gravity)."""

    result: HoistResult
    steady: HoistResult


class DrumSpec(Spec):
    """A rope drum on its shaft."""

    name: str
    radius: PositiveLength
    cage: Mass
    counterweight: Mass = 0.0
    rope: Mass = 0.0


class ShaftSpec(Spec):
    """A shaft of the train; the motor's has no ``driven_by``."""

    name: str
    driven_by: str | None = None
    ratio: float = Field(1.0, gt=0.0, allow_inf_nan=False)
    efficiency: float = Field(1.0, gt=0.0, le=1.0, allow_inf_nan=False)
    inertia: Inertia = 0.0
    friction: Torque = 0.0
    drums: list[DrumSpec] = []


class HoistSpec(Spec):
    """The ``[hoist]`` table."""

    shafts: list[ShaftSpec]
    cage_acceleration: Acceleration | None = None
    drum: str | None = None
    motor_acceleration: AngularAcceleration | None = None
    motor_torque: Torque | None = None
    motor_speed: AngularVelocity | None = None
    gravity: bool = True


class HoistProblem(Spec):
    meta: Meta = Meta()
    hoist: HoistSpec


def model(spec: HoistSpec) -> tuple[Shaft, ...]:
    """The train of the table (SI)."""
    return tuple(Shaft(s.name, s.driven_by, s.ratio, s.efficiency, s.inertia, s.friction,
                       tuple(Drum(d.radius, d.cage, d.counterweight, d.rope, d.name) for d in s.drums))
                 for s in spec.shafts)


def problems(spec: HoistSpec) -> list[tuple[str, str]]:
    """Every rule the schema cannot say, each with its path."""
    out: list[tuple[str, str]] = []
    names = [s.name for s in spec.shafts]
    for k, s in enumerate(spec.shafts):
        if names.count(s.name) > 1:
            out.append((f"hoist.shafts[{k}].name", f"must differ from the other shafts' names; '{s.name}' is used "
                                                    f"{names.count(s.name)} times"))
        if s.driven_by is not None and s.driven_by not in names:
            out.append((f"hoist.shafts[{k}].driven_by", f"must name a shaft of the train ({', '.join(names)}); got "
                                                         f"'{s.driven_by}'"))
        if s.driven_by is None and (s.ratio != 1.0 or s.efficiency != 1.0):
            out.append((f"hoist.shafts[{k}]", "the motor's shaft (no driven_by) has no stage: remove its ratio and "
                                              "efficiency"))
    roots = [s.name for s in spec.shafts if s.driven_by is None]
    if len(roots) != 1:
        out.append(("hoist.shafts", f"must have exactly one motor shaft (without driven_by); got {len(roots)}: "
                                    f"{roots}"))
    given = [n for n in ("cage_acceleration", "motor_acceleration", "motor_torque") if getattr(spec, n) is not None]
    if len(given) != 1:
        out.append(("hoist", f"give exactly one of cage_acceleration, motor_acceleration, motor_torque; got "
                             f"{len(given)}: {given}"))
    drums = [d.name for s in spec.shafts for d in s.drums]
    if len(set(drums)) != len(drums):
        out.append(("hoist.shafts[*].drums", f"every drum needs its own name; got {drums}"))
    if spec.drum is not None and spec.drum not in drums:
        out.append(("hoist.drum", f"must name a drum of the train ({', '.join(drums) or 'none'}); got '{spec.drum}'"))
    if spec.cage_acceleration is not None and not drums:
        out.append(("hoist.cage_acceleration", "needs a drum on one of the shafts; the train has none"))
    if not out:  # the tree itself (a loop of parents)
        try:
            hoist(model(spec), 0.0)
        except InputError as exc:
            out.append(("hoist.shafts", str(exc)))
    return out


def build(problem: Any) -> tuple[Any, list[tuple[str, str]]]:
    found = problems(problem.hoist)
    return (None if found else model(problem.hoist)), found


def check(problem: Any, _model: Any) -> list[str]:
    return []


def motor_acceleration(spec: HoistSpec, shafts: tuple[Shaft, ...], g: float) -> float:
    """The motor's angular acceleration [rad/s^2] the table asks for."""
    if spec.motor_acceleration is not None:
        return float(spec.motor_acceleration)
    if spec.motor_torque is not None:
        return acceleration(shafts, spec.motor_torque, g)
    ratio = hoist(shafts, 0.0, g).speed_ratio
    name = spec.drum or next(d.name for s in shafts for d in s.drums)
    shaft, drum = next((s, d) for s in shafts for d in s.drums if d.name == name)
    return float(spec.cage_acceleration) / (ratio[shaft.name] * drum.radius)  # type: ignore[arg-type]


def analyse(problem: Any, shafts: Any, step: Step) -> Outcome:
    step("hoist")
    spec = problem.hoist
    g = STANDARD_GRAVITY if spec.gravity else 0.0
    alpha = motor_acceleration(spec, shafts, g)
    res = hoist(shafts, alpha, g)
    steady = hoist(shafts, 0.0, g)
    scalars: dict[str, Any] = {"hoist.motor_torque": res.motor_torque, "hoist.steady_torque": steady.motor_torque,
                               "hoist.motor_acceleration": alpha, "hoist.equivalent_inertia": res.equivalent_inertia,
                               "hoist.load_torque": res.load_torque, "hoist.loss_torque": res.loss_torque}
    labels: dict[str, Label] = {}
    failed = []
    if spec.motor_speed is not None:
        scalars["hoist.power"] = res.motor_torque * spec.motor_speed
    for s in shafts:
        for d in s.drums:
            a = res.cage_acceleration[d.name]
            scalars[f"hoist.{d.name}.cage_acceleration"] = a
            scalars[f"hoist.{d.name}.rope_tension"] = d.cage * (g + a)
            labels[f"hoist.{d.name}.cage_acceleration"] = Label(f"{d.name}: cage acceleration (up)", "m/s^2")
            labels[f"hoist.{d.name}.rope_tension"] = Label(f"{d.name}: rope tension at the cage", "N", "kN")
            if g + a < 0.0 or (d.counterweight > 0.0 and g - a < 0.0):
                failed.append(f"the rope of drum '{d.name}' goes slack: a cage or counterweight would have to fall "
                              f"faster than g (cage acceleration {a:.4g} m/s^2)")
    summary = tuple(k for k in ("hoist.motor_torque", "hoist.steady_torque", "hoist.motor_acceleration",
                                "hoist.equivalent_inertia", "hoist.load_torque", "hoist.loss_torque",
                                "hoist.power") if k in scalars) + tuple(k for k in scalars if k.count(".") == 2)
    return Outcome(results=HoistRun(res, steady), scalars=scalars, labels=labels, summary=summary,
                   failed_checks=tuple(failed))


LABELS = {
    "hoist.motor_torque": Label("Motor torque to accelerate the train", "N*m", over="scalar", better="lower"),
    "hoist.steady_torque": Label("Motor torque at steady speed", "N*m", over="scalar", better="lower"),
    "hoist.motor_acceleration": Label("Motor's angular acceleration", "rad/s^2", over="scalar", better="higher"),
    "hoist.equivalent_inertia": Label("Inertia referred to the motor (loss-free)", "kg*m^2", over="scalar",
                                      better="lower"),
    "hoist.load_torque": Label("Load and friction torque referred to the motor (loss-free)", "N*m", over="scalar",
                               better="lower"),
    "hoist.loss_torque": Label("Torque the stages lose", "N*m", over="scalar", better="lower"),
    "hoist.power": Label("Motor power at motor_speed", "W", "kW", over="scalar", better="lower"),
}

KIND = ProblemKind(
    name="hoist",
    schema=HoistProblem,
    build=build,
    check=check,
    analyse=analyse,
    title=lambda problem: problem.meta.name,
    steps=("hoist",),
    labels=LABELS,
    report="machdyn.report.hoist:sections",
)
