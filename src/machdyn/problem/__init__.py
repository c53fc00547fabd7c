"""Problem files: TOML with units on every dimensional value, validated into the engine's model.

>>> from machdyn.problem import dump_problem
>>> from machdyn.reading import load_problem                 # the registry of kinds sits above this package
>>> problem = load_problem("examples/slider_crank.toml")   # doctest: +SKIP
>>> load_problem(dump_problem(problem)) == problem          # doctest: +SKIP
True

The file format is described in ``docs/problem-files.md``.
"""

from __future__ import annotations

import warnings
from typing import Any

import machdyn

from .build import build_mechanism, crank_angles
from .dumper import dump_problem
from .schema import LinkageProblem

__all__ = ["LinkageProblem", "build_mechanism", "crank_angles", "dump_problem", "load_problem"]


def load_problem(source: Any) -> Any:
    """Deprecated: :func:`machdyn.load_problem` (reading a file of any kind moved above the registry of kinds in
    0.1.0, to :mod:`machdyn.reading`). It warns and delegates to the package's public name, and goes in 0.3.0."""
    warnings.warn("machdyn.problem.load_problem is deprecated and goes in 0.3.0: use machdyn.load_problem",
                  DeprecationWarning, stacklevel=2)
    return machdyn.load_problem(source)
