"""The Python API: the same analyses as the command line in a few lines, results as pandas DataFrames."""

from __future__ import annotations

from pathlib import Path

import pandas as pd
import pytest

from machdyn.errors import AssemblyError, ProblemFileError
from machdyn.reading import load_problem
from machdyn.runner import RunResult, check_problem, run_problem

ROOT = Path(__file__).resolve().parents[2]


def test_notebook_use():
    result = run_problem(load_problem(ROOT / "examples" / "slider_crank.toml"))
    assert isinstance(result, RunResult)
    frames = result.frames
    assert set(frames) == {"motion", "joint_forces", "torque_power", "shaking", "energy"}
    torque = frames["torque_power"]
    assert isinstance(torque, pd.DataFrame) and len(torque) == 360
    assert "driving_torque [N*m]" in torque.columns
    assert result.scalars["driving_torque.max_abs"]["unit"] == "N*m"
    summary = result.summary_frame()
    assert list(summary.columns) == ["key", "quantity", "value", "unit"]
    assert isinstance(result.scalars_frame(), pd.DataFrame)


def test_run_problem_accepts_a_path_and_echoes_the_file(tmp_path):
    path = ROOT / "examples" / "four_bar.toml"
    result = run_problem(path)
    assert result.problem_text == path.read_text()
    written = result.write(tmp_path)
    assert {p.name for p in written} >= {"results.json", "report.html", "motion.csv"}


def test_shaking_moment_about_a_point_and_harmonics():
    text = (ROOT / "examples" / "slider_crank.toml").read_text().replace(
        'shaking_moment_about = ["0 mm", "0 mm"]', 'shaking_moment_about = ["100 mm", "0 mm"]'
    )
    result = run_problem(load_problem(text))
    import numpy as np

    moment = result.analysis.forces.shaking_moment(about=(0.1, 0.0))
    # The run's peak is the closed form's, between the samples: at least the largest sample and within the
    # series' change over half a step of it.
    peak, sampled = result.scalars["shaking_moment.max_abs"]["value"], np.max(np.abs(moment))
    assert sampled * (1 - 1e-12) <= peak == pytest.approx(sampled, rel=2e-3)
    assert result.frames["shaking"]["shaking_moment [N*m]"].to_numpy() == pytest.approx(moment)
    assert "driving_torque.harmonic_6.amplitude" in result.scalars
    assert "driving_torque.harmonic_7.amplitude" not in result.scalars


def test_default_masses_are_reported():
    text = (ROOT / "examples" / "four_bar.toml").read_text().replace('mass = "0.40 kg"\n', "")
    result = run_problem(load_problem(text))
    assert any("No mass given for coupler" in w for w in result.warnings)


def test_check_problem_raises_for_a_linkage_that_cannot_close():
    text = (ROOT / "examples" / "four_bar.toml").read_text().replace('length = "130 mm"', 'length = "400 mm"')
    with pytest.raises(AssemblyError):
        check_problem(load_problem(text))


def test_problem_file_error_lists_paths():
    with pytest.raises(ProblemFileError) as info:
        load_problem('[mechanism]\ntype = "slider_crank"\n[drive]\nspeed = "1 rad/s"\n')
    paths = [p for p, _ in info.value.problems]
    assert paths == ["mechanism.crank", "mechanism.rod"]


def test_screw_conveyor_runs_through_the_same_api():
    result = run_problem(ROOT / "examples" / "iodized_salt_conveyor.toml")
    assert result.kind == "screw_conveyor"
    assert set(result.frames) == {"conveyor_span", "conveyor_screw_stress"}, "no crank cycle: the screw's tables"
    assert result.scalars and result.summary_rows


def _doc_blocks() -> list[str]:
    import re

    text = (ROOT / "docs" / "problem-files.md").read_text()
    return re.findall(r"```toml\n(.*?)```", text, flags=re.S)


def test_the_documented_files_are_valid():
    blocks = _doc_blocks()
    linkage, custom, sweep, screen = blocks[:4]  # the complete files; the later blocks are fragments of tables
    assert check_problem(load_problem(linkage)) is not None
    assert check_problem(load_problem(linkage + "\n" + sweep)) is not None
    drive = '[drive]\nspeed = "60 rpm"\n'
    assert check_problem(load_problem(custom + drive)) is not None
    assert check_problem(load_problem(screen)) is not None
