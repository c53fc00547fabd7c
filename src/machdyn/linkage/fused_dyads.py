"""The dyads' code for the fused engine: :mod:`machdyn.linkage.dyads` written as straight-line scalar code.

Each function emits, through a :class:`~machdyn.linkage.fused_source.Generator`, the motion of one dyad
(position on its branch, velocity, acceleration) and registers the code of its force solution, with the
formulas and the order of operations of the NumPy solvers, so that both engines agree to rounding.
"""

from __future__ import annotations

from .dyads import ASSEMBLY_TOL
from .fused_source import Generator
from .refs import split_ref


def _moment_about(load: tuple[str, str, str], x: str, y: str) -> str:
    return f"({load[2]} - ({x} * {load[1]} - {y} * {load[0]}))"


def _anchor(pin: dict, pin_local, other: dict, other_local):
    return (pin, pin_local) if pin_local is None else (other, other_local)


# ------------------------------------------------------------------------------------------- dyad codes


def rrr_code(gen: Generator, d) -> None:
    """RRR: machdyn.linkage.dyads.rrr_motion and rrr_forces, in scalars."""
    a_pin, a_inner = gen.local(d.a, split_ref(d.pin_a)[1]), gen.local(d.a, d.inner)
    b_pin, b_inner = gen.local(d.b, split_ref(d.pin_b)[1]), gen.local(d.b, d.inner)
    La, cda, sda = gen.line(a_pin, a_inner)
    Lb, cdb, sdb = gen.line(b_pin, b_inner)
    br = gen.param(float(d.branch))
    P, Q = gen.ref_point(d.pin_a), gen.ref_point(d.pin_b)
    k = gen.new("d")
    gen.emit(gen.motion, f"""
        {k}dx = {Q['x']} - {P['x']}
        {k}dy = {Q['y']} - {P['y']}
        {k}d2 = {k}dx * {k}dx + {k}dy * {k}dy
        {k}d = math.sqrt({k}d2)
        {k}along = ({La} * {La} - {Lb} * {Lb} + {k}d2) / (2.0 * {k}d)
        {k}h2 = {La} * {La} - {k}along * {k}along
        {k}co = {k}d == 0.0
        {k}ok = ({k}h2 >= -{ASSEMBLY_TOL!r} * {La} * {La}) | {k}co
        {k}h = math.sqrt(max({k}h2, 0.0)) if {k}ok else math.nan
        {k}ux = {k}dx / {k}d
        {k}uy = {k}dy / {k}d
        {k}bx = {P['x']} + {k}along * {k}ux - {br} * {k}h * {k}uy
        {k}by = {P['y']} + {k}along * {k}uy + {br} * {k}h * {k}ux
        {k}px = {k}bx - {P['x']}
        {k}py = {k}by - {P['y']}
        {k}qx = {k}bx - {Q['x']}
        {k}qy = {k}by - {Q['y']}
        {k}det = {k}px * {k}qy - {k}py * {k}qx
        {k}inv = 1.0 / {k}det
        {k}wx = {Q['vx']} - {P['vx']}
        {k}wy = {Q['vy']} - {P['vy']}
        {k}oa = ({k}wx * {k}qx + {k}wy * {k}qy) * {k}inv
        {k}ob = ({k}wx * {k}px + {k}wy * {k}py) * {k}inv
        {k}w2a = {k}oa * {k}oa
        {k}w2b = {k}ob * {k}ob
        {k}wax = {Q['ax']} - {P['ax']} - {k}w2b * {k}qx + {k}w2a * {k}px
        {k}way = {Q['ay']} - {P['ay']} - {k}w2b * {k}qy + {k}w2a * {k}py
        {k}aa = ({k}wax * {k}qx + {k}way * {k}qy) * {k}inv
        {k}ab = ({k}wax * {k}px + {k}way * {k}py) * {k}inv
        {k}ca = ({k}px * {cda} + {k}py * {sda}) / {La}
        {k}sa = ({k}py * {cda} - {k}px * {sda}) / {La}
        {k}cb = ({k}qx * {cdb} + {k}qy * {sdb}) / {Lb}
        {k}sb = ({k}qy * {cdb} - {k}qx * {sdb}) / {Lb}
        {k}dn = 0.0 if {k}co else {k}det / ({La} * {Lb})
    """)
    if a_pin is None and b_pin is None:
        anchor_a, anchor_b = (P, a_pin), (Q, b_pin)
    else:
        B = {"x": f"{k}bx", "y": f"{k}by", "vx": f"{k}Bvx", "vy": f"{k}Bvy", "ax": f"{k}Bax", "ay": f"{k}Bay"}
        gen.emit(gen.motion, f"""
            {k}Bvx = {P['vx']} - {k}oa * {k}py
            {k}Bvy = {P['vy']} + {k}oa * {k}px
            {k}Bax = {P['ax']} - {k}aa * {k}py - {k}w2a * {k}px
            {k}Bay = {P['ay']} + {k}aa * {k}px - {k}w2a * {k}py
        """)
        anchor_a, anchor_b = _anchor(P, a_pin, B, a_inner), _anchor(Q, b_pin, B, b_inner)
    gen.place(d.a, *anchor_a, f"{k}oa", f"{k}aa", f"{k}ca", f"{k}sa", ("atan2",))
    gen.place(d.b, *anchor_b, f"{k}ob", f"{k}ab", f"{k}cb", f"{k}sb", ("atan2",))
    # The transmission angle at B, 0..pi (dyads.rrr_motion: arccos of the links' normalised dot product).
    cos_mu = f"({k}px * {k}qx + {k}py * {k}qy) / ({La} * {Lb})"  # the transmission angle's cosine
    gen.dyad_check(f"{k}ok", f"{k}dn", f"{d.a}-{d.b}", ("acos", cos_mu))

    def forces(gen: Generator) -> None:
        la, lb = gen.load(d.a), gen.load(d.b)
        P, Q = gen.ref_point(d.pin_a, gen.forces), gen.ref_point(d.pin_b, gen.forces)
        B = gen.on(d.a, d.inner)
        f = gen.new("f")
        gen.emit(gen.forces, f"""
            {f}Sx = -({la[0]} + {lb[0]})
            {f}Sy = -({la[1]} + {lb[1]})
            {f}px = {P['x']} - {B['x']}
            {f}py = {P['y']} - {B['y']}
            {f}qx = {Q['x']} - {B['x']}
            {f}qy = {Q['y']} - {B['y']}
            {f}c1 = -{_moment_about(la, B['x'], B['y'])}
            {f}c2 = ({f}qx * {f}Sy - {f}qy * {f}Sx) + {_moment_about(lb, B['x'], B['y'])}
            {f}det = {f}px * {f}qy - {f}py * {f}qx
            {f}fpx = ({f}c1 * {f}qx - {f}px * {f}c2) / {f}det
            {f}fpy = ({f}qy * {f}c1 - {f}py * {f}c2) / {f}det
            {f}fqx = {f}Sx - {f}fpx
            {f}fqy = {f}Sy - {f}fpy
        """)
        gen.react(0, f"{f}fpx", f"{f}fpy")
        gen.react(1, f"{f}fqx", f"{f}fqy")
        gen.react(2, f"{f}fpx + {la[0]}", f"{f}fpy + {la[1]}")
        gen.transmit(split_ref(d.pin_a)[0], P["x"], P["y"], f"{f}fpx", f"{f}fpy")
        gen.transmit(split_ref(d.pin_b)[0], Q["x"], Q["y"], f"{f}fqx", f"{f}fqy")

    gen.force_solvers.append(forces)


