"""A shaft line built from its problem file, and everything its analysis computes (SI).

:func:`build` turns a validated :class:`~machdyn.shafts.schema.ShaftLineProblem` into a :class:`ShaftLine` of the
engine's objects, collecting every mistake as (path, message); :func:`analyse` computes the loads, harmonics,
bearing reactions, the balance, the grade check, the locomotive's figures and the field balance.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import InputError, ProblemFileError
from ..problem.build import build_mechanism
from ..problem.schema import DriveSpec, LinkageProblem, LoadsSpec
from .balance import (
    BalanceResult,
    Plane,
    equivalent_in_planes,
    first_harmonic_corrections,
    single_plane,
    two_plane,
)
from .field import FieldBalance, Reading, TrialRun, split_onto_holes
from .field import single_plane as field_single
from .field import two_plane as field_two
from .frame6 import Frame6, Mount6, Response6, modes6, steady_response
from .grades import GRADES, GradeCheck, allocate, permissible_unbalance
from .linkages import LinkagePlane, linkage_loads
from .locomotive import LocomotiveBalance, locomotive_balance
from .phases import PhaseSearch, search_phases
from .reciprocating import Cylinder, EngineOrders, engine_orders, reciprocating_loads
from .rotating import Bearing, Mass, Reactions, ShaftLoads, bearing_reactions, cycle, rotating_loads

__all__ = ["ShaftLine", "ShaftLineResult", "build", "analyse"]


@dataclass(frozen=True)
class ShaftLine:
    """The engine's objects of a shaft-line problem."""

    speed: float
    positions: int
    harmonics: int
    reference: float
    masses: tuple[Mass, ...]
    cylinders: tuple[Cylinder, ...]
    bearings: tuple[Bearing, ...]
    planes: tuple[Plane, ...]
    holes: tuple[tuple[float, ...], ...]
    field: FieldBalance | None
    field_holes: tuple[tuple[float, ...], ...]
    field_names: tuple[str, ...]
    frame: Frame6 | None = None
    reciprocating_share: float = 0.0
    field_runs: tuple[tuple[Reading, ...], ...] = ()  # original and trial-run readings as entered (for the report)
    linkages: tuple[LinkagePlane, ...] = ()
    balance_target: str = "rotating"
    mass_unit: str = "kg"  # the unit the file writes masses in: the summary and report show corrections in it
    resolution: float | None = None  # [kg] the corrections as fitted are rounded to multiples of this

    def balanced_masses(self) -> list[Mass]:
        """The masses the corrections balance: rotating masses, the cylinders' rotating masses and the share c of
        their reciprocating masses as if revolving at the crank pins."""
        out = [*self.masses, *(c.crank_mass() for c in self.cylinders)]
        c = self.reciprocating_share
        out += [Mass(f"{cy.name} reciprocating share", c * cy.reciprocating_mass, cy.crank, cy.phase, cy.position)
                for cy in self.cylinders if c > 0]
        return out


def _holes(count: int, first: float) -> tuple[float, ...]:
    return tuple(first + 2 * math.pi * k / count for k in range(count)) if count else ()


def _try(problems: list, path: str, make: Any) -> Any:
    try:
        return make()
    except InputError as exc:
        problems.append((path, str(exc)))
        return None


def _field(spec: Any, problems: list) -> FieldBalance | None:
    n = len(spec.planes)
    for i, r in enumerate(spec.original):
        if r.phase is None:
            problems.append((f"field_balancing.original[{i}].phase", "a reading without a phase reference cannot "
                             "enter influence-coefficient balancing: measure the 1x phase against a "
                             "once-per-revolution mark (keyphasor, optical tachometer)"))
    for j, t in enumerate(spec.trials):
        for i, r in enumerate(t.readings):
            if r.phase is None:
                problems.append((f"field_balancing.trials[{j}].readings[{i}].phase", "a reading without a phase "
                                 "reference cannot enter influence-coefficient balancing"))
    if len(spec.original) != n:
        problems.append(("field_balancing.original", f"{n} correction plane(s) need {n} sensor reading(s) per run; "
                         f"got {len(spec.original)}"))
    if sorted(t.plane for t in spec.trials) != list(range(1, n + 1)):
        problems.append(("field_balancing.trials", f"each of the {n} plane(s) needs exactly one trial run; got the "
                         f"planes {[t.plane for t in spec.trials]}"))
    if problems:
        return None
    original = [Reading(r.amplitude, r.phase) for r in spec.original]
    trials = [TrialRun(t.plane - 1, t.mass, t.angle, tuple(Reading(r.amplitude, r.phase) for r in t.readings),
                       t.removed) for t in spec.trials]
    if n == 1:
        t = trials[0]
        return _try(problems, "field_balancing", lambda: field_single(original[0], t.mass, t.angle, t.readings[0],
                                                                      t.removed))
    return _try(problems, "field_balancing", lambda: field_two(original, trials))


