"""Per-design results of a whole population for the optimiser: the catalogue's keys, computed by the one
population evaluator (:func:`machdyn.results.population.evaluate_population`) that sweeps and explorations use
too. Result keys follow the single-design results of ``machdyn run`` (``driving_torque.max_abs``,
``joint.B.max_force``, ``stroke.rocker``...); every value is SI (angles in rad). The compactor's results
(seed 003) are offered for ``[mechanism] machine = "compactor"``.
"""

from __future__ import annotations

import math
from collections.abc import Iterable

import numpy as np

from ...linkage.model import Mechanism
from ...results.population import DEFAULT_MIN_TRANSMISSION_DEG, result_names, result_unit
from ..evaluator import PopulationEvaluator

__all__ = ["evaluate", "result_names", "result_unit"]


def evaluate(mech: Mechanism, phi, speed, acceleration, wanted: Iterable[str], shaking_about=(0.0, 0.0), *,
             machine: str | None = None,
             min_transmission_angle: float = math.radians(DEFAULT_MIN_TRANSMISSION_DEG)) -> dict[str, np.ndarray]:
    """The results ``wanted`` for every design of ``mech`` (N designs), as (N,) arrays, plus
    ``assembled_fraction`` (share of crank angles where the design closes), ``regular`` (closes at every angle,
    passes no dead point or branch change, keeps its transmission angle ``min_transmission_angle`` [rad] away
    from 0 and 180 deg) and the other numeric status columns. Results of designs that are not regular are NaN.
    Every group but the full analysis is computed in one compiled pass over the population when numba is
    present (:mod:`machdyn.linkage.fused_population`), else by the NumPy reference."""
    evaluator = PopulationEvaluator(phi, speed, acceleration, tuple(shaking_about), machine, min_transmission_angle,
                                    engine="fused")
    out = evaluator.vectorised(mech, wanted)
    return {k: v for k, v in out.items() if v.dtype.kind in "fb"}
