"""Property tests: power rises with length, throughput and inclination; a design meets its own duty."""

import math

from hypothesis import given, settings
from hypothesis import strategies as st

from machdyn.conveyor import design, power, tables
from machdyn.errors import InputError

flows = st.floats(0.05, 20.0)  # kg/s
lengths = st.floats(1.0, 60.0)
angles = st.floats(0.0, math.radians(20))
lambdas = st.floats(1.2, 4.0)
diameters = st.sampled_from(tables.standard_diameters()[:8])


def _all_methods(m, length, beta, d, lam):
    vol = m / 1200.0
    lift = length * math.sin(beta)
    return [
        power.power_textbook_360(m, length, lift, lam),
        power.power_textbook_367(m, length, lift, lam),
        power.power_iso7119(m, length, beta, d, lam).total,
        power.power_cema(volume_flow=vol, bulk_density=1200.0, length=length, speed=45 / math.sqrt(d) * math.pi / 30,
                         diameter_factor=55.0, hanger_bearing_factor=1.7, material_factor=1.0, lift=lift,
                         efficiency=0.9).total_watts,
    ]


@settings(max_examples=40, deadline=None)
@given(flows, lengths, angles, diameters, lambdas, st.floats(1.01, 3.0))
def test_power_rises_with_length(m, length, beta, d, lam, k):
    before = _all_methods(m, length, beta, d, lam)
    after = _all_methods(m, length * k, beta, d, lam)
    assert all(a > b for a, b in zip(after, before, strict=True))


@settings(max_examples=40, deadline=None)
@given(flows, lengths, angles, diameters, lambdas, st.floats(1.01, 3.0))
def test_power_rises_with_throughput(m, length, beta, d, lam, k):
    before = _all_methods(m, length, beta, d, lam)
    after = _all_methods(m * k, length, beta, d, lam)
    assert all(a > b for a, b in zip(after, before, strict=True))


@settings(max_examples=40, deadline=None)
@given(flows, lengths, st.floats(0.0, math.radians(19)), diameters, lambdas, st.floats(0.001, math.radians(1)))
def test_power_rises_with_inclination(m, length, beta, d, lam, dbeta):
    before = _all_methods(m, length, beta, d, lam)
    after = _all_methods(m, length, beta + dbeta, d, lam)
    assert all(a > b for a, b in zip(after, before, strict=True))


@settings(max_examples=60, deadline=None)
@given(st.floats(0.01, 30.0), st.floats(400.0, 2500.0), st.floats(0.15, 1.0), st.sampled_from([30.0, 45.0, 60.0]),
       st.floats(0.5, 1.2), st.floats(0.65, 1.0))
def test_design_meets_its_own_duty(m, rho, phi, k, s, c):
    try:
        des = design.design_screw(mass_flow=m, bulk_density=rho, filling=phi, speed_coefficient=k,
                                  pitch_ratio=s, inclination_factor=c)
    except InputError:
        # only when even the largest standard screw at its speed limit cannot carry the duty
        big = tables.standard_diameters()[-1]
        assert design.volume_capacity(big, s * big, angular_speed=design.speed_limit(big, k), filling=phi,
                                          inclination_factor=c) * rho < m
        return
    assert des.capacity_mass >= m * (1 - 1e-9)
    assert des.speed <= des.speed_limit * (1 + 1e-12)
    assert des.diameter >= des.diameter_required
    assert des.filling_actual <= phi * (1 + 1e-9)
    # the required diameter is exactly the one that carries the duty at the speed limit
    d = des.diameter_required
    cap = design.volume_capacity(d, s * d, angular_speed=design.speed_limit(d, k), filling=phi,
                                 inclination_factor=c) * rho
    assert math.isclose(cap, m, rel_tol=1e-9)
