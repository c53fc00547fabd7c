"""The thermal duty of many induction motors at once (:mod:`machdyn.dynamics.population_duty`) equals
:func:`machdyn.dynamics.duty.motor_duty` and :func:`machdyn.dynamics.duty.starts_per_hour` of each motor to 1e-12,
for the duties S1, S3 and S6 of IEC 60034-1."""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.dynamics.drives import InductionMotor
from machdyn.dynamics.duty import motor_duty, rotor_heat_per_hour, starts_per_hour
from machdyn.dynamics.population_duty import duty_population


@pytest.mark.parametrize(("duty", "cdf", "h"), [("S1", 1.0, 1.0), ("S3", 0.4, 0.5), ("S6", 0.25, 1.0)])
def test_random_motors_equal_each_motor_s_duty_check(duty, cdf, h):
    rng = np.random.default_rng(5)
    n = 40
    power, slip = rng.uniform(1e3, 30e3, n), rng.uniform(0.02, 0.06, n)
    ratio, eff = rng.uniform(5.0, 30.0, n), rng.uniform(0.8, 1.0, n)
    motors = [InductionMotor(power[i], 50 * np.pi * (1 - slip[i]), 50 * np.pi, 2.5, ratio[i], eff[i])
              for i in range(n)]
    rated = np.array([float(np.max(m.rated_torque)) for m in motors]) * ratio * eff
    load = rated * rng.uniform(0.3, 1.6, n) / np.sqrt(cdf)  # some overloaded in each duty
    t0, loss = rng.uniform(0.0, 50.0, n), rng.uniform(1e3, 2e4, n)
    rated[7] = 0.0  # no rating: refused
    done = duty_population(load, rated, duty, cdf, t0, h, power, slip, loss)
    assert not done["valid"][7] and np.isnan(done["equivalent"][7])
    for i in (i for i in range(n) if i != 7):
        one = motor_duty(motors[i], load[i], duty, cdf, t0[i], rest_cooling=h)
        for key, want in (("equivalent", one.equivalent), ("load_ratio", one.load_ratio),
                          ("rated_for_duty", one.rated_for_duty)):
            assert abs(done[key][i] - want) <= 1e-12 * abs(want), (key, i)
        assert done["overloaded"][i] == bool(one.overload())
        starts = starts_per_hour(rotor_heat_per_hour(power[i], slip[i]), one.load_ratio, loss[i])
        assert abs(done["starts_allowed"][i] - starts) <= 1e-12 * max(starts, 1.0), i
    assert 0 < done["overloaded"].sum() < n - 1