def _guide(gen: Generator, body: str, point: str, angle) -> tuple[dict, str, str, tuple]:
    """Global point, direction and angle expression of a guide fixed in a known body (dyads._guide_frame)."""
    S = gen.state(body)
    ga = gen.param(angle)
    k = gen.new("g")
    gen.emit(gen.prologue, f"{k}ca = math.cos({ga})\n{k}sa = math.sin({ga})")
    G = gen.point(body, gen.local(body, point, value=True))
    gen.emit(gen.motion, f"""
        {k}ux = {S['c']} * {k}ca - {S['s']} * {k}sa
        {k}uy = {S['s']} * {k}ca + {S['c']} * {k}sa
    """)
    return G, f"{k}ux", f"{k}uy", ("plus", body, ga)


def rrp_code(gen: Generator, d) -> None:
    """RRP: machdyn.linkage.dyads.rrp_motion and rrp_forces, in scalars."""
    a_pin, a_inner = gen.local(d.a, split_ref(d.pin_a)[1]), gen.local(d.a, d.inner)
    b_inner = gen.local(d.b, d.inner)
    La, cda, sda = gen.line(a_pin, a_inner)
    br = gen.param(float(d.branch))
    P = gen.ref_point(d.pin_a)
    gb, gp = split_ref(d.guide.point)
    S = gen.state(gb)
    G, ux, uy, g_angle = _guide(gen, gb, gp, d.guide.angle)
    k = gen.new("d")
    gen.emit(gen.motion, f"""
        {k}rx = {P['x']} - {G['x']}
        {k}ry = {P['y']} - {G['y']}
        {k}t0 = {k}rx * {ux} + {k}ry * {uy}
        {k}e = {ux} * {k}ry - {uy} * {k}rx
        {k}disc = {La} * {La} - {k}e * {k}e
        {k}ok = {k}disc >= -{ASSEMBLY_TOL!r} * {La} * {La}
        {k}s = {k}t0 + {br} * (math.sqrt(max({k}disc, 0.0)) if {k}ok else math.nan)
        {k}bx = {G['x']} + {k}s * {ux}
        {k}by = {G['y']} + {k}s * {uy}
        {k}px = {k}bx - {P['x']}
        {k}py = {k}by - {P['y']}
        {k}nx = -{uy}
        {k}ny = {ux}
        {k}det = {k}px * {ux} + {k}py * {uy}
        {k}cr = {k}px * {uy} - {k}py * {ux}
        {k}gx = {k}bx - {G['x']}
        {k}gy = {k}by - {G['y']}
        {k}vbx = {G['vx']} - {S['w']} * {k}gy
        {k}vby = {G['vy']} + {S['w']} * {k}gx
        {k}wx = {k}vbx - {P['vx']}
        {k}wy = {k}vby - {P['vy']}
        {k}oa = ({k}wx * {k}nx + {k}wy * {k}ny) / {k}det
        {k}ds = {k}oa * {k}cr - ({k}wx * {ux} + {k}wy * {uy})
        {k}w2s = {S['w']} * {S['w']}
        {k}abx = {G['ax']} - {S['al']} * {k}gy - {k}w2s * {k}gx + 2.0 * {k}ds * {S['w']} * {k}nx
        {k}aby = {G['ay']} + {S['al']} * {k}gx - {k}w2s * {k}gy + 2.0 * {k}ds * {S['w']} * {k}ny
        {k}wax = {k}abx - {P['ax']} + {k}oa * {k}oa * {k}px
        {k}way = {k}aby - {P['ay']} + {k}oa * {k}oa * {k}py
        {k}aa = ({k}wax * {k}nx + {k}way * {k}ny) / {k}det
        {k}dds = {k}aa * {k}cr - ({k}wax * {ux} + {k}way * {uy})
        {k}Bvx = {P['vx']} - {k}oa * {k}py
        {k}Bvy = {P['vy']} + {k}oa * {k}px
        {k}Bax = {P['ax']} - {k}aa * {k}py - {k}oa * {k}oa * {k}px
        {k}Bay = {P['ay']} + {k}aa * {k}px - {k}oa * {k}oa * {k}py
        {k}ca = ({k}px * {cda} + {k}py * {sda}) / {La}
        {k}sa = ({k}py * {cda} - {k}px * {sda}) / {La}
        {k}dn = {k}det / {La}
    """)
    B = {"x": f"{k}bx", "y": f"{k}by", "vx": f"{k}Bvx", "vy": f"{k}Bvy", "ax": f"{k}Bax", "ay": f"{k}Bay"}
    anchor, anchor_local = _anchor(P, a_pin, B, a_inner)
    gen.place(d.a, anchor, anchor_local, f"{k}oa", f"{k}aa", f"{k}ca", f"{k}sa", ("atan2",))
    gen.place(d.b, B, b_inner, S["w"], S["al"], ux, uy, g_angle)
    gen.dyad_check(f"{k}ok", f"{k}dn", f"{d.a}-{d.b}", ("asin", f"abs({k}det) / {La}"))
    gen.series_out(f"slide.{d.b}", {"s": f"{k}s", "v": f"{k}ds", "a": f"{k}dds"})

    def forces(gen: Generator) -> None:
        la, lb = gen.load(d.a), gen.load(d.b)
        P = gen.ref_point(d.pin_a, gen.forces)
        B = gen.on(d.a, d.inner)
        sl = gen.state(d.b)
        f = gen.new("f")
        gen.emit(gen.forces, f"""
            {f}Sx = -({la[0]} + {lb[0]})
            {f}Sy = -({la[1]} + {lb[1]})
            {f}px = {P['x']} - {B['x']}
            {f}py = {P['y']} - {B['y']}
            {f}nx = -{sl['s']}
            {f}ny = {sl['c']}
            {f}N = (({f}px * {f}Sy - {f}py * {f}Sx) + {_moment_about(la, B['x'], B['y'])}) / ({f}px * {f}ny - {f}py * {f}nx)
            {f}fpx = {f}Sx - {f}N * {f}nx
            {f}fpy = {f}Sy - {f}N * {f}ny
            {f}C = -{_moment_about(lb, B['x'], B['y'])}
            {f}Nx = {f}N * {f}nx
            {f}Ny = {f}N * {f}ny
        """)  # noqa: E501
        gen.react(0, f"{f}fpx", f"{f}fpy")
        gen.react(1, f"{f}fpx + {la[0]}", f"{f}fpy + {la[1]}")
        gen.react(2, f"{f}Nx", f"{f}Ny", f"{f}N", f"{f}C")
        gen.transmit(split_ref(d.pin_a)[0], P["x"], P["y"], f"{f}fpx", f"{f}fpy")
        gen.transmit(gb, B["x"], B["y"], f"{f}Nx", f"{f}Ny")
        gen.couple_back(gb, f"{f}C")

    gen.force_solvers.append(forces)


