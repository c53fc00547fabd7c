"""The textbook-facing API: with_loads, inverse_position, crank_effort/piston_effort, mass_centre and
energy_fluctuation. Physics identities, closed forms, finite differences, design broadcasting, bad input."""

from dataclasses import replace

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from machdyn.errors import InputError
from machdyn.linkage import (
    BodyTorque,
    PointForce,
    PointMass,
    Spring,
    crank_angles,
    crank_effort,
    double_slider_crank,
    energy_fluctuation,
    four_bar,
    inverse_position,
    kinematics,
    kinetostatics,
    mass_centre,
    piston_effort,
    slider_crank,
    with_loads,
)

# Central differences with h = 1e-6 rad: truncation ~h^2 f''' ~ 1e-12, rounding ~eps |f| / h ~ 1e-10 for the
# O(1)-O(10) quantities here, so 1e-6 relative to the quantity's scale leaves a wide margin.
FD_STEP = 1e-6


# ------------------------------------------------------------------------------------------------ with_loads


def test_with_loads_adds_loads_to_a_new_model_and_leaves_the_old_one():
    base = four_bar(0.04, 0.12, 0.08, 0.10, masses=(0.2, 0.5, 0.4))
    force = PointForce("press", "rocker.B", fx=-30.0)
    torque = BodyTorque("brake", "rocker", -0.5)
    spring = Spring("return", "ground.D", "coupler.B", 800.0, 0.05)
    mass = PointMass("counterweight", "crank", 0.3, (-0.02, 0.0))
    loaded = with_loads(base, forces=force, torques=[torque], springs=(spring,), point_masses=[mass])
    assert base.forces == () and base.torques == () and base.springs == () and base.point_masses == ()
    assert (loaded.forces, loaded.torques, loaded.springs, loaded.point_masses) == (
        (force,), (torque,), (spring,), (mass,)
    )
    # The same model as replacing the fields by hand: the same driving torque.
    by_hand = replace(base, forces=(force,), torques=(torque,), springs=(spring,), point_masses=(mass,))
    phi = crank_angles(36)
    np.testing.assert_array_equal(
        kinetostatics(loaded, phi, 5.0).driving_torque, kinetostatics(by_hand, phi, 5.0).driving_torque
    )
    # Loads accumulate over calls; gravity is replaced only when given.
    twice = with_loads(loaded, forces=PointForce("second", "coupler.A", fy=1.0), gravity=(0.0, 0.0))
    assert [f.name for f in twice.forces] == ["press", "second"] and twice.gravity == (0.0, 0.0)
    assert loaded.gravity == base.gravity


def test_with_loads_keeps_design_arrays():
    base = slider_crank(np.array([0.05, 0.06, 0.07]), 0.2)
    loaded = with_loads(base, forces=PointForce("gas", "slider.B", fx=np.array([-10.0, -20.0, -30.0])))
    assert loaded.design_count == 3
    assert kinetostatics(loaded, crank_angles(12), 3.0).driving_torque.shape == (3, 12)


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"forces": "gas"}, "Every item of forces in with_loads must be a PointForce; got str"),
        ({"torques": 3.0}, "The torques of with_loads must be a BodyTorque or a list of them; got 3.0"),
        ({"forces": [PointForce("f", "rod.Z")]}, "point 'Z' of body 'rod'"),
        ({"springs": Spring("s", "ground.O", "slider.B", -1.0, 0.1)}, "stiffness of spring 's' must be >= 0"),
        ({"gravity": 9.81}, "The gravity must be a vector (gx, gy) in m/s^2; got 9.81"),
        (
            {"forces": [PointForce("f", "slider.B"), PointForce("f", "rod.A")]},
            "names of forces must be unique in a mechanism; got f more than once",
        ),
    ],
)
def test_with_loads_bad_input_names_the_argument(kwargs, message):
    with pytest.raises(InputError) as err:
        with_loads(slider_crank(0.05, 0.2), **kwargs)
    assert message in str(err.value)


def test_with_loads_needs_a_mechanism():
    with pytest.raises(InputError, match="with_loads needs a Mechanism as its first argument; got dict"):
        with_loads({}, forces=())


# ------------------------------------------------------------------------------------------ inverse_position


