"""Slotted-lever quick returns: closed forms against the engine's kinematics, synthesis round trips, the problem
file, its command line and its report."""

from __future__ import annotations

import numpy as np
import pytest
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.errors import InputError
from machdyn.linkage import kinematics
from machdyn.report.slotted_lever import sections
from machdyn.runner import run_problem
from machdyn.synthesis.slotted_lever import (
    measure,
    return_angle,
    slotted_lever,
    whitworth,
    whitworth_time_ratio,
)

SHAPER = """
[meta]
name = "shaper"

[synthesis]
task = "{task}"
stroke = "300 mm"
time_ratio = {ratio}
candidates = 3
"""


@pytest.mark.parametrize(("ratio", "stroke"), [(1.4, 0.2), (2.0, 0.45), (2.8, 0.1)])
def test_slotted_lever_synthesis_has_its_time_ratio_and_stroke_by_the_engine(ratio, stroke):
    """Two methods: the synthesis inverts the closed forms; the engine's kinematics of the built linkage (ram
    velocity roots, no closed form) give back the time ratio and stroke to 1e-9."""
    design = slotted_lever(ratio, stroke, 0.3 * stroke)
    m = measure(design)
    assert m.time_ratio == pytest.approx(ratio, rel=1e-9)
    assert m.stroke == pytest.approx(stroke, rel=1e-9)
    # the crank is at right angles to the lever at both dead positions (Khurmi & Gupta, fig. 5.23)
    for angle in m.dead_angles:
        kin = kinematics(design.mechanism(), np.array([angle]), 1.0)
        pin = complex(kin.point("crank.A").x[0], kin.point("crank.A").y[0])
        lever = pin - design.centre_distance
        assert abs((pin * np.conj(lever)).real) < 1e-9 * abs(pin) * abs(lever)


@pytest.mark.parametrize(("ratio", "stroke", "crank"), [(1.3, 0.2, 0.05), (2.0, 0.3, 0.1), (3.5, 0.4, 0.2)])
def test_whitworth_synthesis_has_its_time_ratio_and_stroke_by_the_engine(ratio, stroke, crank):
    design = whitworth(ratio, stroke, crank)
    m = measure(design)
    assert m.time_ratio == pytest.approx(ratio, rel=1e-9)
    assert m.stroke == pytest.approx(stroke, rel=1e-9)
    assert whitworth_time_ratio(design.crank, design.centre_distance) == pytest.approx(ratio, rel=1e-12)
    # the ram stops when the crank pin crosses the line of stroke: x = d
    for angle in m.dead_angles:
        assert crank * np.cos(angle) == pytest.approx(design.centre_distance, rel=1e-9)


def test_the_cutting_speed_follows_the_lever_at_mid_stroke():
    """Hand formula: at mid cutting stroke the pin is farthest from the lever's pivot (d + r), the lever turns at
    omega r / (d + r) and the ram, driven square by the lever's end, moves at omega l r / (d + r)."""
    d = slotted_lever(2.0, 0.45, 0.24)
    kin = kinematics(d.mechanism(), np.array([np.pi]), 1.0)
    assert abs(kin.point("ram.R").vy[0]) == pytest.approx(d.lever * d.crank / (d.centre_distance + d.crank),
                                                          rel=1e-12)
    m = measure(d)
    # the slot force per unit ram force there is l / (d + r); elsewhere in the cutting stroke it is larger
    assert m.slot_force_per_ram_force >= d.lever / (d.centre_distance + d.crank) * (1 - 1e-9)


def test_bad_designs_are_refused_with_the_rule():
    with pytest.raises(InputError, match="time ratio"):
        return_angle(1.0)
    with pytest.raises(InputError, match="reach past"):
        slotted_lever(2.0, 0.3, 0.3)
    with pytest.raises(InputError, match="longer than the lever"):
        whitworth(2.0, 0.3, 0.1, rod=0.1)


@pytest.mark.parametrize("task", ["slotted_lever", "whitworth"])
def test_problem_file_runs_and_reports(task, tmp_path):
    path = tmp_path / "shaper.toml"
    path.write_text(SHAPER.format(task=task, ratio=1.8), encoding="utf-8")
    run = run_problem(path)
    s = run.scalars
    assert s["synthesis.best.time_ratio"]["value"] == pytest.approx(1.8, rel=1e-9)
    assert s["synthesis.best.stroke"] == {"value": pytest.approx(0.3, rel=1e-9), "unit": "m",
                                          "shown": {"value": pytest.approx(300.0, rel=1e-9), "unit": "mm"}}
    outcome = run.outcomes["synthesis"]
    slots = outcome.series["synthesis_candidates"]["slot_force_per_ram_force"][0]
    assert np.all(np.diff(slots) >= 0.0)  # ranked: smallest slot force first
    html = sections(outcome.results)[0][1]
    assert "<svg" in html and "slot force" in html


@pytest.mark.parametrize(("body", "field"), [
    ('time_ratio = 1.0', "synthesis.time_ratio"),
    ('time_ratio = 2.0\nrod = "10 mm"', "synthesis.rod"),
])
@pytest.mark.parametrize("task", ["slotted_lever", "whitworth"])
def test_check_and_run_refuse_the_same_bad_input(task, body, field, tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text(f'[meta]\nname = "bad"\n\n[synthesis]\ntask = "{task}"\nstroke = "300 mm"\n{body}\n',
                    encoding="utf-8")
    runner = CliRunner()
    checked = runner.invoke(app, ["check", str(path)])
    ran = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "out"), "--quiet"])
    assert checked.exit_code == 2 and ran.exit_code == 2
    assert field in checked.stderr and field in ran.stderr
    assert "Traceback" not in checked.output + ran.output
