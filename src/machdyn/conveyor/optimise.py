"""Choose the best screw for a duty: every candidate of a grid evaluated at once, the feasible ones ranked.

Candidates: the diameters (standard sizes by default) × pitch ratios (full, ¾, ½) × speeds (fractions of the
limit k/√D) × fillings of the ``[screw_conveyor.optimise]`` table. Each is evaluated by
:func:`.screw.screw_states` (vectorised), kept if it carries the duty and passes every check, and ranked by
the objective: least shaft power, or least cost proxy = screw mass [kg] + motor rating [kW] × motor mass per kW
[kg/kW]. The pipe and flight scale with each candidate: the standard pipe of its size (CEMA 350's standard
components, ``data/cema_standard_pipes.csv``), wall d_o/12, flight max(3 mm, D/50). A candidate beyond that
table (above 24 in) has no standard pipe and is not feasible.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import InputError
from .design import RPM, speed_limit
from .model import ConveyorProblem
from .screw import passes, screw_states
from .tables import standard_pipes


@dataclass(frozen=True)
class Ranking:
    """Every candidate (arrays, SI: speed in rad/s), which are feasible, and their order by objective."""

    objective: str
    diameter: np.ndarray
    pitch_ratio: np.ndarray
    speed: np.ndarray
    filling: np.ndarray
    power: np.ndarray
    screw_mass: np.ndarray
    motor_rating: np.ndarray
    value: np.ndarray  # the objective
    feasible_mask: np.ndarray
    order: np.ndarray  # indices of the feasible candidates, best first

    @property
    def candidates(self) -> int:
        return int(self.diameter.size)

    @property
    def feasible(self) -> int:
        return int(self.order.size)

    @property
    def objective_label(self) -> str:
        return "shaft power [W]" if self.objective == "power" else "cost proxy [kg]"

    @property
    def best(self) -> dict[str, float]:
        return self.row(int(self.order[0]))

    def row(self, i: int) -> dict[str, Any]:
        return {"diameter": float(self.diameter[i]), "pitch_ratio": float(self.pitch_ratio[i]),
                "speed": float(self.speed[i]), "filling": float(self.filling[i]), "power": float(self.power[i]),
                "screw_mass": float(self.screw_mass[i]), "motor_rating": float(self.motor_rating[i]),
                "objective": float(self.value[i]),
                "name": f"D {self.diameter[i] * 1000:.0f}, S/D {self.pitch_ratio[i]:g}, {self.speed[i] / RPM:.0f} rpm, "
                        f"φ {self.filling[i]:g}"}

    def table(self, top: int = 10) -> list[dict[str, Any]]:
        """The ``top`` best feasible candidates."""
        return [self.row(int(i)) for i in self.order[:top]]

    def series(self) -> dict[str, tuple[np.ndarray, str]]:
        """Columns of every candidate for a CSV file."""
        return {"diameter": (self.diameter, "m"), "pitch_ratio": (self.pitch_ratio, ""),
                "speed": (self.speed, "rad/s"), "filling": (self.filling, ""), "power": (self.power, "W"),
                "screw_mass": (self.screw_mass, "kg"), "motor_rating": (self.motor_rating, "W"),
                "objective": (self.value, "W" if self.objective == "power" else "kg"),
                "feasible": (self.feasible_mask.astype(float), "")}


def candidate_grid(problem: ConveyorProblem) -> dict[str, np.ndarray]:
    """The flattened grid of candidates (diameter [m], pitch ratio, speed [rad/s], filling) of the search."""
    s = problem.search
    if s is None:
        raise InputError("The problem has no [screw_conveyor.optimise] table.")
    d, r, f, phi = np.meshgrid(np.array(s.diameters), np.array(s.pitch_ratios), np.array(s.speed_fractions),
                               np.array(s.fillings), indexing="ij")
    d, r, f, phi = (a.ravel() for a in (d, r, f, phi))
    return {"diameter": d, "pitch_ratio": r, "speed": f * speed_limit(d, problem.speed_coefficient), "filling": phi}


def evaluate_candidates(problem: ConveyorProblem) -> tuple[dict[str, np.ndarray], dict[str, Any]]:
    """The grid and the states of all its candidates (one vectorised call)."""
    grid = candidate_grid(problem)
    free = problem.replace(pipe_outer_diameter=None, pipe_wall=None, flight_thickness=None, diameter=None,
                           speed=None)
    inside = np.isfinite(standard_pipes(grid["diameter"]))  # the others have no standard pipe: not feasible
    n, k = grid["diameter"].size, int(np.count_nonzero(inside))
    states: dict[str, Any] = {"diameter": grid["diameter"]}
    if k:
        with np.errstate(invalid="ignore", divide="ignore"):
            some = screw_states(free, grid["diameter"][inside], (grid["pitch_ratio"] * grid["diameter"])[inside],
                                grid["speed"][inside], grid["filling"][inside], problem.mass_flow)
        for key, value in some.items():
            if isinstance(value, np.ndarray) and value.shape == (k,):
                full = np.full(n, np.nan)
                full[inside] = value
                states[key] = full
            else:
                states[key] = value
        states["diameter"] = grid["diameter"]
    else:
        raise InputError("No candidate diameter of the design search lies within CEMA's standard screw conveyor "
                         "components (4 to 24 in), from which each candidate's pipe is taken.")
    return grid, states


def best_design(problem: ConveyorProblem) -> Ranking:
    """Rank the candidates of the problem's search; the first meets the duty and every check at least cost.

    Raises :class:`~machdyn.errors.InputError` if no candidate of the grid is feasible.
    """
    s = problem.search
    assert s is not None
    grid, states = evaluate_candidates(problem)
    ok = passes(states) & np.isfinite(states["shaft_power"])
    mass = states["screw_mass"]
    motor = states["motor_rating"]
    value = states["shaft_power"] if s.objective == "power" else mass + motor / 1000.0 * s.motor_mass_per_kw
    idx = np.flatnonzero(ok)
    if idx.size == 0:
        raise InputError(f"No candidate of the design search ({grid['diameter'].size} screws) carries the duty and "
                         f"passes every check: widen screw_conveyor.optimise (diameters, speeds, fillings).")
    order = idx[np.lexsort((idx, value[idx]))]
    return Ranking(s.objective, grid["diameter"], grid["pitch_ratio"], grid["speed"], grid["filling"],
                   states["shaft_power"], mass, motor, value, ok, order)
