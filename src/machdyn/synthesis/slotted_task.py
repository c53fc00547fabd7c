"""The ``slotted_lever`` and ``whitworth`` tasks of a ``[synthesis]`` table: designs over the free scale, each
measured by the engine, ranked by the force in the slot.

Each candidate is synthesised in closed form (:mod:`.slotted_lever`) and then built as the engine's model and
measured: the time ratio and stroke from the engine's exact kinematics, beside the closed form's; the difference
is the candidate's kinematic error. The ram's motion depends on the ratio r / d alone, which the time ratio fixes,
so the free scale changes the size of the mechanism and the forces in it, not the motion: candidates are ranked by
the largest force of the crank pin on the slot per newton resisting the ram in the cutting stroke (smaller first;
a larger mechanism), and the size d + r is listed beside it for the designer to trade.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import InputError
from ..pipeline import Outcome
from ..results.labels import Label
from .slotted_lever import Measured, SlottedLever, candidates, measure


@dataclass(frozen=True)
class SlottedResult:
    """Designs best first, what the engine measured of each and what the task asked."""

    task: str
    time_ratio: float
    stroke: float
    designs: list[SlottedLever]
    measured: list[Measured]

    @property
    def best(self) -> SlottedLever:
        return self.designs[0]

    def error(self, k: int) -> tuple[float, float]:
        """(time ratio error [-], stroke error [m]) of design ``k``: engine's measurement minus the task's."""
        m = self.measured[k]
        return m.time_ratio - self.time_ratio, m.stroke - self.stroke


def synthesise_slotted(spec: Any) -> SlottedResult:
    """Carry out a validated ``[synthesis]`` table whose task is ``slotted_lever`` or ``whitworth``."""
    designs = candidates(spec.task, spec.time_ratio, spec.stroke, spec.candidates, rod_ratio=_rod_ratio(spec))
    measured = [measure(d) for d in designs]
    err = np.array([abs(m.time_ratio - spec.time_ratio) / spec.time_ratio + abs(m.stroke - spec.stroke) / spec.stroke
                    for m in measured])
    peak = np.array([m.slot_force_per_ram_force for m in measured])
    idx = np.lexsort((err, peak))
    return SlottedResult(task=spec.task, time_ratio=spec.time_ratio, stroke=spec.stroke,
                         designs=[designs[i] for i in idx], measured=[measured[i] for i in idx])


def problems(spec: Any) -> list[tuple[str, str]]:
    """The rules of the two tasks the schema cannot say (the same checks the synthesis makes)."""
    out: list[tuple[str, str]] = []
    if spec.stroke is None:
        return [("synthesis.stroke", f"is required by the task '{spec.task}'; it is missing")]
    if not spec.time_ratio > 1.0:
        return [("synthesis.time_ratio", f"must be > 1 for a slotted-lever quick return (1 would need a crank of "
                                         f"no length); got {spec.time_ratio:g}")]
    if spec.rod is not None:
        try:  # the lever and the rod's limit do not depend on the free scale: one candidate tells
            candidates(spec.task, spec.time_ratio, spec.stroke, 1, rod_ratio=_rod_ratio(spec))
        except InputError as exc:
            out.append(("synthesis.rod", str(exc)))
    return out


def _rod_ratio(spec: Any) -> float | None:
    """The given rod over the task's lever (which the time ratio and stroke fix), or None for the default rod."""
    if spec.rod is None:
        return None
    ratio = float(np.cos(np.pi / (1.0 + spec.time_ratio)))  # r / d (slotted lever)
    lever = spec.stroke / 2.0 if spec.task == "whitworth" else spec.stroke / (2.0 * ratio)
    return float(spec.rod / lever)


LABELS = {
    "synthesis.best.centre_distance": ("Best: centre distance (crank to lever pivot)", "m", "mm"),
    "synthesis.best.lever": ("Best: lever length (pivot to rod pin)", "m", "mm"),
    "synthesis.best.rod": ("Best: ram's connecting rod", "m", "mm"),
    "synthesis.best.time_ratio": ("Best: time ratio measured by the engine", "", ""),
    "synthesis.best.stroke": ("Best: stroke measured by the engine", "m", "mm"),
    "synthesis.best.cutting_peak_over_mean": ("Best: cutting stroke's peak ram speed over its mean", "", ""),
    "synthesis.best.return_peak_over_mean": ("Best: return stroke's peak ram speed over its mean", "", ""),
    "synthesis.best.slot_force_per_ram_force": ("Best: largest slot force per newton on the ram (cutting)", "", ""),
}


def outcome(spec: Any) -> Any:
    """The run's :class:`~machdyn.pipeline.Outcome` of a slotted-lever task: the best design's dimensions and
    measured time ratio and stroke, every candidate as ``synthesis_candidates.csv``."""
    result = synthesise_slotted(spec)
    best, m = result.best, result.measured[0]
    scalars: dict[str, Any] = {"synthesis.candidates": float(len(result.designs)),
                               "synthesis.best.crank": best.crank, "synthesis.best.centre_distance":
                               best.centre_distance, "synthesis.best.lever": best.lever, "synthesis.best.rod": best.rod,
                               "synthesis.best.time_ratio": m.time_ratio, "synthesis.best.stroke": m.stroke,
                               "synthesis.best.cutting_peak_over_mean": m.peak_over_mean_slow,
                               "synthesis.best.slot_force_per_ram_force": m.slot_force_per_ram_force,
                               "synthesis.best.return_peak_over_mean": m.peak_over_mean_fast}
    labels = {k: Label(text, unit, shown) if unit else Label(text) for k, (text, unit, shown) in LABELS.items()}
    cols: dict[str, tuple[Any, str]] = {"rank": (np.arange(1, len(result.designs) + 1), "")}
    for name in ("crank", "centre_distance", "lever", "rod"):
        cols[name] = (np.array([getattr(d, name) for d in result.designs]), "m")
    cols["time_ratio_closed_form"] = (np.array([d.time_ratio for d in result.designs]), "")
    cols["time_ratio_engine"] = (np.array([x.time_ratio for x in result.measured]), "")
    cols["stroke_closed_form"] = (np.array([d.stroke for d in result.designs]), "m")
    cols["stroke_engine"] = (np.array([x.stroke for x in result.measured]), "m")
    cols["cutting_peak_over_mean"] = (np.array([x.peak_over_mean_slow for x in result.measured]), "")
    cols["return_peak_over_mean"] = (np.array([x.peak_over_mean_fast for x in result.measured]), "")
    cols["slot_force_per_ram_force"] = (np.array([x.slot_force_per_ram_force for x in result.measured]), "")
    cols["size"] = (np.array([d.centre_distance + d.crank for d in result.designs]), "m")
    summary = ("synthesis.candidates", "synthesis.best.crank", "synthesis.best.centre_distance",
               "synthesis.best.lever", "synthesis.best.rod", "synthesis.best.time_ratio", "synthesis.best.stroke",
               "synthesis.best.cutting_peak_over_mean", "synthesis.best.slot_force_per_ram_force")
    return Outcome(results=result, scalars=scalars, labels=labels, series={"synthesis_candidates": cols},
                   summary=summary)
