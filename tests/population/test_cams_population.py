"""The cams' population form against the single-design run: the exact largest pressure angle, smallest convex
radius of curvature of the pitch curve, smallest base circle meeting the pressure-angle limit and the checks'
failures of N random translating cams (roller and knife edge) equal ``profile`` + ``check_cam`` design by design
to 1e-12 (relative), for the harmonic, cycloidal, 3-4-5, modified trapezoid, modified sine and table laws; and the
designs the single run refuses (not assembling, bad sizes) are flagged, not computed."""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.cams.checks import check_cam
from machdyn.cams.followers import Follower
from machdyn.cams.geometric import rise_angle
from machdyn.cams.population import analyse_population
from machdyn.cams.profile import profile
from machdyn.cams.program import Segment, program
from machdyn.errors import InputError

D = np.radians
LIMIT = D(35.0)
TABLE = ((0.25, 0.1), (0.5, 0.55), (0.8, 0.93))
# one rise law per case; the return is cycloidal and the dwells give constant pieces
LAWS = ("harmonic", "cycloidal", "poly345", "modified_trapezoid", "modified_sine", "table")
N = 50


def _program(law: str, lift: float):
    points = TABLE if law == "table" else ()
    return program([Segment("rise", D(60), lift, law, points=points), Segment("dwell", D(110)),
                    Segment("return", D(130), lift, "cycloidal"), Segment("dwell", D(60))])


def _single(law, lift, rb, rr, e, factor):
    prog = _program(law, lift)
    follower = Follower("translating", "roller" if rr > 0 else "knife", rb, rr, e)
    return check_cam(profile(prog, follower, np.radians(np.arange(0.0, 360.0, 4.0))), prog,
                     pressure_limit=LIMIT, curvature_factor=factor)


def _relative(a: float, b: float) -> float:
    if np.isinf(a) and np.isinf(b):
        return 0.0
    return abs(a - b) / max(abs(b), 1e-300)


@pytest.mark.parametrize("law", LAWS)
def test_the_population_equals_each_design_checked_alone_to_1e_12(law):
    rng = np.random.default_rng(LAWS.index(law) + 11)
    # sizes from comfortable to undercut and steep: base circles of 10-100 mm, rollers up to 30 mm, lifts of 9-60 mm
    rb, rr = rng.uniform(0.01, 0.1, N), rng.uniform(0.0, 0.03, N)
    rr[::7] = 0.0  # knife edges among the rollers
    e, k = rng.uniform(-0.6, 0.6, N) * (rb + rr), rng.uniform(0.3, 2.0, N)
    factor = 1.5
    theta = np.radians(np.arange(0.0, 360.0, 4.0))
    pop = analyse_population(_program(law, 0.03), theta, rb, rr, e, k, LIMIT, factor)
    assert pop.valid.all()
    worst = 0.0
    for i in range(N):
        one = _single(law, 0.03 * k[i], rb[i], rr[i], e[i], factor)
        worst = max(worst, _relative(pop.max_pressure_angle[i], one.max_pressure_angle),
                    _relative(pop.min_pitch_curvature_radius[i], one.min_pitch_radius),
                    _relative(pop.min_base_radius_pressure[i], one.min_base_radius_pressure))
        assert pop.pressure_failed[i] == any(f.startswith("pressure angle") for f in one.failed)
        assert pop.undercut[i] == any(f.startswith("undercut") for f in one.failed)
        assert pop.curvature_failed[i] == any("radius of curvature of the pitch curve" in f for f in one.failed)
    assert worst <= 1e-12
    # the random designs reach both sides of every check
    assert 0 < pop.pressure_failed.sum() < N
    assert 0 < pop.curvature_failed.sum() < N


def test_the_pressure_angles_at_the_given_angles_are_each_designs_profile():
    prog, theta = _program("poly345", 0.03), np.radians(np.arange(0.0, 360.0, 2.0))
    rb, rr, e, k = np.array([0.03, 0.05]), np.array([0.01, 0.0]), np.array([0.005, -0.01]), np.array([0.7, 1.2])
    pop = analyse_population(prog, theta, rb, rr, e, k)
    for i in range(2):
        alone = profile(_program("poly345", 0.03 * k[i]),
                        Follower("translating", "roller" if rr[i] else "knife", rb[i], rr[i], e[i]), theta)
        np.testing.assert_allclose(pop.pressure_angle[i], alone.pressure_angle, rtol=0, atol=1e-12)


