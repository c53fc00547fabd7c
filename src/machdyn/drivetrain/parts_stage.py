"""The ``[parts]`` table of a mechanism problem file: bearings, pins and links checked against the joint forces.

```toml
[[parts.bearings]]
joint = "O"                  # a revolute joint of the mechanism
kind = "ball"                # "ball", "roller" or "plain"
capacity = "25.5 kN"         # basic dynamic load rating C (rolling)
life = "20000 h"             # required rating life (rolling)
reliability = 90             # [%], ISO 281 factor a1 for 90 to 99.95 %

[[parts.pins]]
joint = "B"
diameter = "30 mm"
length = "40 mm"             # in the eye: the projected bearing area is diameter x length
shear_planes = 2
allowable_shear = "80 MPa"
allowable_pressure = "25 MPa"

[[parts.links]]
body = "rod"
area = "800 mm^2"
section_modulus = "4000 mm^3"
endurance_limit = "180 MPa"  # Se of the part, all Marin factors applied
ultimate_strength = "600 MPa"
min_safety = 2.0
```

The forces are those of the constant-speed analysis or, with ``[flywheel]``, those at the real speed.
A part that fails its check is a failed design check (exit 3).
"""

from __future__ import annotations

import re
from typing import Any, Literal

from pydantic import Field, model_validator

from ..dynamics.stage import FlywheelRun
from ..errors import InputError, ProblemFileError
from ..linkage import analyse, crank_angles
from ..linkage import model as _model
from ..pipeline import Capability, Outcome, StageContext
from ..problem.build import build_mechanism
from ..problem.fields import Area, Force, PositiveLength, Pressure, PressureVelocity, SectionModulus, Stress, Time
from ..problem.schema import Spec
from ..results.labels import Label
from .parts import BearingSpec, LinkSpec, PartsResult, PinSpec, size_parts


class BearingTable(Spec):
    joint: str
    kind: Literal["ball", "roller", "plain"]
    capacity: Force | None = None
    life: Time | None = None
    reliability: float = Field(90.0, ge=90.0, le=99.95, allow_inf_nan=False)
    diameter: PositiveLength | None = None
    length: PositiveLength | None = None
    max_pressure: Pressure | None = None
    max_pv: PressureVelocity | None = None

    @model_validator(mode="after")
    def _complete(self):
        if self.kind in ("ball", "roller") and (self.capacity is None or self.capacity <= 0):
            raise ValueError(f"a {self.kind} bearing needs its basic dynamic load rating 'capacity' > 0 N")
        if self.kind == "plain" and (self.diameter is None or self.length is None):
            raise ValueError("a plain bearing needs its 'diameter' and 'length'")
        return self


class PinTable(Spec):
    joint: str
    diameter: PositiveLength
    length: PositiveLength
    shear_planes: Literal[1, 2] = 2
    allowable_shear: Stress | None = None
    allowable_pressure: Pressure | None = None


class LinkTable(Spec):
    body: str
    area: Area
    section_modulus: SectionModulus
    endurance_limit: Stress
    ultimate_strength: Stress
    min_safety: float = Field(1.5, gt=0.0, allow_inf_nan=False)


class PartsSpec(Spec):
    """The ``[parts]`` table."""

    bearings: list[BearingTable] = []
    pins: list[PinTable] = []
    links: list[LinkTable] = []

    @model_validator(mode="after")
    def _something(self):
        if not (self.bearings or self.pins or self.links):
            raise ValueError("[parts] names no part: give [[parts.bearings]], [[parts.pins]] or [[parts.links]]")
        return self


def _specs(table: PartsSpec) -> dict[str, Any]:
    return {
        "bearings": tuple(BearingSpec(b.joint, b.kind, b.capacity, b.life, b.reliability, b.diameter, b.length,
                                      b.max_pressure, b.max_pv) for b in table.bearings),
        "pins": tuple(PinSpec(p.joint, p.diameter, p.length, p.shear_planes, p.allowable_shear,
                              p.allowable_pressure) for p in table.pins),
        "links": tuple(LinkSpec(k.body, k.area, k.section_modulus, k.endurance_limit, k.ultimate_strength,
                                k.min_safety) for k in table.links),
    }


