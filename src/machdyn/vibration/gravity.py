"""The stiffness gravity adds to a rigid frame on mounts: the pendulum term of its rocking modes.

A frame on mounts rests where its mounts carry its weight W = m g. When it turns by a small rotation vector
vartheta about its reference point O, two second-order terms change its potential energy (the linear ones balance
at the static equilibrium):

* its centre of mass c turns with it, R(vartheta) c - c = vartheta x c + 1/2 vartheta x (vartheta x c), so the weight's
  potential -m gamma . (R c) gains -m gamma . 1/2 vartheta x (vartheta x c): the Hessian
  -m [1/2 (gamma c^T + c gamma^T) - (gamma . c) I] on vartheta (gamma the acceleration of gravity);
* each mount i, preloaded by the force P_i = k_i delta_i (its static deflection delta_i = b_i . q_s under the weight,
  q_s = K^-1 (m gamma, m c x gamma)), keeps its line n_i (a mount long against the frame's motion) while its
  attachment point p_i turns: its deflection n_i . (R p_i - p_i) gains 1/2 n_i . vartheta x (vartheta x p_i), the
  Hessian P_i [1/2 (n_i p_i^T + p_i n_i^T) - (n_i . p_i) I].

On a planar frame (gravity in the plane, vartheta = theta e_z) both reduce to the rotation's diagonal term
K_theta,theta += m gamma . c - sum P_i n_i . p_i. For a block on vertical mounts at height y_s under a centre of
mass at height y_c that is -W (y_c - y_s) = -W h: the centre of gravity h above the mounts' elastic support
destabilises the rocking mode, below it (a frame hung from its mounts) stabilises it — the inverted and the
hanging pendulum (Den Hartog, *Mechanical Vibrations*, 4th ed., McGraw-Hill 1956, the pendulum and its stability
in ch. 1; Harris' *Shock and Vibration Handbook*, ch. 3, the resiliently supported rigid body, whose rocking
frequencies leave gravity out). The block's rocking frequency is then omega^2 = (k_r - W h) / I
(tests/vibration/test_gravity_stiffness.py). Valid for small rotations and mounts whose line does not tilt with
the frame's translation (a rope's swing across its line is its own pendulum stiffness,
:func:`machdyn.vibration.frame.pendulum_stiffness`); the frame tips over when the term exceeds the mounts'
rocking stiffness.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError

__all__ = ["gravity_stiffness"]


def gravity_stiffness(mass: float, com, gravity, mounts, stiffness: np.ndarray) -> np.ndarray:
    """The stiffness gravity adds [N/m, N, N*m] to a frame of ``mass`` [kg] with its centre of mass at ``com``
    [m] (2 or 3 coordinates, from the reference point), under ``gravity`` [m/s^2] (a vector of the same size), on
    ``mounts`` (each with ``position``, a unit line and ``stiffness``; planar :class:`~machdyn.vibration.frame.Mount`
    or spatial :class:`~machdyn.shafts.frame6.Mount6`) whose stiffness matrix is ``stiffness`` (3 x 3 or 6 x 6).
    Returns the matrix of the same shape (zero without gravity); see the module docstring.

    Examples
    --------
    A 100 kg block whose centre sits 0.5 m above its two vertical springs: -W h = -490.3 N*m on the rotation.

    >>> from machdyn.vibration.frame import Mount
    >>> mounts = (Mount("l", (-0.5, 0.0), np.pi / 2, 1e5), Mount("r", (0.5, 0.0), np.pi / 2, 1e5),
    ...           Mount("h", (0.0, 0.5), 0.0, 1e5))
    >>> k = sum(m.stiffness * np.outer(m.influence, m.influence) for m in mounts)
    >>> round(float(gravity_stiffness(100.0, (0.0, 0.5), (0.0, -9.80665), mounts, k)[2, 2]), 4)
    -490.3325
    """
    g = np.asarray(gravity, dtype=float)
    c = np.asarray(com, dtype=float)
    size = stiffness.shape[0]
    if not np.any(g):
        return np.zeros((size, size))
    planar = size == 3
    if planar:
        load = mass * np.array([g[0], g[1], c[0] * g[1] - c[1] * g[0]])
    else:
        load = mass * np.concatenate([g, np.cross(c, g)])
    try:
        static = np.linalg.solve(stiffness, load)
    except np.linalg.LinAlgError as exc:
        raise InputError("The frame's mounts leave it free to move: its weight has no static equilibrium on "
                         "them.") from exc
    out = np.zeros((size, size))
    if planar:
        rocking = mass * float(g @ c)
        for m in mounts:
            preload = m.stiffness * float(m.influence @ static)
            n = np.array([np.cos(m.direction), np.sin(m.direction)])
            rocking -= preload * float(n @ np.asarray(m.position, dtype=float))
        out[2, 2] = rocking
        return out
    eye = np.eye(3)
    block = -mass * (0.5 * (np.outer(g, c) + np.outer(c, g)) - float(g @ c) * eye)
    for m in mounts:
        preload = m.stiffness * float(m.influence @ static)
        n, p = np.asarray(m.direction, dtype=float), np.asarray(m.position, dtype=float)
        block += preload * (0.5 * (np.outer(n, p) + np.outer(p, n)) - float(n @ p) * eye)
    out[3:, 3:] = block
    return out
