"""Measured vibration records: reading, band limits, integration to velocity, RMS, peak, crest factor, spectra.

A record is a CSV file with a time column and one or more channels, the unit of each in its header,
``time [s],front [m/s^2],rear [mm/s]``. Channels in an acceleration unit (m/s^2, mm/s^2, g) are integrated to
velocity; channels in a velocity unit (m/s, mm/s, in/s) are used as they are. Everything is computed in SI.

The severity standards judge the RMS vibration velocity in a frequency band, 10...1000 Hz for most machines
(ISO 10816-1:1995 §3 and ISO 2954:2012, the instruments' band). Band limiting and integration are done in the
frequency domain: the discrete Fourier transform of the record, the lines outside the band set to zero (an
ideal band-pass filter) and each line of an acceleration divided by i omega (Brandt, *Noise and Vibration
Analysis*, Wiley, 2011, §3.4 and §9.3.5). For a stationary record of whole periods this is exact; otherwise
the band edges leak by about one frequency line.
"""

from __future__ import annotations

import errno
import math
import re
import stat
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import InputError
from .frame import STANDARD_GRAVITY
from .response import reduction_percent

__all__ = [
    "DEFAULT_BAND",
    "ChannelSummary",
    "Record",
    "RecordAnalysis",
    "analyse_record",
    "band_limit",
    "check_band",
    "compare_records",
    "crest_factor",
    "integrate_to_velocity",
    "order_spectrum",
    "peak",
    "read_record",
    "rms",
    "welch_spectrum",
]

#: The band [Hz] of ISO 10816-1 / ISO 2954 broad-band velocity measurements.
DEFAULT_BAND = (10.0, 1000.0)
#: The record must span at least this many periods of the band's lower edge.
MIN_PERIODS = 5
#: Largest record file read [bytes] and largest number of samples per channel.
MAX_BYTES = 200_000_000
MAX_SAMPLES = 20_000_000
#: Most columns of a record (the time and the channels).
MAX_COLUMNS = 65

_ACCELERATION_UNITS = {"m/s^2": 1.0, "m/s2": 1.0, "m/s**2": 1.0, "mm/s^2": 1e-3, "mm/s2": 1e-3,
                       "g": STANDARD_GRAVITY, "gn": STANDARD_GRAVITY, "g0": STANDARD_GRAVITY}
_VELOCITY_UNITS = {"m/s": 1.0, "mm/s": 1e-3, "cm/s": 1e-2, "in/s": 0.0254, "ips": 0.0254}
_TIME_UNITS = {"s": 1.0, "ms": 1e-3}
_HEADER = re.compile(r"^\s*(?P<name>[^\[\(]+?)\s*[\[\(]\s*(?P<unit>[^\]\)]+?)\s*[\]\)]\s*$")


def check_band(sampling_rate: float, samples: int, band=DEFAULT_BAND, *, what: str = "the signal") -> tuple:
    """Check that a record of ``samples`` samples at ``sampling_rate`` [Hz] can resolve ``band`` (low, high) [Hz].

    Rules: 0 <= low < high; the sampling rate at least twice the band's top (Nyquist-Shannon); the record at
    least ``MIN_PERIODS`` periods of the band's lower edge long, so that the lower edge lies on the fifth
    frequency line or above. Returns the band as floats.
    """
    try:
        low, high = (float(v) for v in band)
    except (TypeError, ValueError):
        raise InputError(f"The band must be two frequencies (low, high) in Hz; got {band!r}.") from None
    if not (math.isfinite(low) and math.isfinite(high) and 0 <= low < high):
        raise InputError(f"The band must satisfy 0 <= low < high (Hz); got ({low:g}, {high:g}) Hz.")
    if not (math.isfinite(sampling_rate) and sampling_rate > 0):
        raise InputError(f"The sampling rate of {what} must be > 0 Hz; got {sampling_rate:g} Hz.")
    if sampling_rate < 2 * high:
        raise InputError(f"The sampling rate of {what} must be at least twice the band's top "
                         f"(2 x {high:g} = {2 * high:g} Hz); got {sampling_rate:g} Hz. Lower the band's top or "
                         f"sample faster.")
    needed = MIN_PERIODS * sampling_rate / low if low > 0 else 16
    needed = max(16, math.ceil(needed - 1e-9))
    if samples < needed:
        raise InputError(f"{what[0].upper() + what[1:]} has too few samples for the band {low:g}-{high:g} Hz: "
                         f"{samples} samples ({samples / sampling_rate:.4g} s) at {sampling_rate:g} Hz; it needs "
                         f"at least {needed} ({MIN_PERIODS} periods of {low:g} Hz).")
    return low, high


