"""Design sweeps in problem files: every variant analysed in one vectorised call, equal to analysing each
variant's own file; mistakes reported with their paths."""

import json
import math
import re
import subprocess
import sys

import numpy as np
import pytest

from machdyn.errors import ProblemFileError
from machdyn.linkage import crank_angles, kinetostatics
from machdyn.problem.build import build_mechanism
from machdyn.reading import load_problem
from machdyn.runner import run_problem
from problem_texts import four_bar

BASE = four_bar("sweep", positions=72)


def _single(text: str, replace: tuple[str, str]) -> float:
    """Peak |driving torque| of one design written out as its own problem file."""
    problem = load_problem(text.replace(*replace))
    forces = kinetostatics(build_mechanism(problem), crank_angles(72), problem.drive.speed)
    return float(np.max(np.abs(forces.driving_torque)))


def test_sweep_of_a_link_length_equals_each_variant_alone():
    text = BASE + '\n[sweep]\nparameter = "mechanism.crank.length"\nvalues = ["30 mm", "35 mm", "40 mm"]\n'
    result = run_problem(load_problem(text))
    frame = result.frames["sweep"]
    assert list(frame["mechanism.crank.length [m]"]) == pytest.approx([0.030, 0.035, 0.040])  # SI, as every column
    for i, value in enumerate(("30 mm", "35 mm", "40 mm")):
        expected = _single(BASE, ('"40 mm", mass = "0.2 kg"', f'"{value}", mass = "0.2 kg"'))
        assert frame["driving_torque.max_abs [N*m]"][i] == pytest.approx(expected, rel=1e-12)
    assert result.scalars["sweep.driving_torque.max_abs"]["unit"] == "N*m"
    assert any(row[0].startswith("Sweep: lowest driving torque, max |T|") for row in result.summary_rows)


def test_sweep_of_the_speed_and_of_a_load_item():
    speeds = BASE + '\n[sweep]\nparameter = "drive.speed"\nstart = "60 rpm"\nstop = "120 rpm"\ncount = 3\n'
    frame = run_problem(load_problem(speeds)).frames["sweep"]
    assert list(frame["drive.speed [rad/s]"]) == pytest.approx([2 * math.pi, 3 * math.pi, 4 * math.pi])
    for rpm, peak in zip((60, 90, 120), frame["driving_torque.max_abs [N*m]"], strict=True):
        assert peak == pytest.approx(_single(BASE, ('"10 rad/s"', f'"{rpm} rpm"')), rel=1e-12)
    loads = BASE + '\n[sweep]\nparameter = "loads.torques[0].torque"\nvalues = ["-1 N*m", "-2 N*m"]\n'
    frame = run_problem(load_problem(loads)).frames["sweep"]
    # The mean power over a turn is the work of the resisting torque on the shaft: -T * mean speed.
    assert list(frame["input_power.mean [W]"]) == pytest.approx([10.0, 20.0], rel=1e-9)


def test_variants_that_cannot_assemble_are_kept_but_not_regular():
    text = BASE + '\n[sweep]\nparameter = "mechanism.crank.length"\nvalues = ["40 mm", "90 mm"]\n'
    frame = run_problem(load_problem(text)).frames["sweep"]
    assert list(frame["regular"]) == [True, False]
    assert np.isnan(frame["driving_torque.max_abs [N*m]"][1])


@pytest.mark.parametrize(
    ("sweep", "path", "message"),
    [
        ('parameter = "mechanism.crnk.length"\nvalues = ["1 mm"]', "sweep.parameter",
         "'mechanism.crnk.length' is not a quantity of this file: mechanism has no key 'crnk'; "
         "did you mean 'crank'?"),
        ('parameter = "mechanism.crank.length"\nvalues = ["30 mm", "3 kg"]', "sweep.values[1]",
         "must be in units of [length] (like m); got '3 kg', which is [mass] (for mechanism.crank.length)"),
        ('parameter = "mechanism.crank.length"\nvalues = ["-30 mm"]', "sweep.values[0]",
         "must be > 0 m; got '-30 mm' (for mechanism.crank.length)"),
        ('parameter = "loads.torques[3].torque"\nvalues = ["1 N*m"]', "sweep.parameter",
         "'loads.torques[3].torque' refers to item 3 of 'torques', which has 1 item(s)"),
        ('parameter = "drive.start"\nvalues = ["10 deg"]', "sweep.parameter",
         "'drive.start' sets the crank angles, which every variant of a sweep shares"),
    ],
)
def test_sweep_mistakes_name_their_path(sweep, path, message):
    with pytest.raises(ProblemFileError) as info:
        run_problem(load_problem(BASE + "\n[sweep]\n" + sweep + "\n"))
    assert (path, message) in info.value.problems


