"""The frozen model of a planar linkage: bodies, ground points, the driving crank, dyads and loads.

A class-II planar linkage is a driving crank plus a sequence of dyads (Assur groups of two bodies and three
joints). Each dyad connects two new bodies to points that are already known (on the ground, the crank or the
bodies of earlier dyads). Joints are identified by name: the joint ``"B"`` between bodies ``coupler`` and
``rocker`` is the point ``"B"`` of each body. A known point is written ``"body.point"``; ground points are
``"ground.NAME"``.

Every numeric parameter may be a float or an array of design variants (leading axis = designs); all
analyses broadcast over designs x crank positions. Values are SI: m, kg, kg*m^2, rad, N, N*m, N/m.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, fields, is_dataclass, replace
from typing import Any

import numpy as np

from ..constants import DOWNWARD_GRAVITY
from ..errors import InputError, check_finite, check_positive
from .dyad_types import PRP, RPR, RRP, RRR, Dyad, Guide
from .refs import GROUND, Array, Number, Vec, split_ref

__all__ = [
    "GROUND", "PRP", "RPR", "RRP", "RRR", "Array", "Body", "BodyTorque", "Crank", "Dyad", "Guide", "LoadValue",
    "Mechanism", "Number", "PointForce", "PointMass", "Spring", "Vec", "joints", "split_ref", "stack_designs",
    "validate",
]


@dataclass(frozen=True)
class Body:
    """A rigid body: mass [kg], centroidal moment of inertia [kg*m^2], centre of mass and named points [m]
    in the body frame."""

    name: str
    points: Mapping[str, Vec]
    mass: Number = 0.0
    inertia: Number = 0.0
    com: Vec = (0.0, 0.0)


@dataclass(frozen=True)
class PointMass:
    """A mass rigidly attached to a body, e.g. a counterweight on the crank; reported on its own in energy.

    ``position`` [m] is in the frame of ``body``; ``inertia`` [kg*m^2] is about the mass's own centre.
    """

    name: str
    body: str
    mass: Number
    position: Vec
    inertia: Number = 0.0


@dataclass(frozen=True)
class Crank:
    """The driver: ``body`` turns about the ground point ``pivot`` (written ``"ground.O"``).

    The crank body must have a point with the pivot's name. Its frame turns with the crank angle phi, so a
    crank pin at angle ``beta`` in the body frame sits at phi + beta: several mechanisms sharing one shaft
    with different phase angles are pins at different angles on the one crank body.
    """

    body: str
    pivot: str


#: A load value: a constant, or a function of the crank angle phi [rad] (array in, array out).
LoadValue = Number | Callable[[Array], Array]


@dataclass(frozen=True)
class PointForce:
    """An external force [N] at a named point, in global axes; ``fx``/``fy`` may be functions of the crank
    angle. ``active`` = (start, end) [rad] limits it to part of the cycle (wrapping through 2*pi allowed)."""

    name: str
    point: str
    fx: LoadValue = 0.0
    fy: LoadValue = 0.0
    active: tuple[float, float] | None = None


@dataclass(frozen=True)
class BodyTorque:
    """An external torque [N*m] on a body (counter-clockwise positive), constant or a function of phi."""

    name: str
    body: str
    torque: LoadValue
    active: tuple[float, float] | None = None


@dataclass(frozen=True)
class Spring:
    """A linear spring [N/m] between two named points: force = stiffness * (length - free_length), pulling
    the points together when stretched."""

    name: str
    point_1: str
    point_2: str
    stiffness: Number
    free_length: Number


@dataclass(frozen=True)
class Mechanism:
    """A planar linkage: ground points, bodies, the driving crank, dyads in solution order, and loads.

    ``gravity`` [m/s^2] is a vector (default standard gravity, 9.80665 m/s^2, towards -y); use (0, 0) to switch
    it off.
    """

    name: str
    ground: Mapping[str, Vec]
    bodies: tuple[Body, ...]
    crank: Crank
    dyads: tuple[Dyad, ...] = ()
    point_masses: tuple[PointMass, ...] = ()
    forces: tuple[PointForce, ...] = ()
    torques: tuple[BodyTorque, ...] = ()
    springs: tuple[Spring, ...] = ()
    gravity: Vec = DOWNWARD_GRAVITY
    _index: dict = field(default_factory=dict, init=False, repr=False, compare=False)
    _designs: int | None = field(default=None, init=False, repr=False, compare=False)
    #: Derived data kept with the (immutable) model, such as the fused engine's code and parameter table.
    _derived: dict = field(default_factory=dict, init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "bodies", tuple(self.bodies))
        object.__setattr__(self, "dyads", tuple(self.dyads))
        object.__setattr__(self, "_index", {b.name: b for b in self.bodies})
        sizes = {np.size(v) for v in _numeric_leaves(self) if np.ndim(v) > 0}
        object.__setattr__(self, "_designs", max(sizes) if sizes else None)
        validate(self, sizes)

    def body(self, name: str) -> Body:
        try:
            return self._index[name]
        except KeyError:
            raise InputError(
                f"Mechanism '{self.name}' has no body '{name}'; bodies: {', '.join(self._index)}."
            ) from None

    @property
    def moving_bodies(self) -> tuple[str, ...]:
        names = [self.crank.body]
        for d in self.dyads:
            names += [d.a, d.b]
        return tuple(names)

    @property
    def design_count(self) -> int | None:
        """The number of design variants (length of the array parameters), or None if all are scalars."""
        return self._designs

    def point_local(self, ref: str) -> Vec:
        """The body-frame coordinates [m] of a point written ``"body.point"``."""
        body, point = split_ref(ref)
        if body == GROUND:
            return self.ground[point]
        return self.body(body).points[point]

    def take_designs(self, index) -> Mechanism:
        """The mechanism restricted to the design variants ``index`` (slice or index array)."""
        return _take(self, index, self.design_count)


def joints(mech: Mechanism) -> list[tuple[str, str, str, str]]:
    """Every joint as (name, kind 'R' or 'P', body 1, body 2), body 1 being the earlier (known) body, in
    solution order. A name used by several joints (two rods on one crank pin 'A') is kept for the first and
    written 'A:body2' for the others."""
    out = [(mech.crank.pivot.split(".")[1], "R", GROUND, mech.crank.body)]
    for d in mech.dyads:
        out += d.joints()
    seen: set[str] = set()
    unique = []
    for name, kind, body_1, body_2 in out:
        key = name if name not in seen else f"{name}:{body_2}"
        seen.add(key)
        unique.append((key, kind, body_1, body_2))
    return unique


# ---------------------------------------------------------------------------------------------- validation


def validate(mech: Mechanism, sizes: set[int]) -> None:
    """Check names, references, masses and finiteness; raise :class:`InputError` naming field and value."""
    label = f"mechanism '{mech.name}'"
    names = [b.name for b in mech.bodies]
    if GROUND in names:
        raise InputError(f"The body name '{GROUND}' is reserved for the frame in {label}.")
    dupes = sorted({n for n in names if names.count(n) > 1})
    if dupes:
        raise InputError(f"Body names must be unique in {label}; got {', '.join(dupes)} more than once.")
    # Point masses are reported beside the bodies (kinetic energy per name): their names must not clash.
    mass_names = names + [pm.name for pm in mech.point_masses]
    clash = sorted({n for n in mass_names if mass_names.count(n) > 1} - set(dupes))
    if clash:
        raise InputError(
            f"Point-mass names must differ from each other and from body names in {label}; "
            f"got {', '.join(clash)} more than once."
        )
    for b in mech.bodies:
        check_positive(f"mass of body '{b.name}'", b.mass, "kg", allow_zero=True)
        check_positive(f"moment of inertia of body '{b.name}'", b.inertia, "kg*m^2", allow_zero=True)
        for coord in b.com:
            check_finite(f"centre of mass of body '{b.name}'", coord, "m")
        for pname, xy in b.points.items():
            for coord in xy:
                check_finite(f"point '{pname}' of body '{b.name}'", coord, "m")
    for gname, xy in mech.ground.items():
        for coord in xy:
            check_finite(f"ground point '{gname}'", coord, "m")
    for pm in mech.point_masses:
        check_positive(f"mass of '{pm.name}'", pm.mass, "kg", allow_zero=True)
        check_positive(f"moment of inertia of '{pm.name}'", pm.inertia, "kg*m^2", allow_zero=True)
        mech.body(pm.body)

    known = {GROUND}
    if split_ref(mech.crank.pivot)[0] != GROUND:
        raise InputError(f"The crank pivot must be a ground point 'ground.NAME'; got {mech.crank.pivot!r}.")
    _require_point(mech, mech.crank.pivot, "crank.pivot", known)
    crank = mech.body(mech.crank.body)
    pivot = split_ref(mech.crank.pivot)[1]
    if pivot not in crank.points:
        raise InputError(f"The crank body '{crank.name}' needs a point '{pivot}' at the pivot.")
    known.add(crank.name)
    placed = {crank.name}
    for i, d in enumerate(mech.dyads):
        where = f"dyad {i + 1} ({d.kind} {d.a}-{d.b})"
        for body in (d.a, d.b):
            mech.body(body)
            if body in placed:
                raise InputError(f"Body '{body}' of {where} is already placed by an earlier group.")
        if d.a == d.b:
            raise InputError(f"The two bodies of {where} must differ; got '{d.a}' twice.")
        if d.has_branch and getattr(d, "branch", None) not in (1, -1):
            raise InputError(f"The branch of {where} must be +1 or -1; got {getattr(d, 'branch', None)!r}.")
        for attr, ref in d.known_points():
            _require_point(mech, ref, f"{where}.{attr}", known)
        for attr, g in d.guides():
            check_finite(f"angle of {where}.{attr}", g.angle, "rad")
        _require_own_points(mech, d, where)
        known |= {d.a, d.b}
        placed |= {d.a, d.b}
    moving = set(mech.moving_bodies)
    stray = [b.name for b in mech.bodies if b.name not in moving]
    if stray:
        raise InputError(
            f"Body '{stray[0]}' of {label} is not moved by the crank or any dyad; add it to a dyad or remove it."
        )
    for f in mech.forces:
        _require_point(mech, f.point, f"force '{f.name}'.point", known)
    for t in mech.torques:
        mech.body(t.body)
    for s in mech.springs:
        _require_point(mech, s.point_1, f"spring '{s.name}'.point_1", known)
        _require_point(mech, s.point_2, f"spring '{s.name}'.point_2", known)
        check_positive(f"stiffness of spring '{s.name}'", s.stiffness, "N/m", allow_zero=True)
        check_positive(f"free length of spring '{s.name}'", s.free_length, "m", allow_zero=True)
    for coord in mech.gravity:
        check_finite("gravity", coord, "m/s^2")
    if len(sizes) > 1:
        raise InputError(
            f"All design-variant arrays of {label} must have the same length; got lengths {sorted(sizes)}."
        )


def _require_point(mech: Mechanism, ref: str, field_name: str, known: set[str]) -> None:
    body, point = split_ref(ref)
    if body == GROUND:
        if point not in mech.ground:
            raise InputError(
                f"The {field_name} refers to ground point '{point}', which does not exist; "
                f"ground points: {', '.join(mech.ground) or 'none'}."
            )
        return
    b = mech.body(body)
    if body not in known:
        raise InputError(
            f"The {field_name} refers to '{ref}' on body '{body}', which is not placed before this group."
        )
    if point not in b.points:
        raise InputError(
            f"The {field_name} refers to point '{point}' of body '{body}', which has points "
            f"{', '.join(b.points) or 'none'}."
        )


def _require_own_points(mech: Mechanism, d: Dyad, where: str) -> None:
    for body, point in d.own_points():
        if point not in mech.body(body).points:
            raise InputError(f"Body '{body}' of {where} needs a point '{point}' for its joint.")


# ---------------------------------------------------------------------------------------- design variants


def _numeric_leaves(obj: Any):
    if isinstance(obj, np.ndarray):
        yield obj
    elif is_dataclass(obj) and not isinstance(obj, type):
        for f in fields(obj):
            if f.init:
                yield from _numeric_leaves(getattr(obj, f.name))
    elif isinstance(obj, Mapping):
        for v in obj.values():
            yield from _numeric_leaves(v)
    elif isinstance(obj, tuple | list):
        for v in obj:
            yield from _numeric_leaves(v)


def _take(obj: Any, index, n: int | None):
    if isinstance(obj, np.ndarray):
        return obj[index] if obj.ndim > 0 and n is not None else obj
    if is_dataclass(obj) and not isinstance(obj, type):
        changes = {f.name: _take(getattr(obj, f.name), index, n) for f in fields(obj) if f.init}
        return replace(obj, **changes)
    if isinstance(obj, Mapping):
        return {k: _take(v, index, n) for k, v in obj.items()}
    if isinstance(obj, tuple):
        return tuple(_take(v, index, n) for v in obj)
    return obj


def stack_designs(variants: list[Mechanism] | tuple[Mechanism, ...], name: str | None = None) -> Mechanism:
    """One mechanism whose numeric parameters are arrays over ``variants``: design variants that share their
    structure (bodies, points, dyads, loads) and differ in numbers, analysed together in one vectorised call.

    Parameters equal in every variant stay scalars. Raises :class:`InputError` if the variants differ in
    structure (names, dyad types, branches, load functions).
    """
    variants = list(variants)
    if not variants:
        raise InputError("stack_designs needs at least one mechanism; got none.")
    if any(v.design_count is not None for v in variants):
        raise InputError("stack_designs takes single designs; one of the mechanisms already has design arrays.")
    first = variants[0]
    stacked = _stack([v for v in variants], "mechanism")
    return replace(stacked, name=name or first.name)


def _stack(items: list, path: str):
    first = items[0]
    numbers = all(isinstance(v, int | float) and not isinstance(v, bool) for v in items)
    if numbers and not path.endswith(".branch"):  # the assembly branch is structure, not a parameter
        values = np.array([float(v) for v in items])
        return float(values[0]) if np.all(values == values[0]) else values
    if is_dataclass(first) and not isinstance(first, type):
        if any(type(v) is not type(first) for v in items):
            raise InputError(f"The design variants differ in structure at {path}: {type(first).__name__} vs others.")
        changes = {
            f.name: _stack([getattr(v, f.name) for v in items], f"{path}.{f.name}") for f in fields(first) if f.init
        }
        return replace(first, **changes)
    if isinstance(first, Mapping):
        if any(list(v.keys()) != list(first.keys()) for v in items):
            raise InputError(f"The design variants differ in structure at {path}: different names.")
        return {k: _stack([v[k] for v in items], f"{path}.{k}") for k in first}
    if isinstance(first, tuple):
        if any(len(v) != len(first) for v in items):
            raise InputError(f"The design variants differ in structure at {path}: different numbers of items.")
        return tuple(_stack([v[i] for v in items], f"{path}[{i}]") for i in range(len(first)))
    if any(v != first for v in items):
        other = next(v for v in items if v != first)
        raise InputError(f"The design variants differ in structure at {path}: {first!r} vs {other!r}.")
    return first


def output_bodies(mech: Mechanism) -> list[tuple[str, str]]:
    """The outputs of a mechanism whose limit positions, strokes and time ratios matter, in dyad order.

    The one definition of an output: each dyad declares its own (``Dyad.outputs``), a slider on a ground
    guide (its travel) or a rocker pinned to the ground (its angle).

    Parameters
    ----------
    mech : Mechanism
        The mechanism.

    Returns
    -------
    list of (str, str)
        (body, "slide" or "angle") of each output.

    Examples
    --------
    >>> from machdyn.linkage import four_bar, slider_crank
    >>> output_bodies(four_bar(0.02, 0.08, 0.07, 0.09)), output_bodies(slider_crank(0.1, 0.3))
    ([('rocker', 'angle')], [('slider', 'slide')])
    """
    return [(out.body, out.kind) for d in mech.dyads for out in d.outputs()]
