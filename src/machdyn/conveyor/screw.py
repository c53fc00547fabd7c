"""Every quantity and check of a screw conveyor for many candidate screws at once (NumPy, SI).

:func:`screw_states` evaluates the cited formula functions of :mod:`.design`, :mod:`.power`, :mod:`.checks` and
:mod:`.plate` for arrays of diameters, pitches, speeds and fillings that broadcast together. A single run
(:mod:`.evaluate`) and the search for the best design (:mod:`.optimise`) both use it, so that they agree.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..dynamics.motors import smallest_rating
from . import checks as ck
from . import power as pw
from . import tables
from .design import speed_limit, volume_capacity
from .model import ConveyorProblem
from .plate import flight_max_stress

#: The design checks every candidate must pass: key -> (name, SI unit, display unit, basis).
CHECKS: dict[str, tuple[str, str, str, str]] = {
    "speed": ("Screw speed n <= k/sqrt(D)", "rad/s", "rpm", "seed 004, n = k/sqrt(D)"),
    "capacity": ("Throughput <= capacity", "kg/s", "t/h", "seed 004, eq 2.83; pipe deducted as in CEMA 350"),
    "motor": ("Motor load", "W", "kW", "IEC 60072-1 rating"),
    "twist": ("Pipe twist rate at the drive", "rad/m", "deg/m", "T/(G·Jp), pipe section"),
    "shear": ("Pipe torsional shear stress", "Pa", "MPa", "T·(d_o/2)/Jp"),
    "stress": ("Pipe equivalent stress (Tresca)", "Pa", "MPa", "seed 004, eq 2.48, pipe section"),
    "deflection": ("Deflection between hangers", "m", "mm", "5ql^4/(384EI), simply supported span"),
    "flight": ("Flight bending stress at the pipe", "Pa", "MPa",
               "seed 004, eqs 2.66-2.70 (corrected); load of one pitch, eq 2.92"),
}


def _arr(x: Any) -> Any:
    """A float array, typed loosely: the formula functions take floats or arrays alike."""
    return np.asarray(x, dtype=float)


def method_powers(problem: ConveyorProblem, diameter: Any, speed: Any, mass_flow: Any,
                  filling_actual: Any) -> dict[str, dict[str, Any]]:
    """Shaft power [W] of every requested method, with its parts [W]; NaN where a method does not apply.

    Each entry: ``{"power": array, "parts": {name: array}, "skip": reason or ""}``.
    """
    p = problem
    length, lift = p.length, p.lift_height
    out: dict[str, dict[str, Any]] = {}
    shape = np.broadcast(diameter, speed, mass_flow, filling_actual).shape
    nan = np.full(shape, np.nan)
    zero = np.zeros(shape)
    for method in p.methods:
        if method == "textbook_360":
            out[method] = {"power": pw.power_textbook_360(mass_flow, length, lift, p.resistance) + zero,
                           "parts": {"lift Q·H/360": 1000 * mass_flow * 3.6 * lift / 360,
                                     "resistance C0·Q·L/360": 1000 * p.resistance * mass_flow * 3.6 * length / 360},
                           "skip": ""}
        elif method == "textbook_367":
            out[method] = {"power": pw.power_textbook_367(mass_flow, length, lift, p.resistance) + zero,
                           "parts": {"lift Q·H/367": mass_flow * pw.G * lift,
                                     "resistance C0·Q·L/367": mass_flow * pw.G * p.resistance * length},
                           "skip": ""}
        elif method == "iso7119":
            if p.inclination > pw.ISO7119_MAX_INCLINATION + 1e-12:
                out[method] = {"power": nan, "parts": {}, "skip": (
                    f"ISO 7119 skipped: it applies to inclinations up to 20 deg; got "
                    f"{math.degrees(p.inclination):.4g} deg.")}
                continue
            iso = pw.power_iso7119(mass_flow, length, p.inclination, diameter, p.resistance)
            progress, no_load = iso.progress + zero, iso.no_load + zero
            incl = mass_flow * pw.G * lift + zero  # lift H as given (equal to L·sin β when not given)
            out[method] = {"power": progress + no_load + incl, "skip": "",
                           "parts": {"P_H progress": progress, "P_N no load": no_load, "P_st inclination": incl}}
        elif method == "cema":
            if p.cema_material_factor is None:
                out[method] = {"power": nan, "parts": {}, "skip": (
                    "CEMA method skipped: give material.cema_material_factor (Fm) or material.cema_material.")}
                continue
            fd = tables.cema_diameter_factors(diameter)
            loading = np.minimum(filling_actual, 0.95)
            r = pw.power_cema(
                volume_flow=mass_flow / p.bulk_density, bulk_density=p.bulk_density, length=length,
                speed=speed, diameter_factor=fd,
                hanger_bearing_factor=tables.cema_hanger_bearing_factor(p.hanger_bearing),
                material_factor=p.cema_material_factor,
                flight_factor=tables.cema_flight_factors(p.flight_type, loading),
                paddle_factor=tables.cema_paddle_factor(p.paddles), efficiency=1.0, lift=lift)
            base = r.friction_hp + r.material_hp + r.lift_hp
            skip = ""
            if np.all(np.isnan(fd)):
                skip = (f"CEMA method skipped: the diameter factor Fd is tabulated for 4 to 24 in screws; got "
                        f"{np.min(diameter) * 1000:g} mm.")
            out[method] = {"power": r.total_watts + zero, "skip": skip, "parts": {
                "HPf friction": r.friction_hp * pw.HP, "HPm material": r.material_hp * pw.HP,
                "lift": r.lift_hp * pw.HP, "overload allowance (Fo - 1)": (r.overload_factor - 1) * base * pw.HP}}
    return out


def screw_states(problem: ConveyorProblem, diameter: Any, pitch: Any, speed: Any, filling: Any,
                 mass_flow: Any) -> dict[str, Any]:
    """Every quantity [SI] and the value and limit of every check of :data:`CHECKS` for candidate screws.

    diameter D [m], pitch S [m], speed ω [rad/s], filling φ [-], mass_flow [kg/s] (the duty): arrays that
    broadcast together. Returns ``{key: array}`` with the keys of the run's results plus ``check.<key>`` and
    ``limit.<key>`` for each check and ``power.<method>`` for each method.
    """
    p = problem
    d, s, n, phi, m_dot = (_arr(x) for x in (diameter, pitch, speed, filling, mass_flow))
    out: dict[str, Any] = {}
    d_o: Any
    wall: Any
    t_f: Any
    # the given pipe, else the standard pipe of each screw's size (NaN beyond the table: such a candidate fails)
    d_o = p.pipe_outer_diameter if p.pipe_outer_diameter is not None else tables.standard_pipes(d)
    deducted = d_o if p.capacity_section == "annulus" else 0.0 * d_o
    cap_v = volume_capacity(d, s, angular_speed=n, filling=phi, inclination_factor=p.inclination_factor,
                            pipe_diameter=deducted)
    v_dot = m_dot / p.bulk_density
    fill_actual = phi * v_dot / cap_v
    n_lim = speed_limit(d, p.speed_coefficient)
    powers = method_powers(p, d, n, m_dot, fill_actual)
    shaft = powers[p.power_method]["power"] if p.power_method in powers else np.nan * d
    motor_required = shaft / p.drive_efficiency
    motor = np.asarray(smallest_rating(motor_required))
    torque = ck.torque_from_power(shaft, angular_speed=n) if p.torque is None else p.torque + 0 * d

    wall = p.pipe_wall if p.pipe_wall is not None else d_o / 12.0
    d_i = d_o - 2 * wall
    t_f = p.flight_thickness if p.flight_thickness is not None else np.maximum(0.003, d / 50.0)
    span, length = p.hanger_spacing, p.length
    radius = p.force_radius_ratio * d
    alpha = ck.helix_angle(s, radius)
    f_axial = ck.axial_force(torque, radius, alpha, p.friction_coefficient)
    p_lat = ck.lateral_load(torque, span, p.lateral_load_factor, d, length)
    dist = ck.distributed_loads(f_axial, p_lat, torque, span, length)
    jp = ck.polar_moment_tube(d_o, d_i)
    mass_len = ck.screw_mass_per_length(d, d_o, d_i, t_f, s, p.steel_density)
    q = np.hypot(mass_len * pw.G, dist["p_n"])
    sigma_eq = ck.pipe_equivalent_stress(q, span, f_axial, torque, d_o, d_i)
    deflection = ck.span_deflection(q, span, p.elastic_modulus, jp / 2.0)
    if p.flight_load == "one_turn":
        pressure = ck.flight_pressure(f_axial, d, d_o)
    else:  # the material's section: the filled fraction of the section its filling refers to
        material = fill_actual * math.pi / 4.0 * (d**2 - deducted**2)
        pressure = ck.flight_turn_pressure(f_axial, d, d_o, s, length, material)
    known = np.isfinite(pressure)  # NaN where the selected power method does not apply to a candidate
    sigma_flight = np.where(known, flight_max_stress(_arr(np.where(known, pressure, 0.0)), d / 2, d_o / 2, t_f,
                                                     p.poisson_ratio), np.nan)
    twist_rate = ck.twist_rate(torque, p.shear_modulus, jp)

    out.update({
        "mass_flow": m_dot + 0 * d, "volume_flow": v_dot + 0 * d, "diameter": d, "pitch": s,
        "speed": n + 0 * d, "speed_limit": n_lim, "capacity": cap_v * p.bulk_density,
        "filling_actual": fill_actual,
        "shaft_power": shaft, "motor_power_required": motor_required, "motor_rating": motor, "torque": torque,
        "helix_angle": alpha, "axial_force": f_axial, "lateral_load": p_lat, "p_d": dist["p_d"],
        "p_n": dist["p_n"], "m_0": dist["m_0"],
        "twist_total": ck.torsion_angle_distributed(dist["m_0"], length, p.shear_modulus, jp),
        "screw_mass_per_length": mass_len, "deflection": deflection, "flight_pressure": pressure,
        "pipe_outer_diameter": d_o + 0 * d, "pipe_inner_diameter": d_i + 0 * d, "flight_thickness": t_f + 0 * d,
        "span_load": q, "screw_mass": mass_len * length,
    })
    for method, entry in powers.items():
        out[f"power.{method}"] = entry["power"]
    values = {"speed": (n + 0 * d, n_lim), "capacity": (m_dot + 0 * d, cap_v * p.bulk_density),
              "motor": (motor_required, motor), "twist": (twist_rate, p.allowable_twist + 0 * d),
              "shear": (ck.shear_stress_tube(torque, d_o, d_i), p.allowable_shear_stress + 0 * d),
              "stress": (sigma_eq, p.allowable_stress + 0 * d),
              "deflection": (deflection, p.max_deflection + 0 * d),
              "flight": (sigma_flight, p.allowable_stress + 0 * d)}
    for key, (value, limit) in values.items():
        out[f"check.{key}"] = value
        out[f"limit.{key}"] = limit
    out["_powers"] = powers
    return out


def passes(states: dict[str, Any]) -> Any:
    """Boolean array: the candidate passes every check of :data:`CHECKS` (NaN fails)."""
    ok = np.ones(np.shape(states["diameter"]), dtype=bool)
    for key in CHECKS:
        with np.errstate(invalid="ignore"):
            ok &= np.asarray(states[f"check.{key}"] <= states[f"limit.{key}"] * (1 + 1e-12))
    return ok
