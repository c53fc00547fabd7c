"""Deprecated: design-space exploration is :mod:`machdyn.studies` (``machdyn.studies.exploration``).

This module re-exports the public names it had and warns on import; it will be removed in 0.3.0.
"""

import warnings

from ..studies.exploration import (
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

__all__ = ["DesignSpace", "Execution", "Exploration", "designs", "execution", "explore", "partition_designs",
           "plan_exploration", "read_exploration"]

warnings.warn("machdyn.explore is deprecated and will be removed in 0.3.0; import from machdyn.studies",
              DeprecationWarning, stacklevel=2)
