"""Small machines for the transient tests: an unbalanced rotor and a slider-crank on frames on springs."""

from __future__ import annotations

import numpy as np

from machdyn.linkage import Body, Crank, Mechanism, PointMass, slider_crank
from machdyn.vibration.frame import Frame, Mount


def rotor(unbalance_mass=1.0, eccentricity=0.1, inertia=0.05, gravity=(0.0, 0.0), name="rotor"):
    """A disc turning about the origin with a point mass ``unbalance_mass`` [kg] at ``eccentricity`` [m]."""
    disc = Body("disc", {"O": (0.0, 0.0)}, mass=0.0, inertia=inertia)
    return Mechanism(name, {"O": (0.0, 0.0)}, (disc,), Crank("disc", "ground.O"),
                     point_masses=(PointMass("unbalance", "disc", unbalance_mass, (eccentricity, 0.0)),),
                     gravity=gravity)


def sprung_block(mass=100.0, inertia=25.0, horizontal=2.5e5, vertical=6.1e5, damping=200.0,
                 vertical_damping=0.0, name="block"):
    """A block whose horizontal spring (at its centre, along x) is soft and whose two vertical springs at
    x = +-0.5 m are stiff (bounce and rock near 110 rad/s): the x mode is the one that matters."""
    mounts = (Mount("h", (0.0, 0.0), 0.0, horizontal, damping),
              Mount("v1", (0.5, 0.0), np.pi / 2, vertical, vertical_damping),
              Mount("v2", (-0.5, 0.0), np.pi / 2, vertical, vertical_damping))
    return Frame(mass, inertia, mounts, name=name)


def small_press():
    """A slider-crank of 50 mm crank and 200 mm rod (3 kg of moving parts), without gravity."""
    return slider_crank(0.05, 0.2, masses=(1.0, 1.5, 0.5), inertias=(2e-4, 5e-3, 0.0), gravity=(0.0, 0.0))


def plate(mass=400.0, inertia=60.0, k=4e5, c=1.2e3):
    """A plate on four springs with dampers (two vertical, two horizontal), modes of 4-8 Hz."""
    mounts = (Mount("v1", (0.6, -0.2), np.pi / 2, k, c), Mount("v2", (-0.6, -0.2), np.pi / 2, k, c),
              Mount("h1", (0.6, -0.2), 0.0, 0.6 * k, c), Mount("h2", (-0.6, -0.2), 0.0, 0.6 * k, c))
    return Frame(mass, inertia, mounts, com=(0.0, -0.1))
