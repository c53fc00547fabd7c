"""Four-bar impact-vibration compactor with an "Archimedes lever" (seed paper 003).

Source: M.A. Asfandiyarov et al., *Mathematical modelling of the modernised impact-vibration mechanism*
(seed 003, Bulletin of SUSU, Mechanical Engineering, 2019). Corrections follow ``seed-reproduction.md`` section
003 (cited as "repro 003.x").

Geometry (paper Fig. 4): crank O-A of radius r about O = (0, 0); the compaction plate A-B of length R1 = l
(eq 6); the pendulum C-B of length R pivoting at C = (l, h). phi is the crank angle, theta2 the direction of
A->B (plate), theta3 the direction of C->B (pendulum). In the engine this is ``four_bar(crank=r, coupler=l,
rocker=R, ground=sqrt(l^2 + h^2), ground_angle=atan2(h, l))``: the engine's ``coupler`` body angle is theta2,
its ``rocker`` body angle is theta3 and ``branch`` is the sigma of repro 003.2 (+1: B to the left of A->C).

The paper gives no dimensions; the defaults of :class:`Compactor` are the illustrative geometry of repro
003.2 (r = 0.03, l = 0.5, h = 0.25, R = 0.25 m, omega1 = 10 rad/s, sigma = -1), which are not from the paper.

Every function takes and returns SI floats or numpy arrays (m, kg, N, rad, rad/s, N m, kg m^2).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from ..constants import DOWNWARD_GRAVITY
from ..errors import AssemblyError, InputError, check_finite, check_positive
from ..linkage import energy, four_bar, kinematics
from ..linkage.extremes import refine_extreme
from ..linkage.force_gain import crank_force_gain
from ..linkage.model import PointForce

__all__ = [
    "Compactor",
    "closed_form",
    "plate_angles",
    "line_angle",
    "line_angle_printed",
    "force_gain_crank",
    "force_gain_lever",
    "plate_normal_force",
    "transmission_angle",
    "reduced_inertia_eq18",
    "reduced_moment",
    "reduced_moment_eq19_printed",
    "GAMMA_LIMIT",
]

#: The design rule of seed 003 (conclusion 2a): the plate's angle to the horizontal must stay below 20 deg.
GAMMA_LIMIT = np.radians(20.0)


def _wrap(angle):
    """Angle [rad] reduced to (-pi, pi]."""
    return -np.mod(-np.asarray(angle, dtype=float) + np.pi, 2.0 * np.pi) + np.pi


def _check_geometry(r, l, h, R):
    check_positive("crank radius r", r, "m")
    check_positive("plate length l", l, "m")
    check_finite("pivot height h", h, "m")
    check_positive("pendulum length R", R, "m")


def closed_form(phi, r, l, h, R, omega1=1.0, branch=-1):
    """Exact position, velocity and acceleration of the compactor four-bar (repro 003.2; seed 003 eqs 2-12).

    Position (solution of eq 7): d = C − A, a = (l² − R² + d²) / (2d), η = √(l² − a²),
    B = A + a u + σ η n (u = d/|d|, n = u turned +90°). Velocities (ω1 constant):
    ω2 = −r ω1 sin(φ − θ3) / (l sin(θ2 − θ3)), ω3 = r ω1 sin(φ − θ2) / (R sin(θ3 − θ2)); accelerations
    ε2 = [R ω3² − r ω1² cos(φ − θ3) − l ω2² cos(θ2 − θ3)] / (l sin(θ2 − θ3)),
    ε3 = [r ω1² cos(φ − θ2) + l ω2² − R ω3² cos(θ3 − θ2)] / (R sin(θ3 − θ2)).

    Parameters
    ----------
    phi : float or array
        Crank angle φ [rad].
    r : float
        Crank radius [m], > 0.
    l : float
        Plate length = horizontal pivot distance [m], > 0.
    h : float
        Pivot height [m].
    R : float
        Pendulum length [m], > 0.
    omega1 : float
        Constant crank speed ω1 [rad/s].
    branch : int
        Assembly branch σ [-], +1 or −1.

    Returns
    -------
    dict of arrays
        xA, yA, xB, yB [m]; theta2, theta3 [rad]; omega2, omega3 [rad/s]; eps2, eps3 [rad/s²].
        Valid where |l − R| ≤ |C − A| ≤ l + R (assembly) and away from sin(θ2 − θ3) = 0 (dead positions).

    Examples
    --------
    The illustrative geometry of repro 003.2 at φ = 60°:

    >>> k = closed_form(np.radians(60.0), 0.03, 0.5, 0.25, 0.25, omega1=10.0)
    >>> round(float(k["theta2"]), 6), round(float(k["theta3"]), 6)
    (-0.05116, -1.513382)
    >>> round(float(k["omega2"]), 6), round(float(k["eps3"]), 6)
    (-0.331274, -5.587902)
    """
    _check_geometry(r, l, h, R)
    if branch not in (1, -1):
        raise InputError(f"The branch sigma must be +1 or -1; got {branch!r}.")
    phi = np.asarray(phi, dtype=float)
    xa, ya = r * np.cos(phi), r * np.sin(phi)
    dx, dy = l - xa, h - ya
    d = np.hypot(dx, dy)
    a = (l**2 - R**2 + d**2) / (2.0 * d)
    eta2 = l**2 - a**2
    if np.any(eta2 < 0):
        raise AssemblyError(
            "The compactor four-bar cannot close at some crank angles: it needs |l - R| <= |C - A| <= l + R; "
            f"got r = {r:g} m, l = {l:g} m, h = {h:g} m, R = {R:g} m."
        )
    eta = np.sqrt(eta2)
    ux, uy = dx / d, dy / d
    xb = xa + a * ux - branch * eta * uy
    yb = ya + a * uy + branch * eta * ux
    th2 = np.arctan2(yb - ya, xb - xa)
    th3 = np.arctan2(yb - h, xb - l)
    s23 = np.sin(th2 - th3)
    w2 = -r * omega1 * np.sin(phi - th3) / (l * s23)
    w3 = r * omega1 * np.sin(phi - th2) / (R * -s23)
    e2 = (R * w3**2 - r * omega1**2 * np.cos(phi - th3) - l * w2**2 * np.cos(th2 - th3)) / (l * s23)
    e3 = (r * omega1**2 * np.cos(phi - th2) + l * w2**2 - R * w3**2 * np.cos(th3 - th2)) / (R * -s23)
    return {"xA": xa, "yA": ya, "xB": xb, "yB": yb, "theta2": th2, "theta3": th3,
            "omega2": w2, "omega3": w3, "eps2": e2, "eps3": e3}


def plate_angles(phi, theta2, theta3):
    """Corrected seed 003 eqs 8-10: (α, β, γ) from the link directions (repro 003.3).

    α = θ2 − φ (crank to plate), β = θ3 − θ2 (plate to pendulum), both reduced to (−π, π];
    γ = θ2 reduced to (−π, π] (plate to the horizontal, positive when B is above A).
    The printed eqs 8-9 put the *product* of the two slopes in the numerator (the angle between two lines is
    arctan|(m1 − m2)/(1 + m1 m2)|, :func:`line_angle`), and even corrected they return only acute angles, lose
    the orientation and divide by zero at φ = 90°, 270° and at α = 90°; atan2 has none of this.

    Parameters
    ----------
    phi : float or array
        Crank angle φ [rad].
    theta2 : float or array
        Plate direction A→B [rad].
    theta3 : float or array
        Pendulum direction C→B [rad].

    Returns
    -------
    tuple of arrays
        (α, β, γ) [rad], each in (−π, π].

    Examples
    --------
    >>> k = closed_form(np.radians(60.0), 0.03, 0.5, 0.25, 0.25)
    >>> [round(float(np.degrees(x)), 2) for x in plate_angles(np.radians(60.0), k["theta2"], k["theta3"])]
    [-62.93, -83.78, -2.93]
    """
    for label, v in (("phi", phi), ("theta2", theta2), ("theta3", theta3)):
        check_finite(f"angle {label}", v, "rad")
    return _wrap(np.asarray(theta2) - phi), _wrap(np.asarray(theta3) - theta2), _wrap(theta2)


def line_angle(m1, m2):
    """Acute angle between two lines of slopes m1, m2: arctan|(m1 − m2) / (1 + m1 m2)|.

    The analytic-geometry form that seed 003 eqs 8-9 intend.

    Parameters
    ----------
    m1, m2 : float or array
        Slopes of the two lines [-]; undefined for vertical lines and at 1 + m1 m2 = 0.

    Returns
    -------
    float or array
        The acute angle [rad], in [0, π/2).

    Examples
    --------
    >>> round(float(np.degrees(line_angle(1.0, 0.0))), 6)
    45.0
    """
    m1, m2 = np.asarray(m1, dtype=float), np.asarray(m2, dtype=float)
    return np.arctan(np.abs((m1 - m2) / (1.0 + m1 * m2)))


def line_angle_printed(m1, m2):
    """Seed 003 eqs 8-9 as extracted (wrong): arctan|m1 m2 / (1 + m1 m2)|.

    Kept to document the error; at the illustrative geometry and φ = 60° it gives 5.56° where the crank-plate
    angle is 62.93°.

    Parameters
    ----------
    m1, m2 : float or array
        Slopes of the two lines [-].

    Returns
    -------
    float or array
        The printed expression [rad].

    Examples
    --------
    >>> round(float(np.degrees(line_angle_printed(1.0, 0.5))), 6)
    18.434949
    """
    m1, m2 = np.asarray(m1, dtype=float), np.asarray(m2, dtype=float)
    return np.arctan(np.abs(m1 * m2 / (1.0 + m1 * m2)))


def force_gain_crank(alpha):
    """Seed 003 force gain k1 = 1 / cos α (eq 1 and Fig. 3b), with the angle checked finite: the engine's
    :func:`machdyn.linkage.force_gain.crank_force_gain`, where its meaning is given (repro 003.3).

    Parameters
    ----------
    alpha : float or array
        Crank-plate angle α [rad], |α| ≠ 90°.

    Returns
    -------
    float or array
        k1 [-], negative when the plate's normal opposes the crank's tangent.

    Examples
    --------
    >>> round(float(force_gain_crank(np.radians(60.0))), 12)
    2.0
    """
    check_finite("angle alpha", alpha, "rad")
    return crank_force_gain(alpha)


def force_gain_lever(l, a):
    """Seed 003 force gain k2 = l / a of the "Archimedes lever" (eq 1).

    The plate is a lever with its fulcrum at B (supported by the near-vertical pendulum): a force at A
    (distance l from B) gives l/a times that force at a particle a distance a from B.

    Parameters
    ----------
    l : float
        Plate length [m], > 0.
    a : float or array
        Distance of the particle from B along the plate [m], 0 < a ≤ l.

    Returns
    -------
    float or array
        k2 [-], ≥ 1.

    Examples
    --------
    >>> float(force_gain_lever(0.6, 0.15))
    4.0
    """
    check_positive("plate length l", l, "m")
    check_positive("lever arm a", a, "m")
    if np.any(np.asarray(a) > l * (1 + 1e-12)):
        raise InputError(f"The lever arm a must not exceed the plate length l = {l:g} m; got {np.max(a):g} m.")
    return l / np.asarray(a, dtype=float)


def plate_normal_force(driving_torque, r, alpha):
    """Force normal to the plate at A that a driving torque balances: F_n = (M / r) k1 = M / (r cos α).

    Virtual work on a massless mechanism (seed 003 eq 1, repro 003.3).

    Parameters
    ----------
    driving_torque : float or array
        Driving torque M [N m].
    r : float
        Crank radius [m], > 0.
    alpha : float or array
        Crank-plate angle α [rad], |α| ≠ 90°.

    Returns
    -------
    float or array
        F_n [N].

    Examples
    --------
    >>> round(float(plate_normal_force(30.0, 0.05, np.radians(60.0))), 9)
    1200.0
    """
    check_positive("crank radius r", r, "m")
    return np.asarray(driving_torque, dtype=float) / r * force_gain_crank(alpha)


def transmission_angle(theta2, theta3):
    """Transmission angle between plate and pendulum, |θ2 − θ3| folded into 0 … π.

    For the illustrative geometry it stays within 82.5 … 97.9° (repro 003.2).

    Parameters
    ----------
    theta2 : float or array
        Plate direction A→B [rad].
    theta3 : float or array
        Pendulum direction C→B [rad].

    Returns
    -------
    float or array
        Transmission angle [rad], in [0, π].

    Examples
    --------
    >>> round(float(np.degrees(transmission_angle(np.radians(10.0), np.radians(100.0)))), 9)
    90.0
    """
    return np.abs(_wrap(np.asarray(theta2, dtype=float) - theta3))


def reduced_inertia_eq18(omega1, I1, m2, v2, I2, omega2, m3, v3, I3, omega3):
    """Seed 003 eq 18: I_red = I1 + m2 (V2/ω1)² + I2 (ω2/ω1)² + m3 (V3/ω1)² + I3 (ω3/ω1)².

    Correct if I1 is about the crank pivot O, I2, I3 are centroidal and V2, V3 are centroid speeds (repro 003.3;
    it equals 2 KE / ω1²). The paper writes G2/g, G3/g: G are weights there, although listed as "mass".

    Parameters
    ----------
    omega1 : float or array
        Crank speed [rad/s], ≠ 0.
    I1 : float
        Crank inertia about O [kg m²], ≥ 0.
    m2 : float
        Plate mass [kg], ≥ 0.
    v2 : float or array
        Plate centroid speed [m/s].
    I2 : float
        Plate centroidal inertia [kg m²], ≥ 0.
    omega2 : float or array
        Plate angular velocity [rad/s].
    m3 : float
        Pendulum mass [kg], ≥ 0.
    v3 : float or array
        Pendulum centroid speed [m/s].
    I3 : float
        Pendulum centroidal inertia [kg m²], ≥ 0.
    omega3 : float or array
        Pendulum angular velocity [rad/s].

    Returns
    -------
    float or array
        I_red [kg m²].

    Examples
    --------
    >>> round(float(reduced_inertia_eq18(10.0, 0.01, 5.0, 0.2, 0.1, -0.5, 3.0, 0.1, 0.05, 0.8)), 6)
    0.01287
    """
    if np.any(np.asarray(omega1) == 0):
        raise InputError("The crank speed omega1 must be non-zero for a reduced inertia; got 0 rad/s.")
    return (I1 + m2 * (np.asarray(v2) / omega1) ** 2 + I2 * (np.asarray(omega2) / omega1) ** 2
            + m3 * (np.asarray(v3) / omega1) ** 2 + I3 * (np.asarray(omega3) / omega1) ** 2)


def reduced_moment(omega1, loads):
    """Corrected seed 003 eq 19: M_red = Σ(F · V_F) / ω1 (repro 003.3).

    Every force is taken with the velocity of **its own point of application**: the compaction force Q with
    the velocity of the plate point where it acts, each weight G_i with its centroid's velocity, the crank's
    weight G1 included (eq 19 omits it, which is right only if the crank's centroid is at O).

    Parameters
    ----------
    omega1 : float or array
        Crank speed [rad/s], ≠ 0.
    loads : iterable
        ((Fx, Fy) [N], (Vx, Vy) [m/s]) pairs: each force with the velocity of its point of application.

    Returns
    -------
    float or array
        M_red [N m]; positive when the loads drive the crank.

    Examples
    --------
    >>> round(float(reduced_moment(10.0, [((0.0, -49.0), (0.1, -0.2)), ((0.0, -2000.0), (0.05, 0.03))])), 6)
    -5.02
    """
    if np.any(np.asarray(omega1) == 0):
        raise InputError("The crank speed omega1 must be non-zero for a reduced moment; got 0 rad/s.")
    power = 0.0
    for (fx, fy), (vx, vy) in loads:
        power = power + np.asarray(fx) * vx + np.asarray(fy) * vy
    return power / omega1


def reduced_moment_eq19_printed(omega1, g2, v2, q, g3, v3):
    """Seed 003 eq 19 as printed (wrong): M = (G2 · V2 + Q · V2 + G3 · V3) / ω1.

    It takes the compaction force Q with the plate-centroid velocity V2 instead of the velocity of Q's point of
    application and omits the crank weight G1. With the assumed data of repro 003.3 (Q = 2000 N vertical at
    0.10 m from B) it gives 24.01 N m at φ = 0 where the correct value is 6.02 N m.

    Parameters
    ----------
    omega1 : float
        Crank speed [rad/s], ≠ 0.
    g2, q, g3 : tuple of float
        Plate weight, compaction force, pendulum weight (Fx, Fy) [N].
    v2, v3 : tuple of float
        Plate and pendulum centroid velocities (Vx, Vy) [m/s].

    Returns
    -------
    float or array
        The printed M [N m]; kept to document the error, use :func:`reduced_moment`.

    Examples
    --------
    >>> round(float(reduced_moment_eq19_printed(10.0, (0.0, -49.0), (0.1, -0.2), (0.0, -2000.0),
    ...                                         (0.0, -29.4), (0.05, 0.03))), 6)
    40.8918
    """
    return reduced_moment(omega1, [(g2, v2), (q, v2), (g3, v3)])


# ------------------------------------------------------------------------------------------ machine


@dataclass(frozen=True)
class Compactor:
    """The compactor four-bar with its masses and the compaction force, built on the linkage engine.

    Geometry [m]: r crank radius, l plate length (= horizontal pivot distance, eq 6), h pivot height, R pendulum
    length; omega1 crank speed [rad/s]; branch sigma (+1/-1). Masses [kg] m1, m2, m3 and centroidal inertias
    [kg m^2] I1, I2, I3 of crank, plate and pendulum; centroids at ``crank_com`` from O along O->A (default 0:
    the crank balanced about O), ``plate_com`` from A along A->B (default l/2), ``pendulum_com`` from C along
    C->B (default R/2). The compaction force ``q_force`` = (Qx, Qy) [N] acts on the plate at ``q_from_b`` [m] from
    B (towards A), during ``q_active`` = (start, end) [rad] of the crank angle or all the time (None).
    ``gravity`` [m/s^2] defaults to the engine's. The defaults are the illustrative geometry of repro 003.2.
    """

    r: float = 0.03
    l: float = 0.5
    h: float = 0.25
    R: float = 0.25
    omega1: float = 10.0
    branch: int = -1
    m1: float = 0.0
    m2: float = 0.0
    m3: float = 0.0
    I1: float = 0.0
    I2: float = 0.0
    I3: float = 0.0
    crank_com: float = 0.0
    plate_com: float | None = None
    pendulum_com: float | None = None
    q_force: tuple[float, float] = (0.0, 0.0)
    q_from_b: float = 0.0
    q_active: tuple[float, float] | None = None
    gravity: tuple[float, float] = field(default=DOWNWARD_GRAVITY)

    def __post_init__(self) -> None:
        _check_geometry(self.r, self.l, self.h, self.R)
        check_finite("crank speed omega1", self.omega1, "rad/s")
        if self.branch not in (1, -1):
            raise InputError(f"The compactor branch must be +1 or -1; got {self.branch!r}.")
        if not 0.0 <= self.q_from_b <= self.l:
            raise InputError(
                f"The compaction force must act on the plate: q_from_b must be within 0 ... {self.l:g} m; "
                f"got {self.q_from_b:g} m."
            )

    @property
    def ground_length(self) -> float:
        """g = |OC| = sqrt(l^2 + h^2) [m]."""
        return float(np.hypot(self.l, self.h))

    def mechanism(self):
        """The engine :class:`~machdyn.linkage.model.Mechanism` (``machdyn.linkage.four_bar``).

        Bodies ``crank`` {O, A}, ``coupler`` = the plate {A, B, Q}, ``rocker`` = the pendulum {D = C, B}; ground
        points O and D = C = (l, h). The compaction force is the point force ``Q`` at ``coupler.Q``.
        """
        plate_com = 0.5 * self.l if self.plate_com is None else self.plate_com
        pendulum_com = 0.5 * self.R if self.pendulum_com is None else self.pendulum_com
        u = self.l - self.q_from_b
        mech = four_bar(
            self.r, self.l, self.R, self.ground_length,
            ground_angle=float(np.arctan2(self.h, self.l)),
            branch=self.branch,
            masses=(self.m1, self.m2, self.m3),
            inertias=(self.I1, self.I2, self.I3),
            coms=((self.crank_com, 0.0), (plate_com, 0.0), (pendulum_com, 0.0)),
            coupler_point=(u, 0.0),
            name="compactor",
        )
        # four_bar names the coupler point "P"; it is the point where Q acts.
        forces = tuple(mech.forces)
        if self.q_force != (0.0, 0.0):
            forces += (PointForce("Q", "coupler.P", self.q_force[0], self.q_force[1], self.q_active),)
        return replace(mech, forces=forces, gravity=(float(self.gravity[0]), float(self.gravity[1])))

    def kinematics(self, phi):
        """Engine kinematics at crank angles phi [rad] with speed omega1."""
        return kinematics(self.mechanism(), phi, speed=self.omega1)

    def angles(self, phi):
        """(alpha, beta, gamma) [rad] at crank angles phi (corrected eqs 8-10, :func:`plate_angles`), from the
        engine's link angles."""
        k = self.kinematics(phi)
        return plate_angles(k.crank_angle, k.body("coupler").angle, k.body("rocker").angle)

    def gamma_check(self, samples: int = 3601, limit: float = GAMMA_LIMIT) -> dict:
        """The design rule gamma < 20 deg (seed 003, conclusion 2a) over a crank revolution.

        Returns {"gamma_max": max |gamma| [rad], "at": the crank angle [rad] where it occurs, "limit": limit,
        "ok": gamma_max < limit, "transmission_min"/"transmission_max": range of :func:`transmission_angle`
        [rad]}. The extreme is located on a grid of ``samples`` angles and refined by re-sampling around it.
        """
        phi = np.linspace(0.0, 2.0 * np.pi, int(samples))
        k = self.kinematics(phi)
        th2, th3 = k.body("coupler").angle, k.body("rocker").angle

        def gamma(x):
            return np.abs(_wrap(self.kinematics(x).body("coupler").angle))

        at, gmax = refine_extreme(gamma, phi, np.abs(_wrap(th2)), "max")
        mu = transmission_angle(th2, th3)
        return {"gamma_max": float(gmax), "at": float(np.mod(at, 2 * np.pi)), "limit": float(limit),
                "ok": bool(gmax < limit), "transmission_min": float(mu.min()),
                "transmission_max": float(mu.max())}

    def reduced_inertia(self, phi):
        """Reduced moment of inertia [kg m^2] at crank angles phi (seed 003 eq 18) = 2 KE / omega1^2, from the
        engine's energy."""
        return energy(self.mechanism(), phi, speed=self.omega1).reduced_inertia

    def reduced_moment(self, phi):
        """Reduced moment of the loads [N m] at crank angles phi (corrected seed 003 eq 19): the power of
        gravity (G1, G2, G3) and of Q at its own point, divided by omega1, from the engine's energy."""
        return energy(self.mechanism(), phi, speed=self.omega1).reduced_moment
