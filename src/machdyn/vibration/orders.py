"""Which orders of a machine's running speed a measuring band leaves out, said as a warning.

A broad-band RMS velocity counts only the frequencies inside its band (ISO 10816-1:1995 §3 and ISO 2954:2012
§4: 10-1000 Hz; ISO 2954 notes that some parts of ISO 10816, those for slow machines under 600 r/min, use a
lower edge of 2 Hz or less). A machine
turning at 5 Hz (300 r/min) has its 1x order, the one unbalance excites, below a 10 Hz lower edge: the RMS then
leaves out the largest part of the vibration without a word. :func:`band_order_warnings` says so, naming the
orders and the band.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["RESONANCE_MARGIN", "band_order_warnings", "near_resonances", "order_levels", "orders_outside_band",
           "resonance_warnings"]


def orders_outside_band(band, running_speed: float, orders: int | None = None) -> tuple[list[int], list[int]]:
    """The orders of the running speed below and above ``band``.

    band : (low, high) [Hz], the band's edges count as inside (as in the band-limited RMS).
    running_speed : Omega [rad/s] > 0, the machine's running (crank) speed.
    orders : the highest order analysed (a frame study's harmonics); None for a record, whose content has no
        highest order: then only the orders below the band are returned (there are finitely many).
    """
    low, high = (float(v) for v in band)
    f1 = running_speed / (2 * math.pi)
    if not (math.isfinite(f1) and f1 > 0):
        return [], []
    top = orders if orders is not None else max(0, math.ceil(low / f1) - 1)
    below = [k for k in range(1, top + 1) if k * f1 < low * (1 - 1e-12)]
    above = [k for k in range(1, (orders or 0) + 1) if k * f1 > high * (1 + 1e-12)]
    return below, above


def _name(orders: list[int], f1: float) -> str:
    if len(orders) == 1:
        return f"order {orders[0]} ({orders[0] * f1:.3g} Hz)"
    return f"orders {orders[0]} to {orders[-1]} ({orders[0] * f1:.3g}–{orders[-1] * f1:.3g} Hz)"


def band_order_warnings(band, running_speed: float, orders: int | None = None, *,
                        what: str = "The band") -> tuple[str, ...]:
    """A warning for each run of orders of ``running_speed`` [rad/s] that ``band`` (low, high) [Hz] leaves out,
    naming the orders, their frequencies and the band; ``what`` starts the sentence (``"[frame] band"``)."""
    below, above = orders_outside_band(band, running_speed, orders)
    low, high = (float(v) for v in band)
    f1 = running_speed / (2 * math.pi)
    speed = f"the running speed of {f1 * 60:.4g} rpm ({f1:.3g} Hz)"
    out = []
    if below:
        out.append(f"{what} {low:g}–{high:g} Hz leaves out {_name(below, f1)} of {speed}: the RMS values do not "
                   f"count {'it' if len(below) == 1 else 'them'}. To count {'it' if len(below) == 1 else 'them'}, "
                   f"set the band's lower edge below {below[0] * f1:.3g} Hz (the record must then span 5 periods "
                   f"of the new edge).")
    if above:
        out.append(f"{what} {low:g}–{high:g} Hz leaves out {_name(above, f1)} of {speed}: the RMS values do not "
                   f"count {'it' if len(above) == 1 else 'them'}. Raise the band's top above "
                   f"{above[-1] * f1:.3g} Hz or keep fewer orders.")
    return tuple(out)


#: A frame mode within this fraction of an order's frequency is said to be near resonance [-]. Outside it the
#: undamped magnification 1/|1 - r^2| of a single mode (Rao, *Mechanical Vibrations*, 5th ed., eq. 3.30 with
#: zero damping) stays below 3.6 (r = 0.85) and 3.1 (r = 1.15); the mounts' damping only lowers it.
RESONANCE_MARGIN = 0.15


def near_resonances(frequencies, running_speed: float, orders: int, margin: float = RESONANCE_MARGIN):
    """(mode number from 1, mode frequency [Hz], order, order frequency [Hz], relative distance) of every mode
    within ``margin`` of an order 1..``orders`` of ``running_speed`` [rad/s]."""
    f1 = running_speed / (2 * math.pi)
    out = []
    for j, f in enumerate(frequencies, start=1):
        for k in range(1, orders + 1):
            distance = float(f) / (k * f1) - 1.0
            if abs(distance) < margin:
                out.append((j, float(f), k, k * f1, distance))
    return out


def resonance_warnings(frequencies, running_speed: float, orders: int, margin: float = RESONANCE_MARGIN,
                       *, what: str = "Frame mode") -> tuple[str, ...]:
    """A warning for every mode within ``margin`` of an order of ``running_speed`` [rad/s], naming the mode,
    the order, both frequencies, the distance and the margin."""
    return tuple(f"{what} {j} ({f:.3g} Hz) lies within {100 * margin:.0f} % of order {k} of the running speed "
                 f"({fk:.3g} Hz; {100 * d:+.1f} %): near resonance, the response there is magnified "
                 f"(at least {1 / abs(1 - (1 + d) ** 2):.2g} times the static response without damping)."
                 for j, f, k, fk, d in near_resonances(frequencies, running_speed, orders, margin))


def order_levels(orders, order_rms, count: int = 6) -> list[float | None]:
    """The RMS amplitude of each order 1..``count`` of an order spectrum (:func:`~machdyn.vibration.signals.
    order_spectrum`: flat-top window, amplitude-correct for a line between two bins, Brandt 2011 §9.3.4): the
    largest value within three spectral lines (and half an order) of the order, None beyond the spectrum.

    orders : the spectrum's orders [-], increasing and evenly spaced; order_rms : RMS per line [unit].
    """
    k_all = np.asarray(orders, dtype=float)
    a_all = np.asarray(order_rms, dtype=float)
    if k_all.size < 2:
        return [None] * count
    reach = min(0.5, 3.0 * float(k_all[1] - k_all[0]))
    out: list[float | None] = []
    for k in range(1, count + 1):
        near = np.abs(k_all - k) <= reach
        out.append(float(a_all[near].max()) if near.any() and k_all[-1] >= k else None)
    return out
