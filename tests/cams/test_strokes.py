"""Each rise's and return's own exact extremes (``cam.segment<n>.<figure>``): the largest of the strokes' peaks is
the turn's exact peak, each agrees with a dense sampling of its own segment (never below it), the keys reach the
run's results, the report's table and the studies' checks, with a did-you-mean for a wrong one."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from machdyn.cams.dynamics import FollowerTrain, Spring, cam_forces
from machdyn.cams.exact import extremes
from machdyn.cams.followers import Follower
from machdyn.cams.profile import profile
from machdyn.cams.program import Segment, program
from machdyn.cams.strokes import strokes
from machdyn.errors import ProblemFileError
from machdyn.runner import check_problem, run_problem

ROOT = Path(__file__).resolve().parents[2]
FEEDER = ROOT / "examples" / "feeder_cam.toml"
SPEED = 200 * math.pi / 30

# A program with a law of each kind of piece: harmonic (its acceleration jumps at the dwells), cycloidal,
# modified trapezoid (five pieces), parabolic (two) and a 3-4-5 return.
PROGRAM = program([Segment("rise", math.radians(80), 0.025, "harmonic"), Segment("dwell", math.radians(30)),
                   Segment("return", math.radians(70), 0.010, "cycloidal"),
                   Segment("rise", math.radians(60), 0.010, "modified_trapezoid"),
                   Segment("return", math.radians(60), 0.012, "parabolic"),
                   Segment("return", math.radians(60), 0.013, "poly345")])
ROLLER = Follower("translating", "roller", 0.04, 0.01, 0.006)
TRAIN = FollowerTrain(2.0, damping=12.0, load=15.0)
SPRING = Spring(2.0e4, 60.0)


@pytest.fixture(scope="module")
def each():
    return strokes(PROGRAM, ROLLER, SPEED, TRAIN, SPRING)


def test_every_rise_and_return_is_a_stroke_named_by_its_segment(each):
    assert [(s.number, s.motion) for s in each] == [(1, "rise"), (3, "return"), (4, "rise"), (5, "return"),
                                                    (6, "return")]
    assert each[0].key("max_velocity") == "cam.segment1.max_velocity"
    for s in each:
        assert s.start < s.end and all(s.start - 1e-12 <= at <= s.end + 1e-12 for at in s.where.values())


def test_the_largest_stroke_peaks_are_the_turns_exact_extremes(each):
    """The pressure angle and the convex radius of curvature: the same exact search as the cam's checks."""
    ext = extremes(PROGRAM, ROLLER)
    assert max(s.figures["max_pressure_angle"] for s in each) == pytest.approx(ext.max_pressure_angle, rel=1e-12)
    assert min(s.figures.get("min_pitch_curvature_radius", np.inf) for s in each) == pytest.approx(
        ext.min_convex_radius, rel=1e-12)


def test_each_stroke_agrees_with_a_dense_sampling_of_its_own_segment(each):
    """40 001 samples of each segment through the program's own svaj, the profile and the forces: the exact peak
    is never below a sample and within 1e-6 (relative) of the best (the samples include each end, just inside);
    the harmonic rise's acceleration peaks at its ends, h (π/β)²/2 ω², and the cycloid's velocity at its middle,
    2 h/β ω (closed forms)."""
    for s in each:
        # 40 001 angles from just inside one end to just inside the other: each end on the segment's own side
        theta = s.start + (s.end - s.start) * np.linspace(1e-10, 1 - 1e-10, 40_001)
        m = PROGRAM.svaj(theta)
        prof = profile(PROGRAM, ROLLER, theta)
        f = cam_forces(PROGRAM, TRAIN, SPRING, SPEED, theta, prof.pressure_angle)
        convex = prof.pitch_curvature_radius[prof.pitch_curvature_radius > 0]
        sampled = {"max_velocity": np.max(np.abs(m.v)) * SPEED,
                   "max_acceleration": np.max(np.abs(m.a)) * SPEED**2, "max_jerk": np.max(np.abs(m.j)) * SPEED**3,
                   "max_pressure_angle": np.max(np.abs(prof.pressure_angle)),
                   "max_contact_force": np.max(f.contact), "max_normal_force": np.max(f.normal),
                   "peak_torque": np.max(np.abs(f.torque))}
        for name, value in sampled.items():
            assert s.figures[name] >= value * (1 - 1e-9), (s.number, name)  # the search stops at 1e-12 of x
            assert s.figures[name] == pytest.approx(value, rel=1e-6), (s.number, name)
        if convex.size:
            assert s.figures["min_pitch_curvature_radius"] <= np.min(convex) * (1 + 1e-12)
            # the parabolic return's smallest radius lies at its end, where the law's acceleration jumps; there the
            # sampled profile's radius converges slowly (6e-6 off at 40 001 samples, 6e-7 at 400 001)
            assert s.figures["min_pitch_curvature_radius"] == pytest.approx(np.min(convex), rel=1e-5)
    harmonic, cycloid = each[0], each[1]
    assert harmonic.figures["max_acceleration"] == pytest.approx(
        0.025 / 2 * (math.pi / math.radians(80)) ** 2 * SPEED**2, rel=1e-9)
    assert cycloid.figures["max_velocity"] == pytest.approx(2 * 0.010 / math.radians(70) * SPEED, rel=1e-9)


