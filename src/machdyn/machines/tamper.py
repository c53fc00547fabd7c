"""Double tamper of an asphalt paver screed: eccentric shaft + eccentric sleeves, two offset slider-cranks.

Source: Sun Jian, *Structure Analysis and Optimization for Compacting System of Asphalt Paver* (seed paper 000).
Corrections follow ``seed-reproduction.md`` section 000 (cited as "repro 000.x").

Geometry of one beam. The shaft journal is eccentric by ``e_journal`` (e_dz) from the shaft axis; a sleeve
turned on the journal adds ``e_sleeve`` (e_dt) at the *sleeve angle* theta, measured from the direction of the
journal eccentricity (theta = 0: both eccentricities aligned, largest stroke). The paper's angle alpha_d of
eqs 1-2 is the angle between the two eccentricity vectors in the triangle, alpha_d = pi - theta. The resultant
eccentricity is the crank radius r of the beam's slider-crank and the stroke is 2 r (repro 000.2, fixed by
Table 2: r_d1 = 2.5 mm for a 5 mm stroke).

Every function takes and returns SI floats or numpy arrays (m, kg, rad, s); angles are radians.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..errors import InputError, check_finite, check_positive

__all__ = [
    "MAIN_SLEEVE_ANGLES",
    "AUX_SLEEVE_ANGLES",
    "TABLE1_ECCENTRICITIES",
    "resultant_eccentricity",
    "eccentricity_phase",
    "eccentricity_phase_eq3",
    "stroke_from_eccentricity",
    "eccentricity_from_stroke",
    "beam_phase",
    "beam_phase_eq4",
    "sleeve_angle_for_stroke",
    "phase_at_nominal_strokes",
    "Table1Entry",
    "table1",
    "exact_position",
    "exact_velocity",
    "exact_acceleration",
    "series_position",
    "series_displacement_from_odc",
    "series_velocity",
    "series_acceleration",
    "double_tamper",
    "complex_mass_substitution",
    "complex_mass_substitution_printed",
    "BalanceAnalysis",
    "balance_analysis",
    "sleeve_mass_condition",
]

#: Sleeve angles [rad] of the main beam that reproduce Table 1, by table label [mm] (repro 000.2 item 4).
MAIN_SLEEVE_ANGLES: dict[int, float] = {3: np.pi, 5: np.radians(120.0), 7: np.radians(90.0), 9: 0.0}
#: Sleeve angles [rad] of the auxiliary beam that reproduce Table 1, by table label [mm].
AUX_SLEEVE_ANGLES: dict[int, float] = {
    0: np.pi,
    3: np.radians(150.0),
    6: np.radians(120.0),
    9: np.radians(90.0),
    12: 0.0,
}
#: Journal and sleeve eccentricities [m] fixed by the extreme strokes of Table 1 (repro 000.2 item 2):
#: main e_dz1 = 3.0 mm, e_dt1 = 1.5 mm; auxiliary e_dz2 = e_dt2 = 3.0 mm.
TABLE1_ECCENTRICITIES: dict[str, float] = {
    "e_journal_main": 3.0e-3,
    "e_sleeve_main": 1.5e-3,
    "e_journal_aux": 3.0e-3,
    "e_sleeve_aux": 3.0e-3,
}


def _check_eccentricities(e_journal, e_sleeve) -> None:
    check_positive("journal eccentricity e_journal", e_journal, "m", allow_zero=True)
    check_positive("sleeve eccentricity e_sleeve", e_sleeve, "m", allow_zero=True)


# ------------------------------------------------------------------------------------ eqs 1-4, Table 1


def resultant_eccentricity(e_journal, e_sleeve, sleeve_angle):
    """Resultant eccentricity e = |e_dz + e_dt * exp(i theta)| [m] of journal plus sleeve.

    Seed 000, eqs 1-2: e = sqrt(e_dz^2 + e_dt^2 - 2 e_dz e_dt cos alpha_d) with alpha_d = pi - theta, i.e.
    e = sqrt(e_dz^2 + e_dt^2 + 2 e_dz e_dt cos theta). (The extraction writes e_d21, e_d11 for e_dz1, e_dt1.)

    Parameters
    ----------
    e_journal : eccentricity of the shaft journal e_dz [m], >= 0
    e_sleeve : eccentricity of the sleeve e_dt [m], >= 0
    sleeve_angle : sleeve angle theta [rad] from the journal eccentricity direction; any real value

    Returns the resultant eccentricity [m], in |e_dz - e_dt| ... e_dz + e_dt. The stroke is twice this value.
    """
    _check_eccentricities(e_journal, e_sleeve)
    check_finite("sleeve angle", sleeve_angle, "rad")
    return np.abs(e_journal + e_sleeve * np.exp(1j * np.asarray(sleeve_angle, dtype=float)))


def eccentricity_phase(e_journal, e_sleeve, sleeve_angle):
    """Phase phi_d [rad] of the resultant eccentricity relative to the journal eccentricity.

    phi_d = atan2(e_dt sin theta, e_dz + e_dt cos theta) (repro 000.2 item 4): the signed form of seed 000
    eq 3. Eq 3 as printed for the main beam has e_d1^2 twice; the third term must be e_dt1^2 (law of cosines);
    eq 3 also loses the sign (arccos gives 0...pi), which this form keeps.

    Parameters
    ----------
    e_journal : journal eccentricity e_dz [m], >= 0
    e_sleeve : sleeve eccentricity e_dt [m], >= 0
    sleeve_angle : sleeve angle theta [rad]

    Returns phi_d [rad] in (-pi, pi]. Where the resultant eccentricity is zero (e_dz = e_dt, theta = pi) the
    phase is undefined and 0 is returned, as Table 1 does for the 0 mm auxiliary stroke (repro 000.2 item 6).
    """
    _check_eccentricities(e_journal, e_sleeve)
    check_finite("sleeve angle", sleeve_angle, "rad")
    th = np.asarray(sleeve_angle, dtype=float)
    x = e_journal + e_sleeve * np.cos(th)
    y = e_sleeve * np.sin(th)
    scale = np.maximum(np.asarray(e_journal, dtype=float) + e_sleeve, np.finfo(float).tiny)
    zero = np.hypot(x, y) <= 1e-12 * scale
    return np.where(zero, 0.0, np.arctan2(y, x))


def eccentricity_phase_eq3(eccentricity, e_journal, e_sleeve):
    """Unsigned phase |phi_d| [rad] from the corrected seed 000 eq 3 (law of cosines).

    cos phi_d = (e^2 + e_dz^2 - e_dt^2) / (2 e e_dz). The paper prints e_d1^2 in place of e_dt1^2 in the main
    beam's formula (repro 000.2); this is the corrected form.

    Parameters
    ----------
    eccentricity : resultant eccentricity e [m], within |e_dz - e_dt| ... e_dz + e_dt (small round-off outside
        is clipped)
    e_journal : journal eccentricity e_dz [m], > 0
    e_sleeve : sleeve eccentricity e_dt [m], >= 0

    Returns |phi_d| [rad] in 0...pi; 0 where e = 0 (phase undefined, Table 1 convention).
    """
    check_positive("resultant eccentricity", eccentricity, "m", allow_zero=True)
    check_positive("journal eccentricity e_journal", e_journal, "m")
    check_positive("sleeve eccentricity e_sleeve", e_sleeve, "m", allow_zero=True)
    e = np.asarray(eccentricity, dtype=float)
    lo, hi = np.abs(e_journal - e_sleeve), e_journal + e_sleeve
    tol = 1e-9 * hi
    if np.any((e < lo - tol) | (e > hi + tol)):
        bad = e[(e < lo - tol) | (e > hi + tol)].ravel()[0] if e.ndim else float(e)
        raise InputError(
            f"The resultant eccentricity must lie between |e_journal - e_sleeve| = {lo:g} m and "
            f"e_journal + e_sleeve = {hi:g} m; got {bad:g} m."
        )
    with np.errstate(divide="ignore", invalid="ignore"):
        c = (e**2 + e_journal**2 - e_sleeve**2) / (2.0 * e * e_journal)
    return np.where(e > 0, np.arccos(np.clip(c, -1.0, 1.0)), 0.0)


def stroke_from_eccentricity(eccentricity):
    """Stroke [m] = 2 * resultant eccentricity (repro 000.1 item 2; Table 2: r_d1 = 2.5 mm for 5 mm).

    eccentricity [m], >= 0.
    """
    check_positive("eccentricity", eccentricity, "m", allow_zero=True)
    return 2.0 * np.asarray(eccentricity, dtype=float)


def eccentricity_from_stroke(stroke):
    """Resultant eccentricity (crank radius) [m] = stroke / 2 (repro 000.1 item 2). stroke [m], >= 0."""
    check_positive("stroke", stroke, "m", allow_zero=True)
    return 0.5 * np.asarray(stroke, dtype=float)


def beam_phase(phi_main, phi_aux):
    """Phase Phi [rad] between the main and auxiliary beams in Table 1's convention.

    Phi = pi - phi_d1 + phi_d2, reduced to [0, 2 pi) (repro 000.2 item 5). This is 2 pi minus seed 000 eq 4
    (Phi = pi + phi_d1 - phi_d2): eq 4 taken literally gives e.g. 104.48 deg for (3 mm, 3 mm) where Table 1
    prints 255 deg, so either eq 4's signs or the direction in which Phi is measured is reversed.

    Parameters
    ----------
    phi_main : |phi_d1| [rad] of the main beam (0...pi, as eq 3 returns it)
    phi_aux : |phi_d2| [rad] of the auxiliary beam (0...pi)
    """
    check_finite("main beam phase", phi_main, "rad")
    check_finite("auxiliary beam phase", phi_aux, "rad")
    return np.mod(np.pi - np.asarray(phi_main, dtype=float) + phi_aux, 2.0 * np.pi)


def beam_phase_eq4(phi_main, phi_aux):
    """Seed 000 eq 4 as printed: Phi = pi + phi_d1 - phi_d2 [rad], reduced to [0, 2 pi).

    Kept to show the paper's form; it does **not** match Table 1 (use :func:`beam_phase`, = 2 pi - eq 4).
    phi_main, phi_aux [rad] in 0...pi.
    """
    check_finite("main beam phase", phi_main, "rad")
    check_finite("auxiliary beam phase", phi_aux, "rad")
    return np.mod(np.pi + np.asarray(phi_main, dtype=float) - phi_aux, 2.0 * np.pi)


def sleeve_angle_for_stroke(stroke, e_journal, e_sleeve):
    """Sleeve angle theta [rad] (0...pi) that gives a wanted stroke; the inverse of eqs 1-2.

    cos theta = ((stroke/2)^2 - e_dz^2 - e_dt^2) / (2 e_dz e_dt)  (seed 000 eqs 1-2, stroke = 2e).

    Parameters
    ----------
    stroke : wanted stroke [m], within 2|e_dz - e_dt| ... 2(e_dz + e_dt)
    e_journal : journal eccentricity e_dz [m], > 0
    e_sleeve : sleeve eccentricity e_dt [m], > 0

    Raises InputError if the stroke is out of the reachable range. The mirror angle -theta gives the same
    stroke with the opposite phase.
    """
    check_positive("stroke", stroke, "m", allow_zero=True)
    check_positive("journal eccentricity e_journal", e_journal, "m")
    check_positive("sleeve eccentricity e_sleeve", e_sleeve, "m")
    s = np.asarray(stroke, dtype=float)
    lo, hi = 2.0 * abs(e_journal - e_sleeve), 2.0 * (e_journal + e_sleeve)
    tol = 1e-9 * hi
    out = (s < lo - tol) | (s > hi + tol)
    if np.any(out):
        bad = s[out].ravel()[0] if s.ndim else float(s)
        raise InputError(
            f"The stroke must lie between 2|e_journal - e_sleeve| = {lo:g} m and 2(e_journal + e_sleeve) = "
            f"{hi:g} m; got {bad:g} m."
        )
    e = 0.5 * s
    c = (e**2 - e_journal**2 - e_sleeve**2) / (2.0 * e_journal * e_sleeve)
    return np.arccos(np.clip(c, -1.0, 1.0))


def phase_at_nominal_strokes(stroke_main, stroke_aux, e_journal_main=3.0e-3, e_sleeve_main=1.5e-3,
                             e_journal_aux=3.0e-3, e_sleeve_aux=3.0e-3):
    """Phase Phi [rad] from eq 3 evaluated at the *nominal* strokes (e = stroke/2), Table 1's convention.

    Phi = pi - |phi_d1| + |phi_d2| with |phi_d| from corrected eq 3 (seed 000 eqs 3-4; repro 000.2 item 3).
    This is what the paper's equations literally give for the table's stroke labels; it differs from Table 1 by
    up to 3.59 deg because the table was computed from sleeve angles in 30 deg steps (see :func:`table1`).

    Parameters
    ----------
    stroke_main, stroke_aux : nominal strokes [m], each within the reachable range of its beam
    e_journal_main, e_sleeve_main, e_journal_aux, e_sleeve_aux : eccentricities [m]; defaults are the values
        fixed by Table 1 (3.0, 1.5, 3.0, 3.0 mm)
    """
    e1 = eccentricity_from_stroke(stroke_main)
    e2 = eccentricity_from_stroke(stroke_aux)
    phi1 = eccentricity_phase_eq3(e1, e_journal_main, e_sleeve_main)
    phi2 = eccentricity_phase_eq3(e2, e_journal_aux, e_sleeve_aux)
    return beam_phase(phi1, phi2)


@dataclass(frozen=True)
class Table1Entry:
    """One row of Table 1: labels [mm] as printed, the sleeve angles [rad], true strokes [m] and phases [rad]."""

    main_label_mm: int
    aux_label_mm: int
    main_sleeve_angle: float
    aux_sleeve_angle: float
    main_stroke: float
    aux_stroke: float
    phase: float
    phase_nominal: float


def table1(e_journal_main=3.0e-3, e_sleeve_main=1.5e-3, e_journal_aux=3.0e-3, e_sleeve_aux=3.0e-3):
    """Reproduce seed 000 Table 1 (20 phase angles) with the sleeve-angle model (repro 000.2 item 4).

    For each main label (3, 5, 7, 9 mm) and auxiliary label (0, 3, 6, 9, 12 mm) the sleeve angles of
    :data:`MAIN_SLEEVE_ANGLES` / :data:`AUX_SLEEVE_ANGLES` give the true strokes (2 * :func:`resultant_eccentricity`,
    e.g. 5.196 mm for the "5" label) and phi_d (:func:`eccentricity_phase`); ``phase`` =
    :func:`beam_phase` of the two |phi_d|. ``phase_nominal`` is :func:`phase_at_nominal_strokes` for the labels,
    which the paper's equations give literally and which does not reproduce the table.

    Parameters: the four eccentricities [m] (defaults from Table 1's extreme strokes).
    Returns a list of 20 :class:`Table1Entry`, main label major.
    """
    rows = []
    for m_label, th1 in MAIN_SLEEVE_ANGLES.items():
        for a_label, th2 in AUX_SLEEVE_ANGLES.items():
            phi1 = eccentricity_phase(e_journal_main, e_sleeve_main, th1)
            phi2 = eccentricity_phase(e_journal_aux, e_sleeve_aux, th2)
            rows.append(
                Table1Entry(
                    main_label_mm=m_label,
                    aux_label_mm=a_label,
                    main_sleeve_angle=float(th1),
                    aux_sleeve_angle=float(th2),
                    main_stroke=float(2.0 * resultant_eccentricity(e_journal_main, e_sleeve_main, th1)),
                    aux_stroke=float(2.0 * resultant_eccentricity(e_journal_aux, e_sleeve_aux, th2)),
                    phase=float(beam_phase(np.abs(phi1), np.abs(phi2))),
                    phase_nominal=float(
                        phase_at_nominal_strokes(
                            m_label * 1e-3, a_label * 1e-3,
                            e_journal_main, e_sleeve_main, e_journal_aux, e_sleeve_aux,
                        )
                    ),
                )
            )
    return rows


# ------------------------------------------------------------------------- eqs 5-10, offset slider-crank


def _check_slider_crank(r, l, e):
    check_positive("crank radius r", r, "m")
    check_positive("rod length l", l, "m")
    check_finite("offset e", e, "m")


def _u(theta, r, l, e):
    u = np.sin(theta) + np.asarray(e, dtype=float) / r
    lam = np.asarray(r, dtype=float) / l
    q = 1.0 - (lam * u) ** 2
    if np.any(q <= 0):
        raise InputError(
            "The offset slider-crank cannot close: it needs |r sin(theta) + e| < l at every angle; "
            f"got r = {r:g} m, l = {l:g} m, e = {np.max(np.abs(e)):g} m."
        )
    return u, lam, q


def exact_position(theta, r, l, e):
    """Exact slider position x [m] of the offset slider-crank of seed 000 section 3 (repro 000.4).

    Crank pin at r(cos theta, sin theta), slider on the line y = -e, x measured from the crank centre:
    x = r cos theta + l sqrt(1 - lambda^2 u^2), lambda = r/l, u = sin theta + e/r.

    Parameters: theta crank angle [rad]; r crank radius (resultant eccentricity) [m] > 0; l rod length [m] > 0;
    e offset [m] (signed). Valid where |r sin theta + e| < l (the rod can reach the slide line).
    """
    _check_slider_crank(r, l, e)
    u, lam, q = _u(theta, r, l, e)
    return r * np.cos(theta) + l * np.sqrt(q)


def exact_velocity(theta, r, l, e, omega):
    """Exact slider velocity dx/dt [m/s] at constant crank speed (repro 000.4).

    v = -r omega [sin theta + lambda cos theta u / sqrt(1 - lambda^2 u^2)], lambda = r/l, u = sin theta + e/r.
    Parameters as :func:`exact_position`, plus omega crank speed [rad/s] (theta = omega t).
    """
    _check_slider_crank(r, l, e)
    check_finite("crank speed omega", omega, "rad/s")
    u, lam, q = _u(theta, r, l, e)
    return -r * omega * (np.sin(theta) + lam * np.cos(theta) * u / np.sqrt(q))


def exact_acceleration(theta, r, l, e, omega):
    """Exact slider acceleration d2x/dt2 [m/s^2] at constant crank speed (repro 000.4).

    a = -r omega^2 [cos theta + lambda cos^2 theta / (1 - lambda^2 u^2)^(3/2) - lambda sin theta u /
    sqrt(1 - lambda^2 u^2)]. Parameters as :func:`exact_velocity`.
    """
    _check_slider_crank(r, l, e)
    check_finite("crank speed omega", omega, "rad/s")
    u, lam, q = _u(theta, r, l, e)
    c, s = np.cos(theta), np.sin(theta)
    return -r * omega**2 * (c + lam * c**2 / q**1.5 - lam * s * u / np.sqrt(q))


def series_position(theta, r, l, e):
    """First-order (small lambda) slider position x [m], consistent with eqs 6-7 (repro 000.4, corrected eq 5).

    x ~ l - e^2/(2 l) + r cos theta - lambda e sin theta - (lambda r / 4)(1 - cos 2 theta), lambda = r/l.
    Seed 000 eq 5 as printed is **wrong**: its crank terms have the opposite sign to the position whose
    derivative is eq 6, the lambda e sin term has the wrong sign, and its last term lambda^2 e^2 / (2(1 + lambda))
    has units of m^2 (the dead-centre correction is lambda^2 e^2 / (2 r (1 + lambda))). Use this function, or
    :func:`series_displacement_from_odc` for the displacement from the outer dead centre.

    Parameters: theta [rad]; r [m] > 0; l [m] > 0; e offset [m] (slider on y = -e). Valid for
    lambda (1 + |e|/r) << 1; the error of x is about (r lambda^3 / 8)(sin theta + e/r)^4.
    """
    _check_slider_crank(r, l, e)
    lam = r / l
    return l - e**2 / (2.0 * l) + r * np.cos(theta) - lam * e * np.sin(theta) - lam * r / 4.0 * (
        1.0 - np.cos(2.0 * theta)
    )


def series_displacement_from_odc(theta, r, l, e):
    """First-order displacement s = x_ODC - x [m] from the outer dead centre (repro 000.4).

    s ~ r (1 - cos theta) + lambda e sin theta + (lambda r / 4)(1 - cos 2 theta) + lambda^2 e^2 / (2 r (1 + lambda)),
    the form seed 000 eq 5 (and eq 8) evidently meant; ds/dt = -eq 6. The paper prints l_d1 instead of r_d1 as
    the constant, the wrong sign on lambda e sin theta and omits the 1/r in the last term.
    Parameters and validity as :func:`series_position`.
    """
    _check_slider_crank(r, l, e)
    lam = r / l
    return (
        r * (1.0 - np.cos(theta))
        + lam * e * np.sin(theta)
        + lam * r / 4.0 * (1.0 - np.cos(2.0 * theta))
        + lam**2 * e**2 / (2.0 * r * (1.0 + lam))
    )


def series_velocity(theta, r, l, e, omega):
    """Seed 000 eq 6 (and eq 9): v ~ -r omega (sin theta + lambda eps cos theta + (lambda/2) sin 2 theta) [m/s].

    lambda = r/l, eps = e/r (so lambda eps = e/l). Correct: it is the exact first-order expansion of
    :func:`exact_velocity` (repro 000.4). Parameters: theta [rad], r [m] > 0, l [m] > 0, e offset [m],
    omega [rad/s]. Validity: error below 2e-5 r omega for lambda ~ 0.01 and e/r <= 2 (table of repro 000.4).
    """
    _check_slider_crank(r, l, e)
    check_finite("crank speed omega", omega, "rad/s")
    lam = r / l
    eps = e / r
    return -r * omega * (np.sin(theta) + lam * eps * np.cos(theta) + lam / 2.0 * np.sin(2.0 * theta))


def series_acceleration(theta, r, l, e, omega):
    """Seed 000 eq 7 (and eq 10): a ~ -r omega^2 (cos theta - lambda eps sin theta + lambda cos 2 theta) [m/s^2].

    d(eq 6)/dt = eq 7 exactly. (Eq 10 is labelled "speed" in the paper but is the acceleration.) Parameters as
    :func:`series_velocity`. Validity: error about 0.5 lambda^3 (1 + e/r)^3 r omega^2 for small lambda (1 + e/r)
    (repro 000.4).
    """
    _check_slider_crank(r, l, e)
    check_finite("crank speed omega", omega, "rad/s")
    lam = r / l
    eps = e / r
    return -r * omega**2 * (np.cos(theta) - lam * eps * np.sin(theta) + lam * np.cos(2.0 * theta))


# ---------------------------------------------------------------------------- engine model of the tamper


def double_tamper(r_main, l_main, r_aux, l_aux, phase=np.pi, *, offset_main=0.0, offset_aux=0.0,
                  beam_masses=(90.0, 63.21), beam_coms=None, beam_inertias=None, sleeve_masses=(0.0, 0.0),
                  slide_angle=-np.pi / 2, name="double_tamper"):
    """The double tamper as an engine :class:`~machdyn.linkage.model.Mechanism` (seed 000 section 3).

    Two offset slider-cranks on one eccentric shaft (``machdyn.linkage.double_slider_crank``): the main beam's
    crank pin at shaft angle 0 and the auxiliary beam's at ``phase`` (Phi). Each beam is the connecting rod
    (E->B, F->C); the beam end slides along a vertical guide (``slide_angle`` = -pi/2: the beams hang below the
    shaft). The eccentric sleeves turn with the shaft; their masses sit at the crank pins as point masses
    ``sleeve_main`` / ``sleeve_aux``. Gravity is on (the engine's default).

    Parameters
    ----------
    r_main, r_aux : resultant eccentricities r_d1, r_d2 (crank radii) [m] > 0
    l_main, l_aux : beam lengths l_EB = l_d1, l_FC = l_d2 [m] > 0
    phase : Phi [rad], angle of the auxiliary crank pin from the main one (paper: pi)
    offset_main, offset_aux : offsets e of the slide lines from the shaft axis [m]
    beam_masses : (m_d2, m_d3) [kg] (Table 2: 90, 63.21)
    beam_coms : ((p1, q1), (p2, q2)) [m], centroid of each beam in its frame (x along E->B); default mid-length
    beam_inertias : centroidal moments of inertia [kg m^2]; default m l^2 / 12
    sleeve_masses : (m_d1, m_d4) [kg]
    slide_angle : direction of both slide lines [rad]

    Bodies: ``crank`` (the shaft, massless, pins A1 = E and A2 = F), ``rod_1`` = main beam, ``rod_2`` =
    auxiliary beam, ``slider_1``, ``slider_2`` = the massless beam ends B and C on their guides.
    """
    from ..linkage import double_slider_crank
    from ..linkage.model import PointMass

    for label, v in (("r_main", r_main), ("l_main", l_main), ("r_aux", r_aux), ("l_aux", l_aux)):
        check_positive(label, v, "m")
    m2, m3 = beam_masses
    check_positive("mass of the main beam", m2, "kg")
    check_positive("mass of the auxiliary beam", m3, "kg")
    if beam_coms is None:
        beam_coms = ((0.5 * l_main, 0.0), (0.5 * l_aux, 0.0))
    if beam_inertias is None:
        beam_inertias = (m2 * l_main**2 / 12.0, m3 * l_aux**2 / 12.0)
    mech = double_slider_crank(
        r_main, l_main, r_aux, l_aux,
        offset_1=offset_main, offset_2=offset_aux, phase=phase,
        slide_angle_1=slide_angle, slide_angle_2=slide_angle,
        masses=(0.0, m2, 0.0, m3, 0.0),
        inertias=(0.0, beam_inertias[0], 0.0, beam_inertias[1], 0.0),
        name=name,
    )
    coms = {"rod_1": beam_coms[0], "rod_2": beam_coms[1]}
    bodies = tuple(
        replace(b, com=tuple(float(c) for c in coms[b.name])) if b.name in coms else b for b in mech.bodies
    )
    crank = mech.body(mech.crank.body)
    sleeves = tuple(
        PointMass(label, crank.name, m, crank.points[pin])
        for label, m, pin in (("sleeve_main", sleeve_masses[0], "A1"), ("sleeve_aux", sleeve_masses[1], "A2"))
    )
    return replace(mech, bodies=bodies, point_masses=tuple(mech.point_masses) + sleeves)


# ------------------------------------------------------------------ eqs 11-22: mass substitution, balance


def complex_mass_substitution(mass, length, p, q):
    """Corrected seed 000 eq 14: two-point complex substitution (m_E, m_B) [kg] of a beam.

    m_E = m (l - p - i q) / l,  m_B = m (p + i q) / l  (repro 000.3), so m_E + m_B = m (eq 11) and
    m_E r_E + m_B r_B = m r_G with r_G = r_E + (p + i q)(r_B - r_E)/l. The same with l_FC, p2, q2, m_d3 gives
    m_F, m_C (eq 18).

    The paper's eq 14 prints m_E = m (l + p + i q)/l: it violates eq 11 (m_E + m_B - m = 2 m (p + i q)/l), because
    eq 12 writes L_EB = r_E + r_B where it must be r_B - r_E.

    Parameters: mass m [kg] > 0; length l = |EB| [m] > 0; p, q [m]: centroid of the beam along and across E->B
    from E (Table 2's p1, q1). Returns the complex masses (m_E, m_B) [kg]; arg m_B = atan(q/p).
    """
    check_positive("beam mass", mass, "kg")
    check_positive("beam length", length, "m")
    check_finite("centroid offset p", p, "m")
    check_finite("centroid offset q", q, "m")
    z = np.asarray(p, dtype=float) + 1j * np.asarray(q, dtype=float)
    return mass * (length - z) / length, mass * z / length


def complex_mass_substitution_printed(mass, length, p, q):
    """Seed 000 eq 14 exactly as printed (wrong; kept for comparison): (m_E, m_B) [kg].

    m_E = m (l + p + i q)/l, m_B = m (p + i q)/l; m_E + m_B - m = 2 m (p + i q)/l != 0 (repro 000.3).
    Parameters as :func:`complex_mass_substitution`.
    """
    check_positive("beam mass", mass, "kg")
    check_positive("beam length", length, "m")
    z = np.asarray(p, dtype=float) + 1j * np.asarray(q, dtype=float)
    return mass * (length + z) / length, mass * z / length


@dataclass(frozen=True)
class BalanceAnalysis:
    """Balance of the two beams against each other (seed 000 eq 22; repro 000.3). SI units.

    - ``arg_main``, ``arg_aux`` [rad]: arg m_B = atan2(q1, p1), arg m_C = atan2(q2, p2)
    - ``phase_mismatch`` [rad]: arg m_C - arg m_B; exact (complex) balance F_B = -F_C needs it to be 0
    - ``ratio_magnitude``: l_FC / l_EB for |F_B| = |F_C| (first harmonic, lambda ignored)
    - ``ratio_real``, ``ratio_imag``: l_FC / l_EB for the real / imaginary part alone
    - ``residual``: unbalanced fraction 2 sin(mismatch / 2) of the first-harmonic force at magnitude balance
    - ``unbalance_equal_lengths``: |m_B| r_d1 / (|m_C| r_d2) if l_FC = l_EB
    - ``aux_mass_equal_lengths`` [kg]: m_d3 for |F_B| = |F_C| with equal lengths (magnitudes)
    - ``aux_mass_equal_lengths_real`` [kg]: the same from the real parts
    - ``sleeve_moment`` [kg m]: m_d4 r_d2 - m_d1 r_d1 required by the summed real parts of eq 22
    """

    arg_main: float
    arg_aux: float
    phase_mismatch: float
    ratio_magnitude: float
    ratio_real: float
    ratio_imag: float
    residual: float
    unbalance_equal_lengths: float
    aux_mass_equal_lengths: float
    aux_mass_equal_lengths_real: float
    sleeve_moment: float


def balance_analysis(r_main=2.5e-3, m_main=90.0, p1=233.19e-3, q1=2.7e-3,
                     r_aux=3.0e-3, m_aux=63.21, p2=229.84e-3, q2=13.03e-3):
    """Balance of the main and auxiliary beams, cranks 180 deg apart (seed 000 eqs 14-22, Table 2; repro 000.3).

    With corrected eq 14, m_B = m_d2 (p1 + i q1)/l_EB and m_C = m_d3 (p2 + i q2)/l_FC. The reciprocating
    balance F_B = -F_C (eq 22, lambda ignored) means m_B r_d1 = m_C r_d2 as complex numbers, which needs
    q1/p1 = q2/p2: with Table 2 (0.6634 deg vs 3.2447 deg) exact balance is impossible for any beam lengths.
    Magnitude balance needs l_FC/l_EB = m_d3 r_d2 |p2 + i q2| / (m_d2 r_d1 |p1 + i q1|) = 0.832 and leaves
    2 sin(1.29 deg) = 4.5 % of the first-harmonic force. Adding the real parts of the rotating and
    reciprocating conditions removes l, p, q: (m_d1 + m_d2) r_d1 = (m_d4 + m_d3) r_d2, i.e.
    m_d4 r_d2 - m_d1 r_d1 = m_d2 r_d1 - m_d3 r_d2 (35.37 kg mm for Table 2).

    Parameters (defaults: Table 2): r_main, r_aux = r_d1, r_d2 [m] > 0; m_main, m_aux = m_d2, m_d3 [kg] > 0;
    p1, q1, p2, q2 [m] beam centroid offsets (p > 0). Returns :class:`BalanceAnalysis`.
    """
    for label, v, unit in (("r_main", r_main, "m"), ("r_aux", r_aux, "m"), ("m_main", m_main, "kg"),
                           ("m_aux", m_aux, "kg"), ("p1", p1, "m"), ("p2", p2, "m")):
        check_positive(label, v, unit)
    check_finite("q1", q1, "m")
    check_finite("q2", q2, "m")
    z1, z2 = complex(p1, q1), complex(p2, q2)
    a1, a2 = np.angle(z1), np.angle(z2)
    mismatch = a2 - a1
    moment_main, moment_aux = m_main * r_main, m_aux * r_aux
    return BalanceAnalysis(
        arg_main=float(a1),
        arg_aux=float(a2),
        phase_mismatch=float(mismatch),
        ratio_magnitude=float(moment_aux * abs(z2) / (moment_main * abs(z1))),
        ratio_real=float(moment_aux * p2 / (moment_main * p1)),
        ratio_imag=float(moment_aux * q2 / (moment_main * q1)) if q1 != 0 else float("inf"),
        residual=float(2.0 * abs(np.sin(mismatch / 2.0))),
        unbalance_equal_lengths=float(moment_main * abs(z1) / (moment_aux * abs(z2))),
        aux_mass_equal_lengths=float(moment_main * abs(z1) / (r_aux * abs(z2))),
        aux_mass_equal_lengths_real=float(moment_main * p1 / (r_aux * p2)),
        sleeve_moment=float(moment_main - moment_aux),
    )


def sleeve_mass_condition(l_main, l_aux, r_main=2.5e-3, m_main=90.0, p1=233.19e-3,
                          r_aux=3.0e-3, m_aux=63.21, p2=229.84e-3):
    """Rotating real-part balance (seed 000 eqs 15-16, 19-20, 22 with corrected eq 14; repro 000.3).

    (m_d1 + Re m_E) r_d1 = (m_d4 + Re m_F) r_d2 with Re m_E = m_d2 (l_EB - p1)/l_EB, Re m_F = m_d3 (l_FC - p2)/l_FC
    gives m_d4 - (r_d1/r_d2) m_d1 = (Re m_E r_d1 - Re m_F r_d2) / r_d2.

    Parameters: l_main = l_EB, l_aux = l_FC [m] > 0; the rest as :func:`balance_analysis` (Table 2 defaults).
    Returns (coefficient r_d1/r_d2, right-hand side [kg]): the sleeve masses must satisfy
    m_d4 - coefficient * m_d1 = rhs. (Eq 19 prints p1, q1 in the auxiliary formula; p2, q2 are meant.)
    """
    check_positive("l_main", l_main, "m")
    check_positive("l_aux", l_aux, "m")
    re_e = m_main * (l_main - p1) / l_main
    re_f = m_aux * (l_aux - p2) / l_aux
    return r_main / r_aux, (re_e * r_main - re_f * r_aux) / r_aux
