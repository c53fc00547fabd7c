"""Design variables addressed by their key path in a problem file, and the population -> engine model map.

A variable is any quantity of the file (``mechanism.crank.length``, ``mechanism.coupler_point[0]``,
``loads.forces[0].fy``, ``drive.speed``) with a lower and an upper bound in its own unit; ``derived`` sets
further quantities from the variables by a formula in SI units (e.g. the compactor's plate length tied to the
horizontal pivot distance, seed 003 eq 6). A population (N designs x V variables, SI) becomes **one** stacked
engine model with arrays of N values: for the standard mechanisms by handing the arrays straight to the
builders, otherwise by building each variant and stacking them (:func:`machdyn.linkage.stack_designs`).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ...errors import InputError, ProblemFileError
from ...linkage import stack_designs
from ...problem.build import build_mechanism
from ...problem.fields import FieldError, Unit, to_si
from ...problem.paths import assign, design_problem, quantity_unit, value_at
from ...units import quantity_of_text, unit_of_text, ureg
from .formula import FORMULA_CONSTANTS, FORMULA_FUNCTIONS, Formula, compile_formula
from .schema import OptimiseSpec

__all__ = ["FORMULA_CONSTANTS", "FORMULA_FUNCTIONS", "SearchSpace", "Formula", "Population", "Variable",
           "compile_formula", "current_values", "search_space"]

@dataclass(frozen=True)
class Variable:
    """A design variable: ``name`` (used in formulas), the ``path`` it sets (None for a free variable),
    bounds in SI, its SI unit and the unit its bounds were written in."""

    name: str
    path: str | None
    lower: float
    upper: float
    unit: str
    display_unit: str


def _default_name(path: str) -> str:
    return re.sub(r"\W+", "_", path.replace("mechanism.", "")).strip("_")


def _display(text: Any, meta: Unit) -> str:
    try:
        return f"{quantity_of_text(str(text)).units:~}" or meta.unit
    except Exception:  # noqa: BLE001 - the value's own error is reported by to_si
        return meta.unit


@dataclass(frozen=True)
class Population:
    """One stacked engine model of N designs and what goes with it: the crank speed and acceleration (a
    float or (N,) array each) and, per design, whether it could be built and why not."""

    mechanism: Any
    speed: Any
    acceleration: Any
    buildable: np.ndarray
    reasons: tuple[str, ...]


@dataclass(frozen=True)
class SearchSpace:
    """The variables and derived quantities of an ``[optimise]`` table over a validated problem."""

    problem: Any
    variables: tuple[Variable, ...]
    formulas: tuple[Formula, ...]
    rules: dict = field(default_factory=dict)

    @property
    def lower(self) -> np.ndarray:
        return np.array([v.lower for v in self.variables])

    @property
    def upper(self) -> np.ndarray:
        return np.array([v.upper for v in self.variables])

    @property
    def names(self) -> list[str]:
        return [v.name for v in self.variables]

    def values(self, population) -> dict[str, np.ndarray]:
        """The quantity arrays a population (N x V, SI) sets, keyed by path (variables, then formulas)."""
        x = np.atleast_2d(np.asarray(population, dtype=float))
        by_name = {v.name: x[:, i] for i, v in enumerate(self.variables)}
        out = {v.path: x[:, i] for i, v in enumerate(self.variables) if v.path is not None}
        for f in self.formulas:
            out[f.path] = np.broadcast_to(f(by_name), (x.shape[0],)).astype(float)
        return out

    def _broken(self, values: dict[str, np.ndarray]) -> tuple[np.ndarray, list[str]]:
        """Designs whose derived quantities break their field's rule (or are not finite), with the reason."""
        n = len(next(iter(values.values())))
        bad = np.zeros(n, dtype=bool)
        reasons = [""] * n
        for path, arr in values.items():
            rule = self.rules[path]
            wrong = ~np.isfinite(arr)
            if rule == ">0":
                wrong |= ~(arr > 0)
            elif rule == ">=0":
                wrong |= ~(arr >= 0)
            for i in np.flatnonzero(wrong & ~bad):
                reasons[i] = f"{path} = {arr[i]:g} breaks its rule ({rule or 'finite'})"
            bad |= wrong
        return bad, reasons

    def problem_at(self, x) -> Any:
        """The validated problem of one design (a vector of V values, SI): written out and read back, so
        every field's rule is checked as for a file."""
        values = self.values(np.asarray(x, dtype=float)[None, :])
        return design_problem(self.problem, {path: float(arr[0]) for path, arr in values.items()})

    def population(self, population) -> Population:
        """The stacked engine model of a population (N x V, SI): one build for the standard mechanisms, a
        build per design and :func:`~machdyn.linkage.stack_designs` otherwise."""
        values = self.values(population)
        bad, reasons = self._broken(values)
        if bad.all():
            raise InputError("No design of the population can be built: " + reasons[0] + ".")
        if bad.any():
            # Designs that break a rule are replaced by the first good one and marked unbuildable.
            good = int(np.flatnonzero(~bad)[0])
            values = {p: np.where(bad, a[good], a) for p, a in values.items()}
        stacked = self.problem
        for path, arr in values.items():
            stacked = assign(stacked, path, arr)
        try:
            mech = build_mechanism(stacked)
            mech.take_designs(slice(0, 1))  # every parameter array has the population's length
        except (TypeError, ValueError, ProblemFileError, AttributeError):
            mech, bad, reasons = self._build_each(values, bad, reasons)
        speed = values.get("drive.speed", self.problem.drive.speed)
        accel = values.get("drive.acceleration", self.problem.drive.acceleration)
        return Population(mech, speed, accel, ~bad, tuple(reasons))

    def _build_each(self, values, bad, reasons):
        n = len(bad)
        mechs: list[Any] = [None] * n
        for i in range(n):
            variant = self.problem
            for path, arr in values.items():
                variant = assign(variant, path, float(arr[i]))
            try:
                mechs[i] = build_mechanism(variant)
            except (ValueError, ProblemFileError) as exc:
                bad[i] = True
                reasons[i] = str(exc).replace("\n", " ")
        good = [m for m in mechs if m is not None]
        if not good:
            raise InputError("No design of the population can be built: " + reasons[0] + ".")
        mechs = [m if m is not None else good[0] for m in mechs]
        return stack_designs(mechs), bad, reasons


