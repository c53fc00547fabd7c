"""The ``[balance]`` table of a mechanism problem file: balance the linkage and report before and after.

```toml
[balance]
method = "counterweights"          # "crank", "berkof_lowen", "counterweights" or "spring"
positions = 360                    # crank angles over one turn for the evaluation

[[balance.counterweights]]         # where counterweights may go (method "counterweights")
body = "crank"
radius = "60 mm"                   # pivoted bodies: the radius that turns m*r into a mass
```

``method = "crank"`` takes ``fraction`` and ``radius`` (a slider-crank); ``"berkof_lowen"`` takes ``crank_radius``
and ``rocker_radius`` (a four-bar); ``"counterweights"`` takes ``[[balance.counterweights]]`` and
``[[balance.masses]]`` (existing ``[[counterweights]]`` of the file whose mass is free) and, optionally,
``[balance.objective]`` (weights of force, moment, torque, joint force: a bounded optimisation instead of
the closed-form least squares) or ``[[balance.states]]`` (operating states: quantities of the file set to other
values, minimising the ``mode = "sum"`` or ``"worst"`` over them); ``"spring"`` takes ``[balance.spring]``.
"""

from __future__ import annotations

from typing import Any, Literal

import numpy as np
from pydantic import Field, model_validator

from ..errors import InputError, ProblemFileError
from ..linkage import kinematics
from ..pipeline import Capability, Outcome, StageContext
from ..problem.build import build_mechanism
from ..problem.fields import Angle, AngularVelocity, Mass, NonNegativeLength, Point, PositiveLength, Stiffness
from ..problem.schema import Spec
from ..results.labels import Label
from .frame import BalanceRun, cycle
from .methods import METHODS, balance, method_fits, operating_states
from .robust import RobustResult

__all__ = ["BalanceSpec", "BalanceRun", "run", "check", "CAPABILITY", "LABELS"]


class SlotSpec(Spec):
    """A place for a counterweight: on ``body``, about its point ``about`` (default its ground pivot), at
    ``radius`` (closed form on pivoted bodies), within ``mass_max`` and ``radius_max`` (optimisation)."""

    body: str
    radius: PositiveLength | None = None
    about: str | None = None
    mass_max: Mass | None = None
    radius_max: PositiveLength | None = None


class MassSpec(Spec):
    """An existing ``[[counterweights]]`` entry of the file (by ``name``) whose mass is free within bounds."""

    name: str
    mass_min: Mass = 0.0
    mass_max: Mass | None = None


class ObjectiveSpec(Spec):
    """Weights of the balancing objective (each term relative to its value before balancing)."""

    force: float = Field(1.0, ge=0.0)
    moment: float = Field(0.0, ge=0.0)
    torque: float = Field(0.0, ge=0.0)
    joint: float = Field(0.0, ge=0.0)
    measure: Literal["rms", "peak"] = "rms"

    @model_validator(mode="after")
    def _some_weight(self):
        if not any(w > 0 for w in (self.force, self.moment, self.torque, self.joint)):
            raise ValueError("at least one of force, moment, torque, joint must be > 0")
        return self


class StateSpec(Spec):
    """An operating state: quantities of the file set to other values (``set``, dotted paths as in ``[sweep]``),
    an optional crank ``speed``, a ``weight`` and a ``crank_turn`` (crank frame turned against the shaft)."""

    name: str
    set: dict[str, Any] = {}
    speed: AngularVelocity | None = None
    weight: float = Field(1.0, ge=0.0)
    crank_turn: Angle = 0.0

    @model_validator(mode="after")
    def _moving(self):
        if self.speed is not None and self.speed == 0.0:
            raise ValueError("speed must not be zero (the shaking force of a state at rest is not defined)")
        return self


class SpringSpec(Spec):
    """A compensating spring from the body-frame ``point`` of ``body`` to the ground ``anchor``."""

    body: str
    point: Point
    anchor: Point
    stiffness_max: Stiffness | None = None
    free_length_min: NonNegativeLength = 0.0
    free_length_max: NonNegativeLength | None = None

    @model_validator(mode="after")
    def _ordered(self):
        if self.free_length_max is not None and self.free_length_max < self.free_length_min:
            raise ValueError(f"free_length_max ({self.free_length_max:g} m) must not be below free_length_min "
                             f"({self.free_length_min:g} m)")
        return self


