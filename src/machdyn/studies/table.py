"""Design sweeps in problem files: one quantity of the file takes several values, or several quantities are
explored together over a full grid, a Latin hypercube or a Sobol sample.

```toml
[sweep]
parameter = "mechanism.crank.length"     # the dotted path of any quantity of the file
values = ["30 mm", "35 mm", "40 mm"]      # or: start = "30 mm", stop = "45 mm", count = 16
```

```toml
[sweep]
method = "sobol"                          # "grid" (every combination), "lhs" or "sobol"
samples = 65536                           # designs drawn (lhs, sobol)
seed = 1                                  # the same seed draws the same designs

[[sweep.quantities]]
parameter = "mechanism.crank.length"
start = "30 mm"                           # a grid also takes count = ..., or values = [...]
stop = "45 mm"
```

Each value is checked by the same rule as the quantity it replaces (unit, sign). A one-quantity sweep given
by ``parameter`` with no other key is analysed as one stacked model by :func:`machdyn.linkage.sweep`; any
other sweep is a design-space exploration (:mod:`machdyn.studies.exploration`): designs drawn partition by partition,
evaluated in bounded memory, written to Parquet, optionally on a Dask cluster.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np
from pydantic import BaseModel, Field, field_validator, model_validator

from ..errors import ProblemFileError
from ..kinds import CAPABILITIES
from ..problem.fields import Angle, FieldError, Unit, to_si
from ..problem.paths import assign, quantity_unit
from ..results.catalogue import ALIASES, canonical, find, population_quantities
from ..results.names import did_you_mean_result, results_to_choose
from ..results.population import DEFAULT_MIN_TRANSMISSION_DEG
from ..units import Q_, convert, quantity_of_text, unit_of_text

#: At most this many designs in one sweep (grids and samples alike).
MAX_DESIGNS = 100_000_000

#: The objective an exploration ranks its designs by unless ``objective`` names another per-design result of
#: the catalogue (:mod:`machdyn.results.catalogue`; old names such as ``max_driving_torque`` are accepted).
DEFAULT_OBJECTIVE = "driving_torque.max_abs"

#: Keys of ``[sweep]`` that make it a design-space exploration (a one-quantity ``parameter`` sweep has none).
EXPLORATION_KEYS = ("quantities", "method", "samples", "seed", "partition", "objective", "scheduler", "workers",
                    "store")



def _of_a_capability(producer: str) -> bool:
    """True for the producer of a capability's results (its table's name, ``parts``)."""
    return producer in CAPABILITIES


def _values_rule(where: str, method: str, values, start, stop, count) -> None:
    ranged = (start, stop, count)
    if method != "grid":
        if values is not None or count is not None:
            raise ValueError(f"{where}with method = '{method}' give start and stop (the range to sample), "
                             "not values or count")
        if start is None or stop is None:
            raise ValueError(f"{where}with method = '{method}' give both start and stop")
        return
    if values is None and any(v is None for v in ranged):
        raise ValueError(f"{where}give either values = [...] or all of start, stop and count")
    if values is not None and any(v is not None for v in ranged):
        raise ValueError(f"{where}give either values = [...] or start, stop and count, not both")
    if values is not None and len(values) < 1:
        raise ValueError(f"{where}values must list at least one value")


class QuantitySpec(BaseModel):
    """``[[sweep.quantities]]``: one quantity of an exploration and its values or its range."""

    model_config = {"extra": "forbid", "frozen": True}

    parameter: str
    values: list[Any] | None = None
    start: Any = None
    stop: Any = None
    count: int | None = Field(None, ge=2, le=1_000_000, strict=True)


def scheduler_address_error(value: str) -> str | None:
    """Why ``value`` is not the address of a Dask scheduler (``tcp://host:8786``, ``tls://[::1]:8786``), or None."""
    shown = value if len(value) <= 80 else value[:77] + "..."
    match = re.fullmatch(r"(tcp|tls)://(\[[0-9A-Fa-f:.]+\]|[A-Za-z0-9](?:[A-Za-z0-9.-]{0,251}[A-Za-z0-9])?):(\d{1,5})",
                         value)
    if match is None:
        return f"must be the address of a Dask scheduler, like 'tcp://host:8786'; got '{shown}'"
    if not 1 <= int(match.group(3)) <= 65535:
        return f"must have a port from 1 to 65535, like 'tcp://host:8786'; got '{shown}'"
    return None


class SweepSpec(BaseModel):
    """``[sweep]``: the quantity to vary and its values (a list, or start/stop/count evenly spaced), or several
    quantities explored together (``quantities``, ``method``, ``samples``, ``seed``), and where and how the
    designs are evaluated (``partition`` designs per task, ``scheduler`` a Dask address, ``workers`` local
    worker processes, ``store`` the Parquet folder, ``objective`` the result that ranks the designs), and what
    each design keeps (``columns``: results besides the default ones; ``min_transmission_angle``: the threshold
    of a degenerate design's poor transmission)."""

    model_config = {"extra": "forbid", "frozen": True}

    parameter: str | None = None
    values: list[Any] | None = None
    start: Any = None
    stop: Any = None
    count: int | None = Field(None, ge=2, le=1_000_000, strict=True)
    quantities: list[QuantitySpec] | None = Field(None, min_length=1, max_length=32)
    method: Literal["grid", "lhs", "sobol"] | None = None
    samples: int | None = Field(None, ge=1, le=MAX_DESIGNS, strict=True)
    seed: int | None = Field(None, ge=0, le=2**63 - 1, strict=True)
    partition: int | None = Field(None, ge=1, le=1_000_000, strict=True)
    objective: str | None = None
    scheduler: str | None = None
    workers: int | None = Field(None, ge=1, le=512, strict=True)
    store: str | None = Field(None, min_length=1)
    min_transmission_angle: Angle | None = None
    columns: list[str] | None = Field(None, max_length=256)

    @field_validator("scheduler")
    @classmethod
    def _an_address(cls, value: str | None) -> str | None:
        problem = scheduler_address_error(value) if value is not None else None
        if problem is not None:
            raise ValueError(problem)
        return value

    @model_validator(mode="after")
    def _one_way_of_giving_values(self):
        if (self.parameter is None) == (self.quantities is None):
            raise ValueError("give either parameter = \"...\" (one quantity) or [[sweep.quantities]] (several), "
                             "not both" if self.parameter is not None else
                             "give parameter = \"...\" (one quantity) or [[sweep.quantities]] (several)")
        method = self.sampling
        if self.parameter is not None:
            _values_rule("", method, self.values, self.start, self.stop, self.count)
        else:
            loose = [k for k in ("values", "start", "stop", "count") if getattr(self, k) is not None]
            if loose:
                raise ValueError(f"with [[sweep.quantities]] give {', '.join(loose)} in each quantity, not in [sweep]")
            for i, q in enumerate(self.quantities or ()):
                _values_rule(f"quantities[{i}]: ", method, q.values, q.start, q.stop, q.count)
        if method == "grid" and self.samples is not None:
            raise ValueError("samples is for method = 'lhs' or 'sobol'; a grid takes every combination of values")
        if method != "grid" and self.samples is None:
            raise ValueError(f"method = '{method}' needs samples = <number of designs>")
        if self.objective is not None:
            found = find(self.goal)
            if found is None or not found[0].group or found[0].kind != "number" or found[0].group == "status":
                names = _objective_names()
                hint = f"{did_you_mean_result(self.objective, names)} ({results_to_choose(self.objective, names)})"
                raise ValueError("objective must name a per-design result (a key of docs/results.md such as "
                                 "driving_torque.max_abs, frame_force.max or joint.<name>.max_force); got "
                                 f"'{self.objective}'{hint}")
        for i, column in enumerate(self.columns or ()):
            found = find(canonical(column))
            if found is None and "." in column:
                continue  # perhaps a result of another table of the file: the sweep's check knows the file's tables
            if found is not None and not found[0].group and _of_a_capability(found[0].producer):
                continue  # a capability's result: its population form or each design's run gives it
            if found is None or not found[0].group or found[0].group == "status":
                names = _objective_names()
                hint = f"{did_you_mean_result(column, names)} ({results_to_choose(column, names)})"
                raise ValueError(f"columns[{i}] must name a per-design result (a key of docs/results.md such as "
                                 f"kinetic_energy.fluctuation); got '{column}'{hint}")
        lowest = self.min_transmission_angle
        if lowest is not None and not 0.0 <= lowest < math.pi / 2:
            raise ValueError(f"min_transmission_angle must be at least 0 deg and below 90 deg; got "
                             f"{math.degrees(lowest):g} deg")
        return self

    @property
    def is_exploration(self) -> bool:
        """True unless this is a one-quantity ``parameter`` sweep with none of the exploration keys."""
        return any(getattr(self, key) is not None for key in EXPLORATION_KEYS)

    @property
    def sampling(self) -> str:
        """The sampling method: ``grid`` unless ``method`` says otherwise."""
        return self.method or "grid"

    @property
    def goal(self) -> str:
        """The per-design result that ranks the designs, best first by its declared better direction
        (:func:`machdyn.results.catalogue.better_of`): ``objective`` (its catalogue key) or the peak driving
        torque."""
        return canonical(self.objective) if self.objective else DEFAULT_OBJECTIVE

    @property
    def extra_columns(self) -> tuple[str, ...]:
        """The results asked for besides the default columns (``columns``, as catalogue keys)."""
        return tuple(canonical(c) for c in self.columns or ())

    @property
    def transmission_limit(self) -> float:
        """The threshold [rad] of ``poor_transmission``: ``min_transmission_angle`` or the default 10 deg."""
        if self.min_transmission_angle is not None:
            return float(self.min_transmission_angle)
        return math.radians(DEFAULT_MIN_TRANSMISSION_DEG)


def _objective_names() -> list[str]:
    """The keys an objective may name, and the old names still accepted."""
    return [q.key for q in population_quantities("compactor") if not q.is_pattern] + list(ALIASES)


@dataclass(frozen=True)
class SweepPlan:
    """The expanded sweep: the parameter's path, its values in SI and in the file's unit, and the variants."""

    parameter: str
    si_unit: str
    display_unit: str
    values_si: np.ndarray
    values_display: np.ndarray
    problems: tuple


def _target(problem: BaseModel, path: str) -> Unit:
    """The unit metadata of the quantity at ``path`` (e.g. ``mechanism.crank.length``)."""
    if path.split(".")[0] == "drive" and path.split(".")[-1] in ("start", "stop"):
        raise FieldError(f"'{path}' sets the crank angles, which every variant of a sweep shares")
    return quantity_unit(problem, path)


def _display_unit(text: Any, meta: Unit) -> str:
    try:
        return f"{quantity_of_text(str(text)).units:~}" or meta.unit
    except Exception:  # the value itself is reported by to_si; fall back to SI here
        return meta.unit


def _written_unit(text: Any, meta: Unit) -> str:
    """The unit a value was written in (``"-1 N*m"`` -> ``"N*m"``) if it is one of the quantity's dimension."""
    parts = str(text).strip().split(maxsplit=1)
    if len(parts) == 2:
        try:
            Q_(1.0, meta.unit).to(unit_of_text(parts[1]))
            return parts[1]
        except Exception:  # noqa: BLE001 - not a plain unit: the pint spelling below
            pass
    return _display_unit(text, meta)


def expand_sweep(problem: Any) -> SweepPlan:
    """The variants of a problem with a ``[sweep]`` table; every mistake reported at once with its path."""
    spec: SweepSpec = problem.sweep
    if spec.parameter is None or spec.is_exploration:
        raise ProblemFileError([("sweep", "expand_sweep expands a one-quantity sweep; explore several quantities "
                                          "with machdyn.studies.exploration")])
    parameter: str = spec.parameter
    try:
        meta = _target(problem, parameter)
    except FieldError as exc:
        raise ProblemFileError([("sweep.parameter", str(exc))]) from None
    problems = []
    if spec.values is not None:
        raw = list(spec.values)
        si = []
        for i, value in enumerate(raw):
            try:
                si.append(to_si(value, meta))
            except FieldError as exc:
                problems.append((f"sweep.values[{i}]", f"{exc} (for {parameter})"))
        display = _display_unit(raw[0], meta)
    else:
        si = []
        for key in ("start", "stop"):
            try:
                si.append(to_si(getattr(spec, key), meta))
            except FieldError as exc:
                problems.append((f"sweep.{key}", f"{exc} (for {parameter})"))
        display = _display_unit(spec.start, meta)
        if not problems:
            si = list(np.linspace(si[0], si[1], int(spec.count or 2)))
    if problems:
        raise ProblemFileError(problems)
    values_si = np.asarray(si, dtype=float)
    variants = tuple(assign(problem, parameter, float(v)) for v in values_si)
    shown = np.array([convert(v, meta.unit, display) for v in values_si]) if display != meta.unit else values_si
    return SweepPlan(parameter, meta.unit, display, values_si, shown, variants)


# ------------------------------------------------------------------------------------- explorations


@dataclass(frozen=True)
class QuantityRange:
    """One explored quantity: its path, units, its grid values (None when sampled) and the ends of its range,
    ``start`` and ``stop`` (all in SI)."""

    parameter: str
    si_unit: str
    display_unit: str
    values: tuple[float, ...] | None
    start: float
    stop: float


def _quantity_specs(spec: SweepSpec) -> list[tuple[str, Any]]:
    """(path prefix for messages, spec) of each explored quantity; a one-quantity sweep is its own spec."""
    if spec.quantities is None:
        return [("sweep", spec)]
    return [(f"sweep.quantities[{i}]", q) for i, q in enumerate(spec.quantities)]


def explore_quantities(problem: Any) -> tuple[QuantityRange, ...]:
    """The quantities a ``[sweep]`` explores, each checked against the quantity it replaces (unit, sign; every
    value of a range obeys the rule when both ends do); every mistake reported at once with its path."""
    spec: SweepSpec = problem.sweep
    out: list[QuantityRange] = []
    problems: list[tuple[str, str]] = []
    seen: set[str] = set()
    for where, q in _quantity_specs(spec):
        assert q.parameter is not None
        if q.parameter in seen:
            problems.append((f"{where}.parameter", f"'{q.parameter}' is explored twice; give each quantity once"))
            continue
        seen.add(q.parameter)
        try:
            meta = _target(problem, q.parameter)
        except FieldError as exc:
            problems.append((f"{where}.parameter", str(exc)))
            continue
        raw = list(q.values) if q.values is not None else [q.start, q.stop]
        keys = [f"values[{i}]" for i in range(len(raw))] if q.values is not None else ["start", "stop"]
        si = []
        for key, value in zip(keys, raw, strict=True):
            try:
                si.append(to_si(value, meta))
            except FieldError as exc:
                problems.append((f"{where}.{key}", f"{exc} (for {q.parameter})"))
        if len(si) < len(raw):
            continue
        if q.values is None and q.count is not None:
            values: tuple[float, ...] | None = tuple(float(v) for v in np.linspace(si[0], si[1], q.count))
        elif q.values is not None:
            values = tuple(float(v) for v in si)
        else:
            values = None
        if values is None and not si[0] != si[1]:
            problems.append((f"{where}.stop", f"must differ from start to give a range to sample; got "
                                              f"'{q.stop}' (for {q.parameter})"))
        out.append(QuantityRange(q.parameter, meta.unit, _written_unit(raw[0], meta), values, float(si[0]),
                                 float(si[-1])))
    if problems:
        raise ProblemFileError(problems)
    return tuple(out)


def sweep_unit(problem: BaseModel, path: str) -> Unit:
    """The unit and sign rule of the quantity at ``path`` of a problem; raises
    :class:`~machdyn.errors.ProblemFileError` naming the path if it is not a quantity that can vary."""
    try:
        return _target(problem, path)
    except FieldError as exc:
        raise ProblemFileError([("parameters", str(exc))]) from None


def substitute(problem: BaseModel, values: dict[str, Any]) -> Any:
    """``problem`` with the quantity at each path replaced by the value given (a float, or an array of one value
    per design), without validation: the values must have been checked (see :func:`explore_quantities`)."""
    for path, value in values.items():
        problem = assign(problem, path, value)
    return problem
