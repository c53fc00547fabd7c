"""Parts sizing, clutch engagement, braking and motor duty against published worked examples with printed
answers."""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.drivetrain.bearings import catalogue_rating, mean_effective_load, weibull_reliability
from machdyn.drivetrain.clutch import engage, stop_constant
from machdyn.drivetrain.strength import goodman_safety
from machdyn.dynamics.duty import equivalent_torque, rated_torque_for_duty, rms_torque


def test_shigley_problem_11_1_ball_bearing_rating_and_reliability():
    """Budynas & Nisbett, *Shigley's Mechanical Engineering Design*, 8th ed., instructor's solutions manual,
    problem 11-1: 30 000 h at 300 rpm (x_D = 540), F_D = 1.2 x 1.898 = 2.278 kN, R = 0.90 -> C10 = 18.59 kN;
    the chosen 02-30 mm bearing (C10 = 19.5 kN) has R = 0.919. Printed to 4 and 3 digits: tolerance half a unit
    of the last printed digit."""
    x_d = 30_000 * 300 * 60 / 1e6
    assert x_d == pytest.approx(540.0)
    assert catalogue_rating(1.898e3, x_d, 0.90, application_factor=1.2) / 1e3 == pytest.approx(18.59, abs=0.005)
    assert weibull_reliability(19.5e3, 1.898e3, x_d, application_factor=1.2) == pytest.approx(0.919, abs=0.0005)


def test_shigley_problem_11_3_roller_bearing_rating_and_reliability():
    """Shigley's MED, 8th ed., solutions manual, problem 11-3: straight roller bearing, x_D = 1440,
    F_D = 1.4 x 1650 lbf = 10.279 kN. The manual takes the Weibull denominator x0 + (theta - x0)(ln 1/0.9)^(1/b) =
    0.9935 as 1 and prints C10 = 91.1 kN: the exact denominator gives 0.2 % more, so 0.3 % tolerance. The
    chosen 03-55 mm bearing (C10 = 102 kN) has R = 0.942 (printed, 3 digits)."""
    assert catalogue_rating(10.279e3, 1440.0, 0.90, kind="roller") / 1e3 == pytest.approx(91.1, rel=3e-3)
    assert weibull_reliability(102e3, 10.279e3, 1440.0, kind="roller") == pytest.approx(0.942, abs=0.0005)


def test_mott_example_14_6_mean_effective_load():
    """R. L. Mott, *Machine Elements in Mechanical Design*, 4th ed., Example Problem 14-6 (p. 626): a 6308 ball
    bearing carries 650 lb for 30 min, 750 lb for 10 min and 250 lb for 20 min of each hour at 600 rpm;
    Fm = 597 lb (printed to the pound: tolerance 0.5 lb)."""
    assert mean_effective_load([650.0, 750.0, 250.0], [30.0, 10.0, 20.0]) == pytest.approx(597.0, abs=0.5)


def test_marks_calculations_goodman_safety_factor_on_a_proportional_load_line():
    """T. H. Brown, *Marks' Calculations for Machine Design*, McGraw-Hill 2005, ch. 7 (strength of machines),
    p. 298, step 17: sigma_a = 80.6 MPa, sigma_m = 202.3 MPa, Se = 229.1 MPa, Sut = 595 MPa on the modified
    Goodman line with the load line through the origin, printed as 229.1 / ((202.3)(0.385 + 0.398)) with the
    ratios rounded to 3 digits: tolerance 0.1 %."""
    printed = 229.1 / (202.3 * (0.385 + 0.398))
    sigma_max, sigma_min = 202.3e6 + 80.6e6, 202.3e6 - 80.6e6
    assert goodman_safety(sigma_max, sigma_min, 229.1e6, 595e6) == pytest.approx(printed, rel=1e-3)


# --- clutch, brake and motor duty ------------------------------------------------------------------------------

RPM = np.pi / 30.0   # [rad/s] per rev/min
HP = 745.7           # [W] per mechanical horsepower


