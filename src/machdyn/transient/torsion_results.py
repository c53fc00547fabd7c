"""The results of a transient run whose drive line has torsionally stiff stages (``[[drivetrain.stages]]``
``torsional_stiffness``): the peak torque through each stiff stage at its output shaft, the two-inertia natural
frequency of a line with one stiff stage, and the line's energy balance, for the catalogue and the report."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..results.labels import Label
from .torsion import TorsionRun

__all__ = ["TORSION_LABELS", "TORSION_SUMMARY", "torsion_checks", "torsion_labels", "torsion_scalars",
           "torsion_series"]

#: The relative tolerance of the drive line's energy balance (its own check).
TORSION_TOLERANCE = 1e-6

TORSION_LABELS = {
    "transient.shaft_peak_torque": Label("Transient: largest torque through a stiff stage (at its output shaft)",
                                         "N*m", over="max_abs", better="lower"),
    "transient.torsion_natural_frequency": Label("Transient: natural frequency of the drive line's two inertias "
                                                 "(one stiff stage)", "Hz", over="scalar", better="none"),
    "transient.shaft_damper_loss": Label("Transient: energy dissipated in the stiff stages' dampers", "J",
                                         over="scalar", better="none"),
    "transient.shaft_energy_error": Label("Transient: drive line energy balance error (relative)", "",
                                          over="scalar", better="lower"),
}

TORSION_SUMMARY = ("transient.shaft_peak_torque", "transient.torsion_natural_frequency")


def torsion_scalars(torsion: TorsionRun, crank_inertia: float) -> dict[str, float]:
    """The catalogue's values (SI; the frequency in Hz). ``crank_inertia`` [kg*m^2]: the crank's group with the
    mechanism's mean reduced inertia, for the two-inertia frequency."""
    out = {"transient.shaft_peak_torque": float(np.max(torsion.peak_torques)),
           "transient.shaft_damper_loss": torsion.damper_loss,
           "transient.shaft_energy_error": torsion.energy_error}
    for stage, peak in zip(torsion.line.stages, torsion.peak_torques, strict=True):
        out[f"transient.stage_{stage + 1}.peak_torque"] = float(peak)
    if torsion.line.groups == 1:
        out["transient.torsion_natural_frequency"] = torsion.line.natural_frequency(crank_inertia) / (2 * math.pi)
    return out


def torsion_labels(torsion: TorsionRun) -> dict[str, Label]:
    """The labels of the per-stage keys made at run time."""
    return {f"transient.stage_{stage + 1}.peak_torque":
            Label(f"Transient: peak torque through stage {stage + 1} ({name}), at its output shaft", "N*m",
                  over="max_abs", better="lower")
            for stage, name in zip(torsion.line.stages, torsion.line.names, strict=True)}


def torsion_checks(torsion: TorsionRun) -> list[str]:
    """A failed check when the drive line's energy balance does not close."""
    if torsion.energy_error > TORSION_TOLERANCE:
        return [f"the energy balance of the drive line's stiff stages closes only to {torsion.energy_error:.3g} "
                f"(relative), more than {TORSION_TOLERANCE:g}: tighten rtol"]
    return []


def torsion_series(torsion: TorsionRun) -> dict[str, tuple[Any, str]]:
    """Columns of the CSV: time and the torque through each stiff stage at its output shaft."""
    every = max(1, torsion.t.size // 20_000)
    out: dict[str, tuple[Any, str]] = {"time": (torsion.t[::every], "s")}
    for stage, torque in zip(torsion.line.stages, torsion.shaft_torque, strict=True):
        out[f"stage_{stage + 1}_torque"] = (torque[::every], "N*m")
    return out
