"""Per-design results of a whole population from the engine: the one place the optimiser calls it.

Kinematic results (strokes, time ratio, transmission angle, the compactor's plate angle and force gain) come
from one call of :func:`machdyn.linkage.kinematics` over designs x crank angles; force results (torque, power,
joint forces, shaking force and moment) from one call of :func:`machdyn.linkage.sweep`, made only when an
objective or constraint needs one of them. Result keys follow the single-design results of ``machdyn run``
(``driving_torque.max_abs``, ``joint.B.max_force``, ``stroke.rocker``...); every value is SI (angles in rad).

Seed 003 (Asfandiyarov et al., 2019) results of a four-bar with a coupler point P (the compactor: plate =
coupler, compaction force at P):

- ``compactor.plate_angle.max`` = max over the cycle of |gamma|, gamma = the plate's angle to the horizontal
  (corrected eq 10; the design rule gamma < 20 deg, conclusion 2a);
- ``compactor.k1.min`` = min over the pressing window of k1 = 1/|cos alpha|, alpha = theta2 - phi (eq 1, eq 8);
- ``compactor.k2`` = l / a, a = l - u the distance of P from B along the plate (eq 1);
- ``compactor.force_gain.min`` = min over the pressing window of k1 k2, the force gain Q/P (eq 1) the design
  guarantees over the whole pressing stroke. The window is the ``active`` range of the first force on the
  coupler that has one (the whole cycle without one).
"""

from __future__ import annotations

import warnings
from collections.abc import Iterable

import numpy as np

from ..linkage.model import GROUND, RPR, RRP, RRR, Mechanism, split_ref

#: Results computed by linkage.sweep (force analysis); the others come from kinematics alone.
FORCE_RESULTS = ("driving_torque.max_abs", "driving_torque.rms", "input_power.mean", "shaking_force.max",
                 "shaking_moment.max_abs")
#: The SI unit of each result family (the last key part decides for joints and strokes).
RESULT_UNITS = {
    "driving_torque.max_abs": "N*m", "driving_torque.rms": "N*m", "input_power.mean": "W",
    "shaking_force.max": "N", "shaking_moment.max_abs": "N*m", "transmission_angle.min": "rad",
    "transmission_angle.max": "rad", "transmission_angle.worst": "rad", "time_ratio": "",
    "compactor.plate_angle.max": "rad", "compactor.k1.min": "", "compactor.k2": "",
    "compactor.force_gain.min": "",
}


def result_unit(key: str, mechanism: Mechanism | None = None) -> str:
    """The SI unit of result ``key``."""
    if key in RESULT_UNITS:
        return RESULT_UNITS[key]
    if key.startswith("joint.") and key.endswith(".max_force"):
        return "N"
    if key.startswith("stroke.") and mechanism is not None:
        return "m" if key[7:] in _sliders(mechanism) else "rad"
    return ""


def _sliders(mech: Mechanism) -> set[str]:
    return {d.b for d in mech.dyads if isinstance(d, RRP) and d.guide.body == GROUND}


def result_names(mech: Mechanism) -> list[str]:
    """Every result key the optimiser can evaluate for a mechanism of this structure."""
    from ..linkage.model import joints

    names = list(FORCE_RESULTS) + [f"joint.{j[0]}.max_force" for j in joints(mech)]
    names += ["transmission_angle.min", "transmission_angle.max", "transmission_angle.worst"]
    outputs = [body for body, _kind in _output_bodies(mech)]
    names += [f"stroke.{b}" for b in outputs]
    if outputs:
        names.append("time_ratio")
    if _compactor_point(mech) is not None:
        names += ["compactor.plate_angle.max", "compactor.k1.min", "compactor.k2", "compactor.force_gain.min"]
    return names


def _output_bodies(mech: Mechanism):
    """Sliders on ground guides (travel) and rockers pinned to the ground (angle), in dyad order."""
    for d in mech.dyads:
        if isinstance(d, RRP) and d.guide.body == GROUND:
            yield d.b, "slide"
        if isinstance(d, RRR | RPR) and split_ref(d.pin_b)[0] == GROUND:
            yield d.b, "angle"