def rpr_code(gen: Generator, d) -> None:
    """RPR: machdyn.linkage.dyads.rpr_motion and rpr_forces, in scalars."""
    a_pin = gen.local(d.a, split_ref(d.pin_a)[1])
    b_pin = gen.local(d.b, split_ref(d.pin_b)[1])
    slide = gen.local(d.b, d.slide[0], value=True)
    sang = gen.param(d.slide[1])
    br = gen.param(float(d.branch))
    k = gen.new("d")
    su, sv = slide if slide is not None else ("0.0", "0.0")
    bu, bv = b_pin if b_pin is not None else ("0.0", "0.0")
    gen.emit(gen.prologue, f"""
        {k}cx = {su} - {bu}
        {k}cy = {sv} - {bv}
        {k}cs = math.cos({sang})
        {k}ss = math.sin({sang})
        {k}e = {k}cs * {k}cy - {k}ss * {k}cx
    """)
    P, Q = gen.ref_point(d.pin_a), gen.ref_point(d.pin_b)
    gen.emit(gen.motion, f"""
        {k}dx = {P['x']} - {Q['x']}
        {k}dy = {P['y']} - {Q['y']}
        {k}D = math.hypot({k}dx, {k}dy)
        {k}ratio = {k}e / {k}D
        {k}co = {k}D == 0.0
        {k}ok = (abs({k}ratio) <= 1.0 + {ASSEMBLY_TOL!r}) | {k}co
        {k}sh = math.asin(min(max({k}ratio, -1.0), 1.0)) if {k}ok else math.nan
        {k}at = math.atan2({k}dy, {k}dx)
        {k}psi = {k}at - {k}sh if {br} == 1.0 else {k}at - (math.pi - {k}sh)
        {k}ux = math.cos({k}psi)
        {k}uy = math.sin({k}psi)
        {k}tb = {k}psi - {sang}
        {k}cb = math.cos({k}tb)
        {k}sb = math.sin({k}tb)
        {k}rcx = {k}cb * {k}cx - {k}sb * {k}cy
        {k}rcy = {k}sb * {k}cx + {k}cb * {k}cy
        {k}t = {k}ux * ({k}dx - {k}rcx) + {k}uy * ({k}dy - {k}rcy)
        {k}nx = -{k}uy
        {k}ny = {k}ux
        {k}det = {k}dx * {k}ux + {k}dy * {k}uy
        {k}cr = {k}dx * {k}uy - {k}dy * {k}ux
        {k}wx = {P['vx']} - {Q['vx']}
        {k}wy = {P['vy']} - {Q['vy']}
        {k}om = ({k}wx * {k}nx + {k}wy * {k}ny) / {k}det
        {k}dt = ({k}wx * {k}ux + {k}wy * {k}uy) - {k}om * {k}cr
        {k}wax = {P['ax']} - {Q['ax']} + {k}om * {k}om * {k}dx - 2.0 * {k}om * {k}dt * {k}nx
        {k}way = {P['ay']} - {Q['ay']} + {k}om * {k}om * {k}dy - 2.0 * {k}om * {k}dt * {k}ny
        {k}al = ({k}wax * {k}nx + {k}way * {k}ny) / {k}det
        {k}ddt = ({k}wax * {k}ux + {k}way * {k}uy) - {k}al * {k}cr
        {k}dn = 0.0 if {k}co else {k}det / {k}D
    """)
    gen.place(d.b, Q, b_pin, f"{k}om", f"{k}al", f"{k}cb", f"{k}sb", ("value", f"{k}tb"))
    gen.place(d.a, P, a_pin, f"{k}om", f"{k}al", f"{k}ux", f"{k}uy", ("value", f"{k}psi"))
    # dyads.rpr_motion's transmission reads its normalised determinant (the name is rebound before it is
    # called), so it is arcsin of |det / D| / D: the same here, so that both engines agree.
    gen.dyad_check(f"{k}ok", f"{k}dn", f"{d.a}-{d.b}", ("asin", f"abs({k}dn) / {k}D"))
    gen.series_out(f"slide.{d.a}", {"s": f"{k}t", "v": f"{k}dt", "a": f"{k}ddt"})

    def forces(gen: Generator) -> None:
        la, lb = gen.load(d.a), gen.load(d.b)
        P, Q = gen.ref_point(d.pin_a, gen.forces), gen.ref_point(d.pin_b, gen.forces)
        bl = gen.state(d.a)
        f = gen.new("f")
        gen.emit(gen.forces, f"""
            {f}nx = -{bl['s']}
            {f}ny = {bl['c']}
            {f}map = {_moment_about(la, P['x'], P['y'])}
            {f}mbq = {_moment_about(lb, Q['x'], Q['y'])}
            {f}dx = {P['x']} - {Q['x']}
            {f}dy = {P['y']} - {Q['y']}
            {f}N = ({f}mbq + {f}map) / ({f}dx * {f}ny - {f}dy * {f}nx)
            {f}fpx = -{f}N * {f}nx - {la[0]}
            {f}fpy = -{f}N * {f}ny - {la[1]}
            {f}fqx = {f}N * {f}nx - {lb[0]}
            {f}fqy = {f}N * {f}ny - {lb[1]}
        """)
        gen.react(0, f"{f}fpx", f"{f}fpy")
        gen.react(1, f"{f}fqx", f"{f}fqy")
        gen.react(2, f"{f}N * {f}nx", f"{f}N * {f}ny", f"{f}N", f"-{f}map")
        gen.transmit(split_ref(d.pin_a)[0], P["x"], P["y"], f"{f}fpx", f"{f}fpy")
        gen.transmit(split_ref(d.pin_b)[0], Q["x"], Q["y"], f"{f}fqx", f"{f}fqy")

    gen.force_solvers.append(forces)


