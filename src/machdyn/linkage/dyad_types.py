"""The dyad types, each declared once: its joints, the points it needs, its motion solver, its force solver
and what a drawing needs.

A dyad (Assur group of class II) attaches two new bodies ``a`` and ``b`` to points already placed. Every
dyad type is a frozen dataclass deriving from :class:`DyadType`; the engine (kinematics, kinetostatics,
diagnostics, the fused engine, validation, drawings and tables) asks the declaration instead of testing
types. The closed forms themselves are written once, in :mod:`machdyn.linkage.dyad_forms`, and called by
:mod:`machdyn.linkage.dyads` (NumPy) and :mod:`machdyn.linkage.fused_dyads` (the compiled engine's kernel).

Adding a dyad type: write its motion and force forms in :mod:`.dyad_forms` (one text for both engines), declare
a dataclass here implementing every method of :class:`DyadType`, add it to :data:`DYAD_TYPES`, and give the fused
engine its code, the calls of the same forms (:data:`machdyn.linkage.fused_dyads.EMITTERS`; see docs/linkage.md).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

from . import dyads as dy
from .refs import GROUND, Number, Points, column, local_point, split_ref

#: A joint as (name, kind 'R' or 'P', earlier body, later body).
JointDecl = tuple[str, str, str, str]


@dataclass(frozen=True)
class Guide:
    """A straight slide line fixed in a known body: through ``point`` (``"body.point"``) with direction
    ``angle`` [rad] measured in that body's frame (0 = along the body's x axis)."""

    point: str
    angle: Number = 0.0

    @property
    def body(self) -> str:
        return self.point.split(".", 1)[0]


@dataclass(frozen=True)
class DyadDrawing:
    """What a drawing of a dyad needs: the bodies drawn as bars or plates (``links``), those drawn as
    sliding blocks (``sliders``), and the straight guides with the slider that runs on each."""

    links: tuple[str, ...]
    sliders: tuple[str, ...]
    guides: tuple[tuple[Guide, str], ...]


@dataclass(frozen=True)
class Output:
    """An output whose limit positions matter: a slider's travel on a ground guide (``kind`` 'slide') or a
    rocker's angle about a ground pivot ('angle')."""

    body: str
    kind: str


class DyadType:
    """What every dyad declaration provides. Subclasses are frozen dataclasses with fields ``a`` and ``b``
    (the two new bodies, ``a`` placed before ``b``) and the joints' data."""

    kind: ClassVar[str]
    #: True if the dyad has two assemblies chosen by ``branch`` (+1 or -1).
    has_branch: ClassVar[bool] = True
    a: str
    b: str

    def joints(self) -> tuple[JointDecl, JointDecl, JointDecl]:
        """The three joints in the order the solvers report their reactions."""
        raise NotImplementedError

    def known_points(self) -> tuple[tuple[str, str], ...]:
        """(field, ``"body.point"``) of every point the dyad hangs on (placed before it), guides included."""
        raise NotImplementedError

    def guides(self) -> tuple[tuple[str, Guide], ...]:
        """(field, guide) of the straight guides fixed in known bodies."""
        return ()

    def own_points(self) -> tuple[tuple[str, str], ...]:
        """(body, point) the dyad's own bodies must have for its joints."""
        raise NotImplementedError

    def slide_bodies(self) -> dict[str, str]:
        """{'a' or 'b': body} of the bodies whose travel along a line the motion solver reports."""
        return {}

    def outputs(self) -> tuple[Output, ...]:
        """The dyad's outputs with limit positions (sliders on ground guides, rockers on ground pivots)."""
        return ()

    def drawing(self) -> DyadDrawing:
        raise NotImplementedError

    def solve_motion(self, mech: Points, states: dict) -> dy.DyadMotion:
        """Position (on the dyad's branch), velocity and acceleration of both bodies from the known states."""
        raise NotImplementedError

    def solve_forces(self, ctx: Any) -> None:
        """Reactions of the three joints from the loads on both bodies; the opposite reactions go back to the
        known bodies (``ctx``: :class:`machdyn.linkage.kinetostatics.ForceContext`)."""
        raise NotImplementedError


def _point(mech: Points, states: dict, ref: str):
    body, point = split_ref(ref)
    return states[body].point(*local_point(mech, body, point))


def _name(ref: str) -> str:
    return split_ref(ref)[1]


def _body(ref: str) -> str:
    return split_ref(ref)[0]


