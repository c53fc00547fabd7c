"""The equivalent machine against the engine: J = 2T/omega^2, exact dJ/dphi against finite differences, the
reduced moment against the engine's, speed-dependent loads against their power."""

import numpy as np
import pytest

from machdyn.dynamics import LinearDamper, RotaryDamper, SpeedForce, equivalent_machine
from machdyn.linkage import energy, four_bar, slider_crank, stack_designs


@pytest.mark.parametrize("build", [
    lambda: four_bar(0.04, 0.12, 0.08, 0.1),
    lambda: slider_crank(0.05, 0.2, 0.01, masses=(1.0, 2.0, 5.0)),
])
def test_inertia_and_moment_match_the_engine(build):
    mech = build()
    eq = equivalent_machine(mech, 240)
    phi = np.linspace(0.05, 6.2, 23)  # between the nodes
    en = energy(mech, phi, 3.0, 0.0)
    j = en.reduced_inertia
    assert np.allclose(eq.inertia(phi), j, rtol=1e-10, atol=0)
    assert np.allclose(eq.position_moment(phi), en.reduced_moment, rtol=1e-9, atol=1e-12 * np.max(np.abs(j)))


def test_exact_slope_equals_finite_differences(bench_mech):
    eq = equivalent_machine(bench_mech, 180)
    phi = np.linspace(0.1, 6.1, 11)
    h = 1e-5

    def j_engine(p):
        return energy(bench_mech, p, 1.0, 0.0).reduced_inertia

    fd = (j_engine(phi + h) - j_engine(phi - h)) / (2 * h)
    # central differences: error ~ h^2 J''' ~ 1e-10 of the slope scale
    scale = np.max(np.abs(fd))
    assert np.max(np.abs(eq.inertia.derivative(phi) - fd)) < 1e-7 * scale


def test_design_variants_reduce_like_single_designs():
    cranks = [0.035, 0.04, 0.045]
    stacked = stack_designs([four_bar(c, 0.12, 0.08, 0.1) for c in cranks])
    eq = equivalent_machine(stacked, 180)
    phi = np.array([0.3, 1.7, 4.0])
    for i, c in enumerate(cranks):
        single = equivalent_machine(four_bar(c, 0.12, 0.08, 0.1), 180)
        assert np.allclose(eq.inertia(np.full(3, phi[i]))[i], single.inertia(phi[i]), rtol=1e-12)


def test_speed_loads_reduce_through_velocity_ratios(bench_mech):
    law_c = 3.0

    def viscous(phi, vx, vy):
        return -law_c * vx, -law_c * vy

    loads = (LinearDamper("damper", "coupler.B", "ground.D", 2.0), RotaryDamper("bearing", "crank", 0.05),
             SpeedForce("drag", "coupler.B", viscous))
    eq = equivalent_machine(bench_mech, 240, speed_loads=loads)
    phi, w = np.linspace(0.2, 6.0, 9), 7.0
    from machdyn.linkage import kinematics

    kin = kinematics(bench_mech, phi, w, 0.0)
    b, d = kin.point("coupler.B"), kin.point("ground.D")
    dx, dy = b.x - d.x, b.y - d.y
    rate = (dx * b.vx + dy * b.vy) / np.hypot(dx, dy)
    power = -2.0 * rate**2 - 0.05 * w * w - law_c * (b.vx**2 + b.vy**2)
    m, dm = eq.speed_moment(phi, w)
    assert np.allclose(m, power / w, rtol=1e-9)
    assert np.allclose(dm, power / w**2, rtol=1e-6)  # every load is linear in the speed
    # the slope of the reduced damping is exact too
    h = 1e-5
    fd = (eq.damping(phi + h) - eq.damping(phi - h)) / (2 * h)
    assert np.allclose(eq.damping.derivative(phi), fd, rtol=1e-6, atol=1e-9)
