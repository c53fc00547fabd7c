"""Published worked flywheel examples reproduced with machdyn.dynamics.

Source of every example: R. S. Khurmi and J. K. Gupta, *Theory of Machines*, S. Chand & Co., chapter 16
"Turning Moment Diagrams and Flywheel", the example and page named in each test, with the answers printed in the
book as reproduced by the FOSSEE Python Textbook Companion of that book
(github.com/FOSSEE/Python-Textbook-Companions, file Theory_Of_Machines/ch16.ipynb). Each answer is recomputed here
from the problem's data through machdyn (torque tables, energy fluctuation, sizing, simulation); the tolerance of
each comparison is the rounding of the printed answer.
"""

import numpy as np
import pytest

from machdyn.dynamics import (
    ConstantTorque,
    EquivalentMachine,
    diagram_energy_fluctuation,
    flywheel_inertia_classic,
    rim_flywheel,
    rim_speed_limit,
    size_flywheel,
    steady_state,
    torque_table,
)

RPM = np.pi / 30.0


def test_khurmi_16_6_torque_cycle_of_three_revolutions():
    """Ex. 16.6 (p. 584 in the companion): the machine torque rises from 750 to 3000 N*m over half a revolution,
    stays for one revolution, falls to 750 N*m over half a revolution and stays for one revolution (a cycle of
    1080°); constant driving torque; flywheel 500 kg at 600 mm radius of gyration; 250 rpm.
    Printed: power 49.087 kW, coefficient of fluctuation of speed 0.072."""
    deg = np.radians([0.0, 180.0, 540.0, 720.0, 1080.0])
    machine_torque = torque_table(deg, [750.0, 3000.0, 3000.0, 750.0, 750.0], interpolation="linear")
    assert machine_torque.period == pytest.approx(6 * np.pi)
    omega = 250 * RPM
    power = machine_torque.mean()[0] * omega
    assert power / 1000 == pytest.approx(49.087, abs=5e-4)  # printed to 1 W
    inertia = 500 * 0.6**2
    delta_e = diagram_energy_fluctuation(machine_torque)[0]
    cs = delta_e / (inertia * omega**2)
    assert cs == pytest.approx(0.072, abs=5e-4)  # printed to three decimals (0.0716)
    # the same machine simulated: load = -machine torque, a constant drive torque equal to its mean
    machine = EquivalentMachine.from_tables(torque_table(deg, [-750.0, -3000.0, -3000.0, -750.0, -750.0],
                                                         interpolation="linear"), inertia)
    ss = steady_state(machine, ConstantTorque(float(machine_torque.mean()[0])), mean_speed=omega)
    # with a constant inertia, delta E = J (w_max^2 - w_min^2)/2 = J w_mean^2 delta holds exactly
    assert ss.delta == pytest.approx(cs, rel=1e-6)


def test_khurmi_16_9_four_stroke_engine_triangular_diagram():
    """Ex. 16.9 (p. 582): single-cylinder four-stroke gas engine, 20 kW at 300 rpm; expansion work three times
    the compression work, suction and exhaust negligible, triangular diagrams; total fluctuation of speed ±2 %.
    Printed: moment of inertia of the flywheel 255.4 kg*m^2."""
    n, power, cs = 300.0, 20e3, 0.04
    work = power * 60 / (n / 2)  # per cycle of two revolutions
    w_exp = 1.5 * work  # W_exp - W_exp/3 = W
    t_exp, t_comp = 2 * w_exp / np.pi, 2 * (w_exp / 3) / np.pi  # triangle heights over half a revolution
    angles = np.radians([0.0, 180.0, 270.0, 360.0, 450.0, 540.0, 720.0])
    engine = torque_table(angles, [0.0, 0.0, -t_comp, 0.0, t_exp, 0.0, 0.0], interpolation="linear")
    assert engine.period == pytest.approx(4 * np.pi)
    assert engine.cycle_integral()[0] == pytest.approx(work, rel=1e-12)
    inertia = flywheel_inertia_classic(diagram_energy_fluctuation(engine)[0], n * RPM, cs)
    assert inertia == pytest.approx(255.4, abs=0.05)  # printed to 0.1 kg*m^2
    # the sizing routine on the same diagram (constant inertia: exact = classic)
    machine = EquivalentMachine.from_tables(engine, 0.0)
    sizing = size_flywheel(machine, n * RPM, cs)
    # both search the extremes on a grid of 8192 points per cycle: error ~1e-7 relative
    assert sizing.exact[0] == pytest.approx(inertia, rel=1e-6)
    assert sizing.classic_total[0] == pytest.approx(inertia, rel=1e-6)


