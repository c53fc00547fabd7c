"""Parts under the engine's joint forces: each check against a closed form."""

from __future__ import annotations

import math

import numpy as np
import pytest

from machdyn.drivetrain.bearings import mean_effective_load, rating_life
from machdyn.drivetrain.parts import BearingSpec, LinkSpec, PinSpec, size_parts
from machdyn.drivetrain.strength import link_section_loads
from machdyn.errors import InputError
from machdyn.linkage import analyse, crank_angles, four_bar
from machdyn.linkage.builders import slider_crank


def test_a_rotating_unbalance_gives_a_constant_load_whose_life_is_the_catalogue_formula():
    """A crank carrying only its own unbalance m r w^2 loads its pivot with a constant force: L10 = (C/F)^3
    million revolutions, at n = w/(2 pi) rev/s."""
    mech = slider_crank(0.05, 0.3, 0.0, masses=(0.0, 0.0, 0.0))
    from dataclasses import replace

    from machdyn.linkage.model import PointMass

    mech = replace(mech, point_masses=(PointMass("unbalance", "crank", 4.0, (0.05, 0.0)),), gravity=(0.0, 0.0))
    w = 150.0
    forces = analyse(mech, crank_angles(360), w).forces
    load = 4.0 * 0.05 * w**2
    done = size_parts(forces, bearings=(BearingSpec("O", "ball", capacity=40e3, life=1.0),))
    life_hours = (40e3 / load) ** 3 * 1e6 / (w / (2 * math.pi) * 3600)
    assert done.checks[0].value / 3600 == pytest.approx(life_hours, rel=1e-9)
    assert done.bearing_loads["O"][1] == pytest.approx(load, rel=1e-9)


def test_the_equal_life_load_weights_the_load_by_the_revolutions_made_under_it():
    """Two load levels at one speed: the time-weighted cube mean; the rating life follows it."""
    fm = mean_effective_load([1000.0, 2000.0], [3.0, 1.0])
    assert fm == pytest.approx(((1000.0**3 * 3 + 2000.0**3) / 4) ** (1 / 3), rel=1e-12)
    assert rating_life(10e3, fm) == pytest.approx((10e3 / fm) ** 3, rel=1e-12)


def test_a_pin_and_a_plain_bearing_take_the_peak_joint_force():
    mech = four_bar(0.05, 0.15, 0.12, 0.14, masses=(1.0, 3.0, 2.0))
    forces = analyse(mech, crank_angles(180), 60.0).forces
    peak = float(np.max(forces.joint("B").magnitude))
    done = size_parts(forces, pins=(PinSpec("B", 0.01, 0.02, 2, allowable_shear=1e9, allowable_pressure=1e9),))
    shear, pressure = done.checks
    assert shear.value == pytest.approx(peak / (2 * math.pi * 0.01**2 / 4), rel=1e-12)
    assert pressure.value == pytest.approx(peak / (0.01 * 0.02), rel=1e-12)


def test_a_link_turning_about_one_end_with_angular_acceleration_bends_as_a_triangular_load():
    """Load growing linearly from 0 at A to q1 at B on a simply supported span: M_max = q1 L^2 / (9 sqrt 3)."""
    from types import SimpleNamespace as S

    mass, length, alpha = 3.0, 0.8, 50.0
    a = S(x=0.0, y=0.0, ax=0.0, ay=0.0)
    b = S(x=length, y=0.0, ax=0.0, ay=alpha * length)  # transverse acceleration alpha * x
    _n, m = link_section_loads(a, b, (0.0, 0.0), mass)
    q1 = mass / length * alpha * length
    assert abs(m) == pytest.approx(q1 * length**2 / (9 * math.sqrt(3)), rel=1e-12)  # the exact maximum


def test_the_links_of_a_four_bar_get_a_finite_goodman_factor_and_a_crank_does_not_count_as_a_link():
    mech = four_bar(0.05, 0.15, 0.12, 0.14, masses=(1.0, 3.0, 2.0))
    forces = analyse(mech, crank_angles(180), 60.0).forces
    done = size_parts(forces, links=(LinkSpec("coupler", 1e-4, 1e-6, 150e6, 600e6, 2.0),))
    assert np.isfinite(done.checks[0].value) and done.checks[0].value > 0
    with pytest.raises(InputError, match="exactly two revolute joints"):
        size_parts(forces, links=(LinkSpec("ground_link_that_is_not_there", 1e-4, 1e-6, 1e8, 1e9),))


def test_a_rolling_bearing_that_never_turns_is_refused_with_a_reason():
    mech = slider_crank(0.05, 0.3, 0.0, masses=(1.0, 1.0, 1.0))
    forces = analyse(mech, crank_angles(90), 20.0).forces
    with pytest.raises(InputError, match="prismatic"):
        size_parts(forces, bearings=(BearingSpec("slider/ground", "ball", capacity=1e4),))
