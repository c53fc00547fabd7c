"""Spur gear teeth rated as the Indian design books do: the beam strength of a tooth (Lewis), the wear strength of
the flanks (Buckingham's load-stress factor) and Buckingham's dynamic load, compared as forces with a factor of
safety.

All functions take and return SI floats: m, N, Pa, m/s. Buckingham's dynamic-load formula is empirical and
dimensionally inconsistent (21 v is added to a square root of newtons): it holds with v in m/s and the forces in N,
which is how it is used here; the product b C e is a force in any consistent units.

Sources
-------
- E. Buckingham, *Analytical Mechanics of Gears*, McGraw-Hill 1949 (Dover reprint 1988), ch. 23-24: the dynamic
  load of spur gears from the tooth error and the teeth's deformation, and the limiting wear load
  F_w = d_p b Q K with the load-stress factor K.
- V. B. Bhandari, *Design of Machine Elements*, 3rd ed., Tata McGraw-Hill 2010, ch. 17 "Spur gears": the beam
  strength S_b = m b σ_b Y (§ "Beam strength of gear tooth"); the wear strength S_w = b Q d_p K with
  Q = 2 z_g/(z_g + z_p) and K = σ_c² sin φ cos φ (1/E_p + 1/E_g)/1.4, and for steel gears of 20° full depth
  K = 0.16 (BHN/100)² N/mm² (§ "Wear strength of gear tooth"); Buckingham's incremental dynamic load
  P_d = 21 v (C e b + P_t)/(21 v + √(C e b + P_t)) with the deformation factor C = k/(1/E_p + 1/E_g),
  k = 0.111 (14.5° full depth), 0.107 (20° full depth), 0.115 (20° stub), and the effective load
  P_eff = C_s P_t + P_d (§ "Estimation of dynamic load by Buckingham's equation"); the equation numbers and pages
  were not checked against a printed copy.
- R. S. Khurmi, J. K. Gupta, *A Textbook of Machine Design*, S. Chand 2005, ch. 28 "Spur gears": the same
  dynamic load W_D = W_T + W_I written with C standing for the product of the deformation factor and the error
  (chapter and page not checked against a printed copy).
"""

from __future__ import annotations

import math

from ..errors import InputError

#: Bhandari's k of the deformation factor C = k/(1/E_p + 1/E_g), by the tooth system (pressure angle in degrees,
#: full depth): 14.5° → 0.111, 20° → 0.107.
DEFORMATION_K = {14.5: 0.111, 20.0: 0.107}
STUB_K = 0.115


def _positive(name: str, value: float, *, zero: bool = False) -> None:
    ok = value >= 0 if zero else value > 0
    if not (math.isfinite(value) and ok):
        raise InputError(f"A gear's {name} must be {'>= 0' if zero else '> 0'}; got {value!r}.")


def beam_strength(module: float, face_width: float, bending_stress: float, form_factor: float) -> float:
    """The largest tangential force a tooth carries in bending by Lewis, S_b = m b σ_b Y (Bhandari, *Design of
    Machine Elements*, 3rd ed., ch. 17, beam strength of the gear tooth). Valid for spur teeth loaded at the tip
    of one tooth; Y is Lewis's form factor on the module (Y = π y).

    Parameters
    ----------
    module : m [m] > 0; face_width : b [m] > 0; bending_stress : σ_b [Pa] > 0, the permissible bending stress
        (the books take S_ut/3 or the endurance limit over its factor);
    form_factor : Y [-] > 0.

    Returns
    -------
    float
        S_b [N].

    Examples
    --------
    >>> round(beam_strength(0.005, 0.060, 150e6, 0.358))
    16110
    """
    for name, value in (("module", module), ("face width", face_width), ("bending stress", bending_stress),
                        ("form factor", form_factor)):
        _positive(name, value)
    return module * face_width * bending_stress * form_factor


def ratio_factor(pinion_teeth: float, gear_teeth: float) -> float:
    """Q = 2 z_g/(z_g + z_p) of two external spur gears (Bhandari, 3rd ed., ch. 17, wear strength).

    Examples
    --------
    >>> round(ratio_factor(30, 75), 6)
    1.428571
    """
    _positive("number of pinion teeth", pinion_teeth)
    _positive("number of gear teeth", gear_teeth)
    return 2.0 * gear_teeth / (gear_teeth + pinion_teeth)


def load_stress_factor(surface_endurance: float, pinion_modulus: float, gear_modulus: float,
                       pressure_angle: float = math.radians(20.0)) -> float:
    """Buckingham's load-stress factor K = σ_c² sin φ cos φ (1/E_p + 1/E_g)/1.4 (Bhandari, 3rd ed., ch. 17).

    It is the Hertz stress of two cylinders of the pitch radii of curvature d sin φ/2 solved for the load: 1.4
    stands for 4/(π (1 − ν²)) = 1.399 with ν = 0.3. Valid for spur gears of metals with ν near 0.3.

    Parameters
    ----------
    surface_endurance : σ_c [Pa] > 0, the surface endurance limit;
    pinion_modulus, gear_modulus : E [Pa] > 0; pressure_angle : φ [rad], 0 < φ < 45°.

    Returns
    -------
    float
        K [Pa].

    Examples
    --------
    >>> round(load_stress_factor(600e6, 207e9, 207e9) / 1e6, 4)
    0.7985
    """
    for name, value in (("surface endurance limit", surface_endurance), ("elastic modulus", pinion_modulus),
                        ("elastic modulus", gear_modulus)):
        _positive(name, value)
    if not (0.0 < pressure_angle < math.radians(45.0)):
        raise InputError(f"A pressure angle is between 0 and 45°; got {math.degrees(pressure_angle):g}°.")
    return (surface_endurance**2 * math.sin(pressure_angle) * math.cos(pressure_angle)
            * (1.0 / pinion_modulus + 1.0 / gear_modulus) / 1.4)


