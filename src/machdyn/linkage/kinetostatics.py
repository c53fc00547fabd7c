"""Kinetostatics: joint reactions, driving torque, input power, and the force and moment on the frame.

d'Alembert's principle turns each body's motion into loads (inertia force -m a_G at the centre of mass,
inertia moment -I alpha), added to gravity, external forces and torques and springs. The dyads are then
solved in reverse order, each in closed form (:mod:`machdyn.linkage.dyads`), passing their reactions back
to the bodies they hang on; the crank's equilibrium gives the pivot reaction and the driving torque
(Artobolevsky, *Theory of Mechanisms and Machines*, ch. 5; seed 003 eqs 13-17).
"""

from __future__ import annotations

from dataclasses import dataclass

from .engines import check_engine
from .fused import fused_kinetostatics
from .kinematics import kinematics
from .loads import applied_forces, applied_torques, mass_elements, spring_states
from .model import Mechanism, joints
from .motion import Kinematics
from .reactions import Forces, Joint, Reaction
from .refs import GROUND, column, full, local_point, split_ref


def _add(loads, body, fx, fy, m):
    if body == GROUND:
        return
    lfx, lfy, lm = loads[body]
    loads[body] = (lfx + fx, lfy + fy, lm + m)


def _add_force_at(loads, body, x, y, fx, fy):
    _add(loads, body, fx, fy, x * fy - y * fx)


class _Frame:
    """Accumulates the loads the mechanism puts on the frame: force and moment about the origin."""

    def __init__(self):
        self.fx = 0.0
        self.fy = 0.0
        self.m = 0.0

    def force_at(self, x, y, fx, fy):
        self.fx = self.fx + fx
        self.fy = self.fy + fy
        self.m = self.m + (x * fy - y * fx)

    def couple(self, c):
        self.m = self.m + c


def body_loads(kin: Kinematics) -> tuple[dict, _Frame]:
    """Resultant load (Fx, Fy, M about the origin) on every moving body from inertia, gravity, external forces
    and torques and springs; and what springs anchored to the frame put on the frame."""
    mech = kin.mechanism
    gx, gy = (column(v) for v in mech.gravity)
    loads = {name: (0.0, 0.0, 0.0) for name in mech.moving_bodies}
    frame = _Frame()
    for m in mass_elements(kin):
        G = m.motion
        fx = m.mass * (gx - G.ax)
        fy = m.mass * (gy - G.ay)
        _add(loads, m.body, fx, fy, G.x * fy - G.y * fx - m.inertia * kin.body(m.body).alpha)
    for f in applied_forces(kin):
        _add_force_at(loads, f.body, f.motion.x, f.motion.y, f.fx, f.fy)
    for t in applied_torques(kin):
        _add(loads, t.body, 0.0, 0.0, t.torque)
    for s in spring_states(kin):
        # A stretched spring pulls point 1 towards point 2 and point 2 towards point 1.
        f1x, f1y = s.tension * s.ex, s.tension * s.ey
        for body, p, sx, sy in ((s.body_1, s.p1, f1x, f1y), (s.body_2, s.p2, -f1x, -f1y)):
            if body == GROUND:
                frame.force_at(p.x, p.y, sx, sy)
            else:
                _add_force_at(loads, body, p.x, p.y, sx, sy)
    return loads, frame


