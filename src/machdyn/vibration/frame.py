"""The machine frame as a rigid planar body on elastic mounts.

Coordinates. The frame's motion is q = (x, y, theta): the small translation [m] of the frame's reference point
(the origin of the frame's coordinates, which is also where the mechanism's shaking moment is taken) and its
small rotation [rad], counter-clockwise positive. A frame point p = (px, py) moves by
u = (x - theta py, y + theta px) (linearised rigid-body motion, Meirovitch, *Fundamentals of Vibrations*,
2001, §7.1).

Mounts. A mount acts along one line: a unit direction n at a frame point p, stiffness k [N/m] and viscous
damping c [N s/m]. Its deflection is delta = n . u = b . q with b = (nx, ny, px ny - py nx), so it adds
k b b^T to the stiffness matrix and c b b^T to the damping matrix. A real mount stiff in two directions
(a rubber mount, a tyre) is two such mounts at one point; the helpers below build them. A hanging rope is
a pendulum: across the rope its restoring stiffness is the tension over the length, T / L = m g / L for the
share m of the frame's weight it carries (Den Hartog, *Mechanical Vibrations*, 4th ed., 1956, §1.3), and along
it the rope's own axial stiffness E A / L.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..constants import STANDARD_GRAVITY
from ..errors import InputError, check_finite
from .gravity import gravity_stiffness

__all__ = [
    "STANDARD_GRAVITY",
    "Frame",
    "Mount",
    "critical_damping",
    "pendulum_stiffness",
    "rope",
    "rubber_mount",
    "tyre",
]


def _check_number(name: str, value: float, unit: str, *, rule: str = "") -> float:
    check_finite(name, value, unit)
    v = float(value)
    if rule == ">0" and not v > 0:
        raise InputError(f"The {name} must be > 0 {unit}; got {v:g} {unit}.")
    if rule == ">=0" and not v >= 0:
        raise InputError(f"The {name} must be >= 0 {unit}; got {v:g} {unit}.")
    return v


@dataclass(frozen=True)
class Mount:
    """One elastic support acting along a line.

    Parameters
    ----------
    name : label of the mount (unique within a frame)
    position : (x, y) [m] of the attachment point in frame coordinates
    direction : angle [rad] of the line of action from the frame's x axis (pi/2: vertical)
    stiffness : k [N/m] >= 0 along that line
    damping : c [N s/m] >= 0 along that line (viscous)
    kind : what the mount is ("spring", "rubber", "tyre", "rope"); informative only
    """

    name: str
    position: tuple[float, float]
    direction: float
    stiffness: float
    damping: float = 0.0
    kind: str = "spring"

    def __post_init__(self) -> None:
        if not self.name:
            raise InputError("A mount needs a non-empty name; got ''.")
        what = f"mount '{self.name}'"
        x, y = self.position
        object.__setattr__(self, "position", (_check_number(f"x position of {what}", x, "m"),
                                              _check_number(f"y position of {what}", y, "m")))
        object.__setattr__(self, "direction", _check_number(f"direction of {what}", self.direction, "rad"))
        object.__setattr__(self, "stiffness", _check_number(f"stiffness of {what}", self.stiffness, "N/m",
                                                            rule=">=0"))
        object.__setattr__(self, "damping", _check_number(f"damping of {what}", self.damping, "N*s/m",
                                                          rule=">=0"))

    @property
    def unit_vector(self) -> np.ndarray:
        """Unit vector n of the line of action (frame axes)."""
        return np.array([np.cos(self.direction), np.sin(self.direction)])

    @property
    def influence(self) -> np.ndarray:
        """b with delta = b . q: the mount's deflection per unit frame coordinate (x, y, theta)."""
        nx, ny = self.unit_vector
        px, py = self.position
        return np.array([nx, ny, px * ny - py * nx])


def critical_damping(stiffness, mass):
    """Critical damping c_c = 2 sqrt(k m) [N s/m] of a mass on a spring.

    Rao, *Mechanical Vibrations*, 5th ed. (2011), eq. (2.67).

    Parameters
    ----------
    stiffness : k [N/m] >= 0
    mass : m [kg] > 0

    Examples
    --------
    >>> round(float(critical_damping(10_000.0, 25.0)), 6)
    1000.0
    """
    return 2.0 * np.sqrt(np.asarray(stiffness, dtype=float) * np.asarray(mass, dtype=float))


def pendulum_stiffness(supported_mass, length, gravity=STANDARD_GRAVITY):
    """Lateral stiffness k = m g / L [N/m] of a hanging rope (a pendulum) carrying the mass m.

    For a small sideways displacement u of the lower end the rope tilts by u / L and its tension m g gets a
    horizontal component m g u / L (Den Hartog, *Mechanical Vibrations*, 4th ed., 1956, §1.3; the pendulum's
    omega^2 = g / L). Valid for tilts of a few degrees.

    Parameters
    ----------
    supported_mass : share m [kg] > 0 of the frame's weight the rope carries
    length : rope length L [m] > 0
    gravity : g [m/s^2] > 0

    Examples
    --------
    >>> round(float(pendulum_stiffness(300.0, 1.2)), 3)
    2451.662
    """
    m = _check_number("mass carried by the rope", supported_mass, "kg", rule=">0")
    L = _check_number("rope length", length, "m", rule=">0")
    g = _check_number("gravity", gravity, "m/s^2", rule=">0")
    return m * g / L