def _slider_crank_angles(r, l, s):
    """Closed form: s = r cos(phi) + sqrt(l^2 - r^2 sin^2 phi)  =>  cos(phi) = (s^2 + r^2 - l^2) / (2 r s)."""
    c = np.arccos((s * s + r * r - l * l) / (2 * r * s))
    return np.sort(np.mod([c, -c], 2 * np.pi), axis=0)


def test_inverse_slider_travel_matches_closed_form_over_designs_and_targets():
    r = np.array([0.05, 0.06, 0.08])
    l = 0.25
    targets = np.array([0.21, 0.25, 0.29])
    sol = inverse_position(slider_crank(r, l), targets, slider="slider")
    assert sol.angles.shape == (3, 3, 2) and np.all(sol.count == 2)
    for i in range(3):
        expected = _slider_crank_angles(r[i], l, targets).T
        np.testing.assert_allclose(sol.angles[i], expected, atol=1e-11)
    np.testing.assert_allclose(sol.reachable[0], l - r, rtol=1e-12)
    np.testing.assert_allclose(sol.reachable[1], l + r, rtol=1e-12)


def test_inverse_finds_the_tangent_root_at_an_extreme_between_samples():
    # An offset slider-crank's outer dead centre s = sqrt((l + r)^2 - e^2) lies at phi = asin(e / (l + r)),
    # between samples: the refined extremum makes it one root, a target just inside it two close roots.
    r, l, e = 0.05, 0.2, 0.03
    mech = slider_crank(r, l, e)
    s_max = np.sqrt((l + r) ** 2 - e * e)
    at_max = inverse_position(mech, s_max, slider="slider", samples=97)
    assert int(at_max.count) == 1
    np.testing.assert_allclose(at_max.angles[0], np.arcsin(e / (l + r)), atol=1e-5)
    inside = inverse_position(mech, s_max - 1e-9, slider="slider", samples=97)
    assert int(inside.count) == 2
    s = kinematics(mech, inside.angles).slide("slider").s
    np.testing.assert_allclose(s, s_max - 1e-9, atol=1e-14)


def test_inverse_body_angle_of_a_rocker_and_partial_crank_range():
    mech = four_bar(0.04, 0.12, 0.08, 0.10, gravity=(0.0, 0.0))
    targets = np.radians([60.0, 90.0, 120.0])
    sol = inverse_position(mech, targets, body="rocker")
    assert np.all(sol.count == 2)
    theta = kinematics(mech, sol.angles.ravel()).body("rocker").angle.reshape(sol.angles.shape)
    np.testing.assert_allclose(theta, targets[:, None] + 0 * sol.angles, atol=1e-11)
    # Only the first solution of each target in a half turn that holds it.
    half = inverse_position(mech, targets[1], body="rocker", crank_range=(0.0, sol.angles[1, 0] + 0.5))
    np.testing.assert_allclose(half.angles, sol.angles[1, :1], atol=1e-11)


def test_inverse_angle_target_is_taken_modulo_a_turn():
    mech = four_bar(0.04, 0.12, 0.08, 0.10, gravity=(0.0, 0.0))
    a = inverse_position(mech, np.radians(90.0), body="rocker")
    b = inverse_position(mech, np.radians(90.0 - 360.0), body="rocker")
    np.testing.assert_allclose(a.angles, b.angles, atol=1e-11)


def test_inverse_double_crank_output_reaches_every_angle():
    mech = four_bar(0.10, 0.12, 0.11, 0.04, gravity=(0.0, 0.0))  # double crank: the output turns fully
    sol = inverse_position(mech, np.radians([-179.0, 0.0, 179.0]), body="rocker")
    assert np.all(sol.count == 1)
    theta = kinematics(mech, sol.angles[:, 0]).body("rocker").angle
    np.testing.assert_allclose(np.angle(np.exp(1j * (theta - np.radians([-179.0, 0.0, 179.0])))), 0.0, atol=1e-11)


