"""Two-plane balance and the ISO 21940-11 grade of N shaft lines at once equal the single-design functions to
1e-12 (relative to the design's total unbalance), and the designs they refuse are flagged."""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.errors import InputError
from machdyn.shafts.balance import Plane, equivalent_in_planes, two_plane
from machdyn.shafts.grades import GradeCheck, allocate, permissible_unbalance
from machdyn.shafts.population import grade_population, two_plane_population
from machdyn.shafts.rotating import Mass

N, M = 40, 4


def _designs(seed):
    rng = np.random.default_rng(seed)
    mass, radius = rng.uniform(0.1, 5.0, (N, M)), rng.uniform(0.01, 0.2, (N, M))
    angle, position = rng.uniform(0.0, 2 * np.pi, (N, M)), rng.uniform(0.0, 1.0, (N, M))
    return mass, radius, angle, position


def _line(i, mass, radius, angle, position):
    return [Mass(f"m{j}", mass[i, j], radius[i, j], angle[i, j], position[i, j]) for j in range(M)]


def test_two_plane_corrections_of_random_lines_equal_the_single_design_balance():
    mass, radius, angle, position = _designs(5)
    zl = np.random.default_rng(6).uniform(-0.2, 0.1, N)
    zl[0] = 1.2  # the planes coincide: refused
    many = two_plane_population(mass, radius, angle, position, zl, 1.2, 0.1, 0.15)
    assert many["valid"].tolist() == [False] + [True] * (N - 1)
    with pytest.raises(InputError):
        two_plane(_line(0, mass, radius, angle, position), Plane("L", zl[0], 0.1), Plane("M", 1.2, 0.15))
    for i in range(1, N):
        one = two_plane(_line(i, mass, radius, angle, position), Plane("L", zl[i], 0.1), Plane("M", 1.2, 0.15))
        for name, c in zip(("L", "M"), one.corrections, strict=True):
            assert many[f"{name}.mass"][i] == pytest.approx(c.mass, rel=1e-12)
            assert many[f"{name}.angle"][i] == pytest.approx(c.angle, rel=1e-12, abs=1e-12)


def test_the_grades_of_random_rotors_equal_the_single_design_check():
    mass, radius, angle, position = _designs(8)
    rng = np.random.default_rng(9)
    rotor, speed, centre = rng.uniform(50.0, 500.0, N), rng.uniform(50.0, 400.0, N), rng.uniform(0.1, 0.9, N)
    centre[1] = 1.5  # outside the bearings: refused
    many = grade_population(6.3, rotor, speed, centre, 0.0, 1.0, mass, radius, angle, position)
    assert many["valid"].tolist() == [True, False] + [True] * (N - 2)
    with pytest.raises(InputError):
        allocate(1.0, centre[1], 0.0, 1.0)
    for i in [0, *range(2, N)]:
        u_per = permissible_unbalance(6.3, rotor[i], speed[i])
        allowed = allocate(u_per, centre[i], 0.0, 1.0)
        ua, ub = equivalent_in_planes(_line(i, mass, radius, angle, position), 0.0, 1.0)
        one = GradeCheck(6.3, rotor[i], speed[i], u_per, allowed, (abs(ua), abs(ub)), ("A", "B"))
        assert many["U_per"][i] == pytest.approx(one.u_per, rel=1e-12)
        assert many["A.allowed"][i] == pytest.approx(one.allowed[0], rel=1e-12)
        assert many["B.residual"][i] == pytest.approx(one.residual[1], rel=1e-12)
        assert many["margin"][i] == pytest.approx(one.margin, rel=1e-12)
        assert many["achieved_G"][i] == pytest.approx(one.achieved_grade * 1e-3, rel=1e-12)
        assert bool(many["passes"][i]) == one.passes


def test_a_balanced_rotor_has_no_residual_and_passes_its_grade():
    """The corrections of the population form, added to the masses, leave no unbalance (1e-12 of the total)."""
    mass, radius, angle, position = _designs(12)
    done = two_plane_population(mass, radius, angle, position, 0.0, 1.0, 0.1, 0.1)
    with_corrections = [np.hstack([x, np.column_stack(extra)]) for x, extra in
                        ((mass, (done["L.mass"], done["M.mass"])), (radius, (np.full(N, 0.1), np.full(N, 0.1))),
                         (angle, (done["L.angle"], done["M.angle"])), (position, (np.zeros(N), np.ones(N))))]
    graded = grade_population(2.5, 100.0, 300.0, 0.5, 0.0, 1.0, *with_corrections)
    total = np.sum(mass * radius, axis=1)
    assert np.all(graded["A.residual"] <= 1e-12 * total) and np.all(graded["B.residual"] <= 1e-12 * total)
    assert graded["passes"].all()
