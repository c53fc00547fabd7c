"""The fused population pass: every per-design number of a population of designs (status checks, transmission
angles, strokes, time ratios, inertial shaking, the compactor plate's figures and, when asked, the
kinetostatic summaries) in one compiled pass over designs x crank positions.

The kernel is generated from the mechanism's code (:mod:`.fused_source`): per design, one loop over the
positions fills a small scratch table (rows below), which :func:`.fused_reduce.motion_summary` and the force
summaries' reduction turn into that design's numbers. No designs x positions array is made. The NumPy path of
:func:`machdyn.results.population.evaluate_population` stays the reference; the tests check both agree.

Scratch rows of a design: 0 closure, 1 regular (closes, no dyad dead), 2.. the dyads' normalised determinants,
then the arguments of their transmission angles, then per output its value and rate, then (``inertial``) the
inertia force -M a_G [N] (x, y) and the inertial shaking moment [N*m], then (``plate``) the plate's cos and
sin, then (``forces``) the rows of the force summaries (:func:`.fused_source.summary_rows`).
"""

from __future__ import annotations

import hashlib
import os
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import InputError
from .averages import angle_weights
from .fused import crank_trig, drive_table, load_kernel, prepared
from .fused_source import SUMMARY_FIELDS, Generated, indent, position_loops, summary_reduction, summary_rows
from .loads import window
from .motion import is_full_turn

#: The text of the reductions, hashed into each kernel's text: a changed reduction is a new kernel (numba's
#: cache does not follow a kernel's callees).
_REDUCE_VERSION = hashlib.sha1(b"".join((Path(__file__).parent / name).read_bytes()
                                        for name in ("fused_reduce.py", "reductions.py"))).hexdigest()[:12]


#: Positions (designs x crank angles) below which one thread runs the whole pass (a thread's start costs more).
MIN_POSITIONS_PER_THREAD = 20_000
_POOL: list = []
_BY_SIGNATURE: dict = {}


def _threads() -> int:
    """Threads of a population pass: ``$MACHDYN_THREADS``, else the processors this process may use."""
    value = os.environ.get("MACHDYN_THREADS")
    if value:
        return max(1, int(value))
    return max(1, len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1))


def _pool():
    if not _POOL:
        _POOL.append(ThreadPoolExecutor(max_workers=_threads(), thread_name_prefix="machdyn-fused"))
    return _POOL[0]


@dataclass(frozen=True)
class PopulationRun:
    """Per-design results of a fused population pass (arrays of N designs)."""

    motion: np.ndarray  # (N, columns of fused_reduce.motion_summary)
    forces: np.ndarray | None  # (N, SUMMARY_FIELDS + joints) when forces were asked for
    energy: np.ndarray | None  # (2, N, M): J(phi) and M(phi) when asked for
    generated: Generated
    dyads: int
    outputs: list[str]


def population_text(g: Generated, forces: bool, inertial: bool, plate: str | None, strokes: bool,
                    energy: bool = False) -> str:
    """The population kernel's text (see the module docstring)."""
    sec = g.sections
    nd = len(sec["transmission"])
    outputs = sec["outputs"]
    no = len(outputs) // 2
    rows = 2 + 2 * nd + 2 * no
    stores = [f"B[{2 + d}, j] = {det}" for d, det in enumerate(sec["dead"])]
    stores += [f"B[{2 + nd + d}, j] = {pair[1]}" for d, pair in enumerate(sec["transmission"])]  # (f, arg)
    for o in range(no):
        if strokes:
            stores.append(f"B[{2 + 2 * nd + 2 * o}, j] = {outputs[2 * o].split(':', 1)[1]}")
        stores.append(f"B[{3 + 2 * nd + 2 * o}, j] = {outputs[2 * o + 1]}")
    work = ["om = Wi[j]", "ep = Ei[j]"] + sec["motion"]
    ri = rp = -1
    if inertial:
        ri = rows
        work += sec["inertial"]
        stores += [f"B[{ri}, j] = (-im_m) * (im_ax / im_m) if im_m > 0.0 else 0.0",
                   f"B[{ri + 1}, j] = (-im_m) * (im_ay / im_m) if im_m > 0.0 else 0.0",
                   f"B[{ri + 2}, j] = im_mz"]
        rows += 3
    if plate is not None:
        rp = rows
        cos_sin = next(a.split(":")[1:] for a in sec["angles"] if a.split(":")[0] == plate)
        stores += [f"B[{rp}, j] = {cos_sin[0]}", f"B[{rp + 1}, j] = {cos_sin[1]}"]
        rows += 2
    if energy:  # J = 2 T / omega^2 (seed 003 eq 18), M = (dT/dt) / omega - torque (power balance)
        if not inertial:
            work += sec["inertial"]
        stores += ["EN_0[j] = 2.0 * im_ke / (om * om)", "EN_1[j] = im_kr / om - torque"]
    scratch, force_stores = summary_rows(g, rows)
    if forces:
        work += sec["forces"]
        stores = force_stores + stores
        reduction = summary_reduction(g)
    else:
        stores = force_stores[:2] + stores
        scratch, reduction = scratch[:2], ""
    return f"""import math

from machdyn.linkage.fused_reduce import motion_summary  # reductions version {_REDUCE_VERSION}


def kernel(P, C0, S0, W, E, DW, LP, about, weighted, full, PH, TK, KINDS, OUT, B, OUTM, EN):
    n = OUTM.shape[0]
    m = C0.shape[0]
    zx = about[0]
    zy = about[1]
    for i in range(n):
        ip = i if P.shape[0] > 1 else 0
        Wi = W[i if W.shape[0] > 1 else 0]
        Ei = E[i if E.shape[0] > 1 else 0]
{indent(sec["prologue"], 2)}
{indent(scratch + (["EN_0 = EN[i, 0]", "EN_1 = EN[i, 1]"] if energy else []), 2)}
{"".join(position_loops(work, stores))}
        motion_summary(B, {nd}, TK, KINDS, {ri}, {rp}, full, PH, OUTM[i])
{reduction}
"""


