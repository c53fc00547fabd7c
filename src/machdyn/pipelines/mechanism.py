"""The ``[mechanism]`` kind: any planar linkage built from dyads, or one of the standard mechanisms."""

from __future__ import annotations

from typing import Any

from ..errors import ProblemFileError
from ..pipeline import Outcome, ProblemKind, Step
from ..problem.build import build_mechanism
from ..problem.schema import CustomSpec, LinkageProblem, LinkSpec
from ..results.linkage import LINKAGE_LABELS
from .linkage_run import analyse_linkage, check_assembly


def build(problem: Any) -> tuple[Any, list[tuple[str, str]]]:
    """The engine's model of the problem, or the problems that stop it being built."""
    try:
        return build_mechanism(problem), []
    except ProblemFileError as exc:
        return None, list(exc.problems)


def default_mass_warnings(problem: Any) -> list[str]:
    """What the file left to defaults that the user should know: bars without masses, bare custom bodies."""
    spec = problem.mechanism
    if isinstance(spec, CustomSpec):
        # Custom bodies have no bar to take defaults from: a mass without inertia is a point mass, a mass without
        # a centre of mass sits at the body's origin; either may not be what the author meant. Say only what
        # was left out.
        said = []
        for i, b in enumerate(spec.bodies):
            given = b.model_fields_set
            if b.mass <= 0.0 or {"inertia", "com"} <= given:
                continue
            left = [text for field, text in (("inertia", "its inertia is taken as 0 kg*m^2 (a point mass)"),
                                              ("com", "its centre of mass is taken at the body's origin (0, 0)"))
                    if field not in given]
            absent = " or ".join(f for f in ("inertia", "com") if f not in given)
            said.append(f"mechanism.bodies[{i}] ('{b.name}'): mass given without {absent}; {' and '.join(left)}. "
                        "Give inertia and com for a real link.")
        return said
    missing = [
        name for name in type(spec).model_fields
        if isinstance(getattr(spec, name), LinkSpec) and getattr(spec, name).mass is None
    ]
    if not missing:
        return []
    return [
        f"No mass given for {', '.join(missing)}: taken as uniform bar(s) of "
        f"{spec.linear_density:g} kg/m (mechanism.linear_density)."
    ]


def analyse(problem: Any, mech: Any, step: Step) -> Outcome:
    return analyse_linkage(problem, mech, step, default_mass_warnings(problem))


KIND = ProblemKind(
    name="mechanism",
    schema=LinkageProblem,
    build=build,
    check=check_assembly,
    analyse=analyse,
    title=lambda problem: problem.meta.name,
    steps=("model", "analysis"),
    labels=LINKAGE_LABELS,
    report="machdyn.report.mechanism:sections",
)
