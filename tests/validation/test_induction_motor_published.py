"""The induction motor's dq model against the equivalent circuit and against published machines.

Sources
-------
* P. Krause, O. Wasynczuk, S. Sudhoff, S. Pekarek, *Analysis of Electric Machinery and Drive Systems*, 3rd ed.,
  Wiley-IEEE Press 2013, chapter 6, the table of induction-machine parameters used for the free-acceleration
  characteristics (§6.10; Table 4.10-1 of the 2nd ed., 2002): four 4-pole, 60 Hz machines with their rated
  power, line voltage, rated speed and r_s, X_ls, X_M, X'_lr, r'_r, J. The table prints the rated speed; the
  free-acceleration characteristics are printed only as curves, so the free acceleration is checked by what
  does not depend on reading a curve: its two reference frames against each other, its end at the
  equivalent circuit's no-load state, and its energy balance.
* S. J. Chapman, *Electric Machinery Fundamentals*, 4th ed., McGraw-Hill 2005, Example 6-5: a 460 V, 25 hp,
  60 Hz, 4-pole, Y-connected motor (R1 = 0.641, R2 = 0.332, X1 = 1.106, X2 = 0.464, XM = 26.3 ohm); printed:
  V_TH = 255.2 V, R_TH = 0.590 ohm, X_TH = 1.106 ohm (his approximation X_TH ~ X1), s_max = 0.198,
  T_max = 229 N*m, T_start = 104 N*m.
"""

import math

import numpy as np
import pytest

from machdyn.linkage import Body, Crank, Mechanism
from machdyn.transient import Exciter, Scenario, coupled_model, run_scenario
from machdyn.transient.electric import motor_run
from machdyn.transient.induction import InductionMachine, breakdown_of, thevenin, thevenin_torque

#: Krause et al., 3rd ed., §6.10: (hp, line voltage [V], rated speed [r/min], r_s, X_ls, X_M, X'_lr, r'_r [ohm],
#: J [kg*m^2])
KRAUSE = {
    "3 hp": (3, 220.0, 1710, 0.435, 0.754, 26.13, 0.754, 0.816, 0.089),
    "50 hp": (50, 460.0, 1705, 0.087, 0.302, 13.08, 0.302, 0.228, 1.662),
    "500 hp": (500, 2300.0, 1773, 0.262, 1.206, 54.02, 1.206, 0.187, 11.06),
    "2250 hp": (2250, 2300.0, 1786, 0.029, 0.226, 13.04, 0.226, 0.022, 63.87),
}


def krause(name, frame="synchronous"):
    _, volts, _, rs, xls, xm, xlr, rr, _ = KRAUSE[name]
    return InductionMachine(rs, rr, xls, xlr, xm, 2, volts, 60.0, frame=frame)


@pytest.mark.parametrize("name", list(KRAUSE))
def test_the_dq_steady_state_is_the_equivalent_circuits_torque_slip_curve(name):
    # the dq equations' right-hand side set to zero at a constant slip (a linear system in the flux linkages) and
    # the per-phase circuit's Thevenin torque are two derivations of the same steady state
    motor = krause(name)
    for slip in np.geomspace(1e-3, 1.0, 40):
        psi = motor.steady_flux(slip)
        torque = motor.electromagnetic_torque(psi)
        assert torque == pytest.approx(float(motor.air_gap_torque(slip)), rel=1e-6)
        i_qs, i_ds, _, _ = motor.currents(psi)
        assert math.hypot(i_qs, i_ds) / math.sqrt(2) == pytest.approx(float(motor.stator_current(slip)), rel=1e-6)


def test_the_integrated_flux_equations_settle_on_the_equivalent_circuits_torque():
    # independent of the linear solve: the flux equations integrated in time at a constant shaft speed (the
    # stationary frame, the supply's phases turning) until the switch-on transient has died out
    from scipy.integrate import solve_ivp

    motor = krause("3 hp", "stationary")
    for slip in (0.01, 0.6):
        wm = (1.0 - slip) * motor.synchronous_speed
        sol = solve_ivp(lambda t, y, wm=wm: motor.rates(t, y, wm)[0], (0.0, 1.6), np.zeros(4), method="DOP853",
                        rtol=1e-10, atol=1e-11)
        # 1.6 s is 18 rotor time constants L_r / r'_r = 0.087 s: the transient's e^-18 = 2e-8 is below the check
        torque = motor.electromagnetic_torque(sol.y[:, -1])
        assert torque == pytest.approx(float(motor.air_gap_torque(slip)), rel=1e-6)


@pytest.mark.parametrize(("name", "tolerance"), [("500 hp", 0.5), ("2250 hp", 0.5), ("3 hp", 12.0),
                                                 ("50 hp", 12.0)])