@settings(max_examples=25, deadline=None)
@given(
    r=st.floats(0.02, 0.1), ratio=st.floats(2.5, 6.0), e=st.floats(-0.5, 0.5), u=st.floats(0.01, 0.99)
)
def test_inverse_then_forward_returns_the_target(r, ratio, e, u):
    mech = slider_crank(r, ratio * r, e * r)
    reach = inverse_position(mech, 0.0 + (ratio + 0.5) * r, slider="slider").reachable
    target = reach[0] + u * (reach[1] - reach[0])
    sol = inverse_position(mech, target, slider="slider")
    assert int(sol.count) == 2
    np.testing.assert_allclose(kinematics(mech, sol.angles).slide("slider").s, target, atol=1e-12)


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"target": 0.5, "slider": "slider"}, "The target slider.s 0.5 m is out of reach: over the crank angles "
                                               "0.0°–360.0° it spans 0.15 m to 0.25 m."),
        ({"target": 0.2}, "exactly one of slider=... (a travel) or body=... (an angle)"),
        ({"target": 0.2, "slider": "slider", "body": "rod"}, "exactly one of slider"),
        ({"target": 0.2, "slider": "rod"}, "Body 'rod' is not a slider or block; sliders: slider"),
        ({"target": np.nan, "slider": "slider"}, "The target of inverse_position must be a finite number"),
        ({"target": 0.2, "slider": "slider", "samples": 4}, "samples of inverse_position must be an integer >= 16"),
        ({"target": 0.2, "slider": "slider", "crank_range": (1.0, 0.5)}, "start < end"),
        ({"target": 0.2, "slider": "slider", "crank_range": (0.0, 7.0)}, "at most one turn"),
    ],
)
def test_inverse_bad_input_by_message(kwargs, message):
    with pytest.raises(InputError) as err:
        inverse_position(slider_crank(0.05, 0.2), **kwargs)
    assert message in str(err.value)


def test_inverse_out_of_reach_names_the_design_and_the_angle_range():
    with pytest.raises(InputError, match=r"0\.255 m is out of reach of design 1: .* spans 0\.15 m to 0\.25 m"):
        inverse_position(slider_crank(np.array([0.06, 0.05]), 0.2), 0.255, slider="slider")
    with pytest.raises(InputError, match=r"rocker.angle .* out of reach: .* spans .*°"):
        inverse_position(four_bar(0.04, 0.12, 0.08, 0.10), np.radians(10.0), body="rocker")


# ------------------------------------------------------------------------------- crank_effort, piston_effort


def _gas_engine(r=0.2, l=0.6, gas=-20_000.0, piston=60.0, rod=(0.0, 0.0)):
    """A horizontal engine: a gas force on the piston towards the crank, no gravity."""
    mech = slider_crank(r, l, masses=(0.0, rod[0], piston), inertias=(0.0, rod[1], 0.0), gravity=(0.0, 0.0))
    return with_loads(mech, forces=PointForce("gas", "slider.B", fx=gas))


def test_crank_effort_matches_the_textbook_closed_form_for_a_massless_rod():
    # Khurmi & Gupta, Theory of Machines, §15.8: F_T = F_P sin(theta + phi) / cos(phi), F_B = F_P cos(theta +
    # phi) / cos(phi), sin(phi) = sin(theta) / n, F_P = F_L - m a_P.
    r, l, omega = 0.2, 0.6, 12.0
    theta = np.radians(np.arange(5.0, 180.0, 10.0))
    forces = kinetostatics(_gas_engine(r, l), theta, omega)
    effort, piston = crank_effort(forces), piston_effort(forces)
    a_p = forces.kinematics.slide("slider").a
    f_p = 20_000.0 + 60.0 * a_p  # the piston accelerates along +x; the gas pushes along -x (towards the crank)
    phi = np.arcsin(np.sin(theta) * r / l)
    np.testing.assert_allclose(piston.along_stroke, f_p, rtol=1e-12)
    np.testing.assert_allclose(piston.rod_thrust, f_p / np.cos(phi), rtol=1e-12)
    np.testing.assert_allclose(effort.tangential, f_p * np.sin(theta + phi) / np.cos(phi), rtol=1e-10)
    np.testing.assert_allclose(effort.radial, f_p * np.cos(theta + phi) / np.cos(phi), rtol=1e-9, atol=1e-9)
    # The side thrust F_N = F_P tan(phi): the compressed rod pushes the piston down, the guide pushes it up (+y).
    np.testing.assert_allclose(piston.normal, f_p * np.tan(phi), rtol=1e-10)