def test_khurmi_16_12_engine_and_resisting_torque_both_varying():
    """Ex. 16.12 (p. 587): engine torque 5000 + 600 sin 2θ N*m, resisting torque 5000 + 500 sin θ N*m;
    flywheel 500 kg at 0.4 m radius of gyration; 150 rpm. Printed: fluctuation of energy 1204 N*m, total
    fluctuation of speed 6.1 %, largest acceleration 3.46 rad/s^2 at θ = 35°."""
    theta = np.radians(np.arange(0.0, 361.0, 10.0))  # the diagram tabulated every 10°, as read off a plot
    net = torque_table(theta, 600 * np.sin(2 * theta) - 500 * np.sin(theta))
    delta_e = diagram_energy_fluctuation(net)[0]
    # spline through 10° samples: error ~1e-4 relative; printed to 1 N*m
    assert delta_e == pytest.approx(1204, abs=1.0)
    inertia, omega = 500 * 0.4**2, 150 * RPM
    assert delta_e / (inertia * omega**2) * 100 == pytest.approx(6.1, abs=0.05)  # printed to 0.1 %
    # simulated: the flywheel alone under both torques; speed at the mean 150 rpm
    ss = steady_state(EquivalentMachine.from_tables(net, inertia), ConstantTorque(0.0), mean_speed=omega)
    assert ss.delta * 100 == pytest.approx(6.1, abs=0.05)
    # the book's stationary points of the acceleration in the first half-turn: a maximum of 3.46 rad/s^2 near
    # 35° and a retardation of 12.2 rad/s^2 near 127.6°
    deg = np.degrees(ss.phi)
    first, second = deg <= 90.0, (deg > 90.0) & (deg <= 180.0)
    i = np.flatnonzero(first)[np.argmax(ss.acceleration[first])]
    k = np.flatnonzero(second)[np.argmin(ss.acceleration[second])]
    assert ss.acceleration[i] == pytest.approx(3.46, abs=0.005)  # printed to 0.01 rad/s^2
    assert deg[i] == pytest.approx(35.0, abs=1.0)  # printed in whole degrees
    assert -ss.acceleration[k] == pytest.approx(12.2, abs=0.05)  # printed to 0.1 rad/s^2
    assert deg[k] == pytest.approx(127.6, abs=0.5)


def test_khurmi_16_14_flywheel_rim_from_the_rim_speed_limit():
    """Ex. 16.14 (p. 592): 800 rpm, fluctuation of speed ±2 %, hoop stress 7 MPa, density 7200 kg/m^3, width
    five times the thickness, fluctuation of energy 450 mm^2 at 500 N*m x pi/30 per mm^2 (23 562 N*m).
    Printed: rim diameter 0.744 m, thickness 84 mm, width 424 mm."""
    omega, cs, rho = 800 * RPM, 0.04, 7200.0
    delta_e = 23562.0
    v = rim_speed_limit(7e6, rho)
    inertia = flywheel_inertia_classic(delta_e, omega, cs)
    part = rim_flywheel(inertia, omega, omega * (1 + cs / 2), rim_speed=v, width_to_thickness=5.0, density=rho)
    assert part.diameter == pytest.approx(0.744, abs=5e-4)  # printed to 1 mm
    # printed as whole millimetres, cut off (84.86 -> 84, 424.3 -> 424): within 1 mm
    assert 84.0 <= part.thickness * 1000 < 85.0
    assert 424.0 <= part.width * 1000 < 425.0
    assert part.within_limit is False or part.rim_speed > v  # at the highest speed the rim runs above v