def kinetostatics(
    mech: Mechanism,
    crank_angle=None,
    speed=1.0,
    acceleration=0.0,
    *,
    kinematics_result: Kinematics | None = None,
    engine: str = "numpy",
) -> Forces:
    """Joint reactions, driving torque and frame loads of ``mech`` at each crank angle.

    Parameters
    ----------
    mech : the linkage; crank_angle [rad]; speed [rad/s]; acceleration [rad/s^2] (as for
        :func:`~machdyn.linkage.kinematics.kinematics`), or an already computed ``kinematics_result``.

    engine : "numpy", "fused" or "auto", as for :func:`~machdyn.linkage.kinematics.kinematics` (without a
        ``kinematics_result``, the fused engine computes motion and forces in one pass).

    Valid away from dead positions, where the reactions grow without bound (the dyad determinant vanishes).
    """
    check_engine(engine)
    if kinematics_result is None and engine != "numpy":
        forces = fused_kinetostatics(mech, crank_angle, speed, acceleration, engine, reference=kinematics)
        if forces is not None:
            return forces
    kin = kinematics_result or kinematics(mech, crank_angle, speed, acceleration)
    loads, frame = body_loads(kin)
    joint_list = tuple(Joint(*j) for j in joints(mech))
    ctx = ForceContext(mech, kin.bodies, loads, frame, [None] * len(joint_list))
    for i in reversed(range(len(mech.dyads))):
        ctx.base = 1 + 3 * i  # the crank's pivot is joint 0; each dyad declares three joints
        mech.dyads[i].solve_forces(ctx)

    crank = mech.crank.body
    O = ctx.point(mech.crank.pivot)
    cfx, cfy, cm = loads[crank]
    torque = -(cm - (O.x * cfy - O.y * cfx))
    ctx.base = 0
    ctx.react(0, -cfx, -cfy)
    frame.force_at(O.x, O.y, cfx, cfy)
    frame.couple(-torque)
    shape = kin.shape
    ordered = {j.name: _broadcast_reaction(r, shape) for j, r in zip(joint_list, ctx.reactions, strict=True)}
    return Forces(
        kin,
        joint_list,
        ordered,
        full(torque, shape),
        full(frame.fx, shape),
        full(frame.fy, shape),
        full(frame.m, shape),
    )


class ForceContext:
    """What a dyad's force solver works with: the body states and accumulated loads, the frame, and the
    reactions of the joints (the dyad's three joints start at index ``base`` of the mechanism's joints)."""

    def __init__(self, mech: Mechanism, states: dict, loads: dict, frame: _Frame, reactions: list):
        self.mech = mech
        self.states = states
        self.loads = loads
        self.frame = frame
        self.reactions = reactions
        self.base = 0

    def point(self, ref: str) -> _PointXY:
        """Position [m] of the known point ``"body.point"``."""
        body, point = split_ref(ref)
        if body == GROUND:
            x, y = self.mech.ground[point]
            return _PointXY(column(x), column(y))
        st = self.states[body]
        px, py = st.offset(*local_point(self.mech, body, point))
        return _PointXY(st.x + px, st.y + py)

    def on(self, body: str, point: str) -> _PointXY:
        """Position [m] of ``point`` of the just solved ``body``."""
        return _point_on(self.states[body], local_point(self.mech, body, point))

    def react(self, index: int, fx, fy, normal=None, couple=None) -> None:
        """The reaction of the dyad's joint ``index`` (0, 1, 2 in the order of its declared joints)."""
        self.reactions[self.base + index] = Reaction(fx, fy, normal, couple)

    def transmit(self, body: str, x, y, fx, fy) -> None:
        """The known body carries the opposite of a reaction it exerts at (x, y)."""
        if body == GROUND:
            self.frame.force_at(x, y, -fx, -fy)
        else:
            _add_force_at(self.loads, body, x, y, -fx, -fy)

    def couple_back(self, body: str, couple) -> None:
        """The known body carries the opposite of a couple a prismatic joint exerts."""
        if body == GROUND:
            self.frame.couple(-couple)
        else:
            _add(self.loads, body, 0.0, 0.0, -couple)


@dataclass(slots=True)
class _PointXY:
    x: object
    y: object


def _point_on(state, local):
    px, py = state.offset(*local)
    return _PointXY(state.x + px, state.y + py)


def _broadcast_reaction(r: Reaction, shape) -> Reaction:
    def b(v):
        return None if v is None else full(v, shape)

    return Reaction(b(r.fx), b(r.fy), b(r.normal), b(r.couple))
