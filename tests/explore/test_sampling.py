"""Designs of a design space: reproducible by seed, the same whichever partitions are drawn and in which order,
full grids in product order, Latin hypercubes stratified per partition, Sobol' points equal to scipy's sequence."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.stats import qmc

from machdyn.errors import InputError
from machdyn.studies.exploration import DesignSpace, designs, partition_designs
from machdyn.studies.table import QuantityRange


def _ranged(*bounds: tuple[float, float]) -> tuple[QuantityRange, ...]:
    return tuple(QuantityRange(f"q{i}", "m", "mm", None, lo, hi) for i, (lo, hi) in enumerate(bounds))


def _grid(*values: tuple[float, ...]) -> tuple[QuantityRange, ...]:
    return tuple(QuantityRange(f"q{i}", "m", "mm", v, v[0], v[-1]) for i, v in enumerate(values))


def test_a_grid_is_every_combination_first_quantity_slowest():
    space = DesignSpace(_grid((1.0, 2.0, 3.0), (10.0, 20.0)), partition=4)
    assert space.size == 6 and space.partitions == 2
    expected = np.array(list(itertools.product((1.0, 2.0, 3.0), (10.0, 20.0))))
    np.testing.assert_array_equal(designs(space), expected)


@pytest.mark.parametrize("method", ["lhs", "sobol"])
def test_same_seed_same_designs_other_seed_other_designs(method):
    quantities = _ranged((0.03, 0.05), (-2.0, 0.0), (60.0, 180.0))
    a = designs(DesignSpace(quantities, method, 1000, seed=7, partition=256))
    b = designs(DesignSpace(quantities, method, 1000, seed=7, partition=256))
    c = designs(DesignSpace(quantities, method, 1000, seed=8, partition=256))
    np.testing.assert_array_equal(a, b)
    assert not np.array_equal(a, c)
    assert a.shape == (1000, 3)
    for k, q in enumerate(quantities):  # inside each range
        assert np.all((a[:, k] >= min(q.start, q.stop)) & (a[:, k] <= max(q.start, q.stop)))


@pytest.mark.parametrize("method", ["grid", "lhs", "sobol"])
def test_partitions_drawn_alone_equal_the_whole(method):
    quantities = _grid(tuple(np.linspace(1, 2, 7)), tuple(np.linspace(5, 6, 9))) if method == "grid" else \
        _ranged((1.0, 2.0), (5.0, 6.0))
    space = DesignSpace(quantities, method, 63, seed=3, partition=10)
    whole = designs(space)
    for index, values in partition_designs(space, [5, 2, 6]):
        start, stop = space.bounds(index)
        np.testing.assert_array_equal(values, whole[start:stop])


def test_sobol_designs_are_scipy_sequence_scaled():
    space = DesignSpace(_ranged((0.0, 2.0), (10.0, 20.0)), "sobol", 64, seed=11, partition=16)
    unit = qmc.Sobol(d=2, scramble=True, rng=np.random.default_rng(11)).random(64)
    np.testing.assert_allclose(designs(space), np.column_stack([2.0 * unit[:, 0], 10.0 + 10.0 * unit[:, 1]]),
                               rtol=1e-15, atol=0)


@settings(max_examples=25, deadline=None)
@given(n=st.integers(1, 200), d=st.integers(1, 4), seed=st.integers(0, 2**32))
def test_each_lhs_partition_has_one_design_per_stratum(n, d, seed):
    space = DesignSpace(_ranged(*[(0.0, 1.0)] * d), "lhs", n, seed=seed, partition=n)
    (_, values), = partition_designs(space)
    for k in range(d):
        strata = np.floor(values[:, k] * n).astype(int)
        assert sorted(strata) == list(range(n))


def test_bad_spaces_are_refused():
    with pytest.raises(InputError, match="must be one of grid, lhs, sobol; got 'random'"):
        DesignSpace(_ranged((0.0, 1.0)), "random", 10)
    with pytest.raises(InputError, match="needs samples >= 1; got None"):
        DesignSpace(_ranged((0.0, 1.0)), "lhs")
    with pytest.raises(InputError, match="A grid needs the values of every quantity"):
        DesignSpace(_ranged((0.0, 1.0)), "grid")
    with pytest.raises(InputError, match=r"Partition index must be in \[0, 1\); got 3"):
        DesignSpace(_ranged((0.0, 1.0)), "lhs", 5).bounds(3)
