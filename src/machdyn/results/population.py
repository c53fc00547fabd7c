"""Per-design results of a population of designs: the one function a sweep, an exploration and the optimiser
evaluate designs with, under the keys of :mod:`machdyn.results.catalogue`.

A mechanism with a designs axis (N designs) is evaluated over the crank angles in groups, each computed only
when one of its results is wanted:

- ``forces``: one call of :func:`machdyn.linkage.sweep` (kinetostatics summarised per design, compiled when
  numba is present): peak and RMS driving torque, mean input power, frame force, shaking moment, joint peaks;
- ``motion``: kinematics in chunks of designs: transmission angles, strokes and time ratios of the outputs, the
  inertial shaking force and moment, the compactor's figures;
- ``geometry``: the Grashof margin and class of a four-bar, from its link lengths;
- ``analysis``: the full analysis of the regular designs (:func:`machdyn.linkage.analyse`) reduced by the same
  function as a run (:func:`machdyn.results.linkage.linkage_scalars`): energy, reduced inertia, work balance...

and always the checks of each design (``status`` group): ``assembled``, ``dead_point``, ``branch_change``,
``near_dead_point``, ``poor_transmission`` (worst transmission angle below ``min_transmission_angle``, default
:data:`DEFAULT_MIN_TRANSMISSION_DEG`), ``regular`` (none of them) and ``status`` (the first fault's name). The
results of a design that is not regular are NaN (but for the Grashof margin and class, which tell why): a
degenerate design never counts as a regular one with enormous forces.

Compactor results (seed 003, Asfandiyarov et al., 2019, for ``machine = "compactor"``: a four-bar whose
coupler is the compaction plate and whose coupler point P is where it presses):

- ``compactor.plate_angle.max`` = max over the cycle of |gamma|, gamma = the plate's angle to the horizontal
  (corrected eq 10; the design rule gamma < 20 deg, conclusion 2a);
- ``compactor.k1.min`` = min over the pressing window of k1 = 1/|cos alpha|, alpha = theta2 - phi (eq 1, eq 8);
- ``compactor.k2`` = l / a, a = l - u the distance of P from B along the plate (eq 1);
- ``compactor.force_gain.min`` = min over the pressing window of k1 k2, the force gain Q/P (eq 1) the design
  guarantees over the whole pressing stroke. The window is the ``active`` range of the first force on the
  coupler that has one (the whole cycle without one).
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Iterable
from typing import Any

import numpy as np

from ..errors import InputError
from ..linkage import analyse, kinematics, sweep
from ..linkage.diagnostics import full_turn_stroke, time_ratio
from ..linkage.engines import available, check_engine
from ..linkage.force_gain import crank_force_gain
from ..linkage.fused_population import run_population
from ..linkage.fused_source import SUMMARY_FIELDS
from ..linkage.grashof import grashof_margin, grashof_type
from ..linkage.loads import window
from ..linkage.mass_centre import inertial_force, inertial_shaking_moment
from ..linkage.model import GROUND, RRR, Mechanism, joints, output_bodies, split_ref
from ..linkage.motion import DEAD_TOL, is_full_turn
from ..linkage.reductions import worst_of
from .catalogue import ENGINE_SUMMARIES, find, population_quantities
from .linkage import HARMONIC_SERIES, linkage_scalars

#: Default threshold [deg] of ``poor_transmission``: a design whose transmission angle comes closer than this to
#: 0 or 180 deg is degenerate (its joint forces grow as 1/sin mu: 5.8 times those at 90 deg at 10 deg). Norton,
#: *Design of Machinery*, 5th ed., §4.10 recommends at least 40 deg for good running; that is a design goal to
#: set as a constraint, not a fault, and the run's diagnostics warn below it.
DEFAULT_MIN_TRANSMISSION_DEG = 10.0
#: |normalised determinant| (the sine of the transmission angle) below which a design is near a dead point.
NEAR_DEAD = math.sin(math.radians(1.0))
#: At most this many designs x crank angles in one kinematics call (bounds the memory of the motion group).
CHUNK_POSITIONS = 1 << 18

STATUS_COLUMNS = ("assembled", "regular", "status", "dead_point", "branch_change", "near_dead_point",
                  "poor_transmission", "assembled_fraction")
#: The status of a design: its first fault in this order, else "regular".
FAULTS = (("assembled", "does not assemble"), ("dead_point", "dead point"), ("branch_change", "branch change"),
          ("near_dead_point", "near dead point"), ("poor_transmission", "poor transmission"))


# ------------------------------------------------------------------------------------------------ names


def per_output(mech: Mechanism) -> list[str]:
    """The outputs that get their own time ratio and transmission angles: the sliders, when there are several
    (a double slider-crank)."""
    sliders = [b for b, kind in output_bodies(mech) if kind == "slide"]
    return sliders if len(sliders) > 1 else []


def compactor_plate(mech: Mechanism) -> tuple[Any, str] | None:
    """(the RRR dyad, the coupler point's name) of a four-bar with a coupler point (the compactor's plate and
    pressing point), else None."""
    if len(mech.dyads) != 1 or not isinstance(mech.dyads[0], RRR):
        return None
    d = mech.dyads[0]
    if split_ref(d.pin_b)[0] != GROUND or split_ref(d.pin_a)[0] != mech.crank.body:
        return None
    extra = [p for p in mech.body(d.a).points if p not in (split_ref(d.pin_a)[1], d.inner) and p != "G"]
    return (d, extra[0]) if len(extra) == 1 else None


def result_names(mech: Mechanism, machine: str | None = None, harmonics: int = 0) -> list[str]:
    """Every numeric result the population evaluator gives for a mechanism of this structure (of ``machine``),
    the amplitude and phase of its first ``harmonics`` harmonics (``[output] harmonics``) included: the
    results a run of it reports."""
    names = []
    outputs = [b for b, _ in output_bodies(mech)]
    per = per_output(mech)
    for q in population_quantities(machine):
        if q.key.startswith("grashof.") and grashof_margin(mech) is None:
            continue
        if q.key == "time_ratio" and not outputs:
            continue
        if "<joint>" in q.key:
            names += [q.key.replace("<joint>", j[0]) for j in joints(mech)]
        elif q.key == "stroke.<body>":
            names += [f"stroke.{b}" for b in outputs]
        elif "<load>" in q.key:
            loads: list[Any] = [*mech.forces, *mech.torques]
            names += [q.key.replace("<load>", load.name) for load in loads]
        elif "<series*>" in q.key:
            names += [q.key.replace("<series*>", s).replace("<order>", str(k)) for s in HARMONIC_SERIES
                      for k in range(1, harmonics + 1)]
        elif "<body>" in q.key:
            names += [q.key.replace("<body>", b) for b in per]
        else:
            names.append(q.key)
    return names


#: The groups a sweep and an exploration compute for every design by default (the ``analysis`` group's results
#: are computed when the objective names one).
SWEEP_GROUPS = ("forces", "motion", "geometry")


def sweep_columns(mech: Mechanism, machine: str | None = None, objective: str | None = None,
                  extra: tuple[str, ...] = ()) -> list[str]:
    """The per-design results a sweep or an exploration keeps for every design: those of
    :data:`SWEEP_GROUPS`, the Grashof class of a four-bar, the ``objective`` if it is another result, and the
    ``extra`` results asked for (``[sweep] columns``)."""
    names = [k for k in result_names(mech, machine) if (f := find(k)) is not None and f[0].group in SWEEP_GROUPS]
    if "grashof.margin" in names:
        names.append("grashof.class")
    for key in (objective, *extra):
        if key is not None and key not in names:
            names.append(key)
    return names


def result_unit(key: str, mech: Mechanism | None = None) -> str:
    """The SI unit of result ``key`` (a stroke's from its output: m for a slider, rad for a rocker; a harmonic
    amplitude's from its series)."""
    if key.startswith("stroke.") and mech is not None:
        return "m" if dict(output_bodies(mech)).get(key[7:]) == "slide" else "rad"
    found = find(key)
    if found is not None and found[0].over_positions == "harmonic_amplitude":
        return HARMONIC_SERIES.get(found[1]["series"], "")  # the unit of its series
    return found[0].unit if found is not None else ""


def _groups(wanted: Iterable[str]) -> set[str]:
    out = set()
    for key in wanted:
        found = find(key)
        if found is not None and found[0].group:
            out.add(found[0].group)
    return out


# ------------------------------------------------------------------------------------------------ evaluation


def evaluate_population(mech: Mechanism, phi, speed, acceleration, wanted: Iterable[str], *,
                        about=(0.0, 0.0), machine: str | None = None,
                        min_transmission_angle: float = math.radians(DEFAULT_MIN_TRANSMISSION_DEG),
                        engine: str = "auto") -> dict[str, np.ndarray]:
    """The results ``wanted`` (catalogue keys) of every design of ``mech`` as (N,) arrays in SI, and the status
    columns. ``phi`` [rad] the crank angles, ``speed`` [rad/s] and ``acceleration`` [rad/s^2] floats or one
    value per design, ``about`` [m] the point of the shaking moments, ``min_transmission_angle`` [rad] the
    threshold of ``poor_transmission``. Results of designs that are not regular are NaN.

    ``engine``: "numpy" (the reference: kinematics in chunks of designs, then whole-array reductions, the
    forces by :func:`machdyn.linkage.sweep`), "fused" (the status, motion and force groups in one compiled
    pass, :mod:`machdyn.linkage.fused_population`: what the optimiser uses) or "auto" (the status and motion
    groups in that pass, the forces by :func:`machdyn.linkage.sweep`, whose own choice of engine keeps a
    sweep's force summaries as they were recorded, to the last bit: a loss-free cycle's mean power is zero
    up to rounding noise that differs between the two engines). "fused" and "auto" fall back to the NumPy
    path when numba is absent or the mechanism does not compile. All agree to rounding."""
    order = list(dict.fromkeys(wanted))
    wanted = set(order)
    groups = _groups(wanted)
    phi = np.asarray(phi, dtype=float)
    n = mech.design_count or max(np.size(speed) if np.ndim(speed) and np.shape(speed) != phi.shape else 1, 1)
    out: dict[str, np.ndarray] = {}
    with np.errstate(all="ignore"), warnings.catch_warnings():
        # Designs that close at no crank angle give all-NaN rows, reported as NaN and flagged.
        warnings.simplefilter("ignore", RuntimeWarning)
        forces = "forces" in groups
        status = _fused(mech, phi, speed, acceleration, n, wanted, about, machine, min_transmission_angle, out,
                        forces and engine == "fused", engine)
        if status is None:  # the reference: NumPy kinematics in chunks, then the sweep for the forces
            status = _motion(mech, phi, speed, acceleration, n, wanted, about, machine, min_transmission_angle,
                             out)
        elif engine == "fused":
            forces = False  # computed in the same pass
        if forces:
            res = sweep(mech, phi, speed, acceleration, shaking_about=tuple(about))
            status["dead_point"] |= ~np.broadcast_to(np.asarray(res.regular, dtype=bool), (n,)) & status["assembled"]
            for key, attr in ENGINE_SUMMARIES.items():
                out[key] = np.asarray(getattr(res, attr), dtype=float)
            for joint, values in res.max_joint_force.items():
                out[f"joint.{joint}.max_force"] = np.asarray(values, dtype=float)
        if "geometry" in groups:
            out.update(_geometry(mech, n))
        regular = _regular(status)
        if "dead_positions.count" in wanted:  # a design that passes one is flagged (dead_point) and not regular
            out["dead_positions.count"] = np.where(np.asarray(status["dead_point"], dtype=bool), np.nan, 0.0)
        if "analysis" in groups:
            found = _analysis(mech, phi, speed, acceleration, n, regular, wanted, about) if regular.any() else {}
            out.update({key: found.get(key, np.full(n, np.nan)) for key in wanted
                        if (f := find(key)) is not None and f[0].group == "analysis"})
    for key, values in list(out.items()):
        arr = np.broadcast_to(values, (n,))
        # A figure of the geometry (the Grashof margin) holds for every design: it tells why one fails.
        if arr.dtype.kind == "f" and not key.startswith("grashof."):
            out[key] = np.where(regular, arr, np.nan)
        else:
            out[key] = np.array(arr)
    status = {k: np.asarray(v) for k, v in status.items()}
    status["regular"] = regular
    status["status"] = _status_text(status, n)
    first = {k: status.pop(k) for k in ("assembled", "regular", "status")}
    ordered = {k: out[k] for k in order if k in out}
    return {**first, **ordered, **{k: v for k, v in out.items() if k not in ordered}, **status}


def _fused(mech, phi, speed, acceleration, n, wanted, about, machine, limit, out, forces, engine):
    """The status columns, and the motion and (``forces``) force groups' results into ``out``, by one fused
    pass (:func:`machdyn.linkage.fused_population.run_population`); None when the fused engine is not used
    (``engine`` "numpy", no numba, crank angles not 1-D, or a mechanism it does not compile: then the NumPy
    path computes them)."""
    check_engine(engine)
    if engine == "numpy" or phi.ndim != 1 or not available():
        return None
    inertial = bool(wanted & {"inertial_shaking_force.max", "inertial_shaking_moment.max_abs"})
    plate = compactor_plate(mech) if machine == "compactor" and any(k.startswith("compactor.") for k in wanted) \
        else None
    coupler = plate[0].a if plate is not None else None
    active = next((f.active for f in mech.forces if f.point.split(".")[0] == coupler and f.active), None) \
        if coupler is not None else None
    try:
        run = run_population(mech, phi, _column(speed, n, phi), _column(acceleration, n, phi), designs=n,
                             about=tuple(about), forces=forces, inertial=inertial, plate=coupler, active=active,
                             strokes=any(k.startswith("stroke.") for k in wanted))
    except InputError:  # a mechanism the fused engine does not compile
        return None
    M = run.motion
    nd = run.dyads
    dead = M[:, 2] > 0.5
    lows, highs, worsts = (M[:, 5 + k:5 + 3 * nd:3] for k in range(3))
    if nd:
        low, high, worst = lows.min(axis=1), highs.max(axis=1), worsts.min(axis=1)
        none = ~np.isfinite(low)
        low, high, worst = (np.where(none, np.nan, v) for v in (low, high, worst))
    else:
        low = high = worst = np.full(n, np.nan)
    status = {
        "assembled": M[:, 0] > 0.5,
        "assembled_fraction": M[:, 1],
        "dead_point": dead,
        "branch_change": M[:, 4] > 0.5,
        "near_dead_point": (M[:, 3] > 0.5) & ~dead,
        "poor_transmission": np.isfinite(worst) & (worst < limit),
    }
    results = {"transmission_angle.min": low, "transmission_angle.max": high, "transmission_angle.worst": worst}
    col = 5 + 3 * nd
    per = per_output(mech)
    for i, (body, kind) in enumerate(output_bodies(mech)):
        results[f"stroke.{body}"] = M[:, col] if kind == "slide" else full_turn_stroke(M[:, col], _step(phi))
        if i == 0:
            results["time_ratio"] = M[:, col + 1]
        if body in per:
            results[f"time_ratio.{body}"] = M[:, col + 1]
        col += 2
    for d, dyad in enumerate(mech.dyads):
        for output in dyad.outputs():
            if output.body in per:
                results[f"transmission_angle.{output.body}.min"] = lows[:, d]
                results[f"transmission_angle.{output.body}.max"] = highs[:, d]
    if inertial:
        results["inertial_shaking_force.max"], results["inertial_shaking_moment.max_abs"] = M[:, col], M[:, col + 1]
        col += 2
    if plate is not None:
        k1_min = M[:, col + 1]
        k2 = np.broadcast_to(_plate_lever_ratio(mech, *plate), (n,))
        results.update({"compactor.plate_angle.max": M[:, col], "compactor.k1.min": k1_min, "compactor.k2": k2,
                        "compactor.force_gain.min": k1_min * k2})
    out.update({k: v for k, v in results.items() if k in wanted})
    if run.forces is not None:
        F = run.forces
        columns = {name: F[:, k] for k, name in enumerate(SUMMARY_FIELDS)}
        status["dead_point"] = dead | (~(columns["regular"] > 0.5) & status["assembled"])
        for key, attr in ENGINE_SUMMARIES.items():
            out[key] = columns[attr]
        for j, joint in enumerate(run.generated.joints):
            out[f"joint.{joint}.max_force"] = F[:, len(SUMMARY_FIELDS) + j]
    return status


def _regular(status: dict[str, np.ndarray]) -> np.ndarray:
    ok = np.asarray(status["assembled"], dtype=bool).copy()
    for key in ("dead_point", "branch_change", "near_dead_point", "poor_transmission"):
        ok &= ~np.asarray(status[key], dtype=bool)
    return ok


def _status_text(status: dict[str, np.ndarray], n: int) -> np.ndarray:
    text = np.full(n, "regular", dtype=object)
    for key, fault in reversed(FAULTS):
        flag = np.asarray(status[key], dtype=bool)
        text = np.where(~flag if key == "assembled" else flag, fault, text)
    return text.astype(str)


def _column(value, n: int, phi) -> Any:
    arr = np.asarray(value, dtype=float)
    if arr.ndim == 1 and arr.shape != phi.shape and arr.size == n:
        return arr[:, None]
    return arr


def _rows(value: Any, part: Any) -> Any:
    arr = np.asarray(value)
    return arr[part] if arr.ndim == 2 and arr.shape[0] > 1 else arr


def _motion(mech, phi, speed, acceleration, n, wanted, about, machine, limit, out) -> dict[str, np.ndarray]:
    """The status columns, and the motion group's results into ``out``, chunk of designs by chunk."""
    col_speed, col_acc = _column(speed, n, phi), _column(acceleration, n, phi)
    per_chunk = max(1, CHUNK_POSITIONS // max(phi.size, 1))
    parts: list[tuple[dict, dict]] = []
    for start in range(0, n, per_chunk):
        part = slice(start, min(n, start + per_chunk))
        sub = mech.take_designs(part) if mech.design_count else mech
        rows = part.stop - part.start
        kin = kinematics(sub, phi, _rows(col_speed, part), _rows(col_acc, part), on_fail="mask")
        parts.append(_motion_chunk(sub, kin, phi, (rows, phi.size), wanted, about, machine, limit))
    status = {k: np.concatenate([np.broadcast_to(p[0][k], (min(per_chunk, n - i * per_chunk),))
                                 for i, p in enumerate(parts)]) for k in parts[0][0]}
    for key in parts[0][1]:
        out[key] = np.concatenate([np.broadcast_to(p[1][key], (min(per_chunk, n - i * per_chunk),))
                                   for i, p in enumerate(parts)])
    return status


def _step(phi) -> float:
    """The spacing of the crank angles [rad] (a full turn for a single angle)."""
    phi = np.ravel(np.asarray(phi, dtype=float))
    return float(abs(phi[1] - phi[0])) if phi.size > 1 else 2 * math.pi


def _full_cycle(phi: np.ndarray) -> bool:
    """True if the crank angles are evenly spaced over one full turn without the end point."""
    return is_full_turn(phi)


def _motion_chunk(mech, kin, phi, shape, wanted, about, machine, limit) -> tuple[dict, dict]:
    assembled = np.broadcast_to(kin.assembled, shape)
    full = _full_cycle(phi)
    dead = np.zeros(shape[0], dtype=bool)
    branch = np.zeros(shape[0], dtype=bool)
    near = np.zeros(shape[0], dtype=bool)
    for rep in kin.dyad_reports:
        det = np.broadcast_to(np.asarray(rep.det, dtype=float), shape)
        mag = np.where(assembled, np.abs(det), np.inf)
        dead |= (~(mag >= DEAD_TOL)).any(axis=1)
        near |= (mag < NEAR_DEAD).any(axis=1)
        nxt = np.roll(det, -1, axis=1)
        pair = assembled & np.roll(assembled, -1, axis=1)
        if not full:
            pair[:, -1] = False
        branch |= (pair & (det * nxt < 0.0)).any(axis=1)
    ok = assembled & (np.abs(np.stack([np.broadcast_to(np.asarray(r.det, float), shape)
                                       for r in kin.dyad_reports])) >= DEAD_TOL).all(axis=0) \
        if kin.dyad_reports else assembled
    results: dict[str, np.ndarray] = {}
    mu_min, mu_max, worst = _transmission(kin, ok, shape)
    results["transmission_angle.min"], results["transmission_angle.max"] = mu_min, mu_max
    results["transmission_angle.worst"] = worst
    status = {
        "assembled": assembled.all(axis=1),
        "assembled_fraction": assembled.mean(axis=1),
        "dead_point": dead,
        "branch_change": branch,
        "near_dead_point": near & ~dead,
        "poor_transmission": np.isfinite(worst) & (worst < limit),
    }
    motion_wanted = any((f := find(k)) is not None and f[0].group == "motion" for k in wanted)
    if not motion_wanted:
        return status, {k: v for k, v in results.items() if k in wanted}
    outputs = output_bodies(mech)
    per = per_output(mech)
    for i, (body, kind) in enumerate(outputs):
        if kind == "slide":
            sm = kin.slide(body)
            values, rates = np.broadcast_to(sm.s, shape), np.broadcast_to(sm.v, shape)
        else:
            b = kin.body(body)
            values = np.unwrap(np.where(ok, np.broadcast_to(b.angle, shape), 0.0), axis=1)
            rates = np.broadcast_to(b.omega, shape)
        results[f"stroke.{body}"] = (np.where(ok, values, -np.inf).max(axis=1)
                                     - np.where(ok, values, np.inf).min(axis=1))
        if kind != "slide":
            results[f"stroke.{body}"] = full_turn_stroke(results[f"stroke.{body}"], _step(phi))
        ratio = time_ratio(phi, rates, ok, full)
        if i == 0:
            results["time_ratio"] = ratio
        if body in per:
            results[f"time_ratio.{body}"] = ratio
    if per:
        for d, rep in zip(mech.dyads, kin.dyad_reports, strict=False):
            for out in d.outputs():
                if out.body in per:
                    mu = np.broadcast_to(np.asarray(rep.transmission, dtype=float), shape)
                    good = ok & np.isfinite(mu)
                    results[f"transmission_angle.{out.body}.min"] = np.where(good, mu, np.inf).min(axis=1)
                    results[f"transmission_angle.{out.body}.max"] = np.where(good, mu, -np.inf).max(axis=1)
    if wanted & {"inertial_shaking_force.max", "inertial_shaking_moment.max_abs"}:
        # -sum m a per design: zero for a massless (statics) design, whatever the other designs of the chunk weigh
        ix, iy = (np.broadcast_to(np.asarray(f, dtype=float), shape) for f in inertial_force(kin))
        results["inertial_shaking_force.max"] = np.where(ok, np.hypot(ix, iy), -np.inf).max(axis=1)
        moment = np.abs(np.broadcast_to(inertial_shaking_moment(kin, (about[0], about[1])), shape))
        results["inertial_shaking_moment.max_abs"] = np.where(ok, moment, -np.inf).max(axis=1)
    if machine == "compactor" and any(k.startswith("compactor.") for k in wanted):
        results.update(_compactor_results(mech, kin, phi, ok, shape))
    return status, {k: v for k, v in results.items() if k in wanted}


def _transmission(kin, ok, shape) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Min, max and worst (closest to 0 or pi) transmission angle [rad] of every dyad over the regular
    positions; NaN for a mechanism whose dyads have none."""
    mus = [np.broadcast_to(np.asarray(rep.transmission, dtype=float), shape) for rep in kin.dyad_reports]
    if not mus:
        nan = np.full(shape[0], np.nan)
        return nan, nan, nan
    mu = np.stack(mus)
    good = np.broadcast_to(ok, mu.shape) & np.isfinite(mu)
    low = np.where(good, mu, np.inf).min(axis=(0, 2))
    high = np.where(good, mu, -np.inf).max(axis=(0, 2))
    worst = np.where(good, worst_of(mu, mu), np.inf).min(axis=(0, 2))
    none = ~good.any(axis=(0, 2))
    return (np.where(none, np.nan, low), np.where(none, np.nan, high), np.where(none, np.nan, worst))


def compactor_results(mech: Mechanism, kin: Any) -> dict[str, float]:
    """The compactor's results (see the module's docstring) of one analysed design, as a run reports them: the
    same function as a population's, over the run's crank angles."""
    phi = np.asarray(kin.crank_angle, dtype=float)
    shape = (1, phi.size)
    ok = np.broadcast_to(np.asarray(kin.assembled, dtype=bool), shape)
    with np.errstate(all="ignore"):
        found = _compactor_results(mech, kin, phi, ok, shape)
    return {k: float(np.ravel(v)[0]) for k, v in found.items()}


def _compactor_results(mech, kin, phi, ok, shape) -> dict[str, np.ndarray]:
    plate = compactor_plate(mech)
    if plate is None:
        return {}
    dyad, point = plate
    coupler = dyad.a
    k2 = _plate_lever_ratio(mech, dyad, point)
    theta2 = np.broadcast_to(kin.body(coupler).angle, shape)
    gamma = np.abs(np.mod(theta2 + np.pi, 2 * np.pi) - np.pi)
    active = next((f.active for f in mech.forces if f.point.split(".")[0] == coupler and f.active), None)
    cols = np.flatnonzero(np.broadcast_to(np.asarray(window(phi, active), dtype=float), phi.shape) > 0)
    # k1 only where the plate presses (the window's crank angles): alpha = theta2 - phi.
    alpha = theta2[:, cols] - np.broadcast_to(kin.body(mech.crank.body).angle, shape)[:, cols]
    k1 = np.abs(crank_force_gain(alpha))
    k1_min = np.where(ok[:, cols], k1, np.inf).min(axis=1) if cols.size else np.full(shape[0], np.nan)
    return {
        "compactor.plate_angle.max": np.where(ok, gamma, -np.inf).max(axis=1),
        "compactor.k1.min": k1_min,
        "compactor.k2": np.broadcast_to(k2, (shape[0],)),
        "compactor.force_gain.min": k1_min * k2,
    }


def _plate_lever_ratio(mech, dyad, point) -> np.ndarray:
    """k2 = l / a of the compactor's plate (seed 003 eq 1): l the plate's length, a = l - u the distance of the
    pressing point P (at u along the plate from A) from B; NaN where P is not between A and B."""
    pts = mech.body(dyad.a).points
    length = np.hypot(np.asarray(pts[dyad.inner][0], dtype=float), np.asarray(pts[dyad.inner][1], dtype=float))
    u = np.asarray(pts[point][0], dtype=float)
    lever = length - u  # a: distance of P from B along the plate
    return np.where((lever > 0) & (u >= 0), length / np.where(lever > 0, lever, 1.0), np.nan)


def _geometry(mech: Mechanism, n: int) -> dict[str, np.ndarray]:
    """The Grashof margin s + l - (p + q) [m] and class of a four-bar (Norton, *Design of Machinery*, 5th ed.,
    §2.12), NaN and "" for other mechanisms."""
    margin = grashof_margin(mech)
    if margin is None:
        return {"grashof.margin": np.full(n, np.nan), "grashof.class": np.full(n, "", dtype=object)}
    kind = np.broadcast_to(np.asarray(grashof_type(mech), dtype=object), (n,))
    return {"grashof.margin": np.broadcast_to(np.asarray(margin, dtype=float), (n,)).copy(), "grashof.class": kind}


def _analysis(mech, phi, speed, acceleration, n, regular, wanted, about) -> dict[str, np.ndarray]:
    """The analysis group's results of the regular designs, reduced by the run's own function (the harmonics
    up to the highest order wanted, the loads' mean powers)."""
    index = np.flatnonzero(regular)
    sub = mech.take_designs(index) if mech.design_count else mech
    spd, acc = (_rows(_column(v, n, phi), index) for v in (speed, acceleration))
    analysis = analyse(sub, phi, spd, acc, diagnostics=False)
    orders = max((int(f[1]["order"]) for k in wanted if (f := find(k)) is not None and "order" in f[1]), default=0)
    values, _ = linkage_scalars(analysis, sub, about=tuple(about), harmonic_orders=orders,
                                with_loads=any(k.startswith("load.") for k in wanted))
    out = {}
    for key in wanted:
        found = find(key)
        if found is None or found[0].group != "analysis" or key not in values:
            continue
        full = np.full(n, np.nan)
        full[index] = np.broadcast_to(np.asarray(values[key], dtype=float), (index.size,))
        out[key] = full
    return out

