"""Torsionally stiff stages of the drive line in a transient run: the two-inertia natural frequency with the gear
ratio referred, the step response's dynamic factor, the rigid limit, energy conservation, the problem file and
its report, and bad input.

Sources: J. P. Den Hartog, *Mechanical Vibrations*, 4th ed., McGraw-Hill 1956, §5.4 (the torsional two-inertia
system, omega_n^2 = k (J_1 + J_2) / (J_1 J_2)) and §5.5 (a geared system reduced to one shaft: inertias and
stiffnesses times the square of the speed ratio); the response of an undamped oscillator to a suddenly applied
constant force overshoots to twice its static deflection (Den Hartog, §2.x, the step load; any vibrations text).
"""

import numpy as np
import pytest

from machdyn.dynamics import ConstantTorque, InductionMotor, equivalent_machine
from machdyn.dynamics.driveline import DriveLine, DriveTrain, Stage
from machdyn.errors import InputError, ProblemFileError
from machdyn.runner import check_problem, run_problem
from machdyn.transient import Exciter, Scenario, coupled_model, run_scenario
from machdyn.transient.torsion import TorsionalLine, torsion_run, torsional_line

from .machines import plate, rotor, small_press

RPM = np.pi / 30.0


def _zero_crossing_frequency(t, x) -> float:
    """Angular frequency [rad/s] from the mean spacing of the zero crossings of x(t) (linear interpolation)."""
    i = np.flatnonzero(np.sign(x[:-1]) != np.sign(x[1:]))
    crossings = t[i] - x[i] * (t[i + 1] - t[i]) / (x[i + 1] - x[i])
    return float(np.pi / np.mean(np.diff(crossings)))


def test_the_twist_oscillates_at_the_two_inertia_frequency_with_the_gear_ratio_referred():
    # motor shaft J0 -- stage 1 (3:1, stiff, k on its output shaft) -- shaft 1 J1 -- stage 2 (2:1, rigid) -- crank
    j0, j1, disc, k, torque = 0.02, 0.3, 1.5, 2.0e4, 5.0
    line = DriveLine(DriveTrain((Stage(3.0, 1.0, "gear", "coupling", torsional_stiffness=k), Stage(2.0)),
                                (j0, j1, 0.0)), ("motor", "shaft 1", "crank"), flywheel_shaft=2)
    torsion, crank_group = torsional_line(line)
    assert torsion.inertias == pytest.approx((j0 * 36.0,)) and torsion.stiffness == pytest.approx((4.0 * k,))
    model = coupled_model([Exciter(rotor(0.0, 0.0, inertia=disc), ConstantTorque(torque), crank_group,
                                   torsion=torsion)], None, positions=32)
    run = run_scenario(model, Scenario(duration=0.5, rtol=1e-11, method="DOP853", samples_per_period=200))
    shafts = torsion_run(run)
    # in the shafts' own coordinates: J0 theta0'' = T_m - k/3 (theta0/3 - theta1), (J1 + disc/4) theta1'' =
    # k (theta0/3 - theta1): omega_n^2 = k (1/(9 J0) + 1/(J1 + disc/4)), written without the reduction to the crank
    expected = np.sqrt(k * (1.0 / (9.0 * j0) + 1.0 / (j1 + disc / 4.0)))
    twist = shafts.psi[0] - run.phi[0]
    static = torque * (disc + 4 * j1) / (torsion.stiffness[0] * (36 * j0 + disc + 4 * j1))  # at the crank
    assert _zero_crossing_frequency(run.t, twist - static) == pytest.approx(expected, rel=1e-3)
    assert torsion.natural_frequency(disc + 4 * j1) == pytest.approx(expected, rel=1e-12)
    # a torque applied at once: the shaft's torque overshoots to twice its static share (undamped)
    static_torque = torsion.stiffness[0] * static / 2.0  # at the stage's output shaft (r_out = 2): K twist / r_out
    # (the peak of the samples, 200 a period of the line: within 1 - cos(pi / 200) = 1.2e-4 of the crest)
    assert shafts.peak_torques[0] == pytest.approx(2.0 * static_torque, rel=1.3e-4)
    assert shafts.energy_error < 1e-8


