"""What an exploration keeps in memory however many designs it has: counts, the best designs and a bounded
uniform sample of the regular designs, merged partition by partition.

The best designs are the ``best`` regular designs best by the objective's declared direction (the lowest of a
result of which less is better, the highest of one of which more is; ties broken by design number); the
sample is the ``sample`` regular designs with the lowest random keys, each design's key drawn from its
partition's own generator (seeded with the partition index), so the sample is uniform without replacement and
the same whatever the order in which partitions finish or are read back from disk (a resumed run gives the same
digest as an uninterrupted one).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ...results.catalogue import as_cost

BEST = 20
SAMPLE = 2000


def _take(columns: dict[str, np.ndarray], rows: np.ndarray) -> dict[str, np.ndarray]:
    return {k: v[rows] for k, v in columns.items()}


def _concat(a: dict[str, np.ndarray], b: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    if not a:
        return dict(b)
    if not b:
        return dict(a)
    return {k: np.concatenate([a[k], b[k]]) for k in a}


def _lowest(columns: dict[str, np.ndarray], key: str, count: int, better: str = "lower") -> dict[str, np.ndarray]:
    """The ``count`` rows best by ``key`` (the lowest, or the highest when ``better`` is "higher"; ties by design
    number), in that order."""
    if not columns:
        return {}
    order = np.lexsort((columns["design"], as_cost(columns[key], better)))[:count]
    return _take(columns, order)


@dataclass
class Digest:
    """Counts, best designs (``best`` columns, sorted by the objective) and a sample (``sample`` columns with a
    ``_key`` column) of the designs seen so far."""

    objective: str
    #: the objective's declared better direction (:data:`machdyn.results.catalogue.BETTER`)
    better: str = "lower"
    designs: int = 0
    assembled: int = 0
    regular: int = 0
    best: dict[str, np.ndarray] = field(default_factory=dict)
    sample: dict[str, np.ndarray] = field(default_factory=dict)
    best_size: int = BEST
    sample_size: int = SAMPLE

    def add(self, columns: dict[str, np.ndarray], index: int, seed: int) -> None:
        """Fold in the columns of partition ``index``."""
        regular = np.asarray(columns["regular"], dtype=bool) & np.isfinite(columns[self.objective])
        self.designs += int(columns["design"].size)
        self.assembled += int(np.count_nonzero(columns["assembled"]))
        self.regular += int(np.count_nonzero(regular))
        rows = np.flatnonzero(regular)
        feasible = _take(columns, rows)
        keys = np.random.default_rng([seed, index, 1]).random(columns["design"].size)[rows]
        self.best = _lowest(_concat(self.best, feasible), self.objective, self.best_size, self.better)
        self.sample = _lowest(_concat(self.sample, {**feasible, "_key": keys}), "_key", self.sample_size)

    def sample_in_design_order(self) -> dict[str, np.ndarray]:
        """The sample without its keys, in design order."""
        if not self.sample:
            return {}
        order = np.argsort(self.sample["design"], kind="stable")
        return {k: v[order] for k, v in self.sample.items() if k != "_key"}
