"""Build the engine's :class:`~machdyn.linkage.model.Mechanism` from a validated linkage problem.

The geometry comes from the engine's builders (``slider_crank``, ``four_bar``, ...) or, for ``custom``, from
the bodies and dyads written out; masses, inertias and centres of mass given in the file then replace the
builders' defaults body by body; gravity, loads and counterweights are added last. References to bodies and
points are checked here so that a misspelling is reported with its path and a "did you mean".
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from ..constants import DOWNWARD_GRAVITY
from ..errors import InputError, ProblemFileError
from ..linkage import model as m
from ..linkage.dyad_types import DYAD_TYPES, Guide
from ..linkage.standard import STANDARD_MECHANISMS
from ..linkage.stroke_loads import stroke_load
from ..results.population import compactor_plate
from .errors import did_you_mean
from .schema import CustomSpec, DoubleCrankSpec, LinkageProblem, LinkSpec

STANDARD_GRAVITY = DOWNWARD_GRAVITY


def crank_angles(problem: LinkageProblem) -> np.ndarray:
    """The crank angles [rad] a problem's ``[drive]`` asks for."""
    d = problem.drive
    if d.start is None and d.stop is None:
        return np.linspace(0.0, 2 * math.pi, d.positions, endpoint=False)
    start = 0.0 if d.start is None else d.start
    stop = start + 2 * math.pi if d.stop is None else d.stop
    return np.linspace(start, stop, d.positions)


def harmonics_of(problem: LinkageProblem) -> int:
    """How many harmonics of the driving torque and the shaking loads a run reports (``[output] harmonics``)."""
    output = getattr(problem, "output", None)
    return int(getattr(output, "harmonics", 0) or 0)


def gravity_vector(problem: LinkageProblem) -> tuple[float, float]:
    g = problem.loads.gravity
    if g == "on":
        return STANDARD_GRAVITY
    if g == "off":
        return (0.0, 0.0)
    return (float(g[0]), float(g[1]))


def _geometry(spec):
    """The mechanism from its builder (or written out for custom) and the list of (body, spec) overrides."""
    name = spec.name or spec.type
    if isinstance(spec, CustomSpec):
        return _custom(spec, name), []
    return STANDARD_MECHANISMS[spec.type].build(spec, linear_density=spec.linear_density, name=name)


def _custom(spec: CustomSpec, name: str):
    problems: list[tuple[str, str]] = []
    names = [b.name for b in spec.bodies]
    for i, d in enumerate(spec.dyads):
        for attr in ("a", "b"):
            body = getattr(d, attr)
            if body not in names:
                problems.append((f"mechanism.dyads[{i}].{attr}", _unknown("body", body, names)))
    if spec.crank.body not in names:
        problems.append(("mechanism.crank.body", _unknown("body", spec.crank.body, names)))
    if problems:
        raise ProblemFileError(problems)
    bodies = tuple(m.Body(b.name, dict(b.points), b.mass, b.inertia, tuple(b.com)) for b in spec.bodies)
    dyads = [_dyad(d) for d in spec.dyads]
    return m.Mechanism(
        name=name,
        ground={k: tuple(v) for k, v in spec.ground.items()},
        bodies=bodies,
        crank=m.Crank(spec.crank.body, spec.crank.pivot),
        dyads=tuple(dyads),
    )


def _dyad(d):
    """The engine's dyad from its problem-file table (same field names; guides and slides as tables)."""
    values = {k: getattr(d, k) for k in type(d).model_fields if k != "type"}
    for key, value in values.items():
        if key.startswith("guide"):
            values[key] = Guide(value.point, value.angle)
        elif key == "slide":
            values[key] = (value.point, value.angle)
    return DYAD_TYPES[d.type](**values)


def _unknown(what: str, value: str, choices: list[str]) -> str:
    plural = {"body": "bodies"}.get(what, what + "s")
    return f"unknown {what} '{value}'{did_you_mean(value, choices)} ({plural}: {', '.join(choices) or 'none'})"


def _span(body) -> float:
    """The distance between a body's first two points (its length as a bar)."""
    pts = list(body.points.values())
    if len(pts) < 2:
        return 0.0
    return float(math.hypot(pts[1][0] - pts[0][0], pts[1][1] - pts[0][1]))


