"""The engine's structure (its import cycles are checked with the whole package's): no private names shared
between modules, every dyad type and standard mechanism declared once and used through its declaration."""

from __future__ import annotations

import ast
import dataclasses
import inspect
from pathlib import Path

import numpy as np
import pytest

import machdyn.linkage as lk
from machdyn.linkage.dyad_types import DYAD_TYPES, DyadType
from machdyn.linkage.fused_dyads import EMITTERS
from machdyn.linkage.standard import STANDARD_MECHANISMS, Part
from machdyn.problem.schema import DYAD_SPECS, MECHANISM_SPECS

PACKAGE = Path(lk.__file__).parent


def _module_imports(path: Path) -> list[tuple[str, list[str]]]:
    """(module, names) of the relative imports at module level, outside ``if TYPE_CHECKING:`` blocks."""
    tree = ast.parse(path.read_text())
    out = []
    for node in tree.body:
        if isinstance(node, ast.ImportFrom) and node.level == 1:
            names = [a.name for a in node.names]
            if node.module is None:  # from . import dyads
                out += [(n, []) for n in names]
            else:
                out.append((node.module, names))
    return out


def test_no_private_names_imported_across_modules():
    for path in PACKAGE.glob("*.py"):
        for module, names in _module_imports(path):
            private = [n for n in names if n.startswith("_")]
            assert not private, f"{path.name} imports {private} from .{module}"


@pytest.mark.parametrize("kind", sorted(DYAD_TYPES))
def test_every_dyad_type_implements_its_declaration(kind):
    cls = DYAD_TYPES[kind]
    assert issubclass(cls, DyadType) and cls.kind == kind
    for method in ("joints", "known_points", "own_points", "drawing", "solve_motion", "solve_forces"):
        assert getattr(cls, method) is not getattr(DyadType, method), f"{kind} does not declare {method}"
    assert kind in EMITTERS, f"the fused engine has no code for {kind}"  # its half of the declaration
    # the problem file's dyad table has exactly the declaration's fields
    spec_fields = set(DYAD_SPECS[kind].model_fields) - {"type"}
    assert spec_fields == {f.name for f in dataclasses.fields(cls)}


def test_mechanism_joints_come_from_the_declarations():
    mech = lk.double_slider_crank(0.05, 0.2, 0.04, 0.18)
    expected = [("O", "R", "ground", "crank")]
    for d in mech.dyads:
        expected += list(d.joints())
    assert lk.joints(mech) == expected
    assert [j[0] for j in expected] == ["O", "A1", "B1", "slider_1/ground", "A2", "B2", "slider_2/ground"]


@pytest.mark.parametrize("kind", sorted(STANDARD_MECHANISMS))
def test_standard_mechanism_table_matches_its_declaration(kind):
    declaration = STANDARD_MECHANISMS[kind]
    spec = MECHANISM_SPECS[kind]
    assert [n for n in spec.model_fields if n not in ("name", "linear_density", "machine", "type")] == [
        f.name for f in declaration.fields
    ]
    signature = inspect.signature(declaration.builder).parameters
    for f in declaration.fields:
        arguments = [a for _, a in f.args] if isinstance(f, Part) else [f.name]
        assert all(a in signature for a in arguments), (kind, f.name)
    for p in declaration.parameters:  # defaults are the builder's
        default = signature[p.name].default
        if default is not inspect.Parameter.empty:
            assert spec.model_fields[p.name].default == default


def test_registry_builds_what_the_builder_builds():
    spec = MECHANISM_SPECS["four_bar"].model_validate(
        {"type": "four_bar", "crank": {"length": "40 mm"}, "coupler": {"length": "120 mm"},
         "rocker": {"length": "80 mm"}, "ground": {"length": "100 mm", "angle": "0.1 rad"}, "branch": "crossed"})
    mech, overrides = STANDARD_MECHANISMS["four_bar"].build(spec, name="fb")
    ref = lk.four_bar(0.04, 0.12, 0.08, 0.1, ground_angle=0.1, branch=-1, name="fb")
    assert [b for b, _ in overrides] == ["crank", "coupler", "rocker"]
    assert mech.dyads == ref.dyads
    phi = lk.crank_angles(12)
    np.testing.assert_array_equal(lk.kinematics(mech, phi).body("rocker").angle,
                                  lk.kinematics(ref, phi).body("rocker").angle)
