"""Field balancing by influence coefficients for N sets of readings at once (N rotors, or one rotor's readings
drawn N times within their scatter): NumPy arrays, sets on the leading axis.

The same method as :func:`machdyn.shafts.field.two_plane`: with the original readings V0 (n sensors) and one trial
run per plane, the influence coefficients a_ij = (V_i(trial j) - V_i(before it)) / W_j and the corrections
W = -a^-1 V0, less any trial mass left on (Thomson & Dahleh, *Theory of Vibration with Applications*, 5th ed., sec.
3.3-3.4; Rao, *Mechanical Vibrations*, 5th ed., sec. 9.2-9.3), solved for every set in one stacked
:func:`numpy.linalg.solve`. A set the single-design function refuses is flagged (``valid`` False, NaN results): a
trial run that changes no reading by 30 % in amplitude or 30 deg in phase, an influence matrix whose column-scaled
condition number exceeds 20 (:data:`machdyn.shafts.field.MAX_CONDITION`), a trial mass not > 0, a non-finite
value.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .field import MAX_CONDITION, TRIAL_AMPLITUDE_CHANGE, TRIAL_PHASE_CHANGE

__all__ = ["field_balance_population"]

TWO_PI = 2.0 * np.pi


def _changed(before: np.ndarray, after: np.ndarray) -> np.ndarray:
    """(N,) whether a trial run moved some reading enough (:func:`machdyn.shafts.field.trial_change` against the
    30 % / 30 deg rule): a reading of zero amplitude that moves counts as an infinite change."""
    size_b, size_a = np.abs(before), np.abs(after)
    with np.errstate(divide="ignore", invalid="ignore"):
        amp = np.where(size_b == 0.0, np.where(size_a > 0, np.inf, 0.0), np.abs(size_a / size_b - 1.0))
    turn = np.arctan2(after.imag, after.real) - np.arctan2(before.imag, before.real)
    phase = np.abs(np.remainder(turn + np.pi, TWO_PI) - np.pi)  # |math.remainder(turn, 2 pi)|
    phase = np.where((size_b > 0) & (size_a > 0), phase, 0.0)
    return (np.max(amp, axis=-1) >= TRIAL_AMPLITUDE_CHANGE) | (np.max(phase, axis=-1) >= TRIAL_PHASE_CHANGE)


def field_balance_population(original: Any, trial_readings: Any, trial_mass: Any, trial_angle: Any,
                             removed: Any = True) -> dict[str, np.ndarray]:
    """The corrections of N field balances in n planes from n sensors.

    Parameters
    ----------
    original : (N, n) complex readings of the original run (amplitude e^{i phase lag}).
    trial_readings : (N, n, n) complex readings, [set, trial run (its plane, in the order run), sensor].
    trial_mass [kg] > 0, trial_angle [rad] : (N, n) or (n,), the trial masses of the runs.
    removed : (n,) bools, whether each trial mass was taken off before the next run.

    Returns
    -------
    dict: ``mass`` (N, n) [kg at the trial radius], ``angle`` (N, n) [rad, 0 ... 2 pi], ``coefficients``
    (N, n, n) and ``valid`` (N,).
    """
    v0 = np.atleast_2d(np.asarray(original, dtype=complex))
    runs = np.asarray(trial_readings, dtype=complex).reshape(v0.shape[0], v0.shape[1], v0.shape[1])
    n_sets, n = v0.shape
    mass = np.broadcast_to(np.asarray(trial_mass, dtype=float), (n_sets, n))
    angle = np.broadcast_to(np.asarray(trial_angle, dtype=float), (n_sets, n))
    off = np.broadcast_to(np.asarray(removed, dtype=bool), (n,))
    weight = mass * np.exp(1j * angle)
    valid = np.all(np.isfinite(v0), axis=1) & np.all(np.isfinite(runs), axis=(1, 2))
    valid &= np.all((mass > 0) & np.isfinite(angle), axis=1)
    a = np.zeros((n_sets, n, n), dtype=complex)
    kept = np.zeros((n_sets, n), dtype=complex)
    baseline = v0
    for k in range(n):  # the runs in the order given: a trial mass left on starts the next run
        vt = runs[:, k]
        valid &= _changed(baseline, vt)
        with np.errstate(divide="ignore", invalid="ignore"):
            a[:, :, k] = (vt - baseline) / weight[:, k, None]
        if not off[k]:
            kept[:, k] += weight[:, k]
            baseline = vt
    safe = np.where(valid[:, None, None], a, np.eye(n))
    if n > 1:
        norms = np.linalg.norm(safe, axis=1)
        sv = np.linalg.svd(safe / np.maximum(norms, 1e-300)[:, None, :], compute_uv=False)
        with np.errstate(divide="ignore"):
            kappa = np.where(sv[:, -1] > 0, sv[:, 0] / sv[:, -1], np.inf)
        valid &= kappa <= MAX_CONDITION
        safe = np.where(valid[:, None, None], safe, np.eye(n))
    w = np.linalg.solve(safe, -np.where(valid[:, None], v0, 0.0)[..., None])[..., 0] - kept
    size = np.abs(w)
    where = np.where(size > 0, np.mod(np.arctan2(w.imag, w.real), TWO_PI), 0.0)
    nan = np.nan
    return {"mass": np.where(valid[:, None], size, nan), "angle": np.where(valid[:, None], where, nan),
            "coefficients": np.where(valid[:, None, None], a, nan), "valid": valid}
