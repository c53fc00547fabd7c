"""Results no machine can have are not reported as success: a load that drives the crank far above its nominal
speed is a failed check, and a conveyor file that both gives the screw and asks for the best screw is refused
instead of having its screw silently replaced."""

from __future__ import annotations

import json
import math

from .helpers import EXAMPLES, check_and_run

COMPACTOR = (EXAMPLES / "compactor_flywheel.toml").read_text(encoding="utf-8")
BEST = (EXAMPLES / "conveyor_best_design.toml").read_text(encoding="utf-8")


def test_load_driving_the_crank_far_above_nominal_speed_is_a_failed_check(tmp_path):
    # the compaction force reversed and ten times larger: it puts work into the machine
    text = COMPACTOR.replace('fx = "3 kN"', 'fx = "-30 kN"', 1)
    check, run = check_and_run(tmp_path, text)
    assert check.code == 0 and run.code == 3, (check, run)
    assert "times the nominal 95.49 rpm of [drive]" in run.stderr and "a load drives the machine" in run.stderr
    scalars = json.loads((tmp_path / "out" / "results.json").read_text())["scalars"]
    assert scalars["flywheel.mean_speed"]["value"] > 1.2 * 95.49 * math.pi / 30  # rad/s


def test_machine_near_its_nominal_speed_passes_the_speed_check(tmp_path):
    check, run = check_and_run(tmp_path, COMPACTOR)
    assert run.code == 0, run
    scalars = json.loads((tmp_path / "out" / "results.json").read_text())["scalars"]
    assert abs(scalars["flywheel.mean_speed"]["value"] / (95.49 * math.pi / 30) - 1.0) <= 0.2


def test_conveyor_best_design_that_also_gives_the_screw_is_refused(tmp_path):
    text = BEST.replace('hanger_spacing = "3 m"', 'diameter = "250 mm"\nspeed = "80 rpm"\nhanger_spacing = "3 m"', 1)
    check, run = check_and_run(tmp_path, text)
    assert (check.code, run.code) == (2, 2), (check, run)
    for said in (check, run):
        assert "screw_conveyor.screw.diameter: is chosen by [screw_conveyor.optimise]" in said.stderr
        assert "screw_conveyor.screw.speed: is chosen by [screw_conveyor.optimise]" in said.stderr
