"""A linkage driven by a cam's follower: the follower moves the linkage's crank, the cam drives it all.

An **oscillating** follower's arm turns about its pivot with the angle psi = psi_0 + s(phi) [rad]
(:mod:`machdyn.cams.followers`; phi the cam angle [rad], s the motion program's angular displacement). In the
cam's frame (cam centre at the origin, pivot at (d, 0), the drawing mirrored about the y axis for a clockwise cam)
the arm's direction from the pivot to the roller centre makes the angle

  theta(phi) = pi - psi(phi)  (counter-clockwise cam),   theta(phi) = psi(phi)  (clockwise cam)   [rad]

with the x axis: the arm is the linkage's crank. A **translating** follower is a slide on its path; the linkage
engine's input being a turning crank, the follower is moved exactly by a massless tangent mechanism: a drive crank
about a ground point at the distance d [m] from the path, level with the middle of the stroke h [m], whose slot
(along the crank) holds a block pinned to the follower at its pitch point (a PRP dyad). The pin lies on the path
at (s - h/2) = d tan theta, so theta(phi) = arctan((s(phi) - h/2)/d) [rad].

At a constant cam speed Omega [rad/s] the crank's angle, speed and acceleration are theta, theta' Omega [rad/s] and
theta'' Omega^2 [rad/s^2] (theta' = dtheta/dphi, chain rule; no theta' dOmega/dt term at a constant cam speed);
the linkage engine takes these arrays as its crank's given speed law, unchanged.

Kinetostatics then gives the torque T_crank(phi) [N*m] the crank must receive to drive the linkage (inertia of its
bodies, gravity, springs and external loads; the follower's own body and the drive are massless here, the
follower's inertia being ``[cam.dynamics] mass``). By power balance (virtual work) the camshaft supplies it through
the follower: T_cam Omega = T_crank theta' Omega, hence

  T_cam(phi) = T_crank(phi) theta'(phi)   [N*m]

(Norton, *Design of Machinery*, 5th ed., ch. 11, the power equation; Uicker, Pennock & Shigley, *Theory of
Machines and Mechanisms*, 4th ed., ch. 17, energy methods and virtual work), and the load the cam must add along
the follower's coordinate s is M_link = T_crank dtheta/ds [N*m for an oscillating follower, N for a translating
one] (dtheta/ds = -/+1, or 1/(d (1 + u^2)) with u = (s - h/2)/d). It adds to the follower's contact force as a load
towards the cam (Norton eq 15.3 with the load F_L now a function of phi): at a constant cam speed it is
M_link = A(phi) Omega^2 + B(phi), A from the motion, B from gravity, springs and external loads (kinetostatics is
linear in the inertia loads, which scale with Omega^2), so the jump speed with the linkage is the lowest root over
phi of (m a + A) Omega^2 + c v Omega + (k s + F_0 + F_L + B) = 0.

For ``[flywheel]`` the linkage adds its reduced quantities at the camshaft, sampled at unit cam speed (where
velocities are the velocity ratios dr/dphi): J(phi) = 2 T [kg*m^2], dJ/dphi = 2 dT/dphi, the potential of gravity
and springs V(phi) [J] with slope -P_conservative, and the reduced moment of the external loads P_loads [N*m]
(Uicker, Pennock & Shigley, ch. 17, the equivalent system; the same reduction as
:func:`machdyn.dynamics.equivalent.equivalent_machine`).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from ..dynamics.equivalent import EquivalentMachine
from ..dynamics.tables import FourierCurve, PeriodicCurve
from ..errors import InputError, ProblemFileError
from ..linkage.energy import Energy, energy
from ..linkage.kinematics import kinematics
from ..linkage.kinetostatics import kinetostatics
from ..linkage.model import Mechanism
from ..linkage.motion import Kinematics, angle_ranges, format_ranges, singular
from ..linkage.reactions import Forces
from ..problem.build import build_mechanism
from ..problem.errors import did_you_mean
from ..problem.schema import (
    DYAD_SPECS,
    BodySpec,
    CustomSpec,
    DriverSpec,
    DriveSpec,
    LinkageProblem,
    LoadsSpec,
)
from .dynamics import FollowerTrain, Spring, jump_speed, least_preload, least_rate, spring_force_needed
from .followers import Follower
from .program import SVAJ, Program
from .schema import FollowerLinkageTable

TABLE = "follower_linkage"
FOLLOWER = "follower"
PIVOT = "pivot"
ROLLER = "roller"
#: the massless drive of a translating follower: a crank about ground.drive with a slot along its x axis, in which
#: a block pinned to the follower at its roller slides (a tangent mechanism)
DRIVE = "cam_drive"
BLOCK = "cam_block"
PATH = "path"
VIRTUAL = (DRIVE, BLOCK)


@dataclass(frozen=True)
class FollowerDrive:
    """The linkage's crank over cam angles phi [rad]: its angle theta [rad], theta' = dtheta/dphi [rad/rad],
    theta'' [rad/rad^2] and ratio = dtheta/ds [rad per m or rad of the follower's displacement s]; ``lever`` the
    distance of a translating follower's drive pivot from its path [m] (0 for an oscillating follower)."""

    phi: np.ndarray
    theta: np.ndarray
    d1: np.ndarray
    d2: np.ndarray
    ratio: np.ndarray
    lever: float = 0.0


def follower_drive(program: Program, follower: Follower, clockwise: bool, phi) -> FollowerDrive:
    """The crank's angle and its derivatives over the cam angles ``phi`` [rad] (module docstring): the arm of an
    oscillating follower, theta = pi - psi or psi; the drive crank of a translating one, tan theta = (s - h/2)/d
    (h the stroke, d = 2 h), whence theta' = u'/(1 + u^2), theta'' = u''/(1 + u^2) - 2 u u'^2/(1 + u^2)^2 with
    u = (s - h/2)/d (chain rule)."""
    phi = np.asarray(phi, dtype=float)
    m = program.svaj(phi)
    if follower.motion == "oscillating":
        sign = 1.0 if clockwise else -1.0
        psi = follower.start_angle + m.s
        theta = psi if clockwise else np.pi - psi
        return FollowerDrive(phi, theta, sign * m.v, sign * m.a, np.full_like(phi, sign))
    d = lever(program)
    u, u1, u2 = (m.s - 0.5 * program.stroke) / d, m.v / d, m.a / d
    q = 1.0 + u * u
    return FollowerDrive(phi, np.arctan(u), u1 / q, u2 / q - 2.0 * u * u1**2 / q**2, 1.0 / (d * q), d)


def lever(program: Program) -> float:
    """The distance d [m] of a translating follower's drive pivot from its path: twice the stroke, so that the
    drive crank stays within +-14 deg of square to the path."""
    return 2.0 * float(program.stroke)


def pivot_point(follower: Follower, clockwise: bool) -> tuple[float, float]:
    """The follower's pivot in the cam's frame [m]: (d, 0), or (-d, 0) for a clockwise cam."""
    d = float(follower.pivot_distance)
    return (-d if clockwise else d, 0.0)


def path_point(follower: Follower, clockwise: bool) -> tuple[float, float]:
    """A translating follower's pitch point at rest in the cam's frame [m]: (e, sqrt(R_p^2 - e^2)), the roller
    centre on the prime circle (:mod:`machdyn.cams.followers`), (e, R_b) for a flat face; x mirrored for a
    clockwise cam."""
    e = float(follower.offset)
    rp = float(follower.prime_radius)
    y = rp if follower.contact == "flat" else float(np.sqrt(rp * rp - e * e))
    return (-e if clockwise else e, y)


def _renamed(path: str, bodies: int, dyads: int) -> str:
    """A path of the linkage file's tables as the path of the ``[follower_linkage]`` table (the follower's own
    ``bodies`` and ``dyads`` come first in the mechanism)."""
    path = re.sub(r"^mechanism\.bodies\[(\d+)\]", lambda m: f"{TABLE}.bodies[{int(m.group(1)) - bodies}]", path)
    path = re.sub(r"^mechanism\.dyads\[(\d+)\]", lambda m: f"{TABLE}.dyads[{int(m.group(1)) - dyads}]", path)
    path = re.sub(r"^mechanism\b", TABLE, path)
    return re.sub(r"^(loads|counterweights)\b", rf"{TABLE}.\1", path)


def _body(name: str, points: dict) -> Any:
    return BodySpec.model_construct(name=name, points=points, mass=0.0, inertia=0.0, com=(0.0, 0.0))


def _drive(table: FollowerLinkageTable, follower: Follower, clockwise: bool, program: Program):
    """The follower's massless bodies, ground points, crank and dyads that move it (before the table's own)."""
    if follower.motion == "oscillating":
        body = _body(FOLLOWER, {PIVOT: (0.0, 0.0), ROLLER: (float(follower.arm_length), 0.0),
                                **table.follower_points})
        return [body], {PIVOT: pivot_point(follower, clockwise)}, (FOLLOWER, PIVOT), []
    x, y = path_point(follower, clockwise)
    centre = (x - lever(program), y + 0.5 * float(program.stroke))
    prp = DYAD_SPECS["PRP"].model_validate({
        "type": "PRP", "a": BLOCK, "b": FOLLOWER, "inner": ROLLER,
        "guide_a": {"point": f"{DRIVE}.{DRIVE}", "angle": "0 deg"},  # the slot, along the drive crank
        "guide_b": {"point": f"ground.{PATH}", "angle": "90 deg"}})  # the follower's path, +y away from the cam
    bodies = [_body(DRIVE, {DRIVE: (0.0, 0.0)}), _body(BLOCK, {ROLLER: (0.0, 0.0)}),
              _body(FOLLOWER, {ROLLER: (0.0, 0.0), **table.follower_points})]
    return bodies, {DRIVE: centre, PATH: (x, 0.0)}, (DRIVE, DRIVE), [prp]


def linkage_mechanism(table: FollowerLinkageTable, follower: Follower, clockwise: bool,
                      program: Program) -> Mechanism:
    """The :class:`~machdyn.linkage.model.Mechanism` of ``[follower_linkage]``: the follower's body ``follower``
    (massless; an oscillating follower's arm, points ``pivot``, ``roller`` and ``follower_points``, turning about
    ``ground.pivot`` as the crank; a translating follower's slide, points ``roller`` and ``follower_points``, moved
    along its path by the massless drive of :func:`follower_drive`), then the table's bodies and dyads. Raises
    :class:`~machdyn.errors.ProblemFileError` naming the table's fields."""
    own_bodies, own_ground, (crank, pivot), own_dyads = _drive(table, follower, clockwise, program)
    problems: list[tuple[str, str]] = []
    for name in own_ground:
        if name in table.ground:
            problems.append((f"{TABLE}.ground.{name}", f"'{name}' is placed by [cam.follower] for the follower's "
                                                       "motion; give the other ground points only"))
    for name in own_bodies[-1].points:
        if name in table.follower_points and name in (PIVOT, ROLLER):
            problems.append((f"{TABLE}.follower_points.{name}", f"the follower's '{name}' point is placed by "
                                                                "[cam.follower]"))
    reserved = [b.name for b in own_bodies]
    for i, b in enumerate(table.bodies):
        if b.name in reserved:
            problems.append((f"{TABLE}.bodies[{i}].name", f"'{b.name}' is the follower's own body; give the body "
                                                          "another name"))
    names = [FOLLOWER, *(b.name for b in table.bodies)]
    for i, d in enumerate(table.dyads):
        for attr in ("a", "b"):
            body = getattr(d, attr)
            if body not in names:
                problems.append((f"{TABLE}.dyads[{i}].{attr}", f"unknown body '{body}'{did_you_mean(body, names)} "
                                                              f"(bodies: {', '.join(names)})"))
    if problems:
        raise ProblemFileError(problems)
    spec = CustomSpec.model_construct(type="custom", name=table.name or TABLE, ground={**own_ground, **table.ground},
                                      crank=DriverSpec.model_construct(body=crank, pivot=f"ground.{pivot}"),
                                      bodies=[*own_bodies, *table.bodies], dyads=[*own_dyads, *table.dyads])
    loads = LoadsSpec.model_construct(gravity=table.loads.gravity, forces=table.loads.forces, stroke_forces=[],
                                      torques=table.loads.torques, springs=table.loads.springs)
    problem = LinkageProblem.model_construct(mechanism=spec, drive=DriveSpec.model_construct(speed=1.0), loads=loads,
                                             counterweights=table.counterweights)
    try:
        return build_mechanism(problem)
    except ProblemFileError as exc:
        raise ProblemFileError([(_renamed(p, len(own_bodies), len(own_dyads)), m) for p, m in exc.problems]) from None


def output_body(table: FollowerLinkageTable, mech: Mechanism) -> str:
    """The body whose travel is the linkage's output: ``output``, else the second body of the last dyad."""
    if table.output is None:
        return mech.dyads[-1].b
    names = [FOLLOWER, *(b.name for b in table.bodies)]
    if table.output not in names:
        hint = did_you_mean(table.output, names)
        raise ProblemFileError([(f"{TABLE}.output", f"unknown body '{table.output}'{hint} (bodies: "
                                                    f"{', '.join(names)})")])
    return table.output


def linkage_motion(mech: Mechanism, drive: FollowerDrive, speed: float) -> Kinematics:
    """The linkage's motion at the cam angles of ``drive`` at the constant cam speed ``speed`` [rad/s]: crank
    angle theta, speed theta' Omega and acceleration theta'' Omega^2. The result's ``crank_angle`` is the cam
    angle, so that a load's ``active`` window reads the cam angle. Raises
    :class:`~machdyn.errors.ProblemFileError` (field ``follower_linkage.dyads``) where the linkage does not close
    or is at a dead position over the follower's motion."""
    kin = kinematics(mech, drive.theta, drive.d1 * speed, drive.d2 * speed**2, on_fail="mask")
    where = f"{TABLE}.dyads"
    fails = ~np.asarray(kin.assembled, dtype=bool)
    if np.any(fails):
        at = format_ranges(angle_ranges(drive.phi, fails))
        raise ProblemFileError([(where, f"the linkage cannot be assembled at cam angles {at}: the links are too "
                                        "short or too long to close over the follower's motion")])
    dead = singular(kin.dyad_reports, kin.shape)
    if np.any(dead):
        at = format_ranges(angle_ranges(drive.phi, dead))
        raise ProblemFileError([(where, f"the linkage passes a dead (toggle) position at cam angles {at}: the "
                                        "follower cannot drive it there; change the geometry")])
    return replace(kin, crank_angle=drive.phi)


@dataclass(frozen=True)
class LinkageLoad:
    """The linkage's load on the follower over the cam angles phi [rad] at the cam speed ``speed`` [rad/s].

    forces, energy : the linkage's kinetostatics and energy (its crank moved by the follower).
    crank_torque : T_crank [N*m], the torque the crank receives to drive the linkage.
    camshaft_torque : T_crank theta' [N*m], the camshaft torque the linkage adds.
    moment : M_link = A Omega^2 + B [N*m|N], the linkage's load on the follower along its coordinate s.
    static : B [N*m|N], its part from gravity, springs and external loads (at zero speed).
    """

    drive: FollowerDrive
    speed: float
    forces: Forces
    energy: Energy
    crank_torque: np.ndarray
    camshaft_torque: np.ndarray
    moment: np.ndarray
    static: np.ndarray

    @property
    def inertial(self) -> np.ndarray:
        """A [N*m*s^2] = (M_link - B) / Omega^2, the part of M_link from the linkage's motion."""
        return (self.moment - self.static) / self.speed**2


def linkage_load(mech: Mechanism, drive: FollowerDrive, speed: float) -> LinkageLoad:
    """Kinetostatics of the linkage at the cam speed ``speed`` [rad/s] and at rest, and the torques and moment
    they put on the follower and the camshaft (module docstring)."""
    kin = linkage_motion(mech, drive, speed)
    forces = kinetostatics(mech, kinematics_result=kin)
    en = energy(mech, forces=forces)
    at_rest = kinematics(mech, drive.theta, 0.0, 0.0, on_fail="mask")
    static_crank = kinetostatics(mech, kinematics_result=replace(at_rest, crank_angle=drive.phi)).driving_torque
    t_crank = np.asarray(forces.driving_torque, dtype=float)
    return LinkageLoad(drive, float(speed), forces, en, t_crank, t_crank * drive.d1, t_crank * drive.ratio,
                       np.asarray(static_crank, dtype=float) * drive.ratio)


def jump_speed_with_linkage(svaj: SVAJ, train: FollowerTrain, spring: Spring, inertial, static) -> float:
    """The lowest cam speed [rad/s] at which the contact force with the linkage, (m a + A) w^2 + c v w +
    (k s + F_0 + F_L + B), reaches 0 somewhere (Norton, *Design of Machinery*, 5th ed., eq 15.3 with the linkage's
    load A w^2 + B; module docstring); inf if never (:func:`machdyn.cams.dynamics.jump_speed`)."""
    return jump_speed(svaj, train, spring, inertial, static)


def spring_needed(svaj: SVAJ, train: FollowerTrain, spring: Spring, inertial, static, design_speed: float,
                  stroke: float) -> tuple[float, float]:
    """The spring that keeps contact with the linkage up to ``design_speed`` [rad/s] (Norton §15.4, as
    :func:`~machdyn.cams.dynamics.size_spring` with the linkage's load): the least rate at the spring's preload
    (inf if the preload alone is too small where the follower rests) and the least preload at its rate, in the
    follower's coordinate [N*m/rad], [N*m]."""
    need = spring_force_needed(svaj, train, design_speed, inertial, static)
    return least_rate(need, svaj, spring.preload, stroke), least_preload(need, svaj, spring.rate)


def _jump_intervals(phi: np.ndarray, windows) -> np.ndarray:
    """True for each interval between the evenly spaced cam angles ``phi`` that holds a window's edge."""
    m = phi.size
    h = 2.0 * np.pi / m
    out = np.zeros(m, dtype=bool)
    for start, end in windows:
        if end - start >= 2.0 * np.pi:
            continue
        for edge in (start, end):
            u = (edge % (2.0 * np.pi)) / h
            k = int(np.floor(u)) % m
            out[k] = True
            if abs(u - round(u)) < 1e-9:
                out[(k - 1) % m] = True
    return out


def with_linkage(machine: EquivalentMachine, mech: Mechanism, program: Program, follower: Follower,
                 clockwise: bool, positions: int) -> EquivalentMachine:
    """The cam's reduced machine with the linkage's reduced inertia, potential and load moment added at the
    camshaft, node by node with their exact slopes (module docstring); the cam's damping kept."""
    if int(positions) != positions or positions < 16:
        raise InputError(f"The number of cam positions must be an integer >= 16; got {positions!r}.")
    phi = np.arange(int(positions)) * (2.0 * np.pi / int(positions))
    period = 2.0 * np.pi
    drive = follower_drive(program, follower, clockwise, phi)
    forces = kinetostatics(mech, kinematics_result=linkage_motion(mech, drive, 1.0))
    en = energy(mech, forces=forces)
    kinetic = np.asarray(en.kinetic_total, dtype=float)
    d_kinetic = np.asarray(en.energy_rate + en.conservative_power, dtype=float)  # dT/dphi at unit cam speed

    def add(curve, values, slopes):
        return PeriodicCurve.hermite(phi, np.asarray(curve(phi)) + values,
                                     np.asarray(curve.derivative(phi)) + slopes, period)

    inertia = add(machine.inertia, 2.0 * kinetic, 2.0 * d_kinetic)
    potential = add(machine.potential, np.asarray(en.potential, dtype=float),
                    -np.asarray(en.conservative_power, dtype=float))
    load = np.asarray(machine.moment(phi)) + np.asarray(en.load_power, dtype=float)
    windows = [f.active for f in mech.forces if f.active is not None]
    windows += [t.active for t in mech.torques if t.active is not None]
    jumps = _jump_intervals(phi, windows)
    moment: Any
    if jumps.any():
        moment = PeriodicCurve.smooth_with_jumps(phi, load, period, jumps)
    else:
        fourier = FourierCurve.from_samples(load, period)
        moment = fourier if fourier.resolved else PeriodicCurve.spline(phi, load, period)
    return EquivalentMachine(inertia, potential, moment, machine.damping, machine.forces, machine.mechanism,
                             machine.speed_loads, machine.single)
