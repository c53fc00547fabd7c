"""Problem files: TOML with units on every dimensional value, validated into the engine's model.

>>> from machdyn.problem import dump_problem
>>> from machdyn.reading import load_problem                 # the registry of kinds sits above this package
>>> problem = load_problem("examples/slider_crank.toml")   # doctest: +SKIP
>>> load_problem(dump_problem(problem)) == problem          # doctest: +SKIP
True

The file format is described in ``docs/problem-files.md``.
"""

from __future__ import annotations

from .build import build_mechanism, crank_angles
from .dumper import dump_problem
from .schema import LinkageProblem

__all__ = ["LinkageProblem", "build_mechanism", "crank_angles", "dump_problem"]
