"""The maximum fluctuation of energy of a turning-moment diagram: the energy a flywheel stores and gives back.

Over one cycle the crank receives the torque T(phi) and gives out the uniform resisting torque T_mean (the same
work per cycle). The energy stored in the rotating parts above its value at the start of the cycle is

    E(phi) = integral from phi_0 to phi of (T - T_mean) dphi

and the maximum fluctuation of energy is its largest swing, dE = max E - min E (R. S. Khurmi & J. K. Gupta,
*Theory of Machines*, ch. 16 "Turning moment diagrams and flywheel", "Maximum fluctuation of energy": the largest
difference of the energies at the crossings of the turning-moment curve with the mean-torque line). The cycle
is one crank revolution (2 pi) for a two-stroke engine, a steam engine or a press, two (4 pi) for a four-stroke
engine.
A flywheel of moment of inertia I at mean speed omega then keeps the coefficient of fluctuation of speed at
C_s = dE / (I omega^2) (ibid., "Energy stored in a flywheel").
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError

_TWO_PI = 2.0 * np.pi


def energy_fluctuation(torque, crank_angle, *, cycle: float | None = None) -> np.ndarray:
    """Maximum fluctuation of energy dE [J] of the torque ``torque`` over one whole cycle of the crank.

    dE = max E - min E with E(phi) = integral (T - T_mean) dphi over the cycle, T_mean the cycle mean
    (Khurmi & Gupta, *Theory of Machines*, ch. 16, "Maximum fluctuation of energy"); integrated with the trapezoidal
    rule, whose error falls with the square of the step, the extremes taken at the crossings of T with T_mean.
    Valid for a uniform resisting torque (the cycle mean) and a crank speed close to constant over the cycle
    (the turning-moment diagram is then the energy diagram); exact to rounding for a piecewise-linear diagram
    with its corners on the samples.

    Parameters
    ----------
    torque : array_like, [N*m]
        The turning moment (or the driving torque: the swing is the same for T and -T) at each crank angle,
        last axis = crank angles; leading axes (design variants) are kept.
    crank_angle : array_like, [rad]
        Evenly spaced, increasing crank angles covering one whole cycle: either without the end point (as
        :func:`~machdyn.linkage.kinematics.crank_angles` gives, the span plus one step is the cycle) or with it
        (the span is the cycle). At least 8 angles.
    cycle : float, optional, [rad]
        The length of the cycle, 2 pi or 4 pi (any whole number of turns). By default the whole number of
        turns the crank angles cover.

    Returns
    -------
    numpy.ndarray
        dE [J] >= 0, shaped like ``torque`` without its last axis (a 0-d array for one design).

    Raises
    ------
    InputError
        If the crank angles are not evenly spaced and increasing, do not cover a whole number of turns (or the
        given ``cycle``), or the torque is not finite or not shaped to match.

    Examples
    --------
    A two-stroke engine's torque T = 1000 + 300 sin 2 phi - 500 cos 2 phi [N*m]: dE = 2 * sqrt(300^2 + 500^2)
    / 2 = 583.1 J.

    >>> import numpy as np
    >>> from machdyn.linkage import crank_angles
    >>> phi = crank_angles(3600)
    >>> round(float(energy_fluctuation(1000 + 300 * np.sin(2 * phi) - 500 * np.cos(2 * phi), phi)), 1)
    583.1
    """
    phi = np.asarray(crank_angle, dtype=float)
    t = np.asarray(torque, dtype=float)
    if phi.ndim != 1 or phi.size < 8:
        raise InputError(
            f"The crank angles for the energy fluctuation must be a 1-D array of at least 8 angles; got shape "
            f"{phi.shape}."
        )
    if t.shape[-1:] != phi.shape:
        raise InputError(
            f"The torque's last axis must match the {phi.size} crank angles; got torque shape {t.shape}."
        )
    if not np.all(np.isfinite(phi)):
        raise InputError("The crank angles for the energy fluctuation must be finite numbers.")
    if not np.all(np.isfinite(t)):
        raise InputError(
            "The torque for the energy fluctuation must be finite at every crank angle; it holds NaN or inf."
        )
    step = np.diff(phi)
    if step[0] <= 0 or not np.allclose(step, step[0], rtol=1e-6, atol=1e-12):
        raise InputError(
            "The crank angles for the energy fluctuation must be evenly spaced and increasing; got steps from "
            f"{np.degrees(step.min()):.4g}° to {np.degrees(step.max()):.4g}°."
        )
    h = float(step[0])
    span = float(phi[-1] - phi[0])
    closes = _whole_turns(span + h, h, cycle)  # end point excluded: the next sample starts the next cycle
    if closes is not None:
        t = np.concatenate([t, t[..., :1]], axis=-1)
    elif _whole_turns(span, h, cycle) is None:
        wanted = (
            "a whole number of turns (360°, 720°, ...)" if cycle is None else f"the cycle of {np.degrees(cycle):g}°"
        )
        raise InputError(
            f"The crank angles for the energy fluctuation must cover {wanted}, with or without the end point; "
            f"they span {np.degrees(span):.6g}° in steps of {np.degrees(h):.6g}°."
        )
    from scipy.integrate import cumulative_trapezoid

    work = cumulative_trapezoid(t, dx=h, axis=-1, initial=0.0)
    # E(phi) = W(phi) - T_mean (phi - phi_0), T_mean = W(end) / cycle: the resisting torque does the cycle's work.
    travelled = h * np.arange(t.shape[-1])
    mean = work[..., -1:] / travelled[-1]
    energy = work - mean * travelled
    # The extremes of E lie where T crosses T_mean, mostly between samples: take the crossing of the linear
    # interpolant and the trapezoid up to it (exact for a piecewise-linear turning-moment diagram).
    excess = t - mean
    a, b = excess[..., :-1], excess[..., 1:]
    crossing = a * b < 0
    with np.errstate(divide="ignore", invalid="ignore"):
        fraction = np.where(crossing, a / (a - b), 0.0)
    at_crossing = energy[..., :-1] + 0.5 * h * fraction * a
    highest = np.maximum(np.max(energy, axis=-1), np.max(at_crossing, axis=-1))
    lowest = np.minimum(np.min(energy, axis=-1), np.min(at_crossing, axis=-1))
    return np.asarray(highest - lowest)


def _whole_turns(length: float, step: float, cycle: float | None) -> int | None:
    """The number of turns ``length`` [rad] covers, if whole (to a thousandth of a step), else None."""
    if cycle is not None:
        turns = cycle / _TWO_PI
        if not np.isfinite(cycle) or cycle <= 0 or abs(turns - round(turns)) > 1e-9:
            raise InputError(f"The cycle must be a whole number of turns (2 pi, 4 pi, ...) in rad; got {cycle!r}.")
        return round(turns) if abs(length - cycle) <= 1e-3 * step else None
    turns = round(length / _TWO_PI)
    return turns if turns >= 1 and abs(length - turns * _TWO_PI) <= 1e-3 * step else None
