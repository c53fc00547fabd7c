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
criterion = "goodman"        # or "soderberg", "gerber", "asme_elliptic"; yield_strength adds Langer's check
```

Instead of ``endurance_limit`` a ``[parts.links.marin]`` table derives it from ``ultimate_strength`` by the Marin
factors (finish, diameter, load, temperature, reliability) and a notch (stress_concentration, notch_radius).

The forces are those of the constant-speed analysis or, with ``[flywheel]``, those at the real speed.
A part that fails its check is a failed design check (exit 3).
"""

from __future__ import annotations

from typing import Any, Literal

from pydantic import Field, model_validator

from ..dynamics.stage import FlywheelRun
from ..errors import InputError, ProblemFileError
from ..linkage import analyse, crank_angles
from ..linkage import model as _model
from ..pipeline import Capability, Outcome, StageContext
from ..problem.build import build_mechanism
from ..problem.fields import (
    Area,
    Force,
    PositiveLength,
    Pressure,
    PressureVelocity,
    SectionModulus,
    Stress,
    TemperatureDifference,
    Time,
)
from ..problem.schema import Spec
from ..results.labels import Label
from . import fatigue
from .parts import BearingSpec, LinkSpec, PartsResult, PinSpec, check_key, size_parts
from .parts_population import parts_population
from .strength import strength_problem


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


class MarinTable(Spec):
    """``[parts.links.marin]``: the link's endurance limit from the specimen's by the Marin factors."""

    finish: Literal["ground", "machined", "cold_drawn", "hot_rolled", "as_forged"] = "machined"
    diameter: PositiveLength | None = None          # (equivalent) diameter for the size factor
    load: Literal["bending", "axial", "torsion"] = "bending"
    temperature: TemperatureDifference | None = None  # absolute, in K (e.g. "373.15 K")
    reliability: float = Field(0.5, ge=0.5, lt=1.0, allow_inf_nan=False)
    miscellaneous: float = Field(1.0, gt=0.0, allow_inf_nan=False)
    specimen_endurance_limit: Stress | None = None  # from a test; default 0.5 Sut (700 MPa above 1400 MPa)
    stress_concentration: float | None = Field(None, ge=1.0, allow_inf_nan=False)  # Kt
    notch_radius: PositiveLength | None = None
    sensitivity: Literal["neuber", "peterson"] = "neuber"

    @model_validator(mode="after")
    def _notch(self):
        if (self.stress_concentration is None) != (self.notch_radius is None):
            raise ValueError("a notch needs both stress_concentration (Kt) and notch_radius")
        return self


class LinkTable(Spec):
    body: str
    area: Area
    section_modulus: SectionModulus
    endurance_limit: Stress | None = None
    marin: MarinTable | None = None
    ultimate_strength: Stress
    yield_strength: Stress | None = None
    criterion: Literal["goodman", "soderberg", "gerber", "asme_elliptic"] = "goodman"
    required_cycles: float | None = Field(None, ge=1.0, allow_inf_nan=False)
    min_safety: float = Field(1.5, gt=0.0, allow_inf_nan=False)

    @model_validator(mode="after")
    def _strengths(self):
        if (self.endurance_limit is None) == (self.marin is None):
            raise ValueError("a link needs either endurance_limit or [parts.links.marin], "
                             f"{'not both' if self.marin is not None else 'one of them'}")
        if self.criterion in ("soderberg", "asme_elliptic") and self.yield_strength is None:
            raise ValueError(f"the {self.criterion} criterion needs yield_strength")
        if self.yield_strength is not None and self.yield_strength > self.ultimate_strength:
            raise ValueError(f"yield_strength {self.yield_strength / 1e6:g} MPa exceeds ultimate_strength "
                             f"{self.ultimate_strength / 1e6:g} MPa")
        problem = strength_problem(self.endurance_limit, self.ultimate_strength) \
            if self.endurance_limit is not None else None
        if problem:
            raise ValueError(problem)
        return self


def link_strength(link: LinkTable) -> tuple[float, float]:
    """The endurance limit S_e [Pa] and the fatigue notch factor K_f of a link's table (Marin factors and notch
    sensitivity of :mod:`machdyn.drivetrain.fatigue`)."""
    if link.marin is None:
        assert link.endurance_limit is not None
        return link.endurance_limit, 1.0
    m = link.marin
    se = fatigue.marin_endurance_limit(link.ultimate_strength, finish=m.finish, diameter=m.diameter, load=m.load,
                                       temperature=m.temperature, reliability=m.reliability,
                                       miscellaneous=m.miscellaneous, specimen=m.specimen_endurance_limit)
    kf = 1.0
    if m.stress_concentration is not None and m.notch_radius is not None:
        q = (fatigue.neuber_sensitivity(link.ultimate_strength, m.notch_radius, m.load)
             if m.sensitivity == "neuber" else fatigue.peterson_sensitivity(link.ultimate_strength, m.notch_radius))
        kf = fatigue.fatigue_notch_factor(m.stress_concentration, q)
    return se.endurance_limit, kf


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


def _link_spec(k: LinkTable, i: int) -> LinkSpec:
    try:
        se, kf = link_strength(k)
    except InputError as exc:
        raise ProblemFileError([(f"parts.links[{i}].marin", str(exc))]) from None
    return LinkSpec(k.body, k.area, k.section_modulus, se, k.ultimate_strength, k.min_safety, k.criterion,
                    k.yield_strength, kf, k.required_cycles)


def _specs(table: PartsSpec) -> dict[str, Any]:
    return {
        "bearings": tuple(BearingSpec(b.joint, b.kind, b.capacity, b.life, b.reliability, b.diameter, b.length,
                                      b.max_pressure, b.max_pv) for b in table.bearings),
        "pins": tuple(PinSpec(p.joint, p.diameter, p.length, p.shear_planes, p.allowable_shear,
                              p.allowable_pressure) for p in table.pins),
        "links": tuple(_link_spec(k, i) for i, k in enumerate(table.links)),
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
    except ProblemFileError as exc:
        return list(exc.problems)
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
        key = check_key(c.part, c.quantity, c.figure)
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


def population(problem: Any, forces: Any) -> dict[str, Any] | None:
    """The ``[parts]`` results of N designs at once from their kinetostatics (the population form,
    :func:`machdyn.drivetrain.parts_population.parts_population`); None with a ``[flywheel]``, whose real speed each
    design's run finds on its own."""
    if getattr(problem, "flywheel", None) is not None:
        return None
    found = parts_population(forces, **_specs(problem.parts))
    found.pop("valid")
    return found


def result_keys(problem: Any) -> dict[str, str]:
    """{key: SI unit} of the checks a run of ``problem``'s ``[parts]`` reports, one per part and figure, made from
    the file's own joint and body names (``parts.bearing.O.rating_life``): what a study may name. A link broken in
    its first cycle reports its ``peak_stress`` instead of its safety factors."""
    table = problem.parts
    keys: dict[str, str] = {}
    for b in table.bearings:
        key = f"parts.bearing.{b.joint}."
        if b.kind in ("ball", "roller"):
            keys[key + "rating_life"] = "s"
        else:
            keys |= {key + f: u for f, u, limit in (("peak_pressure", "Pa", b.max_pressure),
                                                     ("mean_pv", "Pa*m/s", b.max_pv)) if limit is not None}
    for pin in table.pins:
        key = f"parts.pin.{pin.joint}."
        limits = (("peak_shear_stress", pin.allowable_shear), ("peak_bearing_pressure", pin.allowable_pressure))
        keys |= {key + f: "Pa" for f, limit in limits if limit is not None}
    for link in table.links:
        key = f"parts.link.{link.body}."
        keys |= {key + "fatigue_safety": "", key + "peak_stress": "Pa"}
        keys |= {key + f: "" for f, given in (("yield_safety", link.yield_strength),
                                              ("fatigue_damage", link.required_cycles)) if given is not None}
    return keys


LABELS = {"parts.utilisation.max": Label("Parts: largest utilisation of any check", "", over="scalar", better="lower")}

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
    population="machdyn.drivetrain.parts_stage:population",
    result_keys=result_keys,
)