def _override(body, spec) -> object:
    """``body`` with the mass, inertia and centre of mass the file gives.

    A link given a mass but no inertia gets that of a uniform bar, m L^2/12; a block gets 0; the double
    crank gets m (L1^2 + L2^2)/6 (as the builder)."""
    changes: dict = {}
    if spec.mass is not None:
        changes["mass"] = spec.mass
        if spec.inertia is None:
            if isinstance(spec, LinkSpec):
                length = spec.length if spec.length is not None else _span(body)
                changes["inertia"] = spec.mass * length**2 / 12.0
            elif isinstance(spec, DoubleCrankSpec):
                changes["inertia"] = spec.mass * (spec.length_1**2 + spec.length_2**2) / 6.0
            else:
                changes["inertia"] = 0.0
    if spec.inertia is not None:
        changes["inertia"] = spec.inertia
    if spec.com is not None:
        changes["com"] = tuple(spec.com)
    return replace(body, **changes) if changes else body


def _machine_problems(spec, mech) -> list[tuple[str, str]]:
    """The problems of ``[mechanism] machine``: a compactor must be a four-bar with a coupler point (its plate
    and the point where the plate presses)."""
    if getattr(spec, "machine", None) != "compactor":
        return []
    if compactor_plate(mech) is not None:
        return []
    return [("mechanism.machine", "'compactor' needs a four-bar (type = \"four_bar\") with a coupler point "
                                  "(coupler_point = [x, y]), the point of the plate where the material is pressed")]


def build_mechanism(problem: LinkageProblem):
    """The :class:`~machdyn.linkage.model.Mechanism` a linkage problem describes.

    Raises :class:`~machdyn.errors.ProblemFileError` for references to unknown bodies or points and for
    every rule the engine's model check finds broken (each with its path)."""
    spec = problem.mechanism
    try:
        mech, overrides = _geometry(spec)
    except InputError as exc:
        raise ProblemFileError([("mechanism", str(exc))]) from None
    if overrides:
        by_name = dict(overrides)
        bodies = tuple(_override(b, by_name[b.name]) if b.name in by_name else b for b in mech.bodies)
        mech = replace(mech, bodies=bodies)

    problems: list[tuple[str, str]] = _machine_problems(spec, mech)
    body_names = [b.name for b in mech.bodies]
    points = [f"ground.{g}" for g in mech.ground] + [f"{b.name}.{p}" for b in mech.bodies for p in b.points]

    def need_point(path: str, ref: str) -> None:
        if ref not in points:
            problems.append((path, _unknown("point", ref, points)))

    def need_body(path: str, body: str) -> None:
        if body not in body_names:
            problems.append((path, _unknown("body", body, body_names)))

    loads = problem.loads
    forces: list = []
    torques: list = []
    springs: list = []
    masses: list = []
    for i, f in enumerate(loads.forces):
        need_point(f"loads.forces[{i}].point", f.point)
        forces.append(m.PointForce(f.name or f"force_{i + 1}", f.point, f.fx, f.fy, _active(f.active)))
    for i, sf in enumerate(loads.stroke_forces):
        where = f"loads.stroke_forces[{i}]"
        need_point(f"{where}.point", sf.point)
        if sf.point in points:
            try:
                forces.append(stroke_load(mech, sf.name or f"stroke_force_{i + 1}", sf.point, sf.distance, sf.force,
                                          end=sf.end).force)
            except InputError as exc:
                problems.append((where, str(exc)))
    for i, t in enumerate(loads.torques):
        need_body(f"loads.torques[{i}].body", t.body)
        torques.append(m.BodyTorque(t.name or f"torque_{i + 1}", t.body, t.torque, _active(t.active)))
    for i, s in enumerate(loads.springs):
        need_point(f"loads.springs[{i}].point_1", s.point_1)
        need_point(f"loads.springs[{i}].point_2", s.point_2)
        springs.append(m.Spring(s.name or f"spring_{i + 1}", s.point_1, s.point_2, s.stiffness, s.free_length))
    for i, c in enumerate(problem.counterweights):
        need_body(f"counterweights[{i}].body", c.body)
        position = (c.radius * math.cos(c.angle), c.radius * math.sin(c.angle))
        masses.append(m.PointMass(c.name or f"counterweight_{i + 1}", c.body, c.mass, position, c.inertia))
    names = [x.name for x in (*forces, *torques, *springs, *masses)] + body_names
    dupes = sorted({n for n in names if names.count(n) > 1})
    if dupes:
        problems.append(
            ("loads", f"names of loads, counterweights and bodies must differ; got {', '.join(dupes)} twice")
        )
    if problems:
        raise ProblemFileError(problems)
    try:
        return replace(
            mech,
            gravity=gravity_vector(problem),
            forces=tuple(forces),
            torques=tuple(torques),
            springs=tuple(springs),
            point_masses=tuple(masses),
        )
    except InputError as exc:
        raise ProblemFileError([("mechanism", str(exc))]) from None


def _active(active):
    return None if active is None else (float(active[0]), float(active[1]))
