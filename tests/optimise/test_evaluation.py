"""Population evaluation: one vectorised call equals evaluating each design alone; the kinematic results agree
with the engine's own diagnostics and with the seed 003 compactor layer."""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.linkage import diagnose
from machdyn.machines.compactor import Compactor
from machdyn.problem.build import build_mechanism
from machdyn.studies.optimisation import setup
from machdyn.studies.optimisation.evaluate import evaluate, result_names

from .conftest import problem_with

VARIABLES = """
[[optimise.variables]]
parameter = "mechanism.crank.length"
lower = "20 mm"
upper = "55 mm"
[[optimise.variables]]
parameter = "mechanism.coupler.length"
lower = "100 mm"
upper = "160 mm"
[[optimise.variables]]
parameter = "drive.speed"
lower = "60 rpm"
upper = "200 rpm"
[[optimise.objectives]]
result = "driving_torque.max_abs"
"""


def test_vectorised_population_equals_one_design_at_a_time():
    problem = problem_with(VARIABLES)
    ev = setup(problem, problem.optimise)
    rng = np.random.default_rng(11)
    x = ev.space.lower + rng.random((9, 3)) * (ev.space.upper - ev.space.lower)
    x[0] = [0.055, 0.100, 10.0]  # a design that cannot close (crank + ground > coupler + rocker)
    pop = ev.space.population(x)
    wanted = set(result_names(pop.mechanism))
    together = evaluate(pop.mechanism, ev.phi, pop.speed, pop.acceleration, wanted)
    assert not together["regular"][0] and together["regular"][1:].all()
    for i, row in enumerate(x):
        alone_problem = ev.space.problem_at(row)
        alone = evaluate(build_mechanism(alone_problem), ev.phi, alone_problem.drive.speed,
                         alone_problem.drive.acceleration, wanted)
        for key, values in together.items():
            # Rounding only: the same closed forms on arrays of different shapes.
            np.testing.assert_allclose(values[i], alone[key][0], rtol=1e-12, atol=1e-12, err_msg=key)


def test_strokes_time_ratio_and_transmission_agree_with_the_engine_diagnostics():
    problem = problem_with(VARIABLES)
    mech = build_mechanism(problem)
    phi = np.arange(3600) * (2 * np.pi / 3600)
    got = evaluate(mech, phi, 1.0, 0.0, set(result_names(mech)))
    diag = diagnose(mech, samples=3600)
    assert got["stroke.rocker"][0] == pytest.approx(diag.strokes["rocker"], rel=1e-12)
    assert got["time_ratio"][0] == pytest.approx(diag.time_ratio, rel=1e-12)
    assert got["transmission_angle.min"][0] == pytest.approx(diag.transmission_angle_min, rel=1e-12)
    assert got["transmission_angle.max"][0] == pytest.approx(diag.transmission_angle_max, rel=1e-12)


def test_time_ratio_of_a_crank_rocker_matches_its_closed_form():
    """Time ratio = the longer over the shorter crank interval between the two limit positions, found from the
    triangles O-D-B at full extension (|OB| = b + a) and at folding (|OB| = b - a) (Uicker, Pennock & Shigley,
    Theory of Machines and Mechanisms, 5th ed., §1.9)."""
    a, b, c, d = 0.04, 0.12, 0.10, 0.15
    problem = problem_with("")
    mech = build_mechanism(problem)
    phi = np.arange(7200) * (2 * np.pi / 7200)
    got = evaluate(mech, phi, 1.0, 0.0, {"time_ratio"})["time_ratio"][0]
    ext = np.arccos((d**2 + (b + a) ** 2 - c**2) / (2 * d * (b + a)))
    fold = np.arccos((d**2 + (b - a) ** 2 - c**2) / (2 * d * (b - a)))
    # Extended, the crank lies along O->B at angle ext; folded, opposite O->B at fold + pi.
    forward = np.pi + (fold - ext)
    # Linear interpolation of the zero crossings: error ~ step^2 (1e-7 rad at 7200 samples).
    assert got == pytest.approx(forward / (2 * np.pi - forward), rel=1e-6)


