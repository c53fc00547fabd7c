"""Screw size, pitch and speed from the duty (seed 004, eqs 2.83-2.84; Alexandrov's capacity rule).

All functions take and return SI floats: m, s, kg, rad, rad/s. The one exception is the speed coefficient k
of n = k/√D, a material constant kept in the unit its sources tabulate it in (rpm·m^0.5); :func:`speed_limit`
turns it into a speed in rad/s.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import InputError, check_positive
from . import tables

#: rad/s per rpm: the speed coefficient k is tabulated in rpm·m^0.5.
RPM = math.pi / 30.0


def angular_speed_of(function: str, angular_speed: Any, speed_rpm: Any, old_rpm: Any = None,
                     old: str = "a speed given by position") -> Any:
    """The one speed [rad/s] a function was given: ``angular_speed`` [rad/s] or ``speed_rpm`` [rpm] by keyword, or
    ``old_rpm``, the speed a call gave in the form of the releases before 0.1.0 (``old`` says how), read in rpm
    as it was then, with a DeprecationWarning (the position held rpm, then rad/s: a unit never changes silently in one
    place, so the position keeps its first unit until the form goes in 0.3.0)."""
    given = [v is not None for v in (angular_speed, speed_rpm, old_rpm)]
    if sum(given) != 1:
        raise TypeError(f"{function}() takes the speed once, by keyword: angular_speed= [rad/s] or speed_rpm= [rpm]"
                        f"{'; got it ' + str(sum(given)) + ' times' if sum(given) else ''}")
    if old_rpm is not None:
        warnings.warn(f"{function}(): {old} is read in rpm (its unit before 0.1.0); give it by "
                      f"keyword, angular_speed= [rad/s] or speed_rpm= [rpm]; the positional form goes in 0.3.0",
                      DeprecationWarning, stacklevel=3)
        return old_rpm * RPM
    return angular_speed if angular_speed is not None else speed_rpm * RPM


def volume_capacity(diameter: Any, pitch: Any, *old: Any, angular_speed: Any = None, speed_rpm: Any = None,
                    filling: Any = None, inclination_factor: float = 1.0, pipe_diameter: Any = 0.0) -> Any:
    """Volumetric capacity of a screw conveyor Q_v = (π/4)·(D² − d_o²)·S·(ω/2π)·φ·C [m³/s] (ω/2π = n/60 the
    turns per second of a speed n [rpm]).

    With ``pipe_diameter`` d_o = 0 this is seed 004, eq 2.83 divided by ρ (Q in t/h there is
    60·(π/4)·D²·S·n·φ·C·ρ), the whole circle as in Alexandrov, *Materials Handling Equipment* (his worked
    example: F = (π/4)·0.3²·0.8 = 0.057 m²), where φ is the filled fraction of the whole circle. With the pipe's
    outer diameter d_o, the annulus the material can occupy, as CEMA 350 and its manufacturers' guides compute
    capacity (KWS *Screw Conveyor Engineering Guide*, "Screw conveyor capacity": ft³/h per rpm =
    0.7854·(D_s² − D_p²)·P·K·60/1728, K the trough loading); the CEMA capacity tables follow it (a 12-inch screw
    on its 3½-inch pipe at 45 % loading: 19.4 ft³/h per rpm, against 21.2 for the whole circle). φ is then the
    filled fraction of the annulus.

    Parameters
    ----------
    diameter : float or array
        Screw diameter D [m].
    pitch : float or array
        Pitch S [m].
    angular_speed : float or array, keyword
        Angular speed ω [rad/s]; or ``speed_rpm`` [rpm], keyword: one of the two.
    filling : float or array, keyword
        Filling coefficient φ [-], 0 < φ <= 1.
    inclination_factor : float
        C [-] (1.0 horizontal … 0.65 at 20°).
    pipe_diameter : float or array
        Pipe (shaft) outer diameter d_o [m], 0 <= d_o < D; 0 for the whole circle.

    Returns
    -------
    float or array
        Q_v [m³/s]. Valid for control-fed screws with 0 <= β <= 20°.

    Examples
    --------
    >>> q = volume_capacity(0.2, 0.16, speed_rpm=100.62306, filling=0.4, inclination_factor=0.8)
    >>> round(q * 3600, 4)  # seed 004: 9.71 m³/h at 100.6 rpm
    9.7111
    >>> q = volume_capacity(0.2, 0.16, angular_speed=100.62306 * RPM, filling=0.4, inclination_factor=0.8,
    ...                     pipe_diameter=0.1)
    >>> round(q * 3600, 4)  # the 100 mm pipe deducted
    7.2833

    The form of the releases before 0.1.0, ``volume_capacity(D, S, n, φ, C, d_o)`` with n in rpm by position,
    still reads n in rpm and warns (DeprecationWarning); it goes in 0.3.0.
    """
    if len(old) > 4:
        raise TypeError(f"volume_capacity() takes at most 6 positional arguments; got {2 + len(old)}")
    if old:  # the old form: (diameter, pitch, speed_rpm, filling, inclination_factor, pipe_diameter)
        if filling is not None and len(old) > 1:
            raise TypeError("volume_capacity() got filling by position and by keyword")
        filling = old[1] if len(old) > 1 else filling
        inclination_factor = old[2] if len(old) > 2 else inclination_factor
        pipe_diameter = old[3] if len(old) > 3 else pipe_diameter
    speed = angular_speed_of("volume_capacity", angular_speed, speed_rpm, old[0] if old else None)
    if filling is None:
        raise TypeError("volume_capacity() needs filling= (the filling coefficient φ)")
    turns_per_second = speed / (2.0 * math.pi)
    return math.pi / 4.0 * (diameter**2 - pipe_diameter**2) * pitch * turns_per_second * filling * inclination_factor


def speed_limit(diameter: Any, speed_coefficient: float) -> Any:
    """Highest recommended screw speed n = k/√D (seed 004, after eq 2.83), as an angular speed [rad/s].

    Parameters
    ----------
    diameter : float or array
        D [m].
    speed_coefficient : float
        k [rpm·m^0.5]: 60 light non-abrasive, 45 heavy non-abrasive, 30 heavy abrasive
        (``data/speed_coefficient.csv``; Alexandrov).

    Returns
    -------
    float or array
        ω [rad/s] (n = k/√D [rpm] times π/30).

    Examples
    --------
    >>> round(float(speed_limit(0.2, 45.0) / RPM), 3)  # seed 004: 101 rpm
    100.623
    """
    return speed_coefficient / np.sqrt(diameter) * RPM


def diameter_for_duty(volume_flow: float, pitch_ratio: float, speed_coefficient: float, filling: float,
                      inclination_factor: float = 1.0, pipe_diameter: float = 0.0, pipe_ratio: float = 0.0,
                      pipe_of: Callable[[float], float] | None = None) -> float:
    """Smallest screw diameter that carries ``volume_flow`` at the speed limit n = k/√D [m].

    With S = s·D and n = k/√D, eq 2.83 gives Q = 15π·s·k·φ·C·D^{5/2} [m³/h], so
    D = (Q/(15π·s·k·φ·C))^{2/5} (seed 004, eq 2.84; 37.7 = 15π·0.8 there). Seed 004 prints the mass flow divided
    by ρ twice over (ρ cancels) and labels k = 45 as the filling; the result 164.96 mm is the same.
    With the pipe deducted (:func:`volume_capacity`): a pipe in proportion d_o = η·D (``pipe_ratio`` η) divides
    the right-hand side by 1 − η²; a pipe of fixed size d_o (``pipe_diameter``) makes
    Q = 15π·s·k·φ·C·√D·(D² − d_o²), increasing in D > d_o, solved by bisection.

    Parameters
    ----------
    volume_flow : float
        Q [m³/s].
    pitch_ratio : float
        s = S/D [-].
    speed_coefficient : float
        k [rpm·m^0.5].
    filling : float
        φ [-].
    inclination_factor : float
        C [-].
    pipe_diameter : float
        d_o [m] of a given pipe, or 0.
    pipe_ratio : float
        η = d_o/D [-], 0 <= η < 1, when the pipe scales with the screw (used if ``pipe_diameter`` is 0).
    pipe_of : callable, optional
        d_o(D) [m] of the screw's standard pipe (used if ``pipe_diameter`` is 0; e.g.
        :func:`.tables.standard_pipe`, a step function that never falls as D grows): the fixed-pipe solution is
        repeated with the pipe of the diameter found until the pipe stays the same (D only grows, since a larger
        pipe needs a larger screw; at most one step per row of the table).

    Returns
    -------
    float
        D [m].

    Examples
    --------
    >>> round(diameter_for_duty(6.0 / 3600, 0.8, 45.0, 0.4, 0.8) * 1000, 2)  # seed 004, eq 2.84
    164.96
    """
    q_h = volume_flow * 3600.0
    base = q_h / (15.0 * math.pi * pitch_ratio * speed_coefficient * filling * inclination_factor)
    if pipe_diameter <= 0.0 and pipe_of is not None:
        d = base**0.4
        for _ in range(100):
            pipe = pipe_of(d)
            d_next = diameter_for_duty(volume_flow, pitch_ratio, speed_coefficient, filling, inclination_factor,
                                       pipe)
            if pipe_of(d_next) == pipe:
                return d_next
            d = d_next
        return d
    if pipe_diameter <= 0.0:
        return (base / (1.0 - pipe_ratio**2)) ** 0.4
    low, high = pipe_diameter, max(2.0 * pipe_diameter, base**0.4 + pipe_diameter)
    while math.sqrt(high) * (high**2 - pipe_diameter**2) < base:
        high *= 2.0
    for _ in range(200):  # bisection to rounding: the function rises monotonically above d_o
        mid = 0.5 * (low + high)
        if math.sqrt(mid) * (mid**2 - pipe_diameter**2) < base:
            low = mid
        else:
            high = mid
        if high - low <= 1e-15 * high:
            break
    return high


def next_standard_diameter(diameter: float) -> float:
    """The smallest standard nominal diameter [m] ≥ ``diameter`` (``data/standard_diameters.csv``).

    Raises :class:`InputError` if even the largest standard size is too small.
    """
    sizes = tables.standard_diameters()
    for size in sizes:
        if size >= diameter * (1.0 - 1e-12):
            return size
    raise InputError(
        f"The required screw diameter {diameter * 1000:.0f} mm exceeds the largest standard size "
        f"{sizes[-1] * 1000:.0f} mm."
    )


@dataclass(frozen=True)
class ScrewDesign:
    """The screw chosen for a duty (SI: m, rad/s, kg/s and m³/s for flows)."""

    diameter_required: float
    diameter: float
    pitch: float
    speed_limit: float
    speed: float
    inclination_factor: float
    filling: float
    volume_flow: float
    mass_flow: float
    capacity_volume: float
    capacity_mass: float

    @property
    def filling_actual(self) -> float:
        """The filling the screw runs with at the duty flow [-]."""
        return self.filling * self.volume_flow / self.capacity_volume

    @property
    def omega(self) -> float:
        """Angular speed [rad/s] (the same as :attr:`speed`, kept for the first releases' name)."""
        return self.speed


def design_screw(*, mass_flow: float, bulk_density: float, filling: float, speed_coefficient: float,
                 pitch_ratio: float, inclination_factor: float, diameter: float | None = None,
                 angular_speed: float | None = None, speed_rpm: float | None = None, pipe_diameter: float = 0.0,
                 pipe_ratio: float = 0.0, speed: float | None = None,
                 pipe_of: Callable[[float], float] | None = None) -> ScrewDesign:
    """Size the screw for a duty: required and standard diameter, pitch, speed, capacity.

    mass_flow [kg/s], bulk_density [kg/m³], filling φ [-] (≤ 1), speed_coefficient k [rpm·m^0.5],
    pitch_ratio S/D [-], inclination_factor C [-]; ``diameter`` [m] forces a size (otherwise the next
    standard size), ``angular_speed`` [rad/s] or ``speed_rpm`` [rpm] forces a speed (otherwise the speed limit
    k/√D, as in seed 004); ``speed``, the name of the releases before 0.1.0, is read in rpm as it was then and
    warns (DeprecationWarning; it goes in 0.3.0).
    ``pipe_diameter`` [m] (a given pipe) or ``pipe_ratio`` d_o/D [-] (a pipe scaling with the screw) is deducted
    from the capacity (:func:`volume_capacity`), or ``pipe_of`` d_o(D) [m] (the screw's standard pipe, see
    :func:`diameter_for_duty`); all absent: the whole circle, as in seed 004. A standard size whose own pipe
    leaves it short of the duty is passed over for the next one.
    """
    check_positive("throughput", mass_flow, "kg/s")
    check_positive("bulk density", bulk_density, "kg/m^3")
    check_positive("filling coefficient", filling)
    if filling > 1.0:
        raise InputError(f"The filling coefficient must be <= 1; got {filling:g}.")
    check_positive("speed coefficient", speed_coefficient, "rpm*m^0.5")
    check_positive("pitch ratio", pitch_ratio)
    check_positive("inclination factor", inclination_factor)
    if inclination_factor > 1.0:
        raise InputError(f"The inclination factor must be <= 1; got {inclination_factor:g}.")
    volume_flow = mass_flow / bulk_density

    def pipe(d: float) -> float:
        if pipe_diameter > 0.0:
            return pipe_diameter
        return pipe_of(d) if pipe_of is not None else pipe_ratio * d

    def carries(d: float) -> bool:
        cap = volume_capacity(d, pitch_ratio * d, angular_speed=speed_limit(d, speed_coefficient), filling=filling,
                              inclination_factor=inclination_factor, pipe_diameter=min(pipe(d), d))
        return bool(cap >= volume_flow * (1.0 - 1e-12))

    sizes = tables.standard_diameters()
    d_req = diameter_for_duty(volume_flow, pitch_ratio, speed_coefficient, filling, inclination_factor,
                              pipe_diameter, pipe_ratio, pipe_of)

    if diameter is None:
        if d_req > sizes[-1]:
            biggest = sizes[-1]
            n_big = speed_limit(biggest, speed_coefficient)
            cap = volume_capacity(biggest, pitch_ratio * biggest, angular_speed=n_big, filling=filling,
                                  inclination_factor=inclination_factor, pipe_diameter=pipe(biggest))
            raise InputError(
                f"The throughput {mass_flow * 3.6:.4g} t/h ({volume_flow * 3600:.4g} m^3/h) exceeds the "
                f"capacity of the largest standard screw ({biggest * 1000:.0f} mm at {n_big / RPM:.1f} rpm): "
                f"{cap * 3600:.4g} m^3/h. Use several screws or a higher filling or speed coefficient."
            )
        d = next_standard_diameter(d_req)
        while not carries(d) and d < sizes[-1]:  # a standard pipe one row larger at the standard size
            d = next_standard_diameter(d * (1.0 + 1e-9))
    else:
        check_positive("screw diameter", diameter, "m")
        d = diameter
    pitch = pitch_ratio * d
    n_lim = speed_limit(d, speed_coefficient)
    forced = (angular_speed, speed_rpm, speed)
    n = n_lim if forced == (None, None, None) else angular_speed_of("design_screw", *forced, old="speed=")
    check_positive("screw speed", n, "rad/s")
    cap_v = volume_capacity(d, pitch, angular_speed=n, filling=filling, inclination_factor=inclination_factor,
                            pipe_diameter=min(pipe(d), d))
    return ScrewDesign(
        diameter_required=d_req, diameter=d, pitch=pitch, speed_limit=n_lim, speed=n,
        inclination_factor=inclination_factor, filling=filling, volume_flow=volume_flow,
        mass_flow=mass_flow, capacity_volume=cap_v, capacity_mass=cap_v * bulk_density,
    )
