"""Deprecated: design optimisation is :mod:`machdyn.studies` (``machdyn.studies.optimisation``).

This module re-exports the public names it had and warns on import; it will be removed in 0.3.0.
"""

import warnings

from ..studies.optimisation import (
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
    "ConstraintSpec", "History", "NoFeasibleDesign", "ObjectiveSpec", "OptimiseResult", "OptimiseSpec",
    "VariableSpec", "optimise", "setup", "verify",
]

warnings.warn("machdyn.optimise is deprecated and will be removed in 0.3.0; import from machdyn.studies",
              DeprecationWarning, stacklevel=2)
