"""Tabulated turning-moment diagrams: the integration rule, cycles longer than a revolution, bad tables."""

import numpy as np
import pytest

from machdyn.dynamics import diagram_energy_fluctuation, indicator_crank_effort, torque_table
from machdyn.errors import InputError


def test_closed_table_mean_is_exact_where_a_plain_average_is_not():
    phi = np.radians(np.arange(0, 361, 10))
    torque = 5000 + 1500 * np.sin(3 * phi) + 900 * np.cos(phi)   # mean 5000 N*m exactly
    table = torque_table(phi, torque)
    assert table.mean()[0] == pytest.approx(5000.0, rel=1e-12)
    plain = torque.mean()   # 37 samples, 0° counted twice
    assert abs(plain / 5000.0 - 1) > 3e-3


def test_spline_table_finds_the_energy_extremes_between_samples():
    phi = np.radians(np.arange(0, 361, 10))
    table = torque_table(phi, 5000 + 600 * np.sin(2 * phi) - 500 * np.sin(phi))
    # exact: max - min of 500 cos - 300 cos 2 = 404.1667 - (-800)
    assert diagram_energy_fluctuation(table)[0] == pytest.approx(1204.1667, rel=2e-4)


def test_four_stroke_cycle_spans_720_degrees():
    angles = np.radians([0, 180, 270, 360, 450, 540, 720])
    torque = [0, 0, -1000, 0, 3000, 0, 0]
    table = torque_table(angles, torque, interpolation="linear")
    assert table.period == pytest.approx(4 * np.pi)
    assert table.cycle_integral()[0] == pytest.approx(0.5 * np.pi * (3000 - 1000))
    # the integral grows by one cycle's work per period
    assert table.integral(4 * np.pi + 1.0) - table.integral(1.0) == pytest.approx(table.cycle_integral()[0])


def test_indicator_crank_effort_matches_virtual_work():
    phi = np.linspace(0.1, 3.0, 7)
    r, l_rod, area, p = 0.1, 0.4, 0.01, 2e6
    h = 1e-6

    def travel(a):
        return r * (1 - np.cos(a)) + l_rod - np.sqrt(l_rod**2 - (r * np.sin(a)) ** 2)

    fd = (travel(phi + h) - travel(phi - h)) / (2 * h)
    assert np.allclose(indicator_crank_effort(phi, p, area, r, l_rod), p * area * fd, rtol=1e-7)


@pytest.mark.parametrize("angles, torque, message", [
    ([0.0, 1.0, 1.0], [1, 2, 3], "increase"),
    ([0.0, 1.0], [1, 2, 3], "one torque per angle"),
    ([0.0, np.pi, 2 * np.pi], [1.0, 2.0, 3.0], "end with the torque it starts with"),
    ([0.0, 1.0], [1.0, np.nan], "finite"),
])
def test_bad_tables_are_refused(angles, torque, message):
    with pytest.raises(InputError, match=message):
        torque_table(angles, torque)
