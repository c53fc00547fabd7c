"""The Examples sections of the vibration modules run as tests."""

from __future__ import annotations

import doctest
import importlib

import pytest

MODULES = ["frame", "modes", "response", "signals", "severity"]


@pytest.mark.parametrize("name", MODULES)
def test_doctests(name):
    module = importlib.import_module(f"machdyn.vibration.{name}")
    result = doctest.testmod(module, optionflags=doctest.ELLIPSIS)
    assert result.attempted > 0
    assert result.failed == 0
