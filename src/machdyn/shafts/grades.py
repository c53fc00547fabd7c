"""Balance quality grades of rigid rotors (ISO 21940-11:2016, formerly ISO 1940-1:2003).

A grade G names the product e_per w [mm/s] of the permissible specific unbalance and the service speed; the
permissible residual unbalance of a rotor of mass m [kg] at speed w [rad/s] is

    U_per = 1000 G m / w   [g*mm]    (ISO 21940-11:2016, with G = e_per w; ISO 1940-1:2003, sec. 6.2),

i.e. U_per = G m / w in SI (G in m/s, U in kg*m). The grades run in steps of 2.5 from G 0.4 to G 4000 (ISO
21940-11:2016, table 1 of grades; e.g. G 6.3 for fans, pumps, electric motors, G 2.5 for turbines).

Allocation to the two bearing planes A and B of a rotor whose centre of mass lies between them at distances
L_A and L_B (L = L_A + L_B): U_per,A = U_per L_B / L and U_per,B = U_per L_A / L, each kept within 0.3 ... 0.7
of U_per (ISO 1940-1:2003, sec. 7.2, allocation to the bearing planes; ISO 21940-11:2016 keeps it). A
residual unbalance is carried to the bearing planes as the pair of unbalances there with the same force and
couple (:func:`machdyn.shafts.balance.equivalent_in_planes`).
"""

from __future__ import annotations

from dataclasses import dataclass

from ..errors import InputError, check_finite, check_positive

__all__ = ["GRADES", "permissible_unbalance", "allocate", "GradeCheck"]

#: The balance quality grades G [mm/s] of ISO 21940-11:2016.
GRADES = (0.4, 1.0, 2.5, 6.3, 16.0, 40.0, 100.0, 250.0, 630.0, 1600.0, 4000.0)


def check_grade(grade: float) -> None:
    check_finite("balance quality grade G", grade, "mm/s")
    if not any(abs(grade - g) <= 1e-9 * g for g in GRADES):
        names = ", ".join(f"{g:g}" for g in GRADES)
        raise InputError(f"The balance quality grade must be one of ISO 21940-11's G {names} (mm/s); got G {grade:g}.")


def permissible_unbalance(grade: float, rotor_mass: float, speed: float) -> float:
    """U_per [kg*m] = G [mm/s] * 1e-3 * m / w (ISO 21940-11:2016, G = e_per w, U_per = e_per m).

    Parameters: grade G [mm/s] (one of :data:`GRADES`); rotor_mass m [kg] > 0; speed w [rad/s] > 0 (the
    maximum service speed).

    Examples
    --------
    A 100 kg rotor at 3000 rpm to G 6.3: U_per = 1000 * 6.3 * 100 / 314.16 = 2005 g*mm.

    >>> import math
    >>> round(permissible_unbalance(6.3, 100.0, 3000 * math.pi / 30) * 1e6)
    2005
    """
    check_grade(grade)
    check_positive("rotor mass", rotor_mass, "kg")
    check_positive("service speed", speed, "rad/s")
    return grade * 1e-3 * rotor_mass / speed


def allocate(u_per: float, com: float, bearing_a: float, bearing_b: float) -> tuple[float, float]:
    """U_per,A and U_per,B [kg*m] of a rotor whose centre of mass is at ``com`` [m] between bearings at
    ``bearing_a`` and ``bearing_b`` [m]: U_per L_B / L and U_per L_A / L, clipped to 0.3 ... 0.7 U_per
    (ISO 1940-1:2003, sec. 7.2).

    Examples
    --------
    >>> allocate(1.0, 0.25, 0.0, 1.0)
    (0.7, 0.3)
    >>> allocate(1.0, 0.5, 0.0, 1.0)
    (0.5, 0.5)
    """
    check_positive("permissible residual unbalance", u_per, "kg*m", allow_zero=True)
    span = bearing_b - bearing_a
    if abs(span) <= 1e-9 * max(1.0, abs(bearing_a), abs(bearing_b)):
        raise InputError(f"The two bearing planes must stand at different axial positions; both at {bearing_a:g} m.")
    la, lb = (com - bearing_a) / span, (bearing_b - com) / span
    if la < 0.0 or lb < 0.0:
        raise InputError(f"The allocation of ISO 21940-11 sec. 7.2 is for a centre of mass between the bearings; "
                         f"it is at {com:g} m, outside {min(bearing_a, bearing_b):g} ... "
                         f"{max(bearing_a, bearing_b):g} m.")
    share_a = min(0.7, max(0.3, lb))
    share_b = min(0.7, max(0.3, la))
    return u_per * share_a, u_per * share_b


@dataclass(frozen=True)
class GradeCheck:
    """A rotor against its grade: G [mm/s], rotor mass [kg], speed [rad/s], U_per [kg*m], the allocation to
    bearing planes A and B [kg*m], the residual unbalance in each [kg*m] and the margin (allowed / residual,
    >= 1 passes)."""

    grade: float
    rotor_mass: float
    speed: float
    u_per: float
    allowed: tuple[float, float]
    residual: tuple[float, float]
    bearings: tuple[str, str]

    @property
    def margin(self) -> float:
        ratios = [a / r if r > 0 else float("inf") for a, r in zip(self.allowed, self.residual, strict=True)]
        return min(ratios)

    @property
    def passes(self) -> bool:
        return all(r <= a * (1 + 1e-12) for a, r in zip(self.allowed, self.residual, strict=True))

    @property
    def achieved_grade(self) -> float:
        """The G value [mm/s] the residual corresponds to: e w with e = (U_A + U_B) / m."""
        return sum(self.residual) / self.rotor_mass * self.speed * 1e3
