"""One set of balancing masses for several operating states (strokes, phases, speeds) at once.

Each state is a model of the same machine (same bodies and point masses, other geometry or speed). The shaking
force of every state is linear in the shared counterweight unknowns (:func:`~machdyn.balancing.general.
force_model`), so minimising the weighted sum of the states' mean square shaking forces is one stacked linear
least-squares problem, solved with bounds by :func:`scipy.optimize.lsq_linear`; minimising the worst state is
the small convex problem min t subject to ms_s(x) <= t, solved by :func:`scipy.optimize.minimize` (SLSQP) from
the weighted-sum solution. The residual of each state is reported next to its value before.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field, replace

import numpy as np

from ..errors import InputError, check_positive
from ..linkage import Mechanism
from .frame import FrameLoads, cycle, frame_loads
from .general import (
    CounterweightSlot,
    LinearForceModel,
    Slot,
    _decode,
    _point_masses,
    force_model,
    reference_point,
    solve_bounded,
    unknown_bounds,
)

__all__ = ["OperatingState", "StateRow", "RobustResult", "robust_counterweights"]


@dataclass(frozen=True)
class OperatingState:
    """An operating state: a ``name``, its ``mechanism``, crank ``speed`` [rad/s], ``weight`` [-] in the sum and
    ``crank_turn`` [rad]: how far the crank's frame of this state is turned against the shaft on which the
    shared counterweights of the crank sit (e.g. an eccentric sleeve turned to change the stroke moves the
    crank pin, not the shaft's counterweight)."""

    name: str
    mechanism: Mechanism
    speed: float = 1.0
    weight: float = 1.0
    crank_turn: float = 0.0


@dataclass(frozen=True)
class StateRow:
    """Shaking force of one state before and after [N]: RMS and peak, and the RMS reduction [-]."""

    state: str
    rms_before: float
    rms_after: float
    peak_before: float
    peak_after: float

    @property
    def reduction(self) -> float:
        return 1.0 - self.rms_after / self.rms_before if self.rms_before > 0 else 0.0


@dataclass(frozen=True)
class RobustResult:
    """The shared balancing masses: ``values`` {unknown name: value} (masses [kg], first moments [kg*m]), the
    balanced ``models`` per state, ``rows`` per state, the frame loads ``before``/``after`` per state, the
    ``mode`` ('sum' or 'worst'), ``notes`` and ``placed``: {counterweight or point-mass name: (mass [kg],
    body-frame position [m] or None)}, positions of crank counterweights in the shaft's frame."""

    values: dict
    models: tuple[Mechanism, ...]
    rows: tuple[StateRow, ...]
    before: tuple[FrameLoads, ...]
    after: tuple[FrameLoads, ...]
    mode: str
    notes: tuple[str, ...]
    placed: dict = field(default_factory=dict)

    @property
    def worst_after(self) -> float:
        return max(r.rms_after for r in self.rows)

    @property
    def mean_reduction(self) -> float:
        return float(np.mean([r.reduction for r in self.rows]))


def robust_counterweights(states: Sequence[OperatingState], slots: Sequence[Slot], mode: str = "sum",
                          crank_angle=None) -> RobustResult:
    """Balancing masses shared by all ``states`` minimising the weighted sum (``mode='sum'``) or the largest
    (``mode='worst'``) mean square shaking force over a cycle (default 120 crank angles).

    Slots as in :mod:`machdyn.balancing.general`; counterweights on pivoted bodies need a ``radius``.
    """
    if mode not in ("sum", "worst"):
        raise InputError(f"The robust balancing mode must be 'sum' or 'worst'; got {mode!r}.")
    if not states:
        raise InputError("robust_counterweights needs at least one operating state; got none.")
    if not slots:
        raise InputError("robust_counterweights needs at least one slot; got none.")
    for s in states:
        check_positive(f"speed of state '{s.name}'", s.speed, "rad/s")
        check_positive(f"weight of state '{s.name}'", s.weight, allow_zero=True)
    for slot in slots:
        if isinstance(slot, CounterweightSlot):
            reference_point(states[0].mechanism, slot)
    phi = cycle(120) if crank_angle is None else np.asarray(crank_angle, dtype=float)
    before = tuple(frame_loads(s.mechanism, phi, s.speed) for s in states)
    models = [_turned(force_model(s.mechanism, slots, phi, s.speed, b), slots, s)
              for s, b in zip(states, before, strict=True)]
    lo, hi = unknown_bounds(slots, models[0].columns)
    n = phi.size
    scale = np.array([np.sqrt(s.weight / n) for s in states])
    A = np.concatenate([w * lm.matrix for w, lm in zip(scale, models, strict=True)])
    b = np.concatenate([-w * lm.f0 for w, lm in zip(scale, models, strict=True)])
    x, how = solve_bounded(A, b, lo, hi)
    notes = [f"weighted sum over the states: {how}"]
    if mode == "worst":
        x, note = _minimax(models, x, lo, hi, n)
        notes.append(note)
    values = _decode(states[0].mechanism, slots, models[0], x)
    balanced = tuple(_point_masses(s.mechanism, slots, _turn_values(values, slots, s)) for s in states)
    after = tuple(frame_loads(m, phi, s.speed) for m, s in zip(balanced, states, strict=True))
    rows = tuple(StateRow(s.name, bf.rms_force, af.rms_force, bf.peak_force, af.peak_force)
                 for s, bf, af in zip(states, before, after, strict=True))
    named = dict(zip(models[0].unknowns, (float(v) for v in x), strict=True))
    placed = {
        (slot.name if isinstance(slot, CounterweightSlot) else slot.point_mass):
            (float(m), None if pos is None else (float(pos[0]), float(pos[1])))
        for slot, (m, pos) in ((slots[i], v) for i, v in values.items())
    }
    return RobustResult(named, balanced, rows, before, after, mode, tuple(notes), placed)


def _minimax(models, x_sum: np.ndarray, lo: np.ndarray, hi: np.ndarray, n: int) -> tuple[np.ndarray, str]:
    """min t subject to ms_s(x) <= t for every state (SLSQP with exact gradients), in variables scaled by the
    weighted-sum solution and constraints scaled by its worst mean square; falls back to ``x_sum`` if the
    optimiser ends worse than its start."""
    from scipy.optimize import minimize

    s = np.maximum(np.abs(x_sum), 1e-3 * max(float(np.max(np.abs(x_sum))), 1e-12))

    def ms(x, lm):
        r = lm.f0 + lm.matrix @ x
        return float(r @ r) / n

    ref = max(ms(x_sum, lm) for lm in models) or 1.0

    def constraint(lm):
        def fun(z):
            return z[-1] - ms(z[:-1] * s, lm) / ref

        def jac(z):
            r = lm.f0 + lm.matrix @ (z[:-1] * s)
            return np.append(-2.0 * (lm.matrix.T @ r) * s / n / ref, 1.0)

        return {"type": "ineq", "fun": fun, "jac": jac}

    start = np.append(x_sum / s, 1.0)
    bounds = [(a / k if np.isfinite(a) else None, b / k if np.isfinite(b) else None)
              for a, b, k in zip(lo, hi, s, strict=True)] + [(0.0, None)]
    objective_grad = np.append(np.zeros(x_sum.size), 1.0)
    res = minimize(lambda z: z[-1], start, jac=lambda z: objective_grad, method="SLSQP", bounds=bounds,
                   constraints=[constraint(lm) for lm in models], options={"maxiter": 500, "ftol": 1e-12})
    status = "converged" if res.success else f"did not converge ({res.message})"
    x = res.x[:-1] * s
    if max(ms(x, lm) for lm in models) > ref:
        return x_sum, f"worst-state SLSQP {status} after {res.nit} iterations; no improvement, weighted-sum kept"
    return x, f"worst-state SLSQP {status} after {res.nit} iterations"


def _on_crank(slot: Slot, state: OperatingState) -> bool:
    return isinstance(slot, CounterweightSlot) and slot.body == state.mechanism.crank.body


def _turned(lm: LinearForceModel, slots: Sequence[Slot], state: OperatingState) -> LinearForceModel:
    """The force model in the shaft's frame: a crank counterweight at (mu, mv) on the shaft sits at
    R(-turn) (mu, mv) in the state's crank frame."""
    if state.crank_turn == 0.0:
        return lm
    c, s = np.cos(state.crank_turn), np.sin(state.crank_turn)
    matrix = lm.matrix.copy()
    for i, slot in enumerate(slots):
        if not _on_crank(slot, state):
            continue
        ju = lm.columns.index((i, "mu"))
        jv = lm.columns.index((i, "mv"))
        cu, cv = lm.matrix[:, ju], lm.matrix[:, jv]
        matrix[:, ju], matrix[:, jv] = c * cu - s * cv, s * cu + c * cv
    return replace(lm, matrix=matrix)


def _turn_values(values: dict, slots: Sequence[Slot], state: OperatingState) -> dict:
    """Counterweight positions of the shaft frame in the state's crank frame (turned by -crank_turn about the
    slot's reference point)."""
    if state.crank_turn == 0.0:
        return values
    c, s = np.cos(state.crank_turn), np.sin(state.crank_turn)
    out = dict(values)
    for i, slot in enumerate(slots):
        if isinstance(slot, CounterweightSlot) and _on_crank(slot, state):
            mass, pos = values[i]
            ref, _ = reference_point(state.mechanism, slot)
            d = np.asarray(pos) - ref
            out[i] = (mass, ref + np.array([c * d[0] + s * d[1], -s * d[0] + c * d[1]]))
    return out
