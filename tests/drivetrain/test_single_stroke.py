"""The single-stroke cycle of a press: clutch in, stroke, clutch out and brake, the flywheel's recovery.

Checked against closed forms where the machine's inertia is constant (the clutch slip of Shigley's MED, 8th ed.,
§16-8, with constant motor and load torques; Newton's constant-deceleration stop), by the work–energy balance
of a machine whose inertia varies with the crank angle, and through the problem file and the command line."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.drivetrain.clutch import engage
from machdyn.drivetrain.single_stroke import single_stroke, single_stroke_duty
from machdyn.dynamics.drives import InductionMotor
from machdyn.errors import InputError

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "crank_press_drive.toml"


class _Inertia:
    """J(φ) = J0 + a·cos 2φ and its derivative: the shape of a slider-crank's reduced inertia."""

    def __init__(self, j0: float, a: float = 0.0) -> None:
        self.j0, self.a = j0, a

    def __call__(self, phi):
        return np.atleast_1d(self.j0 + self.a * np.cos(2 * np.asarray(phi, dtype=float)))

    def derivative(self, phi):
        return np.atleast_1d(-2 * self.a * np.sin(2 * np.asarray(phi, dtype=float)))


class _Machine:
    """The interface of :class:`~machdyn.dynamics.equivalent.EquivalentMachine` the cycle uses: J(φ) and the
    reduced moment M(φ, ω) of the loads (a constant resisting torque, or a punching window)."""

    def __init__(self, j0: float, a: float = 0.0, load: float = 0.0, window: tuple[float, float] | None = None):
        self.inertia = _Inertia(j0, a)
        self.load, self.window = load, window

    def moment_at(self, phi, _omega):
        phi = float(np.ravel(phi)[0])
        if self.window is None:
            return np.atleast_1d(-self.load)
        inside = self.window[0] <= np.mod(phi, 2 * np.pi) <= self.window[1]
        return np.atleast_1d(-self.load if inside else 0.0)


def test_the_clutch_slip_of_a_constant_inertia_machine_is_shigleys_closed_form():
    j1, j2, w0, tc, t1, t2 = 4.0, 1.5, 30.0, 120.0, 10.0, 15.0
    k = single_stroke(_Machine(j2, load=t2), lambda _w: t1, drive_inertia=j1, driven_inertia=0.0, speed=w0,
                      slip_torque=tc, brake_torque=400.0, start_angle=0.0, brake_angle=5.0)
    closed = engage(j1, w0, j2, 0.0, tc, driving_torque=t1, load_torque=t2)
    # the event locates the end of the slip to the integrator's tolerance (rtol 1e-9)
    assert k.slip_time == pytest.approx(closed.slip_time, rel=1e-6)
    # the dissipated energy is a trapezoid sum over steps of at most 10 ms: second order, 1e-4 of the energy
    assert k.clutch_energy == pytest.approx(closed.dissipated, rel=1e-4)


def test_the_brake_stop_of_a_constant_inertia_machine_is_newtons_constant_deceleration():
    j2, tb = 2.0, 300.0
    k = single_stroke(_Machine(j2), lambda _w: 5.0, drive_inertia=10.0, driven_inertia=0.5, speed=20.0,
                      slip_torque=200.0, brake_torque=tb, start_angle=0.0, brake_angle=4.0)
    # the crank speed when the brake closes, from the start of the braking history
    w_at_brake = float(k.omega[k.phase == "braking"][0])
    j = j2 + 0.5
    assert k.stop_time == pytest.approx(j * w_at_brake / tb, rel=1e-6)
    assert k.stop_angle == pytest.approx(j * w_at_brake**2 / (2 * tb), rel=1e-6)
    assert k.brake_energy == pytest.approx(0.5 * j * w_at_brake**2, rel=1e-6)


