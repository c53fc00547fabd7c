"""Design sweeps: full kinetostatics of many design variants x crank positions, chunked so that memory stays
bounded for any number of designs, reduced to per-design summaries."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from .engines import use_fused
from .fused import run
from .fused_source import SUMMARY_FIELDS
from .kinematics import kinematics
from .kinetostatics import kinetostatics
from .model import Mechanism
from .motion import singular
from .reductions import mean_over_time, peak_abs, rms_over_time

#: Positions (designs x crank angles) evaluated per chunk: large enough to amortise NumPy's per-call cost,
#: small enough that the ~100 float64 arrays alive at once stay near 100 MB.
DEFAULT_CHUNK_POSITIONS = 1 << 17


@dataclass(frozen=True)
class SweepResult:
    """Per-design summaries over the crank angles of a sweep (arrays of length N designs).

    ``assembled`` is False for designs that cannot close at some crank angle; ``regular`` is False for those
    and for designs that pass a dead (toggle) position; the summaries of designs that are not regular are NaN.
    Mean power and RMS torque are averages over time (see :mod:`machdyn.linkage.averages`).
    """

    assembled: np.ndarray
    regular: np.ndarray
    max_driving_torque: np.ndarray
    rms_driving_torque: np.ndarray
    mean_input_power: np.ndarray
    max_joint_force: dict
    max_shaking_force: np.ndarray
    max_shaking_moment: np.ndarray
    positions: int


def sweep(
    mech: Mechanism,
    crank_angle,
    speed=1.0,
    acceleration=0.0,
    *,
    shaking_about=(0.0, 0.0),
    chunk_positions: int = DEFAULT_CHUNK_POSITIONS,
    progress: Callable[[int, int], None] | None = None,
    engine: str = "auto",
) -> SweepResult:
    """Full kinetostatics of every design variant of ``mech`` at every crank angle, summarised per design.

    The designs are processed in chunks of about ``chunk_positions`` positions, so peak memory does not grow
    with the number of designs. ``progress(done, total)`` is called after each chunk.

    ``engine``: "numpy" (the reference: whole-array operations per chunk), "fused" (kinematics,
    kinetostatics and summaries in one compiled pass per position, :mod:`machdyn.linkage.fused`; memory
    independent of the number of crank angles) or "auto" (fused when numba is present and the sweep has at
    least :data:`~machdyn.linkage.engines.AUTO_MIN_POSITIONS` positions). Both give the same summaries to
    rounding.
    """
    phi = np.asarray(crank_angle, dtype=float)
    if phi.ndim != 1:
        raise InputError(f"The sweep needs a 1-D array of crank angles; got shape {phi.shape}.")
    n = _design_count(mech, phi, speed, acceleration)
    if mech.design_count is None and n > 1:
        # Variants that differ only in their drive: one speed (and acceleration) per design, as columns.
        speed, acceleration = (_as_column(v, phi, n) for v in (speed, acceleration))
    per_chunk = max(1, int(chunk_positions) // max(phi.size, 1))
    if use_fused(engine, mech, phi, n * phi.size):
        return _fused_sweep(mech, phi, speed, acceleration, n, shaking_about, per_chunk, progress)
    out = None
    for start in range(0, n, per_chunk):
        stop = min(n, start + per_chunk)
        part_of = slice(start, stop)
        sub = mech.take_designs(part_of) if mech.design_count else mech
        with np.errstate(all="ignore"):
            kin = kinematics(
                sub, phi, _per_design(speed, phi, n, part_of), _per_design(acceleration, phi, n, part_of),
                on_fail="mask",
            )
            forces = kinetostatics(sub, kinematics_result=kin)
            part = _summaries(forces, shaking_about)
        if out is None:
            out = {k: _alloc(v, n) for k, v in part.items()}
        for k, v in part.items():
            if isinstance(v, dict):
                for j, arr in v.items():
                    out[k][j][start:stop] = arr
            else:
                out[k][start:stop] = v
        if progress is not None:
            progress(stop, n)
    assert out is not None  # n >= 1 designs: at least one chunk
    return SweepResult(positions=n * phi.size, **out)


def _fused_sweep(mech, phi, speed, acceleration, n, about, per_chunk, progress) -> SweepResult:
    result = run(mech, phi, speed, acceleration, designs=n, about=about, forces=True, progress=progress,
                 chunk_designs=per_chunk)
    out = result.summary
    columns = {name: out[:, k] for k, name in enumerate(SUMMARY_FIELDS)}
    joints = {name: out[:, len(SUMMARY_FIELDS) + j] for j, name in enumerate(result.generated.joints)}
    return SweepResult(
        assembled=columns.pop("assembled") > 0.5,
        regular=columns.pop("regular") > 0.5,
        max_joint_force=joints,
        positions=n * phi.size,
        **columns,
    )


def _design_count(mech: Mechanism, phi, speed, acceleration) -> int:
    """N designs: from the mechanism's arrays, or from a speed/acceleration given per design."""
    if mech.design_count is not None:
        return mech.design_count
    sizes = {np.size(v) for v in (speed, acceleration) if np.ndim(v) == 1 and np.shape(v) != phi.shape}
    if len(sizes) > 1:
        raise InputError(f"Speed and acceleration per design must have the same length; got {sorted(sizes)}.")
    return sizes.pop() if sizes else 1


def _as_column(value, phi, n):
    arr = np.asarray(value, dtype=float)
    if arr.ndim == 1 and arr.shape != phi.shape and arr.size == n:
        return arr[:, None]
    return value


def _per_design(value, phi, n, part):
    """The chunk's share of a speed or acceleration given per design (an (N,) array not shaped like phi)."""
    arr = np.asarray(value, dtype=float)
    if arr.ndim == 1 and arr.shape != phi.shape and arr.size == n:
        return arr[part]
    if arr.ndim == 2 and arr.shape[0] == n:
        return arr[part]
    return value


def _alloc(v, n):
    if isinstance(v, dict):
        return {k: np.empty(n) for k in v}
    return np.empty(n, dtype=np.asarray(v).dtype)


def _summaries(forces, about) -> dict:
    kin = forces.kinematics
    assembled = np.atleast_2d(kin.assembled).all(axis=-1)
    # A design that passes a dead position has unbounded results there: its summaries are NaN too.
    regular = ~np.atleast_2d(singular(kin.dyad_reports, kin.shape)).any(axis=-1)
    torque = np.atleast_2d(forces.driving_torque)
    ok = assembled & regular & np.isfinite(torque).all(axis=-1)
    bad = np.where(ok, 0.0, np.nan)

    def peak(values):  # the largest magnitude, NaN ignored
        return peak_abs(np.atleast_2d(values)) + bad

    return {
        "assembled": assembled,
        "regular": ok,
        "max_driving_torque": peak(torque),
        "rms_driving_torque": np.atleast_1d(rms_over_time(np.where(np.isfinite(torque), torque, 0.0), kin)) + bad,
        "mean_input_power": np.atleast_1d(
            mean_over_time(np.where(np.isfinite(torque), np.atleast_2d(forces.input_power), 0.0), kin)) + bad,
        "max_joint_force": {name: peak(r.magnitude) for name, r in forces.reactions.items()},
        "max_shaking_force": peak(forces.shaking_force),
        "max_shaking_moment": peak(forces.shaking_moment(about)),
    }
