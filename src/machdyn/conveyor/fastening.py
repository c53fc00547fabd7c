"""The drive's fastenings: the elastic-pin coupling (seed 004, eqs 2.97-2.98) and the motor-base bolts under the
belt pull (eqs 2.72-2.80). SI floats in and out (N, m, Pa, N·m).
"""

from __future__ import annotations

import math

# ------------------------------------------------------------------------- elastic-pin coupling


def coupling_design_torque(torque: float, service_factor: float) -> float:
    """Coupling design torque T_t = k·T [N·m] (seed 004, eq 2.97; k = 1.8 for a screw conveyor)."""
    return service_factor * torque


def bushing_bearing_stress(torque: float, service_factor: float, pins: int, pin_circle: float,
                           pin_diameter: float, bushing_length: float) -> float:
    """Bearing stress of the rubber bushes σ_d = 2·k·T/(Z·D0·d_c·l3) [Pa] (seed 004, eq 2.98)."""
    return 2.0 * service_factor * torque / (pins * pin_circle * pin_diameter * bushing_length)


def pin_bending_stress(torque: float, service_factor: float, pins: int, pin_circle: float,
                       pin_diameter: float, pin_lever: float) -> float:
    """Bending stress of the coupling pins σ_u = k·T·l0/(0.1·d_c³·D0·Z) [Pa] (seed 004, eq 2.98).

    pin_lever l0 = l1 + l2/2 [m] (the paper derives 41.5 mm but substitutes 62 mm).
    """
    return service_factor * torque * pin_lever / (0.1 * pin_diameter**3 * pin_circle * pins)


# ----------------------------------------------------------------------------------- base bolts


def base_bolt_max_force(belt_force: float, belt_preload: float, lever: float, a: float, b: float) -> float:
    """Largest shear force on one of four base bolts under the belt pull [N] (seed 004, eqs 2.72-2.77).

    F′ = F_r + F_0 (2.72), M = (L + a/2)·F′ (2.73), F_Z = F′/4 (2.74), r = ½√(a² + (2b)²) (2.76),
    F_M = M·r/Σr_i² = M/(4r) (2.75), F_max² = F_Z² + F_M² + 2·F_Z·F_M·cos θ, cos θ = a/(2r) (2.77).
    belt_force F_r [N], belt_preload F_0 [N], lever L [m] from the belt line to the bolt group,
    a, b [m] bolt spacings as in the seed's figure 3.2.
    """
    f = belt_force + belt_preload
    moment = (lever + a / 2.0) * f
    r = 0.5 * math.sqrt(a**2 + (2.0 * b) ** 2)
    f_z = f / 4.0
    f_m = moment * r / (4.0 * r**2)
    cos_t = a / (2.0 * r)
    return math.sqrt(f_z**2 + f_m**2 + 2.0 * f_z * f_m * cos_t)


def bolt_minor_diameter_required(force: float, allowable_tensile: float, friction: float = 0.2,
                                 safety: float = 2.0, interfaces: int = 1) -> float:
    """Minor diameter of a preloaded bolt carrying ``force`` in shear by friction [m] (seed 004, 2.78-2.80).

    V = k·F/(i·f) (2.79), d3 ≥ √(1.3·4·V/(π·[σ_k])) (2.78; 1.3 for the torsion while tightening).
    force F [N], allowable_tensile [σ_k] [Pa], friction f [-], safety k [-], interfaces i [-].
    """
    preload = safety * force / (interfaces * friction)
    return math.sqrt(1.3 * 4.0 * preload / (math.pi * allowable_tensile))
