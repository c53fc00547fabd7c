"""Where the partitions of an exploration run: in this process (the default: nothing to start, Dask not even
imported), on a local Dask cluster of worker processes (``workers=N``, loopback only), or on a running Dask
cluster by its address (``scheduler="tcp://host:8786"``).

The client draws each partition's designs (small: partition x quantities floats), sends them with the plan to
a worker, and writes each partition's columns to the Parquet folder as soon as it comes back; at most two
partitions per worker are in flight, so memory stays bounded on the client and on every worker for any number
of designs. Workers need machdyn importable (the same version as the client); they need no shared disk.
"""

from __future__ import annotations

import asyncio
import contextlib
import os
import time
from collections.abc import Callable, Iterator
from concurrent.futures import CancelledError, ThreadPoolExecutor
from contextvars import ContextVar
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

from rich.console import Console
from rich.progress import BarColumn, MofNCompleteColumn, TextColumn, TimeRemainingColumn
from rich.progress import Progress as RichProgress

from ...errors import InputError, OperationalError
from ...kinds import catalogue
from ...results.catalogue import better_of
from .digest import Digest
from .evaluate import ExplorePlan, evaluate_partition
from .sampling import partition_designs
from .store import PartitionStore

#: ``progress(designs done, designs in all)``
Progress = Callable[[int, int], None]

#: Times a partition lost with a worker is sent again before the run gives up.
RETRIES = 3
#: Seconds allowed to reach a Dask scheduler (TCP connection and Dask's handshake) and for it to have a worker.
CONNECT_TIMEOUT = 10.0


def worker_limit() -> int:
    """The most local worker processes a run may start: the machine's processors (``os.cpu_count()``; each
    worker computes with one thread, so more only add memory), or ``MACHDYN_MAX_WORKERS`` where it is set."""
    given = os.environ.get("MACHDYN_MAX_WORKERS", "").strip()
    if given.isdigit() and int(given) >= 1:
        return int(given)
    return max(1, os.cpu_count() or 1)


def workers_error(workers: int) -> str | None:
    """Why ``workers`` local processes are refused on this machine, or None."""
    limit = worker_limit()
    if workers > limit:
        return (f"must be at most {limit} (the processors of this machine; set MACHDYN_MAX_WORKERS to allow more); "
                f"got {workers}")
    return None


def probe_scheduler(address: str, timeout: float = CONNECT_TIMEOUT) -> None:
    """Connect to ``address`` and complete Dask's handshake within ``timeout`` seconds, or raise
    :class:`~machdyn.errors.OperationalError` saying why (nothing listens there, or what answers is not Dask)."""
    from distributed.comm import connect


    async def handshake() -> None:
        comm = await connect(address, timeout=timeout)
        await comm.close()


    try:
        with ThreadPoolExecutor(1) as pool:  # its own event loop, also where the caller runs one (a notebook)
            pool.submit(asyncio.run, asyncio.wait_for(handshake(), timeout)).result()
    except TimeoutError:
        raise OperationalError(f"no Dask scheduler answered at {address} within {timeout:g} s (nothing listens "
                               f"there, or what listens is not a Dask scheduler)") from None
    except OSError as exc:
        raise OperationalError(f"cannot reach the Dask scheduler at {address}: {str(exc)[:200]}") from None
    except Exception as exc:  # noqa: BLE001 - a peer that is not Dask can make the handshake fail in many ways
        raise OperationalError(f"what answers at {address} is not a Dask scheduler ({type(exc).__name__})") from None


@dataclass(frozen=True)
class Execution:
    """How and where to run: ``workers`` local worker processes, or ``scheduler`` the address of a running Dask
    scheduler; ``store`` the Parquet folder when the problem names none; ``progress`` called as partitions
    finish. None: not set."""

    workers: int | None = None
    scheduler: str | None = None
    store: str | Path | None = None
    progress: Progress | None = None
    #: Called with a line of text estimating the time (and memory) of a long run before it starts.
    estimate: Callable[[str], None] | None = None
    #: When a list: an exploration of a changed problem is not swapped into its store when it completes; its
    #: (pending folder, store) is appended here, for the caller to swap in with its other outputs.
    deferred: list | None = None
    #: True: a folder that is not this problem's store (another problem file's, or partitions without a
    #: manifest) is replaced rather than refused (the command line's ``--replace``).
    replace: bool | None = None


_CURRENT: ContextVar[Execution | None] = ContextVar("machdyn_explore_execution", default=None)


def current() -> Execution:
    """The execution settings in force (see :func:`execution`)."""
    return _CURRENT.get() or Execution()