def test_turning_moment_is_minus_driving_torque_for_a_massless_crank_over_designs():
    r = np.array([0.15, 0.2, 0.25])
    mech = with_loads(
        slider_crank(r, 0.8, masses=(0.0, 3.0, 8.0), gravity=(0.0, -9.81)),
        forces=PointForce("gas", "slider.B", fx=-5000.0),
    )
    forces = kinetostatics(mech, crank_angles(72), 30.0)
    effort = crank_effort(forces)
    assert effort.tangential.shape == (3, 72)
    np.testing.assert_allclose(effort.turning_moment, -forces.driving_torque, rtol=1e-10, atol=1e-9)
    np.testing.assert_allclose(effort.driving_force, forces.driving_torque / r[:, None], rtol=1e-12)
    # Power: the pin force times the pin's speed is the turning moment times the crank speed.
    pin = forces.kinematics.point("crank.A")
    reaction = forces.joint("A")
    power = -(reaction.fx * pin.vx + reaction.fy * pin.vy)
    np.testing.assert_allclose(power, effort.turning_moment * 30.0, rtol=1e-10, atol=1e-8)


def test_driving_torque_is_positive_in_the_direction_of_rotation():
    # A press: the slider pushes against a constant process force; the motor supplies positive work whichever
    # way the crank turns, so the driving torque in the direction of rotation is >= 0 on the working stroke.
    mech = with_loads(
        slider_crank(0.05, 0.2, masses=(0.0, 0.0, 0.0), gravity=(0.0, 0.0)),
        forces=PointForce("process", "slider.B", fx=1000.0),  # resists the slider's motion towards -x
    )
    ccw = crank_effort(kinetostatics(mech, np.radians(60.0), 10.0))
    cw = crank_effort(kinetostatics(mech, np.radians(-60.0), -10.0))
    assert float(ccw.driving_torque) > 0 and float(cw.driving_torque) > 0
    np.testing.assert_allclose(cw.driving_torque, ccw.driving_torque, rtol=1e-12)
    np.testing.assert_allclose(cw.tangential, ccw.tangential, rtol=1e-12)


def test_effort_needs_a_pin_when_the_crank_has_several():
    mech = double_slider_crank(0.05, 0.2, 0.05, 0.2, gravity=(0.0, 0.0))
    forces = kinetostatics(mech, crank_angles(8), 5.0)
    with pytest.raises(InputError, match=r"carries 2 pins \(A1, A2\); name one with pin=..."):
        crank_effort(forces)
    with pytest.raises(InputError, match=r"pin must be a joint on the crank 'crank'; got 'B1'; pins: A1, A2"):
        crank_effort(forces, pin="B1")
    with pytest.raises(InputError, match=r"has 2 sliders driven by a rod \(slider_1, slider_2\)"):
        piston_effort(forces)
    both = crank_effort(forces, pin="A1").turning_moment + crank_effort(forces, pin="A2").turning_moment
    np.testing.assert_allclose(both, -forces.driving_torque, rtol=1e-10, atol=1e-10)
    assert piston_effort(forces, slider="slider_2").slider == "slider_2"


def test_piston_effort_needs_a_slider():
    forces = kinetostatics(four_bar(0.04, 0.12, 0.08, 0.10), crank_angles(8), 5.0)
    with pytest.raises(InputError, match="has 0 sliders driven by a rod"):
        piston_effort(forces)
    with pytest.raises(InputError, match="needs the Forces of kinetostatics; got Kinematics"):
        crank_effort(forces.kinematics)


# ------------------------------------------------------------------------------------------------ mass_centre


def _loaded_four_bar():
    base = four_bar(np.array([0.04, 0.045]), 0.12, 0.08, 0.10, masses=(0.2, 0.5, 0.4), gravity=(0.0, 0.0))
    return with_loads(base, point_masses=PointMass("counterweight", "crank", 0.3, (-0.03, 0.01)))


def test_total_mass_times_centre_acceleration_is_minus_the_shaking_force():
    mech = _loaded_four_bar()
    forces = kinetostatics(mech, crank_angles(90), 7.0, 3.0)
    g = mass_centre(forces.kinematics)
    np.testing.assert_allclose(g.mass, 1.4)
    fx, fy = g.inertia_force
    scale = float(np.max(np.hypot(fx, fy)))
    np.testing.assert_allclose(fx, forces.frame_fx, atol=1e-12 * scale)
    np.testing.assert_allclose(fy, forces.frame_fy, atol=1e-12 * scale)
    assert g.ax.shape == (2, 90)


def test_with_gravity_the_frame_force_is_total_weight_minus_mass_times_acceleration():
    mech = with_loads(_loaded_four_bar(), gravity=(0.0, -9.81))
    forces = kinetostatics(mech, crank_angles(30), 7.0)
    g = mass_centre(forces.kinematics)
    np.testing.assert_allclose(forces.frame_fy, g.mass * (-9.81 - g.ay), rtol=1e-12, atol=1e-12)


