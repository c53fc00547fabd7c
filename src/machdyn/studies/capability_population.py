"""A capability's results for a population of linkage designs at once, through the population form the capability
declares (:attr:`machdyn.pipeline.Capability.population`), instead of one run per design.

The study does not know the capability: it finds the table that produces each key in the catalogue, asks the
registry for that table's population form (:func:`machdyn.kinds.population_form`), and hands it the file's
problem and the kinetostatics of the whole population over the file's own crank positions (one engine call,
designs that do not close masked to NaN). A form that cannot stand in for the runs (it returns None), a table a
design variable changes (its values differ from design to design), and keys no form gives are left to the runs
of each design (:mod:`machdyn.studies.per_design`).
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import numpy as np

from ..errors import AssemblyError
from ..kinds import catalogue, population_form
from ..linkage import kinematics, kinetostatics
from ..linkage.engines import available
from ..linkage.fused_generator import Unsupported
from ..problem.build import crank_angles
from ..results.catalogue import find


def population_results(problem: Any, keys: Iterable[str], mechanism: Any, speed: Any, acceleration: Any,
                       count: int, varied: Iterable[str] = ()) -> dict[str, np.ndarray]:
    """The ``keys`` some capability's population form gives for the ``count`` designs of ``mechanism`` (a model of
    N designs, or of one), as (count,) arrays, NaN for a design that does not close.

    Parameters
    ----------
    problem : the file's validated problem (its capability tables are every design's).
    keys : the results asked for.
    mechanism, speed [rad/s], acceleration [rad/s²] : the population's engine model and drive (floats or (N,)).
    count : N.
    varied : the key paths the designs set (``parts.pins.0.diameter``): a table they touch is left to the runs.
    """
    touched = {path.split(".", 1)[0] for path in varied}
    by_table: dict[str, list[str]] = {}
    quantities = catalogue()
    for key in keys:
        found = find(key, quantities)
        if found is not None and found[0].producer not in touched:
            by_table.setdefault(found[0].producer, []).append(key)
    out: dict[str, np.ndarray] = {}
    forces = None
    for table, wanted in by_table.items():
        form = population_form(table)
        if form is None:
            continue
        if forces is None:
            forces = _forces(problem, mechanism, speed, acceleration)
        found_all = form(problem, forces)
        if found_all is None:
            continue
        for key in wanted:
            value = np.asarray(found_all.get(key, np.nan), dtype=float)
            out[key] = np.broadcast_to(value, (count,)).copy()
    return out


def population_keys(problem: Any, keys: Iterable[str], varied: Iterable[str] = ()) -> set[str]:
    """The ``keys`` whose table declares a population form (and is not ``varied``): those a study takes from it
    rather than from a run of each design (the form may still decline at run time)."""
    touched = {path.split(".", 1)[0] for path in varied}
    quantities = catalogue()
    out = set()
    for key in keys:
        found = find(key, quantities)
        if found is not None and found[0].producer not in touched and population_form(found[0].producer) is not None:
            out.add(key)
    return out


def _forces(problem: Any, mechanism: Any, speed: Any, acceleration: Any) -> Any:
    def column(x: Any) -> Any:  # one value per design: a column against the crank positions
        return np.asarray(x, dtype=float)[:, None] if np.ndim(x) == 1 else x

    return population_forces(mechanism, crank_angles(problem), column(speed), column(acceleration))


def population_forces(mechanism: Any, phi: Any, speed: Any, acceleration: Any = 0.0) -> Any:
    """The kinetostatics of every design of ``mechanism`` at the crank angles ``phi`` [rad]: motion and forces in
    one compiled pass when numba is present and every design closes; else the NumPy engine, the positions where
    a design does not close masked to NaN."""
    try:
        return kinetostatics(mechanism, phi, speed, acceleration, engine="fused" if available() else "numpy")
    except Unsupported:  # a mechanism the compiled pass does not handle
        pass
    except AssemblyError:  # some designs do not close
        return kinetostatics(mechanism, kinematics_result=kinematics(mechanism, phi, speed, acceleration,
                                                                     on_fail="mask"))
    try:
        return kinetostatics(mechanism, phi, speed, acceleration)
    except AssemblyError:
        return kinetostatics(mechanism, kinematics_result=kinematics(mechanism, phi, speed, acceleration,
                                                                     on_fail="mask"))
