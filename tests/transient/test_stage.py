"""[transient] from a problem file, and the scenarios' events (speed change, load step) in Python."""

from pathlib import Path

import numpy as np
import pytest

from machdyn.dynamics import InductionMotor, equivalent_machine
from machdyn.dynamics.simulate import balance_speed
from machdyn.runner import run_problem
from machdyn.transient import Exciter, Scenario, coupled_model, run_scenario
from machdyn.transient.run import _shifted

from .machines import small_press

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "rotary_screen_start_stop.toml"
RPM = np.pi / 30.0


@pytest.fixture(scope="module")
def screen():
    return run_problem(EXAMPLE)


def test_the_screen_starts_passes_each_mode_up_and_down_and_stops(screen):
    values = screen.results_json()["scalars"]
    result = screen.outcomes["transient"].results
    modes = len(result.modes.angular_frequencies)
    ups = [p for p in result.passages if p.direction == "up"]
    downs = [p for p in result.passages if p.direction == "down"]
    assert len(ups) == modes and len(downs) == modes  # every mode passed at the start and at the stop
    assert all(p.completed for p in result.passages)
    assert values["transient.stop_time"]["value"] < 20.0  # the brake stopped it
    assert values["transient.captured"]["value"] == 0.0
    assert values["transient.energy_error"]["value"] < 1e-6
    # the braked stop is slower through the modes than the start: more time in their bands
    assert sum(p.time_in_band for p in downs) > sum(p.time_in_band for p in ups)
    # the passages magnify the frame's motion above its steady running at the speed above all modes
    assert values["transient.passage_peak_amplitude"]["value"] > 2 * values["transient.steady_amplitude"]["value"]
    assert not screen.failed_checks


def test_the_screen_report_section_and_series(screen):
    from machdyn.report.transient import sections

    outcome = screen.outcomes["transient"]
    (heading, html), = sections(outcome)
    assert heading == "The machine in time" and "<svg" in html and "peak mount force" in html
    assert {"time", "speed", "frame_x", "mount_force_front_v"} <= set(outcome.series["transient"])
    assert outcome.series["transient_amplitude"]["speed"][0].size > 20


def test_a_new_supply_frequency_moves_the_speed_to_the_shifted_motors_balance():
    mech = small_press()
    motor = InductionMotor(250.0, 1440 * RPM, 1500 * RPM, 2.5, 10.0, 1.0, 1e-3)
    machine = equivalent_machine(mech, 256)
    model = coupled_model([Exciter(mech, motor, 0.05, machine=machine)], None)
    run = run_scenario(model, Scenario(duration=3.0, speed_change_time=1.0, speed_factor=0.8))
    expected = float(balance_speed(machine, _shifted(motor, 0.8), 1, np.linspace(0, 2 * np.pi, 256,
                                                                                   endpoint=False))[0])
    last = run.t >= run.t[-1] - 2 * np.pi / expected
    assert run.omega[0, last].mean() == pytest.approx(expected, rel=2e-3)  # a mean over time, not over the angle
    assert run.energy_error < 1e-6


def test_a_load_step_slows_the_crank_and_its_work_is_counted():
    mech = small_press()
    motor = InductionMotor(250.0, 1440 * RPM, 1500 * RPM, 2.5, 10.0, 1.0, 1e-3)
    model = coupled_model([Exciter(mech, motor, 0.05)], None)
    before = run_scenario(model, Scenario(duration=2.0))
    after = run_scenario(model, Scenario(duration=2.0, load_time=1.0, load_torque=8.0))
    assert after.omega[0, -1] < before.omega[0, -1] - 0.1
    # the press has no other load: the load's work is 8 N*m over the angle turned after the step
    assert before.works[1, -1] == 0.0
    turned = after.phi[0, -1] - np.interp(1.0, after.t, after.phi[0])
    assert -after.works[1, -1] == pytest.approx(8.0 * turned, rel=1e-3)
    assert after.energy_error < 1e-6


def test_the_two_exciter_screen_synchronises_from_its_problem_file():
    """examples/two_exciter_screen.toml: two counter-rotating exciters ([transient.twin], mirrored) started 120
    degrees apart fall into step and shake the box in a straight line, vertically (Blekhman's result; the
    validation with the amplitude is in tests/validation/test_transient_resonance.py)."""
    result = run_problem(EXAMPLE.with_name("two_exciter_screen.toml"))
    values = result.results_json()["scalars"]
    assert abs(values["transient.phase_difference"]["value"]) < np.radians(2.0)  # [rad]
    run = result.outcomes["transient"].results.run
    last = run.t >= run.t[-1] - 0.3
    assert np.ptp(run.q[0][last]) < 0.1 * np.ptp(run.q[1][last])  # hardly any horizontal motion
    assert np.ptp(run.q[2][last]) * 0.8 < 0.1 * np.ptp(run.q[1][last])  # nor rocking (at the mounts, 0.8 m out)
    assert not result.failed_checks
