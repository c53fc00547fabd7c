"""The docstring examples of the public formula functions run as tests."""

import doctest
import importlib

import pytest

MODULES = ["machdyn.dynamics.tables", "machdyn.dynamics.drives", "machdyn.dynamics.flywheel",
           "machdyn.dynamics.motors", "machdyn.dynamics.driveline"]


@pytest.mark.parametrize("name", MODULES)
def test_doctests(name):
    module = importlib.import_module(name)
    result = doctest.testmod(module, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert result.attempted > 0
    assert result.failed == 0
