"""The limits of the coupled model that today's separate analyses already answer.

1. A rigid frame: the crank's equation is the equivalent machine's J phi'' + J'/2 phi'^2 = M_drive + M, so the
   start-up is that of :func:`machdyn.dynamics.simulate` (the same machine, drive and flywheel).
2. A prescribed constant crank speed: the frame is driven by the mechanism's shaking loads, so after the
   free vibration has died out it moves as :func:`machdyn.vibration.response.steady_state` says (for the frame
   that carries the mechanism's moving masses at their mean positions, :func:`carried_frame`).
3. The energy balance of every run: motor work = change of kinetic and potential energy + dissipation + the work
   on the loads, to 1e-6 of the largest energy that flows.
"""

from dataclasses import replace

import numpy as np
import pytest

from machdyn.dynamics import InductionMotor, equivalent_machine, simulate
from machdyn.linkage import analyse, crank_angles
from machdyn.transient import Exciter, Scenario, carried_frame, coupled_model, run_scenario
from machdyn.vibration.response import shaking_loads, steady_state

from .machines import plate, small_press

RPM = np.pi / 30.0


@pytest.fixture(scope="module")
def motor():
    """A 0.25 kW 4-pole motor through a 10:1 gear: the crank runs at about 15 rad/s."""
    return InductionMotor(250.0, 1440 * RPM, 1500 * RPM, 2.5, 10.0, 1.0, 1e-3)


def test_a_rigid_frame_gives_the_start_up_of_the_equivalent_machine(motor):
    from machdyn.linkage import slider_crank

    mech = slider_crank(0.05, 0.2, masses=(1.0, 1.5, 0.5), inertias=(2e-4, 5e-3, 0.0))  # gravity on
    machine = equivalent_machine(mech, 360)
    today = simulate(machine, motor, 0.02, duration=1.0, samples=201, rtol=1e-10)
    model = coupled_model([Exciter(mech, motor, 0.02, machine=machine)], None)
    run = run_scenario(model, Scenario(duration=1.0, rtol=1e-10, method="DOP853"))
    # the times both sample (the integrators' own dense outputs, no interpolation between samples)
    common, mine, theirs = np.intersect1d(np.round(run.t, 9), np.round(today.t, 9), return_indices=True)
    assert common.size > 30
    # both integrate one equation to 1e-10; the curves J(phi), V(phi) are trigonometric interpolants of the same
    # engine values (360 and 256 positions, both resolved), so they agree to round-off
    assert np.max(np.abs(run.omega[0, mine] - today.omega[theirs])) <= 1e-7 * np.max(today.omega)
    assert today.omega[-1] > 10.0  # it did start and run up
    assert run.energy_error < 1e-6


def test_a_prescribed_constant_speed_gives_the_frame_steady_state():
    mech = small_press()
    speed = 30.0
    model = coupled_model([Exciter(mech, None)], plate())
    run = run_scenario(model, Scenario(duration=6.0, prescribed=(speed, 0.0), method="DOP853", rtol=1e-9))
    frame = carried_frame(model)
    loads = shaking_loads(analyse(mech, crank_angles(360), speed), orders=8)
    response = steady_state(frame, loads)
    period = 2 * np.pi / speed
    last = run.t >= run.t[-1] - period
    t = run.t[last]
    for point in ((0.0, 0.0), (0.6, -0.2)):
        amplitudes = response.displacement(point)  # (orders, 2), phase at crank angle 0 when t = 0
        expected = (np.exp(1j * np.outer(t, response.angular_frequencies)) @ amplitudes).real.T
        got = run.point_displacement(point)[:, last]
        # the carried frame holds the moving masses' mean inertia; the coupled model's changes over the turn by
        # the relative amount below, and the free vibration has decayed to exp(-zeta w t) < 1e-4 of its start
        part = model.parts[0]
        variation = float(np.sum(np.hypot(part.ca[7], part.cb[7]))) / frame.inertia
        assert variation < 0.01
        scale = np.max(np.abs(expected))
        assert np.max(np.abs(got - expected)) <= (3 * variation + 1e-3) * scale
    assert run.energy_error < 1e-6


