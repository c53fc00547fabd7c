"""Flywheel sizing for a coefficient of speed fluctuation, and the flywheel as a steel disc or rim.

delta = (omega_max - omega_min) / omega_mean with omega_mean = (omega_max + omega_min) / 2 (Khurmi & Gupta,
*Theory of Machines*, ch. 16 (Turning Moment Diagrams and Flywheel), the coefficient of fluctuation of speed C_s).

Two sizing methods:

* **classic**: J = ΔE / (omega_mean^2 delta), ΔE the maximum fluctuation of energy of the turning-moment diagram
  about the mean torque (Khurmi & Gupta, ch. 16). It treats the whole machine as one constant inertia: the flywheel
  is J less the mean reduced inertia of the linkage.
* **exact (energy-mass, Wittenbauer)**: with the work excess W(phi) = integral of the total reduced moment and
  the kinetic energy T = T0 + W(phi) = (J_f + J(phi)) omega^2 / 2, the speed stays within omega_min..omega_max
  for every phi if and only if
  T0 <= J_f omega_max^2/2 + min(J(phi) omega_max^2/2 - W(phi)) and
  T0 >= J_f omega_min^2/2 + max(J(phi) omega_min^2/2 - W(phi)).
  The least flywheel makes both bounds meet:
  J_f = [max(J omega_min^2/2 - W) - min(J omega_max^2/2 - W)] / (delta omega_mean^2),
  because omega_max^2 - omega_min^2 = 2 delta omega_mean^2 exactly. These are the two tangents of slopes
  omega_max^2/2 and omega_min^2/2 to Wittenbauer's energy-mass diagram (W against J) (seed 003, text after
  eq 19; Artobolevsky, *Theory of Mechanisms and Machines*, the Wittenbauer method). For a constant J it gives
  the classic result exactly.

Both assume the drive gives the mean torque at every angle (speed-dependent loads are taken at the mean speed).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError, check_finite, check_positive
from .equivalent import EquivalentMachine
from .tables import fine_grid

#: Density of steel [kg/m^3] (EN 10025 structural steels: 7850 kg/m^3).
STEEL_DENSITY = 7850.0
#: Poisson's ratio of steel.
STEEL_POISSON = 0.3


def check_delta(delta) -> None:
    """Raise :class:`InputError` unless 0 < delta < 1."""
    check_finite("coefficient of speed fluctuation delta", delta)
    d = np.asarray(delta, dtype=float)
    if np.any((d <= 0) | (d >= 1)):
        bad = float(d[(d <= 0) | (d >= 1)].ravel()[0]) if d.ndim else float(d)
        raise InputError(f"The coefficient of speed fluctuation delta must be > 0 and < 1; got {bad:g}.")


def speed_limits(mean_speed, delta):
    """omega_max, omega_min [rad/s] = omega_mean (1 ± delta/2) (Khurmi & Gupta, ch. 16).

    Parameters
    ----------
    mean_speed : omega_mean [rad/s] > 0.
    delta : coefficient of speed fluctuation, 0 < delta < 1.

    Examples
    --------
    >>> speed_limits(100.0, 0.02)
    (101.0, 99.0)
    """
    check_positive("mean speed", mean_speed, "rad/s")
    check_delta(delta)
    return mean_speed * (1.0 + delta / 2.0), mean_speed * (1.0 - delta / 2.0)


def flywheel_inertia_classic(energy_fluctuation, mean_speed, delta):
    """Moment of inertia [kg*m^2] for a coefficient of speed fluctuation: I = ΔE / (omega^2 delta).

    Parameters
    ----------
    energy_fluctuation : maximum fluctuation of energy ΔE [J] >= 0.
    mean_speed : mean speed omega [rad/s] > 0.
    delta : coefficient of speed fluctuation C_s, 0 < delta < 1.

    Source: Khurmi & Gupta, *Theory of Machines*, ch. 16, ΔE = I omega^2 C_s (used in its examples 16.3-16.15).
    Exact for a constant inertia with omega_mean = (omega_max + omega_min)/2; for a linkage whose reduced inertia
    varies see :func:`size_flywheel` (the energy-mass method).

    Examples
    --------
    >>> round(flywheel_inertia_classic(10083.0, 10 * 3.141592653589793, 0.04), 1)   # Khurmi & Gupta ex. 16.9
    255.4
    """
    check_positive("energy fluctuation", energy_fluctuation, "J", allow_zero=True)
    check_positive("mean speed", mean_speed, "rad/s")
    check_delta(delta)
    return energy_fluctuation / (mean_speed**2 * delta)


@dataclass(frozen=True)
class FlywheelSizing:
    """Result of :func:`size_flywheel` (one value per design where shaped (N,)).

    exact : flywheel inertia by the energy-mass (Wittenbauer) method [kg*m^2] (0 where the linkage suffices).
    classic : ΔE/(omega^2 delta) less the linkage's mean reduced inertia [kg*m^2] (>= 0).
    classic_total : ΔE/(omega^2 delta), the textbook value for the whole machine [kg*m^2].
    energy_fluctuation : ΔE [J]; mean_inertia : mean of J(phi) [kg*m^2]; drive_torque : the mean torque the
    drive gives [N*m]; kinetic_energy_start : T0 at phi = 0 [J] with the exact flywheel; difference : (classic -
    exact) / exact. phi, inertia_curve, work_curve : the energy-mass diagram (J(phi), W(phi)) on a fine grid.
    """

    mean_speed: float
    delta: float
    exact: np.ndarray
    classic: np.ndarray
    classic_total: np.ndarray
    energy_fluctuation: np.ndarray
    mean_inertia: np.ndarray
    drive_torque: np.ndarray
    kinetic_energy_start: np.ndarray
    phi: np.ndarray
    inertia_curve: np.ndarray
    work_curve: np.ndarray

    @property
    def difference(self) -> np.ndarray:
        """(classic - exact) / exact; NaN-free: 0 where both are 0."""
        scale = np.maximum(np.abs(self.exact), np.finfo(float).tiny)
        return np.where(self.exact > 0, (self.classic - self.exact) / scale, 0.0)


def size_flywheel(machine: EquivalentMachine, mean_speed: float, delta: float, *,
                  samples_per_piece: int = 16) -> FlywheelSizing:
    """Flywheel inertia [kg*m^2] that keeps the crank speed within omega_mean (1 ± delta/2), by the classic and
    the exact energy-mass method (see the module docstring).

    Parameters
    ----------
    machine : the equivalent machine (:func:`~machdyn.dynamics.equivalent.equivalent_machine` or
        :meth:`EquivalentMachine.from_tables`); its moment includes every load, the drive gives the mean torque.
    mean_speed : omega_mean [rad/s] > 0.
    delta : 0 < delta < 1.
    samples_per_piece : points per interpolation piece where the extremes are searched.
    """
    check_positive("mean speed", mean_speed, "rad/s")
    check_delta(delta)
    if np.any(machine.inertia.y < 0):
        got = float(np.min(machine.inertia.y))
        raise InputError(f"The reduced moment of inertia must be >= 0 kg*m^2; got {got:g} kg*m^2.")
    phi = fine_grid(machine.inertia, samples_per_piece)
    if machine.moment.x.size > machine.inertia.x.size:
        phi = fine_grid(machine.moment, samples_per_piece)
    n = machine.designs
    q = np.broadcast_to(phi, (n, phi.size))
    wmax, wmin = speed_limits(mean_speed, delta)
    # position moment: external loads exactly integrated, potential exactly; speed loads at the mean speed
    w_ext = machine.moment.integral(q) - machine.moment.integral(np.zeros((n, 1)))
    w_pot = -(machine.potential(q) - machine.potential(np.zeros((n, 1))))
    speed_m = machine.speed_moment(q, mean_speed + 0.0 * q)[0]
    w_speed = _cumulative_periodic(speed_m, phi, machine.period)
    work = w_ext + w_pot + w_speed
    # the drive's mean torque closes the cycle
    cycle = (machine.moment.cycle_integral() + _cycle_total(speed_m, phi, machine.period))
    cycle = np.broadcast_to(cycle, (n,))
    drive = -cycle / machine.period
    work = work + drive[:, None] * phi[None, :]
    j = np.broadcast_to(machine.inertia(q), (n, phi.size))
    upper = (0.5 * wmax**2 * j - work).min(axis=1)
    lower = (0.5 * wmin**2 * j - work).max(axis=1)
    raw = (lower - upper) / (delta * mean_speed**2)
    exact = np.maximum(raw, 0.0)
    t0 = 0.5 * wmax**2 * exact + upper
    de = work.max(axis=1) - work.min(axis=1)
    total = de / (mean_speed**2 * delta)
    jm = machine.inertia.mean() + np.zeros(n)
    classic = np.maximum(total - jm, 0.0)
    return FlywheelSizing(float(mean_speed), float(delta), exact, classic, total, de, jm, drive, t0, phi, j, work)


def _cumulative_periodic(values, phi, period):
    """Cumulative trapezoidal integral of samples on a periodic grid starting at phi[0] (0 at phi[0])."""
    h = np.diff(np.append(phi, phi[0] + period))
    pieces = 0.5 * (values + np.roll(values, -1, axis=-1)) * h
    return np.concatenate([np.zeros(values.shape[:-1] + (1,)), np.cumsum(pieces, axis=-1)[..., :-1]], axis=-1)


def _cycle_total(values, phi, period):
    h = np.diff(np.append(phi, phi[0] + period))
    return (0.5 * (values + np.roll(values, -1, axis=-1)) * h).sum(axis=-1)


# --------------------------------------------------------------------------------------- the physical part


def rim_speed_limit(allowable_stress, density=STEEL_DENSITY, shape: str = "rim", poisson=STEEL_POISSON):
    """Largest rim speed [m/s] for an allowable stress [Pa].

    Thin rim (hoop stress of a rotating ring): sigma = rho v^2, v = sqrt(sigma/rho) (Khurmi & Gupta, *Theory of
    Machines*, ch. 16, ex. 16.14). Solid disc of uniform thickness: the largest stress, at the centre, is
    sigma = (3 + nu)/8 rho v^2 (S. Timoshenko, *Strength of Materials*, Part II, rotating discs), so
    v = sqrt(8 sigma / ((3 + nu) rho)).

    Parameters
    ----------
    allowable_stress : sigma [Pa] > 0.
    density : rho [kg/m^3] > 0 (steel 7850).
    shape : "rim" or "disc".
    poisson : Poisson's ratio nu (disc only).

    Examples
    --------
    >>> round(rim_speed_limit(7.0e6, 7200.0), 3)     # Khurmi & Gupta ex. 16.14: 31.18 m/s
    31.18
    """
    check_positive("allowable stress", allowable_stress, "Pa")
    check_positive("density", density, "kg/m^3")
    if shape == "rim":
        return float(np.sqrt(allowable_stress / density))
    if shape == "disc":
        return float(np.sqrt(8.0 * allowable_stress / ((3.0 + poisson) * density)))
    raise InputError(f"The flywheel shape must be 'rim' or 'disc'; got {shape!r}.")


@dataclass(frozen=True)
class FlywheelPart:
    """A flywheel as a part: ``shape`` 'disc' or 'rim', outer diameter [m], width (axial) [m], rim thickness
    (radial; the radius for a disc) [m], mass [kg], inertia [kg*m^2], rim speed at the highest crank speed
    [m/s] against ``rim_speed_limit`` [m/s]."""

    shape: str
    inertia: float
    diameter: float
    width: float
    thickness: float
    mass: float
    rim_speed: float
    rim_speed_limit: float

    @property
    def within_limit(self) -> bool:
        return bool(self.rim_speed <= self.rim_speed_limit)


def disc_flywheel(inertia, max_speed, *, width_ratio: float = 0.2, density=STEEL_DENSITY,
                  rim_speed_limit: float | None = None) -> FlywheelPart:
    """A solid steel disc of ``inertia`` [kg*m^2]: J = pi rho b R^4 / 2 with width b = width_ratio * D.

    Parameters
    ----------
    inertia : J [kg*m^2] > 0. max_speed : highest speed of the flywheel [rad/s] > 0 (for the rim speed).
    width_ratio : b / D > 0. density : [kg/m^3]. rim_speed_limit : [m/s] (default: the disc limit of a steel
    disc at 100 MPa allowable stress, :func:`rim_speed_limit`).

    Source: J = m R^2 / 2 of a uniform disc; R = (2 J / (pi rho 2 width_ratio))^(1/5) from b = 2 width_ratio R.

    Examples
    --------
    >>> part = disc_flywheel(10.0, 100.0)
    >>> round(part.diameter, 4), round(part.mass, 2)
    (0.5787, 238.92)
    """
    check_positive("flywheel inertia", inertia, "kg*m^2")
    check_positive("flywheel speed", max_speed, "rad/s")
    check_positive("width ratio", width_ratio)
    check_positive("density", density, "kg/m^3")
    radius = (inertia / (np.pi * density * width_ratio)) ** 0.2
    width = 2.0 * width_ratio * radius
    mass = density * np.pi * radius**2 * width
    limit = rim_speed_limit if rim_speed_limit is not None else globals()["rim_speed_limit"](1.0e8, density, "disc")
    return FlywheelPart("disc", float(inertia), float(2 * radius), float(width), float(radius), float(mass),
                        float(max_speed * radius), float(limit))


def rim_flywheel(inertia, mean_speed, max_speed, *, rim_speed: float, width_to_thickness: float = 2.0,
                 density=STEEL_DENSITY, rim_speed_limit: float | None = None, rim_share: float = 1.0) -> FlywheelPart:
    """A flywheel rim of mean diameter D = 2 v / omega_mean carrying ``rim_share`` of ``inertia`` (the arms and
    hub the rest): m = rim_share J / R^2, cross-section A = m / (pi D rho) = b t with b = width_to_thickness t.

    Parameters
    ----------
    inertia : J [kg*m^2] > 0. mean_speed, max_speed : [rad/s]. rim_speed : mean rim speed v [m/s] chosen for the
    design. width_to_thickness : b/t. density [kg/m^3]. rim_speed_limit [m/s] (default v). rim_share : (0, 1].

    Source: Khurmi & Gupta, *Theory of Machines*, ch. 16 (ex. 16.14: D from the rim speed limit,
    m = ΔE/(v^2 C_s), t = sqrt(m / (pi D b/t rho))).

    Examples
    --------
    >>> part = rim_flywheel(23562.0 / (83.776**2 * 0.04), 83.776, 85.45, rim_speed=31.18,
    ...                     width_to_thickness=5.0, density=7200.0)
    >>> round(part.diameter, 3), round(part.thickness * 1000), round(part.width * 1000)   # book: 0.744 m, 84, 424 mm
    (0.744, 85, 424)
    """
    check_positive("flywheel inertia", inertia, "kg*m^2")
    check_positive("mean speed", mean_speed, "rad/s")
    check_positive("rim speed", rim_speed, "m/s")
    check_positive("width to thickness ratio", width_to_thickness)
    if not 0 < rim_share <= 1:
        raise InputError(f"The rim's share of the flywheel inertia must be in (0, 1]; got {rim_share:g}.")
    radius = rim_speed / mean_speed
    mass = rim_share * inertia / radius**2
    area = mass / (2.0 * np.pi * radius * density)
    thickness = np.sqrt(area / width_to_thickness)
    limit = rim_speed if rim_speed_limit is None else rim_speed_limit
    return FlywheelPart("rim", float(inertia), float(2 * radius), float(width_to_thickness * thickness),
                        float(thickness), float(mass), float(max_speed * radius), float(limit))
