"""The engine orders of a population of reciprocating machines (:mod:`machdyn.shafts.engine_population`) equal
:func:`machdyn.shafts.reciprocating.engine_orders` of each machine to 1e-12, and the machines the single path
refuses (a rod not longer than its crank, a negative mass) are flagged."""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.errors import InputError
from machdyn.shafts.engine_population import engine_orders_population
from machdyn.shafts.reciprocating import Cylinder, engine_orders

KEYS = ("primary_force", "secondary_force", "primary_couple", "secondary_couple")


def test_random_engines_equal_each_engine_s_orders_and_refused_ones_are_flagged():
    rng = np.random.default_rng(11)
    n, c = 30, 4
    cyl = {"position": rng.uniform(0.0, 0.6, (n, c)), "phase": rng.uniform(0, 2 * np.pi, (n, c)),
           "axis": rng.choice([np.pi / 2, np.pi / 4, 3 * np.pi / 4], (n, c)), "crank": rng.uniform(0.03, 0.08, (n, c)),
           "rod": rng.uniform(0.15, 0.3, (n, c)), "reciprocating_mass": rng.uniform(0.5, 3.0, (n, c)),
           "rotating_mass": rng.uniform(0.0, 2.0, (n, c))}
    cyl["rod"][4, 2] = 0.02  # shorter than its crank
    cyl["reciprocating_mass"][9, 0] = -1.0
    speed = rng.uniform(50.0, 300.0, n)
    done = engine_orders_population(cyl, speed, samples=72, harmonics=6, reference=0.1)
    for i in range(n):
        try:
            cylinders = [Cylinder(f"c{j}", *(float(cyl[k][i, j]) for k in (
                "position", "phase", "axis", "crank", "rod", "reciprocating_mass", "rotating_mass")))
                for j in range(c)]
        except InputError:
            assert not done["valid"][i]
            continue
        assert done["valid"][i]
        one = engine_orders(cylinders, speed[i], 72, 6, 0.1, include_rotating=True)
        # a balanced order is round-off: compared at the scale of the engine's forces and couples
        force_scale, couple_scale = done["gross_force"][i], done["gross_couple"][i]
        got = {"primary_force": one.primary_force, "secondary_force": one.secondary_force,
               "primary_couple": one.primary_couple, "secondary_couple": one.secondary_couple,
               "peak_force": one.exact.peak_force, "peak_couple": one.exact.peak_couple,
               **{f"order{k}.force": f for k, f in zip(one.orders, one.force_order, strict=True)},
               **{f"order{k}.couple": f for k, f in zip(one.orders, one.couple_order, strict=True)}}
        for key, want in got.items():
            scale = couple_scale if "couple" in key else force_scale
            assert abs(done[key][i] - want) <= 1e-12 * max(abs(want), scale), (key, i)
        for key, want in (("primary_direct", abs(one.primary_dr[0])), ("primary_reverse", abs(one.primary_dr[1])),
                          ("secondary_direct", abs(one.secondary_dr[0])),
                          ("secondary_reverse", abs(one.secondary_dr[1]))):
            assert abs(done[key][i] - want) <= 1e-12 * max(want, done["gross_force"][i] / speed[i] ** 2), (key, i)
    assert done["valid"].sum() == n - 2


@pytest.mark.parametrize("chunk", [7, 1 << 20])
def test_the_chunks_do_not_change_the_result(monkeypatch, chunk):
    """A population larger than a chunk is evaluated chunk by chunk (bounded memory) with the same numbers."""
    import machdyn.shafts.engine_population as ep

    rng = np.random.default_rng(2)
    cyl = {"phase": rng.uniform(0, 2 * np.pi, (9, 2)), "axis": np.pi / 2, "crank": 0.05, "rod": 0.2,
           "reciprocating_mass": 1.0, "position": np.array([0.0, 0.1])}
    whole = engine_orders_population(cyl, 100.0, samples=36, harmonics=4)
    monkeypatch.setattr(ep, "CHUNK_VALUES", chunk)
    parts = engine_orders_population(cyl, 100.0, samples=36, harmonics=4)
    for key, value in whole.items():
        np.testing.assert_array_equal(parts[key], value)
