"""Motor duty (machdyn.dynamics.duty): the equivalent (RMS) torque of a cycle against a published worked example,
the S3/S6 duties of IEC 60034-1 against S1, and the rotor loss of an induction motor's run-up against the energy
balance."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from machdyn.dynamics.drives import InductionMotor
from machdyn.dynamics.duty import (
    equivalent_torque,
    rated_torque_for_duty,
    rms_torque,
    rotor_heat_per_hour,
    run_up_rotor_loss,
    start_rotor_loss,
    starts_per_hour,
)
from machdyn.errors import InputError

ROOT = Path(__file__).resolve().parents[2]

RPM = np.pi / 30.0


def test_rms_torque_of_the_groschopp_worked_example():
    """Groschopp, "Understanding Variable Torque Requirements" (groschopp.com, 28 Sept 2012): a load cycle of
    T = 1, 3, 2, 1 for t = 3, 2, 4, 4 has T_rms = 1.78 (printed to three figures, so the tolerance is half a unit
    of the last printed digit)."""
    assert rms_torque([1.0, 3.0, 2.0, 1.0], [3.0, 2.0, 4.0, 4.0]) == pytest.approx(1.78, abs=0.005)


def test_s3_and_s6_with_duty_factor_one_are_s1():
    for duty in ("S3", "S6"):
        assert equivalent_torque(42.0, duty, 1.0, no_load_torque=7.0) == pytest.approx(42.0, rel=1e-15)
        assert rated_torque_for_duty(50.0, duty, 1.0, no_load_torque=7.0) == pytest.approx(50.0, rel=1e-15)
    assert equivalent_torque(42.0, "S1") == 42.0


def test_s3_rating_is_the_s1_rating_over_root_cdf():
    """Parvalux, "What is an S3 duty cycle?": rated torque in S3 x % = continuous torque / sqrt(x/100)."""
    assert rated_torque_for_duty(10.0, "S3", 0.25) == pytest.approx(20.0, rel=1e-12)
    # S6 with a zero no-load torque is the same thermal budget
    assert rated_torque_for_duty(10.0, "S6", 0.25) == pytest.approx(20.0, rel=1e-12)
    # the no-load periods of S6 spend part of it
    assert rated_torque_for_duty(10.0, "S6", 0.25, no_load_torque=5.0) < 20.0
    # a no-load torque whose share alone, (1 - cdf) T_0^2 = 108, exceeds T_S1^2 = 100, leaves nothing
    assert rated_torque_for_duty(10.0, "S6", 0.25, no_load_torque=12.0) == 0.0


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.floats(-100, 100), st.floats(0.01, 10)), min_size=1, max_size=6),
       st.integers(0, 5), st.floats(0.05, 0.95))
def test_rms_is_invariant_under_splitting_a_segment(segments, which, share):
    torques = [t for t, _ in segments]
    durations = [d for _, d in segments]
    k = which % len(segments)
    split_t = torques[:k] + [torques[k], torques[k]] + torques[k + 1:]
    split_d = durations[:k] + [share * durations[k], (1 - share) * durations[k]] + durations[k + 1:]
    assert rms_torque(split_t, split_d) == pytest.approx(rms_torque(torques, durations), rel=1e-12, abs=1e-12)


@settings(max_examples=40, deadline=None)
@given(st.sampled_from(["S3", "S6"]), st.floats(0.05, 1.0), st.floats(1.0, 100.0), st.floats(0.0, 0.9),
       st.floats(0.1, 1.0))
def test_the_duty_rating_is_where_the_equivalent_torque_meets_the_s1_rating(duty, cdf, rated, idle, cooling):
    """The load torque allowed in S3/S6 heats the motor exactly as its rated torque does in S1."""
    t0 = idle * rated
    allowed = rated_torque_for_duty(rated, duty, cdf, t0, cooling)
    assert equivalent_torque(allowed, duty, cdf, t0, cooling) == pytest.approx(rated, rel=1e-9)


def test_poorer_cooling_at_rest_derates_s3():
    """h = 1 is the Parvalux rule; a motor that cools less at rest (h < 1) carries less; with h -> small the rest
    no longer cools and S3 tends to S1."""
    assert equivalent_torque(10.0, "S3", 0.4, rest_cooling=1.0) == pytest.approx(10.0 * 0.4**0.5, rel=1e-12)
    assert equivalent_torque(10.0, "S3", 0.4, rest_cooling=0.5) == pytest.approx(10.0 * (0.4 / 0.7) ** 0.5,
                                                                                  rel=1e-12)
    assert rated_torque_for_duty(10.0, "S3", 0.4, rest_cooling=0.5) < rated_torque_for_duty(10.0, "S3", 0.4)
    assert rated_torque_for_duty(10.0, "S3", 0.4, rest_cooling=1e-9) == pytest.approx(10.0, rel=1e-6)


def test_rotor_loss_of_a_free_run_up_is_the_kinetic_energy():
    """Energy balance of a run-up at no load: the rotor dissipates T (w_s - w) and J w' = T, so its loss tends to
    1/2 J w_s^2, whatever the torque-speed curve (here the Kloss curve of a 4 kW motor, integrated numerically)."""
    from scipy.integrate import solve_ivp

    motor = InductionMotor(4000.0, 1440 * RPM, 1500 * RPM, 2.5)
    j, ws = 0.5, 1500 * RPM

    def rhs(_t, y):
        return [float(np.ravel(motor.torque_at(y[0]))[0]) / j]

    sol = solve_ivp(rhs, (0.0, 30.0), [0.0], method="LSODA", rtol=1e-10, atol=1e-10, dense_output=True)
    t = np.linspace(0.0, 30.0, 200_001)
    w = sol.sol(t)[0]
    torque = np.ravel(motor.torque_at(w))
    loss = run_up_rotor_loss(t, w, torque, ws)
    assert loss == pytest.approx(0.5 * j * ws**2, rel=1e-4)
    # the closed form for a constant mean torque and no load gives the same
    assert start_rotor_loss(j, ws, float(np.mean(torque[:1000]))) == pytest.approx(0.5 * j * ws**2, rel=1e-12)


def test_rotor_loss_against_a_load_grows_by_tm_over_tm_minus_tl():
    """A constant motor torque T_M against a constant load T_L: w = (T_M - T_L) t / J up to w_s; the integral of
    T_M (w_s - w) dt is the closed form (the trapezoidal rule is exact on a linear integrand)."""
    j, ws, tm, tl = 2.0, 150.0, 40.0, 10.0
    t_end = j * ws / (tm - tl)
    t = np.linspace(0.0, t_end, 11)
    w = (tm - tl) * t / j
    loss = run_up_rotor_loss(t, w, np.full_like(t, tm), ws)
    assert loss == pytest.approx(start_rotor_loss(j, ws, tm, tl), rel=1e-12)
    assert loss == pytest.approx(0.5 * j * ws**2 * (1 + tl / (tm - tl)), rel=1e-12)


def test_starts_per_hour_from_the_rotor_heat():
    heat = rotor_heat_per_hour(4000.0, 0.04)
    assert heat == pytest.approx(3600 * 4000 * 0.04 / 0.96, rel=1e-12)  # 600 kJ an hour
    assert starts_per_hour(heat, 0.0, 1000.0) == pytest.approx(600.0, rel=1e-12)
    assert starts_per_hour(heat, 0.5, 1000.0) == pytest.approx(450.0, rel=1e-12)
    assert starts_per_hour(heat, 1.2, 1000.0) == 0.0


@pytest.mark.parametrize("call, message", [
    (lambda: equivalent_torque(1.0, "S2", 0.5), "duty must be one of"),
    (lambda: equivalent_torque(1.0, "S3", 0.0), "cyclic_duration_factor must be in"),
    (lambda: rms_torque([1.0], [0.0]), "not all 0"),
    (lambda: equivalent_torque(1.0, "S3", 0.5, rest_cooling=0.0), "rest_cooling must be in"),
    (lambda: start_rotor_loss(1.0, 100.0, 5.0, 6.0), "must exceed the load torque"),
])
def test_bad_duty_input_names_the_rule(call, message):
    with pytest.raises(InputError, match=message):
        call()


def test_duty_results_are_in_the_catalogue():
    from machdyn.kinds import catalogue

    keys = {q.key: q for q in catalogue()}
    for key in ("flywheel.motor_duty_load", "flywheel.motor_duty_rated_torque", "flywheel.motor_start_rotor_loss",
                "flywheel.motor_starts_per_hour"):
        assert key in keys and keys[key].producer == "flywheel"


def test_rotor_loss_of_the_simulated_start_up_is_the_energy_balance(bench_machine, motor):
    """The light bench four-bar (gravity only: no work over a turn) run up by its 15:1 motor on a 0.5 kg*m^2
    flywheel: the rotor loss integrated along the start-up, up to the time to steady running, is the energy
    balance J (w_s w_e - w_e^2/2) of an inertia J = flywheel + mean reduced inertia brought from rest to w_e (crank
    units, gear efficiency 1). Tolerance 2 %: the linkage's own inertia and weight vary over the turn."""
    from machdyn.dynamics import start_up
    from machdyn.dynamics.duty import motor_duty

    flywheel = 0.5
    run = start_up(bench_machine, motor, flywheel)
    duty = motor_duty(motor, float(run.steady.rms_drive_torque), start_up=run)
    tr = run.trajectory
    t_end = float(np.ravel(run.time_to_steady)[0])
    w_end = float(np.interp(t_end, np.ravel(tr.t), np.ravel(tr.omega)))
    ws = 1500 * RPM / 15.0
    j = flywheel + float(np.mean(bench_machine.inertia(np.linspace(0, 2 * np.pi, 721))))
    assert duty.start_loss == pytest.approx(j * (ws * w_end - 0.5 * w_end**2), rel=0.02)
    # the starts per hour follow from the rated rotor loss left by the running load
    heat = rotor_heat_per_hour(10.0, 1.0 - 1440 / 1500)
    assert duty.starts_allowed == pytest.approx(heat * (1 - duty.load_ratio**2) / duty.start_loss, rel=1e-12)


def test_the_report_draws_the_motor_duty_with_its_rms_and_rated_lines(tmp_path):
    """The flywheel section shows the motor's duty as a chart: its torque over one steady cycle, the RMS line at
    the run's RMS load and the rated line at the motor's rated torque at the crank (the values of the duty check,
    which the report reads, not computes)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from machdyn.report.dynamics import plot_motor_duty, sections
    from machdyn.runner import run_problem

    outcome = run_problem(ROOT / "examples" / "crank_press.toml").outcomes["flywheel"]
    run = outcome.results
    fig, ax = plt.subplots()
    try:
        plot_motor_duty(run, ax)
        levels = sorted(float(line.get_ydata()[0]) for line in ax.lines[1:])
    finally:
        plt.close(fig)
    assert levels == pytest.approx(sorted([run.duty.load_rms, run.duty.rated]), rel=1e-12)
    assert run.duty.load_rms == pytest.approx(float(run.steady.rms_drive_torque), rel=1e-12)
    html = "".join(body for _, body in sections(outcome))
    assert "Motor duty S1" in html
