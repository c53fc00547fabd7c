"""The population forms of the parts and the clutch equal the single-design functions, design by design, to 1e-12
(relative) on random designs, and flag the designs the single-design functions refuse."""

from __future__ import annotations

import math

import numpy as np
import pytest

from machdyn.drivetrain import population as pop
from machdyn.drivetrain.clutch import engage
from machdyn.drivetrain.fatigue import CRITERIA, fatigue_safety
from machdyn.drivetrain.parts import BearingSpec, LinkSpec, PinSpec, check_key, size_parts
from machdyn.drivetrain.parts_population import parts_population
from machdyn.errors import AssemblyError, InputError
from machdyn.linkage import crank_angles, four_bar, kinematics, kinetostatics

RTOL = 1e-12


def _close(a, b):
    a, b = float(a), float(b)
    if math.isinf(b):
        return a == b
    return abs(a - b) <= RTOL * max(abs(b), 1e-300)


def _parts():
    bearings = (BearingSpec("O", "ball", capacity=30e3, life=2e7), BearingSpec("A", "roller", capacity=40e3),
                BearingSpec("D", "plain", diameter=0.03, length=0.04, max_pressure=20e6, max_pv=2e6))
    pins = (PinSpec("B", 0.012, 0.02, 2, allowable_shear=80e6, allowable_pressure=25e6),)
    links = (LinkSpec("coupler", 4e-4, 2e-6, 150e6, 600e6, criterion="gerber", yield_strength=450e6,
                      notch_factor=1.3, required_cycles=1e7, fraction=0.9),
             LinkSpec("rocker", 3e-4, 1.5e-6, 150e6, 600e6, criterion="asme_elliptic", yield_strength=450e6))
    return {"bearings": bearings, "pins": pins, "links": links}


def test_the_parts_of_random_four_bars_equal_the_single_design_checks():
    """12 random four-bars and one that does not close, one engine call: each check of each design equals
    size_parts of that design; the one the single form refuses (it does not assemble) is flagged, all NaN."""
    rng = np.random.default_rng(7)
    n = 12
    crank, coupler = rng.uniform(0.03, 0.06, n), rng.uniform(0.13, 0.17, n)
    mech = four_bar(np.append(crank, 0.2), np.append(coupler, 0.15), 0.12, 0.14, masses=(1.0, 3.0, 2.0))
    phi = crank_angles(72)
    motion = kinematics(mech, phi, 60.0, on_fail="mask")
    many = parts_population(kinetostatics(mech, kinematics_result=motion), **_parts())
    assert many["valid"].tolist() == [True] * n + [False]
    assert all(np.isnan(v[n]) for k, v in many.items() if k != "valid")
    with pytest.raises(AssemblyError):
        size_parts(kinetostatics(mech.take_designs(n), phi, 60.0), **_parts())
    assert np.all(many["parts.link.coupler.fatigue_damage"][:n] >= 0)
    for i in range(n):
        one = size_parts(kinetostatics(mech.take_designs(i), phi, 60.0), **_parts())
        keys = {check_key(c.part, c.quantity, c.figure): c for c in one.checks}
        assert set(keys) | {"parts.utilisation.max", "valid"} == set(many)
        for key, check in keys.items():
            assert _close(many[key][i], check.value), key
        assert _close(many["parts.utilisation.max"][i], max(c.utilisation for c in one.checks))


def test_a_rolling_bearing_that_does_not_turn_is_flagged_as_the_single_form_refuses_it():
    """A rolling bearing between two bodies turning together makes no revolution: the single form raises, the
    population gives NaN and valid False for that design alone."""
    load = np.ones((3, 8))
    turned = np.vstack([np.full(8, 0.1), np.zeros(8), np.full(8, 0.2)])
    life, _fm, ok = pop.rolling_bearing_life(load, turned, 1.0, 1e3)
    assert ok.tolist() == [True, False, True] and np.isnan(life[1])