def rubber_mount(name, position, vertical_stiffness, horizontal_stiffness, *, loss_factor=0.0,
                 frequency=None, vertical_damping=0.0, horizontal_damping=0.0, kind="rubber"):
    """A mount stiff in two directions: two :class:`Mount` lines at one point, ``name.v`` and ``name.h``.

    Rubber is usually described by a loss factor eta (hysteretic damping); at one excitation frequency f it is
    equivalent to viscous damping c = eta k / (2 pi f) (Rao, *Mechanical Vibrations*, 5th ed., eq. (2.143)).
    Give either ``loss_factor`` with ``frequency`` [Hz], or the viscous dampings directly.

    Parameters
    ----------
    name : label; the two lines are named ``name + ".v"`` and ``name + ".h"``
    position : (x, y) [m]
    vertical_stiffness, horizontal_stiffness : [N/m] >= 0
    loss_factor : eta [-] >= 0 (rubber 0.05...0.3)
    frequency : f [Hz] > 0 at which the loss factor is turned into viscous damping
    vertical_damping, horizontal_damping : c [N s/m] >= 0, added to the damping from the loss factor

    Examples
    --------
    >>> v, h = rubber_mount("m1", (0.5, 0.0), 2e5, 1e5, loss_factor=0.1, frequency=20.0)
    >>> round(v.damping, 3), h.direction
    (159.155, 0.0)
    """
    eta = _check_number(f"loss factor of mount '{name}'", loss_factor, "", rule=">=0")
    extra_v = extra_h = 0.0
    if eta > 0:
        if frequency is None:
            raise InputError(f"The loss factor of mount '{name}' needs the frequency [Hz] at which it is turned "
                             f"into viscous damping; got none.")
        f = _check_number(f"frequency of mount '{name}'", frequency, "Hz", rule=">0")
        extra_v = eta * float(vertical_stiffness) / (2 * np.pi * f)
        extra_h = eta * float(horizontal_stiffness) / (2 * np.pi * f)
    return (
        Mount(f"{name}.v", position, np.pi / 2, vertical_stiffness, vertical_damping + extra_v, kind),
        Mount(f"{name}.h", position, 0.0, horizontal_stiffness, horizontal_damping + extra_h, kind),
    )


def tyre(name, position, vertical_stiffness, lateral_stiffness, *, vertical_damping=0.0, lateral_damping=0.0):
    """A pneumatic tyre as a mount: radial (vertical) and fore-aft (horizontal) stiffness at the contact point.

    Pneumatic tyres of construction machines have radial stiffnesses of the order of 0.5...2 MN/m and damping
    ratios of a few per cent (Wong, *Theory of Ground Vehicles*, 4th ed., 2008, §1.5). Returns two
    :class:`Mount` lines ``name.v`` and ``name.h``.

    Parameters
    ----------
    name : label
    position : (x, y) [m] of the contact point in frame coordinates
    vertical_stiffness, lateral_stiffness : [N/m] >= 0
    vertical_damping, lateral_damping : [N s/m] >= 0

    Examples
    --------
    >>> [m.name for m in tyre("left", (-1.0, -0.4), 1.2e6, 4e5)]
    ['left.v', 'left.h']
    """
    return rubber_mount(name, position, vertical_stiffness, lateral_stiffness, vertical_damping=vertical_damping,
                        horizontal_damping=lateral_damping, kind="tyre")


def rope(name, position, length, supported_mass, axial_stiffness, *, angle=np.pi / 2, damping=0.0,
         gravity=STANDARD_GRAVITY):
    """A hanging rope (pendulum support) as two :class:`Mount` lines at its lower end.

    Along the rope (``name.axial``): the rope's axial stiffness E A / L. Across it (``name.swing``): the
    pendulum stiffness m g / L (:func:`pendulum_stiffness`).

    Parameters
    ----------
    name : label
    position : (x, y) [m] of the rope's lower end (attachment to the frame)
    length : L [m] > 0
    supported_mass : share m [kg] > 0 of the frame's weight the rope carries
    axial_stiffness : E A / L [N/m] > 0
    angle : direction [rad] of the rope from its lower end towards its anchor (pi/2: hanging straight)
    damping : viscous damping across the rope [N s/m] >= 0
    gravity : g [m/s^2]

    Examples
    --------
    >>> axial, swing = rope("r1", (0.0, 0.0), 1.0, 100.0, 5e6)
    >>> round(swing.stiffness, 4), round(swing.direction, 4)
    (980.665, 0.0)
    """
    k_swing = pendulum_stiffness(supported_mass, length, gravity)
    k_axial = _check_number(f"axial stiffness of rope '{name}'", axial_stiffness, "N/m", rule=">0")
    return (
        Mount(f"{name}.axial", position, angle, k_axial, 0.0, "rope"),
        Mount(f"{name}.swing", position, angle - np.pi / 2, k_swing, damping, "rope"),
    )


