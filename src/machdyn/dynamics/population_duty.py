"""The thermal duty of the induction motors of N designs at once: the same equivalent-torque (RMS) method as
:func:`machdyn.dynamics.duty.motor_duty`, over NumPy arrays whose leading axis is the design.

For a duty of IEC 60034-1:2022 (§4.2.1, 4.2.3, 4.2.6) with cyclic duration factor cdf, the thermally equivalent
continuous torque of a load whose RMS torque while loaded is T is T (S1), T sqrt(cdf / (cdf + h (1 - cdf))) (S3,
rest cooling h) or sqrt(cdf T^2 + (1 - cdf) T_0^2) (S6, no-load torque T_0); the motor's load ratio is that torque
over its rated torque at the crank, T_r i eta; the torque it may carry while loaded is the inverse of that rule;
the starts per hour it stands are Q_h (1 - L^2) / W_r, Q_h = 3600 s P_r s_r / (1 - s_r) (the derivations and
their sources are in :mod:`machdyn.dynamics.duty`). Valid for cycles short against the motor's thermal time
constant.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .duty import _check_cooling, _check_duty

__all__ = ["duty_population"]


def duty_population(load_rms: Any, rated_torque: Any, duty: str = "S1", cdf: float = 1.0,
                    no_load_torque: Any = 0.0, rest_cooling: float = 1.0, rated_power: Any = None,
                    rated_slip: Any = None, start_loss: Any = None) -> dict[str, np.ndarray]:
    """The duty figures of N motors (the ``flywheel.motor_*`` duty results of a run).

    Parameters
    ----------
    load_rms : the RMS torque while loaded [N*m] at the crank, (N,).
    rated_torque : each motor's rated S1 torque at the crank [N*m] > 0 (rated torque x ratio x efficiency), (N,).
    duty : "S1", "S3" or "S6" (one for every design); cdf : its cyclic duration factor in (0, 1].
    no_load_torque : T_0 [N*m] of S6; rest_cooling : h in (0, 1] of S3.
    rated_power [W] > 0, rated_slip in (0, 1), start_loss [J] > 0 : for the starts per hour (each (N,) or None).

    Returns
    -------
    dict of (N,) arrays: ``equivalent`` [N*m], ``load_ratio`` [-], ``rated_for_duty`` [N*m], ``overloaded``
    (bool, the load ratio above 1 + 1e-9 as the single check), with the start data ``heat_per_hour`` [J/h] and
    ``starts_allowed`` [1/h] (inf for a start without rotor loss), and ``valid`` (False for a rated torque not > 0
    or a non-finite load, the figures NaN).
    """
    _check_duty(duty, cdf)
    _check_cooling(rest_cooling)
    load = np.asarray(load_rms, dtype=float)
    rated = np.broadcast_to(np.asarray(rated_torque, dtype=float), load.shape)
    t0 = np.broadcast_to(np.asarray(no_load_torque, dtype=float), load.shape)
    valid = np.isfinite(load) & np.isfinite(rated) & (rated > 0)
    if duty == "S1":
        equivalent = load.copy()
        for_duty = rated.copy()
    elif duty == "S3":
        # the RMS of (T over cdf, 0 over h (1 - cdf)), as duty.rms_torque sums it
        equivalent = np.sqrt(load * load * cdf / (cdf + rest_cooling * (1.0 - cdf)))
        for_duty = rated * np.sqrt((cdf + rest_cooling * (1.0 - cdf)) / cdf)
    else:
        equivalent = np.sqrt((load * load * cdf + t0 * t0 * (1.0 - cdf)) / (cdf + (1.0 - cdf)))
        room = rated**2 - (1.0 - cdf) * t0**2
        for_duty = np.sqrt(np.where(room > 0, room, 0.0) / cdf)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = equivalent / rated
    out = {"equivalent": equivalent, "load_ratio": ratio, "rated_for_duty": for_duty}
    if rated_power is not None and rated_slip is not None and start_loss is not None:
        power = np.broadcast_to(np.asarray(rated_power, dtype=float), load.shape)
        slip = np.broadcast_to(np.asarray(rated_slip, dtype=float), load.shape)
        loss = np.broadcast_to(np.asarray(start_loss, dtype=float), load.shape)
        valid = valid & (power > 0) & (slip > 0) & (slip < 1)
        with np.errstate(divide="ignore", invalid="ignore"):
            heat = 3600.0 * power * slip / (1.0 - slip)
            allowed = np.where(loss > 0, np.maximum(0.0, heat * (1.0 - ratio**2) / loss), np.inf)
        out |= {"heat_per_hour": heat, "starts_allowed": allowed}
    found = {k: np.where(valid, v, np.nan) for k, v in out.items()}
    return found | {"overloaded": valid & (ratio > 1.0 + 1e-9), "valid": valid}
