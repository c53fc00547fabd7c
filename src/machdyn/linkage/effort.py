"""Crank effort and piston effort: the textbook forces of the reciprocating engine from machdyn's results.

Textbook terms (R. S. Khurmi & J. K. Gupta, *Theory of Machines*, chapter "Inertia forces in reciprocating
parts"; S. S. Rattan, *Theory of Machines*, the dynamic force analysis of the slider-crank) and machdyn's names:

===================================  ===============================================================
textbook                             machdyn
===================================  ===============================================================
piston effort F_P                    :attr:`PistonEffort.along_stroke`
thrust in the connecting rod F_Q     :attr:`PistonEffort.rod_thrust`
side thrust on the cylinder F_N      :attr:`PistonEffort.normal`
crank effort (crank-pin effort) F_T  :attr:`CrankEffort.tangential`
thrust on the crank-shaft bearings   :attr:`CrankEffort.radial`
turning moment on the crank shaft T  :attr:`CrankEffort.turning_moment`
driving torque (what a motor gives)  :attr:`CrankEffort.driving_torque` (``Forces.driving_torque``)
===================================  ===============================================================

Sign convention. ``Forces.driving_torque`` is the torque the motor (the drive) supplies to the crank,
counter-clockwise positive. Here it is given positive in the direction of rotation (the sign of the crank
speed; a crank at rest counts as turning counter-clockwise). In an engine the links drive the crank: the
turning moment is positive and the "driving" torque is negative (the load absorbs it). For a crank with no
mass, no load of its own and a steady speed, turning moment = -driving torque at every position.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from .model import RRP, split_ref
from .reactions import Forces
from .refs import column


@dataclass(frozen=True)
class CrankEffort:
    """The force at a crank pin resolved along and across the crank, at every position [N, N*m].

    ``tangential`` [N]: the component, perpendicular to the crank and positive in the direction of rotation,
    of the force the driven links exert on the crank at the pin (textbook crank effort F_T).
    ``radial`` [N]: its component along the crank, positive towards the crank's pivot (the thrust on the
    crank-shaft bearings F_B). ``turning_moment`` [N*m] = tangential * radius. ``driving_torque`` [N*m]: the
    torque the motor supplies to the crank, positive in the direction of rotation; ``driving_force`` [N] =
    driving_torque / radius, the tangential force at the pin radius that the motor supplies.
    """

    pin: str
    radius: np.ndarray
    tangential: np.ndarray
    radial: np.ndarray
    driving_torque: np.ndarray

    @property
    def turning_moment(self) -> np.ndarray:
        """Turning moment on the crank shaft [N*m] from the pin force: tangential * radius."""
        return self.tangential * self.radius

    @property
    def driving_force(self) -> np.ndarray:
        """The driving torque per crank radius [N], positive in the direction of rotation."""
        return self.driving_torque / self.radius


def crank_effort(forces: Forces, pin: str | None = None) -> CrankEffort:
    """Crank effort: the tangential and radial force at the crank pin and the driving torque.

    The pin force F is the opposite of the reaction of the joint ``pin`` (which is the force on the driven
    body from the crank). With e_r the unit vector from the pivot O to the pin A, e_t = s k x e_r the
    direction of rotation (s = sign of the crank speed) and r = |OA|::

        F_T = F . e_t,    F_R = -F . e_r,    T = F_T r

    (Khurmi & Gupta, *Theory of Machines*, "Inertia forces in reciprocating parts": F_T = F_Q sin(theta + phi),
    F_B = F_Q cos(theta + phi), T = F_T r for the slider-crank; here from the exact joint reaction of any
    linkage). Valid wherever
    :func:`~machdyn.linkage.kinetostatics.kinetostatics` is: any crank position away from dead positions.

    Parameters
    ----------
    forces : Forces
        The result of :func:`~machdyn.linkage.kinetostatics.kinetostatics` (or ``analyse(...).forces``).
    pin : str, optional
        The joint on the crank to resolve (e.g. ``"A"``); needed only when the crank carries several pins.

    Returns
    -------
    CrankEffort
        Arrays shaped like the crank angles (designs first); ``radius`` [m] is a design column or a scalar.

    Raises
    ------
    InputError
        If ``pin`` is not a joint on the crank, or the crank carries several pins and none is named.

    Examples
    --------
    >>> from machdyn.linkage import PointForce, kinetostatics, slider_crank, with_loads
    >>> engine = with_loads(slider_crank(0.2, 0.6, masses=(0.0, 0.0, 0.0), gravity=(0.0, 0.0)),
    ...                     forces=PointForce("gas", "slider.B", fx=-1000.0))
    >>> effort = crank_effort(kinetostatics(engine, np.radians(90.0), speed=10.0))
    >>> round(float(effort.tangential), 6), round(float(effort.turning_moment), 6)
    (1000.0, 200.0)
    """
    if not isinstance(forces, Forces):
        raise InputError(f"crank_effort needs the Forces of kinetostatics; got {type(forces).__name__}.")
    mech = forces.mechanism
    crank = mech.crank.body
    pins = [j for j in forces.joints if j.body_1 == crank and j.kind == "R"]
    joint = _one(pins, pin, lambda j: j.name,
                 f"The crank '{crank}' of '{mech.name}' carries {len(pins)} pins", "pin",
                 f"The pin must be a joint on the crank '{crank}'", "pins")
    kin = forces.kinematics
    pivot = kin.point(mech.crank.pivot)
    point_name = joint.name.split(":")[0]
    pin_motion = kin.point(f"{crank}.{point_name}")
    u, v = (column(c) for c in mech.body(crank).points[point_name])
    pu, pv = (column(c) for c in mech.body(crank).points[split_ref(mech.crank.pivot)[1]])
    radius = np.hypot(np.asarray(u) - pu, np.asarray(v) - pv)
    if np.any(radius <= 0):
        raise InputError(f"The pin '{joint.name}' lies on the crank's pivot: the crank radius is 0 m.")
    ex = (pin_motion.x - pivot.x) / radius
    ey = (pin_motion.y - pivot.y) / radius
    turning = np.where(kin.speed < 0, -1.0, 1.0)
    reaction = forces.joint(joint.name)
    fx, fy = -reaction.fx, -reaction.fy  # on the crank from the driven body
    tangential = turning * (ex * fy - ey * fx)
    radial = -(ex * fx + ey * fy)
    return CrankEffort(joint.name, radius, tangential, radial, turning * forces.driving_torque)


@dataclass(frozen=True)
class PistonEffort:
    """The force between a piston (slider) and its connecting rod at every position [N].

    ``along_stroke`` (piston effort F_P): the component along the line of stroke of the force the piston
    exerts on the rod, positive towards the crank side (the rod's other joint). ``normal``: the signed force
    of the guide on the piston along the guide's left normal (side thrust F_N). ``rod_thrust`` (F_Q): the
    component of the piston's force on the rod along the rod from the piston pin to its other joint,
    positive in compression; for a rod without mass, F_Q = F_P / cos(phi).
    """

    slider: str
    along_stroke: np.ndarray
    normal: np.ndarray
    rod_thrust: np.ndarray


def piston_effort(forces: Forces, slider: str | None = None) -> PistonEffort:
    """Piston effort: the force of a piston (the slider of an RRP group) on its connecting rod.

    With u the guide direction, B the piston pin, A the rod's other joint and F the force of the piston on the
    rod (the opposite of the reaction at B)::

        F_P = F . u sign((A - B) . u),    F_Q = F . (A - B) / |A - B|

    (Khurmi & Gupta, *Theory of Machines*, "Inertia forces in reciprocating parts": F_P = F_L -+ F_I,
    F_Q = F_P / cos phi.)

    Parameters
    ----------
    forces : Forces
        The result of :func:`~machdyn.linkage.kinetostatics.kinetostatics`.
    slider : str, optional
        The slider body; needed only when the mechanism has several link-and-slider (RRP) groups.

    Returns
    -------
    PistonEffort
        The slider's name; along_stroke F_P [N] (positive towards the crank side), normal side thrust F_N [N]
        and rod_thrust F_Q [N], shaped like the crank angles.

    Raises
    ------
    InputError
        If the mechanism has no RRP group, ``slider`` is not the slider of one, or several exist and none is
        named.

    Examples
    --------
    >>> from machdyn.linkage import PointForce, kinetostatics, slider_crank, with_loads
    >>> engine = with_loads(slider_crank(0.2, 0.6, masses=(0.0, 0.0, 0.0), gravity=(0.0, 0.0)),
    ...                     forces=PointForce("gas", "slider.B", fx=-1000.0))
    >>> round(float(piston_effort(kinetostatics(engine, 1.0, speed=10.0)).along_stroke), 6)
    1000.0
    """
    if not isinstance(forces, Forces):
        raise InputError(f"piston_effort needs the Forces of kinetostatics; got {type(forces).__name__}.")
    mech = forces.mechanism
    groups = [d for d in mech.dyads if isinstance(d, RRP)]
    group = _one(groups, slider, lambda d: d.b,
                 f"Mechanism '{mech.name}' has {len(groups)} sliders driven by a rod", "slider",
                 "The slider must be the slider of a link-and-slider (RRP) group", "sliders")
    kin = forces.kinematics
    piston = kin.body(group.b)
    ux, uy = piston.cos, piston.sin
    pin_b = kin.point(f"{group.a}.{group.inner}")
    pin_a = kin.point(f"{group.a}.{split_ref(group.pin_a)[1]}")
    dx, dy = pin_a.x - pin_b.x, pin_a.y - pin_b.y
    reaction = forces.joint(_joint_name(forces, group.inner, group.b))
    fx, fy = -reaction.fx, -reaction.fy  # on the rod from the piston
    towards_crank = np.where(dx * ux + dy * uy < 0, -1.0, 1.0)
    guide = forces.joint(_joint_name(forces, f"{group.b}/{group.guide.body}", group.b))
    return PistonEffort(
        group.b,
        (fx * ux + fy * uy) * towards_crank,
        np.asarray(guide.normal),
        (fx * dx + fy * dy) / np.hypot(dx, dy),
    )


def _joint_name(forces: Forces, name: str, body_2: str) -> str:
    for j in forces.joints:
        if j.name.split(":")[0] == name and j.body_2 == body_2:
            return j.name
    raise InputError(f"No joint '{name}' on body '{body_2}'; joints: {', '.join(j.name for j in forces.joints)}.")


def _one(items: list, wanted: str | None, name_of, several: str, argument: str, not_found: str, plural: str):
    """The item named ``wanted`` among ``items``, or the only one when none is named; an error naming the
    candidates otherwise."""
    names = ", ".join(name_of(i) for i in items) or "none"
    if wanted is None:
        if len(items) != 1:
            raise InputError(f"{several} ({names}); name one with {argument}=...")
        return items[0]
    found = [i for i in items if name_of(i) == wanted]
    if not found:
        raise InputError(f"{not_found}; got {wanted!r}; {plural}: {names}.")
    return found[0]
