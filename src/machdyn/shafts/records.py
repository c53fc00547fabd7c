"""1x readings (amplitude and phase) from measured records with a once-per-revolution reference channel.

A record is a CSV file: a time column, a reference channel carrying one pulse per revolution (a keyphasor, an
optical tachometer's TTL signal) and the vibration channels, each header ``name [unit]`` (``time [s]``,
``key [V]``, ``drive_end [mm/s]``). The pulses are the rising crossings of the reference signal through the
middle of its range, located between samples by linear interpolation. Between pulses the shaft angle is taken to
grow linearly (constant speed within a revolution), and over the whole revolutions between the first and last
pulse each channel's 1x component is

    C = (2 / N) sum x_j exp(-i phi_j)   ->   x ~ A cos(phi - psi),  A = |C|,  psi = -arg C

(the discrete Fourier coefficient at the shaft frequency, order tracking by resampling on the shaft angle;
Brandt, *Noise and Vibration Analysis*, Wiley, 2011, sec. 12.3). psi is the **phase lag**: the angle the shaft turns
from the reference pulse to the positive peak of the 1x vibration, as balancing instruments show it. A pulse
with a steep edge is located to within half a sample, so the phase is uncertain by w / (2 f_s) [rad] (0.36 deg
for 1485 rpm sampled at 2048 Hz).

The reference must be a pulse channel, never a vibration channel: a vibration's own zero crossings come once per
revolution too, so its 1x phase would read as a plausible but wrong phase lag (every reading turned by that
channel's own phase, the corrections with them). A channel is refused as a reference when it is one of the
sensors read, when its unit is a vibration quantity (a length, a velocity or an acceleration), or when it is not
a two-level pulse train: a keyphasor or a tachometer's TTL output spends almost all its time at its two levels,
while a sinusoidal vibration spends 41 % of its time between 20 % and 80 % of its range (2 asin(0.6)/pi); a
reference with more than :data:`MAX_TRANSITION_SHARE` of its samples there is refused.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import InputError
from ..units import ureg
from ..vibration.signals import csv_failure
from .field import Reading

__all__ = ["RunRecord", "read_run", "pulses", "one_x"]

MAX_BYTES = 50_000_000
#: Largest share of a reference channel's samples between 20 % and 80 % of its range (module docstring).
MAX_TRANSITION_SHARE = 0.2
_HEADER = re.compile(r"^\s*(?P<name>[^\[]+?)\s*\[(?P<unit>[^\]]*)\]\s*$")
_TIME = {"s": 1.0, "ms": 1e-3}


@dataclass(frozen=True)
class RunRecord:
    """The 1x readings of one run: ``readings`` by sensor, the mean ``speed`` [rad/s] over the whole
    revolutions used, their number and the speed's spread (max - min) / mean over them."""

    source: str
    readings: tuple[Reading, ...]
    speed: float
    revolutions: int
    spread: float


def pulses(t: np.ndarray, reference: np.ndarray, what: str = "the reference channel") -> np.ndarray:
    """Times [s] of the rising crossings of ``reference`` through the middle of its range."""
    lo, hi = float(np.min(reference)), float(np.max(reference))
    if not hi > lo:
        raise InputError(f"{what} is flat: it carries no once-per-revolution pulse (a phase reference is needed "
                         "for influence-coefficient balancing).")
    level = 0.5 * (lo + hi)
    above = reference >= level
    k = np.flatnonzero(~above[:-1] & above[1:])
    frac = (level - reference[k]) / (reference[k + 1] - reference[k])
    return t[k] + frac * (t[k + 1] - t[k])


def check_reference(reference: np.ndarray, name: str, unit: str, sensors: tuple[str, ...], source: str) -> None:
    """Refuse a ``reference`` channel that is not a once-per-revolution pulse channel (module docstring)."""
    why = ("a phase reference must be a keyphasor or tachometer channel (a once-per-revolution pulse); name that "
           "channel in field_records.reference")
    if name in sensors:
        raise InputError(f"The reference channel '{name}' of {source} is also read as a vibration sensor: {why}.")
    if _is_vibration_unit(unit):
        raise InputError(f"The reference channel '{name}' of {source} is in {unit}, a vibration unit: {why}.")
    lo, hi = float(np.min(reference)), float(np.max(reference))
    if hi > lo:
        u = (reference - lo) / (hi - lo)
        share = float(np.mean((u > 0.2) & (u < 0.8)))
        if share > MAX_TRANSITION_SHARE:
            raise InputError(f"The reference channel '{name}' of {source} is not a pulse train: {share:.0%} of its "
                             f"samples lie between 20 % and 80 % of its range (a keyphasor's or tachometer's "
                             f"pulses: under {MAX_TRANSITION_SHARE:.0%}; a vibration signal: about 40 %); {why}.")


