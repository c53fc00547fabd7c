"""Vibration severity: the zones of ISO 10816-1 (ISO 20816-1) and the classes of ISO 2372.

The standards judge the broad-band (10...1000 Hz) RMS vibration velocity measured on non-rotating parts. The
boundaries depend on the machine class (I small ... IV large on soft foundations); the tables are data files
in ``data/`` with their sources in ``data/SOURCES.md``.
"""

from __future__ import annotations

import csv
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

import numpy as np

from ..errors import InputError, check_finite
from .response import reduction_percent

__all__ = ["STANDARDS", "Severity", "classify", "severity_range", "zone_boundaries", "compare_severity"]

#: Standard name -> (data file, zone labels from best to worst, meaning of each zone).
STANDARDS: dict[str, tuple[str, tuple[str, ...], tuple[str, ...]]] = {
    "ISO 10816-1": ("iso10816_1_zones.csv", ("A", "B", "C", "D"), (
        "newly commissioned machines",
        "acceptable for unrestricted long-term operation",
        "unsatisfactory for long-term continuous operation",
        "severe enough to cause damage",
    )),
    "ISO 2372": ("iso2372_classes.csv", ("good", "satisfactory", "unsatisfactory", "unacceptable"), (
        "good", "satisfactory (usable)", "unsatisfactory (just tolerable)", "unacceptable (not permissible)",
    )),
}
_ALIASES = {"ISO 20816-1": "ISO 10816-1", "ISO10816-1": "ISO 10816-1", "ISO 10816": "ISO 10816-1",
            "ISO2372": "ISO 2372", "ISO20816-1": "ISO 10816-1"}
_CLASSES = ("I", "II", "III", "IV")


@lru_cache(maxsize=8)
def _read(name: str) -> tuple[dict[str, str], ...]:
    text = resources.files("machdyn.vibration").joinpath("data", name).read_text(encoding="utf-8")
    return tuple(csv.DictReader(text.splitlines()))


def _standard(standard: str) -> str:
    key = " ".join(str(standard).split())
    key = _ALIASES.get(key, _ALIASES.get(key.upper(), key.upper() if key.upper() in STANDARDS else key))
    if key not in STANDARDS:
        raise InputError(f"The severity standard must be one of {', '.join([*STANDARDS, 'ISO 20816-1'])}; "
                         f"got {standard!r}.")
    return key


def _machine_class(machine_class: str) -> str:
    c = str(machine_class).strip().upper()
    if c not in _CLASSES:
        raise InputError(f"The machine class must be one of {', '.join(_CLASSES)} (I small ... IV large on soft "
                         f"foundations); got {machine_class!r}.")
    return c


def zone_boundaries(machine_class: str = "I", standard: str = "ISO 10816-1") -> tuple[float, float, float]:
    """The three zone boundaries [m/s] (RMS velocity) of ``machine_class`` under ``standard``.

    ISO 10816-1:1995 Annex B, Table B.1 (= ISO 2372:1974 class boundaries); see ``data/SOURCES.md``.

    Parameters
    ----------
    machine_class : "I", "II", "III" or "IV"
    standard : "ISO 10816-1" (also "ISO 20816-1") or "ISO 2372"

    Examples
    --------
    >>> [round(b * 1e3, 2) for b in zone_boundaries("II")]  # mm/s
    [1.12, 2.8, 7.1]
    """
    key = _standard(standard)
    c = _machine_class(machine_class)
    row = next(r for r in _read(STANDARDS[key][0]) if r["machine_class"] == c)
    values = [float(v) for k, v in row.items() if k not in ("machine_class", "description")]
    return tuple(v * 1e-3 for v in values)  # type: ignore[return-value]


def severity_range(velocity_rms: float) -> str:
    """The ISO 2372 severity range (its upper limit in mm/s, e.g. "4.5") that holds ``velocity_rms`` [m/s].

    ISO 2372:1974, Table 1. Everything up to 0.112 mm/s is range "0.11"; above 71 mm/s: ">71".

    Examples
    --------
    >>> severity_range(0.005129)
    '7.1'
    """
    check_finite("RMS velocity", velocity_rms, "m/s")
    v = float(velocity_rms) * 1e3
    if v < 0:
        raise InputError(f"The RMS velocity must be >= 0 m/s; got {velocity_rms:g} m/s.")
    rows = _read("iso2372_ranges.csv")
    for r in rows:
        if v <= float(r["upper"]):
            return r["range"]
    return ">71"


@dataclass(frozen=True)
class Severity:
    """A judged vibration level: ``velocity_rms`` [m/s], ``zone`` label, its ``meaning``, the ``standard``,
    ``machine_class`` and the ``boundaries`` [m/s] used, and the zone's index (0 best ... 3 worst)."""

    velocity_rms: float
    zone: str
    meaning: str
    index: int
    standard: str
    machine_class: str
    boundaries: tuple[float, float, float]


def classify(velocity_rms: float, machine_class: str = "I", standard: str = "ISO 10816-1", *,
             boundaries=None) -> Severity:
    """Judge an RMS vibration velocity [m/s] by ``standard`` for ``machine_class``.

    A value on a boundary belongs to the better zone (ISO 10816-1 Table B.1 reads "up to"). ISO 10816-1:1995
    §5.3 and Annex B; ISO 2372:1974 Annex.

    Parameters
    ----------
    velocity_rms : broad-band RMS velocity [m/s] >= 0
    machine_class : "I" ... "IV"
    standard : "ISO 10816-1" (or "ISO 20816-1") or "ISO 2372"
    boundaries : optional three increasing boundaries [m/s] replacing the table's (machine-specific parts)

    Examples
    --------
    >>> classify(3.2e-3, "II").zone  # a 45 kW motor at 3.2 mm/s
    'C'
    >>> classify(0.005129, "I", "ISO 2372").zone  # seed 002's screen before the change
    'unacceptable'
    """
    check_finite("RMS velocity", velocity_rms, "m/s")
    v = float(velocity_rms)
    if v < 0:
        raise InputError(f"The RMS velocity must be >= 0 m/s; got {v:g} m/s.")
    key = _standard(standard)
    c = _machine_class(machine_class)
    b: tuple[float, ...]
    if boundaries is None:
        b = zone_boundaries(c, key)
    else:
        b = tuple(float(x) for x in boundaries)
        if len(b) != 3 or not all(np.isfinite(b)) or not 0 < b[0] < b[1] < b[2]:
            raise InputError(f"The zone boundaries must be three increasing velocities > 0 m/s; got {boundaries!r}.")
    index = int(np.searchsorted(np.asarray(b), v, side="left"))
    labels, meanings = STANDARDS[key][1], STANDARDS[key][2]
    return Severity(v, labels[index], meanings[index], index, key, c, b)  # type: ignore[arg-type]


def compare_severity(before: float, after: float, machine_class: str = "I", standard: str = "ISO 10816-1",
                     *, boundaries=None) -> tuple[Severity, Severity, float]:
    """Both levels [m/s] judged, and the reduction (before - after) / before [%] (as seed 002 reports it)."""
    return (classify(before, machine_class, standard, boundaries=boundaries),
            classify(after, machine_class, standard, boundaries=boundaries),
            float(reduction_percent(before, after)))
