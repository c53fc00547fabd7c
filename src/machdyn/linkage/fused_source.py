"""Straight-line scalar code of a mechanism's whole solution, for the fused engine (:mod:`.fused`).

:func:`generate` walks a mechanism once (crank, dyads in order, loads, dyads in reverse for the forces) and
writes one Python function that loops over designs and crank positions and, at each position, computes in
scalars what the NumPy engine computes in arrays: the same closed forms (:mod:`machdyn.linkage.dyads`), the
same loads (:mod:`machdyn.linkage.loads`), the same order of operations. Every number of the model is read
from a parameter table (one row per design), so the code depends on the mechanism's topology only and one
compiled function serves every design of that topology.

No numba here: the text is compiled by :mod:`machdyn.linkage.fused`.
"""

from __future__ import annotations

import hashlib
import math
from dataclasses import dataclass, field

import numpy as np

from .dyad_forms import forms_version
from .fused_dyads import EMITTERS
from .fused_generator import Generator
from .loads import window
from .model import joints, output_bodies
from .reductions import STREAMS, streams_version
from .refs import GROUND, split_ref

#: The fields of a body state, in the order of the series output.
BODY_FIELDS = ("x", "y", "vx", "vy", "ax", "ay", "th", "w", "al", "c", "s")
#: Per-design summaries, in the order of the summary output (then one column per joint).
SUMMARY_FIELDS = ("assembled", "regular", "max_driving_torque", "rms_driving_torque", "mean_input_power",
                  "max_shaking_force", "max_shaking_moment")

#: The fields the kernel writes (the angles are computed afterwards, see Generated.angles).
KERNEL_BODY_FIELDS = tuple(f for f in BODY_FIELDS if f != "th")



@dataclass
class Generated:
    """The generated code's sections and what the kernels need: parameter columns (each a float or an (N,)
    array), per-position load rows (each an (M,) array), the layout of the series and summary outputs and
    how each body's angle follows from them."""

    sections: dict[str, list[str]]
    params: list
    rows: list
    series: dict[str, tuple]
    motion_series: int
    all_series: int
    joints: list[str]
    angles: list

    texts: dict = field(default_factory=dict, repr=False)
    kernels: dict = field(default_factory=dict, repr=False)

    def source(self, mode: str) -> str:
        """The kernel's text: ``mode`` 'motion' (series of the motion), 'full' (series of motion and forces)
        or 'summary' (per-design summaries)."""
        if mode not in self.texts:
            self.texts[mode] = _kernel_text(self, mode)
        return self.texts[mode]

    def key(self, mode: str) -> str:
        """The kernel's name: a hash of its text and of the dyad forms and reductions it calls."""
        return hashlib.sha1((forms_version() + streams_version() + self.source(mode)).encode()).hexdigest()[:16]


# ---------------------------------------------------------------------------------------------- the kernel

#: |normalised determinant| below which a position is dead (machdyn.linkage.kinematics.DEAD_TOL).
_DEAD_TOL = 1e-6


def _value(gen: Generator, value, on) -> str:
    """A load value (constant, design array or function of the crank angle) times its window ``on``."""
    if callable(value):
        return gen.row(np.asarray(value(gen.phi), dtype=float) * on)
    expr = gen.param(value)
    return expr if np.ndim(on) == 0 else f"{expr} * {gen.row(on)}"


