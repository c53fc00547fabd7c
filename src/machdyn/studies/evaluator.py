"""The one evaluator of the studies: the results of a population of designs, by the catalogue's keys.

A ``[sweep]``, an exploration and an optimisation all ask the same question: the results named by these keys, for
each of these N designs. The evaluator answers with one (N,) array per key, in two ways:

- vectorised — the keys a group of the population evaluator computes (the linkage's own results, the status
  checks), every design at once in one engine call (:func:`machdyn.results.population.evaluate_population`);
- at once by a capability's population form — the keys of a table that declares one (``[parts]``), every design
  at once from the population's kinetostatics (:mod:`machdyn.studies.capability_population`);
- per design — the keys only a run of a design gives (a capability's: a flywheel, a drive train), each regular
  design run whole through its file's stages (:func:`machdyn.studies.per_design.evaluate_designs`).

What a study keeps of the answer is its own: a sweep its columns, an optimiser its costs and violations, an
exploration the rows it writes partition by partition to its store
(:class:`machdyn.studies.exploration.store.PartitionStore`).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..results.population import DEFAULT_MIN_TRANSMISSION_DEG, evaluate_population
from .capability_population import population_results
from .per_design import RunDesign, evaluate_designs


@dataclass(frozen=True)
class PopulationEvaluator:
    """Evaluates populations of linkage designs of one problem.

    phi : the crank angles [rad]; speed [rad/s], acceleration [rad/s^2] : floats, or one value per design;
    about : the point [m] of the shaking moments; machine : the machine the mechanism is (``[mechanism] machine``),
    which decides the machine's own results; min_transmission_angle [rad] : the threshold of a poor transmission;
    engine : the population evaluator's engine ("auto", "fused" or "numpy"); run_design : runs one design's
    validated problem through its stages and returns its results by key (None: no per-design results);
    problem : the file's validated problem, and varied : the key paths the designs set — with them, a capability
    result whose table declares a population form (and is not varied) is computed for all designs at once
    (:mod:`machdyn.studies.capability_population`) instead of by a run of each design.
    """

    phi: Any
    speed: Any = 0.0
    acceleration: Any = 0.0
    about: tuple[float, float] = (0.0, 0.0)
    machine: str | None = None
    min_transmission_angle: float = math.radians(DEFAULT_MIN_TRANSMISSION_DEG)
    engine: str = "auto"
    run_design: RunDesign | None = None
    problem: Any = None
    varied: tuple[str, ...] = ()

    def vectorised(self, mechanism: Any, keys: Iterable[str]) -> dict[str, np.ndarray]:
        """``keys`` and the status columns of every design of ``mechanism`` (one model, N designs), at once."""
        return evaluate_population(mechanism, self.phi, self.speed, self.acceleration, keys, about=self.about,
                                   machine=self.machine, min_transmission_angle=self.min_transmission_angle,
                                   engine=self.engine)

    def per_design(self, problems: Iterable[Any | None], keys: Iterable[str], count: int) -> dict[str, np.ndarray]:
        """``keys`` of each design's run (None: a design not run, NaN), as (count,) arrays."""
        if self.run_design is None:
            raise RuntimeError("results of a capability need a way to run a design (StageContext.run_design)")
        return evaluate_designs(self.run_design, problems, keys, count)

    def __call__(self, mechanism: Any, keys: Iterable[str], count: int, per_design: Iterable[str] = (),
                 problem_of: Callable[[int], Any] | None = None,
                 buildable: np.ndarray | None = None) -> dict[str, np.ndarray]:
        """The results of ``count`` designs as (count,) arrays: ``keys`` vectorised, ``per_design`` by running
        each regular (and ``buildable``) design ``i``, whose validated problem is ``problem_of(i)``. Designs that
        are alike may stack into one model: their vectorised results are repeated."""
        out = {k: np.broadcast_to(np.asarray(v), (count,)).copy()
               for k, v in self.vectorised(mechanism, keys).items()}
        wanted = list(per_design)
        if wanted and self.problem is not None:
            at_once = population_results(self.problem, wanted, mechanism, self.speed, self.acceleration, count,
                                         self.varied)
            regular = np.asarray(out.get("regular", np.ones(count, dtype=bool)), dtype=bool)
            if buildable is not None:
                regular = regular & buildable
            out |= {k: np.where(regular, v, np.nan) for k, v in at_once.items()}
            wanted = [k for k in wanted if k not in at_once]
        if wanted:
            if problem_of is None:
                raise ValueError("per-design results need each design's problem (problem_of)")
            regular = np.asarray(out.get("regular", np.ones(count, dtype=bool)), dtype=bool)
            if buildable is not None:
                regular = regular & buildable
            out |= self.per_design((problem_of(i) if regular[i] else None for i in range(count)), wanted, count)
        return out
