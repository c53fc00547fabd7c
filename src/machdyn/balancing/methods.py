"""The balancing methods of ``[balance]``, one entry each: what the method needs from the table, the check that
it can serve the linkage (run by ``machdyn check`` and before a run alike), and how it balances.

=================  ==========================================  ======================================================
method             needs                                       balances by
=================  ==========================================  ======================================================
``crank``          ``fraction``, ``radius``                    a crank counterweight of a slider-crank
                                                               (:func:`.counterweights.crank_counterweight`)
``berkof_lowen``   ``crank_radius``, ``rocker_radius``         the full force balance of a four-bar
                                                               (:func:`.berkof_lowen.berkof_lowen`)
``spring``         ``spring``                                  a spring that evens the driving torque
                                                               (:func:`.springs.spring_compensation`)
``counterweights`` counterweight slots or free masses           closed-form least squares
                                                               (:func:`.general.least_squares_counterweights`),
                                                               a weighted bounded optimisation
                                                               (:func:`.general.optimise_counterweights`) or robust
                                                               over operating states
                                                               (:func:`.robust.robust_counterweights`)
=================  ==========================================  ======================================================

The table's schema, the check and the stage read this module; none of them dispatches on the method's name.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import AnalysisError, InputError, ProblemFileError
from ..linkage import Mechanism, kinematics
from ..problem.build import build_mechanism
from ..problem.fields import FieldError, to_si
from ..problem.paths import assign, quantity_unit
from .berkof_lowen import berkof_lowen, four_bar_masses
from .counterweights import crank_counterweight, slider_crank_masses, tradeoff_curve
from .frame import cycle
from .general import (
    CounterweightSlot,
    MassSlot,
    Weights,
    least_squares_counterweights,
    optimise_counterweights,
    pivot_point,
    reference_point,
)
from .robust import OperatingState, robust_counterweights
from .springs import spring_compensation, spring_geometry

#: (result, trade-off curve or None) of a balancing method.
Balanced = tuple[Any, Any]


@dataclass(frozen=True)
class Method:
    """One balancing method: the table fields it ``needs``, ``fits(mech, table, speed)`` raising InputError when
    the method cannot serve the linkage, and ``solve(mech, problem, table, phi, speed) -> (result, trade-off)``."""

    needs: tuple[str, ...]
    fits: Callable[[Mechanism, Any, float], None]
    solve: Callable[[Mechanism, Any, Any, np.ndarray, float], Balanced]


def slots(table: Any) -> list[Any]:
    """The counterweight slots and free masses of the table, as the solvers take them."""
    out: list[Any] = [
        CounterweightSlot(s.body, s.radius, s.about, (0.0, np.inf if s.mass_max is None else s.mass_max),
                          (0.0, np.inf if s.radius_max is None else s.radius_max))
        for s in table.counterweights
    ]
    out += [MassSlot(m.name, (m.mass_min, np.inf if m.mass_max is None else m.mass_max)) for m in table.masses]
    return out


def state_problems(problem: Any, table: Any) -> list[tuple[Any, Any]]:
    """(state spec, varied problem) for each ``[[balance.states]]``; every mistake at once with its path."""
    out, problems = [], []
    for i, state in enumerate(table.states):
        varied = problem
        for path, value in state.set.items():
            where = f"balance.states[{i}].set.{path}"
            try:
                meta = quantity_unit(problem, path)
                varied = assign(varied, path, float(to_si(value, meta)))
            except FieldError as exc:
                problems.append((where, str(exc)))
        out.append((state, varied))
    if problems:
        raise ProblemFileError(problems)
    return out


def operating_states(problem: Any, table: Any) -> list[OperatingState]:
    """The operating states of ``[[balance.states]]``, each mechanism built; every mistake at once."""
    states, problems = [], []
    for i, (spec, varied) in enumerate(state_problems(problem, table)):
        try:
            mech = build_mechanism(varied)
        except ProblemFileError as exc:
            problems += [(f"balance.states[{i}]", f"{path}: {msg}") for path, msg in exc.problems]
            continue
        speed = problem.drive.speed if spec.speed is None else spec.speed
        states.append(OperatingState(spec.name, mech, abs(speed), spec.weight, spec.crank_turn))
    if problems:
        raise ProblemFileError(problems)
    return states


def closed_form(mech: Mechanism, table: Any, speed: float) -> Any:
    """The closed-form (least-squares) counterweights of the slots; a solution that cannot be built (a negative
    or zero mass carrying a first moment on a floating body) is an input the method cannot serve: InputError."""
    try:
        return least_squares_counterweights(mech, slots(table), cycle(table.positions), speed)
    except AnalysisError as exc:
        raise InputError(str(exc)) from None


def _crank_fits(mech: Mechanism, table: Any, speed: float) -> None:
    slider_crank_masses(mech)


def _crank(mech: Mechanism, problem: Any, table: Any, phi: np.ndarray, speed: float) -> Balanced:
    return (crank_counterweight(mech, table.fraction, table.radius, phi, speed),
            tradeoff_curve(mech, table.radius, np.linspace(0.0, 1.0, 21), phi, speed))


def _berkof_lowen_fits(mech: Mechanism, table: Any, speed: float) -> None:
    four_bar_masses(mech)


def _berkof_lowen(mech: Mechanism, problem: Any, table: Any, phi: np.ndarray, speed: float) -> Balanced:
    return berkof_lowen(mech, table.crank_radius, table.rocker_radius, phi, speed), None


def _spring_fits(mech: Mechanism, table: Any, speed: float) -> None:
    s = table.spring
    mech.body(s.body)
    kin = kinematics(mech, cycle(table.positions), speed, 0.0, on_fail="raise")
    spring_geometry(kin, s.body, np.asarray(s.point), np.asarray(s.anchor))


def _spring(mech: Mechanism, problem: Any, table: Any, phi: np.ndarray, speed: float) -> Balanced:
    s = table.spring
    result, _ = spring_compensation(
        mech, s.body, s.point, s.anchor, phi, speed,
        stiffness_bounds=(0.0, np.inf if s.stiffness_max is None else s.stiffness_max),
        free_length_bounds=(s.free_length_min, np.inf if s.free_length_max is None else s.free_length_max))
    return result, None


def _counterweights_fits(mech: Mechanism, table: Any, speed: float) -> None:
    closed = table.objective is None
    for slot in slots(table):
        if not isinstance(slot, CounterweightSlot):
            continue
        reference_point(mech, slot)
        pivot = pivot_point(mech, slot.body)
        if closed and slot.radius is None and pivot is not None and (slot.about or pivot) == pivot:
            raise InputError(f"The counterweight slot on pivoted body '{slot.body}' needs a radius for the "
                             "closed-form solution (the force fixes only mass x radius).")


def _counterweights(mech: Mechanism, problem: Any, table: Any, phi: np.ndarray, speed: float) -> Balanced:
    if table.states:
        return robust_counterweights(operating_states(problem, table), slots(table), table.mode, phi), None
    if table.objective is not None:
        o = table.objective
        return optimise_counterweights(mech, slots(table), Weights(o.force, o.moment, o.torque, o.joint, o.measure),
                                       phi, speed), None
    return closed_form(mech, table, speed), None


METHODS: dict[str, Method] = {
    "crank": Method(("fraction", "radius"), _crank_fits, _crank),
    "berkof_lowen": Method(("crank_radius", "rocker_radius"), _berkof_lowen_fits, _berkof_lowen),
    "spring": Method(("spring",), _spring_fits, _spring),
    "counterweights": Method((), _counterweights_fits, _counterweights),
}


def method_fits(mech: Mechanism, table: Any, speed: float) -> None:
    """Raise InputError if the table's method cannot run on ``mech`` (and, for closed-form counterweights
    alone, if their solution cannot be built)."""
    METHODS[table.method].fits(mech, table, speed)
    if table.method == "counterweights" and table.objective is None and not table.states:
        closed_form(mech, table, speed)


def balance(mech: Mechanism, problem: Any, table: Any, phi: np.ndarray, speed: float) -> Balanced:
    """(result, trade-off curve or None) of the table's method on ``mech`` at ``speed`` [rad/s] over the crank
    angles ``phi`` [rad]."""
    return METHODS[table.method].solve(mech, problem, table, phi, speed)
