"""The balance of every design of a population at once: the frame loads before and after, and the closed-form
least-squares counterweights, with NumPy arrays whose leading axis is the design.

The same formulas as the single-design path (:func:`machdyn.balancing.frame.frame_loads`,
:func:`machdyn.balancing.general.least_squares_counterweights`): the shaking force is linear in the counterweight
unknowns (m, m u, m v) (Berkof & Lowen, "A new method for completely force balancing simple linkages", ASME J. Eng.
Ind. 91(1), 1969, 21-26), so each design's force-optimal counterweights solve the linear least-squares problem
min |A x + F0| over the cycle; here every design's (2M, n) matrix A is solved in one stacked call of the
pseudo-inverse (:func:`numpy.linalg.pinv`, the SVD with the cut-off of :func:`numpy.linalg.lstsq`, so that the
minimum-norm solution of dependent unknowns is the same). The balanced designs are then analysed together (one
engine call) for the loads after. A design whose closed form leaves a slot's mass bounds is solved by the
single-design function (scipy's bounded least squares), as its run would be.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

import numpy as np

from ..errors import AnalysisError, AssemblyError, InputError
from ..linkage import Mechanism, PointMass, kinematics, kinetostatics
from ..linkage.engines import available
from ..linkage.fused_generator import Unsupported
from ..linkage.refs import column
from .frame import cycle
from .general import CounterweightSlot, MassSlot, least_squares_counterweights, pivot_point, unknown_bounds
from .methods import METHODS, slots

__all__ = ["kinetostatics_masked", "frame_loads_population", "least_squares_population", "balance_population",
           "BALANCE_KEYS"]

#: design x crank positions evaluated at once: a population is balanced in chunks of this size, so that its memory
#: stays bounded (about 60 doubles per position: 30 MB a chunk)
CHUNK_POSITIONS = 1 << 16

#: the keys of a ``[balance]`` run a population form gives, with the frame-load figure each reads
BALANCE_KEYS = ("rms_force", "peak_force", "rms_moment", "torque_fluctuation", "peak_joint_force")


def _column(speed: Any) -> Any:
    s = np.abs(np.asarray(speed, dtype=float))
    if s.ndim == 0:
        return float(s)
    return s.reshape(s.shape[0], -1)[:, :1]  # one speed per design (constant over the cycle)


def frame_loads_population(mech: Mechanism, phi: np.ndarray, speed: Any, travel: bool = True) -> dict[str, Any]:
    """The figures of :class:`~machdyn.balancing.frame.FrameLoads` for every design of ``mech`` at constant crank
    ``speed`` [rad/s] (a float or one per design) over the crank angles ``phi`` [rad], gravity off, as (N,)
    arrays: ``rms_force``, ``peak_force`` [N], ``rms_moment``, ``peak_moment`` [N*m] (about the crank pivot),
    ``rms_torque``, ``torque_fluctuation`` [N*m], ``peak_joint_force`` [N], ``com_travel`` [m] (NaN without
    ``travel``: a run reports it after balancing only) and ``valid``
    (False for a design that does not close at every angle, its figures NaN). The (N, M) curves ``fx``, ``fy``
    are kept for the least squares."""
    quiet = replace(mech, gravity=(0.0, 0.0))
    n = mech.design_count or 1
    forces = kinetostatics_masked(quiet, phi, speed)
    kin = forces.kinematics
    shape = (n, phi.size)
    fx = np.broadcast_to(np.asarray(forces.frame_fx, dtype=float), shape)
    fy = np.broadcast_to(np.asarray(forces.frame_fy, dtype=float), shape)
    pivot = quiet.ground[quiet.crank.pivot.split(".")[1]]
    moment = np.broadcast_to(np.asarray(forces.shaking_moment(about=pivot), dtype=float), shape)
    torque = np.broadcast_to(np.asarray(forces.driving_torque, dtype=float), shape)
    # the largest |force| of each joint: the root of the largest square (one root per design, no hypot per angle)
    joints = [np.sqrt(np.max(np.broadcast_to(r.fx * r.fx + r.fy * r.fy, shape), axis=1))
              for r in (forces.joint(j.name) for j in forces.joints)]
    peak_joint = np.max(np.stack(joints), axis=0) if joints else np.zeros(n)
    com = _com_travel(kin, shape) if travel else np.full(n, np.nan)
    valid = np.all(np.isfinite(fx) & np.isfinite(fy) & np.isfinite(torque), axis=1)
    out = {
        "rms_force": np.sqrt(np.mean(fx**2 + fy**2, axis=1)),
        "peak_force": np.sqrt(np.max(fx * fx + fy * fy, axis=1)),
        "rms_moment": np.sqrt(np.mean(moment**2, axis=1)),
        "peak_moment": np.max(np.abs(moment), axis=1),
        "rms_torque": np.sqrt(np.mean(torque**2, axis=1)),
        "torque_fluctuation": np.max(torque, axis=1) - np.min(torque, axis=1),
        "peak_joint_force": peak_joint,
        "com_travel": com,
    }
    found: dict[str, Any] = {k: np.where(valid, v, np.nan) for k, v in out.items()}
    return found | {"valid": valid, "fx": fx, "fy": fy, "kinematics": kin}


def _xy(kin: Any, body: str, u: Any, v: Any) -> tuple[Any, Any]:
    """Position (x, y) [m] of the body-frame point (u, v) of ``body`` at every angle (no velocities: the centre
    of mass's travel needs none)."""
    b = kin.bodies[body]
    return b.x + (b.cos * u - b.sin * v), b.y + (b.sin * u + b.cos * v)


def _acc(b: Any, u: Any, v: Any) -> tuple[Any, Any]:
    """Acceleration (ax, ay) [m/s^2] of the body-frame point (u, v) of the body state ``b``."""
    rx, ry = b.cos * u - b.sin * v, b.sin * u + b.cos * v
    w2 = b.omega * b.omega
    return b.ax - b.alpha * ry - w2 * rx, b.ay + b.alpha * rx - w2 * ry


def _com_travel(kin: Any, shape: tuple[int, int]) -> np.ndarray:
    """The travel [m] of the total centre of mass (the larger of its x and y ranges), as
    :func:`~machdyn.balancing.frame.centre_of_mass` gives it: 0 where nothing that moves has mass."""
    mech = kin.mechanism
    masses = [(name, mech.body(name).mass, mech.body(name).com) for name in mech.moving_bodies]
    masses += [(p.body, p.mass, p.position) for p in mech.point_masses]
    total: Any = 0.0
    mx: Any = 0.0
    my: Any = 0.0
    for body, mass, (u, v) in masses:
        m = column(mass)
        x, y = _xy(kin, body, column(u), column(v))
        total, mx, my = total + m, mx + m * x, my + m * y
    if not np.all(np.asarray(total) > 0):
        return np.zeros(shape[0])
    return np.maximum(np.ptp(np.broadcast_to(mx / total, shape), axis=1),
                      np.ptp(np.broadcast_to(my / total, shape), axis=1))


def kinetostatics_masked(mech: Mechanism, phi: np.ndarray, speed: Any) -> Any:
    """Motion and forces of every design: one compiled pass when numba is present and every design closes, else
    the NumPy engine with the positions where a design does not close masked to NaN."""
    try:
        return kinetostatics(mech, phi, speed, 0.0, engine="fused" if available() else "numpy")
    except (Unsupported, AssemblyError):  # a linkage the compiled pass does not handle; a design that fails
        return kinetostatics(mech, kinematics_result=kinematics(mech, phi, speed, 0.0, on_fail="mask"))


def _point(value: Any, n: int) -> tuple[np.ndarray, np.ndarray]:
    """A body-frame point (x, y) of one or N designs as two (N,) arrays."""
    x, y = value
    return (np.broadcast_to(np.asarray(x, dtype=float), (n,)).copy(),
            np.broadcast_to(np.asarray(y, dtype=float), (n,)).copy())


def least_squares_population(mech: Mechanism, slot_list: list[Any], phi: np.ndarray, speed: Any,
                             before: dict[str, Any] | None = None) -> dict[str, Any]:
    """The closed-form least-squares counterweights of every design (the population form of
    :func:`~machdyn.balancing.general.least_squares_counterweights`) and the balanced population.

    Returns ``{"model": the balanced mechanism of N designs, "before": ..., "after": frame figures (see
    :func:`frame_loads_population`), "placed": {name: (mass (N,), x (N,), y (N,))}, "valid": (N,) bool}``. A
    design is not valid where it does not close, or where its force-optimal counterweight on a floating body has a
    mass <= 0 (the single-design function raises AnalysisError: it cannot be built).
    """
    n = mech.design_count or 1
    before = before or frame_loads_population(mech, phi, speed, travel=False)
    kin = before["kinematics"]
    m_pos = phi.size
    f0 = np.concatenate([before["fx"], before["fy"]], axis=1)  # (N, 2M)
    cols: list[np.ndarray] = []
    columns: list[tuple[int, str]] = []
    refs: dict[int, tuple[tuple[np.ndarray, np.ndarray], bool]] = {}

    def stacked(ax: Any, ay: Any) -> np.ndarray:
        return np.concatenate([-np.broadcast_to(ax, (n, m_pos)), -np.broadcast_to(ay, (n, m_pos))], axis=1)

    for i, slot in enumerate(slot_list):
        if isinstance(slot, MassSlot):
            pm = next((p for p in mech.point_masses if p.name == slot.point_mass), None)
            if pm is None:
                raise InputError(f"No point mass '{slot.point_mass}' in mechanism '{mech.name}'; point masses: "
                                 f"{', '.join(p.name for p in mech.point_masses) or 'none'}.")
            cols.append(stacked(*_acc(kin.bodies[pm.body], column(pm.position[0]), column(pm.position[1]))))
            f0 = f0 - np.asarray(pm.mass, dtype=float).reshape(-1, 1) * cols[-1]  # the whole mass is the unknown
            columns.append((i, "m"))
            continue
        pivot = pivot_point(mech, slot.body)
        name = slot.about or pivot
        fixed = name is not None and name == pivot
        ref = _point(mech.body(slot.body).points[name], n) if name is not None else (np.zeros(n), np.zeros(n))
        refs[i] = (ref, fixed)
        # the acceleration of the point R + (u, v) is a_R + u a_x + v a_y: a_x, a_y the accelerations of the body's
        # unit vectors, -w^2 e - alpha e_perp (the derivative of the rigid-body point motion by u and by v)
        b = kin.bodies[slot.body]
        w2 = b.omega * b.omega
        parts = [("mu", -w2 * b.cos - b.alpha * b.sin, -w2 * b.sin + b.alpha * b.cos),
                 ("mv", w2 * b.sin - b.alpha * b.cos, -w2 * b.cos - b.alpha * b.sin)]
        if not fixed:
            parts.insert(0, ("m", *_acc(b, column(ref[0]), column(ref[1]))))
        for key, ax, ay in parts:
            cols.append(stacked(ax, ay))
            columns.append((i, key))
    matrix = np.stack(cols, axis=2)  # (N, 2M, n_unknowns)
    valid = before["valid"].copy()
    finite = np.where(valid[:, None, None], matrix, 0.0)
    rhs = np.where(valid[:, None], -f0, 0.0)
    x = _least_squares(finite, rhs)
    lo, hi = unknown_bounds(slot_list, tuple(columns))
    within = np.all((x >= lo) & (x <= hi), axis=1)
    values: dict[int, dict[str, np.ndarray]] = {}
    for (i, key), value in zip(columns, x.T, strict=True):
        values.setdefault(i, {})[key] = value
    placed: dict[str, tuple[np.ndarray, np.ndarray, np.ndarray]] = {}
    for i, slot in enumerate(slot_list):
        v = values[i]
        if isinstance(slot, MassSlot):
            pm = next(p for p in mech.point_masses if p.name == slot.point_mass)
            placed[slot.point_mass] = (v["m"], *_point(pm.position, n))
            continue
        (rx, ry), fixed = refs[i]
        mu, mv = v["mu"], v["mv"]
        if fixed:
            size = np.hypot(mu, mv)
            mass = size / slot.radius
            with np.errstate(invalid="ignore", divide="ignore"):
                ux = np.where(size > 0, mu / size * slot.radius, 0.0)
                uy = np.where(size > 0, mv / size * slot.radius, 0.0)
            px, py = rx + ux, ry + uy
        else:
            mass = v["m"]
            valid &= ~(within & ~(mass > 0))  # cannot be built: the single function raises AnalysisError
            with np.errstate(invalid="ignore", divide="ignore"):
                px, py = rx + mu / mass, ry + mv / mass
        placed[slot.name] = (mass, px, py)
    # the designs left out (not closing, not buildable, a bound reached) carry no counterweight in the balanced
    # population, so that it builds; their figures are NaN or the single function's
    kept = valid & within
    built = {k: (np.where(kept, m, 0.0), np.where(kept, x_, 0.0), np.where(kept, y_, 0.0))
             for k, (m, x_, y_) in placed.items()}
    balanced = _balanced(mech, slot_list, built)
    after = frame_loads_population(balanced, phi, speed)
    result = {"model": balanced, "before": before, "after": after, "placed": placed}
    for d in np.flatnonzero(valid & ~within):  # a mass bound reached: the bounded solver of the single path
        valid[d] = _solve_alone(mech, slot_list, phi, speed, int(d), result)
    valid &= after["valid"]
    result["valid"] = valid
    return result


def _least_squares(matrix: np.ndarray, rhs: np.ndarray) -> np.ndarray:
    """The minimum-norm least-squares solution x (N, n) of every design's A x = b (A (N, m, n), b (N, m)) by the
    singular value decomposition, singular values below eps * max(m, n) of the largest dropped: the cut-off of
    :func:`numpy.linalg.lstsq` with ``rcond=None`` (Golub & Van Loan, *Matrix Computations*, 4th ed., sec. 5.5.4,
    the pseudo-inverse solution)."""
    u, sv, vt = np.linalg.svd(matrix, full_matrices=False)
    kept = sv > np.finfo(float).eps * max(matrix.shape[1:]) * sv[:, :1]
    y = np.einsum("nij,ni->nj", u, rhs)
    y = np.where(kept, y / np.where(kept, sv, 1.0), 0.0)
    return np.einsum("nji,nj->ni", vt, y)


def _balanced(mech: Mechanism, slot_list: list[Any], placed: dict[str, Any]) -> Mechanism:
    changed = {s.point_mass: placed[s.point_mass][0] for s in slot_list if isinstance(s, MassSlot)}
    kept = tuple(replace(p, mass=changed[p.name]) if p.name in changed else p for p in mech.point_masses)
    added = tuple(PointMass(s.name, s.body, placed[s.name][0], (placed[s.name][1], placed[s.name][2]))
                  for s in slot_list if isinstance(s, CounterweightSlot))
    return replace(mech, point_masses=kept + added)


def _solve_alone(mech: Mechanism, slot_list: list[Any], phi: np.ndarray, speed: Any, i: int,
                 result: dict[str, Any]) -> bool:
    """Design ``i`` by the single-design function (a bound reached), its figures written into ``result``;
    False where that function refuses it."""
    s = speed if np.ndim(speed) == 0 else float(np.ravel(speed)[i])
    try:
        alone = least_squares_counterweights(mech.take_designs(i), slot_list, phi, s)
    except (AnalysisError, InputError):
        return False
    for key in (*BALANCE_KEYS, "peak_moment", "rms_torque"):
        result["after"][key][i] = getattr(alone.after, key)
    result["after"]["com_travel"][i] = alone.after.com_spread
    for p in alone.counterweights:
        mass, px, py = result["placed"][p.name]
        mass[i], px[i], py[i] = p.mass, p.position[0], p.position[1]
    return True


def balance_population(problem: Any, forces: Any) -> dict[str, np.ndarray] | None:
    """The ``[balance]`` results of N linkage designs at once from their kinetostatics (the capability's population
    form): the closed-form counterweights (``method = "counterweights"`` without ``[balance.objective]`` or
    ``[[balance.states]]``); None for the other methods, whose designs are run one by one. Each design at its own
    crank speed (the population's), over the table's ``positions``."""
    table = problem.balance
    if table.method != "counterweights" or table.objective is not None or table.states:
        return None
    mech = forces.mechanism
    speed = _column(forces.kinematics.speed)
    try:
        METHODS[table.method].fits(mech.take_designs(0) if mech.design_count else mech, table, 1.0)
    except InputError:
        return None  # the file's check reports it; the runs say so design by design
    phi = cycle(table.positions)
    n = mech.design_count or 1
    per = max(1, CHUNK_POSITIONS // phi.size)
    parts = []
    for start in range(0, n, per):  # chunks of designs: the memory stays bounded for any population
        part = slice(start, min(n, start + per))
        sub = mech.take_designs(part) if mech.design_count else mech
        parts.append(_balance_keys(sub, slots(table), phi, speed if np.ndim(speed) == 0 else speed[part]))
    # a crank at rest has no shaking force to balance: the single design refuses it (speed must be > 0)
    moving = np.broadcast_to(np.ravel(np.asarray(speed, dtype=float)) > 0, (n,))
    return {k: np.where(moving, np.concatenate([p[k] for p in parts]), np.nan) for k in parts[0]}


def _balance_keys(mech: Mechanism, slot_list: list[Any], phi: np.ndarray, speed: Any) -> dict[str, np.ndarray]:
    """The ``[balance]`` results by key of the designs of ``mech`` (NaN for a design that is not valid)."""
    done = least_squares_population(mech, slot_list, phi, speed)
    valid = done["valid"]
    before, after = done["before"], done["after"]
    out: dict[str, np.ndarray] = {}
    for key in BALANCE_KEYS:
        out[f"balance.{key}_before"] = before[key]
        out[f"balance.{key}_after"] = after[key]
    out["balance.com_travel_after"] = after["com_travel"]
    b, a = before["rms_force"], after["rms_force"]
    with np.errstate(invalid="ignore", divide="ignore"):
        change = np.where(b == 0.0, np.where(a == 0.0, 0.0, np.inf), (a - b) / np.where(b == 0.0, 1.0, b))
    out["balance.force_reduction"] = -change
    for name, (mass, px, py) in done["placed"].items():  # a free mass keeps its [[counterweights]] name
        out[f"balance.{name}.mass"] = mass
        out[f"balance.{name}.x"], out[f"balance.{name}.y"] = px, py
    return {k: np.where(valid, np.broadcast_to(v, valid.shape), np.nan) for k, v in out.items()}
