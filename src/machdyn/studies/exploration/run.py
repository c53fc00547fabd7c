"""Explore the design space of a linkage problem: plan it from the problem's ``[sweep]``, run its partitions
(here or on Dask), keep them in a Parquet folder, and return counts, the best designs and a bounded sample.

```python
from machdyn.studies.exploration import explore
done = explore("examples/four_bar_press_explore.toml", workers=2)
done.best_frame().head()
done.frame()            # every design, read back from done.store
```
"""

from __future__ import annotations

import contextlib
import os
import tempfile
import time
from collections.abc import Callable
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import numpy as np

from ...errors import ProblemFileError
from ...linkage.sweep import DEFAULT_CHUNK_POSITIONS
from ...notebook import ShownInNotebook
from ...problem.build import build_mechanism, crank_angles
from ...problem.errors import did_you_mean
from ...reading import read_problem
from ...results.catalogue import label
from ...results.population import result_unit
from ..table import MAX_DESIGNS, explore_quantities
from .digest import Digest
from .evaluate import ExplorePlan, check_vectorised_build, evaluate_designs
from .execution import ANNOUNCE_AFTER, Progress, announce_estimate, current, progress_bar, run_partitions
from .sampling import DEFAULT_PARTITION, DesignSpace, partition_designs
from .store import PartitionStore, read_exploration

#: At most this many partitions (their numbers are listed in memory when a run starts).
MAX_PARTITIONS = 1_000_000


