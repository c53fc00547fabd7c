"""The reductions of a series over the crank positions of each design, written once.

A result of a linkage is a series (the driving torque, a joint's force, a transmission angle, for one design
over the crank positions, or for N designs x M positions) and one of the reductions below, taken along the last
axis. The run's results (:mod:`machdyn.results.linkage`), the engine's design sweep (:mod:`.sweep`), the
population evaluator (:mod:`machdyn.results.population`) and the compiled kernels (:mod:`.fused_reduce`, which
compiles :func:`worst_of` with numba, and the force summaries of :mod:`.fused_source`, which call the streaming
forms :data:`STREAMS` compiled from this module) all reduce through this module; the catalogue of results names
each reduction by its key in :data:`REDUCTIONS`.

Positions where a design does not assemble are NaN and are left out of the extremes; a design with no value
at any position gives NaN (not numpy's warning). Means and RMS are over time, not crank angle
(:mod:`.averages`: they differ when the crank speed varies).
"""

from __future__ import annotations

import hashlib
import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
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


# ------------------------------------------------------------------------ the same reductions, one position at a time


def _keep_larger(acc: float, value: float, weight: float) -> float:
    return value if value > acc else acc  # a NaN value never wins, as numpy.nanmax leaves it out


def _keep_larger_magnitude(acc: float, value: float, weight: float) -> float:
    size = abs(value)
    return size if size > acc else acc


def _add_weighted(acc: float, value: float, weight: float) -> float:
    return acc + value * weight


def _add_weighted_square(acc: float, value: float, weight: float) -> float:
    return acc + value * value * weight


def _as_is(acc: float, total: float) -> float:
    return acc


def _weighted_mean(acc: float, total: float) -> float:
    return acc / total if total > 0.0 else math.nan


def _weighted_rms(acc: float, total: float) -> float:
    return math.sqrt(acc / total) if total > 0.0 else math.nan


def _root(acc: float, total: float) -> float:
    return math.sqrt(acc)


@dataclass(frozen=True)
class Stream:
    """A reduction taken one crank position at a time, for a compiled kernel that never holds the series:
    ``start`` the accumulator before the first position, ``step(acc, value, weight)`` it after one more
    position whose ``value`` stands for ``weight`` of the time (:func:`.averages.time_weights` up to a common
    factor), ``finish(acc, total)`` the result from the accumulator and the sum of the weights. Plain float
    arithmetic: the population kernels compile these very functions with numba (:func:`compiled_streams`), and
    a test holds each to its array form of :data:`REDUCTIONS` to 1e-12."""

    start: float
    step: Callable[[float, float, float], float]
    finish: Callable[[float, float], float]


#: The reductions of :data:`REDUCTIONS` the compiled population kernels take, one position at a time, by the
#: same names; "max_magnitude" is "max" of a vector series' magnitude fed as its square (one square root per
#: design instead of one per position: the root is monotonic, so the largest square's root is the largest
#: magnitude).
STREAMS: dict[str, Stream] = {
    "max": Stream(-math.inf, _keep_larger, _as_is),
    "max_abs": Stream(0.0, _keep_larger_magnitude, _as_is),
    "time_mean": Stream(0.0, _add_weighted, _weighted_mean),
    "time_rms": Stream(0.0, _add_weighted_square, _weighted_rms),
    "max_magnitude": Stream(0.0, _keep_larger, _root),
}


def streamed(values: Any, how: str, weights: Any) -> float:
    """One series ``values`` reduced by the stream ``how`` of :data:`STREAMS` in plain Python, position by
    position with the time ``weights`` of each (what a compiled kernel does for one design)."""
    stream = STREAMS[how]
    acc, total = stream.start, 0.0
    for value, weight in zip(np.asarray(values, dtype=float).tolist(), np.asarray(weights, dtype=float).tolist(),
                             strict=True):
        acc = stream.step(acc, value, weight)
        total += weight
    return stream.finish(acc, total)


def compiled_streams() -> dict[str, Any]:
    """The functions of :data:`STREAMS` compiled by numba, inlined into the kernels that call them, under the
    names the generated code calls them by (``RS_<name>`` steps, ``RF_<name>`` finishes). numba is imported
    here only."""
    import numba

    jit = numba.njit(inline="always", error_model="numpy", nogil=True)
    out: dict[str, Any] = {}
    for name, stream in STREAMS.items():
        out[f"RS_{name}"] = jit(stream.step)
        out[f"RF_{name}"] = jit(stream.finish)
    return out


def streams_version() -> str:
    """A hash of this module's text: a compiled kernel that inlined the streams is valid for this text only."""
    return hashlib.sha1(Path(__file__).read_bytes()).hexdigest()[:16]


def reduce(values: Any, how: str, kin: Any = None) -> np.ndarray:
    """``values`` reduced along the last axis by the reduction ``how`` (a key of :data:`REDUCTIONS`)."""
    function = REDUCTIONS[how].function
    if function is None:
        raise ValueError(f"The reduction '{how}' is not a reduction of a series over the positions.")
    return function(values, kin)
