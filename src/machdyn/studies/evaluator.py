"""The one evaluator of the studies: the results of a population of designs, by the catalogue's keys.

A ``[sweep]``, an exploration and an optimisation all ask the same question: the results named by these keys, for
each of these N designs. The evaluator answers with one (N,) array per key, in two ways:

- vectorised — the keys a group of the population evaluator computes (the linkage's own results, the status
  checks), every design at once in one engine call (:func:`machdyn.results.population.evaluate_population`);
- at once by a capability's population form — the keys of a table that declares one (``[parts]``), every design
  at once from the population's kinetostatics (:mod:`machdyn.studies.capability_population`);
- per design — the keys only a run of a design gives (a capability's: a flywheel, a drive train), each regular
  design run whole through its file's stages (:func:`machdyn.studies.per_design.evaluate_designs`).

A population larger than its memory allows is evaluated in chunks of designs (:meth:`PopulationEvaluator.chunk`,
from ``memory_budget``), each chunk's results written into the whole population's arrays: the working memory stays
bounded whatever the population, and the results are those of the unchunked call (every design's result is its own).

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

from ..linkage.engines import use_fused
from ..results.population import DEFAULT_MIN_TRANSMISSION_DEG, evaluate_population
from .capability_population import population_results
from .per_design import RunDesign, evaluate_designs

#: The working memory [bytes] a population's evaluation may take, by default (the chunk of designs follows).
DEFAULT_MEMORY_BUDGET = 256 * 2**20

#: Floats the NumPy path holds per design and crank position at most (the kinematics of every body, the joint
#: forces and their reductions): what a chunk's working memory is reckoned by.
FLOATS_PER_POSITION = 128


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
    memory_budget: int = DEFAULT_MEMORY_BUDGET
    workers: int = 1

    def chunk(self) -> int:
        """The designs evaluated at once: the memory budget over a design's working memory, which is
        :data:`FLOATS_PER_POSITION` 8-byte floats per crank position (at least one design)."""
        positions = max(int(np.size(self.phi)), 1)
        return max(1, int(self.memory_budget) // (8 * FLOATS_PER_POSITION * positions))

    def _part(self, value: Any, part: slice, count: int) -> Any:
        """A drive value's rows of the designs ``part``: a float as it is, one value per design sliced."""
        arr = np.asarray(value)
        return arr[part] if arr.ndim >= 1 and arr.shape[0] == count and count > 1 else value

    def _chunks(self, mechanism: Any, count: int):
        """(slice, the designs' model, speed, acceleration) of each chunk of the ``count`` designs."""
        size = self.chunk()
        designs = getattr(mechanism, "design_count", None)
        for start in range(0, count, size):
            part = slice(start, min(count, start + size))
            if size >= count:
                yield part, mechanism, self.speed, self.acceleration
                return
            model = mechanism.take_designs(part) if designs is not None and designs == count else mechanism
            yield part, model, self._part(self.speed, part, count), self._part(self.acceleration, part, count)

    def vectorised(self, mechanism: Any, keys: Iterable[str]) -> dict[str, np.ndarray]:
        """``keys`` and the status columns of every design of ``mechanism`` (one model, N designs), chunk of
        designs by chunk (:meth:`chunk`)."""
        keys = list(keys)
        count = getattr(mechanism, "design_count", None) or 1
        if count <= self.chunk():
            return self._vectorised(mechanism, self.speed, self.acceleration, keys)
        engine = self._engine_of(mechanism, count)
        out: dict[str, np.ndarray] = {}
        for part, model, speed, acceleration in self._chunks(mechanism, count):
            _fill(out, self._vectorised(model, speed, acceleration, keys, engine), part, count)
        return out

    def _engine_of(self, mechanism: Any, count: int) -> str:
        """The engine of every chunk: the one the whole population would run on ("auto" compiles only above a
        size, which a chunk may fall below), so that the chunks give the unchunked call's results."""
        if self.engine != "auto":
            return self.engine
        return "fused" if use_fused("auto", mechanism, self.phi, count * int(np.size(self.phi))) else "auto"

    def _vectorised(self, mechanism: Any, speed: Any, acceleration: Any, keys: list[str],
                    engine: str | None = None) -> dict[str, np.ndarray]:
        return evaluate_population(mechanism, self.phi, speed, acceleration, keys, about=self.about,
                                   machine=self.machine, min_transmission_angle=self.min_transmission_angle,
                                   engine=engine or self.engine)

    def per_design(self, problems: Iterable[Any | None], keys: Iterable[str], count: int) -> dict[str, np.ndarray]:
        """``keys`` of each design's run (None: a design not run, NaN), as (count,) arrays."""
        if self.run_design is None:
            raise RuntimeError("results of a capability need a way to run a design (StageContext.run_design)")
        return evaluate_designs(self.run_design, problems, keys, count, self.workers)

    def __call__(self, mechanism: Any, keys: Iterable[str], count: int, per_design: Iterable[str] = (),
                 problem_of: Callable[[int], Any] | None = None,
                 buildable: np.ndarray | None = None) -> dict[str, np.ndarray]:
        """The results of ``count`` designs as (count,) arrays: ``keys`` vectorised, ``per_design`` by running
        each regular (and ``buildable``) design ``i``, whose validated problem is ``problem_of(i)``. Designs that
        are alike may stack into one model: their vectorised results are repeated. A population above
        :meth:`chunk` designs is evaluated chunk by chunk."""
        keys, per_design = list(keys), list(per_design)
        designs = getattr(mechanism, "design_count", None)
        if count <= self.chunk() or designs not in (None, count):
            return self._call(mechanism, self.speed, self.acceleration, keys, count, per_design, problem_of,
                              buildable)
        engine = self._engine_of(mechanism, count)
        out: dict[str, np.ndarray] = {}
        for part, model, speed, acceleration in self._chunks(mechanism, count):
            start = part.start

            def of(i: int, start: int = start) -> Any:
                assert problem_of is not None
                return problem_of(start + i)

            found = self._call(model, speed, acceleration, keys, part.stop - start, per_design,
                               of if problem_of is not None else None,
                               None if buildable is None else np.asarray(buildable)[part], engine)
            _fill(out, found, part, count)
        return out

    def at_once(self, mechanism: Any, keys: Iterable[str], count: int,
                found: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
        """The ``keys`` that a capability's population form gives for the ``count`` designs (NaN for a design
        that is not regular in ``found``, the designs' status columns), without running any design."""
        if self.problem is None:
            return {}
        at_once = population_results(self.problem, list(keys), mechanism, self.speed, self.acceleration, count,
                                     self.varied)
        regular = np.asarray(found.get("regular", np.ones(count, dtype=bool)), dtype=bool)
        return {k: np.where(regular, v, np.nan) for k, v in at_once.items()}

    def _call(self, mechanism: Any, speed: Any, acceleration: Any, keys: list[str], count: int,
              per_design: list[str], problem_of: Callable[[int], Any] | None,
              buildable: np.ndarray | None, engine: str | None = None) -> dict[str, np.ndarray]:
        out = {k: np.broadcast_to(np.asarray(v), (count,)).copy()
               for k, v in self._vectorised(mechanism, speed, acceleration, keys, engine).items()}
        wanted = list(per_design)
        if wanted and self.problem is not None:
            at_once = population_results(self.problem, wanted, mechanism, speed, acceleration, count,
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


def _fill(out: dict[str, np.ndarray], found: dict[str, np.ndarray], part: slice, count: int) -> None:
    """Write one chunk's (n,) results into the whole population's (count,) arrays, made at the first chunk."""
    for key, value in found.items():
        arr = np.broadcast_to(np.asarray(value), (part.stop - part.start,))
        if key not in out:
            out[key] = np.empty(count, dtype=arr.dtype)
        elif arr.dtype.kind == "U" and arr.dtype.itemsize > out[key].dtype.itemsize:
            out[key] = out[key].astype(arr.dtype)  # a longer text than the chunks before held
        out[key][part] = arr