def test_centre_of_mass_velocity_and_acceleration_are_derivatives():
    mech = _loaded_four_bar()
    phi = crank_angles(24)
    g0, gp, gm = (mass_centre(kinematics(mech, phi + d, 1.0)) for d in (0.0, FD_STEP, -FD_STEP))
    for pos, vel in (("x", "vx"), ("y", "vy"), ("vx", "ax"), ("vy", "ay")):
        derivative = (getattr(gp, pos) - getattr(gm, pos)) / (2 * FD_STEP)
        np.testing.assert_allclose(derivative, getattr(g0, vel), atol=1e-6 * np.max(np.abs(getattr(g0, vel))))


def test_centre_of_mass_stands_still_for_a_fully_balanced_crank():
    # A crank balanced by a counterweight of equal moment and nothing else moving: G stays on the pivot.
    mech = slider_crank(0.05, 0.2, masses=(1.0, 0.0, 0.0), coms=((0.025, 0.0), (0.1, 0.0), (0.0, 0.0)))
    mech = with_loads(mech, point_masses=PointMass("cw", "crank", 0.5, (-0.05, 0.0)))
    g = mass_centre(kinematics(mech, crank_angles(16), 10.0))
    np.testing.assert_allclose([g.x, g.y, g.speed], 0.0, atol=1e-15)


def test_mass_centre_of_a_massless_mechanism_is_an_error():
    mech = slider_crank(0.05, 0.2, masses=(0.0, 0.0, 0.0))
    with pytest.raises(InputError, match="must have a total mass > 0 kg to have a centre of mass; got 0 kg"):
        mass_centre(kinematics(mech, crank_angles(4)))


# ------------------------------------------------------------------------------------------ energy_fluctuation


def test_energy_fluctuation_of_a_sinusoid_over_one_and_two_turns():
    # T = T0 + A sin(k phi): E = -(A/k) cos(k phi), swing 2 A / k; a four-stroke cycle is 4 pi (k = 1/2).
    # The trapezoidal rule's error is about (k h)^2 / 12 relative: 6e-5 for k = 3 at h = 0.5°.
    phi = crank_angles(720)
    np.testing.assert_allclose(energy_fluctuation(500 + 80 * np.sin(3 * phi), phi), 2 * 80 / 3, rtol=1e-4)
    phi4 = np.arange(1440) * (4 * np.pi / 1440)
    np.testing.assert_allclose(energy_fluctuation(500 + 80 * np.sin(phi4 / 2), phi4), 4 * 80, rtol=1e-5)
    # The same cycle with its end point, and the explicit cycle length.
    with_end = np.linspace(0.0, 4 * np.pi, 1441)
    np.testing.assert_allclose(
        energy_fluctuation(500 + 80 * np.sin(with_end / 2), with_end, cycle=4 * np.pi), 320.0, rtol=1e-5
    )


def test_energy_fluctuation_converges_with_the_square_of_the_step():
    exact = np.hypot(300.0, 500.0)

    def error(n):
        phi = crank_angles(n)
        return abs(float(energy_fluctuation(1000 + 300 * np.sin(2 * phi) - 500 * np.cos(2 * phi), phi)) - exact)

    assert 3.5 < error(180) / error(360) < 4.5


def test_energy_fluctuation_of_a_piecewise_linear_diagram_is_exact():
    # One triangle of height 4 over the first half turn, zero after: T_mean = (4 pi / 2) / (2 pi) = 1;
    # the part above the mean is a similar triangle of height 3 and base 3 pi / 4: dE = 9 pi / 8.
    phi = crank_angles(720)
    torque = np.where(phi < np.pi, 4.0 * (1.0 - np.abs(phi - np.pi / 2) / (np.pi / 2)), 0.0)
    np.testing.assert_allclose(energy_fluctuation(torque, phi), 9 * np.pi / 8, rtol=1e-12)


def test_energy_fluctuation_over_designs_and_sign():
    phi = crank_angles(360)
    torque = np.array([[1.0], [2.0], [3.0]]) * np.sin(phi)
    out = energy_fluctuation(torque, phi)
    assert out.shape == (3,)
    np.testing.assert_allclose(out, [2.0, 4.0, 6.0], rtol=1e-4)
    np.testing.assert_array_equal(energy_fluctuation(-torque, phi), out)


