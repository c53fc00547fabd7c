"""The ``[optimise]`` table of a problem file: design variables, objectives and constraints.

```toml
[optimise]
generations = 60                      # differential evolution: at most this many generations
population = 40                       # designs per generation (all evaluated in one engine call)
seed = 1

[[optimise.variables]]
parameter = "mechanism.crank.length"  # the key path of any quantity of the file
lower = "20 mm"
upper = "60 mm"

[[optimise.objectives]]
result = "driving_torque.max_abs"     # any per-design result (see machdyn.studies.optimisation.results)
sense = "minimise"                    # or "maximise", or target = "45 deg"

[[optimise.constraints]]
result = "transmission_angle.worst"
min = "40 deg"
```

Quantities (bounds, limits, targets) are text with units, read in the unit of the quantity they bound.
"""

from __future__ import annotations

from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

from ...problem.fields import Angle


class _Spec(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class VariableSpec(_Spec):
    """A design variable: a quantity of the file (``parameter``) or a free name used in ``derived``."""

    parameter: str | None = None
    name: str | None = Field(None, pattern=r"^[A-Za-z_][A-Za-z0-9_]*$")
    lower: Any
    upper: Any
    unit: str | None = None

    @model_validator(mode="after")
    def _named(self):
        if self.parameter is None and self.name is None:
            raise ValueError("give the variable a parameter (a key path of the file) or a name")
        if self.parameter is None and self.unit is None:
            raise ValueError(f"the free variable '{self.name}' needs a unit (e.g. unit = \"m\")")
        return self


class ObjectiveSpec(_Spec):
    """A result to minimise, maximise or bring to a target value."""

    result: str
    sense: Literal["minimise", "maximise", "minimize", "maximize"] = "minimise"
    target: Any = None


class ConstraintSpec(_Spec):
    """A result that must stay within ``min`` ... ``max`` (either may be left out)."""

    result: str
    min: Any = None
    max: Any = None

    @model_validator(mode="after")
    def _bounded(self):
        if self.min is None and self.max is None:
            raise ValueError(f"the constraint on '{self.result}' needs min, max or both")
        return self


class OptimiseSpec(_Spec):
    """``[optimise]``: variables, one objective (differential evolution) or several (a Pareto front by
    NSGA-II), constraints, and the search settings."""

    variables: list[VariableSpec] = Field(min_length=1)
    derived: dict[str, str] = {}
    objectives: list[ObjectiveSpec] = Field(min_length=1)
    constraints: list[ConstraintSpec] = []
    population: int = Field(40, ge=5, le=100_000, strict=True)
    generations: int = Field(100, ge=1, le=100_000, strict=True)
    tolerance: float = Field(1e-6, gt=0.0, lt=1.0)
    seed: int | None = 1
    positions: int | None = Field(None, ge=8, le=100_000, strict=True)
    #: a design whose transmission angle comes closer than this to 0 or 180 deg is degenerate (default 10 deg)
    min_transmission_angle: Angle | None = Field(None, ge=0.0, lt=1.5707963267948966)