def test_the_fatigue_factors_of_random_stresses_equal_the_scalar_criteria():
    rng = np.random.default_rng(3)
    amp = rng.uniform(0.0, 200e6, 200)
    mean = rng.uniform(-200e6, 300e6, 200)
    amp[:3], mean[:3] = 0.0, (0.0, 100e6, -50e6)  # zero amplitude, zero stress
    for criterion in CRITERIA:
        fat, yld = pop.fatigue_safety_arrays(amp, mean, 150e6, 600e6, 450e6, criterion)
        for i in range(amp.size):
            if amp[i] + abs(mean[i]) >= 600e6:
                with pytest.raises(InputError):
                    fatigue_safety(amp[i], mean[i], 150e6, 600e6, 450e6, criterion)
                assert np.isnan(fat[i]) and np.isnan(yld[i])
                continue
            one = fatigue_safety(amp[i], mean[i], 150e6, 600e6, 450e6, criterion)
            assert _close(fat[i], one.fatigue) and _close(yld[i], one.yielding), (criterion, i)


def test_clutch_engagements_of_random_designs_equal_engage_and_refused_ones_are_flagged():
    rng = np.random.default_rng(11)
    n = 50
    j1, j2 = rng.uniform(0.5, 5.0, n), rng.uniform(0.1, 3.0, n)
    w1, w2 = rng.uniform(50.0, 150.0, n), rng.uniform(-10.0, 60.0, n)
    tc, t1, t2 = rng.uniform(50.0, 300.0, n), rng.uniform(-50.0, 60.0, n), rng.uniform(-20.0, 80.0, n)
    j1[0], w2[1], t2[2] = -1.0, 200.0, 400.0  # refused: a negative inertia, a slower driving side, slip for ever
    many = pop.engage_population(j1, w1, j2, w2, tc, t1, t2)
    for i in range(n):
        try:
            one = engage(j1[i], w1[i], j2[i], w2[i], tc[i], driving_torque=t1[i], load_torque=t2[i])
        except InputError:
            assert not many["valid"][i] and np.isnan(many["slip_time"][i])
            continue
        assert many["valid"][i]
        for name in ("slip_time", "common_speed", "dissipated", "driving_angle", "driven_angle", "driving_work",
                     "load_work", "driven_acceleration", "driving_deceleration"):
            assert _close(many[name][i], getattr(one, name)), (name, i)
    assert not many["valid"][:3].any()



def test_the_exact_largest_moment_of_a_link_bounds_a_dense_sampling_of_it():
    """The moment M(s) of 200 random links under random linear loads: its largest magnitude by the roots of M' is
    that of 20001 samples along the link to their resolution (1e-8 of the peak for a cubic over a step of 5e-5)
    and never below it."""
    from types import SimpleNamespace as S

    from machdyn.drivetrain.strength import link_section_loads

    rng = np.random.default_rng(4)
    n = 200
    mass = rng.uniform(0.5, 5.0, n)
    a = S(x=np.zeros(n), y=np.zeros(n), ax=rng.normal(0, 50, n), ay=rng.normal(0, 50, n))
    b = S(x=rng.uniform(0.1, 1.0, n), y=rng.uniform(-0.5, 0.5, n), ax=rng.normal(0, 50, n), ay=rng.normal(0, 50, n))
    _axial, m = link_section_loads(a, b, (np.zeros(n), np.zeros(n)), mass)
    length = np.hypot(b.x, b.y)
    nx, ny = -b.y / length, b.x / length
    q0, q1 = -mass / length * (a.ax * nx + a.ay * ny), -mass / length * (b.ax * nx + b.ay * ny)
    s = np.linspace(0.0, 1.0, 20001)[:, None]
    sampled = length**2 * (q0 / 3 + q1 / 6) * s - length**2 * (q0 * s**2 / 2 + (q1 - q0) * s**3 / 6)
    peak = sampled[np.argmax(np.abs(sampled), axis=0), np.arange(n)]
    assert np.all(np.abs(m) >= np.abs(peak) * (1 - 1e-12))
    np.testing.assert_allclose(m, peak, rtol=1e-8)
