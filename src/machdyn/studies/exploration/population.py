"""Evaluate a population of designs given by the caller (an optimiser's generation, a list of candidates): the
same engine call as an exploration, here or on Dask, the results in memory.

```python
import numpy as np
from machdyn.studies.exploration.population import evaluate_population
from machdyn.reading import load_problem
problem = load_problem("examples/four_bar.toml")
values = np.array([[0.035, -1.0], [0.04, -2.0]])   # SI: m, N*m
out = evaluate_population(problem, ["mechanism.crank.length", "loads.torques[0].torque"], values)
out["driving_torque.max_abs"]
```
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace
from typing import Any

import numpy as np

from ...errors import InputError
from ...problem.build import crank_angles
from ..table import DEFAULT_OBJECTIVE, QuantityRange, sweep_unit
from .evaluate import ExplorePlan, check_vectorised_build, evaluate_designs
from .execution import run_tasks
from .sampling import DEFAULT_PARTITION, DesignSpace


def _evaluate_chunk(plan: ExplorePlan, _index: int, values: np.ndarray) -> dict[str, np.ndarray]:
    return evaluate_designs(plan, values)


def _checked(problem: Any, parameters: Sequence[str], values: Any) -> tuple[np.ndarray, tuple[QuantityRange, ...]]:
    data = np.asarray(values, dtype=float)
    if data.ndim != 2 or data.shape[1] != len(parameters) or data.shape[0] < 1:
        raise InputError(f"values must be an (n designs, {len(parameters)} parameters) array; got shape {data.shape}.")
    if len(set(parameters)) != len(parameters):
        raise InputError(f"parameters must differ from each other; got {list(parameters)}.")
    quantities = []
    for k, path in enumerate(parameters):
        meta = sweep_unit(problem, path)
        column = data[:, k]
        bad = ~np.isfinite(column)
        if meta.rule == ">0":
            bad |= ~(column > 0)
        elif meta.rule == ">=0":
            bad |= ~(column >= 0)
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            rule = {"": "be finite", ">0": "be > 0", ">=0": "be >= 0"}[meta.rule]
            raise InputError(f"Every value of {path} must {rule} {meta.unit}; design {i} has {float(column[i])!r}.")
        quantities.append(QuantityRange(path, meta.unit, meta.unit, None, float(column.min()), float(column.max())))
    return data, tuple(quantities)


def evaluate_population(
    problem: Any,
    parameters: Sequence[str],
    values: Any,
    *,
    workers: int | None = None,
    scheduler: str | None = None,
    chunk: int = DEFAULT_PARTITION,
) -> dict[str, np.ndarray]:
    """The per-design summaries of the designs ``values`` (n designs x len(parameters), SI) of a linkage problem,
    the quantity at ``parameters[k]`` (key paths such as ``mechanism.crank.length``) taking ``values[:, k]``.

    Returns one array per column, as the columns of an exploration: the parameters, the status columns
    (``assembled``, ``regular``, ``status``...) and the per-design results under their catalogue keys
    (``driving_torque.max_abs`` [N*m], ``frame_force.max`` [N], ``transmission_angle.min`` [rad],
    ``joint.<name>.max_force`` [N]...; :mod:`machdyn.results.catalogue`); NaN results for designs that are not
    regular. Runs in chunks of ``chunk`` designs here, or on a local Dask cluster of ``workers`` processes, or
    on the Dask scheduler at ``scheduler``."""
    data, quantities = _checked(problem, parameters, values)
    n = data.shape[0]
    space = DesignSpace(quantities, "given", n, 0, max(1, int(chunk)))
    plan = ExplorePlan(problem, space, crank_angles(problem), tuple(problem.output.shaking_moment_about),
                       DEFAULT_OBJECTIVE)
    plan = replace(plan, vectorised=check_vectorised_build(plan, data[np.unique([0, n // 2, n - 1])]))
    out: dict[str, np.ndarray] = {}

    def finished(index: int, columns: dict[str, np.ndarray]) -> None:
        start, stop = space.bounds(index)
        for name, column in columns.items():
            if name not in out:
                out[name] = np.empty(n, dtype=column.dtype)
            out[name][start:stop] = column

    items = ((i, data[slice(*space.bounds(i))]) for i in range(space.partitions))
    run_tasks(_evaluate_chunk, plan, items, finished, workers=workers, scheduler=scheduler)
    return out
