"""Balancing: published worked examples with printed answers, reproduced with machdyn's engine.

Each example is built as an engine model (revolving masses as point masses on the crank, reciprocating masses
as the slider, a rod of negligible mass and, where the book neglects obliquity, a very long rod) and balanced
with :func:`machdyn.balancing.counterweights.crank_counterweight` or the general least squares.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from machdyn.balancing.counterweights import balance_mass, crank_counterweight, primary_unbalanced_force
from machdyn.balancing.frame import frame_loads
from machdyn.balancing.general import CounterweightSlot, least_squares_counterweights
from machdyn.linkage import PointMass, slider_crank

#: rod length / crank radius used where a book "neglects the obliquity of the connecting rod": the secondary
#: force is then 1/n = 1e-4 of the primary, far below the printed answers' rounding.
N_LONG = 1.0e4


def _engine(crank_radius, reciprocating, revolving, rod_ratio=N_LONG):
    """Horizontal single-cylinder engine: the crank angle is measured from the inner dead centre (slider on +x,
    crank pin at +x at angle 0), as the books measure theta."""
    mech = slider_crank(crank_radius, crank_radius * rod_ratio, masses=(0.0, 0.0, reciprocating),
                        inertias=(0.0, 0.0, 0.0), gravity=(0.0, 0.0))
    return replace(mech, point_masses=(PointMass("revolving", "crank", revolving, (crank_radius, 0.0)),))


def test_khurmi_gupta_example_22_1_balance_mass():
    """Khurmi & Gupta, *Theory of Machines*, 14th ed., ch. 22 "Balancing of Reciprocating Masses", Example 22.1
    (solution reproduced at sarthaks.com/491921): N = 240 rpm, stroke 300 mm, m = 50 kg reciprocating,
    m1 = 37 kg revolving at r = 150 mm, c = 2/3, balance mass at b = 400 mm. Printed: B = 26.38 kg."""
    w = 2 * np.pi * 240 / 60
    mech = _engine(0.15, 50.0, 37.0)
    result = crank_counterweight(mech, 2.0 / 3.0, 0.4, np.radians([60.0]), speed=w)
    # printed to 2 decimals (26.375 rounds to 26.38): tolerance half a unit of the last printed digit
    assert result.counterweights[0].mass == pytest.approx(26.38, abs=0.005 + 1e-9)
    assert balance_mass(37.0, 50.0, 0.15, 2 / 3, 0.4) == pytest.approx(26.38, abs=0.005 + 1e-9)
    # the residual at 60 deg from the dead centre: the engine's exact value equals the book's formula
    along, across = primary_unbalanced_force(np.radians(60.0), 50.0, 0.15, w, 2.0 / 3.0)
    assert result.after.force[0] == pytest.approx(np.hypot(along, across), rel=2.0 / N_LONG)


def test_textbook_illustration_page_310_partial_balance():
    """"Chapter 12: Balancing of Reciprocating Masses, Illustration 1 (Page 310)" (a theory-of-machines
    textbook's worked example as published with its computed output in the Nemotron-CC-Math-v1 corpus): N = 250
    rpm, crank radius 0.09 m, 120 kg reciprocating, 70 kg revolving, balance mass at 0.15 m balancing all the
    revolving and 2/3 of the reciprocating mass; crank at 30 deg from the inner dead centre.
    Printed: B = 90.0 kg, residual unbalanced force 3263.971 N."""
    w = 2 * np.pi * 250 / 60
    result = crank_counterweight(_engine(0.09, 120.0, 70.0), 2.0 / 3.0, 0.15, np.radians([30.0]), speed=w)
    assert result.counterweights[0].mass == pytest.approx(90.0, abs=0.05)
    # the printed value converts degrees with 57.3 deg/rad (not 180/pi): 1e-4 relative covers that and the
    # long-rod secondary (1e-4 of the primary)
    assert result.after.force[0] == pytest.approx(3263.971, rel=2e-4)


def test_gate_2013_unbalanced_force_normal_to_the_stroke():
    """GATE 2013 ME (question reproduced at byjus.com, "A slider crank mechanism has slider mass of 10 kg, stroke
    of 0.2 m..."): the primary force of a 10 kg slider partially balanced by 6 kg revolving at the crank radius,
    omega = 10 rad/s, crank at 30 deg; asked: the unbalanced force normal to the slider axis. By hand:
    6 * 0.1 * 10^2 * sin 30 deg = 30 N. Here the 6 kg is the counterweight of a 60 % balance at the crank radius."""
    mech = _engine(0.1, 10.0, 0.0)
    result = crank_counterweight(mech, 0.6, 0.1, np.radians([30.0]), speed=10.0)
    assert result.counterweights[0].mass == pytest.approx(6.0, rel=1e-12)
    assert abs(result.after.fy[0]) == pytest.approx(30.0, rel=1e-12)  # across the stroke: exact, no obliquity term


def test_gate_2019_rotating_masses_balanced_by_least_squares():
    """GATE 2019 ME set 2, Q.38 (me.gateoverflow.in/1424): 10 kg at 200 mm and 20 kg at 400 mm, 90 deg apart, on
    one shaft; the balance mass at 200 mm. By hand: sqrt((10*0.2)^2 + (20*0.4)^2) / 0.2 = 41.23 kg (two
    decimals asked). The general least squares finds it with the shaking force gone."""
    mech = _engine(0.2, 0.0, 10.0)
    mech = replace(mech, point_masses=(*mech.point_masses, PointMass("b", "crank", 20.0, (0.0, 0.4))))
    result = least_squares_counterweights(mech, [CounterweightSlot("crank", radius=0.2)], speed=5.0)
    assert result.counterweights[0].mass == pytest.approx(41.23, abs=0.005)
    assert result.after.peak_force < 1e-9 * result.before.peak_force
    # the balance mass sits opposite the resultant of the two mass-radius products
    angle = np.degrees(np.arctan2(*result.counterweights[0].position[::-1]))
    assert angle == pytest.approx(np.degrees(np.arctan2(-8.0, -2.0)), abs=1e-9)
    assert frame_loads(result.model, speed=5.0).com_spread < 1e-12
