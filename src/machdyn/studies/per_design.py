"""Results no population group computes — a capability's: the flywheel and its motor, the drive train, the parts,
a balance, the frame on its mounts, a cam on the crank shaft — for the designs of a population, by running each
design through the file's own stages (the run a ``machdyn run`` of that design makes, without the file's
``[sweep]`` and ``[optimise]``), and reading the result under its catalogue key.

This is general and exact — the optimiser sees what a run of the design reports — and as slow as one run per
design (a flywheel's steady state: milliseconds to a second): the vectorised groups of
:mod:`machdyn.results.population` stay the fast path for the linkage's own results. A design whose run fails (its
drive cannot carry it, its linkage does not close) gets NaN, which the optimiser counts as infeasible.

With ``workers`` > 1 (the command line's ``--workers``) the designs' runs are spread over that many local worker
processes (:func:`run_in_parallel`, :mod:`concurrent.futures`), started once and kept for the later calls of the
run; each design is still run whole and alone, so the results are the same as in this process.
"""

from __future__ import annotations

import atexit
import math
import multiprocessing
from collections.abc import Callable, Iterable, Mapping, Sequence
from concurrent.futures import Executor, ProcessPoolExecutor
from typing import Any

import numpy as np

from ..errors import MachdynError
from ..kinds import CAPABILITIES, KINDS, capability, catalogue, kind, problem_model
from ..results.catalogue import find

#: The tables whose results are not a design's: the studies themselves.
STUDIES = ("sweep", "optimise")

#: Runs one design's problem through its stages and returns its results (SI) by key.
RunDesign = Callable[[Any], Mapping[str, Any]]


class KnownResults(list):
    """The results a study may name: the exact keys listed, and keys that a declared pattern matches
    (``shaft.engine.order2.couple``), as ``accepts(key)`` tells."""

    def __init__(self, names: Iterable[str], accepts: Callable[[str], bool]) -> None:
        super().__init__(names)
        self._accepts = accepts

    def __contains__(self, key: object) -> bool:
        return list.__contains__(self, key) or (isinstance(key, str) and self._accepts(key))


def capability_results(problem: Any) -> dict[str, str]:
    """{key: SI unit} of every numeric result the tables of ``problem`` declare (its kind's main table and every
    other table the file has, but for the studies): what a run of one of its designs reports. Keys made at run
    time (``balance.<part>.mass``) are declared as patterns; :func:`unit_of` resolves them, and those a kind makes
    from the file's own names (``shaft.bearing.front.peak``) are listed here too."""
    present = {t for t in _tables(problem) if getattr(problem, t, None) is not None}
    made = made_keys(problem)
    if made is not None:  # the kind's own results are those a run of this file reports
        present -= set(KINDS)
    declared = {q.key: q.unit for q in catalogue()
                if q.producer in present and q.kind == "number" and "<" not in q.key}
    for table in sorted(present - set(KINDS)):
        declared |= table_keys(problem, table) or {}
    return declared | (made or {})


def table_keys(problem: Any, table: str) -> dict[str, str] | None:
    """{key: SI unit} of the results the capability ``table`` of ``problem`` makes from the file's names
    (:attr:`~machdyn.pipeline.Capability.result_keys`: ``parts.bearing.O.rating_life``), None for a table that
    does not list them."""
    if table not in CAPABILITIES or getattr(problem, table, None) is None:
        return None
    listing = capability(table).result_keys
    return dict(listing(problem)) if listing is not None else None


def unit_of(key: str, problem: Any) -> str | None:
    """The SI unit of a result ``key`` of ``problem`` declared by one of its tables (a pattern's too), or None if
    none declares it. A pattern of a kind that lists the keys it makes from the file's names
    (:attr:`~machdyn.pipeline.ProblemKind.result_keys`) accepts only those: ``shaft.bearing.<typo>.peak`` is no
    result of a file without that bearing; so for a capability's keys made from the file's names
    (:attr:`~machdyn.pipeline.Capability.result_keys`: ``parts.bearing.<joint>.rating_life`` of a joint the
    file's ``[parts]`` does not declare)."""
    present = {t for t in _tables(problem) if getattr(problem, t, None) is not None}
    found = find(key, catalogue())
    if found is None or found[0].producer not in present or found[0].kind != "number":
        return None
    if found[0].is_pattern and found[0].producer in KINDS:
        made = made_keys(problem)
        if made is not None:
            return made.get(key)
    elif found[0].is_pattern:  # a capability's key made from the file's names: a part the file declares
        made = table_keys(problem, found[0].producer)
        if made is not None:
            return made.get(key)
    return found[0].unit


#: The last few problems' keys made from their names, by the problem's identity (the problem is kept, so that
#: its id is not reused while it is cached).
_MADE: dict[int, tuple[Any, dict[str, str] | None]] = {}


