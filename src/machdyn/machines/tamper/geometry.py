"""Double tamper geometry: eccentric shaft and sleeves, strokes and beam phases (seed 000 eqs 1-4, Table 1).

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

from dataclasses import dataclass

import numpy as np

from ...errors import InputError, check_finite, check_positive

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