def search_space(problem: Any, spec: OptimiseSpec) -> SearchSpace:
    """The :class:`SearchSpace` of ``spec`` over ``problem``; every mistake reported at once with its path
    (unknown quantities with a did-you-mean, bounds in the wrong unit, empty or reversed ranges)."""
    problems: list[tuple[str, str]] = []
    variables: list[Variable] = []
    rules: dict[str, str] = {}
    for i, v in enumerate(spec.variables):
        where = f"optimise.variables[{i}]"
        if v.parameter is not None:
            try:
                meta = quantity_unit(problem, v.parameter)
            except FieldError as exc:
                problems.append((f"{where}.parameter", str(exc)))
                continue
        else:
            meta = Unit(_si_unit(v.unit or ""), "free")
        bounds = []
        for key in ("lower", "upper"):
            try:
                bounds.append(to_si(getattr(v, key), meta))
            except FieldError as exc:
                problems.append((f"{where}.{key}", f"{exc} (for {v.parameter or v.name})"))
        if len(bounds) < 2:
            continue
        lo, hi = bounds
        if not hi > lo:
            problems.append((f"{where}.upper", f"must be greater than lower ({v.lower}); "
                                               f"got {v.upper}"))
            continue
        if meta.rule == ">0" and not lo > 0 or meta.rule == ">=0" and not lo >= 0:
            problems.append((f"{where}.lower", f"{v.parameter} must be {meta.rule} {meta.unit}; got {v.lower}"))
            continue
        name = v.name or _default_name(v.parameter or "")
        variables.append(Variable(name, v.parameter, lo, hi, meta.unit, _display(v.lower, meta)))
        if v.parameter is not None:
            rules[v.parameter] = meta.rule
    names = [v.name for v in variables]
    paths = [v.path for v in variables if v.path is not None]
    for dupe in sorted({n for n in names if names.count(n) > 1}):
        problems.append(("optimise.variables", f"two variables are named '{dupe}'; give one a name"))
    for dupe in sorted({p for p in paths if paths.count(p) > 1}):
        problems.append(("optimise.variables", f"'{dupe}' is varied twice"))
    formulas = []
    for path, text in spec.derived.items():
        where = f"optimise.derived.{path}"
        try:
            meta = quantity_unit(problem, path)
            if path in paths:
                raise FieldError(f"'{path}' is already a design variable")
            formulas.append(compile_formula(path, text, names, meta))
            rules[path] = meta.rule
        except FieldError as exc:
            problems.append((where, str(exc)))
    if not problems:
        problems += formula_problems(variables, formulas, rules)
    if problems:
        raise ProblemFileError(problems)
    return SearchSpace(problem, tuple(variables), tuple(formulas), rules)


