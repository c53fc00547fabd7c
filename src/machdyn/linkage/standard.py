"""The standard mechanisms, each declared once: its parameters (as a problem file writes them), their defaults
and its builder.

The problem-file schema (:mod:`machdyn.problem.schema`) makes one table per declaration and
:mod:`machdyn.problem.build` calls the builder through it, so a mechanism added here is known to the Python
API and to problem files alike. Defaults are those of the builder's signature.

A declaration lists its fields in problem-file order. A *part* is a sub-table describing a body (a link with
its length, a block, the double crank) or the ground link; its values go to builder arguments
(``args``: field of the sub-table -> builder argument) and the mass properties it gives replace the
builder's defaults for ``body``. A *parameter* is a plain value (a length, angle, point or branch) passed to
the builder argument of the same name.
"""

from __future__ import annotations

import inspect
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from .builders import double_slider_crank, four_bar, inverted_slider_crank, six_bar, slider_crank
from .model import Mechanism

#: Part kinds: a link with a required length, a link whose length may be left out, a block (slider), the
#: ground link with its direction, the ground link's length only, and the crank of a double slider-crank.
PART_KINDS = ("link", "optional_link", "block", "ground", "ground_length", "double_crank")
#: Parameter kinds.
PARAMETER_KINDS = ("length", "angle", "point", "branch")


@dataclass(frozen=True)
class Part:
    """A sub-table of a standard mechanism: ``name`` in the file, its ``kind`` (:data:`PART_KINDS`), the body
    whose mass properties it sets (None for the ground) and the builder arguments its values feed."""

    name: str
    kind: str
    body: str | None = None
    args: tuple[tuple[str, str], ...] = ()


@dataclass(frozen=True)
class Parameter:
    """A plain value of a standard mechanism: ``name`` (also the builder argument) and its ``kind``."""

    name: str
    kind: str


@dataclass(frozen=True)
class StandardMechanism:
    """One standard mechanism: its ``type`` (the problem file's ``[mechanism] type``), builder and fields."""

    type: str
    builder: Callable[..., Mechanism]
    fields: tuple[Part | Parameter, ...]

    def default(self, argument: str) -> Any:
        """The builder's default for ``argument``; ``inspect.Parameter.empty`` if it has none."""
        return inspect.signature(self.builder).parameters[argument].default

    @property
    def parts(self) -> tuple[Part, ...]:
        return tuple(f for f in self.fields if isinstance(f, Part))

    @property
    def parameters(self) -> tuple[Parameter, ...]:
        return tuple(f for f in self.fields if isinstance(f, Parameter))

    def build(self, values: Any, **options: Any) -> tuple[Mechanism, list[tuple[str, Any]]]:
        """The mechanism from ``values`` (an object with one attribute per field, such as a validated problem
        table) and extra builder ``options`` (name, linear_density...); also the (body, part) pairs whose
        mass properties replace the builder's defaults."""
        kwargs = dict(options)
        overrides = []
        for f in self.fields:
            value = getattr(values, f.name)
            if isinstance(f, Parameter):
                kwargs[f.name] = value
                continue
            for field, argument in f.args:
                kwargs[argument] = getattr(value, field)
            if f.body is not None:
                overrides.append((f.body, value))
        return self.builder(**kwargs), overrides


def _link(name: str, argument: str | None = None) -> Part:
    return Part(name, "link", name, (("length", argument or name),))


STANDARD_MECHANISMS: dict[str, StandardMechanism] = {
    m.type: m
    for m in (
        StandardMechanism("slider_crank", slider_crank, (
            _link("crank"), _link("rod"), Part("slider", "block", "slider"),
            Parameter("offset", "length"), Parameter("slide_angle", "angle"), Parameter("branch", "branch"),
        )),
        StandardMechanism("four_bar", four_bar, (
            _link("crank"), _link("coupler"), _link("rocker"),
            Part("ground", "ground", None, (("length", "ground"), ("angle", "ground_angle"))),
            Parameter("coupler_point", "point"), Parameter("branch", "branch"),
        )),
        StandardMechanism("inverted_slider_crank", inverted_slider_crank, (
            _link("crank"), Part("ground", "ground_length", None, (("length", "ground"),)),
            Part("block", "block", "block"), Part("rocker", "optional_link", "rocker", (("length", "rocker_length"),)),
            Parameter("offset", "length"), Parameter("branch", "branch"),
        )),
        StandardMechanism("six_bar", six_bar, (
            _link("crank"), _link("coupler"), _link("rocker"),
            Part("ground", "ground_length", None, (("length", "ground"),)),
            Parameter("coupler_point", "point"), _link("link5"), _link("link6"), Parameter("pivot6", "point"),
            Parameter("branch", "branch"), Parameter("branch2", "branch"),
        )),
        StandardMechanism("double_slider_crank", double_slider_crank, (
            Part("crank", "double_crank", "crank", (("length_1", "crank_1"), ("length_2", "crank_2"),
                                                    ("phase", "phase"))),
            _link("rod_1"), _link("rod_2"), Part("slider_1", "block", "slider_1"),
            Part("slider_2", "block", "slider_2"),
            Parameter("offset_1", "length"), Parameter("offset_2", "length"),
            Parameter("slide_angle_1", "angle"), Parameter("slide_angle_2", "angle"),
            Parameter("branch_1", "branch"), Parameter("branch_2", "branch"),
        )),
    )
}  # fmt: skip
