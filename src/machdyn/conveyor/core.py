"""The seed's screw-core formulas: torque, axial force and equivalent stress of the screw from the flight pressure
(seed 004, eqs 2.46-2.54, corrected). SI floats in and out (Pa, m, N, N·m).

machdyn's design checks use the real pipe section (:mod:`.checks`); these are the paper's solid-core forms.
"""

from __future__ import annotations

import math

# ----------------------------------------------------------------- screw stress from pressure (2.46-2.54)


def screw_torque_from_pressure(p_max: float, span: float, r1: float, r2: float, tan_beta: float,
                               pitch: float) -> float:
    """Torque at the dangerous section M_x = (p_max·l/2)·tan β·(R1³ − R2³)/3·(2π/t) [N·m].

    Seed 004, eq 2.46 corrected to agree with 2.35 (m_x = p·tan β·(R1³ − R2³)/3·2π/t): the printed
    (p_max·l/2)·(R1³ − R2³)/2·a lacks tan β and has /2 for /3 (printed/correct = 3/(2 tan β)).
    p_max [Pa], span l [m], r1 = R1, r2 = R2 [m], tan_beta [-], pitch t [m].
    """
    return p_max * span / 2.0 * tan_beta * (r1**3 - r2**3) / 3.0 * 2.0 * math.pi / pitch


def screw_axial_from_pressure(p_max: float, span: float, r1: float, r2: float, pitch: float) -> float:
    """Axial force S = (p_max·l/2)·(R1² − R2²)/2·(2π/t) [N] (seed 004, eq 2.47)."""
    return p_max * span / 2.0 * (r1**2 - r2**2) / 2.0 * 2.0 * math.pi / pitch


def screw_axial_from_torque(torque: float, r1: float, r2: float, tan_beta: float) -> float:
    """Axial force S = 3·M_x·(R1 + R2)/(2·tan β·(R1² + R1·R2 + R2²)) [N] (seed 004, eq 2.52 corrected).

    The print has R1² + R1² + R2² for R1² + R1R2 + R2² (2.51 inverted).
    """
    return 3.0 * torque * (r1 + r2) / (2.0 * tan_beta * (r1**2 + r1 * r2 + r2**2))


def screw_equivalent_stress(torque: float, r1: float, r2: float, tan_beta: float) -> float:
    """Tresca equivalent stress of the screw core σ_td = √(σ² + 4τ²) [Pa] (seed 004, eqs 2.48-2.53).

    σ = S/F, F = πR2², τ = M_x/W_c, W_c = πR2³/2 (solid core of radius R2), S from eq 2.52 (corrected):
    σ_td = M_x·√([3(R1 + R2)/(2 tan β (R1² + R1R2 + R2²)·πR2²)]² + 16/(πR2³)²).
    torque M_x [N·m], r1 = R1, r2 = R2 [m], tan_beta [-].
    """
    sigma = screw_axial_from_torque(torque, r1, r2, tan_beta) / (math.pi * r2**2)
    tau = torque / (math.pi * r2**3 / 2.0)
    return math.sqrt(sigma**2 + 4.0 * tau**2)


def screw_equivalent_stress_from_pressure(p_max: float, span: float, r1: float, r2: float,
                                          tan_beta: float, pitch: float) -> float:
    """σ_td from the flight pressure (seed 004, eq 2.54): eq 2.53 with M_x from the corrected eq 2.46."""
    m_x = screw_torque_from_pressure(p_max, span, r1, r2, tan_beta, pitch)
    return screw_equivalent_stress(m_x, r1, r2, tan_beta)
