"""The total centre of mass of a mechanism: its position, velocity and acceleration at every position.

The moving bodies and the point masses attached to them (counterweights) together have the mass M and the
centre of mass G with M r_G = sum m_i r_i, and likewise for its velocity and acceleration. Newton's second law
for the whole moving mechanism gives the shaking force: with gravity off and no external loads, the force the
mechanism exerts on its frame is -M a_G (Newton's second law for a system of bodies; Uicker, Pennock &
Shigley, *Theory of Machines and Mechanisms*, 5th ed., chapter "Balancing"). The mechanism is force-balanced
exactly when G stands still.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import InputError
from .loads import mass_elements
from .motion import Kinematics


@dataclass(frozen=True)
class MassCentre:
    """Total mass [kg] and the motion of the total centre of mass, global axes, at every position.

    ``mass`` is a scalar or a design column (N, 1); the others are shaped like the crank angles, designs first:
    x, y [m], vx, vy [m/s], ax, ay [m/s^2].
    """

    mass: np.ndarray
    x: np.ndarray
    y: np.ndarray
    vx: np.ndarray
    vy: np.ndarray
    ax: np.ndarray
    ay: np.ndarray

    @property
    def speed(self) -> np.ndarray:
        """|v_G| [m/s]."""
        return np.hypot(self.vx, self.vy)

    @property
    def inertia_force(self) -> tuple[np.ndarray, np.ndarray]:
        """-M a_G [N]: the resultant inertia (d'Alembert) force of the moving mechanism."""
        return -self.mass * self.ax, -self.mass * self.ay


def mass_centre(kin: Kinematics) -> MassCentre:
    """The total centre of mass of every moving body and point mass of the mechanism.

    M = sum m_i,  r_G = sum m_i r_i / M,  v_G = sum m_i v_i / M,  a_G = sum m_i a_i / M, each r_i the centre of
    mass of a body or the position of a point mass (the definition of the centre of mass of a system;
    Uicker, Pennock & Shigley, 5th ed., chapter "Balancing").

    Parameters
    ----------
    kin : Kinematics
        The result of :func:`~machdyn.linkage.kinematics.kinematics` (one design or many).

    Returns
    -------
    MassCentre
        Total mass M [kg]; position x, y [m], velocity vx, vy [m/s] and acceleration ax, ay [m/s²] of the
        centre of mass, shaped like the crank angles (designs first).

    Raises
    ------
    InputError
        If the moving mechanism has no mass (for some design): its centre of mass is undefined.

    Examples
    --------
    >>> import numpy as np
    >>> from machdyn.linkage import kinematics, slider_crank
    >>> mech = slider_crank(0.1, 0.3, masses=(0.0, 0.0, 2.0))   # all the mass in the slider
    >>> g = mass_centre(kinematics(mech, 0.0))
    >>> float(g.mass), round(float(g.x), 12)
    (2.0, 0.4)
    """
    if not isinstance(kin, Kinematics):
        raise InputError(f"mass_centre needs the result of kinematics; got {type(kin).__name__}.")
    elements = mass_elements(kin)
    total = sum((np.asarray(e.mass, dtype=float) for e in elements), np.asarray(0.0))
    if np.any(total <= 0):
        raise InputError(
            f"The moving bodies and point masses of '{kin.mechanism.name}' must have a total mass > 0 kg to have "
            f"a centre of mass; got {float(np.min(total)):g} kg."
        )
    sums = {key: sum(e.mass * getattr(e.motion, key) for e in elements) for key in ("x", "y", "vx", "vy", "ax", "ay")}
    shape = kin.shape
    return MassCentre(
        total, *(np.broadcast_to(sums[key] / total, shape) for key in ("x", "y", "vx", "vy", "ax", "ay"))
    )


def inertial_force(kin: Kinematics) -> tuple[np.ndarray, np.ndarray]:
    """-sum m_i a_i [N]: the resultant inertia (d'Alembert) force of the moving bodies and point masses, equal to
    -M a_G where there is mass, and zero for a massless (statics) model, which has no centre of mass (Uicker,
    Pennock & Shigley, 5th ed., chapter "Balancing": the shaking force is the sum of the inertia forces).

    Parameters
    ----------
    kin : Kinematics
        The result of :func:`~machdyn.linkage.kinematics.kinematics` (one design or many).

    Returns
    -------
    tuple of numpy.ndarray
        (fx, fy) [N] per crank position (and design), global axes.

    Examples
    --------
    >>> import numpy as np
    >>> from machdyn.linkage import kinematics, slider_crank
    >>> fx, fy = inertial_force(kinematics(slider_crank(0.1, 0.3, masses=(0.0, 0.0, 0.0)), np.linspace(0, 6, 5)))
    >>> float(np.max(np.abs(fx))), float(np.max(np.abs(fy)))
    (0.0, 0.0)
    """
    if not isinstance(kin, Kinematics):
        raise InputError(f"inertial_force needs the result of kinematics; got {type(kin).__name__}.")
    elements = mass_elements(kin)
    zero = np.zeros(kin.shape)
    fx = sum((-np.asarray(e.mass, dtype=float) * e.motion.ax for e in elements), zero)
    fy = sum((-np.asarray(e.mass, dtype=float) * e.motion.ay for e in elements), zero)
    return np.broadcast_to(fx, kin.shape), np.broadcast_to(fy, kin.shape)


def inertial_shaking_moment(kin: Kinematics, about: tuple[float, float] = (0.0, 0.0)) -> np.ndarray:
    """The inertial shaking moment [N*m] about the point ``about`` [m] (counter-clockwise positive): the moment
    of the d'Alembert loads of every moving mass, sum over i of (r_i - z) x (-m_i a_i) - I_i alpha_i, with r_i,
    a_i the position and acceleration of its centre of mass and alpha_i the angular acceleration of its body.

    With gravity off and no external loads it is the moment the moving mechanism puts on its frame, the
    driving torque's reaction on the motor's stator included (Newton-Euler for the system of bodies; Berkof &
    Lowen, "A new method for completely force balancing simple linkages", J. Eng. Ind. 91(1), 1969, and Uicker,
    Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed., chapter "Balancing"); process loads and
    weight add to the frame's moment (:meth:`~machdyn.linkage.kinetostatics.Forces.shaking_moment`) but not to
    this one.

    Parameters
    ----------
    kin : Kinematics
        The result of :func:`~machdyn.linkage.kinematics.kinematics` (one design or many).
    about : tuple of float
        The point [m] the moment is taken about, global axes.

    Returns
    -------
    numpy.ndarray
        The inertial shaking moment [N*m], shaped like the crank angles (designs first).

    Examples
    --------
    >>> import numpy as np
    >>> from machdyn.linkage import kinematics, slider_crank
    >>> mech = slider_crank(0.1, 0.3, masses=(0.0, 0.0, 2.0), gravity=(0.0, 0.0))  # all the mass in the slider
    >>> m = inertial_shaking_moment(kinematics(mech, np.radians(30.0), 10.0))
    >>> float(np.abs(m).max()) < 1e-12       # the slider moves along the line through the origin
    True
    """
    zx, zy = (float(v) for v in about)
    total: Any = 0.0
    for e in mass_elements(kin):
        m = np.asarray(e.mass, dtype=float)
        s = e.motion
        alpha = kin.body(e.body).alpha
        total = total + (np.asarray(s.x) - zx) * (-m * np.asarray(s.ay)) - (np.asarray(s.y) - zy) * (
            -m * np.asarray(s.ax)) - np.asarray(e.inertia, dtype=float) * np.asarray(alpha)
    return np.broadcast_to(total, kin.shape)
