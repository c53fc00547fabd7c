"""Bad input to the linkage engine: each raises a clear exception whose message names the field, the rule and
the value. Messages are matched exactly."""

from __future__ import annotations

import re
from dataclasses import replace

import numpy as np
import pytest

from machdyn.errors import AssemblyError, InputError, MachdynError
from machdyn.linkage import (
    RRR,
    Crank,
    Mechanism,
    PointForce,
    PointMass,
    Spring,
    crank_angles,
    double_slider_crank,
    energy,
    four_bar,
    inverted_slider_crank,
    kinematics,
    kinetostatics,
    six_bar,
    slider_crank,
)


def raises(exc, message):
    return pytest.raises(exc, match="^" + re.escape(message) + "$")


@pytest.fixture(scope="module")
def fb():
    return four_bar(0.2, 1.0, 1.0, 1.0)


# ------------------------------------------------------------------------------- non-positive values


@pytest.mark.parametrize("build, message", [
    (lambda: four_bar(-0.1, 1, 1, 1), "The crank length of four_bar 'four_bar' must be > 0 m; got -0.1 m."),
    (lambda: four_bar(0.1, 1, 1, 0.0), "The ground length of four_bar 'four_bar' must be > 0 m; got 0 m."),
    (lambda: slider_crank(0.1, 0.0), "The rod length of slider_crank 'slider_crank' must be > 0 m; got 0 m."),
    (lambda: inverted_slider_crank(0.2, -1),
     "The ground length of inverted_slider_crank 'inverted_slider_crank' must be > 0 m; got -1 m."),
    (lambda: double_slider_crank(0.1, 1, 0.1, -1),
     "The rod_2 length of double_slider_crank 'double_slider_crank' must be > 0 m; got -1 m."),
    (lambda: six_bar(0.2, 1, 1, 1, (0.5, 0.2), -1.0, 1, (1, 1)),
     "The link5 length of six_bar 'six_bar' must be > 0 m; got -1 m."),
])
def test_non_positive_lengths(build, message):
    with raises(InputError, message):
        build()


def test_non_positive_masses_and_inertias(fb):
    with raises(InputError, "The mass of body 'coupler' must be >= 0 kg; got -2 kg."):
        four_bar(0.1, 1, 1, 1, masses=(1, -2, 1))
    with raises(InputError, "The moment of inertia of body 'rod' must be >= 0 kg*m^2; got -1 kg*m^2."):
        slider_crank(0.1, 1, inertias=(0, -1, 0))
    with raises(InputError, "The mass of 'p' must be >= 0 kg; got -1 kg."):
        replace(fb, point_masses=(PointMass("p", "crank", -1.0, (0.0, 0.0)),))
    with raises(InputError, "The stiffness of spring 's' must be >= 0 N/m; got -1 N/m."):
        replace(fb, springs=(Spring("s", "coupler.B", "ground.O", -1.0, 0.0),))
    with raises(InputError, "The free length of spring 's' must be >= 0 m; got -1 m."):
        replace(fb, springs=(Spring("s", "coupler.B", "ground.O", 1.0, -1.0),))


def test_design_arrays_with_a_bad_element():
    # the message reports the first offending element of a design array
    with raises(InputError, "The coupler length of four_bar 'four_bar' must be > 0 m; got -0.5 m."):
        four_bar(0.2, np.array([1.0, -0.5, 2.0]), 1, 1)
    with raises(InputError, "All design-variant arrays of mechanism 'four_bar' must have the same length; "
                            "got lengths [2, 3]."):
        four_bar(np.array([0.2, 0.3]), np.array([1, 1, 1.0]), 1, 1)


# ------------------------------------------------------------------------------------------ NaN / inf


def test_nan_and_inf_inputs(fb):
    with raises(InputError, "The crank length of four_bar 'four_bar' must be a finite number; got nan m."):
        four_bar(np.nan, 1, 1, 1)
    with raises(InputError, "The rod length of slider_crank 'slider_crank' must be a finite number; got inf m."):
        slider_crank(0.1, np.inf)
    with raises(InputError, "The crank angle must be a finite number; got nan rad."):
        kinematics(fb, np.array([0.0, np.nan]))
    with raises(InputError, "The crank speed must be a finite number; got inf rad/s."):
        kinematics(fb, 0.0, speed=np.inf)
    with raises(InputError, "The crank acceleration must be a finite number; got -inf rad/s^2."):
        kinematics(fb, 0.0, acceleration=-np.inf)
    with raises(InputError, "The centre of mass of body 'crank' must be a finite number; got nan m."):
        four_bar(0.2, 1, 1, 1, coms=((np.nan, 0), (0, 0), (0, 0)))
    with raises(InputError, "The gravity must be a finite number; got nan m/s^2."):
        replace(fb, gravity=(0.0, np.nan))


def test_nan_offset_is_rejected():
    with raises(InputError, "The offset of slider_crank 'slider_crank' must be a finite number; got nan m."):
        slider_crank(0.1, 1.0, np.nan)


