"""Counterweights on any bodies of any linkage: force-optimal by linear least squares, or a weighted
objective of shaking force, shaking moment, driving torque and joint force with bounds on mass and radius.

A counterweight of mass m at the body-frame point P = R + (u, v) of a body (R a reference point of the body)
adds -m a_P = -(m a_R + (m u) a_x + (m v) a_y) to the shaking force, where a_x, a_y are the accelerations of
the body's unit vectors (a_x = a_{R + (1, 0)} - a_R). The shaking force is therefore *linear* in the unknowns
(m, m u, m v) - and in (m u, m v) alone where R is a fixed pivot (a_R = 0) - so the force-optimal counterweights
over a whole cycle solve a linear least-squares problem in closed form (Berkof & Lowen, "A new method for
completely force balancing simple linkages", ASME J. Eng. Ind. 91(1), 1969, 21-26, for the idea that the
shaking force is a linear combination of the link motions; the least-squares form is the standard normal
equation of that linear map). The moment, the driving torque and the joint forces are not linear in the
counterweights (the counterweight's own inertia and position enter squared), so the weighted objective is a
small bounded nonlinear problem solved with :func:`scipy.optimize.minimize` from the least-squares start.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np

from ..errors import AnalysisError, InputError, check_finite, check_positive
from ..linkage import Mechanism, PointMass, kinematics
from ..linkage.model import GROUND, split_ref
from .frame import BalanceResult, FrameLoads, compare, cycle, frame_loads

__all__ = [
    "CounterweightSlot",
    "MassSlot",
    "LinearForceModel",
    "force_model",
    "least_squares_counterweights",
    "Weights",
    "optimise_counterweights",
    "pivot_point",
]


@dataclass(frozen=True)
class CounterweightSlot:
    """Where a counterweight may go: on ``body``, about the body point ``about`` (a point name; default the
    body's ground pivot if it has one, else its frame origin), at ``radius`` [m] from it for the closed-form
    solution (needed on pivoted bodies, where the force fixes only m*radius), within ``mass_bounds`` [kg] and
    ``radius_bounds`` [m] for the bounded optimisation."""

    body: str
    radius: float | None = None
    about: str | None = None
    mass_bounds: tuple[float, float] = (0.0, np.inf)
    radius_bounds: tuple[float, float] = (0.0, np.inf)

    @property
    def name(self) -> str:
        return f"cw_{self.body}"


@dataclass(frozen=True)
class MassSlot:
    """An existing point mass of the model whose mass (not position) is a design variable, within
    ``mass_bounds`` [kg] (e.g. the eccentric sleeves of the double tamper)."""

    point_mass: str
    mass_bounds: tuple[float, float] = (0.0, np.inf)


Slot = CounterweightSlot | MassSlot


def pivot_point(mech: Mechanism, body: str) -> str | None:
    """The name of the point of ``body`` that sits on a ground pivot (the crank's, or a dyad link's pinned
    to the ground), or None."""
    if body == mech.crank.body:
        return split_ref(mech.crank.pivot)[1]
    for d in mech.dyads:
        for link, pin in ((d.a, getattr(d, "pin_a", None)), (d.b, getattr(d, "pin_b", None))):
            if link == body and pin is not None and split_ref(pin)[0] == GROUND:
                return split_ref(pin)[1]
    return None


def reference_point(mech: Mechanism, slot: CounterweightSlot) -> tuple[np.ndarray, bool]:
    """(the point [m, body frame] a slot's counterweight is placed about, whether that point is the body's pivot
    on the frame): the slot's ``about`` point, else the pivot, else the body's origin; InputError for a point the
    body lacks."""
    body = mech.body(slot.body)
    name = slot.about or pivot_point(mech, slot.body)
    if name is None:
        return np.zeros(2), False
    if name not in body.points:
        raise InputError(f"The counterweight slot on '{slot.body}' refers to point '{name}', which the body lacks; "
                         f"its points: {', '.join(body.points)}.")
    return np.asarray(body.points[name], dtype=float), name == pivot_point(mech, slot.body)


@dataclass(frozen=True)
class LinearForceModel:
    """The shaking force as F(x) = F0 + A x over the crank angles: ``f0`` (2M,) stacks Fx then Fy [N] of the
    model as it is (without the point masses of :class:`MassSlot` slots, whose whole mass is an unknown),
    ``matrix`` (2M, n) the force per unit of each unknown, ``unknowns`` names them."""

    f0: np.ndarray
    matrix: np.ndarray
    unknowns: tuple[str, ...]
    columns: tuple[tuple[int, str], ...]  # (slot index, 'm' | 'mu' | 'mv')


def force_model(mech: Mechanism, slots: Sequence[Slot], crank_angle, speed: float = 1.0,
                base: FrameLoads | None = None) -> LinearForceModel:
    """The linear map from counterweight unknowns to shaking force (see the module docstring)."""
    phi = np.asarray(crank_angle, dtype=float)
    kin = kinematics(replace(mech, gravity=(0.0, 0.0)), phi, speed, 0.0)
    base = base or frame_loads(mech, phi, speed)
    cols, names, index = [], [], []
    f0 = np.concatenate([base.fx, base.fy])
    for i, slot in enumerate(slots):
        if isinstance(slot, MassSlot):
            pm = next((p for p in mech.point_masses if p.name == slot.point_mass), None)
            if pm is None:
                raise InputError(f"No point mass '{slot.point_mass}' in mechanism '{mech.name}'; point masses: "
                                 f"{', '.join(p.name for p in mech.point_masses) or 'none'}.")
            P = kin.local_point(pm.body, pm.position)
            cols.append(np.concatenate([-np.broadcast_to(P.ax, phi.shape), -np.broadcast_to(P.ay, phi.shape)]))
            f0 = f0 - float(pm.mass) * cols[-1]  # the unknown is the whole mass, not a change of it
            names.append(f"{pm.name}.mass")
            index.append((i, "m"))
            continue
        ref, fixed = reference_point(mech, slot)
        R = kin.local_point(slot.body, tuple(ref))
        X = kin.local_point(slot.body, tuple(ref + (1.0, 0.0)))
        Y = kin.local_point(slot.body, tuple(ref + (0.0, 1.0)))
        parts = [("mu", X.ax - R.ax, X.ay - R.ay), ("mv", Y.ax - R.ax, Y.ay - R.ay)]
        if not fixed:
            parts.insert(0, ("m", R.ax, R.ay))
        for key, ax, ay in parts:
            cols.append(np.concatenate([-np.broadcast_to(ax, phi.shape), -np.broadcast_to(ay, phi.shape)]))
            names.append(f"{slot.name}.{key}")
            index.append((i, key))
    matrix = np.stack(cols, axis=1) if cols else np.zeros((2 * phi.size, 0))
    return LinearForceModel(f0, matrix, tuple(names), tuple(index))


def _point_masses(mech: Mechanism, slots: Sequence[Slot], values: dict) -> Mechanism:
    """``mech`` with the counterweights / changed masses ``values`` = {slot index: (mass, position or None)}."""
    changed = {slots[i].point_mass: v[0] for i, v in values.items() if isinstance(slots[i], MassSlot)}
    kept = tuple(replace(p, mass=changed[p.name]) if p.name in changed else p for p in mech.point_masses)
    added = tuple(
        PointMass(slots[i].name, slots[i].body, float(m), (float(pos[0]), float(pos[1])))
        for i, (m, pos) in values.items() if isinstance(slots[i], CounterweightSlot)
    )
    return replace(mech, point_masses=kept + added)


def least_squares_counterweights(mech: Mechanism, slots: Sequence[Slot], crank_angle=None,
                                 speed: float = 1.0) -> BalanceResult:
    """Counterweights that minimise the mean square shaking force over ``crank_angle`` (default one turn):
    the linear least-squares solution - closed form (:func:`numpy.linalg.lstsq`, minimum norm where the
    counterweights are not all independent) when no mass bound is reached, else the bounded linear least
    squares of :func:`scipy.optimize.lsq_linear` (masses of :class:`MassSlot` and of floating counterweights
    within their ``mass_bounds``).

    On a pivoted body the force fixes only the first moment m (u, v): the slot's ``radius`` then sets the mass.
    On a floating body the force fixes m and m (u, v); an optimum at zero mass with a non-zero first moment
    cannot be built and raises :class:`~machdyn.errors.AnalysisError` (use :func:`optimise_counterweights`).
    """
    if not slots:
        raise InputError("least_squares_counterweights needs at least one slot; got none.")
    phi = cycle() if crank_angle is None else np.asarray(crank_angle, dtype=float)
    before = frame_loads(mech, phi, speed)
    lin = force_model(mech, slots, phi, speed, before)
    lo, hi = unknown_bounds(slots, lin.columns)
    x, _ = solve_bounded(lin.matrix, -lin.f0, lo, hi)
    values = _decode(mech, slots, lin, x)
    balanced = _point_masses(mech, slots, values)
    after = frame_loads(balanced, phi, speed)
    added = tuple(p for p in balanced.point_masses if p not in mech.point_masses)
    return BalanceResult(balanced, before, after, compare(before, after), added,
                         ("closed-form least squares of the shaking force",))


def unknown_bounds(slots: Sequence[Slot], columns) -> tuple[np.ndarray, np.ndarray]:
    """Lower and upper bounds of the linear unknowns: masses within their slot's ``mass_bounds``, first
    moments free."""
    lo, hi = [], []
    for i, key in columns:
        slot = slots[i]
        if key == "m":
            lo.append(slot.mass_bounds[0])
            hi.append(slot.mass_bounds[1])
        else:
            lo.append(-np.inf)
            hi.append(np.inf)
    return np.array(lo, dtype=float), np.array(hi, dtype=float)


def solve_bounded(matrix: np.ndarray, rhs: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> tuple[np.ndarray, str]:
    """min |A x - b| within lo <= x <= hi: the closed form if it lies within the bounds, else
    :func:`scipy.optimize.lsq_linear` on unit-norm columns; values a rounding error off a bound are put on it.
    Returns (x, how it was solved)."""
    x, *_ = np.linalg.lstsq(matrix, rhs, rcond=None)
    if np.all((x >= lo) & (x <= hi)):
        return x, "closed-form least squares"
    from scipy.optimize import lsq_linear

    scale = np.linalg.norm(matrix, axis=0)
    scale = np.where(scale > 0, scale, 1.0)
    fit = lsq_linear(matrix / scale, rhs, bounds=(lo * scale, hi * scale))
    tol = 1e-9 * max(float(np.max(np.abs(fit.x))), 1e-300)
    y = np.where(np.abs(fit.x - lo * scale) <= tol, lo * scale, fit.x)
    y = np.where(np.abs(y - hi * scale) <= tol, hi * scale, y)
    return y / scale, f"bounded least squares ({fit.message})"


def _decode(mech: Mechanism, slots: Sequence[Slot], lin: LinearForceModel, x: np.ndarray) -> dict:
    per: dict[int, dict[str, float]] = {}
    for (i, key), value in zip(lin.columns, x, strict=True):
        per.setdefault(i, {})[key] = float(value)
    values: dict[int, tuple[float, np.ndarray | None]] = {}
    for i, slot in enumerate(slots):
        v = per.get(i, {})
        if isinstance(slot, MassSlot):
            values[i] = (v["m"], None)
            continue
        ref, fixed = reference_point(mech, slot)
        first = np.array([v["mu"], v["mv"]])
        if fixed:
            if slot.radius is None:
                raise InputError(f"The counterweight slot on pivoted body '{slot.body}' needs a radius for the "
                                 "closed-form solution (the force fixes only mass x radius).")
            check_positive(f"radius of the counterweight on '{slot.body}'", slot.radius, "m")
            size = float(np.hypot(*first))
            mass = size / slot.radius
            pos = ref + (first / size * slot.radius if size > 0 else np.zeros(2))
        else:
            mass = v["m"]
            if mass <= 0:
                raise AnalysisError(f"The force-optimal counterweight on floating body '{slot.body}' has mass "
                                    f"{mass:.4g} kg with first moment {first.tolist()} kg*m: it cannot be built; "
                                    "use the bounded optimisation (optimise_counterweights, [balance.objective]).")
            pos = ref + first / mass
        values[i] = (mass, pos)
    return values


@dataclass(frozen=True)
class Weights:
    """Weights of the balancing objective; each term is divided by its value before balancing. ``measure``
    is 'rms' or 'peak'. Terms: shaking force, shaking moment, driving torque (RMS or peak), peak joint force."""

    force: float = 1.0
    moment: float = 0.0
    torque: float = 0.0
    joint: float = 0.0
    measure: str = "rms"


def _terms(loads: FrameLoads, measure: str) -> np.ndarray:
    if measure == "rms":
        return np.array([loads.rms_force, loads.rms_moment, loads.rms_torque, loads.peak_joint_force])
    return np.array([loads.peak_force, loads.peak_moment, np.max(np.abs(loads.torque)), loads.peak_joint_force])


def optimise_counterweights(mech: Mechanism, slots: Sequence[Slot], weights: Weights = Weights(), crank_angle=None,
                            speed: float = 1.0, *, max_iterations: int = 200) -> BalanceResult:
    """Counterweights (mass, radius, angle per :class:`CounterweightSlot`; mass per :class:`MassSlot`) that
    minimise sum_k w_k q_k(after) / q_k(before) for the terms of :class:`Weights`, within the slots' bounds,
    by :func:`scipy.optimize.minimize` (L-BFGS-B) started from the projected least-squares solution.

    The optimiser's outcome is in ``notes``; if it did not converge the note says so (the best point found is
    still returned and evaluated).
    """
    from scipy.optimize import minimize

    if not slots:
        raise InputError("optimise_counterweights needs at least one slot; got none.")
    if weights.measure not in ("rms", "peak"):
        raise InputError(f"The objective measure must be 'rms' or 'peak'; got {weights.measure!r}.")
    w = np.array([weights.force, weights.moment, weights.torque, weights.joint], dtype=float)
    check_finite("objective weights", w)
    if np.any(w < 0) or not np.any(w > 0):
        raise InputError(f"The objective weights must be >= 0 with at least one > 0; got {w.tolist()}.")
    phi = cycle(72) if crank_angle is None else np.asarray(crank_angle, dtype=float)
    before = frame_loads(mech, phi, speed)
    scale = _terms(before, weights.measure)
    scale = np.where(scale > 0, scale, 1.0)
    bounds: list[tuple[float | None, float | None]] = []
    refs: list[np.ndarray | None] = []
    for slot in slots:
        _check_bounds(slot)
        if isinstance(slot, MassSlot):
            bounds.append(slot.mass_bounds)
            refs.append(None)
        else:
            refs.append(reference_point(mech, slot)[0])
            bounds += [slot.mass_bounds, slot.radius_bounds, (None, None)]  # the angle wraps: no bound
    start = _start(mech, slots, phi, speed, before, bounds)

    def model_of(z):
        values, k = {}, 0
        for i, slot in enumerate(slots):
            if isinstance(slot, MassSlot):
                values[i] = (z[k], None)
                k += 1
            else:
                m, rho, ang = z[k:k + 3]
                values[i] = (m, refs[i] + rho * np.array([np.cos(ang), np.sin(ang)]))
                k += 3
        return _point_masses(mech, slots, values)

    def objective(z):
        return float(w @ (_terms(frame_loads(model_of(z), phi, speed), weights.measure) / scale))

    res = minimize(objective, start, method="L-BFGS-B", bounds=bounds, options={"maxiter": max_iterations})
    balanced = model_of(res.x)
    after = frame_loads(balanced, phi, speed)
    added = tuple(p for p in balanced.point_masses if p not in mech.point_masses)
    status = "converged" if res.success else f"did not converge ({res.message})"
    note = f"L-BFGS-B {status} after {res.nit} iterations; objective {res.fun:.6g} (1 = unbalanced)"
    return BalanceResult(balanced, before, after, compare(before, after), added, (note,))


def _check_bounds(slot: Slot) -> None:
    pairs = [("mass_bounds", slot.mass_bounds, "kg")]
    if isinstance(slot, CounterweightSlot):
        pairs.append(("radius_bounds", slot.radius_bounds, "m"))
    for label, (lo, hi), unit in pairs:
        if not (lo >= 0 and hi >= lo):
            raise InputError(f"The {label} of slot '{getattr(slot, 'body', getattr(slot, 'point_mass', '?'))}' must "
                             f"satisfy 0 <= low <= high; got ({lo}, {hi}) {unit}.")


def _start(mech, slots, phi, speed, before, bounds) -> np.ndarray:
    """The least-squares solution in (mass, radius, angle) form, projected into the bounds."""
    lin = force_model(mech, slots, phi, speed, before)
    x, *_ = np.linalg.lstsq(lin.matrix, -lin.f0, rcond=None)
    per: dict[int, dict[str, float]] = {}
    for (i, key), value in zip(lin.columns, x, strict=True):
        per.setdefault(i, {})[key] = float(value)
    z: list[float] = []
    for i, slot in enumerate(slots):
        v = per.get(i, {})
        if isinstance(slot, MassSlot):
            z.append(v["m"])
            continue
        first = np.array([v["mu"], v["mv"]])
        size = float(np.hypot(*first))
        lo, hi = slot.radius_bounds
        rho = slot.radius if slot.radius is not None else (min(max(0.1, lo), hi) if np.isfinite(hi) else max(0.1, lo))
        mass = v.get("m", size / rho if rho > 0 else 0.0)
        if "m" in v and mass > 0:
            rho = size / mass
        z += [mass, rho, float(np.arctan2(first[1], first[0]))]
    lower = np.array([-np.inf if b[0] is None else b[0] for b in bounds], dtype=float)
    upper = np.array([np.inf if b[1] is None else b[1] for b in bounds], dtype=float)
    return np.clip(np.array(z, dtype=float), lower, upper)
