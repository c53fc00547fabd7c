"""Designs of a design space, drawn partition by partition so that no more than one partition is ever in memory.

A design space is a tuple of explored quantities (:class:`~machdyn.studies.table.QuantityRange`) and a method:

- ``grid``: every combination of the quantities' values, the first quantity varying slowest (the order of
  ``itertools.product``); design ``i`` is found from ``i`` alone (:func:`numpy.unravel_index`).
- ``lhs``: a Latin hypercube (McKay, Beckman & Conover, Technometrics 21 (1979) 239-245) per partition, drawn
  by :class:`scipy.stats.qmc.LatinHypercube` from the generator seeded with ``(seed, partition index)``: each
  partition is a Latin hypercube of its own size, so partitions can be drawn in any order, on any worker.
- ``sobol``: one scrambled Sobol' sequence (Owen scrambling, :class:`scipy.stats.qmc.Sobol` seeded with
  ``seed``), cut into consecutive partitions; its balance properties hold for 2^m designs.

The same space, seed and partition size always give the same designs, whatever the number of workers.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Iterable, Iterator
from dataclasses import dataclass

import numpy as np

from ...errors import InputError
from ..table import QuantityRange

#: Designs per partition unless the problem says otherwise: 2^14, a power of 2 so that every Sobol' partition
#: is balanced, and small enough that a partition of 360 positions takes seconds.
DEFAULT_PARTITION = 1 << 14

#: How designs are drawn; "given": designs given by the caller (an optimiser's population), never drawn here.
METHODS = ("grid", "lhs", "sobol", "given")


@dataclass(frozen=True)
class DesignSpace:
    """The explored quantities, how designs are drawn, how many, from which seed, and in partitions of which
    size. ``samples`` is ignored by a grid (its size is the product of the numbers of values)."""

    quantities: tuple[QuantityRange, ...]
    method: str = "grid"
    samples: int | None = None
    seed: int = 0
    partition: int = DEFAULT_PARTITION

    def __post_init__(self) -> None:
        if self.method not in METHODS:
            raise InputError(f"The sampling method must be one of {', '.join(METHODS[:3])}; got '{self.method}'.")
        if not self.quantities:
            raise InputError("A design space needs at least one quantity; got none.")
        if self.partition < 1:
            raise InputError(f"The partition size must be >= 1 design; got {self.partition}.")
        if self.method == "grid" and any(q.values is None for q in self.quantities):
            raise InputError("A grid needs the values of every quantity (values = [...] or start, stop, count).")
        if self.method != "grid" and (self.samples is None or self.samples < 1):
            raise InputError(f"Method '{self.method}' needs samples >= 1; got {self.samples}.")

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(q.parameter for q in self.quantities)

    @property
    def shape(self) -> tuple[int, ...]:
        """The number of values of each quantity (a grid)."""
        return tuple(len(q.values or ()) for q in self.quantities)

    @property
    def size(self) -> int:
        """The number of designs."""
        if self.method == "grid":
            return math.prod(self.shape)
        assert self.samples is not None
        return int(self.samples)

    @property
    def partitions(self) -> int:
        return -(-self.size // self.partition)

    def bounds(self, index: int) -> tuple[int, int]:
        """The first design and one past the last of partition ``index``."""
        if not 0 <= index < self.partitions:
            raise InputError(f"Partition index must be in [0, {self.partitions}); got {index}.")
        start = index * self.partition
        return start, min(self.size, start + self.partition)


def _scale(unit: np.ndarray, space: DesignSpace) -> np.ndarray:
    """Points of the unit cube mapped onto each quantity's range, start + u (stop - start)."""
    start = np.array([q.start for q in space.quantities])
    stop = np.array([q.stop for q in space.quantities])
    return start + unit * (stop - start)


def grid_designs(space: DesignSpace, start: int, stop: int) -> np.ndarray:
    """Designs ``start`` to ``stop - 1`` of a grid, as an (n, K) array in SI."""
    index = np.unravel_index(np.arange(start, stop, dtype=np.int64), space.shape)
    columns = [np.asarray(q.values, dtype=float)[i] for q, i in zip(space.quantities, index, strict=True)]
    return np.stack(columns, axis=1)


def lhs_designs(space: DesignSpace, index: int) -> np.ndarray:
    """Partition ``index`` of a Latin-hypercube exploration, an (n, K) array in SI."""
    from scipy.stats import qmc

    start, stop = space.bounds(index)
    rng = np.random.default_rng([space.seed, index])
    unit = qmc.LatinHypercube(d=len(space.quantities), rng=rng).random(stop - start)
    return _scale(unit, space)


def _sobol(space: DesignSpace):
    from scipy.stats import qmc

    return qmc.Sobol(d=len(space.quantities), scramble=True, rng=np.random.default_rng(space.seed))


def _draw(sampler, n: int) -> np.ndarray:
    with warnings.catch_warnings():
        # scipy warns when a draw is not 2^m points; the exploration says so once, as a result warning.
        warnings.simplefilter("ignore", UserWarning)
        return sampler.random(n)


def partition_designs(space: DesignSpace, wanted: Iterable[int] | None = None) -> Iterator[tuple[int, np.ndarray]]:
    """(index, (n, K) designs in SI) of the partitions ``wanted`` (all by default), in increasing order.

    Grid and Latin-hypercube partitions are drawn from their index alone; the Sobol' sequence is walked once,
    skipping the partitions not wanted without drawing them (:meth:`scipy.stats.qmc.Sobol.fast_forward`)."""
    if space.method == "given":
        raise InputError("The designs of a population are given by the caller, not drawn.")
    todo = sorted(set(range(space.partitions) if wanted is None else wanted))
    if space.method == "sobol":
        sampler = _sobol(space)
        position = 0
        for index in todo:
            start, stop = space.bounds(index)
            if start > position:
                sampler.fast_forward(start - position)
            position = stop
            yield index, _scale(_draw(sampler, stop - start), space)
        return
    for index in todo:
        if space.method == "grid":
            yield index, grid_designs(space, *space.bounds(index))
        else:
            yield index, lhs_designs(space, index)


def designs(space: DesignSpace) -> np.ndarray:
    """Every design of a (small) space at once, an (N, K) array in SI; large spaces go by partitions."""
    parts = [values for _, values in partition_designs(space)]
    return np.concatenate(parts, axis=0)


def is_power_of_two(n: int) -> bool:
    return n > 0 and n & (n - 1) == 0