def test_zero_speed_has_no_reduced_inertia(fb):
    with raises(InputError, "The reduced inertia needs a non-zero crank speed; got 0 rad/s."):
        _ = energy(fb, crank_angles(4), speed=0.0).reduced_inertia


def test_crank_pivot_must_be_on_the_ground(fb):
    with raises(InputError, "The crank pivot must be a ground point 'ground.NAME'; got 'crank.O'."):
        replace(fb, crank=Crank("crank", "crank.O"))


# ------------------------------------------------------------------------------------- assembly


def test_linkage_that_cannot_close_anywhere():
    with raises(AssemblyError, "Mechanism 'four_bar' cannot be assembled at any of the requested crank angles: the "
                               "links are too short or too long to close the loop. Grashof type: non-Grashof "
                               "triple-rocker."):
        kinematics(four_bar(0.2, 0.3, 0.3, 3.0), crank_angles(36))
    with raises(AssemblyError, "Mechanism 'slider_crank' cannot be assembled at any of the requested crank angles: "
                               "the links are too short or too long to close the loop."):
        kinematics(slider_crank(0.1, 0.3, 1.0), crank_angles(36))


def test_linkage_that_closes_only_in_part():
    with raises(AssemblyError, "Mechanism 'four_bar' cannot be assembled for crank angles 130.0°–230.0°; restrict "
                               "the crank angles to where it closes or change the link lengths. Grashof type: "
                               "non-Grashof triple-rocker."):
        kinematics(four_bar(1.0, 1.0, 1.2, 1.5), crank_angles(36))
    # on_fail="mask" returns NaN there instead
    k = kinematics(four_bar(1.0, 1.0, 1.2, 1.5), crank_angles(36), on_fail="mask")
    assert np.all(np.isnan(k.body("coupler").angle[~k.assembled]))
    assert np.all(np.isfinite(k.body("coupler").angle[k.assembled]))
    assert np.degrees(crank_angles(36)[~k.assembled]).tolist() == pytest.approx(np.arange(130, 231, 10.0))
    with raises(InputError, "on_fail must be 'raise' or 'mask'; got 'x'."):
        kinematics(four_bar(1.0, 1.0, 1.2, 1.5), 0.0, on_fail="x")


def test_branch_that_does_not_exist(fb):
    with raises(InputError, "The branch must be one of +1, -1, 'open', 'crossed', 'up', 'down'; got 0."):
        four_bar(0.2, 1, 1, 1, branch=0)
    with raises(InputError, "The branch2 must be one of +1, -1, 'open', 'crossed', 'up', 'down'; got 3."):
        six_bar(0.2, 1, 1, 1, (0.5, 0.2), 1, 1, (1, 1), branch2=3)
    with raises(InputError, "The branch of dyad 1 (RRR coupler-rocker) must be +1 or -1; got 0."):
        Mechanism("x", fb.ground, fb.bodies, fb.crank, (RRR("coupler", "rocker", "crank.A", "ground.D", "B", 0),))


# ----------------------------------------------------------------------------------- unknown names


def test_unknown_point_references(fb):
    k = kinematics(fb, 0.0)
    with raises(InputError, "Body 'coupler' has no point 'Z'; its points: A, B."):
        k.point("coupler.Z")
    with raises(InputError, "Mechanism 'four_bar' has no body 'nobody'; bodies: crank, coupler, rocker."):
        k.point("nobody.A")
    with raises(InputError, "A point reference must be written 'body.point'; got 'coupler'."):
        k.point("coupler")
    with raises(InputError, "The force 'f'.point refers to point 'Z' of body 'coupler', which has points A, B."):
        replace(fb, forces=(PointForce("f", "coupler.Z", 1.0),))
    with raises(InputError, "The spring 's'.point_2 refers to ground point 'Q', which does not exist; ground "
                            "points: O, D."):
        replace(fb, springs=(Spring("s", "coupler.B", "ground.Q", 1.0, 0.0),))
    with raises(InputError, "The dyad 1 (RRR coupler-rocker).pin_b refers to ground point 'E', which does not "
                            "exist; ground points: O, D."):
        Mechanism("x", fb.ground, fb.bodies, fb.crank, (RRR("coupler", "rocker", "crank.A", "ground.E", "B", 1),))
    with raises(InputError, "Body 'coupler' is not a slider or block; sliders: none."):
        k.slide("coupler")
    with raises(InputError, "No joint 'Z'; joints: O, A, D, B."):
        kinetostatics(fb, 0.0).joint("Z")
    with raises(InputError, "Body names must be unique in mechanism 'x'; got crank more than once."):
        Mechanism("x", fb.ground, fb.bodies + (fb.bodies[0],), fb.crank, fb.dyads)


def test_every_error_is_a_machdyn_error(fb):
    # callers can catch MachdynError; InputError is also a ValueError
    with pytest.raises(MachdynError):
        kinematics(four_bar(0.2, 0.3, 0.3, 3.0), 0.0)
    with pytest.raises(ValueError):
        kinematics(fb, 0.0).point("coupler.Z")
    with pytest.raises(MachdynError):
        Mechanism("x", fb.ground, fb.bodies, Crank("crank", "ground.Q"), fb.dyads)