def test_the_rated_speed_printed_in_krauses_table(name, tolerance):
    # the speed at which the dq steady state gives the rated power on the shaft: the large machines' printed
    # speeds to the printing's 0.5 r/min; the small machines' circuits give 11-12 r/min more than their printed
    # (nameplate) speeds (1721 for 1710, 1717 for 1705 r/min: the circuit gives the rated power at a slip 10 %
    # smaller), which the tolerance admits and says
    from scipy.optimize import brentq

    hp, _, printed, *_ = KRAUSE[name]
    motor = krause(name)

    def surplus(slip):
        return motor.electromagnetic_torque(motor.steady_flux(slip)) * (1 - slip) * motor.synchronous_speed \
            - 746.0 * hp

    slip = brentq(surplus, 1e-5, 0.2, xtol=1e-14)
    assert (1.0 - slip) * 1800.0 == pytest.approx(printed, abs=tolerance)


def test_chapman_example_6_5_thevenin_breakdown_and_starting_torque():
    v_th, z_th = thevenin(266.0, 0.641, 1.106, 26.3)  # Chapman rounds 460 / sqrt 3 = 265.6 V to 266 V
    assert abs(v_th) == pytest.approx(255.2, abs=0.05)
    assert z_th.real == pytest.approx(0.590, abs=5e-4)
    assert z_th.imag == pytest.approx(1.075, abs=5e-4)  # exact; Chapman takes X_TH ~ X1 = 1.106 ohm
    w = 2 * math.pi * 60
    # with his printed Thevenin values the formulas give his printed answers to their last digit
    t_max, s_max = breakdown_of(255.2, 0.590, 1.106, 0.332, 0.464, 2, w)
    assert s_max == pytest.approx(0.198, abs=5e-4)
    assert t_max == pytest.approx(229.0, abs=0.5)
    assert float(thevenin_torque(1.0, 255.2, 0.590, 1.106, 0.332, 0.464, 2, w)) == pytest.approx(104.0, abs=0.5)
    # the exact circuit differs from his approximate one by the X_TH approximation (3 % of X_TH + X2): within 3 %
    motor = InductionMachine(0.641, 0.332, 1.106, 0.464, 26.3, 2, 460.0, 60.0)
    assert motor.breakdown[0] == pytest.approx(229.0, rel=0.03)
    assert motor.breakdown[1] == pytest.approx(0.198, rel=0.03)
    assert float(motor.air_gap_torque(1.0)) == pytest.approx(104.0, rel=0.03)


def _flywheel(inertia):
    disc = Body("disc", {"O": (0.0, 0.0)}, mass=0.0, inertia=inertia)
    return Mechanism("rotor", {"O": (0.0, 0.0)}, (disc,), Crank("disc", "ground.O"), gravity=(0.0, 0.0))


@pytest.fixture(scope="module")
def free_acceleration():
    """Krause's 3-hp machine accelerating its own rotor (J = 0.089 kg*m^2) from rest, unloaded, for 1 s, in both
    reference frames."""
    runs = {}
    for frame in ("synchronous", "stationary"):
        model = coupled_model([Exciter(_flywheel(KRAUSE["3 hp"][-1]), krause("3 hp", frame))], None, positions=32)
        runs[frame] = run_scenario(model, Scenario(duration=1.0, rtol=1e-9))
    return runs


def test_krauses_free_acceleration_is_the_same_in_both_reference_frames(free_acceleration):
    sync, stat = free_acceleration["synchronous"], free_acceleration["stationary"]
    common, a, b = np.intersect1d(np.round(sync.t, 9), np.round(stat.t, 9), return_indices=True)
    assert common.size > 100
    # two formulations (constant supply in the synchronous frame; 60 Hz phases in the stationary one) agree to
    # the integrators' tolerance
    assert np.max(np.abs(sync.omega[0, a] - stat.omega[0, b])) <= 1e-6 * 188.5
    ma, mb = motor_run(sync), motor_run(stat)
    assert ma.peak_torque == pytest.approx(mb.peak_torque, rel=1e-6)
    assert ma.peak_current == pytest.approx(mb.peak_current, rel=1e-6)


def test_krauses_free_acceleration_ends_at_the_no_load_state_and_closes_its_energy(free_acceleration):
    run = free_acceleration["synchronous"]
    motor = motor_run(run)
    ws = 2 * math.pi * 60 / 2
    # unloaded and loss-free mechanically: it ends at synchronous speed (1 s is 5 electrical settling times)
    assert run.omega[0, -1] == pytest.approx(ws, rel=1e-5)
    # the switch-on's torque pulsations exceed the steady state's breakdown torque (61.9 N*m), as in Krause's
    # free-acceleration curves of this machine
    assert motor.breakdown_torque == pytest.approx(61.87, abs=0.01)
    assert motor.peak_torque > 1.5 * motor.breakdown_torque
    # energy: electrical input = copper loss + magnetic energy + kinetic energy, to 1e-6 of the input
    kinetic = 0.5 * KRAUSE["3 hp"][-1] * run.omega[0, -1] ** 2
    balance = motor.electrical_input - motor.copper_loss - motor.magnetic_energy_change - kinetic
    assert abs(balance) <= 1e-6 * motor.electrical_input
    # at the no-load state the stator draws the magnetising current of the equivalent circuit at s = 0
    assert motor.current[-1] / math.sqrt(2) == pytest.approx(float(krause("3 hp").stator_current(0.0)), rel=1e-4)