def test_sweep_needs_values_or_a_range():
    with pytest.raises(ProblemFileError, match=re.escape("give either values = [...] or all of start, stop and count")):
        load_problem(BASE + '\n[sweep]\nparameter = "mechanism.crank.length"\nstart = "1 mm"\n')


def test_cli_writes_the_sweep_table(tmp_path):
    path = tmp_path / "sweep.toml"
    path.write_text(BASE + '\n[sweep]\nparameter = "mechanism.coupler.mass"\nvalues = ["0.5 kg", "1 kg"]\n')
    done = subprocess.run([sys.executable, "-m", "machdyn.cli", "run", str(path), "--out", str(tmp_path / "out"),
                           "--quiet"], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    lines = (tmp_path / "out" / "sweep.csv").read_text().splitlines()
    assert lines[0].startswith("mechanism.coupler.mass [kg],assembled,regular,status,driving_torque.max_abs [N*m]")
    assert len(lines) == 3
    assert "Design sweep of mechanism.coupler.mass" in (tmp_path / "out" / "report.html").read_text()


# ------------------------------------------------------------------------------- several quantities

EXPLORE = """
[sweep]
method = "sobol"
samples = 64
seed = 4
partition = 32

[[sweep.quantities]]
parameter = "mechanism.crank.length"
start = "30 mm"
stop = "45 mm"

[[sweep.quantities]]
parameter = "mechanism.coupler.length"
start = "110 mm"
stop = "130 mm"

[[sweep.quantities]]
parameter = "drive.speed"
start = "60 rpm"
stop = "120 rpm"

[[sweep.quantities]]
parameter = "loads.torques[0].torque"
start = "-1 N*m"
stop = "0 N*m"
"""


def test_a_one_quantity_file_is_not_an_exploration_and_an_exploration_dumps_back():
    from machdyn.problem import dump_problem

    one = load_problem(BASE + '\n[sweep]\nparameter = "mechanism.crank.length"\nvalues = ["30 mm"]\n')
    assert not one.sweep.is_exploration
    assert not load_problem(dump_problem(one)).sweep.is_exploration
    several = load_problem(BASE + EXPLORE)
    assert several.sweep.is_exploration and several.sweep.sampling == "sobol"
    assert load_problem(dump_problem(several)) == several


@pytest.mark.parametrize(
    ("sweep", "path", "message"),
    [
        ('method = "lhs"\nsamples = 8\n[[sweep.quantities]]\nparameter = "mechanism.crank.length"\n'
         'values = ["1 mm"]', "sweep",
         "quantities[0]: with method = 'lhs' give start and stop (the range to sample), not values or count"),
        ('parameter = "mechanism.crank.length"\nvalues = ["30 mm"]\nsamples = 8', "sweep",
         "samples is for method = 'lhs' or 'sobol'; a grid takes every combination of values"),
        ('method = "sobol"\nparameter = "mechanism.crank.length"\nstart = "30 mm"\nstop = "40 mm"', "sweep",
         "method = 'sobol' needs samples = <number of designs>"),
        ('method = "sobol"\nsamples = 8\nobjective = "max_drving_torque"\nparameter = "drive.speed"\n'
         'start = "1 rad/s"\nstop = "2 rad/s"', "sweep",
         "objective must name a per-design result (a key of docs/results.md such as driving_torque.max_abs, "
         "frame_force.max or joint.<name>.max_force); got 'max_drving_torque'; did you mean 'max_driving_torque'?"),
        ('scheduler = "localhost:8786"\nparameter = "drive.speed"\nvalues = ["1 rad/s"]', "sweep.scheduler",
         "must be the address of a Dask scheduler, like 'tcp://host:8786'; got 'localhost:8786'"),
    ],
)
def test_exploration_table_mistakes(sweep, path, message):
    with pytest.raises(ProblemFileError) as info:
        load_problem(BASE + "\n[sweep]\n" + sweep + "\n")
    # a wrong result name is followed by the results to choose from
    assert any(p == path and (m == message or m.startswith(message + " (results")) for p, m in info.value.problems)


def test_exploration_mistakes_in_quantities_are_all_reported_with_their_paths():
    text = BASE + EXPLORE.replace("mechanism.coupler.length", "mechanism.cuopler.length").replace(
        'start = "-1 N*m"', 'start = "-1 kg"').replace('stop = "120 rpm"', 'stop = "60 rpm"')
    with pytest.raises(ProblemFileError) as info:
        load_problem(text)
    assert info.value.problems == [
        ("sweep.quantities[1].parameter", "'mechanism.cuopler.length' is not a quantity of this file: mechanism has "
                                          "no key 'cuopler'; did you mean 'coupler'?"),
        ("sweep.quantities[2].stop", "must differ from start to give a range to sample; got '60 rpm' "
                                     "(for drive.speed)"),
        ("sweep.quantities[3].start", "must be in units of [mass] * [length] ** 2 / [time] ** 2 (like N*m); got "
                                      "'-1 kg', which is [mass] (for loads.torques[0].torque)"),
    ]
    bad_joint = BASE + EXPLORE.replace("partition = 32", 'partition = 32\nobjective = "joint.X.max_force"')
    with pytest.raises(ProblemFileError) as info:
        load_problem(bad_joint)
    assert info.value.problems[0][0] == "sweep.objective"
    assert "'joint.X.max_force' is not a result of this mechanism" in info.value.problems[0][1]


def test_cli_explores_writes_parquet_and_the_design_space_section(tmp_path):
    import pyarrow.parquet as pq

    path = tmp_path / "explore.toml"
    path.write_text(BASE + EXPLORE)
    out = tmp_path / "out"
    script = ("import sys; from machdyn.cli import app\n"
              "try:\n    app(sys.argv[1:])\nexcept SystemExit as e:\n    code = e.code\n"
              "print('CLUSTER' if any(m.split('.')[0] == 'distributed' for m in sys.modules) else 'NO CLUSTER')\n"
              "sys.exit(code)\n")
    done = subprocess.run([sys.executable, "-c", script, "run", str(path), "--out", str(out), "--quiet"],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    # An exploration in this process never imports dask.distributed (pint itself imports dask's core if present).
    assert done.stdout.strip() == "NO CLUSTER"
    parts = sorted((out / "sweep.parquet").glob("part-*.parquet"))
    assert [p.name for p in parts] == ["part-000000.parquet", "part-000001.parquet"]
    assert pq.read_schema(parts[0]).field("drive.speed").metadata[b"unit"] == b"rad/s"
    best = (out / "sweep_best.csv").read_text().splitlines()
    assert best[0].startswith("design,mechanism.crank.length [m],mechanism.coupler.length [m],drive.speed [rad/s]")
    scalars = json.loads((out / "results.json").read_text())["scalars"]
    assert scalars["sweep.designs"]["value"] == 64
    best = scalars["sweep.best.drive.speed"]
    assert best["unit"] == "rad/s" and best["shown"]["unit"] == "rpm"  # shown in the unit the file wrote
    assert 60.0 * math.pi / 30 <= best["value"] <= 120.0 * math.pi / 30
    assert best["shown"]["value"] == pytest.approx(best["value"] * 30 / math.pi, rel=1e-12)
    html = (out / "report.html").read_text()
    assert "Design space of mechanism.crank.length, mechanism.coupler.length, drive.speed" in html
    assert "Best designs" in html


def test_cli_refuses_workers_and_scheduler_together(tmp_path):
    from typer.testing import CliRunner

    from machdyn.cli import app

    path = tmp_path / "explore.toml"
    path.write_text(BASE + EXPLORE)
    result = CliRunner().invoke(app, ["run", str(path), "--workers", "2", "--scheduler", "tcp://127.0.0.1:1"])
    assert result.exit_code == 2
    assert "give --workers or --scheduler, not both" in result.output


def test_cli_workers_option_runs_on_dask_with_the_same_results(tmp_path):
    import pandas as pd
    from typer.testing import CliRunner

    from machdyn.cli import app

    path = tmp_path / "explore.toml"
    path.write_text(BASE + EXPLORE)
    runner = CliRunner()
    here = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "here"), "--quiet"])
    assert here.exit_code == 0, here.output
    dask = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "dask"), "--quiet", "--workers", "2"])
    assert dask.exit_code == 0, dask.output
    pd.testing.assert_frame_equal(pd.read_parquet(tmp_path / "dask" / "sweep.parquet"),
                                  pd.read_parquet(tmp_path / "here" / "sweep.parquet"), check_exact=True)
    assert (tmp_path / "dask" / "sweep_best.csv").read_text() == (tmp_path / "here" / "sweep_best.csv").read_text()
