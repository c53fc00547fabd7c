"""Evaluate one partition of designs: build the partition's engine model with one array per explored quantity
and evaluate it with the studies' evaluator (:class:`machdyn.studies.evaluator.PopulationEvaluator`, with which
sweeps, explorations and the optimiser evaluate designs; its columns are catalogue keys).

A partition's model is built by putting the partition's values, as arrays, into the validated problem and
building it once (every builder and load of the engine broadcasts over designs). Before a run, a few designs
built that way are compared with the same designs built one by one (:func:`check_vectorised_build`); where a
quantity does not broadcast, every partition is built design by design and stacked instead: slower, same
result.
"""

from __future__ import annotations

import hashlib
import json
import math
from dataclasses import dataclass, fields, is_dataclass, replace
from typing import Any

import numpy as np

from ... import __version__
from ...errors import ProblemFileError
from ...kinds import CAPABILITIES, catalogue
from ...linkage import stack_designs
from ...problem.build import build_mechanism
from ...results.catalogue import find
from ...results.population import DEFAULT_MIN_TRANSMISSION_DEG, sweep_columns
from ..evaluator import PopulationEvaluator
from ..per_design import capability_results
from ..table import substitute
from .sampling import DesignSpace

#: Changes when the columns an exploration keeps change, so that partitions stored before are not reused.
COLUMNS_VERSION = 2

#: Quantities of the drive: passed to the engine per design, not built into the model.
DRIVE = ("drive.speed", "drive.acceleration")


@dataclass(frozen=True)
class ExplorePlan:
    """Everything a worker needs to evaluate any partition: the validated problem, the design space, the crank
    angles [rad], the point the shaking moment is taken about [m], and whether models are built vectorised."""

    problem: Any
    space: DesignSpace
    angles: np.ndarray
    about: tuple[float, float]
    objective: str
    vectorised: bool = True
    #: the threshold [rad] of a design's poor_transmission (see machdyn.results.population)
    min_transmission_angle: float = math.radians(DEFAULT_MIN_TRANSMISSION_DEG)
    #: results kept besides the default columns ([sweep] columns, catalogue keys)
    extra_columns: tuple[str, ...] = ()
    #: runs one design's problem through the file's stages, for the columns of a capability that declares no
    #: population form (:mod:`machdyn.studies.per_design`); None: such columns are NaN (a check without a run)
    run_design: Any = None

    @property
    def fingerprint(self) -> str:
        """A digest of everything that decides the results (problem, space, angles), not of where they run."""
        spec = self.problem.model_dump(mode="json", exclude={"sweep", "meta"})  # a new title keeps the results
        data = {
            "version": __version__,
            "problem": spec,
            "space": [self.space.method, self.space.samples, self.space.seed, self.space.partition,
                      [[q.parameter, q.values, q.start, q.stop] for q in self.space.quantities]],
            "angles": [float(a) for a in self.angles],
            "about": list(self.about),
            "columns": [self.objective, self.min_transmission_angle, COLUMNS_VERSION, list(self.extra_columns)],
        }
        return hashlib.sha256(json.dumps(data, sort_keys=True).encode()).hexdigest()


def _single(plan: ExplorePlan, row: np.ndarray):
    return build_mechanism(substitute(plan.problem, {p: float(v) for p, v in zip(plan.space.names, row,
                                                                                   strict=True)}))


def _with_design_axis(mech, n: int):
    """``mech`` with a designs axis of length ``n`` even when no model parameter varies (a swept drive), so that
    per-design drive values are never mistaken for per-position ones."""
    if mech.design_count is not None:
        return mech
    crank = mech.body(mech.crank.body)
    bodies = tuple(replace(b, mass=np.full(n, float(b.mass))) if b is crank else b for b in mech.bodies)
    return replace(mech, bodies=bodies)


def build_designs(plan: ExplorePlan, values: np.ndarray) -> tuple[Any, Any, Any]:
    """(model with a designs axis, crank speed, crank acceleration) of the designs ``values`` (n, K) in SI; the
    drive values are (n, 1) columns when explored, floats otherwise."""
    n = values.shape[0]
    names = plan.space.names
    model_values = {p: values[:, k] for k, p in enumerate(names) if p not in DRIVE}
    if not model_values:
        mech = build_mechanism(plan.problem)
    elif plan.vectorised:
        mech = build_mechanism(substitute(plan.problem, model_values))
    else:
        mech = stack_designs([_single(plan, row) for row in values])
    drive = plan.problem.drive
    speed: Any = float(drive.speed)
    accel: Any = float(drive.acceleration)
    if "drive.speed" in names:
        speed = values[:, names.index("drive.speed"), None].copy()
    if "drive.acceleration" in names:
        accel = values[:, names.index("drive.acceleration"), None].copy()
    return _with_design_axis(mech, n), speed, accel


