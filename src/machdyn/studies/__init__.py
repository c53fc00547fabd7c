"""Studies of many designs of one problem: the ``[sweep]`` of one quantity, the exploration of several over a
design space (written to Parquet, resumable, on Dask), and the optimisation of objectives under constraints.

One evaluator serves them all (:class:`~machdyn.studies.evaluator.PopulationEvaluator`): a population of linkage
designs evaluated in one vectorised engine call under the catalogue's keys, and each regular design run whole
through its problem file's stages where a result needs them; the exploration writes the rows it evaluates to its
store.

:mod:`.evaluator` is that evaluator, :mod:`.table` the ``[sweep]`` table, :mod:`.sweep` its capability,
:mod:`.exploration` and :mod:`.optimisation` the two searches, :mod:`.views` the designs a study analyses whole
for playback, :mod:`.per_design` a study's run of one design.
"""

from .evaluator import PopulationEvaluator
from .exploration import (
    DesignSpace,
    Execution,
    Exploration,
    designs,
    execution,
    explore,
    partition_designs,
    plan_exploration,
    read_exploration,
)
from .optimisation import (
    ConstraintSpec,
    History,
    NoFeasibleDesign,
    ObjectiveSpec,
    OptimiseResult,
    OptimiseSpec,
    VariableSpec,
    optimise,
    setup,
    verify,
)

__all__ = [
    "ConstraintSpec", "DesignSpace", "Execution", "Exploration", "History", "NoFeasibleDesign", "ObjectiveSpec",
    "OptimiseResult", "OptimiseSpec", "PopulationEvaluator", "VariableSpec", "designs", "execution", "explore",
    "optimise", "partition_designs", "plan_exploration", "read_exploration", "setup", "verify",
]
