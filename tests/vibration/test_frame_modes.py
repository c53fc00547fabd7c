"""Frame on mounts: matrices, natural frequencies against closed forms, and the refusal of bad frames."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from machdyn.errors import InputError
from machdyn.vibration import Frame, Mount, check_supported, modes, pendulum_stiffness, rope, rubber_mount, tyre

UP = np.pi / 2


def symmetric_frame(m=1200.0, inertia=300.0, k=2e5, kh=5e4, a=0.8):
    """Two vertical springs at x = +-a and one horizontal spring through the centre of mass."""
    return Frame(m, inertia, (Mount("left", (-a, 0.0), UP, k), Mount("right", (a, 0.0), UP, k),
                              Mount("side", (0.0, 0.0), 0.0, kh)))


def test_symmetric_frame_frequencies_match_closed_form():
    # Uncoupled modes (Rao, Mechanical Vibrations, 5th ed., §5.6): bounce sqrt(2k/m), pitch sqrt(2 k a^2 / I),
    # sway sqrt(kh/m). Exact up to the eigen-solver's rounding: rel 1e-12.
    m, inertia, k, kh, a = 1200.0, 300.0, 2e5, 5e4, 0.8
    result = modes(symmetric_frame(m, inertia, k, kh, a))
    expected = sorted([np.sqrt(2 * k / m), np.sqrt(2 * k * a**2 / inertia), np.sqrt(kh / m)])
    np.testing.assert_allclose(result.angular_frequencies, expected, rtol=1e-12)
    np.testing.assert_allclose(result.frequencies, np.array(expected) / (2 * np.pi), rtol=1e-12)


def test_mode_shapes_are_mass_normalised_and_diagonalise_k():
    f = symmetric_frame()
    r = modes(f)
    phi = r.shapes
    np.testing.assert_allclose(phi.T @ f.mass_matrix() @ phi, np.eye(3), atol=1e-12)
    np.testing.assert_allclose(phi.T @ f.stiffness_matrix() @ phi, np.diag(r.angular_frequencies**2),
                               rtol=1e-10, atol=1e-6)
    assert set(r.dominant()) == {"x", "y", "theta"}


@settings(max_examples=30, deadline=None)
@given(m=st.floats(10, 5000), r_g=st.floats(0.1, 2.0), k=st.floats(1e3, 1e7), a=st.floats(0.1, 3.0),
       xg=st.floats(-0.5, 0.5))
def test_coupled_frame_rayleigh_quotients(m, r_g, k, a, xg):
    # With the centre of mass off the middle, bounce and pitch couple; the eigenpairs must still satisfy
    # K phi = w^2 M phi (residual relative to |K phi| below 1e-9) and the sum of w^2 equals trace(M^-1 K).
    f = Frame(m, m * r_g**2, (Mount("l", (-a, 0.0), UP, k), Mount("r", (a, 0.0), UP, 2 * k),
                              Mount("h", (0.0, -0.2), 0.0, k)), com=(xg, 0.3))
    r = modes(f)
    kk, mm = f.stiffness_matrix(), f.mass_matrix()
    for j in range(3):
        phi = r.shapes[:, j]
        res = kk @ phi - r.angular_frequencies[j] ** 2 * (mm @ phi)
        assert np.linalg.norm(res) <= 1e-9 * np.linalg.norm(kk @ phi)
    assert np.sum(r.angular_frequencies**2) == pytest.approx(np.trace(np.linalg.solve(mm, kk)), rel=1e-9)


def test_mass_matrix_is_rigid_body_kinetic_energy():
    # 1/2 qdot^T M qdot = 1/2 m |v_G|^2 + 1/2 I_G w^2 for v_G = v_O + w x r_G (exact identity).
    f = Frame(50.0, 4.0, (Mount("a", (0, 0), 0.0, 1.0),), com=(0.3, -0.2))
    qd = np.array([0.7, -1.1, 2.3])
    vg = np.array([qd[0] - qd[2] * -0.2, qd[1] + qd[2] * 0.3])
    assert 0.5 * qd @ f.mass_matrix() @ qd == pytest.approx(0.5 * 50 * vg @ vg + 0.5 * 4.0 * qd[2] ** 2, rel=1e-14)


def test_hanging_frame_swings_as_a_pendulum():
    # A frame hung on two ropes of length L with its centre of mass at the attachment level sways at
    # sqrt(g/L), the simple pendulum (Den Hartog, Mechanical Vibrations, 4th ed., §1.3). Rel 1e-12.
    m, L = 1200.0, 1.5
    mounts = rope("front", (-1.0, 0.0), L, m / 2, 5e7) + rope("rear", (1.0, 0.0), L, m / 2, 5e7)
    r = modes(Frame(m, 400.0, mounts))
    assert r.angular_frequencies[0] == pytest.approx(np.sqrt(9.80665 / L), rel=1e-12)
    assert r.dominant()[0] == "x"
    assert pendulum_stiffness(m / 2, L) == pytest.approx(m / 2 * 9.80665 / L)


def test_mount_helpers():
    v, h = rubber_mount("m", (0.2, -0.1), 3e5, 1e5, loss_factor=0.2, frequency=25.0)
    assert (v.name, h.name) == ("m.v", "m.h")
    assert v.damping == pytest.approx(0.2 * 3e5 / (2 * np.pi * 25.0))
    assert h.damping == pytest.approx(0.2 * 1e5 / (2 * np.pi * 25.0))
    tv, th = tyre("t", (1.0, -0.5), 1e6, 3e5, vertical_damping=2000.0)
    assert tv.kind == th.kind == "tyre" and tv.damping == 2000.0 and tv.direction == pytest.approx(UP)
    np.testing.assert_allclose(tv.influence, [0.0, 1.0, 1.0], atol=1e-15)
    np.testing.assert_allclose(th.influence, [1.0, 0.0, 0.5], atol=1e-15)


# ------------------------------------------------------------------------------------------- bad input


def test_negative_stiffness_is_refused_with_its_name_and_value():
    with pytest.raises(InputError, match=r"stiffness of mount 'rear' must be >= 0 N/m; got -2000 N/m"):
        Mount("rear", (0.5, 0.0), UP, -2000.0)


def test_negative_damping_and_nan_position_are_refused():
    with pytest.raises(InputError, match="damping of mount 'a'"):
        Mount("a", (0.0, 0.0), UP, 1e4, -1.0)
    with pytest.raises(InputError, match="x position of mount 'a'"):
        Mount("a", (float("nan"), 0.0), UP, 1e4)


def test_unsupported_frame_is_a_mechanism_not_a_structure():
    # Only vertical mounts: the frame can slide sideways freely.
    f = Frame(100.0, 10.0, (Mount("l", (-1, 0), UP, 1e5), Mount("r", (1, 0), UP, 1e5)))
    with pytest.raises(InputError, match=r"not supported.*translation along \(-?1\.000, 0\.000\).*mechanism, "
                                         r"not a structure"):
        modes(f)
    # Mounts all through one point: it can rotate about that point.
    g = Frame(100.0, 10.0, (Mount("v", (0.5, 0.2), UP, 1e5), Mount("h", (0.5, 0.2), 0.0, 1e5)))
    with pytest.raises(InputError, match=r"rotation about the point \(0\.5 m, 0\.2 m\)"):
        check_supported(g)
    with pytest.raises(InputError, match="every mount has zero stiffness"):
        check_supported(Frame(1.0, 1.0, (Mount("z", (0, 0), 0.0, 0.0),)))


def test_frame_definition_errors():
    with pytest.raises(InputError, match="mass of frame 'frame' must be > 0 kg"):
        Frame(0.0, 1.0, (Mount("a", (0, 0), 0.0, 1.0),))
    with pytest.raises(InputError, match="at least one mount"):
        Frame(1.0, 1.0, ())
    with pytest.raises(InputError, match="unique; got a twice"):
        Frame(1.0, 1.0, (Mount("a", (0, 0), 0.0, 1.0), Mount("a", (1, 0), 0.0, 1.0)))
    with pytest.raises(InputError, match="No mount 'b'"):
        Frame(1.0, 1.0, (Mount("a", (0, 0), 0.0, 1.0),)).mount("b")
    with pytest.raises(InputError, match="loss factor of mount 'm' needs the frequency"):
        rubber_mount("m", (0, 0), 1e5, 1e5, loss_factor=0.1)