#: Points of the variables' box at which every derived formula must give a finite value: its centre, its corners
#: (at most 2**SAMPLE_CORNER_DIMS of them) and a fixed scatter inside.
SAMPLE_CORNER_DIMS = 8
SAMPLE_INSIDE = 64


def _sample_points(variables: list[Variable]) -> np.ndarray:
    """(S x V) SI points of the variables' box: the centre, the corners (up to 2**SAMPLE_CORNER_DIMS), and a
    fixed pseudo-random scatter (the same for every check and run of a file)."""
    lo = np.array([v.lower for v in variables])
    hi = np.array([v.upper for v in variables])
    dims = len(variables)
    unit = [np.full(dims, 0.5)]
    if dims <= SAMPLE_CORNER_DIMS:
        unit += [np.array([(k >> j) & 1 for j in range(dims)], dtype=float) for k in range(2**dims)]
    unit += list(np.random.default_rng(0).random((SAMPLE_INSIDE, dims)))
    return lo + np.array(unit) * (hi - lo)


def formula_problems(variables: list[Variable], formulas: list[Formula],
                     rules: dict[str, str] | None = None) -> list[tuple[str, str]]:
    """Derived formulas that are not finite somewhere in the variables' box (a division by zero, an overflow,
    the square root of a negative number), or that break their field's rule (``>0``, ``>=0``) over the whole box:
    each named with its field, the value and the variables where it happens, so that such a file is refused
    before a search of designs that cannot be built."""
    if not variables or not formulas:
        return []
    points = _sample_points(variables)
    by_name = {v.name: points[:, i] for i, v in enumerate(variables)}
    out = []
    for f in formulas:
        value = np.broadcast_to(f(by_name), (points.shape[0],))
        bad = np.flatnonzero(~np.isfinite(value))
        rule = (rules or {}).get(f.path, "")
        if bad.size:
            where = ("is not finite anywhere in the variables' ranges" if bad.size == value.size else
                     f"is not finite at {bad.size} of {value.size} sampled designs in the variables' ranges")
            out.append((f"optimise.derived.{f.path}",
                        f"'{f.expression}' {where} (e.g. {value[bad[0]]:g} at {_at(variables, points[bad[0]])}): "
                        f"a division by zero, an overflow or a function outside its domain; write a formula "
                        f"that is finite over the whole range of its variables"))
        elif rule in (">0", ">=0") and not np.any(value > 0 if rule == ">0" else value >= 0):
            out.append((f"optimise.derived.{f.path}",
                        f"'{f.expression}' must be {rule} but is {value[0]:g} {f.unit.unit} at "
                        f"{_at(variables, points[0])} and breaks the rule over the whole range of its variables"))
    return out


def _at(variables: list[Variable], point: np.ndarray) -> str:
    return ", ".join(f"{v.name} = {point[i]:.6g} {v.unit}".rstrip() for i, v in enumerate(variables))


def _si_unit(unit: str) -> str:
    """The SI unit of a free variable's unit (``"mm"`` -> ``"m"``)."""
    try:
        q = ureg.Quantity(1.0, unit_of_text(unit)).to_base_units()
    except Exception:  # noqa: BLE001 - reported as a field error by the caller
        raise ProblemFileError([("optimise.variables", f"unknown unit {unit!r}")]) from None
    return f"{q.units:~}".replace(" ", "")


def current_values(space: SearchSpace) -> np.ndarray | None:
    """The variables' values in the problem as given (free variables: mid-range), or None if one lies outside
    its bounds (the search then starts from its own sample only)."""
    out = []
    for v in space.variables:
        x = value_at(space.problem, v.path) if v.path is not None else 0.5 * (v.lower + v.upper)
        if not v.lower <= x <= v.upper:
            return None
        out.append(x)
    return np.array(out)