@dataclass(frozen=True)
class RRR(DyadType):
    """Dyad of two links joined by revolute joints: ``a`` pinned at the known point ``pin_a``, ``b`` at
    ``pin_b``, and a to b at the inner joint ``inner``.

    ``branch`` = +1 puts the inner joint to the left of the line from pin_a to pin_b, -1 to the right.
    """

    kind: ClassVar[str] = "RRR"
    a: str
    b: str
    pin_a: str
    pin_b: str
    inner: str
    branch: int = 1

    def joints(self):
        return (
            (_name(self.pin_a), "R", _body(self.pin_a), self.a),
            (_name(self.pin_b), "R", _body(self.pin_b), self.b),
            (self.inner, "R", self.a, self.b),
        )

    def known_points(self):
        return (("pin_a", self.pin_a), ("pin_b", self.pin_b))

    def own_points(self):
        return ((self.a, _name(self.pin_a)), (self.a, self.inner), (self.b, _name(self.pin_b)), (self.b, self.inner))

    def outputs(self):
        return (Output(self.b, "angle"),) if _body(self.pin_b) == GROUND else ()

    def drawing(self):
        return DyadDrawing((self.a, self.b), (), ())

    def solve_motion(self, mech, states):
        return dy.rrr_motion(
            _point(mech, states, self.pin_a),
            _point(mech, states, self.pin_b),
            local_point(mech, self.a, _name(self.pin_a)),
            local_point(mech, self.a, self.inner),
            local_point(mech, self.b, _name(self.pin_b)),
            local_point(mech, self.b, self.inner),
            self.branch,
        )

    def solve_forces(self, ctx):
        la, lb = ctx.loads[self.a], ctx.loads[self.b]
        P, Q = ctx.point(self.pin_a), ctx.point(self.pin_b)
        B = ctx.on(self.a, self.inner)
        fp, fq, fab = dy.rrr_forces(la, lb, P, Q, B)
        ctx.react(0, *fp)
        ctx.react(1, *fq)
        ctx.react(2, *fab)
        ctx.transmit(_body(self.pin_a), P.x, P.y, *fp)
        ctx.transmit(_body(self.pin_b), Q.x, Q.y, *fq)



@dataclass(frozen=True)
class RRP(DyadType):
    """Dyad link + slider: link ``a`` pinned at the known point ``pin_a`` and to slider ``b`` at ``inner``;
    the slider's point ``inner`` moves along ``guide`` (a line fixed in a known body).

    ``branch`` = +1 puts the slider ahead of the foot of pin_a on the guide (along the guide direction),
    -1 behind it.
    """

    kind: ClassVar[str] = "RRP"
    a: str
    b: str
    pin_a: str
    inner: str
    guide: Guide
    branch: int = 1

    def joints(self):
        return (
            (_name(self.pin_a), "R", _body(self.pin_a), self.a),
            (self.inner, "R", self.a, self.b),
            (f"{self.b}/{self.guide.body}", "P", self.guide.body, self.b),
        )

    def known_points(self):
        return (("pin_a", self.pin_a), ("guide", self.guide.point))

    def guides(self):
        return (("guide", self.guide),)

    def own_points(self):
        return ((self.a, _name(self.pin_a)), (self.a, self.inner), (self.b, self.inner))

    def slide_bodies(self):
        return {"b": self.b}

    def outputs(self):
        return (Output(self.b, "slide"),) if self.guide.body == GROUND else ()

    def drawing(self):
        return DyadDrawing((self.a,), (self.b,), ((self.guide, self.b),))

    def solve_motion(self, mech, states):
        gb, gp = split_ref(self.guide.point)
        return dy.rrp_motion(
            _point(mech, states, self.pin_a),
            states[gb],
            local_point(mech, gb, gp),
            column(self.guide.angle),
            local_point(mech, self.a, _name(self.pin_a)),
            local_point(mech, self.a, self.inner),
            local_point(mech, self.b, self.inner),
            self.branch,
        )

    def solve_forces(self, ctx):
        la, lb = ctx.loads[self.a], ctx.loads[self.b]
        gb = self.guide.body
        P = ctx.point(self.pin_a)
        B = ctx.on(self.a, self.inner)
        slider = ctx.states[self.b]
        fp, fab, N, couple = dy.rrp_forces(la, lb, P, B, slider.cos, slider.sin)
        nx, ny = -slider.sin, slider.cos
        ctx.react(0, *fp)
        ctx.react(1, *fab)
        ctx.react(2, N * nx, N * ny, N, couple)
        ctx.transmit(_body(self.pin_a), P.x, P.y, *fp)
        ctx.transmit(gb, B.x, B.y, N * nx, N * ny)
        ctx.couple_back(gb, couple)



