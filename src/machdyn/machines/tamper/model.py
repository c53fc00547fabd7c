"""The double tamper as an engine model, and seed 000's mass substitution and balance (eqs 11-22, Table 2).

Corrections follow ``seed-reproduction.md`` section 000.3 (cited as "repro 000.3"). SI floats or arrays.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ...errors import check_finite, check_positive
from ...linkage import double_slider_crank
from ...linkage.model import PointMass


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
        replace(b, com=(float(coms[b.name][0]), float(coms[b.name][1]))) if b.name in coms else b for b in mech.bodies
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