def _linkage(spec: Any, where: str, speed: float, problems: list) -> LinkagePlane | None:
    try:
        drive = DriveSpec.model_construct(speed=speed, acceleration=0.0, positions=360, start=None, stop=None)
        mech = build_mechanism(LinkageProblem.model_construct(
            mechanism=spec.mechanism, drive=drive, loads=LoadsSpec(gravity="off"),
            counterweights=list(spec.counterweights)))
    except ProblemFileError as exc:
        problems += [(f"{where}.{path}", message) for path, message in exc.problems]
        return None
    plane = _try(problems, where, lambda: LinkagePlane(spec.name, mech, spec.position, spec.phase, spec.axis))
    if plane is not None and speed > 0:  # every crank angle of the turn must assemble
        _try(problems, where, lambda: linkage_loads((plane,), speed, np.linspace(0, 2 * np.pi, 36, endpoint=False)))
    return plane


def _runs(problem: Any) -> tuple[tuple[Reading, ...], ...]:
    fb = problem.field_balancing
    if fb is None:
        return ()
    runs = [tuple(Reading(r.amplitude, r.phase) for r in fb.original)]
    runs += [tuple(Reading(r.amplitude, r.phase) for r in t.readings) for t in fb.trials]
    return tuple(runs)


def build(problem: Any) -> tuple[ShaftLine | None, list[tuple[str, str]]]:
    """The :class:`ShaftLine` of a validated problem and every mistake found building it."""
    problems: list[tuple[str, str]] = []
    s = problem.shaft_line
    if s.speed <= 0:
        problems.append(("shaft_line.speed", f"must be > 0 rad/s; got {s.speed:g} rad/s"))
    linkages = tuple(lk for i, spec in enumerate(problem.linkages)
                     if (lk := _linkage(spec, f"linkages[{i}]", s.speed, problems)) is not None)
    if not problem.masses and not problem.cylinders and not problem.linkages and problem.field_balancing is None and \
            getattr(problem, "field_records", None) is None:
        problems.append(("shaft_line", "a shaft line needs [[masses]], [[cylinders]], [[linkages]], "
                         "[field_balancing] or [field_records]"))
    for table, items in (("masses", problem.masses), ("cylinders", problem.cylinders), ("bearings", problem.bearings)):
        names = [m.name for m in items]
        for i, name in enumerate(names):
            if name in names[:i]:
                problems.append((f"{table}[{i}].name", f"must be unique; '{name}' is used twice"))
    masses = tuple(m for i, spec in enumerate(problem.masses) if (m := _try(
        problems, f"masses[{i}]", lambda spec=spec: Mass(spec.name, spec.mass, spec.radius, spec.angle,
                                                          spec.position))) is not None)
    cylinders = tuple(c for i, spec in enumerate(problem.cylinders) if (c := _try(
        problems, f"cylinders[{i}]", lambda spec=spec: Cylinder(
            spec.name, spec.position, spec.phase, spec.axis, spec.crank, spec.rod, spec.reciprocating_mass,
            spec.rotating_mass))) is not None)
    bearings = tuple(Bearing(b.name, b.position, b.stiffness) for b in problem.bearings)
    if len(bearings) == 1:
        problems.append(("bearings", "bearing reactions need at least two bearings; got one"))
    elif len(bearings) >= 2 and np.ptp([b.position for b in bearings]) == 0.0:
        problems.append(("bearings", f"the bearings must stand at distinct axial positions; all at "
                         f"{bearings[0].position:g} m"))
    planes: tuple[Plane, ...] = ()
    holes: tuple[tuple[float, ...], ...] = ()
    if problem.balance is not None:
        planes = tuple(Plane(p.name, p.position, p.radius) for p in problem.balance.planes)
        holes = tuple(_holes(p.holes, p.first_hole) for p in problem.balance.planes)
        if len(planes) == 2 and abs(planes[0].position - planes[1].position) <= 1e-9 * max(
                1.0, abs(planes[0].position)):
            problems.append(("balance.planes[1].position", f"the two correction planes must stand at different "
                             f"axial positions (a couple cannot be corrected in one plane); both are at "
                             f"{planes[0].position:g} m"))
        if problem.balance.target == "first_harmonic" and problem.balance.reciprocating_fraction > 0:
            problems.append(("balance.reciprocating_fraction", "applies to target \"rotating\"; the first "
                             "harmonic's target already takes all a counterweight can reach"))
        if any(0 < p.holes < 2 for p in problem.balance.planes):
            problems.append(("balance.planes", "a split onto fixed holes needs at least 2 holes"))
    g = problem.grade
    if g is not None:
        if not any(abs(g.G - v) <= 1e-9 * v for v in GRADES):
            problems.append(("grade.G", f"must be one of ISO 21940-11's grades {', '.join(f'{v:g}' for v in GRADES)}"
                             f" (mm/s); got {g.G:g}"))
        names = [b.name for b in bearings]
        pair = g.bearings or tuple(names[:2])
        if len(bearings) < 2:
            problems.append(("grade", "the grade check allocates the permissible unbalance to two bearing planes: "
                             "give at least two [[bearings]]"))
        elif any(n not in names for n in pair):
            problems.append(("grade.bearings", f"must name two of the bearings {names}; got {list(pair)}"))
        else:
            za, zb = (next(b.position for b in bearings if b.name == n) for n in pair)
            com = 0.5 * (za + zb) if g.centre is None else g.centre
            if za == zb:
                problems.append(("grade.bearings", "the two bearings of the grade check must stand apart"))
            elif not min(za, zb) <= com <= max(za, zb):
                problems.append(("grade.centre", f"the allocation of ISO 21940-11 is for a centre of mass between "
                                 f"the bearings ({min(za, zb):g} ... {max(za, zb):g} m); got {com:g} m"))
        if g.state == "balanced" and problem.balance is None:
            problems.append(("grade.state", "'balanced' checks the rotor after its corrections: give [balance] "
                             "or set state = \"as_given\""))
    loco = problem.locomotive
    if loco is not None:
        if not cylinders:
            problems.append(("locomotive", "the locomotive's balance needs its [[cylinders]]"))
        if loco.dead_load is not None and not loco.dead_load > 0:
            problems.append(("locomotive.dead_load", f"must be > 0 N; got {loco.dead_load:g} N"))
        if loco.wheel_planes[0] == loco.wheel_planes[1]:
            problems.append(("locomotive.wheel_planes", f"the two wheel planes must stand apart; both at "
                             f"{loco.wheel_planes[0]:g} m"))
    field = None
    field_holes: tuple[tuple[float, ...], ...] = ()
    names_f: tuple[str, ...] = ()
    if problem.field_balancing is not None:
        fp: list[tuple[str, str]] = []
        field = _field(problem.field_balancing, fp)
        problems += fp
        field_holes = tuple(_holes(p.holes, p.first_hole) for p in problem.field_balancing.planes)
        names_f = tuple(p.name for p in problem.field_balancing.planes)
    frame = None
    if problem.frame is not None:
        fs = problem.frame
        mounts = tuple(m for i, ms in enumerate(fs.mounts) if (m := _try(
            problems, f"frame.mounts[{i}]", lambda ms=ms: Mount6(ms.name, ms.position, ms.direction, ms.stiffness,
                                                                  ms.damping))) is not None)
        if len(mounts) == len(fs.mounts):
            frame = _try(problems, "frame", lambda: Frame6(fs.mass, fs.inertia, mounts, fs.com,
                                                            tuple(fs.gravity) if fs.gravity else (0.0, 0.0, 0.0)))
        if frame is not None:
            _try(problems, "frame.mounts", lambda: modes6(frame))
        if not masses and not cylinders and not problem.linkages:
            problems.append(("frame", "the frame's response needs the shaft line's [[masses]], [[cylinders]] or "
                             "[[linkages]]"))
        if fs.orders >= s.positions // 2:
            problems.append(("frame.orders", f"must be < {s.positions // 2} for {s.positions} angles per turn; "
                             f"got {fs.orders}"))
    if problem.phase_search is not None:
        ps = problem.phase_search
        if not cylinders:
            problems.append(("phase_search", "the search of crank phases needs [[cylinders]]"))
        else:
            _try(problems, "phase_search", lambda: search_phases(cylinders, ps.cylinders, ps.objective, ps.step,
                                                                 1.0, s.reference))
    if problems:
        return None, problems
    return ShaftLine(s.speed, s.positions, s.harmonics, s.reference, masses, cylinders, bearings, planes, holes,
                     field, field_holes, names_f, frame=frame,
                     reciprocating_share=problem.balance.reciprocating_fraction if problem.balance is not None else 0.0,
                     field_runs=_runs(problem), linkages=linkages,
                     balance_target=problem.balance.target if problem.balance is not None else "rotating",
                     mass_unit=getattr(problem, "mass_unit", "kg"),
                     resolution=problem.balance.resolution if problem.balance is not None else None), []