def _names(table: PartsSpec, mech: Any) -> list[tuple[str, str]]:
    joints = {name: kind for name, kind, _b1, _b2 in _model.joints(mech)}
    bodies = set(mech.moving_bodies)
    problems = []
    named: list[tuple[str, list[Any]]] = [("bearings", list(table.bearings)), ("pins", list(table.pins))]
    for group, items in named:
        for i, item in enumerate(items):
            if item.joint not in joints:
                problems.append((f"parts.{group}[{i}].joint",
                                 f"names no joint of the mechanism; joints: {', '.join(joints)}; got {item.joint!r}"))
            elif group == "bearings" and joints[item.joint] != "R":
                problems.append((f"parts.{group}[{i}].joint",
                                 f"a bearing sits at a revolute joint; {item.joint!r} is prismatic"))
    for i, link in enumerate(table.links):
        if link.body not in bodies:
            problems.append((f"parts.links[{i}].body",
                             f"names no moving body; bodies: {', '.join(sorted(bodies))}; got {link.body!r}"))
    return problems


def check(problem: Any, table: PartsSpec, source: str | None = None) -> list[tuple[str, str]]:
    """The names of joints and bodies exist, and the parts can be evaluated on the model (as ``run`` does)."""
    try:
        mech = build_mechanism(problem)
    except ProblemFileError:
        return []  # the kind's own check reports the model's mistakes
    problems = _names(table, mech)
    if problems:
        return problems
    try:
        size_parts(analyse(mech, crank_angles(36), 1.0).forces, **_specs(table))
    except InputError as exc:
        return [("parts", str(exc))]
    return []


def run(ctx: StageContext) -> Outcome:
    """Stage of ``[parts]``: every part checked over the cycle; a failed part is a failed design check."""
    problems = _names(ctx.table, ctx.mechanism)
    if problems:
        raise ProblemFileError(problems)
    flywheel = ctx.result_of("flywheel", FlywheelRun)  # None: no [flywheel], or no steady state
    forces = flywheel.real.real if flywheel is not None else ctx.analysis.forces
    done = size_parts(forces, **_specs(ctx.table))
    scalars, labels = {}, {}
    worst = 0.0
    for c in done.checks:
        key = "parts." + c.part.replace(" ", ".") + "." + (c.figure or _slug(c.quantity))
        scalars[key] = c.value
        labels[key] = Label(f"{c.part[0].upper()}{c.part[1:]}: {c.quantity}", c.unit,
                            {"s": "h", "Pa": "MPa", "Pa*m/s": "MPa*m/s"}.get(c.unit))
        worst = max(worst, c.utilisation)
    scalars["parts.utilisation.max"] = worst
    failed = tuple(f"{c.part}: {c.quantity} {c.value:.4g} {c.unit} against {c.limit:.4g} {c.unit} "
                   f"(utilisation {100 * c.utilisation:.0f} %)" for c in done.failed)
    series = {}
    if done.bearing_loads:
        series["parts_bearings"] = {"crank_angle": (done.crank_angle, "rad"),
                                    **{f"{j}.load": (load, "N") for j, (load, _m) in done.bearing_loads.items()}}
    return Outcome(results=done, scalars=scalars, labels=labels, series=series,
                   summary=(*scalars,), failed_checks=failed)


def _slug(text: str) -> str:
    return re.sub(r"[^a-z0-9]+", "_", text.lower()).strip("_")


LABELS = {"parts.utilisation.max": Label("Parts: largest utilisation of any check", "")}

CAPABILITY = Capability(
    table="parts",
    schema=PartsSpec,
    run=run,
    step="sizing the parts",
    kinds=("mechanism",),
    labels=LABELS,
    report="machdyn.report.parts:sections",
    check=check,
    after=("flywheel",),
    result_type=PartsResult,
)
