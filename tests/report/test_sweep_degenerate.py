"""Degenerate designs of a sweep are flagged, not counted as regular, and the plots scale to the regular ones."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from machdyn.reading import load_problem
from machdyn.report import plots
from machdyn.runner import run_problem

ROOT = Path(__file__).resolve().parents[2]
SWEEP = '\n[sweep]\nparameter = "mechanism.crank.length"\nvalues = ["40 mm", "80 mm", "89.9 mm", "95 mm"]\n'


def _sweep(extra: str = ""):
    text = (ROOT / "examples" / "four_bar.toml").read_text(encoding="utf-8") + SWEEP + extra
    return run_problem(load_problem(text))


def test_a_design_near_its_dead_point_is_flagged_not_regular():
    """Crank 89.9 mm of the 130/120/100 mm four-bar: s + l = 219.9 mm against p + q = 220 mm (Norton, Design of
    Machinery, 5th ed., §2.12), so it turns fully but its transmission angle comes within a few degrees of
    180 deg; crank 95 mm cannot turn fully (s + l > p + q)."""
    scalars = _sweep().results_json()["scalars"]
    assert scalars["sweep.status"]["value"] == ["regular", "regular", "poor transmission", "does not assemble"]
    assert scalars["sweep.regular"]["value"] == [True, True, False, False]
    worst = scalars["sweep.transmission_angle.worst"]["value"]
    assert np.radians(10.0) < worst[1] < np.radians(40.0) and np.isnan(worst[2])  # no results for a degenerate one
    assert scalars["sweep.grashof.margin"]["value"][2] < 0 < scalars["sweep.grashof.margin"]["value"][3]
    assert scalars["sweep.regular_count"]["value"] == 2.0
    counts = {k.removeprefix("sweep.count."): v["value"] for k, v in scalars.items() if k.startswith("sweep.count.")}
    assert counts == {"does_not_assemble": 1.0, "dead_point": 0.0, "branch_change": 0.0, "near_dead_point": 0.0,
                      "poor_transmission": 1.0}


def test_the_transmission_threshold_is_the_users():
    scalars = _sweep('min_transmission_angle = "1 deg"\n').results_json()["scalars"]
    assert scalars["sweep.status"]["value"][2] == "regular"
    assert np.isfinite(scalars["sweep.joint.B.max_force"]["value"][2])


def test_plot_of_a_sweep_scales_to_the_regular_designs():
    ax = Figure().subplots()
    plots.plot_sweep(ax, [1.0, 2.0, 3.0, 4.0], [10.0, 11.0, 1.3e8, 12.0], parameter="a", parameter_unit="mm",
                     quantity="peak force", unit="N", regular=[True, True, False, True])
    low, high = ax.get_ylim()
    assert 5.0 < low and high < 20.0


def test_any_result_of_the_catalogue_can_be_asked_for_as_a_sweep_column():
    """``[sweep] columns`` adds results of the full analysis (kinetic energy, the flywheel's energy) computed per
    design by the run's own function: each variant's value equals that variant run alone."""
    result = _sweep('columns = ["kinetic_energy.fluctuation", "flywheel.energy_fluctuation"]\n')
    scalars = result.results_json()["scalars"]
    alone = run_problem(load_problem((ROOT / "examples" / "four_bar.toml").read_text(encoding="utf-8")
                                     .replace('length = "40 mm"', 'length = "80 mm"', 1))).results
    got = scalars["sweep.kinetic_energy.fluctuation"]["value"]
    assert np.isclose(got[1], alone["kinetic_energy.fluctuation"], rtol=1e-9)
    assert np.isnan(got[2]) and np.isnan(got[3])
    assert np.isclose(scalars["sweep.flywheel.energy_fluctuation"]["value"][1], alone["flywheel.energy_fluctuation"],
                      rtol=1e-9)


def test_a_column_that_names_no_result_is_refused_with_its_path():
    from machdyn.errors import ProblemFileError
    from machdyn.runner import check_problem

    text = (ROOT / "examples" / "four_bar.toml").read_text(encoding="utf-8") + SWEEP
    try:
        check_problem(load_problem(text + 'columns = ["joint.Z.max_force"]\n'))
    except ProblemFileError as exc:
        assert exc.problems[0][0] == "sweep.columns[0]" and "joint.Z.max_force" in exc.problems[0][1]
    else:
        raise AssertionError("an unknown column was accepted")


def test_a_threshold_outside_0_to_90_deg_is_refused():
    from machdyn.errors import ProblemFileError

    text = (ROOT / "examples" / "four_bar.toml").read_text(encoding="utf-8") + SWEEP
    try:
        load_problem(text + 'min_transmission_angle = "95 deg"\n')
    except ProblemFileError as exc:
        assert "min_transmission_angle must be at least 0 deg and below 90 deg; got 95 deg" in str(exc)
    else:
        raise AssertionError("a threshold of 95 deg was accepted")
