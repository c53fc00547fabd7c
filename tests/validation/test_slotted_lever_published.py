"""Crank-and-slotted-lever quick returns against printed textbook answers.

Each printed answer is checked twice: by the closed form (Khurmi & Gupta's section 5.14 formulas in
:mod:`machdyn.synthesis.slotted_lever`) and by the engine's kinematics of the same linkage (the ram's stops found
from its velocity alone). The synthesis is checked by giving it back the printed answer and reading the book's
dimensions out.
"""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.linkage import kinematics
from machdyn.synthesis.slotted_lever import (
    SlottedLever,
    measure,
    slotted_lever,
    slotted_lever_stroke,
    slotted_lever_time_ratio,
)


def _built(r: float, d: float, lever: float) -> SlottedLever:
    """The book's linkage with machdyn's ram (the rod and line of stroke as :func:`slotted_lever` places them)."""
    via = slotted_lever(slotted_lever_time_ratio(r, d), slotted_lever_stroke(r, d, lever), d)
    assert via.crank == pytest.approx(r, rel=1e-12) and via.lever == pytest.approx(lever, rel=1e-12)
    return via


def test_khurmi_gupta_example_5_1_time_ratio():
    """Khurmi & Gupta, *Theory of Machines*, 14th ed. (Eurasia 2009), ch. 5, example 5.1, p. 110: centre distance
    300 mm, crank 120 mm; printed time ratio 1.7 (one decimal: 1.70995 exact, so 3 % covers the rounding; the
    exact value to 1e-5)."""
    q = slotted_lever_time_ratio(0.12, 0.3)
    assert q == pytest.approx(1.7, rel=0.03)
    assert q == pytest.approx(1.709953, abs=1e-5)
    # the engine on the same linkage (the book gives no lever; 500 mm reaches past d + r = 420 mm)
    assert measure(_built(0.12, 0.3, 0.5)).time_ratio == pytest.approx(1.709953, abs=1e-5)


def test_khurmi_gupta_example_5_2_time_ratio_and_stroke():
    """Khurmi & Gupta, *Theory of Machines*, 14th ed., ch. 5, example 5.2, p. 110: centre distance 240 mm, crank
    120 mm, slotted lever 450 mm; printed: time ratio 2, stroke 450 mm (exact values, tolerance rounding)."""
    assert slotted_lever_time_ratio(0.12, 0.24) == pytest.approx(2.0, rel=1e-12)
    assert slotted_lever_stroke(0.12, 0.24, 0.45) == pytest.approx(0.45, rel=1e-12)
    m = measure(_built(0.12, 0.24, 0.45))
    assert m.time_ratio == pytest.approx(2.0, rel=1e-9)
    assert m.stroke == pytest.approx(0.45, rel=1e-9)
    # synthesis: the printed answers back in, the book's crank and lever out
    design = slotted_lever(2.0, 0.45, 0.24)
    assert design.crank == pytest.approx(0.12, rel=1e-12)
    assert design.lever == pytest.approx(0.45, rel=1e-12)


def test_sarkar_illustration_1_lever_inclination_and_stroke():
    """B. K. Sarkar, *Theory of Machines* (Tata McGraw-Hill 2002), ch. 1, illustration 1, p. 15: centre distance
    200 mm, crank 100 mm, lever 400 mm; printed inclination of the lever at its extremes 30.00 deg. The stroke
    2 l r / d = 400 mm is computed (the book's companion prints -13.790 mm from a degrees/radians slip)."""
    design = _built(0.1, 0.2, 0.4)
    m = measure(design)
    for angle in m.dead_angles:  # the engine's lever angle against the line of centres at each dead position
        lever = float(kinematics(design.mechanism(), np.array([angle]), 1.0).body("rocker").angle[0])
        off_centre_line = abs(np.pi - abs(np.angle(np.exp(1j * lever))))
        assert np.degrees(off_centre_line) == pytest.approx(30.0, abs=1e-4)
    assert m.stroke == pytest.approx(0.4, rel=1e-9)


def test_sarkar_illustration_2_time_ratio():
    """B. K. Sarkar, *Theory of Machines*, ch. 1, illustration 2, p. 16: centre distance 300 mm, crank 150 mm;
    printed time ratio 2.0 (exact)."""
    assert slotted_lever_time_ratio(0.15, 0.3) == pytest.approx(2.0, rel=1e-12)
    assert measure(_built(0.15, 0.3, 0.5)).time_ratio == pytest.approx(2.0, rel=1e-9)