def load_stress_factor_from_hardness(bhn: float) -> float:
    """K = 0.16 (BHN/100)² N/mm² of steel gears with 20° full-depth teeth (Bhandari, 3rd ed., ch. 17; in
    :func:`load_stress_factor` with E = 207 GPa for both wheels it is a surface endurance limit of 2.686 BHN
    N/mm²).

    Parameters
    ----------
    bhn : the Brinell hardness [-] > 0 (of the softer wheel).

    Returns
    -------
    float
        K [Pa].

    Examples
    --------
    >>> round(load_stress_factor_from_hardness(350) / 1e6, 3)
    1.96
    """
    _positive("Brinell hardness", bhn)
    return 0.16e6 * (bhn / 100.0) ** 2


def wear_strength(face_width: float, pinion_diameter: float, pinion_teeth: float, gear_teeth: float,
                  load_stress: float) -> float:
    """The largest tangential force the flanks carry without pitting, S_w = b Q d_p K (Buckingham's limiting
    wear load; Bhandari, 3rd ed., ch. 17). Valid for external spur gears.

    Parameters
    ----------
    face_width : b [m] > 0; pinion_diameter : d_p [m] > 0 of the pitch circle; pinion_teeth, gear_teeth : z > 0;
    load_stress : K [Pa] > 0 (:func:`load_stress_factor` or :func:`load_stress_factor_from_hardness`).

    Returns
    -------
    float
        S_w [N].

    Examples
    --------
    >>> round(wear_strength(0.060, 0.150, 30, 75, 1.96e6))
    25200
    """
    _positive("face width", face_width)
    _positive("pinion diameter", pinion_diameter)
    _positive("load-stress factor", load_stress)
    return face_width * ratio_factor(pinion_teeth, gear_teeth) * pinion_diameter * load_stress


def deformation_factor(pinion_modulus: float, gear_modulus: float, pressure_angle: float = math.radians(20.0),
                       *, stub: bool = False) -> float:
    """Buckingham's deformation factor C = k/(1/E_p + 1/E_g), k = 0.111 for 14.5° and 0.107 for 20° full-depth
    teeth, 0.115 for 20° stub teeth (Bhandari, 3rd ed., ch. 17).

    Parameters
    ----------
    pinion_modulus, gear_modulus : E [Pa] > 0; pressure_angle : φ [rad], 14.5° or 20°; stub : 20° stub teeth.

    Returns
    -------
    float
        C [Pa] (force per unit face width per unit tooth error).

    Examples
    --------
    Steel on steel, 20° full depth, in N/mm² (C e b is then in N for e and b in mm):

    >>> round(deformation_factor(207e9, 207e9) / 1e6, 1)
    11074.5
    """
    _positive("elastic modulus", pinion_modulus)
    _positive("elastic modulus", gear_modulus)
    degrees = round(math.degrees(pressure_angle), 3)
    if stub:
        if degrees != 20.0:
            raise InputError(f"Stub teeth have a 20° pressure angle here; got {degrees:g}°.")
        k = STUB_K
    elif degrees in DEFORMATION_K:
        k = DEFORMATION_K[degrees]
    else:
        raise InputError(f"Buckingham's deformation factor is tabulated for 14.5° and 20° teeth; got {degrees:g}° "
                         "(give deformation_factor).")
    return k / (1.0 / pinion_modulus + 1.0 / gear_modulus)


def buckingham_increment(tangential_load: float, pitch_speed: float, face_width: float, deformation: float,
                         tooth_error: float) -> float:
    """Buckingham's incremental dynamic load P_d = 21 v (C e b + P_t)/(21 v + √(C e b + P_t)) (Buckingham,
    *Analytical Mechanics of Gears*; Bhandari, 3rd ed., ch. 17, in SI: v in m/s, forces in N). Valid for spur
    gears of steel or cast iron at pitch speeds up to about 20 m/s; the total dynamic load is P_t + P_d.

    Parameters
    ----------
    tangential_load : P_t [N] >= 0; pitch_speed : v [m/s] >= 0; face_width : b [m] > 0;
    deformation : C [Pa] > 0 (:func:`deformation_factor`); tooth_error : e [m] >= 0, the sum of both wheels'
        profile errors.

    Returns
    -------
    float
        P_d [N].

    Examples
    --------
    >>> round(buckingham_increment(1000.0, 5.0, 0.05, 11.4e9, 20e-6), 1)
    6017.9
    """
    for name, value in (("tangential load", tangential_load), ("pitch-line speed", pitch_speed),
                        ("tooth error", tooth_error)):
        _positive(name, value, zero=True)
    _positive("face width", face_width)
    _positive("deformation factor", deformation)
    a = deformation * tooth_error * face_width + tangential_load
    if a == 0.0:
        return 0.0
    return 21.0 * pitch_speed * a / (21.0 * pitch_speed + math.sqrt(a))
