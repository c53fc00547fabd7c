"""Bad input and runaway runs: refused before the run, or stopped with a message naming why and how far."""

import re
from pathlib import Path

import numpy as np
import pytest

from machdyn.dynamics import TorqueSpeedTable
from machdyn.errors import InputError, ProblemFileError
from machdyn.runner import check_problem, run_problem
from machdyn.transient import Exciter, Scenario, TransientLimitError, coupled_model, run_scenario

from .machines import rotor, sprung_block

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "rotary_screen_start_stop.toml"
GRAVITY = (0.0, -9.80665)


def test_a_motor_that_cannot_start_the_crank_is_refused_naming_both_torques():
    # 1 kg at 0.1 m held level by gravity: 0.98 N*m to lift, against 0.5 N*m of starting torque
    model = coupled_model([Exciter(rotor(1.0, 0.1, gravity=GRAVITY), TorqueSpeedTable((0.0, 50.0), (0.5, 0.0)))],
                          sprung_block())
    with pytest.raises(InputError, match=r"cannot start.*0\.5 N\*m.*0\.9807 N\*m"):
        run_scenario(model, Scenario(duration=1.0))


def test_a_motor_that_cannot_lift_the_crank_over_rolls_back_and_the_run_ends():
    model = coupled_model([Exciter(rotor(1.0, 0.1, gravity=GRAVITY), TorqueSpeedTable((0.0, 50.0), (0.5, 0.0)))],
                          None)
    run = run_scenario(model, Scenario(duration=5.0, angle=-np.pi / 2))  # hanging down: it starts, swings, falls
    assert run.ended == "rolled back"
    assert run.t[-1] < 5.0
    assert np.max(run.phi[0]) < np.pi / 2  # it never got over the top
    assert run.energy_error < 1e-6


def test_the_evaluation_budget_stops_a_run_saying_how_far_it_came():
    model = coupled_model([Exciter(rotor(), TorqueSpeedTable((0.0, 100.0), (30.0, 0.0)))], sprung_block())
    with pytest.raises(TransientLimitError, match=r"budget of 1,000 evaluations at t = .* of 100 s"):
        run_scenario(model, Scenario(duration=100.0, max_evaluations=1000))


def test_the_time_budget_stops_a_run():
    model = coupled_model([Exciter(rotor(), TorqueSpeedTable((0.0, 100.0), (30.0, 0.0)))], sprung_block())
    with pytest.raises(TransientLimitError, match=r"stopped after 0\.01 s of computing"):
        run_scenario(model, Scenario(duration=100.0, max_seconds=0.01))


@pytest.mark.parametrize(("kwargs", "message"), [
    ({"duration": -1.0}, "duration of a transient run must be > 0 s"),
    ({"duration": 1.0, "switch_off": 2.0}, r"switch off .* must lie in \[0, duration = 1 s\]"),
    ({"duration": 1.0, "method": "Euler"}, "method must be one of"),
    ({"duration": 1.0, "speed_factor": 0.0}, "speed factor"),
])
def test_a_scenario_with_a_wrong_value_is_refused(kwargs, message):
    with pytest.raises(InputError, match=message):
        Scenario(**kwargs)


def _text(**changes) -> str:
    text = EXAMPLE.read_text(encoding="utf-8")
    for key, value in changes.items():
        text = re.sub(rf"(?m)^{key} = .*$", f"{key} = {value}", text)
    return text


def test_check_refuses_a_run_that_would_take_hours():
    text = _text(duration='"50000 s"', switch_off='"10 s"', brake_time='"10 s"')
    for step in (check_problem, run_problem):  # check and run agree, and the run does not start
        with pytest.raises(ProblemFileError, match=r"transient\.duration: a run of 50000 s would take about"):
            step(text)


def test_check_names_a_missing_point_and_a_missing_drive():
    text = _text(point='"nowhere"')
    with pytest.raises(ProblemFileError, match=r"transient\.point: no point 'nowhere'"):
        run_problem(text)
    no_drive = re.sub(r"(?ms)^\[flywheel\].*?(?=^\[frame\])", "", EXAMPLE.read_text(encoding="utf-8"))
    with pytest.raises(ProblemFileError, match=r"needs \[flywheel\]"):
        run_problem(no_drive)


def test_a_table_with_mistakes_lists_each_with_its_path():
    text = _text(duration='"-3 s"', brake_torque='"-5 N*m"')
    with pytest.raises(ProblemFileError) as caught:
        run_problem(text)
    paths = [p for p, _ in caught.value.problems]
    assert any(p.startswith("transient.duration") for p in paths), paths
