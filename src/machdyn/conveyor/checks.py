"""Loads on the screw and the verification checks (seed 004, eqs 2.46-2.54, 2.72-2.80, 2.85-2.98).

Formula functions take and return SI floats (N, m, Pa, rad, W). :class:`Check` holds one verification:
value, limit, utilisation = value/limit and pass/fail (value ≤ limit).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import InputError
from ..results.labels import display_factor
from .core import (  # noqa: F401 - re-exported: the seed's screw-core formulas
    screw_axial_from_pressure,
    screw_axial_from_torque,
    screw_equivalent_stress,
    screw_equivalent_stress_from_pressure,
    screw_torque_from_pressure,
)
from .design import angular_speed_of
from .fastening import (  # noqa: F401 - re-exported: the checks of the drive's fastenings
    base_bolt_max_force,
    bolt_minor_diameter_required,
    bushing_bearing_stress,
    coupling_design_torque,
    pin_bending_stress,
)


@dataclass(frozen=True)
class Check:
    """One verification: ``value`` must not exceed ``limit`` (both in the SI ``unit``).

    ``display`` is the unit the check is shown in (the SI unit if empty); :meth:`message` is the one wording
    of a failed check, used by every output.
    """

    name: str
    value: float
    limit: float
    unit: str
    source: str = ""
    display: str = ""

    @property
    def utilisation(self) -> float:
        return self.value / self.limit if self.limit else math.inf

    @property
    def passed(self) -> bool:
        return bool(self.value <= self.limit * (1.0 + 1e-12))

    def shown(self) -> tuple[float, float, str]:
        """(value, limit, unit) in the display unit."""
        unit = self.display or self.unit
        if unit == self.unit:
            return self.value, self.limit, unit
        f = display_factor(self.unit, unit)
        return self.value * f, self.limit * f, unit

    def message(self) -> str:
        """``"Screw speed n <= k/sqrt(D): 150 rpm > limit 100.6 rpm"``: the wording of a failed check."""
        value, limit, unit = self.shown()
        u = f" {unit}" if unit else ""
        return f"{self.name}: {value:.4g}{u} > limit {limit:.4g}{u}"


# --------------------------------------------------------------------------------------------- torque


def torque_from_power(power: Any, *old: Any, angular_speed: Any = None, speed_rpm: Any = None) -> Any:
    """Shaft torque T = P/ω [N·m] (seed 004, eq 2.85: T = 9.55·10⁶·P/n with T in N·mm, P in kW).

    Parameters
    ----------
    power : float or array
        Shaft power P [W], >= 0.
    angular_speed : float or array, keyword
        Screw angular speed ω [rad/s], > 0; or ``speed_rpm`` [rpm], keyword: one of the two. The form of the
        releases before 0.1.0, ``torque_from_power(P, n)`` with n in rpm by position, still reads n in rpm and
        warns (DeprecationWarning); it goes in 0.3.0.

    Returns
    -------
    float or array
        T [N·m].

    Examples
    --------
    >>> # seed 004, eq 2.90 at 101 rpm: 106 184.65 N·mm with 9.55e6 for 30e6/π
    >>> round(torque_from_power(1123.0, speed_rpm=101.0) * 1000, 2)
    106176.83
    """
    if len(old) > 1:
        raise TypeError(f"torque_from_power() takes at most 2 positional arguments; got {1 + len(old)}")
    speed = angular_speed_of("torque_from_power", angular_speed, speed_rpm, old[0] if old else None)
    if np.any(np.asarray(speed) <= 0):
        raise InputError(f"The screw speed must be > 0 rad/s; got {np.min(speed):g} rad/s.")
    return power / speed


# ----------------------------------------------------------------------------------- screw loads


def helix_angle(pitch: float, radius: float) -> float:
    """Helix (lead) angle α at radius R: tan α = S/(2πR) [rad] (seed 004, eq 2.88, corrected).

    Parameters
    ----------
    pitch : float or array
        Pitch S [m], > 0.
    radius : float or array
        Radius R [m], > 0 (0.3…0.4·D where the material's friction force acts, eq 2.87).

    Returns
    -------
    float or array
        α [rad], 0 < α < π/2. The paper substitutes the drive power (1.123) for the pitch and gets
        α = 0°8′46″; with the real pitch 160 mm and R = 70 mm, α = 19.99°.

    Examples
    --------
    >>> round(math.degrees(helix_angle(0.160, 0.070)), 4)
    19.9905
    """
    return np.arctan(pitch / (2.0 * math.pi * radius))


def axial_force(torque: float, radius: float, helix: float, friction_coefficient: float) -> float:
    """Axial force on the screw F_a = T/(R·tan(α + γ)), tan γ = f [N] (seed 004, eq 2.86).

    Parameters
    ----------
    torque : float or array
        Screw torque T [N·m].
    radius : float or array
        Radius R [m] where the material's friction force acts, R = (0.3…0.4)·D (seed 004, eq 2.87).
    helix : float or array
        Helix angle α at R [rad] (:func:`helix_angle`).
    friction_coefficient : float
        Friction coefficient f of the material on the flight [-].

    Returns
    -------
    float or array
        F_a [N]. Valid for α + γ < 90° (otherwise the screw is self-locking: :class:`InputError`).

    Examples
    --------
    >>> round(float(axial_force(106.18465, 0.070, math.atan(0.160 / (2 * math.pi * 0.070)), 1.0)), 2)  # 707.66 N
    707.66
    """
    gamma = np.arctan(friction_coefficient)
    if np.any(np.asarray(helix + gamma) >= math.pi / 2):
        raise InputError(
            f"The helix angle plus the friction angle must be < 90 deg; got "
            f"{np.degrees(np.max(helix)):.4g} + {np.degrees(np.max(gamma)):.4g} deg."
        )
    return torque / (radius * np.tan(helix + gamma))


def lateral_load(torque: float, span: float, radius_factor: float, diameter: float, length: float) -> float:
    """Horizontal (lateral) load on one span of the screw P_n = 2·T·l/(k·D·L) [N] (seed 004, eq 2.91).

    Parameters
    ----------
    torque : float or array
        Torque T [N·m].
    span : float
        Span l between hangers [m].
    radius_factor : float
        k [-], 0.7…0.8 (seed 004).
    diameter : float or array
        Screw diameter D [m].
    length : float
        Conveyor length L [m].

    Returns
    -------
    float or array
        P_n [N].

    Examples
    --------
    >>> round(lateral_load(103.86429, 3.0, 0.7, 0.2, 21.0), 4)  # seed 004, eq 2.91: 211.96 N
    211.9679
    """
    return 2.0 * torque * span / (radius_factor * diameter * length)


def distributed_loads(axial: float, lateral: float, torque: float, span: float, length: float) -> dict:
    """Loads spread along the screw (seed 004, eqs 2.92-2.94).

    p_d = F_a/L [N/m] (the paper calls it "vertical"; it is the axial force per length), p_n = P_n/l [N/m]
    (printed "P_n/1"), m_0 = T/L [N·m/m].

    Parameters
    ----------
    axial : float or array
        Axial force F_a [N].
    lateral : float or array
        Lateral load per span P_n [N].
    torque : float or array
        Torque T [N·m].
    span : float
        Span l [m].
    length : float
        Conveyor length L [m].

    Returns
    -------
    dict
        ``p_d``, ``p_n``, ``m_0``.

    Examples
    --------
    >>> {k: round(v, 4) for k, v in distributed_loads(1509.646, 211.96, 103.86429, 3.0, 21.0).items()}
    {'p_d': 71.8879, 'p_n': 70.6533, 'm_0': 4.9459}
    """
    return {"p_d": axial / length, "p_n": lateral / span, "m_0": torque / length}


# ---------------------------------------------------------------------------------------- torsion


def polar_moment_tube(outer_diameter: float, inner_diameter: float = 0.0) -> float:
    """Polar second moment of a tube J_p = π(d_o⁴ − d_i⁴)/32 [m⁴].

    Parameters
    ----------
    outer_diameter : float or array
        d_o [m], > d_i.
    inner_diameter : float or array
        d_i [m], >= 0 (0 for a solid shaft).

    Returns
    -------
    float or array
        J_p [m⁴]. Source: elementary torsion of circular sections (any strength-of-materials text).

    Examples
    --------
    >>> round(polar_moment_tube(0.2, 0.1) * 1e4, 6)  # seed 004 uses 0.1·D⁴(1 − η⁴) = 1.5e-4
    1.472622
    """
    if not (np.all(np.asarray(outer_diameter) > inner_diameter) and np.all(np.asarray(inner_diameter) >= 0)):
        raise InputError(
            f"The pipe needs outer diameter > inner diameter >= 0; got {np.min(outer_diameter):g} m and "
            f"{np.max(inner_diameter):g} m."
        )
    return math.pi * (outer_diameter**4 - inner_diameter**4) / 32.0


def polar_moment_seed(diameter: float, eta: float) -> float:
    """The seed's approximation J_p = 0.1·D⁴(1 − η⁴), η = d/D [m⁴] (seed 004, before eq 2.97).

    The seed applies it to the flight diameter (D = 200 mm, η = 0.5), i.e. treats the flight as a tube;
    machdyn's checks use the pipe section (:func:`polar_moment_tube`) instead.
    """
    return 0.1 * diameter**4 * (1.0 - eta**4)


def torsion_angle_distributed(torque_per_length: float, length: float, shear_modulus: float,
                              polar_moment: float) -> float:
    """Twist of a shaft of length L loaded by a uniform torque m_0: φ = m_0·L²/(2·G·J_p) [rad].

    Seed 004's own integral (φ = ∫M_z dz/(GJ_p), M_z = m_0·z). The printed number 7.3·10⁻⁶ rad uses D² for
    D⁴ and drops the ½; correctly, with the paper's J_p = 0.1·0.2⁴·(1 − 0.5⁴), φ = 9.10·10⁻⁵ rad.

    Parameters
    ----------
    torque_per_length : float or array
        m_0 [N·m/m].
    length : float
        L [m].
    shear_modulus : float
        G [Pa].
    polar_moment : float or array
        J_p [m⁴].

    Returns
    -------
    float or array
        φ [rad].

    Examples
    --------
    >>> round(torsion_angle_distributed(4.9457, 21.0, 8e10, 0.1 * 0.2**4 * (1 - 0.5**4)) * 1e5, 4)
    9.0877
    """
    return torque_per_length * length**2 / (2.0 * shear_modulus * polar_moment)


def shear_stress_tube(torque: float, outer_diameter: float, inner_diameter: float = 0.0) -> float:
    """Torsional shear stress τ = T·(d_o/2)/J_p [Pa] of a tube or solid shaft.

    Parameters
    ----------
    torque : float or array
        T [N·m].
    outer_diameter, inner_diameter : float or array
        d_o > d_i >= 0 [m].

    Returns
    -------
    float or array
        τ at the outer surface [Pa]. Source: elementary torsion of circular sections.

    Examples
    --------
    >>> round(shear_stress_tube(100.0, 0.1) / 1e6, 6)
    0.509296
    """
    return torque * outer_diameter / 2.0 / polar_moment_tube(outer_diameter, inner_diameter)


# ------------------------------------------------------------------------- bending between hangers


def screw_mass_per_length(diameter: float, pipe_outer: float, pipe_inner: float, flight_thickness: float,
                          pitch: float, density: float = 7850.0) -> float:
    """Mass of pipe plus helical flight per metre [kg/m].

    The flight per pitch is the annulus (π/4)(D² − d_o²) stretched by 1/cos α_m, α_m the helix angle at the
    mean radius; diameter D, pipe_outer d_o, pipe_inner d_i, flight_thickness, pitch [m]; density [kg/m³].
    """
    pipe = density * math.pi / 4.0 * (pipe_outer**2 - pipe_inner**2)
    r_mean = (diameter + pipe_outer) / 4.0
    stretch = 1.0 / np.cos(helix_angle(pitch, r_mean))
    flight = density * flight_thickness * math.pi / 4.0 * (diameter**2 - pipe_outer**2) * stretch / pitch
    return pipe + flight


def span_bending_moment(load_per_length: float, span: float) -> float:
    """Largest bending moment of a simply supported span under a uniform load M = q·l²/8 [N·m].

    Parameters
    ----------
    load_per_length : float or array
        q [N/m].
    span : float
        l [m].

    Returns
    -------
    float or array
        M [N·m]. Conservative for a continuous screw over several hangers (q·l²/10…q·l²/12 there).

    Examples
    --------
    >>> span_bending_moment(100.0, 3.0)
    112.5
    """
    return load_per_length * span**2 / 8.0


def span_deflection(load_per_length: float, span: float, elastic_modulus: float, second_moment: float) -> float:
    """Mid-span deflection of a simply supported span δ = 5·q·l⁴/(384·E·I) [m].

    Parameters
    ----------
    load_per_length : float or array
        q [N/m].
    span : float
        l [m].
    elastic_modulus : float
        E [Pa].
    second_moment : float or array
        I [m⁴].

    Returns
    -------
    float or array
        δ [m]. Source: Timoshenko & Gere, *Mechanics of Materials*, simply supported beam, uniform load.

    Examples
    --------
    >>> round(span_deflection(100.0, 3.0, 2.1e11, 1e-6) * 1000, 4)
    0.5022
    """
    return 5.0 * load_per_length * span**4 / (384.0 * elastic_modulus * second_moment)


# ------------------------------------------------------------------------- pipe and flight checks


def twist_rate(torque, shear_modulus, polar_moment):
    """Rate of twist of the pipe at the drive, θ' = T/(G·J_p) [rad/m].

    Parameters
    ----------
    torque : float or array
        Screw torque T [N·m].
    shear_modulus : float
        Shear modulus G [Pa].
    polar_moment : float or array
        Polar second moment J_p of the pipe [m⁴] (:func:`polar_moment_tube`).

    Returns
    -------
    float or array
        θ' [rad/m]. Source: elementary torsion of a circular tube (seed 004 integrates the same law along the
        screw, eq after 2.94). Valid for linear elastic tubes, G > 0.

    Examples
    --------
    >>> round(twist_rate(100.0, 80e9, 1e-6), 9)
    0.00125
    """
    return torque / (shear_modulus * polar_moment)


def pipe_equivalent_stress(load_per_length, span, axial, torque, outer_diameter, inner_diameter):
    """Tresca equivalent stress in the pipe between two hangers σ_eq = √((σ_b + σ_a)² + 4τ²) [Pa].

    σ_b = (q·l²/8)·(d_o/2)/I (the simply supported span, I = J_p/2), σ_a = F_a/A, τ = T·(d_o/2)/J_p.

    Parameters
    ----------
    load_per_length : float or array
        Lateral load q on the span [N/m] (weight of pipe and flight combined with p_n).
    span : float
        Hanger spacing l [m].
    axial : float or array
        Axial force F_a [N].
    torque : float or array
        Torque T [N·m].
    outer_diameter, inner_diameter : float or array
        Pipe diameters d_o > d_i >= 0 [m].

    Returns
    -------
    float or array
        σ_eq [Pa]. Source: seed 004, eqs 2.48-2.49 (σ_td = √(σ² + 4τ²)), applied to the pipe section.

    Examples
    --------
    >>> round(float(pipe_equivalent_stress(0.0, 3.0, 0.0, 100.0, 0.1, 0.0)) / 1e6, 6)  # pure torsion: 2·τ
    1.018592
    """
    jp = polar_moment_tube(outer_diameter, inner_diameter)
    area = math.pi / 4.0 * (outer_diameter**2 - inner_diameter**2)
    sigma_b = span_bending_moment(load_per_length, span) * (outer_diameter / 2.0) / (jp / 2.0)
    sigma_a = axial / area
    tau = shear_stress_tube(torque, outer_diameter, inner_diameter)
    return np.sqrt((sigma_b + sigma_a) ** 2 + 4.0 * tau**2)


def flight_pressure(axial, diameter, pipe_outer_diameter):
    """Mean pressure on one flight turn carrying the whole axial force, p = F_a/(π(R1² − R2²)) [Pa].

    Parameters
    ----------
    axial : float or array
        Axial force F_a [N].
    diameter : float or array
        Screw (flight) diameter D = 2·R1 [m].
    pipe_outer_diameter : float or array
        Pipe diameter d_o = 2·R2 [m] (< D).

    Returns
    -------
    float or array
        p [Pa]. Source: seed 004, eq 2.56 corrected (N = p·π(R1² − R2²)); conservative, since the axial force is
        in fact shared by the turns in contact with the material.

    Examples
    --------
    >>> round(flight_pressure(1000.0, 0.2, 0.1), 3)
    42441.318
    """
    return axial / (math.pi * ((diameter / 2.0) ** 2 - (pipe_outer_diameter / 2.0) ** 2))


def flight_turn_pressure(axial, diameter, pipe_outer_diameter, pitch, length, material_area):
    """Pressure on one flight turn when the axial force is shared by the turns along the screw [Pa]:
    p = (F_a·S/L)/A_m, A_m the material's cross-section in the annulus.

    The axial force builds up along the screw with the uniform intensity p_d = F_a/L (seed 004, eq 2.92, which
    the seed itself uses for the pipe), so one pitch S of length, one flight turn, carries F_a·S/L (all of it
    for a screw shorter than one pitch). That share is pressed on the part of the flight's face in contact with
    the material; projected on the cross-section, that part is the material's cross-section A_m (φ times the
    annulus π(R1² − R2²) when the screw is filled to φ of it), so the contact pressure is (F_a·S/L)/A_m. The
    flight's plate model is axisymmetric: it takes this pressure on the whole face, which bounds the sector load
    from above for the clamped-edge moment. CEMA 350 and the manufacturers' guides (KWS, Martin) size flights
    from thickness tables instead of a stress; seed 004 (eq 2.56) puts the whole axial force on one turn's whole
    face (:func:`flight_pressure`, kept as the ``one_turn`` option).

    Parameters
    ----------
    axial : float or array
        Axial force F_a [N] at the drive end.
    diameter, pipe_outer_diameter : float or array
        D = 2·R1 and d_o = 2·R2 [m].
    pitch, length : float or array
        S and the screw length L [m], > 0.
    material_area : float or array
        A_m [m²] > 0, the material's cross-section (at most the annulus, to which it is clipped).

    Returns
    -------
    float or array
        p [Pa].

    Examples
    --------
    >>> round(float(flight_turn_pressure(1000.0, 0.2, 0.1, 0.2, 10.0, 0.3 * math.pi * (0.1**2 - 0.05**2))), 3)
    2829.421
    """
    annulus = math.pi * ((diameter / 2.0) ** 2 - (pipe_outer_diameter / 2.0) ** 2)
    share = np.minimum(1.0, pitch / length)
    return axial * share / np.minimum(material_area, annulus)


def lift_height(length, inclination):
    """Lift of an inclined screw H = L·sin β [m] (seed 004, worked example: 21·sin 10° = 3.65 m).

    Parameters
    ----------
    length : float
        Conveyor (screw) length L [m].
    inclination : float
        Inclination β [rad], 0 <= β < π/2.

    Returns
    -------
    float
        H [m].

    Examples
    --------
    >>> round(lift_height(21.0, math.radians(10.0)), 5)
    3.64661
    """
    return length * math.sin(inclination)