def test_designs_the_single_run_refuses_are_flagged_and_not_computed():
    prog = _program("cycloidal", 0.03)
    # good; offset = prime radius (does not assemble); offset beyond it; base radius 0; negative roller;
    # lift scale 0; a NaN; good again
    rb = np.array([0.05, 0.03, 0.02, 0.0, 0.04, 0.04, np.nan, 0.04])
    rr = np.array([0.01, 0.01, 0.01, 0.01, -0.01, 0.01, 0.01, 0.0])
    e = np.array([0.0, 0.04, -0.05, 0.0, 0.0, 0.0, 0.0, 0.01])
    k = np.array([1.0, 1.0, 1.0, 1.0, 1.0, 0.0, 1.0, 1.0])
    pop = analyse_population(prog, np.radians(np.arange(0.0, 360.0, 5.0)), rb, rr, e, k)
    np.testing.assert_array_equal(pop.valid, [True, False, False, False, False, False, False, True])
    bad = ~pop.valid
    for field in (pop.max_pressure_angle, pop.min_pitch_curvature_radius, pop.min_base_radius_pressure):
        assert np.isnan(field[bad]).all() and np.isfinite(field[~bad]).all()
    assert np.isnan(pop.pressure_angle[bad]).all()
    assert not (pop.pressure_failed[bad] | pop.undercut[bad] | pop.curvature_failed[bad]).any()
    # the single run refuses the same designs with an error naming the rule
    for i in (1, 2):
        with pytest.raises(InputError, match="too small to assemble"):
            Follower("translating", "roller", rb[i], rr[i], e[i])
    with pytest.raises(InputError, match="base_radius must be > 0"):
        Follower("translating", "roller", rb[3], rr[3], e[3])
    # the good designs are those of the single run
    one = _single("cycloidal", 0.03, rb[7], rr[7], e[7], 1.0)
    assert pop.max_pressure_angle[7] == pytest.approx(one.max_pressure_angle, rel=1e-12)


def test_an_undercut_design_is_flagged_as_the_single_run_fails_it():
    """A 40 mm roller on a 20 mm base circle with a 45 mm harmonic rise over 60 deg: the pitch curve where the rise
    ends is sharper than the roller (the single run reports "undercut"); a 5 mm roller on a 90 mm circle is not."""
    prog = _program("harmonic", 0.045)
    pop = analyse_population(prog, np.radians(np.arange(0.0, 360.0, 5.0)), [0.02, 0.09], [0.04, 0.005])
    one = _single("harmonic", 0.045, 0.02, 0.04, 0.0, 1.0)
    assert any(f.startswith("undercut") for f in one.failed)
    np.testing.assert_array_equal(pop.undercut, [True, False])
    assert pop.min_pitch_curvature_radius[0] == pytest.approx(one.min_pitch_radius, rel=1e-12)


def test_bad_arguments_are_refused_naming_the_rule():
    prog = _program("cycloidal", 0.03)
    with pytest.raises(InputError, match="differ in length"):
        analyse_population(prog, [0.0], [0.05, 0.06], [0.01, 0.01, 0.01])
    with pytest.raises(InputError, match="pressure_limit"):
        analyse_population(prog, [0.0], 0.05, 0.01, pressure_limit=D(90.0))
    shape = (0.02, 0.008, 0.01)  # base, nose and roller radius [m] of a tangent cam
    rise = rise_angle("tangent", shape[0], shape[1], 0.01, shape[2])
    tangent = program([Segment("rise", rise, 0.01, "tangent", contour=shape), Segment("dwell", D(180) - rise),
                       Segment("return", D(120), 0.01, "cycloidal"), Segment("dwell", D(60))])
    with pytest.raises(InputError, match="tangent law follows from one cam's own base circle"):
        analyse_population(tangent, [0.0], 0.02, 0.01)


def test_chunks_of_designs_give_the_whole_population_s_results(monkeypatch):
    """The designs are evaluated in chunks (bounded memory): chunks of 7 give the results of one pass, bit for bit;
    no cam angles give no per-angle array and the same extremes."""
    import machdyn.cams.population as population

    rng = np.random.default_rng(2)
    n = 40
    args = (_program("poly345", 0.03), np.radians(np.arange(0.0, 360.0, 10.0)), rng.uniform(0.03, 0.08, n),
            rng.uniform(0.0, 0.02, n), rng.uniform(-0.01, 0.01, n), rng.uniform(0.5, 1.5, n))
    whole = population.analyse_population(*args)
    monkeypatch.setattr(population, "CHUNK_DESIGNS", 7)
    chunked = population.analyse_population(*args)
    for field in ("max_pressure_angle", "min_pitch_curvature_radius", "min_base_radius_pressure", "pressure_angle"):
        np.testing.assert_array_equal(getattr(chunked, field), getattr(whole, field))
    bare = population.analyse_population(args[0], [], *args[2:])
    assert bare.pressure_angle.shape == (n, 0)
    np.testing.assert_array_equal(bare.max_pressure_angle, whole.max_pressure_angle)