def test_the_found_brake_angle_brings_the_crank_to_rest_at_the_start_angle_one_turn_on():
    machine = _Machine(1.2, a=0.3, load=800.0, window=(4.0, 4.6))
    k = single_stroke(machine, lambda w: 60.0 * (25.0 - w), drive_inertia=30.0, driven_inertia=0.2, speed=24.0,
                      slip_torque=900.0, brake_torque=600.0, start_angle=math.pi / 2)
    assert abs(k.overrun) < 1e-7
    assert math.pi / 2 + math.pi < k.brake_angle < math.pi / 2 + 2 * math.pi
    assert k.omega[-1] == 0.0 and k.phase[-1] in ("braking", "recovery")


def test_work_of_motor_and_loads_equals_the_kinetic_energy_change_plus_clutch_and_brake_losses():
    machine = _Machine(1.2, a=0.3, load=800.0, window=(4.0, 4.6))
    j1 = 30.0

    def motor(w):
        return 60.0 * (25.0 - w)  # an induction motor's slip line, at the crank

    k = single_stroke(machine, motor, drive_inertia=j1, driven_inertia=0.2, speed=24.0, slip_torque=900.0,
                      brake_torque=600.0, start_angle=0.0)
    end = np.flatnonzero(k.t <= k.stroke_time)[-1]
    kinetic_drive = 0.5 * j1 * (k.omega_drive[end] ** 2 - 24.0**2)  # the crank is at rest at both ends
    losses = k.clutch_energy + k.brake_energy
    residual = k.motor_work + k.load_work - kinetic_drive - losses
    scale = abs(k.motor_work) + abs(k.load_work) + losses
    # trapezoid sums over steps of at most 10 ms with switches inside some steps: 1e-3 of the energies moved
    assert abs(residual) < 1e-3 * scale


def test_a_clutch_too_weak_for_the_load_is_refused_by_name():
    with pytest.raises(InputError, match="clutch does not turn the machine"):
        single_stroke(_Machine(1.0, load=500.0), lambda _w: 10.0, drive_inertia=5.0, driven_inertia=0.0, speed=20.0,
                      slip_torque=100.0, brake_torque=300.0, start_angle=0.0, max_time=5.0)


def test_the_press_example_reports_its_single_stroke_its_motor_duty_and_writes_its_time_history(tmp_path):
    result = CliRunner().invoke(app, ["run", str(EXAMPLE), "--out", str(tmp_path)])
    assert result.exit_code == 0, result.output
    assert "Single stroke: most strokes a minute" in result.output
    import pandas as pd

    history = pd.read_csv(tmp_path / "single_stroke.csv")
    assert [c.split(" [")[0] for c in history.columns] == ["time", "crank_angle", "crank_speed", "drive_side_speed",
                                                            "clutch_torque", "motor_torque"]
    assert history["time [s]"].is_monotonic_increasing
    assert history["clutch_torque [N*m]"].abs().max() > 0
    scalars = json.loads((tmp_path / "results.json").read_text())["scalars"]
    load = scalars["single_stroke.motor_load"]["value"]
    assert 0.0 < load < 1.0
    # the example's motor runs in S1, where the torque allowed while loaded is the rated torque
    rated = scalars["flywheel.motor_duty_rated_torque"]["value"]
    assert scalars["single_stroke.motor_rms_torque"]["value"] == pytest.approx(load * rated, rel=1e-9)
    # strokes at 20 a minute leave the motor idling: less loaded than running the press continuously
    assert load < scalars["flywheel.motor_rms_load"]["value"]


def test_a_stroke_rate_the_drive_cannot_reach_is_a_failed_check(tmp_path):
    text = EXAMPLE.read_text().replace("strokes_per_minute = 20 ", "strokes_per_minute = 45 ")
    path = tmp_path / "press.toml"
    path.write_text(text)
    result = CliRunner().invoke(app, ["run", str(path), "--out", str(tmp_path / "out")])
    assert result.exit_code == 3, result.output
    assert "strokes a minute" in result.output and "clutch.strokes_per_minute = 45" in result.output


