import numpy as np
import pytest

from machdyn.dynamics import InductionMotor, equivalent_machine
from machdyn.linkage import four_bar

RPM = np.pi / 30.0


@pytest.fixture(scope="session")
def bench_mech():
    """The benchmark four-bar: crank 40, coupler 120, rocker 80, ground 100 mm, 1 kg/m bars, gravity on."""
    return four_bar(0.04, 0.12, 0.08, 0.1)


@pytest.fixture(scope="session")
def bench_machine(bench_mech):
    return equivalent_machine(bench_mech, 360)


@pytest.fixture(scope="session")
def motor():
    """A 4-pole motor reduced 15:1 to the crank (about 10 rad/s)."""
    return InductionMotor(rated_power=10.0, rated_speed=1440 * RPM, synchronous_speed=1500 * RPM,
                          breakdown_ratio=2.5, ratio=15.0)