class BalanceSpec(Spec):
    """The ``[balance]`` table (see the module docstring)."""

    method: Literal["crank", "berkof_lowen", "counterweights", "spring"]
    positions: int = Field(360, ge=8, le=100_000, strict=True)
    fraction: float | None = Field(None, ge=0.0, le=1.0)
    radius: PositiveLength | None = None
    crank_radius: PositiveLength | None = None
    rocker_radius: PositiveLength | None = None
    counterweights: list[SlotSpec] = []
    masses: list[MassSpec] = []
    objective: ObjectiveSpec | None = None
    states: list[StateSpec] = []
    mode: Literal["sum", "worst"] = "sum"
    spring: SpringSpec | None = None
    reference_reduction: float | None = Field(None, ge=0.0, le=1.0)
    reference_source: str = ""

    @model_validator(mode="after")
    def _method_needs(self):
        needs = METHODS[self.method].needs
        missing = [n for n in needs if getattr(self, n) is None]
        if missing:
            raise ValueError(f"method '{self.method}' needs {', '.join(missing)}")
        if self.method == "counterweights" and not (self.counterweights or self.masses):
            raise ValueError("method 'counterweights' needs [[balance.counterweights]] or [[balance.masses]]")
        if self.states and self.objective is not None:
            raise ValueError("give either [[balance.states]] (robust least squares) or [balance.objective], not both")
        return self


LABELS = {
    "balance.rms_force_before": Label("Balance: RMS shaking force before", "N", over="time_rms", better="lower"),
    "balance.rms_force_after": Label("Balance: RMS shaking force after", "N", over="time_rms", better="lower"),
    "balance.peak_force_before": Label("Balance: peak shaking force before", "N", over="max", better="lower"),
    "balance.peak_force_after": Label("Balance: peak shaking force after", "N", over="max", better="lower"),
    "balance.rms_moment_before": Label("Balance: RMS shaking moment before", "N*m", over="time_rms", better="lower"),
    "balance.rms_moment_after": Label("Balance: RMS shaking moment after", "N*m", over="time_rms", better="lower"),
    "balance.torque_fluctuation_before": Label("Balance: driving torque fluctuation before", "N*m", over="range",
                                               better="lower"),
    "balance.torque_fluctuation_after": Label("Balance: driving torque fluctuation after", "N*m", over="range",
                                              better="lower"),
    "balance.peak_joint_force_before": Label("Balance: peak joint force before", "N", over="max", better="lower"),
    "balance.peak_joint_force_after": Label("Balance: peak joint force after", "N", over="max", better="lower"),
    "balance.com_travel_after": Label("Balance: travel of the total centre of mass after", "m", "mm", over="range",
                                      better="lower"),
    "balance.force_reduction": Label("Balance: RMS shaking force reduction", "", over="scalar", better="higher"),
    "balance.mean_reduction": Label("Balance: mean RMS shaking force reduction over the states", "", over="scalar",
                                    better="higher"),
    "balance.worst_before": Label("Balance: worst state's RMS shaking force before", "N", over="time_rms",
                                  better="lower"),
    "balance.worst_after": Label("Balance: worst state's RMS shaking force after", "N", over="time_rms",
                                 better="lower"),
    "balance.spring_stiffness": Label("Balance: spring stiffness", "N/m", over="scalar", better="none"),
    "balance.spring_free_length": Label("Balance: spring free length", "m", "mm", over="scalar", better="none"),
}


def check(problem: Any, table: BalanceSpec, source: str | None = None) -> list[tuple[str, str]]:
    """Validations that need the model, so that ``check`` and ``run`` agree: the method fits the linkage, the
    bodies, points and masses named exist, closed-form counterweights on pivoted bodies have a radius, a spring
    never has zero length, and every operating state builds and assembles over the whole turn."""
    try:
        mech = build_mechanism(problem)
    except (ProblemFileError, InputError):
        return []  # the kind reports the model's own problems
    found: list[tuple[str, str]] = []
    # a misspelled body is reported once, under its own field, not again for the method and every state
    bodies = {b.name for b in mech.bodies}
    named = [(f"balance.counterweights[{i}].body", s.body) for i, s in enumerate(table.counterweights)]
    if table.spring is not None:
        named.append(("balance.spring.body", table.spring.body))
    for field, body in named:
        if body not in bodies:
            found.append((field, f"mechanism '{mech.name}' has no body '{body}'; bodies: "
                                 f"{', '.join(b.name for b in mech.bodies)}"))
    if found:
        return found
    try:
        method_fits(mech, table, abs(float(problem.drive.speed)))
    except InputError as exc:
        found.append(("balance", str(exc)))
    names = {c.name for c in problem.counterweights if c.name}
    for i, m in enumerate(table.masses):
        if m.name not in names:
            found.append((f"balance.masses[{i}].name", f"no [[counterweights]] entry named '{m.name}'; named: "
                          f"{', '.join(sorted(names)) or 'none'}"))
    try:
        states = operating_states(problem, table)
    except ProblemFileError as exc:
        return found + list(exc.problems)
    for i, state in enumerate(states):
        try:
            kinematics(state.mechanism, cycle(table.positions), state.speed, 0.0, on_fail="raise")
            METHODS[table.method].fits(state.mechanism, table, state.speed)
        except InputError as exc:
            found.append((f"balance.states[{i}]", str(exc)))
    return found