def test_a_very_stiff_line_gives_the_rigid_start_up():
    mech = small_press()
    motor = InductionMotor(250.0, 1440 * RPM, 1500 * RPM, 2.5, 10.0, 1.0, 0.0)
    machine = equivalent_machine(mech, 256)
    j_a = 1e-3 * 100.0  # 1e-3 kg*m^2 on the motor shaft, 10:1 to the crank
    j_b = 0.05 + float(np.mean(machine.inertia(np.linspace(0.0, 2 * np.pi, 256))))  # flywheel and mechanism
    rigid = run_scenario(coupled_model([Exciter(mech, motor, 0.05 + j_a, machine=machine)], None),
                         Scenario(duration=1.0, rtol=1e-9))
    differences = []
    for k in (2.0e4, 8.0e4):
        line = TorsionalLine((j_a,), (k,), (0.0,), (1.0,), ("coupling",), (0,))
        run = run_scenario(coupled_model([Exciter(mech, motor, 0.05, machine=machine, torsion=line)], None),
                           Scenario(duration=1.0, rtol=1e-9, method="LSODA"))
        # the stiff run is sampled 24 times a period of its spring: its speed between samples, linearly
        difference = float(np.max(np.abs(np.interp(rigid.t, run.t, run.omega[0]) - rigid.omega[0])))
        differences.append(difference)
        # what separates the runs is the undamped spring's ringing, started by the motor's torque applied at once:
        # a crank speed amplitude of at most J_a / (J_a + J_b) times the twist's rate, the static twist under the
        # breakdown torque T_b J_b / (K (J_a + J_b)) times omega_n
        omega_n = np.sqrt(k * (j_a + j_b) / (j_a * j_b))
        ringing = j_a / (j_a + j_b) * float(motor.breakdown_torque) * j_b / (k * (j_a + j_b)) * omega_n
        assert difference <= ringing
        assert torsion_run(run).energy_error < 1e-6
    # that amplitude goes as K^-1/2: four times the stiffness, half the difference -- the rigid run is the limit
    assert differences[0] / differences[1] == pytest.approx(2.0, rel=0.1)


def test_a_free_undamped_line_on_an_undamped_frame_keeps_its_energy():
    line = TorsionalLine((0.4,), (3.0e3,), (0.0,), (1.0,), ("coupling",), (0,))
    model = coupled_model([Exciter(small_press(), None, 0.05, torsion=line)], plate(c=0.0))
    run = run_scenario(model, Scenario(duration=1.0, speed=20.0, rtol=1e-11, method="DOP853"))
    shafts = torsion_run(run)
    total = run.energy + shafts.energy
    assert np.ptp(shafts.energy) > 1e-3 * total[0]  # the spring does work: the mechanism's inertia varies
    assert np.max(np.abs(total - total[0])) <= 1e-8 * total[0]


def test_a_stiff_line_with_the_motors_electrical_states_closes_both_balances():
    from machdyn.transient.electric import motor_run
    from machdyn.transient.induction import InductionMachine
    from machdyn.transient.motor_table import energy_error

    motor = InductionMachine(0.435, 0.816, 0.754, 0.754, 26.13, 2, 220.0, 60.0, ratio=10.0)
    line = TorsionalLine((8.9,), (2.0e4,), (20.0,), (1.0,), ("coupling",), (0,))  # the 3-hp rotor at the crank
    model = coupled_model([Exciter(small_press(), motor, 0.5, torsion=line)], None)
    run = run_scenario(model, Scenario(duration=0.4))
    assert energy_error(motor_run(run), run) < 1e-6
    shafts = torsion_run(run)
    assert shafts.energy_error < 1e-6 and shafts.damper_loss > 0


#: A slider-crank (the compressor of examples/slider_crank.toml, without its gas load) driven through a belt and a
#: stiff gear pair, started at its running speed: small enough for a test
LINE = """
[mechanism]
type = "slider_crank"
[mechanism.crank]
length = "50 mm"
mass = "2.5 kg"
inertia = "0.004 kg*m^2"
com = ["15 mm", "0 mm"]
[mechanism.rod]
length = "200 mm"
mass = "1.2 kg"
inertia = "0.0055 kg*m^2"
com = ["60 mm", "0 mm"]
[mechanism.slider]
mass = "1.5 kg"
[drive]
speed = "300 rpm"
positions = 90
[flywheel]
inertia = "0.3 kg*m^2"
start_up = false
[flywheel.motor]
kind = "induction"
rated_power = "1.1 kW"
rated_speed = "1440 rpm"
synchronous_speed = "1500 rpm"
[drivetrain]
motor_inertia = "0.004 kg*m^2"
[[drivetrain.stages]]
name = "belt"
kind = "belt"
ratio = 2.5
inertia = "0.02 kg*m^2"
shaft = "countershaft"
[[drivetrain.stages]]
name = "gear pair"
ratio = 2.0
inertia = "0.1 kg*m^2"
torsional_stiffness = "20 kN*m/rad"
torsional_damping = "5 N*m*s/rad"
[transient]
duration = "0.6 s"
start_speed = "300 rpm"
"""


