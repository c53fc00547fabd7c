"""Process loads given against the stroke (punching, blanking, compaction curves), turned into loads against the
crank angle through the linkage's own kinematics.

A force–stroke table gives the force F [N] a slider meets against its distance x [m] before the end of its
working stroke. The end of the working stroke is one of the slider's two dead centres: ``"outer"``, farther
from the crank pivot (bottom dead centre of a press whose ram moves away from the crank), or ``"inner"``. While
the slider moves towards that end, the force acts along the guide against its motion, F(x(φ)); on the return
stroke it is zero. The conversion is exact: x(φ) comes from the engine's closed-form position of the slider,
tabulated on a fine grid of crank angles and interpolated between (linear, 3600 positions per turn by default:
a stroke resolution far below the table's own).

The work the load takes per stroke is the area under the table, W = ∫ F dx (trapezoid rule, the table being
piecewise linear); the engine's work balance over a cycle reproduces it (tested).

Sources: the work of a force along its path, W = ∫ F dx (its definition; for a press, the area under the
force–stroke diagram of the operation); the conversion to crank angle is the engine's kinematics.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from .kinematics import kinematics
from .model import Mechanism, PointForce
from .refs import split_ref


@dataclass(frozen=True)
class StrokeLoad:
    """The crank-angle load made from a force–stroke table, with what the report states about it: the slider's
    stroke [m], the crank angles [rad] where the working stroke starts and ends, and the work per stroke [J]."""

    force: PointForce
    stroke: float
    working_start: float
    working_end: float
    work: float


def table_work(distance: Sequence[float] | np.ndarray, force: Sequence[float] | np.ndarray) -> float:
    """Work [J] of a piecewise-linear force–stroke table, the area under it (trapezoid rule).

    Parameters
    ----------
    distance : x [m], increasing; force : F [N] at each x.

    Returns
    -------
    float
        W = ∫ F dx [J].

    Examples
    --------
    A blanking curve rising to 60 kN over 1 mm and falling to 0 over 3 mm takes 120 J:

    >>> table_work([0.0, 0.003, 0.004], [0.0, 60e3, 0.0])
    120.0
    """
    x = np.asarray(distance, dtype=float)
    f = np.asarray(force, dtype=float)
    return float(np.sum(0.5 * (f[1:] + f[:-1]) * np.diff(x)))


def stroke_load(mech: Mechanism, name: str, point: str, distance: Sequence[float], force: Sequence[float], *,
                end: str = "outer", samples: int = 3600) -> StrokeLoad:
    """A force–stroke table at ``point`` (on a slider with a fixed guide) as a load against the crank angle.

    Parameters
    ----------
    mech : the linkage (one design).
    name : the load's name.
    point : ``"body.point"`` on the slider.
    distance : x [m], the distance before the end of the working stroke, increasing from 0.
    force : F [N] >= 0 at each x (the resistance the slider meets).
    end : "outer" or "inner", the dead centre where the working stroke ends.
    samples : crank positions per turn of the tabulated stroke.

    Returns
    -------
    StrokeLoad
    """
    x_tab = np.asarray(distance, dtype=float)
    f_tab = np.asarray(force, dtype=float)
    if x_tab.ndim != 1 or x_tab.size < 2 or x_tab.shape != f_tab.shape:
        raise InputError(f"The force-stroke table '{name}' needs at least two (distance, force) pairs of equal "
                         f"length; got {x_tab.size} distances and {f_tab.size} forces.")
    if not (np.all(np.isfinite(x_tab)) and np.all(np.isfinite(f_tab))):
        raise InputError(f"The force-stroke table '{name}' has a value that is not a finite number.")
    if x_tab[0] < 0 or np.any(np.diff(x_tab) <= 0):
        raise InputError(f"The distances of the force-stroke table '{name}' must start at >= 0 m and increase; got "
                         f"{', '.join(f'{v:g}' for v in x_tab)} m.")
    if np.any(f_tab < 0):
        raise InputError(f"The forces of the force-stroke table '{name}' are resistances and must be >= 0 N.")
    if end not in ("outer", "inner"):
        raise InputError(f"The end of the working stroke of '{name}' is 'outer' or 'inner'; got {end!r}.")
    if mech.design_count is not None:
        raise InputError(f"A force-stroke table converts the stroke of one design; '{mech.name}' has "
                         f"{mech.design_count}.")
    phi = np.linspace(0.0, 2 * np.pi, samples, endpoint=False)
    kin = kinematics(mech, phi, 1.0)
    if not np.all(np.asarray(kin.assembled)):
        raise InputError(f"The force-stroke table '{name}' needs the linkage to assemble over the whole turn.")
    p = kin.point(point)
    px, py = np.broadcast_to(np.asarray(p.x, float), phi.shape), np.broadcast_to(np.asarray(p.y, float), phi.shape)
    vx, vy = np.broadcast_to(np.asarray(p.vx, float), phi.shape), np.broadcast_to(np.asarray(p.vy, float), phi.shape)
    # the guide: the straight line the point travels on (its two dead centres span it)
    i_far = int(np.argmax(np.hypot(px - px[0], py - py[0])))
    j_far = int(np.argmax(np.hypot(px - px[i_far], py - py[i_far])))
    chord = np.array([px[j_far] - px[i_far], py[j_far] - py[i_far]])
    stroke = float(np.hypot(*chord))
    if stroke <= 0:
        raise InputError(f"The point {point} of the force-stroke table '{name}' does not move.")
    u = chord / stroke
    off_line = np.abs((px - px[i_far]) * u[1] - (py - py[i_far]) * u[0])
    if float(off_line.max()) > 1e-6 * stroke:
        raise InputError(f"The point {point} of '{name}' does not move on a straight line (a slider on a fixed "
                         "guide); a force-stroke table needs one.")
    s = (px - px[i_far]) * u[0] + (py - py[i_far]) * u[1]  # 0 .. stroke along u
    pivot = mech.ground[split_ref(mech.crank.pivot)[1]]
    d_lo = np.hypot(px[i_far] - float(np.ravel(pivot[0])[0]), py[i_far] - float(np.ravel(pivot[1])[0]))
    d_hi = np.hypot(px[j_far] - float(np.ravel(pivot[0])[0]), py[j_far] - float(np.ravel(pivot[1])[0]))
    end_at_high = (d_hi > d_lo) == (end == "outer")
    x = stroke - s if end_at_high else s  # distance before the end of the working stroke
    rate = vx * u[0] + vy * u[1]  # ds/dphi
    working = rate > 0 if end_at_high else rate < 0
    if x_tab[-1] > stroke * (1 + 1e-9):
        raise InputError(f"The force-stroke table '{name}' reaches {x_tab[-1]:g} m before the end of the stroke, "
                         f"but the stroke of {point} is {stroke:g} m.")
    magnitude = np.where(working, np.interp(x, x_tab, f_tab, left=f_tab[0], right=0.0), 0.0)
    magnitude = np.where(x <= x_tab[-1], magnitude, 0.0)
    sign = np.where(rate > 0, -1.0, 1.0)  # against the motion along u
    fx_grid, fy_grid = magnitude * sign * u[0], magnitude * sign * u[1]
    starts = np.flatnonzero(working & ~np.roll(working, 1))
    ends = np.flatnonzero(~working & np.roll(working, 1))
    load = PointForce(name, point, _periodic(phi, fx_grid), _periodic(phi, fy_grid))
    return StrokeLoad(load, stroke, float(phi[starts[0]]) if starts.size else 0.0,
                      float(phi[ends[0]]) if ends.size else 0.0, table_work(x_tab, f_tab))


@dataclass(frozen=True)
class PeriodicTable:
    """A load component tabulated over one turn, linear between its crank angles [rad] (values [N]); equal
    tables compare equal, so a model rebuilt from its problem file equals the original."""

    angles: tuple[float, ...]
    values: tuple[float, ...]

    def __call__(self, angle: np.ndarray) -> np.ndarray:
        grid = np.append(np.asarray(self.angles), 2 * np.pi)
        at = np.mod(np.asarray(angle, dtype=float), 2 * np.pi)
        if all(np.ndim(v) == 0 for v in self.values):
            data = np.append(np.asarray(self.values, dtype=float), self.values[0])
            return np.interp(at, grid, data)
        # design variants stacked (machdyn.linkage.stack_designs): each angle's value is an array over the N
        # designs, whose strokes differ; interpolate each design's own table -> (N, ...) at the angles
        table = np.stack(np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in self.values)), axis=-1)
        table = np.concatenate([table, table[:, :1]], axis=1)
        i = np.clip(np.searchsorted(grid, at, side="right") - 1, 0, grid.size - 2)
        w = (at - grid[i]) / (grid[i + 1] - grid[i])
        if at.ndim == 2 and at.shape[0] == table.shape[0]:  # one row of angles per design
            lo, hi = np.take_along_axis(table, i, axis=1), np.take_along_axis(table, i + 1, axis=1)
        else:
            lo, hi = table[:, i], table[:, i + 1]
        return lo * (1 - w) + hi * w


def _periodic(phi: np.ndarray, values: np.ndarray) -> Callable[[np.ndarray], np.ndarray]:
    return PeriodicTable(tuple(float(v) for v in phi), tuple(float(v) for v in values))