def _check_signal(x, what: str) -> np.ndarray:
    a = np.asarray(x, dtype=float)
    if a.ndim != 1:
        raise InputError(f"The {what} must be a 1-D array of samples; got shape {a.shape}.")
    bad = np.flatnonzero(~np.isfinite(a))
    if bad.size:
        raise InputError(f"The {what} has {bad.size} NaN or infinite sample(s), the first at index {bad[0]}; "
                         f"clean or cut the record first.")
    return a


def _band_mask(n: int, sampling_rate: float, band) -> tuple[np.ndarray, np.ndarray]:
    f = np.fft.rfftfreq(n, 1.0 / sampling_rate)
    low, high = band
    return f, (f >= low) & (f <= high)


def band_limit(signal, sampling_rate, band=DEFAULT_BAND) -> np.ndarray:
    """The part of ``signal`` inside ``band`` (low, high) [Hz] (ideal band-pass in the frequency domain).

    ISO 10816-1:1995 §3 (broad-band measurement, typically 10...1000 Hz); Brandt (2011) §3.4.

    Parameters
    ----------
    signal : samples (any unit), 1-D, finite
    sampling_rate : f_s [Hz] >= 2 x the band's top
    band : (low, high) [Hz]

    Examples
    --------
    >>> fs = 4096.0
    >>> t = np.arange(4096) / fs
    >>> x = 3.0 + np.sin(2 * np.pi * 50 * t) + np.sin(2 * np.pi * 1500 * t)
    >>> round(float(rms(band_limit(x, fs, (10, 1000)))), 6)  # the offset and 1500 Hz are removed
    0.707107
    """
    x = _check_signal(signal, "signal")
    band = check_band(float(sampling_rate), x.size, band)
    spectrum = np.fft.rfft(x)
    _, keep = _band_mask(x.size, float(sampling_rate), band)
    return np.fft.irfft(np.where(keep, spectrum, 0.0), n=x.size)


def integrate_to_velocity(acceleration, sampling_rate, band=DEFAULT_BAND) -> np.ndarray:
    """Velocity [m/s] from an acceleration record [m/s^2], band-limited to ``band`` [Hz].

    In the frequency domain V(f) = A(f) / (i 2 pi f) on the lines inside the band, 0 outside (Brandt, *Noise
    and Vibration Analysis*, 2011, §9.3.5). The band's lower edge must be > 0 (integration of a constant is
    undefined). A sine a sin(2 pi f t) gives the velocity -a/(2 pi f) cos(2 pi f t), RMS a / (2 pi f sqrt 2).

    Parameters
    ----------
    acceleration : samples [m/s^2], 1-D, finite
    sampling_rate : f_s [Hz] >= 2 x the band's top
    band : (low, high) [Hz], low > 0

    Examples
    --------
    >>> fs = 2048.0
    >>> t = np.arange(2048) / fs
    >>> v = integrate_to_velocity(10.0 * np.sin(2 * np.pi * 80 * t), fs)
    >>> round(float(rms(v)) * 1e3, 6)  # mm/s: 10 / (2 pi 80 sqrt 2) m/s
    14.067442
    """
    a = _check_signal(acceleration, "acceleration record")
    low, high = check_band(float(sampling_rate), a.size, band, what="the acceleration record")
    if low <= 0:
        raise InputError(f"Integration to velocity needs a band with a lower edge > 0 Hz; got {low:g} Hz.")
    f, keep = _band_mask(a.size, float(sampling_rate), (low, high))
    spectrum = np.fft.rfft(a)
    omega = 2 * np.pi * np.where(keep, f, 1.0)
    return np.fft.irfft(np.where(keep, spectrum / (1j * omega), 0.0), n=a.size)


def rms(signal) -> float:
    """Root mean square sqrt(mean(x^2)) of the samples (ISO 2041:2009, 'root-mean-square value').

    Examples
    --------
    >>> rms([1.0, -1.0, 1.0, -1.0])
    1.0
    """
    x = _check_signal(signal, "signal")
    if x.size == 0:
        raise InputError("The RMS needs at least one sample; got none.")
    return float(np.sqrt(np.mean(x**2)))