def test_a_file_with_a_stiff_gear_pair_reports_its_shaft_torque():
    from machdyn.report.transient_drive import sections

    result = run_problem(LINE)
    assert not result.failed_checks
    values = {k: v["value"] for k, v in result.results_json()["scalars"].items()}
    assert values["transient.stage_2.peak_torque"] == values["transient.shaft_peak_torque"] > 0
    assert values["transient.shaft_energy_error"] < 1e-6 and values["transient.energy_error"] < 1e-6
    outcome = result.outcomes["transient"]
    line = outcome.results.torsion.line
    # the groups: motor shaft and countershaft (0.004 x 5^2 + 0.02 x 2^2 = 0.18 kg*m^2 at the crank); the
    # crankshaft's: the bull gear, the flywheel (on the crank shaft) and the mechanism
    assert line.inertias == pytest.approx((0.18,)) and line.stiffness == pytest.approx((2.0e4,))
    assert values["transient.torsion_natural_frequency"] == pytest.approx(
        line.natural_frequency(outcome.results.crank_inertia) / (2 * np.pi))
    found = dict(sections(outcome))
    assert "<svg" in found["Torque through the drive line's stiff stages"]
    assert "stage_2_torque" in outcome.series["transient_shafts"]


def test_a_file_with_the_motors_electrical_states_behind_the_stiff_stage_warns_of_another_motor():
    # Krause's 3-hp machine on a 60 Hz supply (1800 rpm) where [flywheel.motor] is a 1500 rpm motor: the run
    # goes on, both balances closed, and says that the two motors differ
    text = LINE.replace('start_speed = "300 rpm"', 'start_speed = "300 rpm"\nduration = "0.3 s"').replace(
        'duration = "0.6 s"\n', "") + """
[transient.motor]
model = "induction-dq"
stator_resistance = "0.435 ohm"
rotor_resistance = "0.816 ohm"
stator_leakage_reactance = "0.754 ohm"
rotor_leakage_reactance = "0.754 ohm"
magnetizing_reactance = "26.13 ohm"
pole_pairs = 2
line_voltage = "220 V"
frequency = "60 Hz"
"""
    result = run_problem(text)
    assert not result.failed_checks
    assert any("1800 rpm synchronous" in w and "1500 rpm" in w for w in result.warnings), result.warnings
    values = {k: v["value"] for k, v in result.results_json()["scalars"].items()}
    assert values["transient.motor_energy_error"] < 1e-6 and values["transient.shaft_energy_error"] < 1e-6


def test_a_stiff_stage_is_checked_in_the_file():
    text = LINE.replace('torsional_stiffness = "20 kN*m/rad"', 'torsional_stiffness = "-1 N*m/rad"')
    with pytest.raises(ProblemFileError, match=r"drivetrain\.stages\[1\]\.torsional_stiffness: must be > 0"):
        check_problem(text)
    damped_only = LINE.replace('torsional_stiffness = "20 kN*m/rad"\n', "")
    with pytest.raises(ProblemFileError, match=r"torsional_damping .* needs torsional_stiffness"):
        check_problem(damped_only)


def test_check_and_run_refuse_a_stiff_stage_with_no_inertia_before_it():
    text = LINE.replace('motor_inertia = "0.004 kg*m^2"', 'motor_inertia = "0 kg*m^2"').replace(
        'inertia = "0.02 kg*m^2"', 'inertia = "0 kg*m^2"')
    for step in (check_problem, run_problem):
        with pytest.raises(ProblemFileError, match=r"drivetrain\.stages\[1\]\.torsional_stiffness: .*no inertia"):
            step(text)


def test_a_stiff_stage_without_inertia_before_it_is_refused():
    with pytest.raises(InputError, match=r"before the stiff stage 'coupling' have no inertia"):
        TorsionalLine((0.0,), (1e3,), (0.0,), (1.0,), ("coupling",), (0,))
    with pytest.raises(InputError, match=r"torsional stiffness must be > 0 N\*m/rad; got -5"):
        DriveTrain((Stage(2.0, torsional_stiffness=-5.0),), (1.0, 1.0))