def _loads(gen: Generator) -> None:
    """The loads on every moving body and the frame (machdyn.linkage.kinetostatics.body_loads)."""
    mech, out = gen.mech, gen.forces
    gx, gy = gen.param(mech.gravity[0]), gen.param(mech.gravity[1])
    gen.emit(out, "ffx = 0.0\nffy = 0.0\nffm = 0.0")
    for name in mech.moving_bodies:
        k = gen.prefixes[name]
        gen.emit(out, f"{k}lx = 0.0\n{k}ly = 0.0\n{k}lm = 0.0")
    masses = [(b.name, b.com, b.mass, b.inertia) for b in map(mech.body, mech.moving_bodies)]
    masses += [(pm.body, pm.position, pm.mass, pm.inertia) for pm in mech.point_masses]
    for body, com, mass, inertia in masses:
        G = gen.point(body, gen.local_xy(com, value=True), out)
        m, i = gen.param(mass), gen.param(inertia)
        f = gen.new("m")
        gen.emit(out, f"{f}fx = {m} * ({gx} - {G['ax']})\n{f}fy = {m} * ({gy} - {G['ay']})")
        gen.add_load(body, f"{f}fx", f"{f}fy",
                     f"{G['x']} * {f}fy - {G['y']} * {f}fx - {i} * {gen.state(body)['al']}")
    for force in mech.forces:
        on = window(gen.phi, force.active)
        fx, fy = _value(gen, force.fx, on), _value(gen, force.fy, on)
        body = split_ref(force.point)[0]
        p = gen.ref_point(force.point, out, value=True)
        f = gen.new("e")
        gen.emit(out, f"{f}x = {fx}\n{f}y = {fy}")
        gen.add_load(body, f"{f}x", f"{f}y", f"{p['x']} * {f}y - {p['y']} * {f}x")
    for torque in mech.torques:
        gen.add_load(torque.body, "0.0", "0.0", _value(gen, torque.torque, window(gen.phi, torque.active)))
    for spring in mech.springs:
        p1, p2 = gen.ref_point(spring.point_1, out, True), gen.ref_point(spring.point_2, out, True)
        k, l0 = gen.param(spring.stiffness), gen.param(spring.free_length)
        f = gen.new("k")
        gen.emit(out, f"""
            {f}dx = {p2['x']} - {p1['x']}
            {f}dy = {p2['y']} - {p1['y']}
            {f}l = math.hypot({f}dx, {f}dy)
            {f}ex = {f}dx / {f}l if {f}l > 0 else 0.0
            {f}ey = {f}dy / {f}l if {f}l > 0 else 0.0
            {f}T = {k} * ({f}l - {l0})
            {f}f1x = {f}T * {f}ex
            {f}f1y = {f}T * {f}ey
            {f}f2x = -{f}f1x
            {f}f2y = -{f}f1y
        """)
        for ref, p, sx, sy in ((spring.point_1, p1, f"{f}f1x", f"{f}f1y"), (spring.point_2, p2, f"{f}f2x", f"{f}f2y")):
            gen.add_force_at(split_ref(ref)[0], p["x"], p["y"], sx, sy)


def generate(mech, phi: np.ndarray) -> Generated:
    """The kernel of ``mech`` (see the module docstring). Raises :class:`Unsupported` for what it cannot
    compile."""
    gen = Generator(mech, np.asarray(phi, dtype=float))
    crank = mech.crank.body
    pivot = split_ref(mech.crank.pivot)[1]
    o = gen.local(GROUND, pivot)
    O = {"x": o[0] if o else "0.0", "y": o[1] if o else "0.0", "vx": "0.0", "vy": "0.0", "ax": "0.0", "ay": "0.0"}
    gen.emit(gen.motion, "c0 = C0[j]\ns0 = S0[j]")  # cos and sin of the crank angles, computed once
    gen.place(crank, O, gen.local(crank, pivot), "om", "ep", "c0", "s0", ("crank",))
    for d in mech.dyads:
        EMITTERS[d.kind](gen, d)
    motion_series = list(gen.series_lines)
    gen.series_lines.clear()
    population = _population_sections(gen)
    _loads(gen)
    for i in reversed(range(len(mech.dyads))):
        gen.joint_base = 1 + 3 * i
        gen.force_solvers[i](gen)
    cl = gen.load(crank)
    gen.emit(gen.forces, f"""
        torque = -({cl[2]} - ({O['x']} * {cl[1]} - {O['y']} * {cl[0]}))
        ffx = ffx + {cl[0]}
        ffy = ffy + {cl[1]}
        ffm = ffm + ({O['x']} * {cl[1]} - {O['y']} * {cl[0]})
        ffm = ffm + (-torque)
    """)
    gen.joint_base = 0
    gen.react(0, f"-{cl[0]}", f"-{cl[1]}")
    names = [j[0] for j in joints(mech)]
    for j, outputs in sorted(gen.reactions):
        gen.series_out(f"joint.{j}", outputs)
    gen.series_out("forces", {"torque": "torque", "fx": "ffx", "fy": "ffy", "m": "ffm"})
    force_series = list(gen.series_lines)
    sections = {"prologue": gen.prologue, "motion": gen.motion, "forces": gen.forces,
                "motion_series": motion_series, "force_series": force_series,
                "assembled": gen.assembled, "dead": gen.dead_checks, **population}
    return Generated(sections, gen.params, gen.rows, gen.series, len(motion_series), len(gen.stored), names,
                     gen.angles)