def _is_vibration_unit(unit: str) -> bool:
    """Whether ``unit`` measures a displacement, a velocity or an acceleration."""
    try:
        dim = ureg.Quantity(1.0, unit).dimensionality
    except Exception:  # noqa: BLE001 - an unknown unit (e.g. "TTL") is no vibration unit
        return False
    return dim in ({"[length]": 1}, {"[length]": 1, "[time]": -1}, {"[length]": 1, "[time]": -2})


def one_x(t: np.ndarray, x: np.ndarray, pulse_times: np.ndarray) -> Reading:
    """The 1x reading of ``x`` over the whole revolutions between the first and last pulse (module docstring)."""
    inside = (t >= pulse_times[0]) & (t < pulse_times[-1])
    angle = np.interp(t[inside], pulse_times, 2 * np.pi * np.arange(pulse_times.size))
    c = 2.0 * np.mean(x[inside] * np.exp(-1j * angle))
    return Reading(float(abs(c)), float(-np.angle(c) % (2 * np.pi)))


def read_run(path: str | Path, reference: str, sensors: tuple[str, ...], max_bytes: int = MAX_BYTES) -> RunRecord:
    """Read a run's record and return its 1x readings at ``sensors`` (channel names) against the pulses of the
    channel ``reference``. At least two whole revolutions are needed."""
    import pandas as pd

    p = Path(path)
    if not p.is_file():
        raise InputError(f"The record file {p} does not exist.")
    if p.stat().st_size > max_bytes:
        raise InputError(f"The record file {p} is larger than {max_bytes / 1e6:.0f} MB.")
    try:
        frame = pd.read_csv(p, comment="#", skipinitialspace=True, encoding="utf-8-sig")
    except (ValueError, pd.errors.ParserError, UnicodeDecodeError) as exc:
        raise InputError(f"The record file {p} is not a readable CSV: {csv_failure(exc)}.") from None
    names = {}
    for j, column in enumerate(frame.columns):
        m = _HEADER.match(str(column))
        if not m:
            raise InputError(f"Column {j + 1} of {p} has no unit in its header, so the file is not a record: write "
                             "the header as 'name [unit]', e.g. 'time [s]' or 'keyphasor [V]'.")
        names[m["name"].strip()] = (j, m["unit"].strip())
    first = str(frame.columns[0])
    tname = _HEADER.match(first)
    if tname is None or tname["unit"].strip() not in _TIME:
        raise InputError(f"The first column of {p} must be the time in s or ms (a header such as 'time [s]').")
    try:
        values = frame.to_numpy(dtype=float)
    except ValueError:
        raise InputError(f"The record file {p} holds text where numbers are expected.") from None
    if not np.all(np.isfinite(values)):
        raise InputError(f"The record file {p} holds NaN or empty samples; clean or cut the record first.")
    t = values[:, 0] * _TIME[tname["unit"].strip()]
    if t.size < 8 or np.any(np.diff(t) <= 0):
        raise InputError(f"The time column of {p} must increase strictly over at least 8 samples.")
    for name in (reference, *sensors):
        if name not in names:
            raise InputError(f"The record file {p} has no channel '{name}' (named in the problem file); its header "
                             f"names {len(names) - 1} channel(s) after the time, which are not quoted here: check the "
                             "spelling against the file's first line.")
    check_reference(values[:, names[reference][0]], reference, names[reference][1], sensors, str(p))
    times = pulses(t, values[:, names[reference][0]], f"The reference channel '{reference}' of {p}")
    if times.size < 3:
        raise InputError(f"The reference channel '{reference}' of {p} holds {times.size} once-per-revolution "
                         "pulse(s); at least 3 (two whole revolutions) are needed for a phase reading.")
    periods = np.diff(times)
    spread = float((periods.max() - periods.min()) / periods.mean())
    if spread > 0.05:
        raise InputError(f"The shaft speed in {p} is not steady: its revolutions last from {periods.min():.4g} s "
                         f"to {periods.max():.4g} s; field balancing needs a steady speed (within 5 %).")
    readings = tuple(one_x(t, values[:, names[s][0]], times) for s in sensors)
    speed = float(2 * np.pi * (times.size - 1) / (times[-1] - times[0]))
    return RunRecord(str(p), readings, speed, int(times.size - 1), spread)