def test_compactor_results_agree_with_the_machine_layer(compactor):
    """Plate angle gamma and force gains from the population evaluation against machines.compactor."""
    mech = build_mechanism(compactor)
    phi = np.arange(3600) * (2 * np.pi / 3600)
    got = evaluate(mech, phi, 10.0, 0.0, set(result_names(mech, "compactor")), machine="compactor")
    machine = Compactor(r=0.03, l=0.5, h=0.25, R=0.25, branch=-1)
    check = machine.gamma_check(samples=3601)
    # The machine layer refines the extreme between samples; a 0.1 deg grid is within 1e-6 rad of it.
    assert got["compactor.plate_angle.max"][0] == pytest.approx(check["gamma_max"], abs=1e-6)
    window = phi[(phi >= np.radians(220)) & (phi <= np.radians(260))]
    alpha, _beta, _gamma = machine.angles(window)
    k1 = np.min(np.abs(1.0 / np.cos(alpha)))
    assert got["compactor.k1.min"][0] == pytest.approx(k1, rel=1e-12)
    assert got["compactor.k2"][0] == pytest.approx(0.5 / 0.1, rel=1e-12)
    assert got["compactor.force_gain.min"][0] == pytest.approx(k1 * 5.0, rel=1e-12)


def test_a_design_that_closes_at_no_angle_gives_nan_results_and_no_warning():
    """Warnings are errors in this suite: a population with a design that never closes must evaluate quietly."""
    from machdyn.linkage import four_bar

    mech = four_bar([0.04, 0.04], [0.12, 0.01], [0.10, 0.01], 0.15)
    got = evaluate(mech, np.arange(36) * (2 * np.pi / 36), 10.0, 0.0, set(result_names(mech)))
    assert got["regular"].tolist() == [True, False]
    assert got["assembled_fraction"][1] == 0.0
    assert np.isnan(got["driving_torque.max_abs"][1]) and np.isfinite(got["driving_torque.max_abs"][0])


def test_the_examples_split_compaction_force_equals_the_force_at_p(compactor):
    """The example writes Q at P as Q a/l at A plus Q (l - a)/l at B: on a rigid plate the same resultant and
    moment, so the driving torque and every joint force agree to rounding."""
    from dataclasses import replace

    from machdyn.linkage import crank_angles, kinetostatics
    from machdyn.linkage.model import PointForce

    mech = build_mechanism(compactor)
    phi = crank_angles(360)
    split = kinetostatics(mech, phi, 10.0)
    at_p = kinetostatics(replace(mech, forces=(PointForce("Q", "coupler.P", 0.0, 2000.0, mech.forces[0].active),)),
                         phi, 10.0)
    scale = np.max(np.abs(at_p.driving_torque))
    np.testing.assert_allclose(split.driving_torque, at_p.driving_torque, rtol=0, atol=1e-12 * scale)
    for name in ("O", "D"):
        np.testing.assert_allclose(split.joint(name).magnitude, at_p.joint(name).magnitude, rtol=1e-12)


def test_compactor_results_come_with_the_machine_not_with_a_point_named_p():
    """A four-bar with a coupler point P is not a compactor unless its file says so: its results offer no
    compactor figures, and asking for one says how to get them."""
    from machdyn.errors import ProblemFileError

    problem = problem_with(VARIABLES)
    mech = build_mechanism(problem)
    assert "P" in mech.body("coupler").points
    assert not any(k.startswith("compactor.") for k in result_names(mech))
    assert "compactor.force_gain.min" in result_names(mech, "compactor")
    with pytest.raises(ProblemFileError, match='machine = \\"compactor\\"'):
        problem_with(VARIABLES.replace('result = "driving_torque.max_abs"', 'result = "compactor.k2"'))