def test_start_and_braked_stop_on_a_frame_balance_their_energy(motor):
    mech = small_press()
    model = coupled_model([Exciter(mech, motor, 0.02)], plate())
    run = run_scenario(model, Scenario(duration=3.0, switch_off=1.2, brake_time=1.2, brake_torque=3.0))
    assert run.ended == "stopped"
    w = run.works[:, -1]
    assert w[0] > 0 and w[2] > 0 and w[3] > 0  # the motor gave, the mounts and the brake took
    assert run.energy_error < 1e-6
    # at rest again the energy is back near its start: what the motor gave went to the mounts, brake and loads
    assert abs(run.energy[-1] - run.energy[0]) < 0.02 * w[0]


def test_a_rigid_frame_runs_into_the_periodic_steady_state(motor):
    """The start-up on a rigid frame settles into the periodic steady state that :func:`steady_state` finds
    directly (shooting / Fourier collocation), at every crank angle of the last turn."""
    from machdyn.dynamics import steady_state as periodic_steady_state

    mech = small_press()
    machine = equivalent_machine(mech, 256)
    steady = periodic_steady_state(machine, motor, 0.02)
    model = coupled_model([Exciter(mech, motor, 0.02, machine=machine)], None)
    run = run_scenario(model, Scenario(duration=1.0, rtol=1e-10, method="DOP853"))
    last = run.phi[0] >= run.phi[0, -1] - 2 * np.pi
    expected = steady.speed_curve()(np.mod(run.phi[0, last], 2 * np.pi))
    # the start-up's remainder decays with the motor's time constant J / |dT/domega| (a few hundredths of a
    # second here): after 1 s the speed agrees to 1e-9 at every node (the Hermite curve of the steady speed
    # between the steady state's nodes is good to O(h^4)); 1e-7 allows for either
    assert float(steady.delta) > 1e-3  # a fluctuating speed, compared angle by angle
    assert np.max(np.abs(run.omega[0, last] - np.ravel(expected))) <= 1e-7 * float(steady.mean_speed)


@pytest.mark.parametrize("prescribed", [None, (5.0, 20.0)])
def test_the_scalar_right_hand_side_is_the_matrix_one(motor, monkeypatch, prescribed):
    """One crank on a frame runs through the scalar right-hand side of machdyn.transient.fast; the general one
    (the mass matrix assembled and solved) integrates the same equations (gravity on, so its coupling counts)."""
    from machdyn.linkage import slider_crank
    from machdyn.transient import fast

    mech = slider_crank(0.05, 0.2, masses=(1.0, 1.5, 0.5), inertias=(2e-4, 5e-3, 0.0))
    model = coupled_model([Exciter(mech, motor, 0.02, origin=(0.2, 0.1), angle=0.3)], plate())
    scenario = Scenario(duration=0.8, switch_off=0.5, brake_time=0.5, brake_torque=2.0, prescribed=prescribed,
                        method="DOP853", rtol=1e-10)
    quick = run_scenario(model, scenario)
    monkeypatch.setattr(fast, "usable", lambda model: False)
    general = run_scenario(model, scenario)
    assert quick.t.shape == general.t.shape
    assert np.max(np.abs(quick.q - general.q)) <= 1e-7 * np.max(np.abs(general.q))
    assert np.max(np.abs(quick.omega - general.omega)) <= 1e-7 * np.max(np.abs(general.omega))
    assert np.max(np.abs(quick.drive_torque - general.drive_torque)) <= 1e-6 * np.max(np.abs(general.drive_torque))


def test_without_drive_and_dampers_the_energy_of_crank_and_frame_is_conserved():
    """Lagrange's equations of the coupled model conserve T + V when nothing drives or dissipates: a check of
    every derivative in them (J', a', Mm', the weight turning with the frame) against the curves themselves. The
    crank is given a speed and left free on undamped mounts, with gravity, the mechanism placed off the frame's
    reference point and turned."""
    from machdyn.linkage import slider_crank
    from machdyn.vibration.frame import Frame

    mech = slider_crank(0.05, 0.2, masses=(1.0, 1.5, 0.5), inertias=(2e-4, 5e-3, 0.0))
    undamped = Frame(40.0, 6.0, tuple(replace(m, damping=0.0) for m in plate().mounts), com=(0.0, -0.1))
    model = coupled_model([Exciter(mech, None, 0.002, origin=(0.2, 0.1), angle=0.3)], undamped)
    run = run_scenario(model, Scenario(duration=1.0, speed=20.0, method="DOP853", rtol=1e-10))
    assert np.max(np.abs(run.q[1])) > 5e-5  # the light frame does move (some 0.08 mm)
    swing = np.max(np.abs(run.energy - run.energy[0])) / run.energy[0]
    assert swing < 1e-8
