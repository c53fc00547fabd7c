"""The public API does not move under its users: every package names it in ``__all__`` (each name there exists),
a renamed or moved public name keeps its old name for a minor version with a DeprecationWarning and the same
answer, and a parameter whose unit changed keeps its old unit in its old place (the new unit takes a keyword)."""

from __future__ import annotations

import ast
import importlib
import importlib.util
import math
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import machdyn
from machdyn import conveyor, dynamics, problem
from machdyn.conveyor import checks, design
from machdyn.dynamics.motors import smallest_rating

SRC = Path(__file__).resolve().parents[2] / "src" / "machdyn"
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
#: Packages kept only to re-export moved names; importing them warns (tested below).
DEPRECATED_PACKAGES = {"machdyn.explore": "machdyn.studies", "machdyn.optimise": "machdyn.studies"}
PACKAGES = sorted(".".join(p.parent.relative_to(SRC.parent).parts) for p in SRC.rglob("__init__.py"))


def _declared_all(package: str) -> list[str] | None:
    """The names the package's ``__init__`` assigns to ``__all__`` (None if it assigns none)."""
    path = SRC.parent.joinpath(*package.split("."), "__init__.py")
    for node in ast.parse(path.read_text(encoding="utf-8")).body:
        targets = node.targets if isinstance(node, ast.Assign) else [node.target] if isinstance(node, ast.AnnAssign) \
            else []
        if any(isinstance(t, ast.Name) and t.id == "__all__" for t in targets):
            return list(ast.literal_eval(node.value))
    return None


def _import(package: str):
    with warnings.catch_warnings():
        if package in DEPRECATED_PACKAGES:
            warnings.simplefilter("ignore", DeprecationWarning)
        return importlib.import_module(package)


def test_every_package_names_its_public_api():
    assert len(PACKAGES) >= 20
    assert [p for p in PACKAGES if _declared_all(p) is None] == []


@pytest.mark.parametrize("package", PACKAGES)
def test_every_public_name_exists(package):
    """A name of ``__all__`` is an attribute of the package or one of its modules, and is listed once."""
    module = _import(package)
    names = module.__all__
    assert len(set(names)) == len(names)
    missing = [n for n in names if not hasattr(module, n) and importlib.util.find_spec(f"{package}.{n}") is None]
    assert missing == []


@pytest.mark.parametrize("old", sorted(DEPRECATED_PACKAGES))
def test_moved_packages_warn_and_re_export_the_same_objects(old):
    sys.modules.pop(old, None)
    with pytest.warns(DeprecationWarning, match=DEPRECATED_PACKAGES[old]):
        module = importlib.import_module(old)
    new = importlib.import_module(DEPRECATED_PACKAGES[old])
    assert module.__all__ and all(getattr(module, n) is getattr(new, n) for n in module.__all__)


def test_energy_fluctuation_is_the_diagram_energy_fluctuation_with_a_warning():
    """T = 5000 + 1500 sin 3phi N*m: E = -500 cos 3phi J, so the fluctuation is 1000 J (Khurmi & Gupta, *Theory of
    Machines*, ch. 16: the energy is the integral of T - T_mean); the spline through 5 deg samples is within 1e-3."""
    phi = np.linspace(0.0, 2.0 * np.pi, 73)
    curve = dynamics.torque_table(phi, 5000.0 + 1500.0 * np.sin(3.0 * phi))
    with pytest.warns(DeprecationWarning, match="diagram_energy_fluctuation"):
        old = dynamics.energy_fluctuation(curve)
    assert old == pytest.approx(dynamics.diagram_energy_fluctuation(curve), rel=0.0)
    assert float(old[0]) == pytest.approx(1000.0, rel=1e-3)


def test_problem_load_problem_reads_any_kind_with_a_warning():
    path = EXAMPLES / "slider_crank.toml"
    with pytest.warns(DeprecationWarning, match="machdyn.load_problem"):
        old = problem.load_problem(path)
    assert old == machdyn.load_problem(path)


def test_volume_capacity_by_position_keeps_its_rpm():
    """Q_v = (pi/4) D^2 S (n/60) phi C (seed 004, eq 2.83 over the bulk density): 0.30 m, 0.25 m, 60 rpm, 0.40
    gives 7.0686e-3 m^3/s (25.4 m^3/h); read as 60 rad/s it would be 9.55 times that."""
    expected = math.pi / 4.0 * 0.30**2 * 0.25 * (60.0 / 60.0) * 0.40
    with pytest.warns(DeprecationWarning, match="rpm"):
        old = conveyor.volume_capacity(0.30, 0.25, 60.0, 0.40)
    assert old == pytest.approx(expected, rel=1e-12)
    assert conveyor.volume_capacity(0.30, 0.25, speed_rpm=60.0, filling=0.40) == pytest.approx(expected, rel=1e-12)
    by_rad = conveyor.volume_capacity(0.30, 0.25, angular_speed=2.0 * math.pi, filling=0.40)
    assert by_rad == pytest.approx(expected, rel=1e-12)
    with pytest.warns(DeprecationWarning):  # the old form's every position: C and the pipe's diameter
        piped = conveyor.volume_capacity(0.30, 0.25, 60.0, 0.40, 0.8, 0.1)
    assert piped == pytest.approx(math.pi / 4.0 * (0.30**2 - 0.1**2) * 0.25 * 0.40 * 0.8, rel=1e-12)


@pytest.mark.parametrize("call", [
    lambda: conveyor.volume_capacity(0.3, 0.25, filling=0.4),
    lambda: conveyor.volume_capacity(0.3, 0.25, angular_speed=6.0, speed_rpm=60.0, filling=0.4),
    lambda: conveyor.volume_capacity(0.3, 0.25, angular_speed=6.0),
    lambda: checks.torque_from_power(1000.0),
])
def test_a_speed_missing_or_given_twice_is_refused(call):
    with pytest.raises(TypeError, match="speed|filling"):
        call()


def test_torque_from_power_by_position_keeps_its_rpm():
    """T = P / omega = 1000 W / (60 rpm = 2 pi rad/s) (seed 004, eq 2.85)."""
    with pytest.warns(DeprecationWarning, match="rpm"):
        old = checks.torque_from_power(1000.0, 60.0)
    assert old == pytest.approx(1000.0 / (2.0 * math.pi), rel=1e-12)
    assert checks.torque_from_power(1000.0, angular_speed=2.0 * math.pi) == pytest.approx(old, rel=1e-12)


def test_design_screw_speed_keeps_its_rpm():
    duty = dict(mass_flow=2.0, bulk_density=1200.0, filling=0.4, speed_coefficient=45.0, pitch_ratio=0.8,
                inclination_factor=1.0)
    with pytest.warns(DeprecationWarning, match="speed="):
        old = design.design_screw(**duty, speed=60.0)
    assert old.speed == pytest.approx(60.0 * design.RPM, rel=1e-12)
    assert design.design_screw(**duty, speed_rpm=60.0) == old
    assert design.design_screw(**duty, angular_speed=60.0 * design.RPM) == old


def test_select_motor_is_the_one_motor_selection_with_a_warning():
    with pytest.warns(DeprecationWarning, match="smallest_rating"):
        old = conveyor.select_motor(5000.0)
    assert old == smallest_rating(5000.0) and old >= 5000.0
