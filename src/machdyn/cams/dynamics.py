"""The cam machine's dynamics: follower train, return spring sized against jump, contact force, camshaft torque,
a forward simulation of the follower with contact, and the reduced inertia and moment for the flywheel.

The follower train is one lumped mass on its path (Norton, *Design of Machinery*, 5th ed., §15.3, fig 15-4 and
eq 15.1; Rothbart, *Cam Design Handbook*, ch. 9): mass m [kg] of a translating follower (or moment of inertia
about the pivot [kg*m^2] of an oscillating one, when every force below is a moment about the pivot and every
length an angle), return spring of rate k [N/m] and preload F_0 [N] (its force k s + F_0 at displacement s),
viscous damping c [N*s/m] and a constant load F_L [N] pushing the follower towards the cam (its weight on a
vertical path, a process force). At a constant cam speed omega [rad/s] the force the cam must supply along the
follower's path is (Norton eq 15.3, force-closed cam)

  F_c(theta) = m a omega^2 + c v omega + k s + F_0 + F_L,   with v = ds/dtheta, a = d2s/dtheta2,

and the cam and the follower part where F_c < 0 (follower jump). The force along the common normal is
F_c / cos(phi) (phi the pressure angle; for an oscillating follower F_c / (l cos phi), l the arm). The camshaft
torque is by virtual work T = F_c v (no friction at the contact; Norton eq 15.11), so that its work over a turn
is c omega times the integral of v^2: zero for a conservative follower, the damper's loss otherwise.

Jump speed: F_c = 0 is a quadratic in omega at each angle; where a < 0 its positive root is the speed at which
contact is lost there, and the smallest over the turn is the jump speed. The spring is sized for a design speed
omega_d = (1 + margin) x the running speed: with the preload given, the smallest rate that keeps F_c >= 0 at
omega_d is k = max over s > 0 of (-(m a omega_d^2 + c v omega_d) - F_L - F_0)/s; with the rate given, the least
preload is F_0 = max(-(m a omega_d^2 + c v omega_d) - F_L - k s). Both are direct; the jump speed of the sized
spring is then omega_d exactly (Norton §15.4 on choosing the spring rate and preload).

The spring is sized and the jump speed found over the same angles, whatever the cam's ``positions``:
:func:`contact_angles`, 3600 angles over the turn and 65 on every smooth piece of every segment
(:func:`machdyn.cams.exact.segment_angles`), so that a segment shorter than the turn's grid is seen, with the
acceleration's peak on each piece to about 0.1 % (the cosine's drop over half a step, (pi/64)^2/8).

Reduced machine (for ``[flywheel]``): the cam is a one-degree-of-freedom machine with J(theta) = J_cam + m v^2
(slope 2 m v a), potential V = k s^2/2 + (F_0 + F_L) s (slope F_c's static part times v) and reduced damping
c v^2 (slope 2 c v a) -- the same reduced quantities as a linkage's (Uicker, Pennock & Shigley, *Theory of Machines
and Mechanisms*, 4th ed., ch. 17, the equivalent system).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..dynamics.equivalent import EquivalentMachine
from ..dynamics.tables import PeriodicCurve
from ..errors import AnalysisError, InputError, check_positive
from .exact import segment_angles
from .program import SVAJ, Program


@dataclass(frozen=True)
class FollowerTrain:
    """Lumped follower train (generalised to the follower's coordinate; see the module docstring).

    mass : m [kg] (or [kg*m^2] about the pivot), > 0.
    spring_rate : k [N/m] (or [N*m/rad]); None: sized.
    preload : F_0 [N] (or [N*m]) at s = 0, >= 0; None: sized.
    damping : c [N*s/m] (or [N*m*s/rad]), >= 0.
    load : F_L [N] (or [N*m]), a constant force towards the cam.
    cam_inertia : J_cam of the camshaft and cam [kg*m^2], >= 0.
    """

    mass: float
    spring_rate: float | None = None
    preload: float | None = 0.0
    damping: float = 0.0
    load: float = 0.0
    cam_inertia: float = 0.0

    def __post_init__(self):
        check_positive("follower mass (cam.dynamics.mass)", self.mass, "kg")
        check_positive("damping (cam.dynamics.damping)", self.damping, "N*s/m", allow_zero=True)
        check_positive("cam inertia (cam.dynamics.cam_inertia)", self.cam_inertia, "kg*m^2", allow_zero=True)
        if self.spring_rate is not None:
            check_positive("spring rate (cam.spring.rate)", self.spring_rate, "N/m", allow_zero=True)
        if self.preload is not None:
            check_positive("spring preload (cam.spring.preload)", self.preload, "N", allow_zero=True)
        if not np.isfinite(self.load):
            raise InputError(f"cam.dynamics.load must be a finite force; got {self.load}.")


@dataclass(frozen=True)
class Spring:
    """A return spring: rate [N/m], preload [N], the design speed it was sized for [rad/s] (None: given)."""

    rate: float
    preload: float
    design_speed: float | None = None


def contact_angles(prog: Program, positions: int = 3600) -> np.ndarray:
    """The cam angles [rad] over which the spring is sized and the jump speed found (module docstring)."""
    return np.union1d(np.arange(positions) * (2.0 * np.pi / positions), segment_angles(prog))


def size_spring(prog: Program, train: FollowerTrain, speed: float, margin: float = 0.2, positions: int = 3600,
                residual: float = 0.0) -> Spring:
    """The return spring that keeps contact up to (1 + margin) x ``speed`` [rad/s] (module docstring).

    The train's rate or its preload, whichever is given, is kept; the other is sized. ``residual`` [N] is a
    contact force to keep at the design speed (0: contact just kept). Both given: returned unchanged.
    """
    check_positive("cam speed (cam.speed)", speed, "rad/s")
    if not (np.isfinite(margin) and margin >= 0):
        raise InputError(f"cam.spring.margin must be >= 0; got {margin!r}.")
    if train.spring_rate is not None and train.preload is not None:
        return Spring(float(train.spring_rate), float(train.preload))
    wd = speed * (1.0 + margin)
    m = prog.svaj(contact_angles(prog, positions))
    need = spring_force_needed(m, train, wd) + residual
    if train.spring_rate is not None:
        k = float(train.spring_rate)
        return Spring(k, least_preload(need, m, k), wd)
    f0 = float(train.preload or 0.0)
    k = least_rate(need, m, f0, prog.stroke)
    if not np.isfinite(k):
        low = m.s <= 1e-12 * max(prog.stroke, 1e-300)
        raise InputError(f"cam.spring.preload {f0:g} N is less than the {float(np.max(need[low])):.4g} N the follower "
                         "needs where it rests on the base circle; give a larger preload (or the spring rate).")
    return Spring(k, f0, wd)


def spring_force_needed(svaj: SVAJ, train: FollowerTrain, speed: float, inertial=0.0, static=0.0) -> np.ndarray:
    """The spring force [N] (or moment) that keeps the contact force at zero at each cam angle at ``speed`` [rad/s]:
    -(m a + A) w^2 - c v w - F_L - B (the contact force of the module docstring set to 0; a load the follower
    drives besides its own, A w^2 + B, as in :func:`jump_speed`)."""
    return (-((train.mass * svaj.a + np.asarray(inertial, dtype=float)) * speed**2 + train.damping * svaj.v * speed)
            - train.load - np.asarray(static, dtype=float))


def least_preload(need: np.ndarray, svaj: SVAJ, rate: float) -> float:
    """The least preload [N] that with the spring rate [N/m] gives at least the force ``need`` [N] everywhere."""
    return max(float(np.max(need - rate * svaj.s)), 0.0)


def least_rate(need: np.ndarray, svaj: SVAJ, preload: float, stroke: float) -> float:
    """The least spring rate [N/m] that with ``preload`` [N] gives at least ``need`` [N] everywhere; inf where the
    follower rests on the base circle (s = 0) and the preload alone is too small."""
    low = svaj.s <= 1e-12 * max(stroke, 1e-300)
    if np.any(need[low] > preload):
        return float("inf")
    up = ~low
    return max(float(np.max((need[up] - preload) / svaj.s[up])), 0.0) if np.any(up) else 0.0


@dataclass(frozen=True)
class CamForces:
    """Forces over cam angles at a constant cam speed [rad/s]: contact force along the follower's path F_c [N],
    along the common normal [N], spring force [N], inertia force m a omega^2 [N], camshaft torque [N*m], and the
    jump speed of the spring [rad/s]."""

    svaj: SVAJ
    speed: float
    contact: np.ndarray
    normal: np.ndarray
    spring: np.ndarray
    inertia: np.ndarray
    torque: np.ndarray
    jump_speed: float

    @property
    def work_per_cycle(self) -> float:
        """Work of the camshaft torque over one turn [J] (the rectangle rule on evenly spaced angles, exact for
        a trigonometric polynomial of lower degree than the samples; the theta samples must span one turn)."""
        return float(np.mean(self.torque) * 2.0 * np.pi)


def jump_speed(svaj: SVAJ, train: FollowerTrain, spring: Spring, inertial=0.0, static=0.0) -> float:
    """The lowest cam speed [rad/s] at which F_c reaches 0 somewhere over the turn (inf if never). A load the
    follower drives besides its own, A w^2 + B per cam angle (``inertial`` A [N*s^2 or N*m*s^2], ``static`` B [N or
    N*m]; a linkage it moves, :mod:`.follower_linkage`), adds to the contact force's terms in w^2 and w^0."""
    a_ = train.mass * svaj.a + np.asarray(inertial, dtype=float)
    b_ = train.damping * svaj.v
    c_ = spring.rate * svaj.s + spring.preload + train.load + np.asarray(static, dtype=float)
    if np.any(c_ <= 0):
        return 0.0
    neg = a_ < 0
    if not np.any(neg):
        return float("inf")
    disc = b_[neg] ** 2 - 4.0 * a_[neg] * c_[neg]
    roots = (-b_[neg] - np.sqrt(disc)) / (2.0 * a_[neg])
    return float(np.min(roots))


def cam_forces(prog: Program, train: FollowerTrain, spring: Spring, speed: float, theta,
               pressure_angle=None, arm_length: float | None = None) -> CamForces:
    """Contact force, spring force and camshaft torque at cam angles theta [rad] at ``speed`` [rad/s]
    (module docstring). ``pressure_angle`` [rad] at theta gives the normal force; ``arm_length`` [m] of an
    oscillating follower converts its moment to a force."""
    check_positive("cam speed (cam.speed)", speed, "rad/s")
    m = prog.svaj(theta)
    spring_force = spring.rate * m.s + spring.preload
    inertia = train.mass * m.a * speed**2
    fc = inertia + train.damping * m.v * speed + spring_force + train.load
    phi = np.zeros_like(fc) if pressure_angle is None else np.asarray(pressure_angle)
    normal = fc / np.cos(phi) / (arm_length if arm_length else 1.0)
    return CamForces(m, float(speed), fc, normal, spring_force, inertia, fc * m.v,
                     jump_speed(prog.svaj(contact_angles(prog)), train, spring))


@dataclass(frozen=True)
class Simulation:
    """A forward simulation of the follower on the cam: time [s], cam angle [rad], follower position x and the
    cam's s [m], contact force [N]; the largest separation x - s over the last turn [m] and whether contact was
    kept (separation below ``tolerance``)."""

    t: np.ndarray
    theta: np.ndarray
    x: np.ndarray
    s: np.ndarray
    contact: np.ndarray
    max_separation: float
    tolerance: float

    @property
    def kept_contact(self) -> bool:
        return self.max_separation <= self.tolerance


def simulate_follower(prog: Program, train: FollowerTrain, spring: Spring, speed: float, turns: int = 3,
                      contact_stiffness: float | None = None, samples: int = 720) -> Simulation:
    """Integrate the follower's motion with scipy.integrate.solve_ivp (RK45, steps well inside the contact's
    period): a free mass pressed by its spring and load, pushed by the cam through a stiff one-sided contact,
    m x'' = N - c x' - (k x + F_0) - F_L with N = max(0, k_c (s - x) + c_c (s' - x')) while s > x, 0 otherwise.
    k_c defaults to m (200 omega)^2 (a contact frequency 200 times the cam's) and c_c to its critical damping, so
    the contact yields far less than the lift. The follower starts on the cam in a dwell; the largest separation
    x - s over the last turn is compared with a tolerance of 0.1 % of the stroke (the contact's own give at the
    largest force is some 1e-4 of it)."""
    from scipy.integrate import solve_ivp

    check_positive("cam speed", speed, "rad/s")
    mass, k, f0, c, load = train.mass, spring.rate, spring.preload, train.damping, train.load
    kc = contact_stiffness if contact_stiffness is not None else mass * (200.0 * speed) ** 2
    cc = 2.0 * np.sqrt(kc * mass)

    # s and v tabulated finely with their exact slopes and read by cubic Hermite pieces (error O(h^4), h = 0.01
    # deg: far below the contact's give); a table lookup is 20 times quicker than evaluating the laws
    nodes = 36_000
    h = 2.0 * np.pi / nodes
    tab = prog.svaj(np.arange(nodes + 1) * h)
    sv = np.stack([tab.s, tab.v * h, tab.v, tab.a * h], axis=1).tolist()

    def cam(t: float) -> tuple[float, float]:
        u = (speed * t) % (2.0 * np.pi) / h
        i = min(int(u), nodes - 1)
        x = u - i
        s0, m0, v0, n0 = sv[i]
        s1, m1, v1, n1 = sv[i + 1]
        x2, x3 = x * x, x * x * x
        h00, h10, h01, h11 = 2 * x3 - 3 * x2 + 1, x3 - 2 * x2 + x, -2 * x3 + 3 * x2, x3 - x2
        s = h00 * s0 + h10 * m0 + h01 * s1 + h11 * m1
        v = h00 * v0 + h10 * n0 + h01 * v1 + h11 * n1
        return s, v * speed

    def rhs(t: float, y: np.ndarray) -> np.ndarray:
        s, sd = cam(t)
        pen = s - y[0]
        n = max(0.0, kc * pen + cc * (sd - y[1])) if pen > 0 else 0.0
        return np.array([y[1], (n - c * y[1] - k * y[0] - f0 - load) / mass])

    period = 2.0 * np.pi / speed
    s0, v0 = cam(0.0)
    static = (k * s0 + f0 + load) / kc
    t_eval = np.linspace((turns - 1) * period, turns * period, samples * 1 + 1)
    sol = solve_ivp(rhs, (0.0, turns * period), np.array([s0 - static, v0]), method="RK45", t_eval=t_eval,
                    max_step=period / 1000.0, rtol=1e-7, atol=1e-10 * max(prog.stroke, 1e-6))
    if not sol.success:
        raise AnalysisError(f"the follower simulation failed: {sol.message}")
    th = speed * sol.t
    m = prog.svaj(th)
    x = sol.y[0]
    pen = m.s - x
    n = np.where(pen > 0, np.maximum(0.0, kc * pen + cc * (m.v * speed - sol.y[1])), 0.0)
    sep = float(np.max(x - m.s))
    return Simulation(sol.t, th, x, m.s, n, sep, 1e-3 * prog.stroke)


def cam_machine(prog: Program, train: FollowerTrain, spring: Spring, positions: int = 720, phase: float = 0.0):
    """The cam as an :class:`~machdyn.dynamics.equivalent.EquivalentMachine` (module docstring): reduced inertia
    J_cam + m v^2, potential of the spring and load, reduced damping c v^2, each with its exact slope; over the
    shaft angle phi = theta - ``phase`` [rad] (a cam mounted ``phase`` ahead on a crank shaft)."""
    if int(positions) != positions or positions < 16:
        raise InputError(f"The number of cam positions must be an integer >= 16; got {positions!r}.")
    th = np.arange(int(positions)) * (2.0 * np.pi / int(positions))
    m = prog.svaj(th + phase)
    period = 2.0 * np.pi
    j = train.cam_inertia + train.mass * m.v**2
    inertia = PeriodicCurve.hermite(th, j, 2.0 * train.mass * m.v * m.a, period)
    static = spring.rate * m.s + spring.preload + train.load
    potential = PeriodicCurve.hermite(th, 0.5 * spring.rate * m.s**2 + (spring.preload + train.load) * m.s,
                                      static * m.v, period)
    damping = PeriodicCurve.hermite(th, train.damping * m.v**2, 2.0 * train.damping * m.v * m.a, period)
    return EquivalentMachine(inertia, potential, PeriodicCurve.constant(0.0, period), damping, single=True)
