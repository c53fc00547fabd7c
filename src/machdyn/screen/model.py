"""The rotary screen's inputs (seed 002) and its engine model."""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..errors import InputError, check_positive
from ..linkage import slider_crank
from ..linkage.model import PointMass, Spring


@dataclass(frozen=True)
class RotaryScreen:
    """Inputs of the rotary grading screen (seed 002, section 1 and the worked example after eq 10).

    R crank radius [m]; m1 crank mass [kg]; L rod length [m]; m2 rod (screen body) mass [kg]; m3 slider mass
    [kg]; l_AS1 crank centroid from A [m]; l_BS2, l_CS2 rod centroid from B and C [m] (l_BS2 + l_CS2 = L);
    m_e counterweight mass [kg]; r_e counterweight radius [m]; omega crank speed [rad/s].
    Valid for R < L (the crank fully rotates); all values > 0 except m1, m3, m_e, l_AS1 >= 0.
    """

    R: float = 0.045
    m1: float = 2.0
    L: float = 3.6
    m2: float = 1200.0
    m3: float = 4.0
    l_AS1: float = 0.02
    l_BS2: float = 1.9
    l_CS2: float = 1.7
    m_e: float = 116.62
    r_e: float = 0.219
    omega: float = 21.0

    def __post_init__(self) -> None:
        for name, unit in (("R", "m"), ("L", "m"), ("m2", "kg"), ("l_BS2", "m"), ("l_CS2", "m"),
                           ("r_e", "m"), ("omega", "rad/s")):
            check_positive(f"rotary screen {name}", getattr(self, name), unit)
        for name, unit in (("m1", "kg"), ("m3", "kg"), ("m_e", "kg"), ("l_AS1", "m")):
            check_positive(f"rotary screen {name}", getattr(self, name), unit, allow_zero=True)
        if not self.R < self.L:
            raise InputError(
                f"The rotary screen crank radius R must be smaller than the rod length L = {self.L:g} m; "
                f"got {self.R:g} m."
            )
        if abs(self.l_BS2 + self.l_CS2 - self.L) > 1e-9 * self.L:
            raise InputError(
                f"The rotary screen rod centroid distances must add up to L = {self.L:g} m; got l_BS2 + l_CS2 = "
                f"{self.l_BS2 + self.l_CS2:g} m."
            )

    @property
    def lam(self) -> float:
        """lambda = R / L [-]."""
        return self.R / self.L

    @property
    def m_C(self) -> float:
        """Mass substituted at the slider C [kg], seed 002 eq 5: m_C = (l_BS2/L) m2 + m3
        (:func:`~machdyn.screen.translating_mass`)."""
        return self.l_BS2 / self.L * self.m2 + self.m3

    # ------------------------------------------------------------------------------------- engine model
    def mechanism(self, spring: bool = False, stiffness: float | None = None):
        """The screen as an engine :class:`~machdyn.linkage.model.Mechanism` (``machdyn.linkage.slider_crank``).

        Bodies: ``crank`` (mass m1, centroid at l_AS1 on A->B, centroidal inertia m1 l_AS1 (R - l_AS1) so that
        its kinetic energy equals that of the static substitute (l_AS1/R) m1 at the pin, as eq 8 assumes);
        ``rod`` (mass m2, centroid l_BS2 from B, centroidal inertia m2 l_BS2 l_CS2: with this inertia the
        two-point substitution of eqs 4-5 is dynamically exact, so the engine's rod energy is exactly
        1/2 (l_CS2/L) m2 v_B^2 + 1/2 (l_BS2/L) m2 v_C^2); ``slider`` (m3); the counterweight as the point mass
        ``counterweight`` (m_e at r_e opposite the pin). Gravity is off (the screen is horizontal).
        With ``spring=True`` a linear spring ``spring`` of stiffness K (default eq 17, m_C omega^2) joins the
        slider to the ground point ``spring_anchor`` on the slide line at the crank centre, with free length
        sqrt(L^2 - R^2): its force is zero at alpha = 90 deg and 270 deg and its extension is exactly the
        slider displacement S' of eq 13 (without the series expansion).
        The engine's crank angle is the paper's alpha (see the module docstring).
        """
        crank_inertia = self.m1 * self.l_AS1 * (self.R - self.l_AS1)
        if crank_inertia < 0:
            raise InputError(
                f"The rotary screen crank centroid l_AS1 must lie between A and B (0 ... {self.R:g} m) for a "
                f"static-equivalent crank inertia; got {self.l_AS1:g} m."
            )
        mech = slider_crank(
            self.R, self.L, 0.0,
            masses=(self.m1, self.m2, self.m3),
            inertias=(crank_inertia, self.m2 * self.l_BS2 * self.l_CS2, 0.0),
            coms=((self.l_AS1, 0.0), (self.l_BS2, 0.0), (0.0, 0.0)),
            name="rotary_screen" + ("_spring" if spring else ""),
        )
        counterweight = PointMass("counterweight", "crank", self.m_e, (-self.r_e, 0.0))
        changes: dict = {"point_masses": (*mech.point_masses, counterweight), "gravity": (0.0, 0.0)}
        if spring:
            k = self.m_C * self.omega**2 if stiffness is None else stiffness  # eq 17 (spring_stiffness)
            ground = dict(mech.ground)
            ground["spring_anchor"] = (0.0, 0.0)
            changes["ground"] = ground
            changes["springs"] = (
                *mech.springs,
                Spring("spring", "slider.B", "ground.spring_anchor", k, float(np.sqrt(self.L**2 - self.R**2))),
            )
        return replace(mech, **changes)


#: The worked example of seed 002 (section 2).
PAPER_SCREEN = RotaryScreen()


def _s(screen: RotaryScreen) -> RotaryScreen:
    if not isinstance(screen, RotaryScreen):
        raise InputError(f"Expected a RotaryScreen; got {type(screen).__name__}.")
    return screen


def link_ratio(screen: RotaryScreen) -> float:
    """lambda = R / L [-] (seed 002, section 1). 0.0125 for the paper's screen."""
    return _s(screen).R / screen.L
