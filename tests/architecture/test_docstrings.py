"""The documentation standard of the formula functions: every public function of the covered modules reads
like a handbook entry, with numpydoc "Parameters" (when it takes any), "Returns" and a runnable "Examples"
section (the examples themselves run as doctests over src/machdyn)."""

from __future__ import annotations

import importlib
import inspect
import re

import pytest

COVERED_MODULES = (
    "machdyn.linkage.averages",
    "machdyn.linkage.dyads",
    "machdyn.linkage.effort",
    "machdyn.linkage.energy",
    "machdyn.linkage.extremes",
    "machdyn.linkage.fluctuation",
    "machdyn.linkage.grashof",
    "machdyn.linkage.harmonics",
    "machdyn.linkage.inverse",
    "machdyn.linkage.mass_centre",
    "machdyn.machines.compactor",
    "machdyn.screen.formulas",
    "machdyn.screen.ratio",
    "machdyn.screen.slider",
    "machdyn.units",
)


def _public_functions(module_name):
    module = importlib.import_module(module_name)
    names = getattr(module, "__all__", None) or [n for n in vars(module) if not n.startswith("_")]
    for name in names:
        obj = getattr(module, name, None)
        if inspect.isfunction(obj) and obj.__module__ == module_name:
            yield f"{module_name}.{name}", obj


FUNCTIONS = [item for module in COVERED_MODULES for item in _public_functions(module)]


def _has_section(doc: str, title: str) -> bool:
    """A numpydoc section: the title on its own line, underlined with dashes."""
    return re.search(rf"^\s*{title}\s*\n\s*-{{{len(title)}}}", doc, flags=re.MULTILINE) is not None


def test_every_covered_module_has_public_functions():
    found = {name.rsplit(".", 1)[0] for name, _ in FUNCTIONS}
    assert found == set(COVERED_MODULES)


@pytest.mark.parametrize(("name", "func"), FUNCTIONS, ids=[name for name, _ in FUNCTIONS])
def test_public_function_has_numpydoc_sections(name, func):
    doc = inspect.getdoc(func) or ""
    takes_parameters = any(p.name not in ("self", "cls") for p in inspect.signature(func).parameters.values())
    required = (["Parameters"] if takes_parameters else []) + ["Returns", "Examples"]
    missing = [title for title in required if not _has_section(doc, title)]
    assert not missing, f"{name} lacks the numpydoc section(s) {missing}"
    examples = doc.split("Examples", 1)[1]
    assert ">>> " in examples, f"{name} has an Examples section without a runnable example"
