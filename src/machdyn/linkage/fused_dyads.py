"""The dyads in the fused engine's kernel: each emits, through a :class:`~machdyn.linkage.fused_source.Generator`,
a call of its closed form (:mod:`machdyn.linkage.dyad_forms`, compiled for scalars and inlined) for its motion
(position on its branch, velocity, acceleration) and registers the call of its force form, and places its two
bodies. The forms are the NumPy engine's too: both engines compute one text, so they agree to rounding.
"""

from __future__ import annotations

from .fused_generator import Generator
from .refs import split_ref


def _motion(point: dict[str, str]) -> list[str]:
    """A point's position, velocity and acceleration names, in the order the forms take them."""
    return [point[f] for f in ("x", "y", "vx", "vy", "ax", "ay")]


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
    gen.call(k, "rrr_motion", ("ok", "co", "bx", "by", "Bvx", "Bvy", "Bax", "Bay", "px", "py", "qx", "qy", "oa",
                               "aa", "ob", "ab", "ca", "sa", "cb", "sb", "det", "dn"),
             [*_motion(P), *_motion(Q), La, cda, sda, Lb, cdb, sdb, br])
    if a_pin is None and b_pin is None:
        anchor_a, anchor_b = (P, a_pin), (Q, b_pin)
    else:
        B = {"x": f"{k}bx", "y": f"{k}by", "vx": f"{k}Bvx", "vy": f"{k}Bvy", "ax": f"{k}Bax", "ay": f"{k}Bay"}
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
        gen.call(f, "rrr_forces", ("fpx", "fpy", "fqx", "fqy"),
                 [*la, *lb, P["x"], P["y"], Q["x"], Q["y"], B["x"], B["y"]], gen.forces)
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
    gen.call(k, "rrp_motion", ("ok", "s", "bx", "by", "Bvx", "Bvy", "Bax", "Bay", "oa", "aa", "ca", "sa", "ds",
                               "dds", "det", "dn"),
             [*_motion(P), *_motion(G), S["w"], S["al"], ux, uy, La, cda, sda, br])
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
        gen.call(f, "rrp_forces", ("fpx", "fpy", "N", "nx", "ny", "C"),
                 [*la, *lb, P["x"], P["y"], B["x"], B["y"], sl["c"], sl["s"]], gen.forces)
        gen.emit(gen.forces, f"{f}Nx = {f}N * {f}nx\n{f}Ny = {f}N * {f}ny")
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
    gen.call(k, "rpr_motion", ("ok", "co", "psi", "ux", "uy", "tb", "cb", "sb", "t", "om", "al", "dt", "ddt", "det",
                               "D", "dn"),
             [*_motion(P), *_motion(Q), f"{k}cx", f"{k}cy", f"{k}e", sang, br])
    gen.place(d.b, Q, b_pin, f"{k}om", f"{k}al", f"{k}cb", f"{k}sb", ("value", f"{k}tb"))
    gen.place(d.a, P, a_pin, f"{k}om", f"{k}al", f"{k}ux", f"{k}uy", ("value", f"{k}psi"))
    # the transmission angle arcsin(|d . u| / D), as dyads.rpr_motion's
    gen.dyad_check(f"{k}ok", f"{k}dn", f"{d.a}-{d.b}", ("asin", f"abs({k}det) / {k}D"))
    gen.series_out(f"slide.{d.a}", {"s": f"{k}t", "v": f"{k}dt", "a": f"{k}ddt"})

    def forces(gen: Generator) -> None:
        la, lb = gen.load(d.a), gen.load(d.b)
        P, Q = gen.ref_point(d.pin_a, gen.forces), gen.ref_point(d.pin_b, gen.forces)
        bl = gen.state(d.a)
        f = gen.new("f")
        gen.call(f, "rpr_forces", ("fpx", "fpy", "fqx", "fqy", "N", "nx", "ny", "C"),
                 [*la, *lb, P["x"], P["y"], Q["x"], Q["y"], bl["c"], bl["s"]], gen.forces)
        gen.react(0, f"{f}fpx", f"{f}fpy")
        gen.react(1, f"{f}fqx", f"{f}fqy")
        gen.react(2, f"{f}N * {f}nx", f"{f}N * {f}ny", f"{f}N", f"{f}C")
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
    gen.call(k, "prp_motion", ("ok", "cr", "s1", "s2", "bx", "by", "Bvx", "Bvy", "Bax", "Bay", "ds1", "ds2", "dds1",
                               "dds2"),
             [*_motion(G1), Si["w"], Si["al"], u1x, u1y, *_motion(G2), Sj["w"], Sj["al"], u2x, u2y])
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
        gen.call(f, "prp_forces", ("Na", "ca", "Nb", "cb", "n1x", "n1y", "n2x", "n2y"),
                 [*la, *lb, B["x"], B["y"], sa["c"], sa["s"], sb["c"], sb["s"]], gen.forces)
        gen.emit(gen.forces, f"""
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


#: Each dyad type's code, by its kind (``DyadType.kind``): the fused engine's half of a dyad's declaration.
EMITTERS = {"RRR": rrr_code, "RRP": rrp_code, "RPR": rpr_code, "PRP": prp_code}