def _population_sections(gen: Generator) -> dict[str, list]:
    """What the population kernels (:mod:`.fused_population`) compute at each position beyond the motion:
    every dyad's transmission angle (its function and argument); each body's cos and sin; each output's value
    and rate (a slider's travel and speed, a rocker's angle atan2(sin, cos), as the NumPy engine's body angle,
    and angular velocity); and the inertia loads
    (machdyn.linkage.mass_centre): the sums over the masses of m, m a_x, m a_y (in the order of
    machdyn.linkage.loads.mass_elements), the inertial shaking moment sum (r - z) x (-m a) - I alpha about
    z = (zx, zy), the kinetic energy T = sum m v^2/2 + I w^2/2 and its rate dT/dt = sum m v.a + I w alpha
    (machdyn.linkage.energy)."""
    out = {"transmission": list(gen.transmissions), "outputs": [], "inertial": [], "angles": []}
    for body, kind in output_bodies(gen.mech):
        if kind == "slide":
            value, rate = gen.exprs[f"slide.{body}.s"], gen.exprs[f"slide.{body}.v"]
        else:
            state = gen.bodies[body]
            value, rate = f"math.atan2({state['s']}, {state['c']})", state["w"]
        out["outputs"] += [f"{kind}:{value}", rate]
    for body in gen.mech.moving_bodies:
        state = gen.bodies[body]
        out["angles"] += [f"{body}:{state['c']}:{state['s']}"]
    mech, section = gen.mech, out["inertial"]
    masses = [(b.name, b.com, b.mass, b.inertia) for b in map(mech.body, mech.moving_bodies)]
    masses += [(pm.body, pm.position, pm.mass, pm.inertia) for pm in mech.point_masses]
    gen.emit(section, "im_m = 0.0\nim_ax = 0.0\nim_ay = 0.0\nim_mz = 0.0\nim_ke = 0.0\nim_kr = 0.0")
    for body, com, mass, inertia in masses:
        G = gen.point(body, gen.local_xy(com, value=True), section)
        m, i = gen.param(mass), gen.param(inertia)
        gen.emit(section, f"""
            im_m = im_m + {m}
            im_ax = im_ax + {m} * {G['ax']}
            im_ay = im_ay + {m} * {G['ay']}
            im_mz = im_mz + ({G['x']} - zx) * (-{m} * {G['ay']}) - ({G['y']} - zy) * (-{m} * {G['ax']}) \
                - {i} * {gen.state(body)['al']}
            im_ke = im_ke + 0.5 * {m} * ({G['vx']} * {G['vx']} + {G['vy']} * {G['vy']}) \
                + 0.5 * {i} * {gen.state(body)['w']} * {gen.state(body)['w']}
            im_kr = im_kr + {m} * ({G['vx']} * {G['ax']} + {G['vy']} * {G['ay']}) \
                + {i} * {gen.state(body)['w']} * {gen.state(body)['al']}
        """)
    return out


def indent(lines: list[str], level: int) -> str:
    pad = "    " * level
    return "\n".join(pad + line for line in lines) if lines else pad + "pass"


#: Rows written per loop over the positions: with more output streams the compiler no longer vectorises the
#: loop (its run-time checks that the rows do not overlap grow with the square of their number).
ROWS_PER_LOOP = 10
#: At most this many copies of a loop: each copy adds to the compilation time (seconds for a big mechanism),
#: so beyond it one loop writes every row, unvectorised.
MAX_LOOPS = 3


def position_loops(work: list[str], stores: list[str]) -> list[str]:
    """Loops over the positions, each computing ``work`` and writing at most ROWS_PER_LOOP rows (the
    compiler drops from each loop what its rows do not need), or one loop when that would take more than
    MAX_LOOPS copies."""
    per_loop = ROWS_PER_LOOP if len(stores) <= ROWS_PER_LOOP * MAX_LOOPS else max(len(stores), 1)
    out = []
    for start in range(0, max(len(stores), 1), per_loop):
        out.append(f"        for j in range(m):\n{indent(work + stores[start:start + per_loop], 3)}\n")
    return out


def _kernel_text(g: Generated, mode: str) -> str:
    """Per design: the prologue, then one loop over the positions in straight-line, branch-free code that
    the compiler vectorises (the outputs go to one 1-D row each), then, for summaries, a loop of reductions
    over the per-position rows of a small scratch table (no designs x positions arrays)."""
    sec = g.sections
    head = f"""import math


def kernel(P, C0, S0, W, E, DW, LP, about, weighted, S, OUT, B):
    n = OUT.shape[0] if S.shape[0] == 0 else S.shape[1]
    m = C0.shape[0]
    zx = about[0]
    zy = about[1]
    for i in range(n):
        ip = i if P.shape[0] > 1 else 0
        Wi = W[i if W.shape[0] > 1 else 0]
        Ei = E[i if E.shape[0] > 1 else 0]
{indent(sec["prologue"], 2)}
"""
    position = ["om = Wi[j]", "ep = Ei[j]"] + sec["motion"]
    if mode != "summary":
        rows = sec["motion_series"] + (sec["force_series"] if mode == "full" else [])
        hoist = [f"S_{k} = S[{k}, i]" for k in range(len(rows))]
        work = position + (sec["forces"] if mode == "full" else [])
        return head + indent(hoist, 2) + "\n" + "".join(position_loops(work, rows)) + "\n"
    scratch, stores = summary_rows(g, 2)
    return head + indent(scratch, 2) + "\n" + "".join(position_loops(position + sec["forces"], stores)) + \
        summary_reduction(g)


