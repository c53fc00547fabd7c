"""[transient.motor]: an induction motor's electrical states integrated with the machine — its events (switch-off,
speed change), its energy balance, the problem file, the report section, a motor that cannot start and bad
input."""

import re
from pathlib import Path

import numpy as np
import pytest

from machdyn.dynamics import equivalent_machine
from machdyn.dynamics.simulate import balance_speed
from machdyn.errors import InputError, ProblemFileError
from machdyn.runner import check_problem, run_problem
from machdyn.transient import Exciter, Scenario, coupled_model, run_scenario
from machdyn.transient.electric import motor_run
from machdyn.transient.induction import InductionMachine
from machdyn.transient.motor_table import energy_error
from machdyn.transient.run import _shifted

from .machines import rotor, small_press

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "rotary_screen_induction_dq.toml"


def _motor(**changes):
    """Krause's 3-hp machine through a 10:1 gear of 90 % efficiency (the press's crank at about 18 rad/s)."""
    values = dict(ratio=10.0, efficiency=0.9, rotor_inertia=0.089, line_voltage=220.0)
    values |= changes
    return InductionMachine(0.435, 0.816, 0.754, 0.754, 26.13, 2, frequency=60.0, **values)


def test_a_switch_off_opens_the_stator_and_its_field_energy_is_booked():
    model = coupled_model([Exciter(small_press(), _motor(), 0.5)], None)
    run = run_scenario(model, Scenario(duration=2.0, switch_off=1.0))
    motor = motor_run(run)
    after = run.t > 1.0
    assert np.all(motor.torque[after] == pytest.approx(0.0, abs=1e-9))  # an open stator carries no torque
    assert np.all(motor.current[after] == pytest.approx(0.0, abs=1e-9))
    assert motor.switching_loss > 0.0  # the stator's leakage field goes into the contactor's arc
    # input = copper + switching + magnetic + gear loss + the machine's own balance, to 1e-6 of the input
    assert energy_error(motor, run) < 1e-6
    # the gear loss is (1 - eta) of the air-gap work while the motor drives
    assert motor.air_gap_work - run.works[0, -1] == pytest.approx(0.1 * motor.air_gap_work, rel=0.05)


def test_a_new_supply_frequency_moves_the_speed_to_the_shifted_circuits_balance():
    mech = small_press()
    motor = _motor(efficiency=1.0)
    machine = equivalent_machine(mech, 256)
    model = coupled_model([Exciter(mech, motor, 0.5, machine=machine)], None)
    run = run_scenario(model, Scenario(duration=2.0, speed_change_time=1.0, speed_factor=0.8))
    shifted = _shifted(motor, 0.8, 1.0)
    assert shifted.supply_factor == 0.8 and shifted.phase == pytest.approx(0.2 * 120 * np.pi)
    expected = float(balance_speed(machine, shifted, 1, np.linspace(0, 2 * np.pi, 256, endpoint=False))[0])
    last = run.t >= run.t[-1] - 2 * np.pi / expected
    # the slider-crank's inertia varies over the turn: a mean over time, not over the angle (as for the curve)
    assert run.omega[0, last].mean() == pytest.approx(expected, rel=2e-3)
    assert energy_error(motor_run(run), run) < 1e-6


def test_bad_motor_data_are_refused_naming_the_value():
    with pytest.raises(InputError, match=r"stator resistance of the induction motor must be > 0 ohm; got -1"):
        _motor().__class__(-1.0, 0.8, 0.7, 0.7, 26.0, 2, 220.0, 60.0)
    with pytest.raises(InputError, match=r"pole pairs .* integer >= 1; got 1.5"):
        InductionMachine(0.4, 0.8, 0.7, 0.7, 26.0, 1.5, 220.0, 60.0)  # type: ignore[arg-type]


def _text(**changes) -> str:
    text = EXAMPLE.read_text(encoding="utf-8")
    text = re.sub(r'(?m)^duration = .*$', 'duration = "2.5 s"', text)
    text = re.sub(r"(?m)^(switch_off|brake_time|brake_torque) = .*$\n", "", text)
    for key, value in changes.items():
        text = re.sub(rf"(?m)^{key} = .*$", f"{key} = {value}", text)
    return text


@pytest.fixture(scope="module")
def screen():
    """The rotary screen's start on its mounts with its motor's dq model (2.5 s)."""
    return run_problem(_text())


def test_the_screen_with_its_motors_electrical_states_reports_them(screen):
    values = {k: v["value"] for k, v in screen.results_json()["scalars"].items()}
    assert not screen.failed_checks
    assert values["transient.energy_error"] < 1e-6
    assert values["transient.motor_energy_error"] < 1e-6
    # the switch-on's torque pulsations exceed the steady state's breakdown torque; the start's current is
    # several times the running current
    assert values["transient.motor_peak_torque"] > values["transient.motor_breakdown_torque"]
    outcome = screen.outcomes["transient"]
    motor = outcome.results.motor
    assert motor.peak_current > 4 * motor.current[-1]
    assert values["transient.time_to_speed"] < 2.5
    # the motor's speed at the end is the equivalent circuit's balance with the machine's mean load (its
    # free speed, from the same motor's steady-state curve), within the speed fluctuation over a turn
    assert values["transient.final_speed"] == pytest.approx(values["transient.free_speed"], rel=0.02)
    assert {"time", "electromagnetic_torque", "stator_current"} <= set(outcome.series["transient_motor"])
    assert "transient.motor_peak_current" in {row.key for row in screen.summary.rows}


def test_the_report_adds_the_motors_section(screen):
    from machdyn.report.transient_drive import sections

    found = dict(sections(screen.outcomes["transient"]))
    assert "The machine in time" in found
    html = found["The motor's electrical states"]
    assert "<svg" in html and "copper loss" in html and "breakdown" in html


def test_a_motor_too_weak_to_start_the_crank_is_refused_naming_both_torques():
    # 1 kg at 0.1 m held level by gravity: 0.98 N*m to lift; at a tenth of its voltage Krause's 3-hp motor starts
    # with 1 % of its 53 N*m (the steady state's torque at standstill, the equivalent circuit's at s = 1)
    weak = _motor(ratio=1.0, efficiency=1.0, rotor_inertia=0.0, line_voltage=22.0)
    assert weak.starting_torque == pytest.approx(0.5297, abs=1e-4)
    model = coupled_model([Exciter(rotor(1.0, 0.1, gravity=(0.0, -9.80665)), weak)], None)
    with pytest.raises(InputError, match=r"cannot start.*0\.5297 N\*m.*0\.9807 N\*m"):
        run_scenario(model, Scenario(duration=1.0))


def test_the_motor_table_is_checked_with_every_mistake_and_its_path():
    text = _text(model='"induction"', stator_resistance='"-1 ohm"', frequency='"-50 Hz"')
    for step in (check_problem, run_problem):
        with pytest.raises(ProblemFileError) as caught:
            step(text)
        paths = {p for p, _ in caught.value.problems}
        assert {"transient.motor.model", "transient.motor.stator_resistance",
                "transient.motor.frequency"} <= paths, paths


def test_the_motor_table_needs_an_induction_motor_in_flywheel():
    text = _text().replace('kind = "induction"', 'kind = "constant_torque"')
    for step in (check_problem, run_problem):
        with pytest.raises(ProblemFileError, match=r"transient\.motor: an induction motor's electrical model"):
            step(text)
