"""Choosing an induction motor from the standard ratings for a machine's mean power and peak torque.

The ratings are the IEC 60072-1 preferred outputs (``data/motors.csv``, see ``data/SOURCES.md``). The gear ratio
is chosen so that the motor runs at its rated speed when the crank turns at the machine's mean speed.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache
from importlib import resources

import numpy as np

from ..errors import InputError, check_positive
from .drives import InductionMotor


@cache
def standard_ratings() -> tuple[float, ...]:
    """IEC 60072-1 preferred rated outputs [W], increasing."""
    text = resources.files("machdyn.dynamics").joinpath("data/motors.csv").read_text(encoding="utf-8")
    lines = [ln.strip() for ln in text.splitlines()[1:] if ln.strip()]
    return tuple(float(v) * 1000.0 for v in lines)


def smallest_rating(required_power):
    """The smallest IEC 60072-1 preferred rating [W] >= ``required_power`` [W] (``data/motors.csv``).

    The one motor selection by power of machdyn: the screw conveyor's drive and :func:`select_motor` use it.
    A required power within a relative 1e-12 of a rating is met by that rating (the round-off of a power
    computed in another order must not move the choice up one size).

    Parameters
    ----------
    required_power : float or array
        Power the motor must give [W], >= 0.

    Returns
    -------
    float or array
        The rating [W]; NaN where the power exceeds the largest rating (200 kW).

    Examples
    --------
    >>> smallest_rating(1276.0), smallest_rating(1500.0), smallest_rating(250e3)
    (1500.0, 1500.0, nan)
    """
    ratings = np.asarray(standard_ratings())
    required = np.asarray(required_power, dtype=float)
    idx = np.searchsorted(ratings, required * (1.0 - 1e-12), side="left")
    chosen = np.where(idx < ratings.size, ratings[np.minimum(idx, ratings.size - 1)], np.nan)
    return float(chosen) if chosen.ndim == 0 else chosen


@dataclass(frozen=True)
class MotorChoice:
    """The chosen motor and why: the power needed [W], the peak crank torque it must carry [N*m] and the
    motor's breakdown torque at the crank [N*m]."""

    motor: InductionMotor
    required_power: float
    peak_torque: float
    breakdown_torque: float


def select_motor(mean_power, peak_torque, crank_speed, *, synchronous_speed=1500 * np.pi / 30,
                 rated_slip=0.04, breakdown_ratio=2.5, gear_efficiency=1.0, service_factor=1.0,
                 torque_margin=1.0, rotor_inertia=0.0) -> MotorChoice:
    """The smallest IEC 60072-1 rating that gives ``mean_power`` [W] and whose breakdown torque at the crank
    carries ``peak_torque`` [N*m] times ``torque_margin``.

    Parameters
    ----------
    mean_power : mean power the machine takes at the crank [W] > 0.
    peak_torque : largest torque the drive must give at the crank [N*m] (with its flywheel: the steady state's
        peak drive torque).
    crank_speed : mean crank speed [rad/s] > 0.
    synchronous_speed : of the motor [rad/s] (1500 rpm: 4 poles at 50 Hz).
    rated_slip, breakdown_ratio : catalogue values of the motor (typical defaults, see data/SOURCES.md).
    gear_efficiency, service_factor, torque_margin : >= their neutral values 1 (efficiency <= 1).
    rotor_inertia : [kg*m^2].

    Examples
    --------
    >>> choice = select_motor(2500.0, 500.0, 10.0)
    >>> choice.motor.rated_power
    3000.0
    """
    check_positive("mean power", mean_power, "W")
    check_positive("peak torque", peak_torque, "N*m", allow_zero=True)
    check_positive("crank speed", crank_speed, "rad/s")
    if not 0 < rated_slip < 1:
        raise InputError(f"The rated slip must be between 0 and 1; got {rated_slip:g}.")
    if not 0 < gear_efficiency <= 1:
        raise InputError(f"The gear efficiency must be in (0, 1]; got {gear_efficiency:g}.")
    needed = mean_power / gear_efficiency * service_factor
    rated_speed = synchronous_speed * (1.0 - rated_slip)
    ratio = rated_speed / crank_speed
    first = smallest_rating(needed)
    for rating in standard_ratings():
        if not rating >= first:  # below the power needed (every rating fails when none is large enough)
            continue
        motor = InductionMotor(rating, rated_speed, synchronous_speed, breakdown_ratio, ratio, gear_efficiency,
                               rotor_inertia)
        if float(motor.breakdown_torque) >= peak_torque * torque_margin:
            return MotorChoice(motor, float(needed), float(peak_torque), float(motor.breakdown_torque))
    biggest = standard_ratings()[-1]
    raise InputError(
        f"No standard motor up to {biggest / 1000:g} kW gives {needed / 1000:.4g} kW with a breakdown torque of at "
        f"least {peak_torque * torque_margin:.4g} N*m at the crank; add a flywheel to lower the peak torque or "
        f"split the drive.")