def mount_sum(mounts, rate: str) -> np.ndarray:
    """Σ r_i b_i b_iᵀ over ``mounts``: the frame's stiffness (``rate="stiffness"``) or damping (``"damping"``)
    matrix from each mount's line rate r_i and influence vector b_i (its deflection per unit frame coordinate;
    the assembly of springs in parallel, e.g. Harris' Shock and Vibration Handbook, ch. 3 "Vibration of a
    resiliently supported rigid body"). Serves the planar frame (b of 3 entries) and the frame in space (6)."""
    b = np.array([m.influence for m in mounts])
    return b.T @ (np.array([getattr(m, rate) for m in mounts])[:, None] * b)


@dataclass(frozen=True)
class Frame:
    """A rigid planar frame on mounts (definition only; see :func:`machdyn.vibration.modes.modes` and
    :func:`machdyn.vibration.response.steady_state` for results).

    Parameters
    ----------
    mass : m [kg] > 0, everything that moves with the frame (the mechanism's stationary parts included)
    inertia : centroidal moment of inertia I_G [kg m^2] > 0 about the axis normal to the plane
    mounts : the :class:`Mount` lines supporting the frame
    com : (x, y) [m] of the centre of mass in frame coordinates
    name : label
    gravity : (g_x, g_y) [m/s^2] in frame axes, or (0, 0): the weight's pendulum term in the rocking stiffness
        (:mod:`machdyn.vibration.gravity`)
    """

    mass: float
    inertia: float
    mounts: tuple[Mount, ...]
    com: tuple[float, float] = (0.0, 0.0)
    name: str = "frame"
    gravity: tuple[float, float] = (0.0, 0.0)

    def __post_init__(self) -> None:
        _check_number(f"mass of frame '{self.name}'", self.mass, "kg", rule=">0")
        _check_number(f"inertia of frame '{self.name}'", self.inertia, "kg*m^2", rule=">0")
        object.__setattr__(self, "com", tuple(_check_number(f"centre of mass of frame '{self.name}'", c, "m")
                                              for c in self.com))
        mounts = tuple(self.mounts)
        if not mounts:
            raise InputError(f"The frame '{self.name}' needs at least one mount; got none.")
        for m in mounts:
            if not isinstance(m, Mount):
                raise InputError(f"The mounts of frame '{self.name}' must be Mount objects; got {type(m).__name__}.")
        names = [m.name for m in mounts]
        dupes = sorted({n for n in names if names.count(n) > 1})
        if dupes:
            raise InputError(f"The mount names of frame '{self.name}' must be unique; got {', '.join(dupes)} twice.")
        object.__setattr__(self, "mounts", mounts)
        object.__setattr__(self, "gravity", tuple(_check_number(f"gravity of frame '{self.name}'", g, "m/s^2")
                                                  for g in self.gravity))

    def mount(self, name: str) -> Mount:
        """The mount called ``name``."""
        for m in self.mounts:
            if m.name == name:
                return m
        raise InputError(f"No mount '{name}' on frame '{self.name}'; mounts: {', '.join(m.name for m in self.mounts)}.")

    def mass_matrix(self) -> np.ndarray:
        """M [kg, kg m, kg m^2] for q = (x, y, theta) of the reference point: the rigid body's kinetic energy
        1/2 m |v_G|^2 + 1/2 I_G theta_dot^2 with v_G = (x_dot - theta_dot yG, y_dot + theta_dot xG)."""
        m, (xg, yg) = self.mass, self.com
        return np.array([
            [m, 0.0, -m * yg],
            [0.0, m, m * xg],
            [-m * yg, m * xg, self.inertia + m * (xg**2 + yg**2)],
        ])

    def influence_matrix(self) -> np.ndarray:
        """B (n_mounts x 3): row i is the mount's deflection per unit (x, y, theta)."""
        return np.array([m.influence for m in self.mounts])

    def stiffness_matrix(self) -> np.ndarray:
        """K = sum k_i b_i b_i^T [N/m, N, N m], plus the weight's pendulum term on the rotation when the frame has
        ``gravity`` (:func:`machdyn.vibration.gravity.gravity_stiffness`)."""
        k = mount_sum(self.mounts, "stiffness")
        return k + gravity_stiffness(self.mass, self.com, self.gravity, self.mounts, k)

    def damping_matrix(self) -> np.ndarray:
        """C = sum c_i b_i b_i^T [N s/m, N s, N m s]."""
        return mount_sum(self.mounts, "damping")

    @staticmethod
    def point_matrix(point) -> np.ndarray:
        """P (2 x 3) with u = P q: the displacement of frame point ``point`` (x, y) [m] per unit coordinate."""
        px, py = (float(v) for v in point)
        return np.array([[1.0, 0.0, -py], [0.0, 1.0, px]])
