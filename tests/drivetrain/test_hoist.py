"""Hoists and branched trains: hand formulas, the energy balance, the power's direction through a lossy stage,
and the [hoist] problem file with its command line and report."""

from __future__ import annotations

import numpy as np
import pytest
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.constants import STANDARD_GRAVITY as G
from machdyn.drivetrain.hoist import Drum, Shaft, acceleration, hoist
from machdyn.report.hoist import sections
from machdyn.runner import run_problem

LINE = (
    Shaft("motor", inertia=1.2, friction=5.0),
    Shaft("drum shaft", "motor", 20.0, 0.9, 150.0, 250.0, (Drum(0.6, 1500.0, 900.0, 120.0, "cage"),)),
    Shaft("skip shaft", "drum shaft", 2.0, 0.95, 20.0, 40.0, (Drum(0.4, 300.0, name="skip"),)),
)


def test_one_stage_is_khurmi_and_guptas_geared_system():
    """Khurmi & Gupta, *Theory of Machines*, 14th ed., ch. 3, torque to accelerate a geared system:
    T_A = (I_A + G^2 I_B / eta) alpha_A with G = omega_B / omega_A."""
    i, eta, ja, jb, alpha = 5.0, 0.85, 0.3, 40.0, 12.0
    t = hoist((Shaft("a", inertia=ja), Shaft("b", "a", i, eta, jb)), alpha).motor_torque
    assert t == pytest.approx((ja + jb / (i * i * eta)) * alpha, rel=1e-12)


def test_a_chain_with_power_flowing_down_takes_every_loss_on_its_path():
    """Closed form for demands that are all positive: T_m = sum_k r_k Q_k / prod_(j <= k) eta_j."""
    alpha = 26.0
    res = hoist(LINE, alpha)
    r = [1.0, 1 / 20, 1 / 40]
    etas = [1.0, 0.9, 0.9 * 0.95]
    q = [1.2 * alpha * r[0] + 5.0,
         150.0 * alpha * r[1] + 250.0 + 2520.0 * 0.36 * alpha * r[1] + 600.0 * G * 0.6,
         20.0 * alpha * r[2] + 40.0 + 300.0 * 0.16 * alpha * r[2] + 300.0 * G * 0.4]
    assert res.motor_torque == pytest.approx(sum(rk * qk / ek for rk, qk, ek in zip(r, q, etas, strict=True)),
                                             rel=1e-12)
    assert res.equivalent_inertia == pytest.approx(1.2 + (150 + 2520 * 0.36) / 400 + (20 + 48) / 1600, rel=1e-12)
    assert res.cage_acceleration["cage"] == pytest.approx(alpha * 0.6 / 20, rel=1e-12)


def test_energy_balance_of_a_loss_free_hoist_from_rest():
    """Second method: from rest at constant motor acceleration for t seconds, the motor's work T theta equals
    the kinetic energy of every shaft and mass, the potential energy gained and the friction's work, each
    computed from its own speed and travel."""
    line = tuple(Shaft(s.name, s.parent, s.ratio, 1.0, s.inertia, s.friction, s.drums) for s in LINE)
    alpha, t = 20.0, 1.7
    torque = hoist(line, alpha).motor_torque
    theta_m, omega_m = 0.5 * alpha * t * t, alpha * t
    work = torque * theta_m
    r = {"motor": 1.0, "drum shaft": 1 / 20, "skip shaft": 1 / 40}
    energy = 0.0
    for s in line:
        w, turn = omega_m * r[s.name], theta_m * r[s.name]
        energy += 0.5 * s.inertia * w * w + s.friction * turn
        for d in s.drums:
            v, h = w * d.radius, turn * d.radius
            energy += 0.5 * (d.cage + d.counterweight + d.rope) * v * v + (d.cage - d.counterweight) * G * h
    assert work == pytest.approx(energy, rel=1e-12)


def test_an_overrunning_load_drives_back_through_the_stage_with_its_loss_on_the_other_side():
    """A counterweight heavier than the cage at steady speed: the load drives the motor, and the stage passes
    eta times the power back (T_m = r Q eta), not r Q / eta."""
    line = (Shaft("m"), Shaft("d", "m", 10.0, 0.8, drums=(Drum(0.5, 500.0, 800.0),)))
    q = (500.0 - 800.0) * G * 0.5
    assert hoist(line, 0.0).motor_torque == pytest.approx(q * 0.8 / 10.0, rel=1e-12)


def test_acceleration_inverts_the_torque():
    for torque in (-50.0, 260.0, 900.0):
        alpha = acceleration(LINE, torque)
        assert hoist(LINE, alpha).motor_torque == pytest.approx(torque, rel=1e-10, abs=1e-9)


HOIST = """
[meta]
name = "hoist"

[hoist]
{head}

[[hoist.shafts]]
name = "motor"
inertia = "1.2 kg*m^2"

[[hoist.shafts]]
name = "drum shaft"
driven_by = "{parent}"
ratio = 20
efficiency = 0.9
inertia = "150 kg*m^2"

[[hoist.shafts.drums]]
name = "cage"
radius = "0.6 m"
cage = "1500 kg"
counterweight = "900 kg"
"""


def test_the_problem_file_runs_and_reports(tmp_path):
    run = run_problem(HOIST.format(head='cage_acceleration = "0.8 m/s^2"', parent="motor"))
    out = run.outcomes["hoist"]
    res = out.results.result
    assert res.cage_acceleration["cage"] == pytest.approx(0.8, rel=1e-12)
    assert run.scalars["hoist.cage.rope_tension"]["value"] == pytest.approx(1500 * (G + 0.8), rel=1e-12)  # N
    html = sections(out)[0][1]
    assert "<svg" in html and "stages' loss" in html
    assert np.isclose(sum(res.shaft_demand.values()) + res.loss_torque, res.motor_torque)


@pytest.mark.parametrize(("head", "parent", "field"), [
    ('cage_acceleration = "0.8 m/s^2"\nmotor_torque = "100 N*m"', "motor", "hoist"),
    ('motor_torque = "100 N*m"', "gearbox", "hoist.shafts[1].driven_by"),
    ('cage_acceleration = "0.8 m/s^2"\ndrum = "skip"', "motor", "hoist.drum"),
])
def test_check_and_run_refuse_the_same_bad_input(head, parent, field, tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text(HOIST.format(head=head, parent=parent), encoding="utf-8")
    runner = CliRunner()
    checked = runner.invoke(app, ["check", str(path)])
    ran = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "out"), "--quiet"])
    assert checked.exit_code == 2 and ran.exit_code == 2
    assert field in checked.stderr and field in ran.stderr
    assert "Traceback" not in checked.output + ran.output


def test_a_slack_rope_is_a_failed_design_check(tmp_path):
    path = tmp_path / "slack.toml"
    path.write_text(HOIST.format(head='cage_acceleration = "-12 m/s^2"', parent="motor"), encoding="utf-8")
    ran = CliRunner().invoke(app, ["run", str(path), "--out", str(tmp_path / "out"), "--quiet"])
    assert ran.exit_code == 3 and "slack" in ran.output