def made_keys(problem: Any) -> dict[str, str] | None:
    """{key: SI unit} of the results ``problem``'s kind makes from the file's names, None for a kind that does not
    list them (or whose analysis of the file fails: its own check reports why)."""
    hit = _MADE.get(id(problem))
    if hit is not None and hit[0] is problem:
        return hit[1]
    made = None
    fields = getattr(type(problem), "model_fields", {})
    name = next((t for t in fields if t in KINDS and getattr(problem, t, None) is not None), None)
    listing = kind(name).result_keys if name is not None else None
    if listing is not None:
        try:
            made = dict(listing(problem))
        except (MachdynError, ArithmeticError, ValueError):
            made = None
    if len(_MADE) >= 8:
        _MADE.clear()
    _MADE[id(problem)] = (problem, made)
    return made


def _tables(problem: Any) -> list[str]:
    fields = getattr(type(problem), "model_fields", {})
    return [t for t in fields if t not in STUDIES]


def evaluate_designs(run_design: RunDesign, problems: Iterable[Any | None], keys: Iterable[str],
                     count: int, workers: int = 1) -> dict[str, np.ndarray]:
    """(count,) arrays of ``keys`` over the designs: ``problems`` yields each design's validated problem (None
    for a design that cannot be built), run by ``run_design`` — on ``workers`` local processes when more than
    one (``run_design`` and the problems must then pickle: a module's function, validated problems); NaN where a
    design's run fails or does not report the key."""
    wanted = tuple(keys)
    out = {k: np.full(count, math.nan) for k in wanted}
    todo = [(i, problem) for i, problem in enumerate(problems) if problem is not None]
    if workers > 1 and len(todo) > 1:
        found = run_in_parallel(run_portable, [(run_design, Portable(p), wanted) for _i, p in todo], workers)
    else:
        found = [run_one(run_design, p, wanted) for _i, p in todo]
    for (i, _problem), values in zip(todo, found, strict=True):
        for k, v in (values or {}).items():
            out[k][i] = v
    return out


def run_one(run_design: RunDesign, problem: Any, keys: Sequence[str]) -> dict[str, float] | None:
    """The finite scalar values of ``keys`` a run of one design reports, None where its run fails."""
    try:
        values = run_design(problem)
    except (MachdynError, ArithmeticError, ValueError):  # a design the run refuses or cannot analyse
        return None
    found = {}
    for k in keys:
        v = values.get(k)
        if v is not None and np.ndim(v) == 0 and math.isfinite(float(v)):
            found[k] = float(v)
    return found


class Portable:
    """A validated problem as a worker process receives it. A problem's class is made for its kind's tables
    (:func:`machdyn.kinds.problem_model`), so pickle cannot find it by name: the problem travels as its kind
    and its fields, and the worker puts them back into its own copy of that class (no validation again: the
    values are the ones validated here); a problem of another class travels as itself."""

    def __init__(self, problem: Any) -> None:
        self.problem = problem

    def __reduce__(self) -> tuple[Any, tuple]:
        cls = type(self.problem)
        name = next((k for k in KINDS if _model_of(k) is cls), None)
        if name is None:
            return (Portable, (self.problem,))
        return (_restore, (name, self.problem.__getstate__()))


def _model_of(kind_name: str) -> Any:
    return problem_model(kind_name)


def _restore(kind_name: str, state: Any) -> Portable:
    cls = _model_of(kind_name)
    problem = cls.__new__(cls)
    problem.__setstate__(state)
    return Portable(problem)


def run_portable(run_design: RunDesign, design: Portable, keys: Sequence[str]) -> dict[str, float] | None:
    """:func:`run_one` of a design sent to a worker process."""
    return run_one(run_design, design.problem, keys)


#: The pool of worker processes of the run (one size at a time), started at its first use.
_POOL: dict[int, Executor] = {}


def pool(workers: int) -> Executor:
    """A pool of ``workers`` local processes, kept for the later calls of this process: forked where the platform
    can (a worker starts in a fraction of a second with machdyn already imported; it runs designs only, never
    the caller's other threads' work), else spawned (each worker imports machdyn afresh, a few seconds)."""
    if workers not in _POOL:
        for old in _POOL.values():
            old.shutdown(wait=False, cancel_futures=True)
        _POOL.clear()
        method = "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn"
        _POOL[workers] = ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context(method))
    return _POOL[workers]


@atexit.register
def _close_pools() -> None:
    for executor in _POOL.values():
        executor.shutdown(wait=True, cancel_futures=True)
    _POOL.clear()


def run_in_parallel(fn: Callable[..., Any], calls: Sequence[tuple], workers: int) -> list[Any]:
    """``[fn(*args) for args in calls]``, in order, computed on ``workers`` local processes (a few calls per
    task, so that a short run is not dominated by the messages between the processes)."""
    chunk = max(1, math.ceil(len(calls) / (4 * workers)))
    return list(pool(workers).map(_star, [(fn, args) for args in calls], chunksize=chunk))


def _star(item: tuple[Callable[..., Any], tuple]) -> Any:
    fn, args = item
    return fn(*args)


def where_designs_ran(workers: int) -> str:
    """How a study's per-design runs ran, for its output: ``per design, 2 workers`` or ``per design, in this
    process``."""
    return f"per design, {workers} workers" if workers > 1 else "per design, in this process"
