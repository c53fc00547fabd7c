"""Rotary grading screen: slider-crank energy analysis and the energy-storing spring (seed paper 002).

Source: Yuan Rui et al., *Study of Vibration Decreasing and Energy Saving of Rotary Grading Screen* (seed 002,
Trans. CSAM 2013). Corrections follow ``seed-reproduction.md`` section 002 (cited as "repro 002.x").

The screen is modelled as a centred slider-crank: crank A-B (radius R, mass m1, centroid S1 at l_AS1 from A),
rod B-C (length L, mass m2, centroid S2 at l_BS2 from B and l_CS2 from C), slider C (mass m3), a counterweight
m_e at radius r_e opposite the crank pin, crank speed omega. The screen moves horizontally, so gravity does no
work and is left out.

**Crank angle.** The paper's alpha is the angle between the crank A->B and the x axis, with the slider on the
+x side of A (eq 1: S = L + R[cos alpha - ...] is largest at alpha = 0) and alpha = omega t increasing
counter-clockwise (eq 2: v = dS/dt). The engine's slider-crank has its slide line along +x through the crank
centre and measures its crank angle counter-clockwise from +x, so **alpha = the engine's crank angle** and
omega = the engine's ``speed``; the paper's S is the slider's x coordinate (the engine's slide displacement).

Every function takes and returns SI floats or numpy arrays (m, kg, rad, rad/s, J, N/m, N m, W).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..errors import InputError, check_finite, check_positive

__all__ = [
    "RotaryScreen",
    "PAPER_SCREEN",
    "link_ratio",
    "slider_position_series",
    "slider_velocity_series",
    "slider_acceleration_series",
    "slider_position_exact",
    "slider_velocity_exact",
    "rotating_mass",
    "translating_mass",
    "t1",
    "t1_max",
    "t1_max_with_lambda",
    "t2",
    "t3",
    "t3_printed",
    "total_energy",
    "energy_range",
    "fluctuation_power",
    "spring_stiffness",
    "spring_displacement_series",
    "spring_displacement_exact",
    "spring_energy",
    "w1_ratio_eq20",
    "w1_ratio_first_order",
    "w1_ratio_printed",
    "w1_range_eq20",
    "w1_range_printed",
    "pr_printed",
    "pr_first_order",
    "pr_eq20",
    "input_torque",
    "energy_figures",
]


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
        from ..linkage import slider_crank
        from ..linkage.model import PointMass, Spring

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
            k = spring_stiffness(self) if stiffness is None else stiffness
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


# ---------------------------------------------------------------------------------------- eqs 1-3


def slider_position_series(alpha, R, L):
    """Slider position of a centred slider-crank, first order in λ (seed 002, eq 1).

    S ≈ L + R [cos α − (λ/4)(1 − cos 2α)], λ = R/L: the expansion of the exact
    S = R cos α + √(L² − R² sin² α) (:func:`slider_position_exact`), correct (repro 002.3).

    Parameters
    ----------
    alpha : float or array
        Crank angle α [rad], any real.
    R : float
        Crank radius [m], > 0.
    L : float
        Rod length [m], > R.

    Returns
    -------
    float or array
        S [m], measured from the crank centre along the slide line. Valid for λ ≲ 0.3: the error is about
        R λ³ sin⁴ α / 8.

    Examples
    --------
    >>> round(float(slider_position_series(np.pi / 3, 0.1, 0.8)), 7)
    0.8453125
    >>> round(float(slider_position_exact(np.pi / 3, 0.1, 0.8)), 7)
    0.8452987
    """
    check_positive("crank radius R", R, "m")
    check_positive("rod length L", L, "m")
    lam = R / L
    return L + R * (np.cos(alpha) - lam / 4.0 * (1.0 - np.cos(2.0 * alpha)))


def slider_velocity_series(alpha, R, L, omega):
    """Slider velocity, first order in λ (seed 002, eq 2): v ≈ −ω R (sin α + (λ/2) sin 2α).

    Parameters
    ----------
    alpha : float or array
        Crank angle α [rad].
    R, L : float
        Crank radius and rod length [m], 0 < R < L.
    omega : float
        Constant crank speed ω [rad/s].

    Returns
    -------
    float or array
        v [m/s]; correct to first order in λ = R/L (valid for λ ≲ 0.3).

    Examples
    --------
    >>> round(float(slider_velocity_series(np.pi / 3, 0.1, 0.8, 21.0)), 6)
    -1.932319
    """
    check_positive("crank radius R", R, "m")
    check_positive("rod length L", L, "m")
    lam = R / L
    return -omega * R * (np.sin(alpha) + lam / 2.0 * np.sin(2.0 * alpha))


def slider_acceleration_series(alpha, R, L, omega):
    """Slider acceleration, first order in λ (seed 002, eq 3): a ≈ −ω² R (cos α + λ cos 2α).

    Parameters
    ----------
    alpha : float or array
        Crank angle α [rad].
    R, L : float
        Crank radius and rod length [m], 0 < R < L.
    omega : float
        Constant crank speed ω [rad/s].

    Returns
    -------
    float or array
        a [m/s²]; correct to first order in λ = R/L (valid for λ ≲ 0.3).

    Examples
    --------
    >>> round(float(slider_acceleration_series(np.pi / 3, 0.1, 0.8, 21.0)), 5)
    -19.29375
    """
    check_positive("crank radius R", R, "m")
    check_positive("rod length L", L, "m")
    lam = R / L
    return -omega**2 * R * (np.cos(alpha) + lam * np.cos(2.0 * alpha))


def slider_position_exact(alpha, R, L):
    """Exact slider position S = R cos alpha + sqrt(L^2 - R^2 sin^2 alpha) [m] (centred slider-crank).

    Parameters: alpha [rad]; R [m] > 0; L [m] > R.
    """
    check_positive("crank radius R", R, "m")
    check_positive("rod length L", L, "m")
    return R * np.cos(alpha) + np.sqrt(L**2 - (R * np.sin(alpha)) ** 2)


def slider_velocity_exact(alpha, R, L, omega):
    """Exact slider velocity dS/dt = -omega R sin alpha [1 + R cos alpha / sqrt(L^2 - R^2 sin^2 alpha)] [m/s].

    Parameters: alpha [rad]; R [m] > 0; L [m] > R; omega [rad/s] (constant).
    """
    check_positive("crank radius R", R, "m")
    check_positive("rod length L", L, "m")
    s, c = np.sin(alpha), np.cos(alpha)
    return -omega * R * s * (1.0 + R * c / np.sqrt(L**2 - (R * s) ** 2))


# -------------------------------------------------------------------------------------- eqs 4-10


def rotating_mass(screen: RotaryScreen) -> float:
    """Mass substituted at the crank pin B (seed 002, eq 4): m_B = (l_AS1/R) m1 + (l_CS2/L) m2.

    Static two-point substitution of the crank and of the rod's share at B (correct; repro 002).

    Parameters
    ----------
    screen : RotaryScreen
        The screen: R, L [m]; m1, m2 [kg]; l_AS1, l_CS2 [m].

    Returns
    -------
    float
        m_B [kg].

    Examples
    --------
    >>> round(rotating_mass(PAPER_SCREEN), 4)
    567.5556
    """
    s = _s(screen)
    return s.l_AS1 / s.R * s.m1 + s.l_CS2 / s.L * s.m2


def translating_mass(screen: RotaryScreen) -> float:
    """Mass substituted at the slider C (seed 002, eq 5): m_C = (l_BS2/L) m2 + m3.

    Parameters
    ----------
    screen : RotaryScreen
        The screen: L, l_BS2 [m]; m2, m3 [kg].

    Returns
    -------
    float
        m_C [kg].

    Examples
    --------
    >>> round(translating_mass(PAPER_SCREEN), 4)
    637.3333
    """
    s = _s(screen)
    return s.l_BS2 / s.L * s.m2 + s.m3


def t1(screen: RotaryScreen, alpha, *, with_lambda: bool = True):
    """Seed 002 eq 7: kinetic energy of the translating mass, T1 = 1/2 m_C R^2 omega^2 f^2 [J].

    f = sin alpha + (lambda/2) sin 2 alpha (eq 2), or f = sin alpha with ``with_lambda=False`` (as eq 15 does).
    alpha [rad] (any real); first order in lambda.
    """
    s = _s(screen)
    check_finite("crank angle alpha", alpha, "rad")
    lam = s.lam if with_lambda else 0.0
    f = np.sin(alpha) + lam / 2.0 * np.sin(2.0 * np.asarray(alpha, dtype=float))
    return 0.5 * translating_mass(s) * s.R**2 * s.omega**2 * f**2


def t1_max(screen: RotaryScreen) -> float:
    """Largest kinetic energy of the translating mass (seed 002, eq 15): T1max = ½ m_C R² ω².

    Parameters
    ----------
    screen : RotaryScreen
        The screen: R [m], ω [rad/s] and the masses of eq 5 [kg].

    Returns
    -------
    float
        T1max [J] with λ = R/L ignored, as the paper does; :func:`t1_max_with_lambda` keeps λ (it is 0.0156 %
        larger for the paper's screen). Valid for λ ≲ 0.1.

    Examples
    --------
    >>> round(t1_max(PAPER_SCREEN), 4)
    284.5773
    """
    s = _s(screen)
    return 0.5 * translating_mass(s) * s.R**2 * s.omega**2


def t1_max_with_lambda(screen: RotaryScreen) -> tuple[float, float]:
    """Maximum of eq 7 with lambda kept (repro 002.2): (T1max [J], alpha* [rad]).

    d/dalpha (sin alpha + (lambda/2) sin 2 alpha) = 0 gives 2 lambda c^2 + c - lambda = 0,
    c = cos alpha* = (-1 + sqrt(1 + 8 lambda^2)) / (4 lambda). 284.6218 J at 89.284 deg for the paper's screen
    (ignoring lambda underestimates T1max by 0.0156 %). Valid for 0 < lambda < 1.
    """
    s = _s(screen)
    lam = s.lam
    c = (-1.0 + np.sqrt(1.0 + 8.0 * lam**2)) / (4.0 * lam)
    a = float(np.arccos(c))
    return float(t1(s, a)), a


def t2(screen: RotaryScreen) -> float:
    """Seed 002 eq 8: T2 = 1/2 m_B R^2 omega^2 [J], constant (253.4206 J for the paper's screen)."""
    s = _s(screen)
    return 0.5 * rotating_mass(s) * s.R**2 * s.omega**2


def t3(screen: RotaryScreen) -> float:
    """Seed 002 eq 9: T3 = 1/2 m_e r_e^2 omega^2 [J], constant (1233.3032 J; the paper prints 1233.31).

    Eqs 10 and 19 print 1/2 m_e r_e omega^2 (square missing); the numbers in the text use the square.
    """
    s = _s(screen)
    return 0.5 * s.m_e * s.r_e**2 * s.omega**2


def t3_printed(screen: RotaryScreen) -> float:
    """Seed 002 eqs 10/19 as printed: 1/2 m_e r_e omega^2 (dimensionally wrong: kg m/s^2; 5631.52 for the
    paper's screen). Kept only to document the misprint; use :func:`t3`."""
    s = _s(screen)
    return 0.5 * s.m_e * s.r_e * s.omega**2


def total_energy(screen: RotaryScreen, alpha, *, with_lambda: bool = True):
    """Seed 002 eqs 6/10 (with the square on r_e): W = T1 + T2 + T3 [J]. alpha [rad]."""
    return t1(screen, alpha, with_lambda=with_lambda) + t2(screen) + t3(screen)


def energy_range(screen: RotaryScreen) -> tuple[float, float]:
    """Range of W (seed 002, text after eq 10): (T2 + T3, T2 + T3 + T1max) [J], lambda ignored.

    1486.7239 ... 1771.3012 J for the paper's screen (paper: 1486.73 ~ 1771.31 J).
    """
    base = t2(screen) + t3(screen)
    return base, base + t1_max(screen)


def fluctuation_power(screen: RotaryScreen) -> float:
    """Power of the energy fluctuation (seed 002 section 2): 2 T1max per revolution, T1max omega / pi [W].

    1902.26 W for the paper's screen (paper: 1.90 kW). This counts the two energy rises per revolution only;
    counting rises and falls would double it (repro 002.1 item 7).
    """
    s = _s(screen)
    return t1_max(s) * s.omega / np.pi


# ---------------------------------------------------------------------------------- eqs 13-26, spring


def spring_stiffness(screen: RotaryScreen) -> float:
    """Stiffness of the energy-storing spring (seed 002, eq 17): K = m_C ω².

    From T1max = V1max = ½ K R² (eqs 14–16); √(K/m_C) = ω, i.e. the spring tunes the translating mass to
    resonate at the running speed.

    Parameters
    ----------
    screen : RotaryScreen
        The screen: ω [rad/s] and the masses of eq 5 [kg].

    Returns
    -------
    float
        K [N/m].

    Examples
    --------
    >>> round(spring_stiffness(PAPER_SCREEN))
    281064
    """
    s = _s(screen)
    return translating_mass(s) * s.omega**2


def spring_displacement_series(alpha, R, L):
    """Seed 002 eq 13: S' = S - sqrt(L^2 - R^2) ~ R [cos alpha + (lambda/4)(1 + cos 2 alpha)] [m].

    Correct to first order (repro 002.3). Parameters: alpha [rad]; R [m] > 0; L [m] > R.
    """
    check_positive("crank radius R", R, "m")
    check_positive("rod length L", L, "m")
    lam = R / L
    return R * (np.cos(alpha) + lam / 4.0 * (1.0 + np.cos(2.0 * alpha)))


def spring_displacement_exact(alpha, R, L):
    """Exact spring extension S' = S - sqrt(L^2 - R^2) [m], zero at alpha = 90 deg and 270 deg.

    Parameters: alpha [rad]; R [m] > 0; L [m] > R.
    """
    return slider_position_exact(alpha, R, L) - np.sqrt(L**2 - R**2)


def spring_energy(screen: RotaryScreen, alpha, *, exact: bool = False):
    """Seed 002 eq 18: V1 = 1/2 K S'^2 [J] with K from eq 17 and S' from eq 13 (or exact with ``exact``)."""
    s = _s(screen)
    sp = spring_displacement_exact(alpha, s.R, s.L) if exact else spring_displacement_series(alpha, s.R, s.L)
    return 0.5 * spring_stiffness(s) * sp**2


def w1_ratio_eq20(alpha, lam):
    """Seed 002 eq 20 divided by T1max: W1/T1max = (sin a + (lam/2) sin 2a)^2 + (cos a + (lam/4)(1 + cos 2a))^2.

    Evaluated as printed, without further expansion (eq 20 itself is correct). alpha [rad]; lam = R/L in (0, 1).
    """
    check_positive("lambda", lam)
    a = np.asarray(alpha, dtype=float)
    return (np.sin(a) + lam / 2.0 * np.sin(2.0 * a)) ** 2 + (np.cos(a) + lam / 4.0 * (1.0 + np.cos(2.0 * a))) ** 2


def w1_ratio_first_order(alpha, lam):
    """Corrected seed 002 eq 21: W1/T1max ~ 1 + lam cos alpha (1 + sin^2 alpha) (repro 002.3).

    The paper prints 1 + 3 lam sin^2 alpha cos alpha, which is **wrong** (the difference is lam cos a cos 2a); it
    is what eq 20 gives with a sign error in eq 13's (1 + cos 2a). alpha [rad]; lam = R/L, small.
    """
    check_positive("lambda", lam)
    a = np.asarray(alpha, dtype=float)
    return 1.0 + lam * np.cos(a) * (1.0 + np.sin(a) ** 2)


def w1_ratio_printed(alpha, lam):
    """Seed 002 eq 21 as printed (wrong, see :func:`w1_ratio_first_order`): 1 + 3 lam sin^2 alpha cos alpha."""
    check_positive("lambda", lam)
    a = np.asarray(alpha, dtype=float)
    return 1.0 + 3.0 * lam * np.sin(a) ** 2 * np.cos(a)


def w1_range_printed(lam) -> tuple[float, float]:
    """Seed 002 eqs 23-24: W1/T1max in 1 -+ (2 lam / 3) sqrt 3 (from the wrong eq 21). lam = R/L."""
    check_positive("lambda", lam)
    d = 2.0 * lam * np.sqrt(3.0) / 3.0
    return 1.0 - d, 1.0 + d


def w1_range_eq20(lam, samples: int = 400_001) -> tuple[float, float]:
    """Exact range of eq 20's W1/T1max over a revolution [-] (repro 002.3: [0.986444, 1.013660] at lam = 0.0125).

    The extremes (near alpha = 35.26 deg and 144.74 deg) are located on a uniform grid of ``samples`` points
    and then refined by re-sampling around them. lam = R/L in (0, 1).
    """
    check_positive("lambda", lam)
    a = np.linspace(0.0, 2.0 * np.pi, int(samples))
    w = w1_ratio_eq20(a, lam)

    def ratio(x):
        return w1_ratio_eq20(np.asarray(x), lam)

    return _refined_extreme(ratio, a, w, "min"), _refined_extreme(ratio, a, w, "max")


def pr_printed(lam) -> float:
    """Seed 002 eq 26: P_r = 4 lam sqrt(3) / 3 (0.028868 at lam = 0.0125; the paper prints the truncated 0.028).

    Rests on the wrong eq 21; the correct value is :func:`pr_first_order` / :func:`pr_eq20`.
    """
    check_positive("lambda", lam)
    return 4.0 * lam * np.sqrt(3.0) / 3.0


def pr_first_order(lam) -> float:
    """Corrected seed 002 eq 26: P_r = (8/3) sqrt(2/3) lam = 2.17732 lam (0.027217 at lam = 0.0125).

    From the corrected eq 21, extremes at cos alpha = +-sqrt(2/3) (repro 002.3). lam = R/L, small.
    """
    check_positive("lambda", lam)
    return 8.0 / 3.0 * np.sqrt(2.0 / 3.0) * lam


def pr_eq20(lam) -> float:
    """P_r = (max - min) of eq 20's W1/T1max, evaluated exactly (repro 002.3: 0.027217 at lam = 0.0125)."""
    lo, hi = w1_range_eq20(lam)
    return hi - lo


def input_torque(screen: RotaryScreen, alpha, *, spring: bool = False):
    """Seed 002 eq 12: M_in = dW/dalpha [N m] at constant omega, W from eq 10 (and eq 19 with ``spring``).

    dT1/dalpha = m_C R^2 omega^2 f f' with f = sin a + (lam/2) sin 2a, f' = cos a + lam cos 2a; the spring adds
    K S' dS'/dalpha = -K R^2 g f with g = cos a + (lam/4)(1 + cos 2a) (eq 13). Peak |M_in| of the paper's screen:
    287.16 N m without the spring, 7.115 N m with it (repro 002.3). alpha [rad].
    """
    s = _s(screen)
    check_finite("crank angle alpha", alpha, "rad")
    a = np.asarray(alpha, dtype=float)
    lam = s.lam
    f = np.sin(a) + lam / 2.0 * np.sin(2.0 * a)
    fp = np.cos(a) + lam * np.cos(2.0 * a)
    m = translating_mass(s) * s.R**2 * s.omega**2 * f * fp
    if spring:
        g = np.cos(a) + lam / 4.0 * (1.0 + np.cos(2.0 * a))
        m = m - spring_stiffness(s) * s.R**2 * g * f
    return m


# ---------------------------------------------------------------------------------------- figures


def _entry(quantity, unit, paper, formula, engine, source, note=""):
    return {
        "quantity": quantity,
        "unit": unit,
        "paper": paper,
        "formula": None if formula is None else float(formula),
        "engine": None if engine is None else float(engine),
        "source": source,
        "note": note,
    }


def _refined_extreme(func, grid, values, pick):
    """The extreme ``pick`` ('max' or 'min') of a smooth periodic func sampled on a uniform grid, refined by
    re-sampling ever finer around the best sample (:func:`machdyn.linkage.extremes.refine_extreme`)."""
    from ..linkage.extremes import refine_extreme

    return refine_extreme(func, grid, values, pick)[1]


def energy_figures(screen: RotaryScreen = PAPER_SCREEN, samples: int = 3601) -> dict[str, dict]:
    """The paper's energy figures next to machdyn's: the paper's formula and the engine's exact value.

    Returns a dict keyed by figure name; each value is a dict with ``quantity`` (text), ``unit``, ``paper``
    (the printed value for the paper's own screen, or None for another screen or where the paper prints none),
    ``formula`` (the paper's formula, corrected where it is wrong, evaluated for ``screen``), ``engine`` (the
    same quantity from the exact engine model :meth:`RotaryScreen.mechanism`, or None where not applicable),
    ``source`` (equation) and ``note``. Keys: lambda, m_B, m_C, T1max, T1max_lambda, T2, T3, W_min, W_max,
    fluctuation_power, K, W1_min_ratio, W1_max_ratio, P_r, P_r_printed, W1_fluctuation, M_in_peak,
    M_in_peak_spring.

    The engine's values are found on a uniform grid of ``samples`` crank angles with the extremes refined by
    re-sampling ever finer around them, so they are exact to far below the printed digits.
    """
    from ..linkage import energy, kinetostatics

    s = _s(screen)
    paper = s == PAPER_SCREEN
    w = s.omega
    grid = np.linspace(0.0, 2.0 * np.pi, int(samples))
    plain, sprung = s.mechanism(spring=False), s.mechanism(spring=True)

    def total(mech):
        return lambda a: energy(mech, a, speed=w).total

    def torque(mech):
        return lambda a: kinetostatics(mech, a, speed=w).driving_torque

    def extremes(func):
        values = func(grid)
        return _refined_extreme(func, grid, values, "min"), _refined_extreme(func, grid, values, "max")

    w_min, w_max = extremes(total(plain))
    t3_engine = float(energy(plain, np.zeros(1), speed=w).kinetic["counterweight"][0])
    t2_engine = w_min - t3_engine  # at the dead centres the slider is at rest: W = T2 + T3 exactly
    t1_engine = w_max - w_min
    # with the spring, W1 = T1 + V1 = W' - (T2 + T3)
    w1_lo, w1_hi = (v - w_min for v in extremes(total(sprung)))
    m0_lo, m0_hi = extremes(torque(plain))
    m1_lo, m1_hi = extremes(torque(sprung))
    m0_peak, m1_peak = max(-m0_lo, m0_hi), max(-m1_lo, m1_hi)
    t1m = t1_max(s)
    lam = s.lam
    lo20, hi20 = w1_range_eq20(lam)
    tl, _ = t1_max_with_lambda(s)
    fine = np.linspace(0.0, 2.0 * np.pi, 20001)
    return {
        "lambda": _entry("crank-rod ratio lambda = R/L", "", 0.0125 if paper else None, lam, None, "sec. 1"),
        "m_B": _entry("rotating mass m_B", "kg", None, rotating_mass(s), None, "eq 4"),
        "m_C": _entry("translating mass m_C", "kg", None, translating_mass(s), None, "eq 5"),
        "T1max": _entry("max kinetic energy of the translating parts T1max", "J", 284.58 if paper else None, t1m,
                        t1_engine, "eq 15", "formula ignores lambda; engine: exact kinematics"),
        "T1max_lambda": _entry("T1max with lambda kept (eq 7)", "J", None, tl, t1_engine, "eq 7",
                               "maximum of eq 7 at cos a = (-1 + sqrt(1 + 8 lam^2)) / (4 lam)"),
        "T2": _entry("kinetic energy of the rotating mass T2", "J", 253.42 if paper else None, t2(s), t2_engine,
                     "eq 8"),
        "T3": _entry("kinetic energy of the counterweight T3", "J", 1233.31 if paper else None, t3(s), t3_engine,
                     "eq 9", "eqs 10/19 print r_e without the square"),
        "W_min": _entry("total kinetic energy, minimum", "J", 1486.73 if paper else None, energy_range(s)[0],
                        w_min, "eq 10"),
        "W_max": _entry("total kinetic energy, maximum", "J", 1771.31 if paper else None, energy_range(s)[1],
                        w_max, "eq 10"),
        "fluctuation_power": _entry("power of the energy fluctuation T1max omega / pi", "W",
                                    1900.0 if paper else None, fluctuation_power(s), t1_engine * w / np.pi,
                                    "sec. 2", "two energy rises per revolution"),
        "K": _entry("spring stiffness K = m_C omega^2", "N/m", None, spring_stiffness(s), None, "eq 17"),
        "W1_min_ratio": _entry("W1 = T1 + V1, minimum / T1max", "", 0.986 if paper else None, lo20,
                               w1_lo / t1m, "eqs 20, 24", "formula: eq 20 evaluated exactly"),
        "W1_max_ratio": _entry("W1 = T1 + V1, maximum / T1max", "", 1.014 if paper else None, hi20,
                               w1_hi / t1m, "eqs 20, 23", "formula: eq 20 evaluated exactly"),
        "P_r": _entry("relative fluctuation of W1, P_r", "", 0.028 if paper else None, pr_first_order(lam),
                      (w1_hi - w1_lo) / t1m, "eq 26 corrected",
                      "paper: 4 lam sqrt(3)/3 from the wrong eq 21; correct (8/3) sqrt(2/3) lam"),
        "P_r_printed": _entry("P_r by the paper's eq 26 (wrong)", "", 0.028 if paper else None, pr_printed(lam),
                              None, "eq 26"),
        "W1_fluctuation": _entry("fluctuation of W1 with the spring", "J", None, pr_first_order(lam) * t1m,
                                 w1_hi - w1_lo, "eqs 20-26 corrected"),
        "M_in_peak": _entry("peak input torque dW/dalpha, no spring", "N*m", None,
                            float(np.max(np.abs(input_torque(s, fine)))), m0_peak, "eq 12"),
        "M_in_peak_spring": _entry("peak input torque dW/dalpha, with spring", "N*m", None,
                                   float(np.max(np.abs(input_torque(s, fine, spring=True)))), m1_peak,
                                   "eqs 12, 19"),
    }

