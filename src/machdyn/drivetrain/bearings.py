"""Rolling and plain bearings under the varying load of a machine cycle.

Rolling bearings: the basic rating life of ISO 281 under the load equivalent to the cycle's varying load (the
mean of the p-th power of the load, weighted by the revolutions made under it), the life-adjustment factor a1
for a reliability above 90 %, and the three-parameter Weibull reliability of Shigley's text. Plain bearings: the
mean pressure on the projected area and the product p·v.

Sources
-------
- ISO 281:2007, *Rolling bearings — Dynamic load ratings and rating life*: L10 = (C/P)^p million revolutions,
  p = 3 for ball and 10/3 for roller bearings (§6.2 and §7.2); reliability factor a1 (Table 12).
- R. G. Budynas, J. K. Nisbett, *Shigley's Mechanical Engineering Design*, 8th ed., §11-3 to §11-8:
  eq (11-6) (catalogue rating from a design life at a reliability, Weibull x0 = 0.02, θ − x0 = 4.439,
  b = 1.483) and eq (11-18) (reliability of a chosen bearing); variable loading, §11-8.
- R. L. Mott, *Machine Elements in Mechanical Design*, 4th ed., ch. 14, eq. (14-11), p. 626: mean effective load
  Fm = (Σ Fi^p Ni / N)^(1/p) under varying loads.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..errors import InputError

#: ISO 281:2007 Table 12: reliability [%] -> life-adjustment factor a1.
A1_FACTORS = {90.0: 1.0, 95.0: 0.64, 96.0: 0.55, 97.0: 0.47, 98.0: 0.37, 99.0: 0.25, 99.2: 0.22, 99.4: 0.19,
              99.6: 0.16, 99.8: 0.12, 99.9: 0.093, 99.92: 0.087, 99.94: 0.080, 99.95: 0.077}

#: Weibull parameters of Shigley's text (8th ed., §11-4) for the reliability of a ball or roller bearing.
WEIBULL_X0, WEIBULL_THETA_MINUS_X0, WEIBULL_B = 0.02, 4.439, 1.483


def life_exponent(kind: str) -> float:
    """The load-life exponent p of ISO 281: 3 for ball bearings, 10/3 for roller bearings.

    Parameters
    ----------
    kind : "ball" or "roller".

    Returns
    -------
    float
        p [-].

    Examples
    --------
    >>> life_exponent("roller")
    3.3333333333333335
    """
    if kind == "ball":
        return 3.0
    if kind == "roller":
        return 10.0 / 3.0
    raise InputError(f"A rolling bearing is 'ball' or 'roller'; got {kind!r}.")


def rating_life(capacity: Any, load: Any, kind: str = "ball") -> Any:
    """Basic rating life L10 = (C/P)^p [million revolutions] (ISO 281:2007, eq. in §6.2/§7.2).

    Parameters
    ----------
    capacity : basic dynamic load rating C [N] (> 0).
    load : equivalent dynamic load P [N] (>= 0; a bearing without load lives for ever: inf).
    kind : "ball" (p = 3) or "roller" (p = 10/3).

    Returns
    -------
    float or ndarray
        L10 [10^6 rev], reached or exceeded by 90 % of a large group of identical bearings.

    Examples
    --------
    A bearing of C = 19.5 kN under 2.278 kN lives (19.5/2.278)^3 = 627 million revolutions:

    >>> round(float(rating_life(19.5e3, 2.278e3)), 1)
    627.2
    """
    p = life_exponent(kind)
    c = np.asarray(capacity, dtype=float)
    f = np.asarray(load, dtype=float)
    with np.errstate(divide="ignore"):
        life = np.where(f > 0, (c / np.where(f > 0, f, 1.0)) ** p, np.inf)
    return life if life.ndim else float(life)


def reliability_factor(reliability: float) -> float:
    """ISO 281:2007 Table 12: the life-adjustment factor a1 for a reliability [%] from 90 to 99.95 (linear
    between the tabulated values).

    Parameters
    ----------
    reliability : R [%], 90 <= R <= 99.95.

    Returns
    -------
    float
        a1 [-]; the life at R is a1 · L10.

    Examples
    --------
    >>> reliability_factor(99.0)
    0.25
    """
    keys = np.array(sorted(A1_FACTORS))
    if not keys[0] <= reliability <= keys[-1]:
        raise InputError(f"ISO 281 gives the reliability factor a1 for 90 % to 99.95 %; got {reliability:g} %.")
    return float(np.interp(reliability, keys, [A1_FACTORS[k] for k in keys]))


def catalogue_rating(design_load: float, design_life: float, reliability: float, kind: str = "ball",
                     application_factor: float = 1.0) -> float:
    """The catalogue rating C10 a bearing needs to reach ``design_life`` rating lives at ``reliability``
    (Shigley's MED, 8th ed., eq. 11-6, with the Weibull parameters of §11-4).

    C10 = a_f F_D [x_D / (x0 + (θ − x0)(ln 1/R)^(1/b))]^(1/a)

    Parameters
    ----------
    design_load : F_D [N].
    design_life : x_D, the design life as a multiple of the rating life (L_D / L_10) [-].
    reliability : R, 0 < R < 1.
    kind : "ball" (a = 3) or "roller" (a = 10/3).
    application_factor : a_f [-] >= 1.

    Returns
    -------
    float
        C10 [N].

    Examples
    --------
    Shigley 8th ed., problem 11-1 (solutions manual): F_D = 2.278 kN, x_D = 540, R = 0.90 give 18.59 kN:

    >>> round(catalogue_rating(2.278e3, 540.0, 0.90) / 1e3, 2)
    18.59
    """
    if not 0.0 < reliability < 1.0:
        raise InputError(f"A reliability is between 0 and 1; got {reliability:g}.")
    a = life_exponent(kind)
    denominator = WEIBULL_X0 + WEIBULL_THETA_MINUS_X0 * math.log(1.0 / reliability) ** (1.0 / WEIBULL_B)
    return application_factor * design_load * (design_life / denominator) ** (1.0 / a)


def weibull_reliability(capacity: float, design_load: float, design_life: float, kind: str = "ball",
                        application_factor: float = 1.0) -> float:
    """Reliability of a chosen bearing at ``design_life`` rating lives (Shigley's MED, 8th ed., eq. 11-18).

    R = exp{−[(x_D (a_f F_D / C10)^a − x0) / (θ − x0)]^b}

    Parameters
    ----------
    capacity : C10 [N]; design_load : F_D [N]; design_life : x_D [-]; kind : "ball" or "roller";
    application_factor : a_f [-].

    Returns
    -------
    float
        R [-] (1 where the life is within the Weibull guaranteed life x0).

    Examples
    --------
    Shigley 8th ed., problem 11-1: the chosen 02-30 mm bearing of C10 = 19.5 kN has R = 0.919:

    >>> round(weibull_reliability(19.5e3, 2.278e3, 540.0), 3)
    0.919
    """
    a = life_exponent(kind)
    x = design_life * (application_factor * design_load / capacity) ** a
    if x <= WEIBULL_X0:
        return 1.0
    return math.exp(-(((x - WEIBULL_X0) / WEIBULL_THETA_MINUS_X0) ** WEIBULL_B))


def mean_effective_load(loads: Any, revolutions: Any, kind: str = "ball") -> Any:
    """The constant load of equal life to a varying one (Mott, eq. 14-11; ISO 281 §7.2 for variable load):

    Fm = (Σ Fi^p Ni / Σ Ni)^(1/p)

    Parameters
    ----------
    loads : Fi [N] along the last axis (positions of a cycle, or load levels).
    revolutions : Ni, the revolutions (or any measure proportional to them: time at constant speed, the
        relative rotation angle) made under each load, same shape.
    kind : "ball" (p = 3) or "roller" (p = 10/3).

    Returns
    -------
    float or ndarray
        Fm [N] (over the last axis).

    Examples
    --------
    Mott, 4th ed., Example Problem 14-6: 650 lb for 30 min, 750 lb for 10 min, 250 lb for 20 min at constant
    speed give Fm = 597 lb:

    >>> round(float(mean_effective_load([650.0, 750.0, 250.0], [30.0, 10.0, 20.0])), 0)
    597.0
    """
    p = life_exponent(kind)
    f = np.abs(np.asarray(loads, dtype=float))
    n = np.abs(np.asarray(revolutions, dtype=float))
    total = np.sum(n, axis=-1)
    if np.any(total <= 0):
        raise InputError("The bearing makes no revolution over the cycle: its rating life is not defined.")
    out = (np.sum(f**p * n, axis=-1) / total) ** (1.0 / p)
    return out if np.ndim(out) else float(out)


def plain_bearing_pv(load: Any, diameter: float, length: float, sliding_speed: Any) -> tuple[Any, Any]:
    """Mean pressure on the projected area and the p·v product of a plain (journal) bearing.

    p = F / (d·l),  v = |ω_rel|·d/2  (Shigley's MED, 8th ed., §12-15, boundary-lubricated bearings; the
    allowable p, v and pv are the bushing maker's).

    Parameters
    ----------
    load : F [N]; diameter : d [m] > 0; length : l [m] > 0; sliding_speed : v [m/s].

    Returns
    -------
    (p [Pa], pv [Pa·m/s])

    Examples
    --------
    >>> p, pv = plain_bearing_pv(10e3, 0.04, 0.05, 0.5)
    >>> round(float(p) / 1e6, 3), round(float(pv) / 1e6, 3)
    (5.0, 2.5)
    """
    if diameter <= 0 or length <= 0:
        raise InputError(f"A plain bearing needs a diameter and a length > 0 m; got {diameter:g} m, {length:g} m.")
    p = np.asarray(load, dtype=float) / (diameter * length)
    return p, p * np.abs(np.asarray(sliding_speed, dtype=float))
