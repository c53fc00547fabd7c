"""Gravity's pendulum term in the stiffness of a frame on mounts: the rocking frequency of a simple block.

A block of mass m and centroidal inertia I on two vertical springs k at +-a, their line of action a height h below
its centre of mass, and a horizontal spring at the height of the centre (so that sliding does not couple with
rocking). Rocking by theta about the centre lowers the centre of the weight W = m g relative to the springs'
preloaded attachment points by W h theta^2 / 2 while the springs store k a^2 theta^2 (twice): Lagrange gives
I theta'' + (2 k a^2 - W h) theta = 0, omega^2 = (2 k a^2 - W h) / I — the inverted pendulum's destabilising
-W h (Den Hartog, *Mechanical Vibrations*, 4th ed., 1956, ch. 1; positive h: the centre above the springs), a
stabilising +W |h| when the block hangs below them. Checked against :func:`machdyn.vibration.modes.modes` (the
planar frame) and :func:`machdyn.shafts.frame6.modes6` (the frame in space, rocking about two axes), and by a
second, independent method: the block's exact nonlinear equations (finite rotation, preloaded springs that keep
their direction, the weight) integrated in time, its rocking period read from the zero crossings.
"""

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from machdyn.constants import STANDARD_GRAVITY as G
from machdyn.errors import InputError
from machdyn.shafts.frame6 import Frame6, Mount6, modes6
from machdyn.vibration.frame import Frame, Mount
from machdyn.vibration.modes import modes

M, I, K, A, KH = 200.0, 12.0, 5e4, 0.4, 1.5e5


def block(h, *, reference_at_springs=True, gravity=(0.0, -G)):
    """The block with its centre h above the springs' line; coordinates from the springs' midpoint, or from the
    centre of mass."""
    base = 0.0 if reference_at_springs else -h
    com = (0.0, h) if reference_at_springs else (0.0, 0.0)
    mounts = (Mount("left", (-A, base), np.pi / 2, K), Mount("right", (A, base), np.pi / 2, K),
              Mount("slide", (0.0, base + h), 0.0, KH))
    return Frame(M, I, mounts, com=com, gravity=gravity)


def closed_form(h):
    return np.sqrt((2 * K * A * A - M * G * h) / I)


@pytest.mark.parametrize("h", [0.5, 0.2, -0.3])
def test_the_rocking_frequency_of_a_block_is_the_closed_forms(h):
    for reference_at_springs in (True, False):  # the term does not depend on where the coordinates start
        w = np.sort(modes(block(h, reference_at_springs=reference_at_springs)).angular_frequencies)
        expected = np.sort([np.sqrt(2 * K / M), np.sqrt(KH / M), closed_form(h)])
        assert w == pytest.approx(expected, rel=1e-12)
    without = np.sort(modes(block(h, gravity=(0.0, 0.0))).angular_frequencies)
    rocking = np.sqrt(2 * K * A * A / I)
    assert np.any(np.isclose(without, rocking, rtol=1e-12))  # no gravity: the springs' rocking stiffness alone


def test_the_block_tips_over_when_its_weight_outweighs_the_springs():
    h = 1.05 * 2 * K * A * A / (M * G)
    with pytest.raises(InputError, match="tips over"):
        modes(block(h))


def test_the_exact_nonlinear_block_rocks_at_the_closed_forms_frequency():
    """Independent of the stiffness matrix: the block's own equations, finite rotation, springs preloaded by
    the weight and keeping their direction, integrated from a small tilt."""
    h = 0.5
    preload = M * G / 2  # each vertical spring carries half the weight at rest
    arms = np.array([[-A, -h], [A, -h]])  # attachment points from the centre, in the block

    def rhs(t, s):
        x, y, th, vx, vy, om = s
        c, sn = np.cos(th), np.sin(th)
        fx, fy, moment = -KH * x, -M * G, 0.0
        for px, py in arms:
            rx, ry = c * px - sn * py, sn * px + c * py  # the arm turned with the block
            stretch = (y + ry) - py  # the attachment point's rise from its rest height
            f = preload - K * stretch  # vertical, pushing up
            fy += f
            moment += rx * f
        return [vx, vy, om, fx / M, fy / M, moment / I]

    w = closed_form(h)
    period = 2 * np.pi / w
    t = np.linspace(0.0, 12 * period, 24001)
    sol = solve_ivp(rhs, (0.0, t[-1]), [0.0, 0.0, 1e-4, 0.0, 0.0, 0.0], method="DOP853", rtol=1e-11,
                    atol=1e-14, t_eval=t)
    th = sol.y[2]
    down = np.flatnonzero((th[:-1] > 0) & (th[1:] <= 0))
    crossings = t[down] + th[down] / (th[down] - th[down + 1]) * (t[1] - t[0])
    measured = 2 * np.pi / np.mean(np.diff(crossings))
    # the linear interpolation of the crossings is good to (dt w)^2 ~ 1e-6; the nonlinearity to theta^2 ~ 1e-8
    assert measured == pytest.approx(w, rel=1e-5)
    assert measured < np.sqrt(2 * K * A * A / I) * 0.98  # gravity lowered it by 3 %, a thousand times the tolerance


def test_the_frame_in_space_rocks_about_both_axes_at_the_closed_forms():
    """Four vertical mounts at (+-a, 0, +-b), the centre h above them, sliding mounts at the centre's height."""
    a, b, h, inertia = 0.4, 0.3, 0.45, (14.0, 20.0, 12.0)
    mounts = [Mount6(f"v{i}", (sa * a, 0.0, sb * b), (0, 1, 0), K / 2)
              for i, (sa, sb) in enumerate(((1, 1), (1, -1), (-1, 1), (-1, -1)))]
    mounts += [Mount6("x1", (0.0, h, b), (1, 0, 0), KH), Mount6("x2", (0.0, h, -b), (1, 0, 0), KH),
               Mount6("z", (0.0, h, 0.0), (0, 0, 1), KH)]
    frame = Frame6(M, inertia, tuple(mounts), (0.0, h, 0.0), (0.0, -G, 0.0))
    w = 2 * np.pi * modes6(frame)[0]
    weight = M * G
    rock_z = np.sqrt((2 * K * a * a - weight * h) / inertia[2])  # four mounts of K/2 at +-a
    rock_x = np.sqrt((2 * K * b * b - weight * h) / inertia[0])
    for expected in (rock_z, rock_x):
        assert np.min(np.abs(w / expected - 1)) <= 1e-10