def evaluate_designs(plan: ExplorePlan, values: np.ndarray) -> dict[str, np.ndarray]:
    """The per-design results of the designs ``values`` (n, K) in SI: one array per column, quantities first
    (SI), then the status columns (``assembled``, ``regular``, ``status``...) and the results of
    :func:`~machdyn.results.population.sweep_columns` under their catalogue keys."""
    mech, speed, accel = build_designs(plan, values)
    machine = getattr(plan.problem.mechanism, "machine", None)
    by_capability = capability_columns(plan)
    wanted = sweep_columns(mech, machine, plan.objective,
                           tuple(k for k in plan.extra_columns if k not in by_capability))
    evaluator = PopulationEvaluator(plan.angles, speed, accel, plan.about, machine, plan.min_transmission_angle,
                                    run_design=plan.run_design, problem=plan.problem, varied=plan.space.names)
    if by_capability:
        # A capability's columns: from its population form, every design at once, where the capability declares
        # one; else by a run of each regular design (NaN where no run is at hand, as in a check).
        res = evaluator(mech, wanted, values.shape[0], by_capability if plan.run_design is not None else (),
                        lambda i: _problem_of(plan, values[i]))
        if plan.run_design is None:
            res |= evaluator.at_once(mech, by_capability, values.shape[0], res)
        res |= {k: np.full(values.shape[0], np.nan) for k in by_capability if k not in res}
    else:
        res = evaluator.vectorised(mech, wanted)
    missing = [(f"sweep.columns[{i}]", f"'{k}' is not a result of this mechanism")
               for i, k in enumerate(plan.extra_columns) if k not in res]
    if missing:
        raise ProblemFileError(missing)
    columns: dict[str, np.ndarray] = {p: np.ascontiguousarray(values[:, k]) for k, p in enumerate(plan.space.names)}
    for key, data in res.items():
        if key != "assembled_fraction":
            columns[key] = data if data.dtype.kind in "fb" else data.astype(str)
    return columns


def capability_columns(plan: ExplorePlan) -> tuple[str, ...]:
    """The ``[sweep] columns`` that are results of the file's capability tables (``parts.utilisation.max``), not
    of its linkage (which the population's engine call gives)."""
    declared = capability_results(plan.problem)
    quantities = catalogue()

    def of_a_capability(key: str) -> bool:
        found = find(key, quantities)
        return key in declared and found is not None and found[0].producer in CAPABILITIES

    return tuple(k for k in plan.extra_columns if of_a_capability(k))


def _problem_of(plan: ExplorePlan, row: np.ndarray) -> Any:
    """The validated problem of one design of the space (its quantities set), for a run of it."""
    return substitute(plan.problem, {p: float(v) for p, v in zip(plan.space.names, row, strict=True)})


def evaluate_partition(plan: ExplorePlan, index: int, values: np.ndarray) -> dict[str, np.ndarray]:
    """The columns of partition ``index`` (its designs ``values``), with the global ``design`` number first."""
    start, stop = plan.space.bounds(index)
    if values.shape != (stop - start, len(plan.space.quantities)):
        raise ValueError(f"partition {index} holds {stop - start} designs of {len(plan.space.quantities)} "
                         f"quantities; got values of shape {values.shape}")
    return {"design": np.arange(start, stop, dtype=np.int64), **evaluate_designs(plan, values)}


def _same(a: Any, b: Any, n: int) -> bool:
    """True if two models hold the same numbers for each of ``n`` designs (arrays or scalars broadcast)."""
    if isinstance(a, int | float | np.ndarray) and not isinstance(a, bool):
        if not isinstance(b, int | float | np.ndarray) or isinstance(b, bool):
            return False
        x, y = (np.broadcast_to(np.asarray(v, dtype=float), (n,)) for v in (a, b))
        return bool(np.allclose(x, y, rtol=1e-12, atol=0.0, equal_nan=True))
    if is_dataclass(a) and not isinstance(a, type):
        return type(a) is type(b) and all(_same(getattr(a, f.name), getattr(b, f.name), n)
                                          for f in fields(a) if f.init)
    if isinstance(a, dict):
        return isinstance(b, dict) and list(a) == list(b) and all(_same(a[k], b[k], n) for k in a)
    if isinstance(a, tuple | list):
        return isinstance(b, tuple | list) and len(a) == len(b) and all(_same(x, y, n) for x, y in
                                                                           zip(a, b, strict=True))
    return bool(a == b)


def check_vectorised_build(plan: ExplorePlan, values: np.ndarray) -> bool:
    """True if the designs ``values`` (a few rows) built at once equal the same designs built one by one.

    Raises :class:`~machdyn.errors.ProblemFileError` if a design cannot be built at all (a bad combination of
    values); any failure of the vectorised build alone only means the slower build is used."""
    try:
        one_by_one = stack_designs([_single(plan, row) for row in values])
    except ProblemFileError as exc:
        shown = ", ".join(f"{p} = {v:.6g}" for p, v in zip(plan.space.names, values[0], strict=True))
        raise ProblemFileError([("sweep", f"the design ({shown}) cannot be built: {path}: {msg}")
                                for path, msg in exc.problems]) from None
    try:
        at_once, _, _ = build_designs(replace(plan, vectorised=True), values)
    except Exception:  # noqa: BLE001 - a quantity that does not broadcast: build design by design instead
        return False
    return _same(at_once, _with_design_axis(one_by_one, values.shape[0]), values.shape[0])
