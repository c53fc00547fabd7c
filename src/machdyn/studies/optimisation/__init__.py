"""Design optimisation: design variables addressed by problem-file path, objectives and constraints on any
per-design result, a global search that evaluates each generation in one vectorised engine call
(differential evolution) and a Pareto front for several objectives (NSGA-II). See ``docs/optimise.md``."""

from .result import History, NoFeasibleDesign, OptimiseResult
from .schema import ConstraintSpec, ObjectiveSpec, OptimiseSpec, VariableSpec
from .study import optimise, setup, verify

__all__ = [
    "ConstraintSpec", "History", "NoFeasibleDesign", "ObjectiveSpec", "OptimiseResult", "OptimiseSpec",
    "VariableSpec", "optimise", "setup", "verify",
]