@contextlib.contextmanager
def execution(**settings: Any) -> Iterator[Execution]:
    """Set where explorations run inside a ``with`` block (the command line's ``--workers``, ``--scheduler``
    and ``--out``): ``with execution(workers=2): run_problem(...)``. Settings given override those in force."""
    now = replace(current(), **{k: v for k, v in settings.items() if v is not None})
    if now.workers is not None and now.workers < 1:
        raise InputError(f"workers must be >= 1; got {now.workers}.")
    if now.workers is not None and workers_error(now.workers):
        raise InputError(f"workers {workers_error(now.workers)}.")
    token = _CURRENT.set(now)
    try:
        yield now
    finally:
        _CURRENT.reset(token)


#: What a stopped run that is not a design-space exploration keeps (the command line's message): nothing; a sweep
#: run variant by variant, an optimisation, a single analysis all start again from their beginning.
RESTARTS = ("the outputs were not replaced, and nothing of this run was kept: run again, it starts from the "
            "beginning (only a design-space exploration, [sweep] with a method, resumes from its finished "
            "partitions)")


def ignored_where(problem: Any, warnings: list[str]) -> list[str]:
    """A warning when ``workers`` or ``scheduler`` is set (``--workers``, ``--scheduler``) for a run they do not
    act on: they spread the designs of a design-space exploration only (a sweep run variant by variant says so
    in its own ``warnings``)."""
    settings = current()
    given = [name for name, value in (("--workers", settings.workers), ("--scheduler", settings.scheduler))
             if value is not None]
    if not given or getattr(getattr(problem, "sweep", None), "is_exploration", False) or \
            any("--workers" in w for w in warnings):
        return []
    return [f"{' and '.join(given)} {'were' if len(given) > 1 else 'was'} ignored: only a design-space exploration "
            "([sweep] with a method) runs on workers; this run ran in this process."]


#: Runs estimated to take less than this [s] are not announced.
ANNOUNCE_AFTER = 30.0


def announce_estimate(seconds: float, what: str, memory: float | None = None) -> None:
    """Tell the user (through the execution settings' ``estimate``) how long ``what`` will take, if long."""
    report = current().estimate
    if report is None or not seconds >= ANNOUNCE_AFTER:
        return
    text = f"{what}: about {_duration(seconds)}"
    if memory is not None:
        text += f" and {memory / 1e6:,.0f} MB per process"
    report(text + " (stop it with Ctrl-C; run machdyn with --max-time to bound it)")


def _duration(seconds: float) -> str:
    if seconds < 120:
        return f"{seconds:.0f} s"
    if seconds < 7200:
        return f"{seconds / 60:.0f} min"
    if seconds < 172800:
        return f"{seconds / 3600:.1f} h"
    return f"{seconds / 86400:.1f} days"


@contextlib.contextmanager
def progress_bar(description: str) -> Iterator[Progress]:
    """A rich progress bar of designs done on the terminal (stderr), as a ``progress`` callback."""
    with RichProgress(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(), TimeRemainingColumn(),
                  console=Console(stderr=True), transient=True) as bar:
        task = bar.add_task(description, total=None)

        def update(done: int, total: int) -> None:
            bar.update(task, completed=done, total=total)

        yield update


@dataclass(frozen=True)
class RunStats:
    """How a run of partitions went: the digest, partitions computed now and read back from disk, seconds."""

    digest: Digest
    computed: int
    reused: int
    seconds: float
    where: str


def run_partitions(
    plan: ExplorePlan,
    store: PartitionStore,
    units: dict[str, tuple[str, str]],
    *,
    workers: int | None = None,
    scheduler: str | None = None,
    progress: Progress | None = None,
    on_partition: Callable[[int], None] | None = None,
) -> RunStats:
    """Evaluate every partition of ``plan`` not yet in ``store``, write each as it finishes, and digest all.

    ``on_partition(index)`` is called after each partition computed now is written (an exception raised there
    stops the run; the partitions written stay and a later run resumes from them)."""
    started = time.perf_counter()
    space = plan.space
    digest = Digest(plan.objective, better_of(plan.objective, catalogue()))
    have: set[int] = set()
    done = 0
    for index in sorted(store.done()):
        columns = store.verified(index, space.bounds(index)) if index < space.partitions else None
        if columns is None:
            continue
        have.add(index)
        digest.add(columns, index, space.seed)
        done += columns["design"].size
    pending = [i for i in range(space.partitions) if i not in have]
    if progress is not None:
        progress(done, space.size)

    def finished(index: int, columns: dict) -> None:
        nonlocal done
        store.write(index, columns, units)
        digest.add(columns, index, space.seed)
        done += columns["design"].size
        if progress is not None:
            progress(done, space.size)
        if on_partition is not None:
            on_partition(index)

    if not pending:
        where = "nothing to compute"
    else:
        where = run_tasks(evaluate_partition, plan, partition_designs(space, pending), finished, workers=workers,
                          scheduler=scheduler)
    return RunStats(digest, len(pending), len(have), time.perf_counter() - started, where)