@pytest.mark.parametrize("slip_torque", [5.0, 500.0])
def test_openstax_example_11_7_coupled_flywheels(slip_torque):
    """W. Moebs, S. J. Ling, J. Sanny, *University Physics Volume 1*, OpenStax 2016, §11.3, Example 11.7
    "Coupled Flywheels": a flywheel at 600 rev/min and a second one at rest with three times its moment of
    inertia are brought to one speed by friction; printed: omega = 1/4 omega0 = 150 rev/min = 15.7 rad/s, and
    "3/4 of the initial kinetic energy is lost to the coupling". The example gives no friction torque: the
    common speed and the loss do not depend on it (two torques are tried). 150 rev/min and 3/4 are exact; 15.7
    rad/s is printed to 3 digits (tolerance half a unit of its last digit)."""
    j0 = 1.3   # [kg m^2], any value: the example states only the ratio
    e = engage(j0, 600 * RPM, 3 * j0, 0.0, slip_torque)
    assert e.common_speed / RPM == pytest.approx(150.0, rel=1e-12)
    assert e.common_speed == pytest.approx(15.7, abs=0.05)
    assert e.dissipated / (0.5 * j0 * (600 * RPM) ** 2) == pytest.approx(0.75, rel=1e-12)


def test_fossee_764_example_11_14_clutch_engagement_time_and_heat():
    """Friction clutches, Example 11.14 of the textbook worked in FOSSEE Scilab Textbook Companion no. 764
    (FOSSEE/Scilab-TBC-Uploads, 764/CH11/EX11.14: data11_14.sci, result11_14.txt): a single-plate clutch transmits
    10 kW at 2000 rpm; input shaft 20 kg with radius of gyration 75 mm, output shaft 35 kg with 125 mm, the
    output shaft at rest. Printed results: time t1 = 0.409285 s, heat generated E = 2046.422713 J (the
    companion's figures for the book's example; the book's own printout was not available here). The clutch
    torque is the rated torque P/omega. Tolerance one unit of the sixth printed decimal."""
    j1, j2 = 20.0 * 0.075**2, 35.0 * 0.125**2
    w1 = 2000 * RPM
    e = engage(j1, w1, j2, 0.0, 10e3 / w1)
    assert e.slip_time == pytest.approx(0.409285, abs=1e-6)
    assert e.dissipated == pytest.approx(2046.422713, abs=1e-6)
    # both shafts turn at the common speed of conserved angular momentum when the slip ends
    assert e.common_speed == pytest.approx(j1 * w1 / (j1 + j2), rel=1e-12)


def test_fossee_764_example_12_1_flywheel_disk_braked_to_rest():
    """Brakes, Example 12.1 of the textbook worked in FOSSEE Scilab Textbook Companion no. 764
    (764/CH12/EX12.1: solution12_1.sce, result12_1.txt): a solid disk 1 m in diameter and 0.2 m thick
    (density 7200 kg/m^3) used as a flywheel at 350 rpm is brought to rest in 1.5 s by a brake. Printed results:
    energy absorbed E = 94956.722333 J, brake torque Mt = 3454.361540 N m. With that torque machdyn's stop
    takes the printed 1.5 s and the brake's work over the stop is the printed energy. Tolerances: the printed
    torque is rounded to 1e-6 N m (relative 3e-10), hence 1e-8 relative on the time and the work."""
    mass = np.pi / 4 * 1.0**2 * 0.2 * 7200.0
    inertia = mass * 1.0**2 / 8   # k = D / sqrt(8) for a solid disk
    stop = stop_constant(inertia, 350 * RPM, 3454.361540)
    assert stop.time == pytest.approx(1.5, rel=1e-8)
    assert 3454.361540 * stop.angle == pytest.approx(94956.722333, rel=1e-8)


def test_fossee_764_example_12_3_hoist_drum_braked_with_a_descending_load():
    """Brakes, Example 12.3 of the textbook worked in FOSSEE Scilab Textbook Companion no. 764
    (764/CH12/EX12.3: solution12_3.sce, result12_3.txt): a 2500 kg mass descending at 1.5 m/s on a drum of
    0.75 m radius (drum 50 kg, radius of gyration 0.7 m) is brought to rest in 0.5 m. Printed results: energy
    absorbed E = 15124 J (kinetic energy of the mass and the drum plus the mass's potential energy, g = 9.81),
    brake torque Mt = 22686 N m. In machdyn the weight is a driving load (resisting torque -m g R) and the mass
    is reflected to the drum (m R^2): with the printed torque the drum stops after h/R, i.e. the mass after
    0.5 m, and the brake's work is the printed energy. The printed values are exact in the data: tolerance
    1e-9 relative."""
    m, r, g = 2500.0, 0.75, 9.81
    inertia = 50.0 * 0.7**2 + m * r**2
    stop = stop_constant(inertia, 1.5 / r, 22686.0, resisting_torque=-m * g * r)
    assert stop.angle * r == pytest.approx(0.5, rel=1e-9)
    assert 22686.0 * stop.angle == pytest.approx(15124.0, rel=1e-9)


