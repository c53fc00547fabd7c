"""The right-hand side of one crank on a frame in scalar arithmetic: the same equations as
:meth:`machdyn.transient.model.CoupledModel.matrices` (see :mod:`machdyn.transient.model`), with the 4 x 4 mass
matrix solved by its Schur complement on the frame's 3 x 3 block, for the common case where a run's time goes
into the interpreter's overhead of small arrays."""

from __future__ import annotations

import math

import numpy as np

from .model import CoupledModel


def usable(model: CoupledModel) -> bool:
    """True for one crank on a frame whose loads are all Fourier channels (no speed forces, no switched loads)."""
    if model.cranks != 1 or model.frame is None:
        return False
    part = model.parts[0]
    return part.moment_curve is None and part.damping_curve is None and not part.machine.forces


def _solve3(m, r):
    """x with m x = r for a symmetric positive definite 3 x 3 m (nested lists) by Cramer's rule."""
    a, b, c = m[0]
    _, e, f = m[1]
    i = m[2][2]
    c11, c12, c13 = e * i - f * f, c * f - b * i, b * f - c * e
    c22, c23, c33 = a * i - c * c, b * c - a * f, a * e - b * b
    det = a * c11 + b * c12 + c * c13
    x0 = (c11 * r[0] + c12 * r[1] + c13 * r[2]) / det
    x1 = (c12 * r[0] + c22 * r[1] + c23 * r[2]) / det
    x2 = (c13 * r[0] + c23 * r[1] + c33 * r[2]) / det
    return x0, x1, x2


def _terms(model: CoupledModel):
    """f(phi, w, q, q', brake, load) -> (J with the added inertia, a, the frame block, the crank row's forces
    without the drive, the frame rows' forces, the mounts' dissipation, the loads' moment)."""
    part = model.parts[0]
    k = part.k
    both = np.vstack([np.hstack([part.ca, part.cb]), np.hstack([part.cb * k, -part.ca * k])])
    c0 = part.c0.tolist()
    added, coupling, own, mass_m = part.added, part.coupling, part.own, part.mass
    mf = model.mass_f.tolist()
    kf = model.stiffness.tolist()
    cf = model.damping.tolist()
    gx, gy = (float(v) for v in part.gravity)
    mean_weight = float(model.mean_weight[0])

    def terms(phi, w, x, yy, b, dx, dy, db, brake_torque, load_torque, width):
        arg = phi * k
        vals = (both @ np.concatenate([np.cos(arg), np.sin(arg)])).tolist()
        j, dv = c0[0] + vals[0] + added, vals[11]
        ax0, ay0, ab = c0[2] + vals[2], c0[3] + vals[3], c0[4] + vals[4] + coupling
        # the momentum per crank speed and its slope turn with the frame (see CoupledModel.matrices)
        ax, ay = ax0 - b * ay0, ay0 + b * ax0
        turned = dy * ax0 - dx * ay0
        sx, sy, rr = c0[5] + vals[5], c0[6] + vals[6], c0[7] + vals[7]
        dj, dax0, day0, dab, dsx, dsy, dr = vals[10], vals[12], vals[13], vals[14], vals[15], vals[16], vals[17]
        dax, day = dax0 - b * day0, day0 + b * dax0
        moment, damping = c0[8] + vals[8], c0[9] + vals[9]
        # frame block M_frame + Mm, its phi-derivative times q', and the velocity forces
        mq = [[mf[0][0] + mass_m, mf[0][1], mf[0][2] - sy],
              [mf[1][0], mf[1][1] + mass_m, mf[1][2] + sx],
              [mf[2][0] - sy, mf[2][1] + sx, mf[2][2] + rr + own]]
        dmq_dq = (-dsy * db, dsx * db, -dsy * dx + dsx * dy + dr * db)
        quad = dx * dmq_dq[0] + dy * dmq_dq[1] + db * dmq_dq[2]
        load = moment - damping * w - load_torque * math.tanh(w / width)
        brake = -brake_torque * math.tanh(w / width)
        r_phi = -0.5 * dj * w * w + 0.5 * quad - db * turned + load + brake + b * (gy * dsx - gx * dsy) - dv
        ww = w * w
        cq = (cf[0][0] * dx + cf[0][1] * dy + cf[0][2] * db, cf[1][0] * dx + cf[1][1] * dy + cf[1][2] * db,
              cf[2][0] * dx + cf[2][1] * dy + cf[2][2] * db)
        r_q = (-(dax * ww + dmq_dq[0] * w - db * w * ay0) - (kf[0][0] * x + kf[0][1] * yy + kf[0][2] * b) - cq[0],
               -(day * ww + dmq_dq[1] * w + db * w * ax0) - (kf[1][0] * x + kf[1][1] * yy + kf[1][2] * b) - cq[1],
               -(dab * ww + dmq_dq[2] * w) + w * turned - (kf[2][0] * x + kf[2][1] * yy + kf[2][2] * b) - cq[2]
               + gy * sx - gx * sy - mean_weight)
        loss = dx * cq[0] + dy * cq[1] + db * cq[2]
        return j, (ax, ay, ab), mq, r_phi, r_q, loss, load, brake

    return terms


