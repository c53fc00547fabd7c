"""The results of N designs of a kind with no linkage population — a cam, a shaft line — at once, through the
population form its kind declares (:attr:`machdyn.pipeline.ProblemKind.population`), instead of one whole run per
design (:mod:`machdyn.studies.per_design`).

``[optimise]`` (:mod:`machdyn.studies.optimisation.by_runs`) and ``[sweep]`` (:mod:`machdyn.studies.sweep.runs`)
ask :func:`kind_population_form` once, with the file's own design, whether the form gives every result they need
for the paths their designs set: if it does, every population is evaluated by it and the study says so; if not,
they run each design whole and say why. A sweep runs whole only the variants the form gives no value for (a
variant that cannot be built, or whose run would fail), so that their status names the reason; with the form, a
variant's status does not name the design checks its run would fail (a pressure angle over its limit).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import MachdynError
from ..kinds import KINDS, kind
from ..pipeline import import_object
from .exploration.execution import current

#: The message a study gives when the population form evaluates its designs.
AT_ONCE = "population form: {count} designs at once ({kind} kind, one NumPy pass per population)"


@dataclass(frozen=True)
class KindPopulation:
    """A kind's population form bound to one problem and the results a study asks for."""

    problem: Any
    keys: tuple[str, ...]
    form: Callable[[Any, Mapping[str, Any], Iterable[str]], dict[str, np.ndarray] | None]
    kind: str

    def __call__(self, values: Mapping[str, Any]) -> dict[str, np.ndarray] | None:
        """(N,) arrays of the keys for the designs whose values by path are ``values``; None if the form declines."""
        try:
            found = self.form(self.problem, values, self.keys)
        except (MachdynError, ArithmeticError, ValueError):
            return None
        if found is None or any(k not in found for k in self.keys):
            return None
        return {k: np.asarray(found[k], dtype=float) for k in self.keys}


def tell(text: str) -> None:
    """Say ``text`` to the user on the terminal, where the run has a channel for notes (the execution settings'
    ``estimate``)."""
    report = current().estimate
    if report is not None and text:
        report(text)


def kind_name(problem: Any) -> str | None:
    """The main table of ``problem``'s kind (``"cam"``), None if it has none."""
    fields = getattr(type(problem), "model_fields", {})
    return next((t for t in fields if t in KINDS and getattr(problem, t, None) is not None), None)


def kind_population_form(problem: Any, keys: Iterable[str],
                         start: Mapping[str, Any]) -> tuple[KindPopulation | None, str]:
    """The population form of ``problem``'s kind for ``keys``, tried on the designs ``start`` (values by path,
    each a (N,) array: the paths the study's designs set), and a sentence for the user: what evaluates the designs
    and, when they are run one by one, why."""
    name = kind_name(problem)
    wanted = tuple(dict.fromkeys(keys))
    path = kind(name).population if name is not None else None
    if path is None:
        return None, f"each design run whole: the {name or 'file'} kind has no population form"
    ready = KindPopulation(problem, wanted, import_object(path), name or "")
    if ready(start) is None:
        varied = ", ".join(start) or "none"
        return None, (f"each design run whole: the {name} kind's population form does not give "
                      f"{', '.join(wanted)} for designs that set {varied}")
    return ready, ""


def sweep_at_once(problem: Any, parameter: str, values_si: Any, asked: Iterable[str]) -> dict[str, np.ndarray] | None:
    """The columns ``asked`` of a one-quantity sweep's variants by the kind's population form, (N,) arrays (NaN
    where a variant must be run whole to learn why it has no value), or None when the form cannot give them; the
    user is told when it does."""
    values = {parameter: np.asarray(values_si, dtype=float)}
    ready, why = kind_population_form(problem, asked, values)
    found = ready(values) if ready is not None else None
    if found is None:  # the sweep announces a long run of its variants itself
        return None
    tell(f"sweep of {parameter}: " + AT_ONCE.format(count=len(values[parameter]), kind=ready.kind if ready else ""))
    return found