def test_khurmi_16_1_speeds_from_the_flywheel_and_the_energy_fluctuation():
    """Ex. 16.1 (p. 573): flywheel of 6.5 t, radius of gyration 1.8 m, maximum fluctuation of energy 56 kN*m,
    mean speed 120 rpm; printed: N1 = 121 rpm, N2 = 119 rpm (rounded to whole rpm). Simulated here: a turning
    moment 28 sin(theta) kN*m (its energy swings by 2 x 28 = 56 kN*m) on the constant inertia m k^2."""
    inertia = 6500.0 * 1.8**2
    phi = np.linspace(0.0, 2 * np.pi, 361)
    machine = EquivalentMachine.from_tables(torque_table(phi, 28e3 * np.sin(phi)), inertia)
    # spline through 1° steps
    assert float(diagram_energy_fluctuation(machine.moment)[0]) == pytest.approx(56e3, rel=1e-6)
    ss = steady_state(machine, ConstantTorque(0.0), 0.0, mean_speed=120 * RPM)
    n1, n2 = float(np.max(ss.omega)) / RPM, float(np.min(ss.omega)) / RPM
    assert abs(n1 - 121) < 0.5 and abs(n2 - 119) < 0.5  # the book's whole rpm
    # for a constant inertia the classic formula is exact: delta = dE / (I w^2)
    assert float(ss.delta) == pytest.approx(56e3 / (inertia * (120 * RPM) ** 2), rel=1e-5)


def test_khurmi_16_3_flywheel_mass_from_the_coefficient_of_fluctuation_of_energy():
    """Ex. 16.3 (p. 574): steam engine 300 kW at 90 rpm, coefficient of fluctuation of energy 0.1, speed within
    ±0.5 % of the mean, radius of gyration 2 m; printed: m = 5628 kg (the companion prints the integer part)."""
    w = 90 * RPM
    work_per_cycle = 300e3 * 2 * np.pi / w
    inertia = flywheel_inertia_classic(0.1 * work_per_cycle, w, 0.01)
    assert 5628.0 <= inertia / 2.0**2 < 5629.0


@pytest.mark.parametrize("return_apex_deg", [250.0, 270.0, 290.0])
def test_khurmi_16_7_double_acting_steam_engine_triangles(return_apex_deg):
    """Ex. 16.7 (p. 578): turning moment on the outward stroke a triangle 0-180° of height 2000 N*m with its apex at
    80° (4 pi/9), on the return stroke a triangle 180-360° of height 1500 N*m; 100 rpm, speed within ±0.75 %,
    radius of gyration 1.75 m. Printed: coefficient of fluctuation of energy 18 % (integer part), m = 197.3 kg,
    minimum speed at 35° and maximum at 136° from the inner dead centre (whole degrees). The companion gives the
    return triangle's height, not its apex: the answer does not depend on it (three apex positions are checked)."""
    angles = np.radians([0.0, 80.0, 180.0, return_apex_deg, 360.0])
    torque = [0.0, 2000.0, 0.0, 1500.0, 0.0]
    engine = torque_table(angles, torque, interpolation="linear")
    mean = float(engine.mean()[0])
    assert mean == pytest.approx(875.0, rel=1e-12)
    machine = EquivalentMachine.from_tables(torque_table(angles, np.array(torque) - mean, interpolation="linear"))
    w = 100 * RPM
    sizing = size_flywheel(machine, w, 0.015)
    de = float(sizing.energy_fluctuation[0])
    assert int(100 * de / (mean * 2 * np.pi)) == 18
    mass = float(sizing.exact[0]) / 1.75**2
    assert mass == pytest.approx(197.3, abs=0.05)  # printed to 0.1 kg
    ss = steady_state(machine, ConstantTorque(0.0), float(sizing.exact[0]), mean_speed=w)
    assert float(ss.delta) == pytest.approx(0.015, rel=1e-4)
    slow = np.degrees(ss.phi[np.argmin(ss.omega)])
    fast = np.degrees(ss.phi[np.argmax(ss.omega)])
    # exactly 80 - 45 = 35° and 80 + 56.25 = 136.25° (printed 35 and 136); the simulation's nodes are 1/2° apart
    assert abs(slow - 35.0) <= 0.5 and abs(fast - 136.25) <= 0.5