def right_hand_side(model: CoupledModel, state: dict, check_budget, brake_width: float):
    """f(t, y) for y = (phi, omega, x, y, beta, x', y', beta', 4 works) (see :mod:`machdyn.transient.run`)."""
    terms = _terms(model)

    def rhs(t, y):
        check_budget(t)
        phi, w, x, yy, b, dx, dy, db = (float(v) for v in y[:8])
        j, a, mq, r_phi, r_q, loss, load, brake = terms(phi, w, x, yy, b, dx, dy, db, state["brake"],
                                                        state["load"], brake_width)
        torque = state["torques"][0]
        drive = torque(w) if state["on"] and torque is not None else 0.0
        z = _solve3(mq, r_q)
        u = _solve3(mq, a)
        acc_phi = (r_phi + drive - (a[0] * z[0] + a[1] * z[1] + a[2] * z[2])) / (
            j - (a[0] * u[0] + a[1] * u[1] + a[2] * u[2]))
        ddx, ddy, ddb = z[0] - u[0] * acc_phi, z[1] - u[1] * acc_phi, z[2] - u[2] * acc_phi
        return np.array([w, acc_phi, dx, dy, db, ddx, ddy, ddb, drive * w, load * w, loss, -brake * w])

    return rhs


def prescribed_right_hand_side(model: CoupledModel, profile, state: dict, check_budget, brake_width: float):
    """f(t, y) for y = (x, y, beta, x', y', beta', 4 works) with the crank's motion given by ``profile(t)`` ->
    (angle, speed, acceleration), and f(t, y, True) -> the drive torque that holds it."""
    terms = _terms(model)

    def rhs(t, y, torque_only=False):
        if not torque_only:
            check_budget(t)
        phis, omegas, alphas = profile(t)
        phi, w, alpha = float(phis[0]), float(omegas[0]), float(alphas[0])
        x, yy, b, dx, dy, db = (float(v) for v in y[:6])
        j, a, mq, r_phi, r_q, loss, load, _ = terms(phi, w, x, yy, b, dx, dy, db, 0.0, state["load"],
                                                    brake_width)
        ddq = _solve3(mq, (r_q[0] - a[0] * alpha, r_q[1] - a[1] * alpha, r_q[2] - a[2] * alpha))
        drive = j * alpha + a[0] * ddq[0] + a[1] * ddq[1] + a[2] * ddq[2] - r_phi
        if torque_only:
            return np.array([drive])
        return np.array([dx, dy, db, ddq[0], ddq[1], ddq[2], drive * w, load * w, loss, 0.0])

    return rhs