def peak(signal) -> float:
    """Largest |x| of the samples (the 0-peak value; ISO 2041:2009).

    Examples
    --------
    >>> peak([0.5, -2.0, 1.0])
    2.0
    """
    x = _check_signal(signal, "signal")
    if x.size == 0:
        raise InputError("The peak needs at least one sample; got none.")
    return float(np.max(np.abs(x)))


def crest_factor(signal) -> float:
    """Peak over RMS [-] (sqrt 2 for a sine; ISO 2041:2009).

    Examples
    --------
    >>> t = np.arange(1000) / 1000
    >>> round(crest_factor(np.sin(2 * np.pi * 5 * t)), 4)
    1.4142
    """
    r = rms(signal)
    if r == 0:
        raise InputError("The crest factor of a signal that is zero everywhere is undefined.")
    return peak(signal) / r


def welch_spectrum(signal, sampling_rate, *, segment_seconds: float = 1.0):
    """Power spectral density [unit^2/Hz] by Welch's method (Hann window, 50 % overlap; ``scipy.signal.welch``).

    Welch, IEEE Trans. Audio Electroacoust. 15 (1967) 70-73. Segments of ``segment_seconds`` (at most the
    record). Returns (frequencies [Hz], psd). The integral of the psd over a band is the mean square in it.

    Examples
    --------
    >>> fs = 1000.0
    >>> t = np.arange(10_000) / fs
    >>> f, p = welch_spectrum(2.0 * np.sin(2 * np.pi * 100 * t), fs)
    >>> round(float(np.sum(p) * (f[1] - f[0])), 3)  # mean square of a sine of amplitude 2
    2.0
    """
    from scipy.signal import welch

    x = _check_signal(signal, "signal")
    fs = float(sampling_rate)
    if not fs > 0:
        raise InputError(f"The sampling rate must be > 0 Hz; got {fs:g} Hz.")
    nperseg = int(min(x.size, max(16, round(segment_seconds * fs))))
    if x.size < 16:
        raise InputError(f"A Welch spectrum needs at least 16 samples; got {x.size}.")
    return welch(x, fs=fs, window="hann", nperseg=nperseg, noverlap=nperseg // 2, detrend="constant")


def order_spectrum(signal, sampling_rate, crank_speed, *, max_order: float = 20.0):
    """RMS amplitude per spectral line against the order of the crank frequency (constant speed).

    Order = f / (Omega / 2 pi). The amplitude of each line is that of the DFT of the whole record with a flat-top
    window (amplitude-correct for lines between bins; Brandt 2011 §9.3.4), converted to RMS (amplitude /
    sqrt 2). Returns (orders [-], rms [unit]) up to ``max_order``.

    Parameters
    ----------
    signal : samples, 1-D
    sampling_rate : f_s [Hz]
    crank_speed : Omega [rad/s] > 0
    max_order : highest order returned

    Examples
    --------
    >>> fs = 1024.0
    >>> t = np.arange(4096) / fs
    >>> orders, amp = order_spectrum(3.0 * np.sin(2 * np.pi * 12.5 * t), fs, 2 * np.pi * 12.5)
    >>> i = int(np.argmax(amp))
    >>> round(float(orders[i]), 3), round(float(amp[i] * np.sqrt(2)), 3)
    (1.0, 3.0)
    """
    from scipy.signal import get_window

    x = _check_signal(signal, "signal")
    if not (np.isfinite(crank_speed) and crank_speed > 0):
        raise InputError(f"The crank speed of an order spectrum must be > 0 rad/s; got {crank_speed!r}.")
    if x.size < 16:
        raise InputError(f"An order spectrum needs at least 16 samples; got {x.size}.")
    w = get_window("flattop", x.size)
    spectrum = np.fft.rfft((x - x.mean()) * w)
    amplitude = 2.0 * np.abs(spectrum) / np.sum(w)
    f = np.fft.rfftfreq(x.size, 1.0 / float(sampling_rate))
    orders = f / (crank_speed / (2 * np.pi))
    keep = orders <= max_order
    return orders[keep], amplitude[keep] / np.sqrt(2.0)


# ---------------------------------------------------------------------------------------------- records


@dataclass(frozen=True)
class Record:
    """A measured record: ``time`` [s], ``channels`` {name: samples in SI}, ``quantities`` {name:
    "acceleration" or "velocity"}, ``sampling_rate`` [Hz] and the ``source`` file."""

    time: np.ndarray
    channels: dict
    quantities: dict
    sampling_rate: float
    source: str = ""

    @property
    def duration(self) -> float:
        return self.time.size / self.sampling_rate


def _unit_of(column: str, source: str, number: int) -> tuple[str, str, float]:
    """The channel name, quantity and scale to SI of column ``number`` (1-based) from its header text. A message
    names the file and the column's number, never the text: the file may not be a record at all (a ``.env``)."""
    match = _HEADER.match(column)
    if not match:
        raise InputError(f"Column {number} of {source} has no unit in its header, so the file is not a record: "
                         f"write the header as 'name [unit]', e.g. 'front [m/s^2]' or 'time [s]'.")
    name, unit = match["name"].strip(), match["unit"].strip()
    key = unit.replace(" ", "").lower().replace("²", "^2").replace("**", "^")
    if key in _ACCELERATION_UNITS:
        return name, "acceleration", _ACCELERATION_UNITS[key]
    if key in _VELOCITY_UNITS:
        return name, "velocity", _VELOCITY_UNITS[key]
    if key in _TIME_UNITS:
        return name, "time", _TIME_UNITS[key]
    known = ", ".join([*_ACCELERATION_UNITS, *_VELOCITY_UNITS])
    raise InputError(f"The unit in the header of column {number} of {source} is not a time, acceleration or "
                     f"velocity unit; use s or ms for the time and one of {known}.")


def _regular_file_size(p: Path) -> int:
    """The size of the regular file ``p`` [bytes]; a precise :class:`InputError` for anything else."""
    try:
        info = p.stat()
    except FileNotFoundError:
        raise InputError(f"The record file {p} does not exist.") from None
    except OSError as exc:
        if exc.errno == errno.ELOOP:
            raise InputError(f"The record file {p} is a loop of symbolic links.") from None
        raise InputError(f"The record file {p} cannot be read: {exc.strerror or exc}.") from None
    if stat.S_ISDIR(info.st_mode):
        raise InputError(f"The record file {p} is a folder, not a CSV file.")
    if not stat.S_ISREG(info.st_mode):
        raise InputError(f"The record file {p} is not a regular file (a FIFO, a socket or a device); "
                         f"give a CSV file.")
    return info.st_size


def _check_header(p: Path) -> None:
    """Refuse a header of more than :data:`MAX_COLUMNS` columns or with a repeated channel name before the file
    is parsed (a header of millions of columns would take minutes and gigabytes to read)."""
    try:
        with p.open("r", encoding="utf-8-sig", errors="replace") as handle:
            header = ""
            for _ in range(10_000):
                line = handle.readline(1_000_001)
                if not line:
                    break
                if not line.lstrip().startswith("#"):
                    header = line
                    break
    except OSError as exc:
        raise InputError(f"The record file {p} cannot be read: {exc.strerror or exc}.") from None
    if len(header) > 1_000_000 or header.count(",") + 1 > MAX_COLUMNS:
        raise InputError(f"The record file {p} has more than {MAX_COLUMNS} columns in its header; a record holds "
                         f"a time column and at most {MAX_COLUMNS - 1} channels.")
    names = [c.strip() for c in header.rstrip("\r\n").split(",")]
    for j, name in enumerate(names):
        if name and name in names[:j]:
            raise InputError(f"The channel names of {p} must be unique; column {j + 1} repeats column "
                             f"{names.index(name) + 1}.")


def csv_failure(exc: Exception) -> str:
    """Why pandas could not read a CSV file, without the file's text: the parser's own messages name line and
    field counts only; any other reason is given by its kind."""
    import pandas as pd

    if isinstance(exc, pd.errors.ParserError):
        return _quote(str(exc).strip().splitlines()[0] if str(exc).strip() else "a malformed line", 160)
    if isinstance(exc, UnicodeDecodeError):
        return f"it is not UTF-8 text (byte {exc.start})"
    if isinstance(exc, pd.errors.EmptyDataError):
        return "it is empty"
    return type(exc).__name__


def _quote(text: str, limit: int = 40) -> str:
    """A bounded excerpt of a file's text for a message."""
    return text if len(text) <= limit else text[: limit - 3] + "..."


#: The largest sample magnitude read [m/s^2 or m/s]: beyond it a record is corrupt or in the wrong unit, and its
#: squares overflow the RMS and the spectra.
MAX_SAMPLE = 1e12


def read_record(path, *, max_bytes: int = MAX_BYTES) -> Record:
    """Read a vibration record from a CSV file.

    The first column is the time (``time [s]`` or ``[ms]``), evenly spaced and increasing; each further column
    is a channel with its unit in the header (acceleration: m/s^2, mm/s^2, g; velocity: m/s, mm/s, cm/s, in/s).
    Lines starting with ``#`` are comments. The file may be at most ``max_bytes`` bytes.
    """
    import pandas as pd

    p = Path(path)
    size = _regular_file_size(p)
    if size > max_bytes:
        raise InputError(f"The record file {p} is {size / 1e6:.1f} MB; records are limited to "
                         f"{max_bytes / 1e6:.0f} MB. Cut it into shorter records.")
    _check_header(p)
    try:
        frame = pd.read_csv(p, comment="#", skipinitialspace=True, encoding="utf-8-sig")
    except (ValueError, pd.errors.ParserError, UnicodeDecodeError) as exc:
        raise InputError(f"The record file {p} is not a readable CSV: {csv_failure(exc)}.") from None
    if frame.shape[1] < 2:
        raise InputError(f"The record file {p} needs a time column and at least one channel; "
                         f"got {frame.shape[1]} column(s).")
    if len(frame) > MAX_SAMPLES:
        raise InputError(f"The record file {p} has {len(frame)} samples; at most {MAX_SAMPLES} are read.")
    columns = [_unit_of(str(c), str(p), j) for j, c in enumerate(frame.columns, start=1)]
    if columns[0][1] != "time":
        raise InputError(f"The first column of {p} must be the time in s or ms (a header such as 'time [s]'); its "
                         f"unit is an {columns[0][1]}'s.")
    try:
        values = frame.to_numpy(dtype=float)
    except ValueError:
        raise InputError(f"The record file {p} holds text where numbers are expected.") from None
    t = values[:, 0] * columns[0][2]
    if t.size < 2 or not np.all(np.isfinite(t)):
        raise InputError(f"The time column of {p} must hold at least two finite values.")
    dt = np.diff(t)
    repeated = np.flatnonzero(dt <= 0)
    if repeated.size:
        i = int(repeated[0])
        raise InputError(f"The time column of {p} must increase strictly: row {i + 2} ({t[i + 1]:.6g} s) does not "
                         f"follow row {i + 1} ({t[i]:.6g} s); {repeated.size} such step(s) (duplicate or "
                         f"out-of-order time stamps).")
    step = float((t[-1] - t[0]) / (t.size - 1))
    # Even steps up to the rounding of the printed times: every time within 1 % of a step of a uniform grid.
    off_grid = np.abs(t - (t[0] + step * np.arange(t.size)))
    if not step > 0 or np.any(dt <= 0) or np.max(off_grid) > 0.01 * step:
        raise InputError(f"The time column of {p} must increase in even steps (a constant sampling rate); "
                         f"steps range from {dt.min():.6g} s to {dt.max():.6g} s.")
    channels, quantities = {}, {}
    for j, (name, quantity, scale) in enumerate(columns[1:], start=1):
        if quantity == "time":
            raise InputError(f"Only the first column of {p} may be a time; column {j + 1} is one too.")
        if name in channels:
            raise InputError(f"The channel names of {p} must be unique; column {j + 1} repeats an earlier one.")
        x = values[:, j]
        bad = np.flatnonzero(~np.isfinite(x))
        if bad.size:
            raise InputError(f"The channel '{name}' of {p} has {bad.size} NaN or empty sample(s), the first at "
                             f"t = {t[bad[0]]:.6g} s (row {bad[0] + 1}); clean or cut the record first.")
        huge = np.flatnonzero(np.abs(x * scale) > MAX_SAMPLE)
        if huge.size:
            raise InputError(f"The channel '{name}' of {p} has {huge.size} sample(s) beyond {MAX_SAMPLE:g} in SI "
                             f"units (m/s^2 or m/s), which no machine's vibration reaches, the first "
                             f"{x[huge[0]]:g} at t = {t[huge[0]]:.6g} s (row {huge[0] + 1}); check the record's "
                             f"units or clean it.")
        channels[name] = x * scale
        quantities[name] = quantity
    return Record(t, channels, quantities, 1.0 / step, str(p))


@dataclass(frozen=True)
class ChannelSummary:
    """The numbers a standard judges, for one channel (all SI, band-limited to ``band``).

    ``velocity_rms`` [m/s], ``velocity_peak`` [m/s], ``acceleration_rms`` [m/s^2] (None for a velocity channel),
    ``crest_factor`` [-] of the measured quantity (None for a channel that is zero in the band), the Welch
    spectrum of the velocity (``frequencies`` [Hz], ``velocity_psd`` [(m/s)^2/Hz]) and, with a crank speed, the
    velocity order spectrum (``orders`` [-], ``order_rms`` [m/s]).
    """

    name: str
    quantity: str
    band: tuple
    velocity_rms: float
    velocity_peak: float
    acceleration_rms: float | None
    crest_factor: float | None
    frequencies: np.ndarray
    velocity_psd: np.ndarray
    orders: np.ndarray | None = None
    order_rms: np.ndarray | None = None


@dataclass(frozen=True)
class RecordAnalysis:
    """Per-channel summaries of one record, and the ``mean_velocity_rms`` [m/s] over the channels (seed 002
    averages its measuring points and directions)."""

    source: str
    sampling_rate: float
    duration: float
    channels: tuple[ChannelSummary, ...]

    def channel(self, name: str) -> ChannelSummary:
        for c in self.channels:
            if c.name == name:
                return c
        raise InputError(f"No channel '{name}' in {self.source}; channels: "
                         f"{', '.join(c.name for c in self.channels)}.")

    @property
    def mean_velocity_rms(self) -> float:
        return float(np.mean([c.velocity_rms for c in self.channels]))


def analyse_record(record: Record, band=DEFAULT_BAND, *, crank_speed: float | None = None,
                   channels=None) -> RecordAnalysis:
    """RMS and peak velocity, RMS acceleration, crest factor and spectra of each channel of ``record``.

    Acceleration channels are band-limited and integrated (:func:`integrate_to_velocity`); velocity channels
    are band-limited (:func:`band_limit`). ``crank_speed`` [rad/s] adds an order spectrum.
    """
    fs = record.sampling_rate
    band = check_band(fs, record.time.size, band, what=f"the record {record.source}")
    names = list(record.channels) if channels is None else list(channels)
    out = []
    for name in names:
        if name not in record.channels:
            raise InputError(f"No channel '{name}' in {record.source}; channels: {', '.join(record.channels)}.")
        x = record.channels[name]
        # A constant channel (a disconnected, dead or saturated sensor) would read 0 mm/s, i.e. zone A "good".
        if np.ptp(x) == 0:
            raise InputError(f"The channel '{name}' of {record.source} is constant ({x[0]:g} in SI units) over "
                             f"all {x.size} samples; a dead, disconnected or saturated sensor cannot be judged.")
        if record.quantities[name] == "acceleration":
            measured = band_limit(x, fs, band)
            velocity = integrate_to_velocity(x, fs, band)
            acc_rms: float | None = rms(measured)
        else:
            measured = velocity = band_limit(x, fs, band)
            acc_rms = None
        f, psd = welch_spectrum(velocity, fs)
        orders = order_rms = None
        if crank_speed is not None:
            orders, order_rms = order_spectrum(velocity, fs, crank_speed)
        cf = crest_factor(measured) if rms(measured) > 0 else None
        out.append(ChannelSummary(name, record.quantities[name], band, rms(velocity), peak(velocity), acc_rms,
                                  cf, f, psd, orders, order_rms))
    return RecordAnalysis(record.source, fs, record.duration, tuple(out))


def compare_records(before: RecordAnalysis, after: RecordAnalysis) -> dict:
    """Reduction (before - after) / before x 100 [%] of the RMS velocity per channel present in both records,
    and of the mean over them (key ``"mean"``), as seeds 000 and 002 report their tests."""
    common = [c.name for c in before.channels if c.name in {a.name for a in after.channels}]
    if not common:
        raise InputError(f"The records {before.source} and {after.source} have no channel name in common.")
    out = {n: float(reduction_percent(before.channel(n).velocity_rms, after.channel(n).velocity_rms))
           for n in common}
    out["mean"] = float(reduction_percent(np.mean([before.channel(n).velocity_rms for n in common]),
                                          np.mean([after.channel(n).velocity_rms for n in common])))
    return out