def summary_rows(g: Generated, base: int) -> tuple[list[str], list[str]]:
    """The scratch rows of the per-design summaries (closure, regularity, then from row ``base`` the driving
    torque, the frame force and moment and each joint's squared force) and the lines that fill them."""
    sec = g.sections
    n_joints = len(g.joints)
    assembled = " & ".join(f"({a})" for a in sec["assembled"]) or "True"
    regular = " & ".join(f"(abs({d}) >= {_DEAD_TOL!r})" for d in sec["dead"]) or "True"
    scratch = ["B_ok = B[0]", "B_reg = B[1]", f"B_t = B[{base}]", f"B_fx = B[{base + 1}]",
               f"B_fy = B[{base + 2}]", f"B_fm = B[{base + 3}]"]
    scratch += [f"B_j{j} = B[{base + 4 + j}]" for j in range(n_joints)]
    stores = [f"B_ok[j] = 1.0 if {assembled} else 0.0", f"B_reg[j] = 1.0 if {regular} else 0.0",
              "B_t[j] = torque", "B_fx[j] = ffx", "B_fy[j] = ffy", "B_fm[j] = ffm"]
    stores += [f"B_j{j}[j] = r{j}x * r{j}x + r{j}y * r{j}y" for j in range(n_joints)]
    return scratch, stores


#: How the kernel reduces each per-design force summary after "assembled" and "regular" (the order of
#: :data:`SUMMARY_FIELDS`): the name of its reduction in :data:`.reductions.STREAMS` (the reductions of the NumPy
#: path, one position at a time) and the value it reduces at position j; then every joint's largest force,
#: "max_magnitude" of its squared force row.
SUMMARY_REDUCTIONS: tuple[tuple[str, str, str], ...] = (
    ("max_driving_torque", "max_abs", "torque"),
    ("rms_driving_torque", "time_rms", "torque"),
    ("mean_input_power", "time_mean", "torque * Wi[j]"),
    ("max_shaking_force", "max_magnitude", "B_fx[j] * B_fx[j] + B_fy[j] * B_fy[j]"),
    ("max_shaking_moment", "max_abs", "B_fm[j] - (zx * B_fy[j] - zy * B_fx[j])"),
)
assert tuple(f for f, _, _ in SUMMARY_REDUCTIONS) == SUMMARY_FIELDS[2:]


def _start(how: str) -> str:
    start = STREAMS[how].start
    return "-math.inf" if start == -math.inf else repr(start)


def summary_reduction(g: Generated) -> str:
    """The per-design reduction of the summary rows into OUT[i] (:data:`SUMMARY_FIELDS`, then the joints), each
    by its stream of :data:`SUMMARY_REDUCTIONS` (compiled from :mod:`.reductions`, inlined)."""
    reduced = [(how, value) for _, how, value in SUMMARY_REDUCTIONS]
    reduced += [("max_magnitude", f"B_j{j}[j]") for j in range(len(g.joints))]  # squared: one root per design
    init = [f"a{k} = {_start(how)}" for k, (how, _) in enumerate(reduced)]
    steps = [f"a{k} = RS_{how}(a{k}, {value}, wt)" for k, (how, value) in enumerate(reduced)]
    finish = [f"OUT[i, {2 + k}] = RF_{how}(a{k}, s_wsum) + bad" for k, (how, _) in enumerate(reduced)]
    return f"""
        s_asm = True
        s_reg = True
        s_wsum = 0.0
{indent(init, 2)}
        for j in range(m):
            s_asm = s_asm and B_ok[j] > 0.5
            s_reg = s_reg and B_reg[j] > 0.5
            torque = B_t[j]
            if not math.isfinite(torque):
                s_reg = False
            wt = DW[j] / abs(Wi[j]) if weighted else DW[j]
            s_wsum += wt
{indent(steps, 3)}
        ok = s_asm and s_reg
        bad = 0.0 if ok else math.nan
        OUT[i, 0] = 1.0 if s_asm else 0.0
        OUT[i, 1] = 1.0 if ok else 0.0
{indent(finish, 2)}
"""