def run_tasks(task: Callable, plan: Any, items: Iterator[tuple[int, Any]], finished: Callable[[int, Any], None], *,
              workers: int | None = None, scheduler: str | None = None) -> str:
    """Call ``finished(index, task(plan, index, values))`` for each ``(index, values)`` of ``items``: here, or on
    a local Dask cluster of ``workers`` processes, or on the Dask scheduler at ``scheduler``, with at most two
    tasks per worker in flight (in the order they finish). Returns where they ran."""
    if workers is None and scheduler is None:
        for index, values in items:
            finished(index, task(plan, index, values))
        return "in process"
    from distributed import Client, LocalCluster, as_completed


    cluster = None
    if scheduler is not None:
        probe_scheduler(scheduler)
        try:
            client = Client(scheduler, timeout=f"{CONNECT_TIMEOUT:g}s")
            client.wait_for_workers(1, timeout=CONNECT_TIMEOUT)
        except (OSError, TimeoutError) as exc:
            raise OperationalError(f"the Dask scheduler at {scheduler} has no worker, or was lost, within "
                                   f"{CONNECT_TIMEOUT:g} s ({type(exc).__name__})") from None
        where = f"Dask cluster at {scheduler}"
    else:
        assert workers is not None
        problem = workers_error(workers)
        if problem is not None:
            raise InputError(f"workers {problem}.")
        import dask

        # Dask sets MALLOC_TRIM_THRESHOLD_ in its workers, which turns off glibc's adaptive mmap threshold: every
        # large NumPy temporary of the engine is then mapped and unmapped anew, about 4x slower (measured).
        try:
            with dask.config.set({"distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": None}):
                cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                                       dashboard_address="127.0.0.1:0", silence_logs=40)
            client = Client(cluster)
        except (OSError, TimeoutError) as exc:
            raise OperationalError(f"the local Dask cluster of {workers} worker(s) could not start: "
                                   f"{str(exc)[:200]}") from None
        where = f"local Dask cluster of {workers} worker process(es)"
    try:
        width = max(1, len(client.scheduler_info().get("workers", {})) or (workers or 1))
        shared = client.scatter(plan, broadcast=True)
        source = iter(items)
        running = as_completed()
        futures: dict[Any, tuple[int, Any, Any]] = {}

        attempts: dict[int, int] = {}

        def send(index: int, values: Any) -> None:
            # Scattered, and released with the result: designs passed inline to submit stay referenced by the
            # client until it closes, so its memory would grow with the number of partitions (measured).
            for attempt in range(RETRIES + 1):
                try:
                    sent = client.scatter(values, hash=False)
                    future = client.submit(task, shared, index, sent, pure=False)
                    break
                except _lost_cluster() as exc:  # the worker chosen went away: wait for another
                    if attempt == RETRIES:
                        raise OperationalError(f"the Dask cluster lost its workers while partition {index} was "
                                               f"sent ({type(exc).__name__}); run again to resume") from None
                    time.sleep(1.0)
            futures[future] = (index, values, sent)
            running.add(future)

        def submit() -> bool:
            item = next(source, None)
            if item is None:
                return False
            send(*item)
            return True

        for _ in range(2 * width):
            if not submit():
                break
        for future in running:
            index, values, sent = futures.pop(future)
            try:
                columns = future.result()
            except _lost_work() as exc:
                # A worker was lost with this partition (or its designs): the partition is computed again.
                future.release()
                sent.release()
                attempts[index] = attempts.get(index, 0) + 1
                if attempts[index] > RETRIES:
                    raise OperationalError(f"the Dask cluster lost partition {index} {attempts[index]} times "
                                           f"({type(exc).__name__}: {str(exc)[:160]}); run again to resume") from None
                send(index, values)
                continue
            future.release()
            sent.release()
            finished(index, columns)
            submit()
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    return where


def _lost_work() -> tuple[type[BaseException], ...]:
    """What a partition's result raises when a worker went away with it (or with its designs)."""
    return (*_lost_cluster(), CancelledError)


def _lost_cluster() -> tuple[type[BaseException], ...]:
    """The exceptions by which Dask says a worker or the scheduler went away (not an error of the task)."""
    from distributed.comm.core import CommClosedError
    from distributed.scheduler import KilledWorker

    return (KilledWorker, CommClosedError, OSError, TimeoutError)