@dataclass(frozen=True)
class RPR(DyadType):
    """Dyad block + rocker: block ``a`` pinned at the known point ``pin_a`` slides along a line fixed in
    rocker ``b``; the rocker is pinned at the known point ``pin_b``.

    The slide line is ``slide`` = (point name in b, angle [rad] in b's frame); the block's frame is aligned
    with it. ``branch`` = +1 points the slide direction from the rocker side towards the block, -1 away.
    """

    kind: ClassVar[str] = "RPR"
    a: str
    b: str
    pin_a: str
    pin_b: str
    slide: tuple[str, Number]
    branch: int = 1

    def joints(self):
        return (
            (_name(self.pin_a), "R", _body(self.pin_a), self.a),
            (_name(self.pin_b), "R", _body(self.pin_b), self.b),
            (f"{self.a}/{self.b}", "P", self.b, self.a),
        )

    def known_points(self):
        return (("pin_a", self.pin_a), ("pin_b", self.pin_b))

    def own_points(self):
        return ((self.a, _name(self.pin_a)), (self.b, _name(self.pin_b)), (self.b, self.slide[0]))

    def slide_bodies(self):
        return {"a": self.a}

    def outputs(self):
        return (Output(self.b, "angle"),) if _body(self.pin_b) == GROUND else ()

    def drawing(self):
        return DyadDrawing((self.b,), (self.a,), ())

    def solve_motion(self, mech, states):
        return dy.rpr_motion(
            _point(mech, states, self.pin_a),
            _point(mech, states, self.pin_b),
            local_point(mech, self.a, _name(self.pin_a)),
            local_point(mech, self.b, _name(self.pin_b)),
            local_point(mech, self.b, self.slide[0]),
            column(self.slide[1]),
            self.branch,
        )

    def solve_forces(self, ctx):
        la, lb = ctx.loads[self.a], ctx.loads[self.b]
        P, Q = ctx.point(self.pin_a), ctx.point(self.pin_b)
        block = ctx.states[self.a]
        fp, fq, N, couple = dy.rpr_forces(la, lb, P, Q, block.cos, block.sin)
        nx, ny = -block.sin, block.cos
        ctx.react(0, *fp)
        ctx.react(1, *fq)
        ctx.react(2, N * nx, N * ny, N, couple)
        ctx.transmit(_body(self.pin_a), P.x, P.y, *fp)
        ctx.transmit(_body(self.pin_b), Q.x, Q.y, *fq)



@dataclass(frozen=True)
class PRP(DyadType):
    """Dyad of two sliders joined by a revolute joint ``inner``: ``a`` slides along ``guide_a``, ``b`` along
    ``guide_b`` (lines fixed in known bodies). The joint sits where the two lines cross (no branch)."""

    kind: ClassVar[str] = "PRP"
    has_branch: ClassVar[bool] = False
    a: str
    b: str
    inner: str
    guide_a: Guide
    guide_b: Guide

    def joints(self):
        return (
            (f"{self.a}/{self.guide_a.body}", "P", self.guide_a.body, self.a),
            (f"{self.b}/{self.guide_b.body}", "P", self.guide_b.body, self.b),
            (self.inner, "R", self.a, self.b),
        )

    def known_points(self):
        return (("guide_a", self.guide_a.point), ("guide_b", self.guide_b.point))

    def guides(self):
        return (("guide_a", self.guide_a), ("guide_b", self.guide_b))

    def own_points(self):
        return ((self.a, self.inner), (self.b, self.inner))

    def slide_bodies(self):
        return {"a": self.a, "b": self.b}

    def drawing(self):
        return DyadDrawing((), (self.a, self.b), ((self.guide_a, self.a), (self.guide_b, self.b)))

    def solve_motion(self, mech, states):
        b1, p1 = split_ref(self.guide_a.point)
        b2, p2 = split_ref(self.guide_b.point)
        return dy.prp_motion(
            states[b1],
            local_point(mech, b1, p1),
            column(self.guide_a.angle),
            states[b2],
            local_point(mech, b2, p2),
            column(self.guide_b.angle),
            local_point(mech, self.a, self.inner),
            local_point(mech, self.b, self.inner),
        )

    def solve_forces(self, ctx):
        la, lb = ctx.loads[self.a], ctx.loads[self.b]
        B = ctx.on(self.a, self.inner)
        sa, sb = ctx.states[self.a], ctx.states[self.b]
        Na, ca, Nb, cb, fab = dy.prp_forces(la, lb, B, (sa.cos, sa.sin), (sb.cos, sb.sin))
        g1, g2 = self.guide_a.body, self.guide_b.body
        n1 = (-sa.sin, sa.cos)
        n2 = (-sb.sin, sb.cos)
        ctx.react(0, Na * n1[0], Na * n1[1], Na, ca)
        ctx.react(1, Nb * n2[0], Nb * n2[1], Nb, cb)
        ctx.react(2, *fab)
        ctx.transmit(g1, B.x, B.y, Na * n1[0], Na * n1[1])
        ctx.transmit(g2, B.x, B.y, Nb * n2[0], Nb * n2[1])
        ctx.couple_back(g1, ca)
        ctx.couple_back(g2, cb)



#: Every dyad type by its name, as problem files and messages write it.
DYAD_TYPES: dict[str, type[DyadType]] = {t.kind: t for t in (RRR, RRP, RPR, PRP)}

Dyad = RRR | RRP | RPR | PRP
