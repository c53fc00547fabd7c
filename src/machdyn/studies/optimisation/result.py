"""The frozen result of a design optimisation: the best design, its results, the history, the front."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ...errors import InputError
from ...notebook import ShownInNotebook


class NoFeasibleDesign(InputError):
    """No design within the bounds meets every constraint; the message lists the tightest constraints."""


@dataclass(frozen=True)
class History:
    """Per generation: evaluations so far, the best objective value of a feasible design (NaN before the
    first one), the share of the generation that is feasible and, for a Pareto front, the hypervolume of the
    feasible front (normalised; :func:`machdyn.studies.optimisation.pareto.hypervolumes`)."""

    generation: np.ndarray
    evaluations: np.ndarray
    best: np.ndarray
    feasible_share: np.ndarray
    hypervolume: np.ndarray | None = None


@dataclass(frozen=True)
class OptimiseResult(ShownInNotebook):
    """What :func:`machdyn.studies.optimisation.optimise` found.

    ``x`` the best design's variables (SI, in the order of ``names``); ``results`` its per-design results
    (SI floats); ``objective`` the objective(s) there; ``verified`` True when the best design, rebuilt alone
    from its problem file, meets every constraint; ``converged`` and ``message`` the search's own report;
    ``front_x``/``front_f`` the Pareto front (multi-objective only: designs x variables, designs x objectives,
    objectives as results in SI); ``problem`` the best design as a validated problem and ``problem_text`` as
    a problem file ready to run; ``improved`` whether the best design is better than the file's own.
    """

    method: str
    names: tuple[str, ...]
    units: tuple[str, ...]
    display_units: tuple[str, ...]
    lower: np.ndarray
    upper: np.ndarray
    x: np.ndarray
    results: dict[str, float]
    objectives: tuple[Any, ...]
    constraints: tuple[Any, ...]
    objective: np.ndarray
    converged: bool
    message: str
    evaluations: int
    seconds: float
    verified: bool
    history: History
    problem: Any = None
    problem_text: str = ""
    front_x: np.ndarray | None = None
    front_f: np.ndarray | None = None
    warnings: tuple[str, ...] = field(default_factory=tuple)
    #: the nominal design and the optimum analysed one by one for playback (filled in by the stage)
    views: tuple = ()
    #: whether the best design is better than the file's own (None: several objectives, or the file's values lie
    #: outside the bounds, so there is no single design to compare with)
    improved: bool | None = None

    @property
    def designs_per_second(self) -> float:
        return self.evaluations / self.seconds if self.seconds > 0 else float("inf")
