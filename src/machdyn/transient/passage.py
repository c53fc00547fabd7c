"""What a run says about resonance: the amplitude against the crank speed, each passage through a mode of the
frame (its peak amplitude, peak mount force and the time spent near the mode), and whether the drive passed the
resonance or was captured by it (the Sommerfeld effect: Kononenko, *Vibrating Systems with a Limited Power
Supply*, Iliffe 1969, ch. 1 and 2).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .run import Transient

__all__ = ["AmplitudeCurve", "Passage", "amplitude_curve", "capture", "passages"]


@dataclass(frozen=True)
class AmplitudeCurve:
    """Amplitude against speed: per turn of the first crank, its mean speed [rad/s], the time at the middle of
    the turn [s], the largest displacement [m] of the point from its rest position in the turn (along the
    direction, or of the vector) and the largest mount force [N]."""

    speed: np.ndarray
    time: np.ndarray
    amplitude: np.ndarray
    mount_force: np.ndarray


@dataclass(frozen=True)
class Passage:
    """One passage of the first crank's speed through a natural frequency of the frame.

    mode : 1-based number of the mode; frequency [rad/s]; direction "up" or "down"; time [s] the speed crosses
    the frequency; peak_amplitude [m] and peak_mount_force [N] while the speed is within twice the band of the
    frequency, and at least 1.5 sqrt(pi / alpha) after the crossing (alpha the rate of the speed there: a fast
    passage peaks after the speed has left the band); time_in_band [s] while it is within the band (a relative
    ``band`` of the frequency); speed_at_peak [rad/s]; completed False if the run ended inside the band (still in
    resonance at its end).
    """

    mode: int
    frequency: float
    direction: str
    time: float
    peak_amplitude: float
    peak_mount_force: float
    time_in_band: float
    speed_at_peak: float
    completed: bool


def _along(run: Transient, point, direction) -> np.ndarray:
    u = run.point_displacement(point)
    if direction is None:  # the length of the displacement (two components on a planar frame, three in space)
        return np.sqrt(np.sum(u * u, axis=0))
    return np.abs(math.cos(direction) * u[0] + math.sin(direction) * u[1])


def amplitude_curve(run: Transient, point=(0.0, 0.0), direction: float | None = None) -> AmplitudeCurve:
    """The amplitude at frame ``point`` (x, y) [m] along ``direction`` [rad] (None: the vector's length) per turn
    of the first crank, against that turn's mean speed."""
    amp = _along(run, point, direction)
    force = np.max(np.abs(run.mount_force), axis=0) if run.mount_force.size else np.zeros_like(run.t)
    turns = np.floor(np.abs(run.phi[0] - run.phi[0, 0]) / (2.0 * math.pi)).astype(int)
    edges = np.flatnonzero(np.diff(turns)) + 1
    bounds = np.concatenate([[0], edges])
    speed, when, a_out, f_out = [], [], [], []
    for lo, hi in zip(bounds[:-1], bounds[1:], strict=True):
        dt = run.t[hi] - run.t[lo]
        if dt <= 0:
            continue
        speed.append(abs(run.phi[0, hi] - run.phi[0, lo]) / dt)
        when.append(0.5 * (run.t[lo] + run.t[hi]))
        a_out.append(float(amp[lo:hi + 1].max()))
        f_out.append(float(force[lo:hi + 1].max()))
    return AmplitudeCurve(np.array(speed), np.array(when), np.array(a_out), np.array(f_out))


def passages(run: Transient, frequencies, point=(0.0, 0.0), direction: float | None = None,
             band: float = 0.1) -> list[Passage]:
    """Every passage of the first crank's speed through the angular ``frequencies`` [rad/s] (the frame's
    modes), in time order (see :class:`Passage`)."""
    w = np.abs(run.omega[0])
    t = run.t
    amp = _along(run, point, direction)
    force = np.max(np.abs(run.mount_force), axis=0) if run.mount_force.size else np.zeros_like(t)
    found: list[Passage] = []
    for j, wn in enumerate(np.atleast_1d(frequencies), start=1):
        wn = float(wn)
        if not wn > 0:
            continue
        above = w >= wn
        crossings = np.flatnonzero(above[1:] != above[:-1])
        # one passage per entry into the wide band: crossings inside one stay in the band are one passage
        wide = np.abs(w / wn - 1.0) <= 2.0 * band
        narrow = np.abs(w / wn - 1.0) <= band
        used = np.zeros(t.size, dtype=bool)
        for c in crossings:
            if used[c]:
                continue
            lo, hi = int(c), int(c) + 1
            while lo > 0 and wide[lo - 1]:
                lo -= 1
            while hi < t.size - 1 and wide[hi + 1]:
                hi += 1
            # a fast passage peaks after the speed has left the band: undamped, 1.217 sqrt(pi / alpha) after the
            # crossing at the sweep rate alpha (Lewis 1932, the Cornu spiral's farthest point); look that far
            rate = abs(w[c + 1] - w[c]) / max(t[c + 1] - t[c], 1e-300)
            if rate > 0:
                reach = t[c] + 1.5 * math.sqrt(math.pi / rate)
                hi = max(hi, min(int(np.searchsorted(t, reach)), t.size - 1))
            used[lo:hi + 1] = True
            inside = slice(lo, hi + 1)
            k = lo + int(np.argmax(amp[inside]))
            in_band = narrow[inside]
            dt = np.diff(t[inside])
            spent = float(np.sum(dt * (in_band[1:] & in_band[:-1])))
            found.append(Passage(j, wn, "up" if w[c + 1] > w[c] else "down", float(t[c]), float(amp[k]),
                                 float(force[inside].max()), spent, float(w[k]),
                                 bool(hi < t.size - 1 or not wide[-1])))
    return sorted(found, key=lambda p: p.time)


def capture(run: Transient, frequencies, free_speed: float, band: float = 0.1) -> tuple[bool, float]:
    """(captured, final speed [rad/s]): the drive is captured if, with the motors on at the end of the run, the
    first crank's mean speed over its last turn stays within twice ``band`` below a natural frequency although
    the drive alone would turn it at ``free_speed`` [rad/s] (its speed on a rigid frame), more than twice
    ``band`` above it."""
    turns = np.abs(run.phi[0] - run.phi[0, -1]) <= 2.0 * math.pi
    first = int(np.argmax(turns))
    dt = run.t[-1] - run.t[first]
    final = abs(float(run.phi[0, -1] - run.phi[0, first])) / dt if dt > 0 else abs(float(run.omega[0, -1]))
    captured = False
    for wn in np.atleast_1d(frequencies):
        if free_speed > wn * (1.0 + 2.0 * band) and wn * (1.0 - 2.0 * band) <= final <= wn * (1.0 + band):
            captured = True
    return captured, final