def run(ctx: StageContext) -> Outcome:
    """Balance the model by the table's method and report the frame loads before and after."""
    table: Any = ctx.table  # a validated BalanceSpec: the method's fields are present (model validator)
    mech = ctx.mechanism
    if mech.design_count is not None:
        raise ProblemFileError([("balance", "balancing takes a single design; remove [sweep] or balance each design")])
    speed = abs(float(ctx.problem.drive.speed))
    phi = cycle(table.positions)
    try:
        result, tradeoff = balance(mech, ctx.problem, table, phi, speed)
    except InputError as exc:
        raise ProblemFileError([("balance", str(exc))]) from None
    done = BalanceRun(table.method, result, tradeoff, table.reference_reduction, table.reference_source,
                      table.fraction)
    return _outcome(done)


def _outcome(done: BalanceRun) -> Outcome:
    r = done.result
    warnings = [n for n in getattr(r, "notes", ()) if "did not converge" in n]
    if isinstance(r, RobustResult):
        rows = r.rows
        scalars = {
            "balance.mean_reduction": r.mean_reduction,
            "balance.worst_before": max(x.rms_before for x in rows),
            "balance.worst_after": r.worst_after,
        }
        labels: dict[str, Label] = {}
        for name, (mass, pos) in r.placed.items():
            key = f"balance.{name}.mass"
            scalars[key] = mass
            labels[key] = Label(f"Balance: mass of {name}", "kg")
            if pos is not None:
                for axis, value in zip("xy", pos, strict=True):
                    scalars[f"balance.{name}.{axis}"] = value
                    labels[f"balance.{name}.{axis}"] = Label(f"Balance: {axis} of {name} (body frame)", "m", "mm")
        series = {"balance_states": {
            "state": (np.array([x.state for x in rows]), ""),
            "rms_before": (np.array([x.rms_before for x in rows]), "N"),
            "rms_after": (np.array([x.rms_after for x in rows]), "N"),
            "peak_before": (np.array([x.peak_before for x in rows]), "N"),
            "peak_after": (np.array([x.peak_after for x in rows]), "N"),
            "reduction": (np.array([x.reduction for x in rows]), ""),
        }}
        summary = ("balance.mean_reduction", "balance.worst_before", "balance.worst_after", *labels)
        return Outcome(results=done, scalars=scalars, labels=labels, series=series,
                       summary=summary, warnings=tuple(warnings))
    t = r.table
    scalars = {f"balance.{row.key}_{when}": value for row in t.rows
               for when, value in (("before", row.before), ("after", row.after))
               if f"balance.{row.key}_{when}" in LABELS}
    scalars["balance.force_reduction"] = -t.row("rms_force").change
    labels = {}
    for p in r.counterweights:
        if hasattr(p, "stiffness"):
            scalars["balance.spring_stiffness"] = float(p.stiffness)
            scalars["balance.spring_free_length"] = float(p.free_length)
            continue
        key = f"balance.{p.name}.mass"
        scalars[key] = float(p.mass)
        labels[key] = Label(f"Balance: mass of {p.name} on {p.body}", "kg")
        for axis, value in zip("xy", p.position, strict=True):
            k = f"balance.{p.name}.{axis}"
            scalars[k] = float(value)
            labels[k] = Label(f"Balance: {axis} of {p.name} in the frame of {p.body}", "m", "mm")
    series = {"balance_force": {
        "crank_angle": (r.before.crank_angle, "rad"),
        "fx_before": (r.before.fx, "N"), "fy_before": (r.before.fy, "N"),
        "fx_after": (r.after.fx, "N"), "fy_after": (r.after.fy, "N"),
        "moment_before": (r.before.moment, "N*m"), "moment_after": (r.after.moment, "N*m"),
        "torque_before": (r.before.torque, "N*m"), "torque_after": (r.after.torque, "N*m"),
    }}
    if done.tradeoff is not None:
        c = done.tradeoff
        series["balance_tradeoff"] = {
            "fraction": (c.fraction, ""), "counterweight_mass": (c.counterweight_mass, "kg"),
            "peak_along": (c.peak_along, "N"), "peak_across": (c.peak_across, "N"),
            "peak_total": (c.peak_total, "N"), "rms_total": (c.rms_total, "N"),
        }
    summary = ("balance.rms_force_before", "balance.rms_force_after", "balance.force_reduction",
               "balance.rms_moment_before", "balance.rms_moment_after", *[k for k in scalars if k.endswith(".mass")],
               *[k for k in ("balance.spring_stiffness", "balance.spring_free_length") if k in scalars])
    return Outcome(results=done, scalars=scalars, labels=labels, series=series, summary=summary,
                   warnings=tuple(warnings))


CAPABILITY = Capability(
    table="balance",
    schema=BalanceSpec,
    run=run,
    step="balancing",
    kinds=("mechanism",),
    labels=LABELS,
    report="machdyn.report.balancing:sections",
    check=check,
    result_type=BalanceRun,
    population="machdyn.balancing.population:balance_population",
)
