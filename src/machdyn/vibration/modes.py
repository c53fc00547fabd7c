"""Natural frequencies and mode shapes of a frame on mounts.

The undamped free vibration M q'' + K q = 0 has the modes K phi = omega^2 M phi, a generalised symmetric
eigenproblem (Rao, *Mechanical Vibrations*, 5th ed., 2011, §6.10), solved with ``scipy.linalg.eigh``. A frame
whose mounts leave a rigid-body motion unrestrained (K singular) is a mechanism, not a structure: it has a
zero frequency and no steady-state response to a static load, so it is refused.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from .frame import Frame, mount_sum

__all__ = ["Modes", "modes", "check_supported"]

_COORDINATES = ("x", "y", "theta")
#: Relative size of an eigenvalue of K below which the frame counts as unsupported in that direction.
_SINGULAR = 1e-10


def _describe(vector: np.ndarray, frame: Frame) -> str:
    """Say in words which rigid motion ``vector`` (x, y, theta) is: a translation or a rotation about a point."""
    x, y, th = vector
    scale = max(abs(x), abs(y), abs(th) * max(1.0, *(abs(c) for m in frame.mounts for c in m.position)))
    if abs(th) * max(1.0, *(abs(c) for m in frame.mounts for c in m.position)) < 1e-9 * scale:
        return f"a translation along ({x / np.hypot(x, y):.3f}, {y / np.hypot(x, y):.3f})"
    # small rotation about the point c where u = 0: x - th cy = 0, y + th cx = 0
    return f"a rotation about the point ({-y / th + 0.0:.4g} m, {x / th + 0.0:.4g} m)"


def check_supported(frame: Frame) -> None:
    """Raise :class:`~machdyn.errors.InputError` if the mounts leave a rigid motion of ``frame`` free.

    The test is on the stiffness matrix alone, scaled so that it does not depend on units: an eigenvalue of
    S K S (S = diag(1, 1, 1/size), size = largest mount distance) below 1e-10 of the largest one.
    """
    size = max(1.0, *(np.hypot(*m.position) for m in frame.mounts))
    s = np.diag([1.0, 1.0, 1.0 / size])
    k = s @ mount_sum(frame.mounts, "stiffness") @ s
    values, vectors = np.linalg.eigh(k)
    top = float(np.max(values))
    if top <= 0:
        raise InputError(f"The frame '{frame.name}' is not supported: every mount has zero stiffness "
                         f"(a mechanism, not a structure).")
    free = [i for i, v in enumerate(values) if v < _SINGULAR * top]
    if free:
        motions = "; ".join(_describe(s @ vectors[:, i], frame) for i in free)
        raise InputError(
            f"The frame '{frame.name}' is not supported: its mounts leave {len(free)} rigid motion(s) free "
            f"({motions}), so it is a mechanism, not a structure. Add a mount that resists this motion."
        )
    weighed = np.linalg.eigvalsh(s @ frame.stiffness_matrix() @ s)
    if weighed[0] < _SINGULAR * top:
        raise InputError(
            f"The frame '{frame.name}' tips over on its mounts: its weight's pendulum term (its centre of gravity "
            f"above the mounts' elastic support) exceeds their rocking stiffness. Spread the mounts, stiffen them or "
            f"lower the centre of gravity.")


@dataclass(frozen=True)
class Modes:
    """Natural frequencies and mode shapes of a frame.

    ``angular_frequencies`` [rad/s] and ``frequencies`` [Hz] ascending; ``shapes`` (3 x n) column j is mode j
    in (x [m], y [m], theta [rad]), mass-normalised (phi^T M phi = 1); ``damping_ratios`` [-] are the modal
    estimates phi^T C phi / (2 omega) (exact when C is proportional to M and K).
    """

    frame: Frame
    angular_frequencies: np.ndarray
    shapes: np.ndarray
    damping_ratios: np.ndarray

    @property
    def frequencies(self) -> np.ndarray:
        return self.angular_frequencies / (2 * np.pi)

    def dominant(self) -> tuple[str, ...]:
        """The coordinate (x, y or theta) that carries most of each mode's kinetic energy."""
        m = self.frame.mass_matrix()
        out = []
        for j in range(self.shapes.shape[1]):
            phi = self.shapes[:, j]
            share = phi * (m @ phi)  # diagonal split of phi^T M phi; off-diagonal terms go with their row
            out.append(_COORDINATES[int(np.argmax(np.abs(share)))])
        return tuple(out)

    def point_shape(self, point, mode: int) -> np.ndarray:
        """Displacement (ux, uy) [m] of frame point ``point`` in mode ``mode`` (mass-normalised)."""
        return Frame.point_matrix(point) @ self.shapes[:, mode]


def modes(frame: Frame) -> Modes:
    """Natural frequencies and mass-normalised mode shapes of ``frame`` (K phi = omega^2 M phi).

    Rao, *Mechanical Vibrations*, 5th ed. (2011), §6.10; solved with ``scipy.linalg.eigh(K, M)``.

    Parameters
    ----------
    frame : the frame on its mounts; must be supported (:func:`check_supported`)

    Examples
    --------
    A 100 kg block on one vertical and one horizontal spring at its centre, and a torsion pair:

    >>> from machdyn.vibration.frame import Frame, Mount
    >>> f = Frame(100.0, 10.0, (Mount("v1", (-1, 0), np.pi / 2, 2e4), Mount("v2", (1, 0), np.pi / 2, 2e4),
    ...                         Mount("h", (0, 0), 0.0, 1e4)))
    >>> [round(float(w), 4) for w in modes(f).angular_frequencies]
    [10.0, 20.0, 63.2456]
    """
    from scipy.linalg import eigh

    check_supported(frame)
    m, k, c = frame.mass_matrix(), frame.stiffness_matrix(), frame.damping_matrix()
    values, vectors = eigh(k, m)
    omega = np.sqrt(np.clip(values, 0.0, None))
    zeta = np.einsum("ij,ik,kj->j", vectors, c, vectors) / (2 * omega)
    # A fixed sign: the largest entry of each shape positive (eigh's sign is arbitrary).
    signs = np.sign(vectors[np.argmax(np.abs(vectors), axis=0), np.arange(3)])
    return Modes(frame, omega, vectors * signs, zeta)