def test_openstax_college_physics_10_1_problem_3_grindstone_stopped_by_an_axe():
    """P. P. Urone, R. Hinrichs et al., *College Physics*, OpenStax 2012, §10.1, Problems & Exercises 3
    (Integrated Concepts): a grindstone (a disk) of 90.0 kg and 0.340 m radius turning at 90.0 rpm, a steel axe
    pressed against it with a radial force of 20.0 N, kinetic friction coefficient 0.20. Printed answers:
    (a) -0.26 rad/s^2, (b) 27 rev before it comes to rest. The axe is a brake of torque mu N r = 1.36 N m on a
    disk of J = m r^2/2; the deceleration is omega0 over the stopping time. Tolerances: half a unit of the last
    printed digit (0.005 rad/s^2, 0.5 rev)."""
    inertia = 0.5 * 90.0 * 0.340**2
    brake = 0.20 * 20.0 * 0.340
    omega0 = 90.0 * RPM
    stop = stop_constant(inertia, omega0, brake)
    assert -omega0 / stop.time == pytest.approx(-0.26, abs=0.005)
    assert stop.angle / (2 * np.pi) == pytest.approx(27.0, abs=0.5)
    # the brake's work over the stop is the kinetic energy it takes away
    assert brake * stop.angle == pytest.approx(0.5 * inertia * omega0**2, rel=1e-12)


def test_ge_technical_reference_rms_horsepower_of_a_varying_duty_cycle():
    """GE Industrial Motors catalogue, Section TR "Technical Reference Guide", varying duty cycle, Table 15
    (gemotors.cld.bz/wm9HNat/189): eight parts of 15, 40, 30, 5, 148, 200, 12 and 70 s at 32, 74, 27, 32, 66,
    27, 32 and 27 hp; printed sum of (hp)^2 t = 1,115,196 over 520 s and RMS Hp = 46.3 (so required 46.3 x 1.10
    = 50.9 hp). At the constant speed of an induction motor the power is proportional to the torque, so the RMS
    torque at any speed gives the RMS power. Tolerance half a unit of the printed last digit."""
    times = [15.0, 40.0, 30.0, 5.0, 148.0, 200.0, 12.0, 70.0]
    power = np.array([32.0, 74.0, 27.0, 32.0, 66.0, 27.0, 32.0, 27.0]) * HP
    assert sum(times) == 520.0
    assert float(np.sum((power / HP) ** 2 * times)) == pytest.approx(1_115_196.0, rel=1e-12)
    speed = 1780 * RPM   # any constant speed: it cancels
    rms_hp = rms_torque(power / speed, times) * speed / HP
    assert rms_hp == pytest.approx(46.3, abs=0.05)
    assert 1.10 * rms_hp == pytest.approx(50.9, abs=0.05)


def test_h2w_torque_at_a_ten_percent_duty_cycle():
    """H2W Technologies, "Rotary Motion Calculator" (h2wtech.com/page/rotary-motion-calculator), duty-cycle
    example: "Torque at 10% Duty Cycle = 1 N-m X (1/10%)^1/2 = 1 N-m X 3.16 = 3.16 N-m" (stated there for DC
    motors: the intermittent S3 rule with rest at zero torque), and "Duty Cycle = 1 sec on, 3 sec off = 25%".
    Printed to 3 digits: tolerance half a unit of the last digit. The inverse, the equivalent continuous torque
    of 3.16 N m at 10 %, is the 1 N m rating."""
    assert rated_torque_for_duty(1.0, "S3", 0.10) == pytest.approx(3.16, abs=0.005)
    assert equivalent_torque(rated_torque_for_duty(1.0, "S3", 0.10), "S3", 0.10) == pytest.approx(1.0, rel=1e-12)
    cdf = 1.0 / (1.0 + 3.0)
    assert cdf == 0.25
    assert rms_torque([2.0, 0.0], [1.0, 3.0]) == pytest.approx(equivalent_torque(2.0, "S3", cdf), rel=1e-12)