def _compactor_point(mech: Mechanism):
    """The coupler point P of a four-bar (one RRR from the crank to the ground), else None."""
    if len(mech.dyads) != 1 or not isinstance(mech.dyads[0], RRR):
        return None
    d = mech.dyads[0]
    if split_ref(d.pin_b)[0] != GROUND or split_ref(d.pin_a)[0] != mech.crank.body:
        return None
    return "P" if "P" in mech.body(d.a).points else None


def evaluate(mech: Mechanism, phi, speed, acceleration, wanted: Iterable[str],
             shaking_about=(0.0, 0.0)) -> dict[str, np.ndarray]:
    """The results ``wanted`` for every design of ``mech`` (N designs), as (N,) arrays, plus
    ``assembled_fraction`` (share of crank angles where the design closes) and ``regular`` (closes at every
    angle and passes no dead position). Results of designs that are not regular are NaN."""
    from ..linkage import kinematics, sweep
    from ..linkage.kinematics import singular

    wanted = set(wanted)
    phi = np.asarray(phi, dtype=float)
    n = mech.design_count or max(np.size(speed) if np.ndim(speed) else 1, 1)
    col_speed = np.asarray(speed, dtype=float)
    col_speed = col_speed[:, None] if col_speed.ndim == 1 else col_speed
    col_acc = np.asarray(acceleration, dtype=float)
    col_acc = col_acc[:, None] if col_acc.ndim == 1 else col_acc
    with np.errstate(all="ignore"):
        kin = kinematics(mech, phi, col_speed, col_acc, on_fail="mask")
        shape = (n, phi.size)
        assembled = np.broadcast_to(kin.assembled, shape)
        ok = assembled & ~np.broadcast_to(singular(kin.dyad_reports, kin.shape), shape)
        out: dict[str, np.ndarray] = {
            "assembled_fraction": assembled.mean(axis=1),
            "regular": ok.all(axis=1),
        }
        out.update(_kinematic_results(mech, kin, phi, ok, shape, wanted))
        if wanted & (set(FORCE_RESULTS) | {k for k in wanted if k.startswith("joint.")}):
            with warnings.catch_warnings():
                # Designs that close at no crank angle give all-NaN rows, whose peaks the sweep reports as
                # NaN (and flags not regular) after NumPy warns about them.
                warnings.simplefilter("ignore", RuntimeWarning)
                res = sweep(mech, phi, speed, acceleration, shaking_about=shaking_about)
            out["regular"] = out["regular"] & np.asarray(res.regular, dtype=bool)
            for key, attr in (("driving_torque.max_abs", "max_driving_torque"),
                              ("driving_torque.rms", "rms_driving_torque"),
                              ("input_power.mean", "mean_input_power"),
                              ("shaking_force.max", "max_shaking_force"),
                              ("shaking_moment.max_abs", "max_shaking_moment")):
                out[key] = np.asarray(getattr(res, attr), dtype=float)
            for joint, values in res.max_joint_force.items():
                out[f"joint.{joint}.max_force"] = np.asarray(values, dtype=float)
    bad = ~out["regular"]
    for key, values in out.items():
        if key not in ("assembled_fraction", "regular"):
            out[key] = np.where(bad, np.nan, np.broadcast_to(values, (n,)))
    return out