def _pressing(motor, speed=24.0, drive_inertia=30.0):
    return single_stroke(_Machine(1.2, a=0.3, load=800.0, window=(4.0, 4.6)), motor, drive_inertia=drive_inertia,
                         driven_inertia=0.2, speed=speed, slip_torque=900.0, brake_torque=600.0, start_angle=0.0)


def test_the_motor_rms_of_a_constant_torque_drive_is_that_torque():
    k = _pressing(lambda _w: 55.0)
    assert k.motor_rms() == pytest.approx(55.0, rel=1e-12)
    assert k.motor_rms(3 * (k.stroke_time + k.recovery_time)) == pytest.approx(55.0, rel=1e-12)


def test_the_motor_rms_over_a_period_is_the_mean_square_of_the_stroke_and_the_idling():
    """RMS over the stroke and recovery, checked on the time history resampled at 1 ms (trapezoid, second order:
    1e-3), and for a longer period the identity rms(P)^2 P = rms(busy)^2 busy + T_idle^2 (P - busy) exactly."""
    k = _pressing(lambda w: 60.0 * (25.0 - w))
    busy = k.stroke_time + k.recovery_time
    grid = np.linspace(0.0, busy, int(busy / 1e-3) + 1)
    torque = np.interp(grid, k.t, k.motor_torque)
    assert k.motor_rms() == pytest.approx(np.sqrt(np.trapezoid(torque**2, grid) / busy), rel=1e-3)
    assert k.idle_torque == pytest.approx(60.0, rel=1e-12)
    period = 2.5 * busy
    assert k.motor_rms(period) ** 2 * period == pytest.approx(k.motor_rms() ** 2 * busy + 60.0**2 * (period - busy),
                                                              rel=1e-9)
    with pytest.raises(InputError, match="shorter"):
        k.motor_rms(0.5 * busy)


def test_the_motor_torque_history_carries_the_motor_work():
    """The motor's work over the stroke is the integral of its torque times the driving side's speed (the
    history's own columns, same trapezoid)."""
    k = _pressing(lambda w: 60.0 * (25.0 - w))
    upto = k.t <= k.stroke_time
    assert np.trapezoid((k.motor_torque * k.omega_drive)[upto], k.t[upto]) == pytest.approx(k.motor_work, rel=1e-12)


def test_a_motor_too_small_for_repeated_strokes_is_overloaded_by_name():
    """The same stroke, an induction motor of 0.2 kW at 1440/1500 rpm through a 6.5:1 drive: its rated torque at
    the crank, 0.2e3/(1440 rpm) x 6.5 = 8.6 N*m, against the RMS over strokes back to back. A flywheel of 8 kg*m^2
    gives up 480 J per stroke at a speed drop of ~25 %, far past the motor's 4 % rated slip: it recovers near its
    breakdown torque, overloaded."""
    motor = InductionMotor(rated_power=200.0, rated_speed=1440 * np.pi / 30, synchronous_speed=1500 * np.pi / 30,
                           ratio=6.5)
    rated = 200.0 / (1440 * np.pi / 30) * 6.5
    k = _pressing(lambda w: np.ravel(motor.torque_at(w))[0], speed=1500 * np.pi / 30 / 6.5, drive_inertia=8.0)
    duty = single_stroke_duty(k, motor, strokes_per_minute=None)
    assert duty.rated == pytest.approx(rated, rel=1e-12)
    assert duty.load_rms == pytest.approx(k.motor_rms(), rel=1e-12)
    assert duty.load_ratio > 1.0
    assert "overloaded" in duty.overload()[0]
    # slower strokes leave the motor idling between them: a lower RMS
    slow = single_stroke_duty(k, motor, strokes_per_minute=0.25 * 60.0 / (k.stroke_time + k.recovery_time))
    assert slow.load_rms < duty.load_rms
