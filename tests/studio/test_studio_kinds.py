"""The studio on a cam file and a shaft line: a cam's program points and the fields their drags set, its live
answer without the follower's simulation (and with it on Full run), and a shaft line edited through its fields
with its balance recomputed."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from machdyn.reading import read_problem
from machdyn.runner import run_problem
from machdyn.studio.session import Studio

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _studio(tmp_path, example: str) -> Studio:
    path = tmp_path / example
    shutil.copy(EXAMPLES / example, path)
    return Studio(path)


def test_a_cam_opens_editable_with_its_program_points(tmp_path):
    studio = _studio(tmp_path, "feeder_cam.toml")
    assert studio.editable
    live = studio.evaluate({})
    cam = live["cam"]
    # rise 110 deg to 30 mm, dwell 70 deg, return 120 deg, dwell 60 deg: three inner boundaries
    assert [v for p in cam["points"] for v in (p["theta"], p["s"])] == pytest.approx([110, 30, 180, 30, 300, 0])
    first = cam["points"][0]
    assert [(r["key"], r["sign"]) for r in first["x"]] == [("cam.segments[0].angle", 1.0),
                                                           ("cam.segments[1].angle", -1.0)]
    # the stroke end: the rise reaching it and the return leaving it change their lifts together
    assert [(r["key"], r["sign"]) for r in first["y"]] == [("cam.segments[0].lift", 1.0),
                                                           ("cam.segments[2].lift", 1.0)]
    assert cam["points"][2]["y"] == []  # the bottom of the stroke is the base circle
    # the headline is the run's own largest pressure angle; the curves have one value per shown angle
    assert live["headline"]["value"] == pytest.approx(max(abs(v) for v in cam["curves"][1]["y"]), rel=1e-4)
    assert {len(c["y"]) for c in cam["curves"]} == {len(cam["angles"])}
    assert live["deferred"] == ["the simulation of the cam's follower"]
    labels = " | ".join(r["label"] for r in live["summary"])
    assert "lift-off" not in labels.lower()
    # what the live edit leaves out is the file's own switch, [cam.dynamics] simulate = false
    text = (EXAMPLES / "feeder_cam.toml").read_text()
    ran = run_problem(read_problem(text)).outcomes["cam"]
    quick = run_problem(read_problem(text.replace('cam_inertia = "0.004 kg*m^2"',
                                                  'cam_inertia = "0.004 kg*m^2"\nsimulate = false'))).outcomes["cam"]
    assert ran.results.simulation is not None and quick.results.simulation is None
    assert set(ran.scalars) - set(quick.scalars) == {"cam.simulated_max_separation"}
    assert all(quick.scalars[k] == ran.scalars[k] for k in quick.scalars)  # nothing else changes
    # a shorter rise of the same lift is steeper: a larger pressure angle
    steeper = studio.evaluate({"cam.segments[0].angle": "90", "cam.segments[1].angle": "90"})
    assert steeper["headline"]["value"] > live["headline"]["value"]


def test_a_cam_edit_that_breaks_the_program_answers_checks_message(tmp_path):
    studio = _studio(tmp_path, "feeder_cam.toml")
    assert studio.evaluate({})["ok"]
    bad = studio.evaluate({"cam.segments[0].angle": "100"})  # 10 deg short of a full turn
    assert not bad["ok"] and "must fill one turn of the cam, 360 deg" in bad["message"]
    assert studio.last_valid is not None and studio.last_valid["cam"]["points"][0]["theta"] == pytest.approx(110)


def test_a_shaft_line_is_edited_through_its_fields(tmp_path):
    studio = _studio(tmp_path, "shaft_tamper_line.toml")
    assert studio.editable
    apart = {r["label"]: r["value"] for r in studio.evaluate({})["summary"]}
    together = {r["label"]: r["value"] for r in studio.evaluate({"linkages[1].phase": "0"})["summary"]}
    couple = "Shaft line: largest resultant couple about the reference plane"
    force = "Shaft line: largest resultant force on the frame"
    # two equal tampers 600 mm either side of the reference plane: in phase their forces add and their moments
    # about the plane cancel (to rounding of force x lever); half a turn apart the forces cancel to the
    # difference of the tampers' own unbalance and the couple is the tamper's force x 1.2 m
    assert together[couple] < 1e-9 * together[force] * 0.6
    assert apart[couple] > 100 and together[force] > 5 * apart[force]
    bad = studio.evaluate({"linkages[1].phase": "half"})  # judged as check judges a file, beside its field
    assert not bad["ok"] and {"path": "linkages[1].phase", "message": "is not a quantity with a unit; got 'half "
                              "deg' (the unit 'half' is unknown)"} in bad["problems"]