def scratch_rows(g: Generated, forces: bool, inertial: bool, plate: str | None) -> int:
    nd = len(g.sections["transmission"])
    rows = 2 + 2 * nd + len(g.sections["outputs"]) + (3 if inertial else 0) + (2 if plate is not None else 0)
    return rows + (4 + len(g.joints) if forces else 0)


def motion_columns(g: Generated, inertial: bool, plate: str | None) -> int:
    return 5 + 3 * len(g.sections["transmission"]) + len(g.sections["outputs"]) + (2 if inertial else 0) + (
        2 if plate is not None else 0)


def run_population(mech, phi, speed, acceleration, *, designs: int, about=(0.0, 0.0), forces: bool = False,
                   inertial: bool = False, plate: str | None = None, active=None, strokes: bool = True,
                   energy: bool = False) -> PopulationRun:
    """One fused population pass over ``designs`` designs x crank angles ``phi`` [rad] at crank ``speed``
    [rad/s] and ``acceleration`` [rad/s^2] (floats, one per design or per angle). ``forces``: the force
    summaries too (shaking moments about ``about`` [m]); ``inertial``: the inertial shaking force and moment;
    ``plate``: the body whose angle is the compactor plate's, pressing over the crank window ``active``;
    ``strokes``: the outputs' strokes (NaN without); ``energy`` (with ``forces``): the curves J(phi) [kg*m^2]
    and M(phi) [N*m] of every design, the reduced moment of inertia 2 T / omega^2 and the reduced moment of
    every load but inertia and the drive, (dT/dt) / omega - driving torque (the power balance), as
    ``PopulationRun.energy`` (2, N, M), for :mod:`machdyn.dynamics.population_flywheel`."""
    if energy and not forces:
        raise InputError("The energy curves of a population need its forces (forces=True).")
    phi = np.ascontiguousarray(phi, dtype=float)
    generated, P = prepared(mech, phi)
    mode = f"population-{int(forces)}{int(inertial)}{int(strokes)}{int(energy)}-{plate or ''}"
    # The code's sections name the kernel without writing and hashing its text: an optimiser's every
    # generation (a new model of the same topology) finds its kernel here.
    signature = (mode, *(tuple(lines) for lines in generated.sections.values()))
    kernel = _BY_SIGNATURE.get(signature)
    if kernel is None:
        generated.texts[mode] = population_text(generated, forces, inertial, plate, strokes, energy)
        kernel = _BY_SIGNATURE[signature] = load_kernel(generated, mode)
    W = drive_table(speed, phi, mech.design_count)
    E = drive_table(acceleration, phi, mech.design_count)
    LP = np.stack(generated.rows) if generated.rows else np.zeros((1, 1))
    DW = np.ascontiguousarray(np.broadcast_to(angle_weights(phi), phi.shape), dtype=float)
    weighted = bool(np.all(W != 0.0))
    C0, S0 = crank_trig(phi)
    PH = np.empty((3, phi.size))
    PH[0] = phi
    PH[1] = np.mod(np.roll(phi, -1) - phi, 2 * np.pi)
    PH[2] = np.broadcast_to(np.asarray(window(phi, active), dtype=float), phi.shape) if plate else 0.0
    kinds = np.array([(1 if o.startswith("angle:") else 0) if strokes else -1
                      for o in generated.sections["outputs"][::2]], dtype=np.int64)
    TK = np.array([1 if pair[0] == "acos" else 0 for pair in generated.sections["transmission"]], dtype=np.int64)
    OUTM = np.empty((designs, motion_columns(generated, inertial, plate)))
    OUT = np.empty((designs if forces else 0, len(SUMMARY_FIELDS) + len(generated.joints)))
    rows = scratch_rows(generated, forces, inertial, plate)
    # designs first, so that each thread's share is one contiguous block (the compiler vectorises its loops)
    EN = np.empty((designs, 2, phi.size)) if energy else np.empty((0, 2, 1))
    full, about = is_full_turn(phi), np.asarray(about, dtype=float)

    def part(start: int, stop: int) -> None:
        def cut(table):
            return table[start:stop] if table.shape[0] > 1 else table

        kernel(cut(P), C0, S0, cut(W), cut(E), DW, LP, about, weighted, full, PH, TK, kinds,
               OUT[start:stop] if forces else OUT, np.empty((rows, phi.size)), OUTM[start:stop],
               EN[start:stop] if energy else EN)

    threads = min(_threads(), max(1, designs * phi.size // MIN_POSITIONS_PER_THREAD))
    if threads <= 1:
        part(0, designs)
    else:  # the kernel releases the GIL: the designs are shared out between threads
        bounds = np.linspace(0, designs, threads + 1).astype(int)
        others = [_pool().submit(part, int(a), int(b)) for a, b in zip(bounds[1:-1], bounds[2:], strict=True)]
        part(0, int(bounds[1]))  # the first share in this thread
        for future in others:
            future.result()
    return PopulationRun(OUTM, OUT if forces else None, EN.transpose(1, 0, 2) if energy else None, generated,
                         len(generated.sections["transmission"]),
                         [o.split(":", 1)[1] for o in generated.sections["outputs"][::2]])