def plan_exploration(problem: Any, run_design: Any = None) -> ExplorePlan:
    """The plan of a linkage problem's ``[sweep]``: quantities checked, the space sized, the vectorised build
    of the models checked against design-by-design building on a few designs. Every mistake is reported with
    its path (:class:`~machdyn.errors.ProblemFileError`). ``run_design`` runs one design's problem through the
    file's stages, for the columns of a capability without a population form
    (:func:`~machdyn.studies.exploration.evaluate.evaluate_designs`)."""
    spec = problem.sweep
    quantities = explore_quantities(problem)
    space = DesignSpace(quantities, spec.sampling, spec.samples, spec.seed or 0, spec.partition or DEFAULT_PARTITION)
    if space.size > MAX_DESIGNS:
        raise ProblemFileError([("sweep", f"a sweep may have at most {MAX_DESIGNS:,} designs; this grid has "
                                          f"{space.size:,} ({' x '.join(map(str, space.shape))})")])
    if space.partitions > MAX_PARTITIONS:
        least = -(-space.size // MAX_PARTITIONS)
        raise ProblemFileError([("sweep.partition", f"{space.size:,} designs in partitions of {space.partition:,} "
                                                    f"make more than {MAX_PARTITIONS:,} partitions; give a partition "
                                                    f"of at least {least:,} designs")])
    plan = ExplorePlan(problem, space, crank_angles(problem), tuple(problem.output.shaking_moment_about),
                       spec.goal, min_transmission_angle=spec.transmission_limit, extra_columns=spec.extra_columns,
                       run_design=run_design)
    _, first = next(partition_designs(space, [0]))
    probe = first[np.unique([0, first.shape[0] // 2, first.shape[0] - 1])]
    plan = replace(plan, vectorised=check_vectorised_build(plan, probe))
    columns = evaluate_designs(plan, probe[:1])
    if plan.objective not in columns:
        known = [c for c in columns if c.startswith("joint.")]
        raise ProblemFileError([("sweep.objective", f"'{plan.objective}' is not a result of this mechanism"
                                                    f"{did_you_mean(plan.objective, known)} (joints: "
                                                    f"{', '.join(known)})")])
    return plan


def column_units(plan: ExplorePlan, columns: list[str]) -> dict[str, tuple[str, str]]:
    """(SI unit, label) of each column of an exploration (the results' from the catalogue)."""
    mech = build_mechanism(plan.problem)
    out: dict[str, tuple[str, str]] = {"design": ("", "Design number")}
    out |= {q.parameter: (q.si_unit, q.parameter) for q in plan.space.quantities}
    for name in columns:
        found = label(name)
        if name not in out and found is not None:
            out[name] = (result_unit(name, mech), found.text)
    return {k: out[k] for k in columns if k in out}


@dataclass(frozen=True)
class Exploration(ShownInNotebook):
    """An explored design space: the plan, the Parquet folder holding every design (``store``), the digest
    (counts, best designs, a bounded sample of the regular designs), partitions computed now and reused from
    disk, the seconds it took and where it ran, and the (SI unit, label) of every column."""

    plan: ExplorePlan
    store: Path
    digest: Digest
    computed: int
    reused: int
    seconds: float
    where: str
    units: dict[str, tuple[str, str]]
    notes: tuple[str, ...] = ()
    pending: Path | None = None
    #: the nominal and the best designs analysed one by one for playback (filled in by the ``[sweep]`` stage)
    views: tuple = ()

    @property
    def designs(self) -> int:
        return self.digest.designs

    def frame(self):
        """Every design as a pandas DataFrame (SI; for spaces that fit in memory)."""
        if self.pending is not None and self.pending.is_dir():  # not swapped into the store yet
            return read_exploration(self.pending)
        return read_exploration(self.store)

    def best_frame(self):
        """The best regular designs, lowest objective first (SI)."""
        import pandas as pd

        return pd.DataFrame(self.digest.best)

    def sample_frame(self):
        """A uniform sample of at most 2,000 regular designs, in design order (SI)."""
        import pandas as pd

        return pd.DataFrame(self.digest.sample_in_design_order())


class ExplorationInterrupted(KeyboardInterrupt):
    """An exploration stopped by Ctrl-C: ``done`` of ``total`` partitions are complete in ``store`` (each
    partition file is written whole or not at all); running the same problem again resumes from them."""

    def __init__(self, store: Path, done: int, total: int):
        super().__init__(f"{done} of {total} partitions in {store}")
        self.store, self.done, self.total = store, done, total

    @property
    def message(self) -> str:
        return (f"{self.done} of {self.total} partition(s) of the design-space exploration are on disk in "
                f"{self.store}; run the same command again to resume: they are reused, only the other "
                f"{self.total - self.done} computed")


def _store_folder(plan: ExplorePlan, given: str | os.PathLike | None, default: str | os.PathLike | None,
                  source: str | None) -> Path:
    """The Parquet folder: the one given to the call, else ``[sweep] store`` (relative to the problem file), else
    the execution settings' default (the command line's output folder), else one named by the exploration in
    the temporary directory (so that a rerun resumes)."""
    if given is not None:
        return Path(given)
    spec_store = store_in_file(plan.problem, source)
    if spec_store is not None:
        return spec_store
    if default is not None:
        return Path(default)
    return Path(tempfile.gettempdir()) / f"machdyn-explore-{plan.fingerprint[:16]}"


def store_in_file(problem: Any, source: str | os.PathLike | None) -> Path | None:
    """The folder ``[sweep] store`` names, against the problem file's folder (the working folder for text given
    directly), or None. It must lie inside that folder, and not be the folder itself: a problem file cannot make
    a run write or delete files elsewhere. Raises :class:`~machdyn.errors.ProblemFileError` naming the field."""
    name = problem.sweep.store
    if name is None:
        return None
    base = Path(source).parent if source else Path.cwd()
    folder = Path(name) if Path(name).is_absolute() else base / name
    try:
        resolved, inside = folder.resolve(), base.resolve()
    except (OSError, RuntimeError):  # a loop of symbolic links
        raise ProblemFileError([("sweep.store", f"'{name[:80]}' is a loop of symbolic links")]) from None
    if not resolved.is_relative_to(inside) or resolved == inside:
        raise ProblemFileError([("sweep.store", f"must name a folder inside the problem file's folder {inside} "
                                                f"(e.g. \"press.parquet\"); got '{name[:80]}'")])
    return folder


def _estimate(plan: ExplorePlan, workers: int | None) -> None:
    """Announce the time and memory of a long exploration, from the time of a small batch of its designs."""
    if current().estimate is None:
        return
    batch = next(partition_designs(plan.space, [0]))[1][:32]
    began = time.perf_counter()
    evaluate_designs(plan, batch)
    per_design = (time.perf_counter() - began) / max(batch.shape[0], 1)
    seconds = per_design * plan.space.size / max(workers or 1, 1)
    if seconds < ANNOUNCE_AFTER:
        return
    positions = plan.angles.size
    # a worker holds its partition's results and the engine's chunk of positions (about 60 doubles each)
    memory = 8.0 * (60 * min(plan.space.partition * positions, DEFAULT_CHUNK_POSITIONS)
                    + 32 * plan.space.partition)
    announce_estimate(seconds, f"{plan.space.size:,} designs x {positions:,} crank positions on "
                               f"{workers or 1} process(es)", memory)


def _where(workers: int | None, scheduler: str | None, spec: Any) -> tuple[int | None, str | None]:
    """The first of the call, the execution settings in force and the [sweep] table that says where to run."""
    settings = current()
    for w, s in ((workers, scheduler), (settings.workers, settings.scheduler), (spec.workers, spec.scheduler)):
        if w is not None or s is not None:
            return (None, s) if s is not None else (w, None)
    return None, None


def explore(
    problem: Any,
    *,
    store: str | os.PathLike | None = None,
    workers: int | None = None,
    scheduler: str | None = None,
    progress: Progress | bool | None = None,
    on_partition: Callable[[int], None] | None = None,
    source: str | None = None,
    replace: bool | None = None,
    run_design: Any = None,
) -> Exploration:
    """Explore the design space of a linkage problem with a ``[sweep]`` table (a problem, a path or TOML text).

    store : the Parquet folder (default: ``[sweep] store`` relative to the problem file, then the execution
        settings' store, then a folder named by the exploration in the temporary directory). Partitions already
        there for the same problem and design space are kept, not recomputed.
    workers, scheduler : run on a local Dask cluster of ``workers`` processes, or on the Dask scheduler at this
        address (default: the execution settings', then ``[sweep]``'s, then in this process).
    progress : ``progress(designs done, designs in all)`` as partitions finish, or True for a progress bar on
        the terminal.
    on_partition : ``on_partition(index)`` after each partition computed is written.
    replace : replace a store that is not this problem's (another problem file's, or partitions without a
        manifest) instead of refusing it (default: the execution settings').
    run_design : runs one design's problem through the file's stages (a module's function, so that Dask can
        send it), for the columns of a capability without a population form; the columns of a capability with
        one come from it, every design of a partition at once.
    """
    if isinstance(problem, str | os.PathLike):
        loaded = read_problem(problem)
        problem, source = loaded.spec, loaded.source if source is None else source
    plan = plan_exploration(problem, run_design)
    settings = current()
    folder = _store_folder(plan, store, settings.store, source)
    workers, scheduler = _where(workers, scheduler, problem.sweep)
    probe = evaluate_designs(plan, next(partition_designs(plan.space, [0]))[1][:1])
    units = column_units(plan, ["design", *probe])
    info = {"method": plan.space.method, "seed": plan.space.seed, "designs": plan.space.size,
            "partition": plan.space.partition, "partitions": plan.space.partitions,
            "columns": {k: {"unit": u, "label": label} for k, (u, label) in units.items()}}
    _estimate(plan, workers)
    keeper = PartitionStore(folder, plan.fingerprint, info, source=source,
                            replace=bool(replace if replace is not None else settings.replace))
    report = progress if progress is not None else settings.progress
    try:
        with contextlib.ExitStack() as stack:
            if report is True:
                report = stack.enter_context(progress_bar(f"{plan.space.size:,} designs"))
            try:
                stats = run_partitions(plan, keeper, units, workers=workers, scheduler=scheduler,
                                       progress=report or None, on_partition=on_partition)
            except KeyboardInterrupt as stop:  # kept as the cause: a SIGTERM stays told apart from Ctrl-C
                raise ExplorationInterrupted(folder, len(keeper.done()), plan.space.partitions) from stop
    except BaseException:
        keeper.close()
        raise
    swap = keeper.finish(defer=settings.deferred is not None)
    if swap is not None and settings.deferred is not None:
        settings.deferred.append(swap)
    return Exploration(plan, folder, stats.digest, stats.computed, stats.reused, stats.seconds, stats.where, units,
                       tuple(keeper.notes), swap[0] if swap is not None else None)