@dataclass(frozen=True)
class ShaftLineResult:
    """Everything a shaft-line run computes (SI)."""

    line: ShaftLine
    loads: ShaftLoads
    reactions: Reactions | None
    engine: EngineOrders | None
    balance: BalanceResult | None
    reactions_after: Reactions | None
    splits: tuple[dict[int, float], ...]
    applied: tuple[Mass, ...]
    grade: GradeCheck | None
    locomotive: LocomotiveBalance | None
    field_splits: tuple[dict[int, float], ...]
    frame_frequencies: np.ndarray | None = None
    frame_response: Response6 | None = None
    phases: PhaseSearch | None = None
    linkage_torque: np.ndarray | None = None


def _applied(line: ShaftLine, balance: BalanceResult, splits: tuple[dict[int, float], ...],
             resolution: float | None) -> tuple[Mass, ...]:
    """The correction masses as fitted: in the holes when the plane has holes, rounded to ``resolution``."""
    out = []
    for c, split, holes in zip(balance.corrections, splits, line.holes, strict=True):
        parts = [(m, holes[k], f"{c.plane.name} hole {k + 1}") for k, m in split.items()] if holes else \
            [(c.mass, c.angle, f"correction {c.plane.name}")]
        for m, a, name in parts:
            fitted = m if resolution is None else round(m / resolution) * resolution
            out.append(Mass(name, fitted, c.plane.radius, a, c.plane.position))
    return tuple(out)