def test_a_flat_face_reports_its_radius_and_no_pressure_angle():
    flat = Follower("translating", "flat", 0.03)
    [rise, back] = strokes(PROGRAM, flat, SPEED)[:2]
    assert "max_pressure_angle" not in rise.figures and "max_contact_force" not in rise.figures
    ext = extremes(PROGRAM, flat)
    assert min(s.figures["min_surface_curvature_radius"] for s in strokes(PROGRAM, flat, SPEED)) == pytest.approx(
        ext.min_flat_radius, rel=1e-12)
    assert back.figures["max_velocity"] < rise.figures["max_velocity"]


@pytest.fixture(scope="module")
def feeder():
    return run_problem(FEEDER)


def test_a_run_reports_each_stroke_and_the_largest_is_the_turns_peak(feeder):
    """The feeder cam (cycloidal rise, 3-4-5 return): its run's scalars carry segments 1 and 3, not the dwells;
    the turn's results, sampled at 720 angles, lie at or below the strokes' largest and within 1e-4 of it."""
    scalars = feeder.results.values
    keys = {k for k in scalars if k.startswith("cam.segment")}
    assert {k.split(".")[1] for k in keys} == {"segment1", "segment3"}
    for figure in ("max_velocity", "max_acceleration", "max_contact_force", "peak_torque"):
        top = max(scalars[f"cam.segment{n}.{figure}"] for n in (1, 3))
        assert scalars[f"cam.{figure}"] <= top * (1 + 1e-12)
        assert scalars[f"cam.{figure}"] == pytest.approx(top, rel=1e-4)
    assert max(scalars[f"cam.segment{n}.max_pressure_angle"] for n in (1, 3)) == pytest.approx(
        scalars["cam.max_pressure_angle"], rel=1e-12)
    assert feeder.results.label("cam.segment3.max_pressure_angle").display == "deg"


def test_the_report_tabulates_the_strokes(feeder, tmp_path):
    from machdyn.report.cams import stroke_table

    html = stroke_table(feeder.outcomes["cam"].results)
    assert html.count("<tr") == 3 and "peak |v|" in html and "largest |φ|" in html and "return" in html


def test_a_study_accepts_a_stroke_and_refuses_a_wrong_one_with_its_nearest():
    text = FEEDER.read_text(encoding="utf-8")
    good = text + ('\n[sweep]\nparameter = "cam.base_radius"\nvalues = ["40 mm"]\n'
                   'columns = ["cam.segment3.max_acceleration"]\n')
    check_problem(good)
    with pytest.raises(ProblemFileError) as bad:
        check_problem(good.replace("cam.segment3.max_acceleration", "cam.segment2.max_acceleration"))
    [(path, message)] = bad.value.problems
    assert path == "sweep.columns[0]"
    assert "is not a result of this cam file; did you mean 'cam.segment" in message