def test_energy_fluctuation_of_an_engine_converges_with_the_sampling():
    # A slider-crank's driving torque is smooth and periodic: 360 and 3600 samples agree to the O(h^2) error.
    mech = with_loads(slider_crank(0.05, 0.2, masses=(0.5, 1.0, 2.0)), forces=PointForce("gas", "slider.B", fx=-300.0))
    coarse, fine = (
        energy_fluctuation(kinetostatics(mech, crank_angles(n), 40.0).driving_torque, crank_angles(n))
        for n in (360, 3600)
    )
    np.testing.assert_allclose(coarse, fine, rtol=1e-4)


@pytest.mark.parametrize(
    ("phi", "torque", "kwargs", "message"),
    [
        (np.linspace(0, 1.5 * np.pi, 100), None, {}, "must cover a whole number of turns (360°, 720°, ...)"),
        (crank_angles(360), None, {"cycle": 4 * np.pi}, "must cover the cycle of 720°"),
        (crank_angles(360), None, {"cycle": 3.0}, "The cycle must be a whole number of turns"),
        (np.sort(np.random.default_rng(1).uniform(0, 6, 50)), None, {}, "evenly spaced and increasing"),
        (crank_angles(4), None, {}, "at least 8 angles"),
        (crank_angles(36), np.full(36, np.nan), {}, "must be finite at every crank angle"),
        (crank_angles(36), np.zeros(35), {}, "last axis must match the 36 crank angles"),
    ],
)
def test_energy_fluctuation_bad_input_by_message(phi, torque, kwargs, message):
    t = np.sin(phi) if torque is None else torque
    with pytest.raises(InputError) as err:
        energy_fluctuation(t, phi, **kwargs)
    assert message in str(err.value)


# ------------------------------------------------------------------------------------ property tests (random)


@st.composite
def engines(draw):
    """A random offset slider-crank or crank-rocker four-bar, its crank without mass, with random masses, a
    counterweight on the coupler and a force on the output: one that turns fully."""
    masses = (0.0, draw(st.floats(0.1, 5.0)), draw(st.floats(0.1, 5.0)))
    if draw(st.booleans()):
        r = draw(st.floats(0.02, 0.1))
        mech = slider_crank(r, r * draw(st.floats(2.5, 6.0)), r * draw(st.floats(-0.8, 0.8)), masses=masses,
                            gravity=(0.0, 0.0))
        force = PointForce("load", "slider.B", fx=draw(st.floats(-500.0, 500.0)))
        body = "rod"
    else:
        crank = draw(st.floats(0.02, 0.04))
        mech = four_bar(crank, 0.12, 0.08, 0.10, masses=masses, gravity=(0.0, 0.0))
        force = PointForce("load", "rocker.B", fy=draw(st.floats(-500.0, 500.0)))
        body = "coupler"
    weight = PointMass("cw", body, draw(st.floats(0.0, 2.0)), (0.01, draw(st.floats(-0.02, 0.02))))
    return with_loads(mech, forces=force, point_masses=weight)


@settings(max_examples=25, deadline=None)
@given(mech=engines(), speed=st.floats(-40.0, 40.0).filter(lambda w: abs(w) > 0.5), accel=st.floats(-50.0, 50.0))
def test_random_engines_obey_the_centre_of_mass_and_crank_effort_identities(mech, speed, accel):
    forces = kinetostatics(mech, crank_angles(36), speed, accel)
    kin = forces.kinematics
    g = mass_centre(kin)
    # Frame force = the external force on the moving parts - M a_G (gravity off).
    fx, fy = g.inertia_force
    load = mech.forces[0]
    scale = float(np.max(np.hypot(fx, fy))) + abs(float(load.fx)) + abs(float(load.fy)) + 1.0
    np.testing.assert_allclose(forces.frame_fx, fx + load.fx, atol=1e-9 * scale)
    np.testing.assert_allclose(forces.frame_fy, fy + load.fy, atol=1e-9 * scale)
    # A crank without mass or load of its own: the pin's turning moment balances the drive at every position.
    effort = crank_effort(forces)
    torque_scale = float(np.max(np.abs(forces.driving_torque))) + 1e-9
    np.testing.assert_allclose(effort.turning_moment, -effort.driving_torque, atol=1e-9 * torque_scale)
    np.testing.assert_allclose(effort.driving_torque, np.sign(speed) * forces.driving_torque, rtol=1e-15)