def _grade(problem: Any, line: ShaftLine, applied: tuple[Mass, ...]) -> GradeCheck:
    g = problem.grade
    names = [b.name for b in line.bearings]
    pair = g.bearings or tuple(names[:2])
    za, zb = (next(b.position for b in line.bearings if b.name == n) for n in pair)
    com = 0.5 * (za + zb) if g.centre is None else g.centre
    u_per = permissible_unbalance(g.G, g.rotor_mass, line.speed)
    allowed = allocate(u_per, com, za, zb)
    masses = list(line.masses) + (list(applied) if g.state == "balanced" else [])
    ua, ub = equivalent_in_planes(masses, za, zb)
    return GradeCheck(g.G, g.rotor_mass, line.speed, u_per, allowed, (abs(ua), abs(ub)), (pair[0], pair[1]))


def analyse(problem: Any, line: ShaftLine) -> ShaftLineResult:
    """Loads over the turn (rotating masses + cylinders, exact), harmonics, reactions, balance and checks."""
    theta = cycle(line.positions)
    loads = rotating_loads(line.masses, line.speed, theta, line.reference)
    engine = None
    if line.cylinders:
        engine = engine_orders(line.cylinders, line.speed, line.positions, min(line.harmonics, line.positions // 2 - 1),
                               line.reference, include_rotating=True)
        loads = loads + reciprocating_loads(line.cylinders, line.speed, theta, line.reference)
    torque = None
    if line.linkages:
        extra, torque = linkage_loads(line.linkages, line.speed, theta, line.reference)  # torques per linkage
        loads = loads + extra
    reactions = bearing_reactions(loads, line.bearings) if len(line.bearings) >= 2 else None
    balance = None
    splits: tuple[dict[int, float], ...] = ()
    reactions_after = None
    applied: tuple[Mass, ...] = ()
    if line.planes:
        rotating = line.balanced_masses()
        if problem.balance.target == "first_harmonic":
            balance = BalanceResult(first_harmonic_corrections(loads, line.planes), loads, loads)
        elif len(line.planes) == 2:
            balance = two_plane(rotating, line.planes[0], line.planes[1], line.speed, theta, line.reference)
        else:
            balance = single_plane(rotating, line.planes[0], line.speed, theta, line.reference)
        splits = tuple(split_onto_holes(c.mass, c.angle, h) if h else {} for c, h in
                       zip(balance.corrections, line.holes, strict=True))
        applied = _applied(line, balance, splits, problem.balance.resolution)
        after = loads + rotating_loads(applied, line.speed, theta, line.reference)
        balance = BalanceResult(balance.corrections, loads, after)
        reactions_after = bearing_reactions(after, line.bearings) if len(line.bearings) >= 2 else None
    grade = _grade(problem, line, applied) if problem.grade is not None else None
    loco = None
    if problem.locomotive is not None:
        lo = problem.locomotive
        loco = locomotive_balance(line.cylinders, lo.wheel_planes, lo.radius, lo.fraction, line.speed, lo.dead_load)
    field_splits: tuple[dict[int, float], ...] = ()
    if line.field is not None:
        f = line.field
        field_splits = tuple(split_onto_holes(m, a, h) if h else {} for m, a, h in
                             zip(f.correction_mass, f.correction_angle, line.field_holes, strict=True))
    freqs = response = None
    if line.frame is not None:
        fs = problem.frame
        freqs, _ = modes6(line.frame)
        response = steady_response(line.frame, balance.after if balance is not None else loads, fs.shaft,
                                   fs.orders, {p.name: p.position for p in fs.points})
    phases = None
    if problem.phase_search is not None:
        ps = problem.phase_search
        phases = search_phases(line.cylinders, ps.cylinders, ps.objective, ps.step, line.speed, line.reference)
    return ShaftLineResult(line, loads, reactions, engine, balance, reactions_after, splits, applied, grade, loco,
                           field_splits, freqs, response, phases, torque)
