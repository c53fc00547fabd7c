"""The reductions of a series over the crank positions of each design, written once.

A result of a linkage is a series (the driving torque, a joint's force, a transmission angle, for one design
over the crank positions, or for N designs x M positions) and one of the reductions below, taken along the last
axis. The run's results (:mod:`machdyn.results.linkage`), the engine's design sweep (:mod:`.sweep`), the
population evaluator (:mod:`machdyn.results.population`) and the compiled population kernels (:mod:`.fused_reduce`,
which compiles :func:`worst_of` with numba) all reduce through this module; the catalogue of results names each
reduction by its key in :data:`REDUCTIONS`.

Positions where a design does not assemble are NaN and are left out of the extremes; a design with no value
at any position gives NaN (not numpy's warning). Means and RMS are over time, not crank angle
(:mod:`.averages`: they differ when the crank speed varies).
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from .averages import time_mean, time_rms
from .harmonics import harmonics


def _quiet(func: Callable[..., Any]) -> Callable[..., Any]:
    def reduce(*args: Any, **kw: Any) -> Any:
        with np.errstate(all="ignore"), warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)  # an all-NaN design stays NaN
            return func(*args, **kw)

    reduce.__name__, reduce.__doc__ = func.__name__, func.__doc__
    return reduce


@_quiet
def peak(values: Any, kin: Any = None) -> np.ndarray:
    """The largest value along the last axis (NaN ignored)."""
    return np.nanmax(np.asarray(values, dtype=float), axis=-1)


@_quiet
def least(values: Any, kin: Any = None) -> np.ndarray:
    """The smallest value along the last axis (NaN ignored)."""
    return np.nanmin(np.asarray(values, dtype=float), axis=-1)


@_quiet
def peak_abs(values: Any, kin: Any = None) -> np.ndarray:
    """The largest magnitude along the last axis (NaN ignored)."""
    return np.nanmax(np.abs(np.asarray(values, dtype=float)), axis=-1)


@_quiet
def spread(values: Any, kin: Any = None) -> np.ndarray:
    """The largest minus the smallest value along the last axis (NaN ignored)."""
    arr = np.asarray(values, dtype=float)
    return np.nanmax(arr, axis=-1) - np.nanmin(arr, axis=-1)


@_quiet
def mean_over_angle(values: Any, kin: Any = None) -> np.ndarray:
    """The mean of the samples along the last axis, each crank position alike (NaN ignored)."""
    return np.nanmean(np.asarray(values, dtype=float), axis=-1)


@_quiet
def mean_over_time(values: Any, kin: Any) -> np.ndarray:
    """The mean over time of the kinematics ``kin`` (:func:`.averages.time_mean`)."""
    return np.asarray(time_mean(values, kin), dtype=float)


@_quiet
def rms_over_time(values: Any, kin: Any) -> np.ndarray:
    """The root mean square over time of the kinematics ``kin`` (:func:`.averages.time_rms`)."""
    return np.asarray(time_rms(values, kin), dtype=float)


def worst_of(smallest: Any, largest: Any) -> Any:
    """The worst transmission angle [rad], the one nearest 0 or pi, of a dyad whose angle spans [``smallest``,
    ``largest``] [rad] (Norton, *Design of Machinery*, 5th ed., §4.10: the forces grow as 1/sin mu, alike at
    mu and pi - mu). Plain ufuncs: floats, arrays, and scalars inside a numba kernel alike."""
    return np.minimum(smallest, np.pi - largest)


@_quiet
def worst_angle(values: Any, kin: Any = None) -> np.ndarray:
    """The worst transmission angle [rad] along the last axis: :func:`worst_of` its smallest and largest."""
    arr = np.asarray(values, dtype=float)
    return worst_of(np.nanmin(arr, axis=-1), np.nanmax(arr, axis=-1))


def at_angle(values: Any, phi: Any, angle: float) -> np.ndarray:
    """The value at crank angle ``angle`` [rad], linear between the samples at ``phi`` [rad] (one turn, periodic)."""
    arr = np.asarray(values, dtype=float)
    p = np.asarray(phi, dtype=float).ravel()
    order = np.argsort(np.mod(p, 2 * math.pi))
    grid = np.mod(p, 2 * math.pi)[order]
    where = float(np.mod(angle, 2 * math.pi))
    rows = arr.reshape(-1, arr.shape[-1])[:, order]
    out = np.array([np.interp(where, grid, r, period=2 * math.pi) for r in rows])
    return out.reshape(arr.shape[:-1])


def harmonic(values: Any, phi: Any, order: int) -> tuple[np.ndarray, np.ndarray]:
    """(amplitude [unit of values], phase [rad]) of harmonic ``order`` of a series over one even turn
    (:func:`.harmonics.harmonics`)."""
    h = harmonics(values, phi, orders=order)
    return np.asarray(h.amplitude)[..., order - 1], np.asarray(h.phase)[..., order - 1]


@dataclass(frozen=True)
class Reduction:
    """A reduction of a series over the crank positions: its ``text`` and the function of (values, kinematics)
    that computes it (None for the figures a capability computes itself: a cycle's figure, a count)."""

    text: str
    function: Callable[[Any, Any], np.ndarray] | None = None
    #: The extreme it takes ("max" of the series, "min", "max_abs"), which :mod:`.extremes` refines.
    extreme: str = ""


#: The reductions by the name the catalogue of results gives them.
REDUCTIONS: dict[str, Reduction] = {
    "max": Reduction("largest value", peak, "max"),
    "min": Reduction("smallest value", least, "min"),
    "max_abs": Reduction("largest magnitude", peak_abs, "max_abs"),
    "angle_mean": Reduction("mean over the crank angle", mean_over_angle),
    "time_mean": Reduction("mean over time", mean_over_time),
    "time_rms": Reduction("root mean square over time", rms_over_time),
    "range": Reduction("largest minus smallest value", spread),
    "worst": Reduction("nearest 0 or 180 deg (transmission angle)", worst_angle),
    "at_position": Reduction("value at a crank angle"),
    "harmonic_amplitude": Reduction("amplitude of the n-th harmonic over one turn"),
    "harmonic_phase": Reduction("phase of the n-th harmonic over one turn"),
    "cycle": Reduction("a figure of the whole cycle"),
    "count": Reduction("a count over the cycle"),
    "scalar": Reduction("a single figure per design, not a series over the positions"),
}


def reduce(values: Any, how: str, kin: Any = None) -> np.ndarray:
    """``values`` reduced along the last axis by the reduction ``how`` (a key of :data:`REDUCTIONS`)."""
    function = REDUCTIONS[how].function
    if function is None:
        raise ValueError(f"The reduction '{how}' is not a reduction of a series over the positions.")
    return function(values, kin)