def _kinematic_results(mech, kin, phi, ok, shape, wanted) -> dict[str, np.ndarray]:
    out: dict[str, np.ndarray] = {}
    full_cycle = phi.size > 2 and np.allclose(np.diff(phi), 2 * np.pi / phi.size, rtol=1e-9, atol=1e-12)
    mus = [np.broadcast_to(np.asarray(rep.transmission, dtype=float), shape) for rep in kin.dyad_reports
           if rep.kind == "RRR"]
    if mus and wanted & {"transmission_angle.min", "transmission_angle.max", "transmission_angle.worst"}:
        mu = np.stack(mus)
        good = np.broadcast_to(ok, mu.shape) & np.isfinite(mu)
        out["transmission_angle.min"] = np.where(good, mu, np.inf).min(axis=(0, 2))
        out["transmission_angle.max"] = np.where(good, mu, -np.inf).max(axis=(0, 2))
        worst = np.minimum(mu, np.pi - mu)
        out["transmission_angle.worst"] = np.where(good, worst, np.inf).min(axis=(0, 2))
    first = True
    for body, kind in _output_bodies(mech):
        if f"stroke.{body}" not in wanted and not (first and "time_ratio" in wanted):
            first = False
            continue
        if kind == "slide":
            sm = kin.slide(body)
            values, rates = np.broadcast_to(sm.s, shape), np.broadcast_to(sm.v, shape)
        else:
            b = kin.body(body)
            values = np.unwrap(np.where(ok, np.broadcast_to(b.angle, shape), 0.0), axis=1)
            rates = np.broadcast_to(b.omega, shape)
        out[f"stroke.{body}"] = (np.where(ok, values, -np.inf).max(axis=1)
                                 - np.where(ok, values, np.inf).min(axis=1))
        if first:
            out["time_ratio"] = _time_ratio(phi, rates, ok, full_cycle)
            first = False
    point = _compactor_point(mech)
    if point is not None and any(k.startswith("compactor.") for k in wanted):
        out.update(_compactor_results(mech, kin, phi, ok, shape))
    return out


def _time_ratio(phi, rates, ok, full_cycle) -> np.ndarray:
    """Quick-return ratio per design (Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
    §1.9): longer over shorter crank interval between the output's two limit positions (rate = 0), located
    by linear interpolation; NaN unless the crank turns fully and there are exactly two limit positions."""
    nxt = np.roll(rates, -1, axis=1)
    ok_pair = ok & np.roll(ok, -1, axis=1)
    if not full_cycle:
        ok_pair[:, -1] = False
    cross = ok_pair & ((rates == 0.0) | (rates * nxt < 0.0))
    count = cross.sum(axis=1)
    step = np.mod(np.roll(phi, -1) - phi, 2 * np.pi)
    with np.errstate(all="ignore"):
        frac = np.where(rates == 0.0, 0.0, rates / (rates - nxt))
    where = np.broadcast_to(phi, rates.shape) + np.broadcast_to(step, rates.shape) * frac
    i1 = np.argmax(cross, axis=1)
    rest = cross.copy()
    rest[np.arange(len(i1)), i1] = False
    i2 = np.argmax(rest, axis=1)
    rows = np.arange(len(i1))
    forward = np.mod(where[rows, i2] - where[rows, i1], 2 * np.pi)
    back = 2 * np.pi - forward
    ratio = np.maximum(forward, back) / np.minimum(forward, back)
    return np.where((count == 2) & full_cycle, ratio, np.nan)


def _compactor_results(mech, kin, phi, ok, shape) -> dict[str, np.ndarray]:
    from ..linkage.loads import window

    coupler = mech.dyads[0].a
    pts = mech.body(coupler).points
    length = np.hypot(np.asarray(pts[mech.dyads[0].inner][0], dtype=float),
                      np.asarray(pts[mech.dyads[0].inner][1], dtype=float))
    u = np.asarray(pts["P"][0], dtype=float)
    lever = length - u  # a: distance of P from B along the plate
    k2 = np.where((lever > 0) & (u >= 0), length / np.where(lever > 0, lever, 1.0), np.nan)
    theta2 = np.broadcast_to(kin.body(coupler).angle, shape)
    gamma = np.abs(np.mod(theta2 + np.pi, 2 * np.pi) - np.pi)
    active = next((f.active for f in mech.forces if f.point.split(".")[0] == coupler and f.active), None)
    cols = np.flatnonzero(np.broadcast_to(np.asarray(window(phi, active), dtype=float), phi.shape) > 0)
    # k1 only where the plate presses (the window's crank angles): alpha = theta2 - phi.
    alpha = theta2[:, cols] - np.broadcast_to(kin.body(mech.crank.body).angle, shape)[:, cols]
    k1 = 1.0 / np.abs(np.cos(alpha))
    k1_min = np.where(ok[:, cols], k1, np.inf).min(axis=1) if cols.size else np.full(shape[0], np.nan)
    return {
        "compactor.plate_angle.max": np.where(ok, gamma, -np.inf).max(axis=1),
        "compactor.k1.min": k1_min,
        "compactor.k2": np.broadcast_to(k2, (shape[0],)),
        "compactor.force_gain.min": k1_min * k2,
    }