def prp_code(gen: Generator, d) -> None:
    """PRP: machdyn.linkage.dyads.prp_motion and prp_forces, in scalars."""
    b1, p1 = split_ref(d.guide_a.point)
    b2, p2 = split_ref(d.guide_b.point)
    Si, Sj = gen.state(b1), gen.state(b2)
    G1, u1x, u1y, ang1 = _guide(gen, b1, p1, d.guide_a.angle)
    G2, u2x, u2y, ang2 = _guide(gen, b2, p2, d.guide_b.angle)
    a_inner, b_inner = gen.local(d.a, d.inner), gen.local(d.b, d.inner)
    k = gen.new("d")
    gen.emit(gen.motion, f"""
        {k}cr0 = {u1x} * {u2y} - {u1y} * {u2x}
        {k}ok = abs({k}cr0) > 1e-12
        {k}cr = {k}cr0 if {k}ok else math.nan
        {k}Dx = {G2['x']} - {G1['x']}
        {k}Dy = {G2['y']} - {G1['y']}
        {k}s1 = ({k}Dx * {u2y} - {k}Dy * {u2x}) / {k}cr
        {k}s2 = ({k}Dx * {u1y} - {k}Dy * {u1x}) / {k}cr
        {k}bx = {G1['x']} + {k}s1 * {u1x}
        {k}by = {G1['y']} + {k}s1 * {u1y}
        {k}g1x = {k}bx - {G1['x']}
        {k}g1y = {k}by - {G1['y']}
        {k}g2x = {k}bx - {G2['x']}
        {k}g2y = {k}by - {G2['y']}
        {k}vix = {G1['vx']} - {Si['w']} * {k}g1y
        {k}viy = {G1['vy']} + {Si['w']} * {k}g1x
        {k}vjx = {G2['vx']} - {Sj['w']} * {k}g2y
        {k}vjy = {G2['vy']} + {Sj['w']} * {k}g2x
        {k}wx = {k}vjx - {k}vix
        {k}wy = {k}vjy - {k}viy
        {k}ds1 = ({k}wx * {u2y} - {k}wy * {u2x}) / {k}cr
        {k}ds2 = ({k}wx * {u1y} - {k}wy * {u1x}) / {k}cr
        {k}wi2 = {Si['w']} * {Si['w']}
        {k}wj2 = {Sj['w']} * {Sj['w']}
        {k}aix = {G1['ax']} - {Si['al']} * {k}g1y - {k}wi2 * {k}g1x - 2.0 * {k}ds1 * {Si['w']} * {u1y}
        {k}aiy = {G1['ay']} + {Si['al']} * {k}g1x - {k}wi2 * {k}g1y + 2.0 * {k}ds1 * {Si['w']} * {u1x}
        {k}ajx = {G2['ax']} - {Sj['al']} * {k}g2y - {k}wj2 * {k}g2x - 2.0 * {k}ds2 * {Sj['w']} * {u2y}
        {k}ajy = {G2['ay']} + {Sj['al']} * {k}g2x - {k}wj2 * {k}g2y + 2.0 * {k}ds2 * {Sj['w']} * {u2x}
        {k}wax = {k}ajx - {k}aix
        {k}way = {k}ajy - {k}aiy
        {k}dds1 = ({k}wax * {u2y} - {k}way * {u2x}) / {k}cr
        {k}dds2 = ({k}wax * {u1y} - {k}way * {u1x}) / {k}cr
        {k}Bvx = {k}vix + {k}ds1 * {u1x}
        {k}Bvy = {k}viy + {k}ds1 * {u1y}
        {k}Bax = {k}aix + {k}dds1 * {u1x}
        {k}Bay = {k}aiy + {k}dds1 * {u1y}
    """)
    B = {"x": f"{k}bx", "y": f"{k}by", "vx": f"{k}Bvx", "vy": f"{k}Bvy", "ax": f"{k}Bax", "ay": f"{k}Bay"}
    gen.place(d.a, B, a_inner, Si["w"], Si["al"], u1x, u1y, ang1)
    gen.place(d.b, B, b_inner, Sj["w"], Sj["al"], u2x, u2y, ang2)
    gen.dyad_check(f"{k}ok", f"{k}cr", f"{d.a}-{d.b}", ("asin", f"abs({k}cr)"))
    gen.series_out(f"slide.{d.a}", {"s": f"{k}s1", "v": f"{k}ds1", "a": f"{k}dds1"})
    gen.series_out(f"slide.{d.b}", {"s": f"{k}s2", "v": f"{k}ds2", "a": f"{k}dds2"})

    def forces(gen: Generator) -> None:
        la, lb = gen.load(d.a), gen.load(d.b)
        B = gen.on(d.a, d.inner)
        sa, sb = gen.state(d.a), gen.state(d.b)
        f = gen.new("f")
        gen.emit(gen.forces, f"""
            {f}Sx = -({la[0]} + {lb[0]})
            {f}Sy = -({la[1]} + {lb[1]})
            {f}n1x = -{sa['s']}
            {f}n1y = {sa['c']}
            {f}n2x = -{sb['s']}
            {f}n2y = {sb['c']}
            {f}cr = {f}n1x * {f}n2y - {f}n1y * {f}n2x
            {f}Na = ({f}Sx * {f}n2y - {f}Sy * {f}n2x) / {f}cr
            {f}Nb = ({f}n1x * {f}Sy - {f}n1y * {f}Sx) / {f}cr
            {f}ca = -{_moment_about(la, B['x'], B['y'])}
            {f}cb = -{_moment_about(lb, B['x'], B['y'])}
            {f}Nax = {f}Na * {f}n1x
            {f}Nay = {f}Na * {f}n1y
            {f}Nbx = {f}Nb * {f}n2x
            {f}Nby = {f}Nb * {f}n2y
        """)
        gen.react(0, f"{f}Nax", f"{f}Nay", f"{f}Na", f"{f}ca")
        gen.react(1, f"{f}Nbx", f"{f}Nby", f"{f}Nb", f"{f}cb")
        gen.react(2, f"{f}Na * {f}n1x + {la[0]}", f"{f}Na * {f}n1y + {la[1]}")
        gen.transmit(b1, B["x"], B["y"], f"{f}Nax", f"{f}Nay")
        gen.transmit(b2, B["x"], B["y"], f"{f}Nbx", f"{f}Nby")
        gen.couple_back(b1, f"{f}ca")
        gen.couple_back(b2, f"{f}cb")

    gen.force_solvers.append(forces)
