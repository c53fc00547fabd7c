"""The ``[parts]`` table of N linkage designs at once: every check of :func:`.parts.size_parts`, from the
kinetostatics of a mechanism of N designs over its cycle (joint forces (N, K)), by the formulas of
:mod:`.population` (ISO 281:2007 rating life with Mott's equal-life load; Shigley's MED pin stresses, plain
bearing p·v and fatigue criteria; the inertial bending of :func:`.strength.link_section_loads`).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..errors import InputError
from ..linkage import model as _model
from .bearings import life_exponent
from .parts import CRITERION_NAMES, check_key
from .population import _rows, link_fatigue, pin_peaks, plain_bearing, rolling_bearing_life
from .strength import link_section_loads


def parts_population(forces: Any, *, bearings: tuple = (), pins: tuple = (),
                     links: tuple = ()) -> dict[str, np.ndarray]:
    """The ``[parts]`` results of N designs from their kinetostatics over a cycle (one engine call on a
    mechanism of N designs, :func:`machdyn.linkage.kinetostatics`), by the keys the ``[parts]`` stage reports
    (``parts.bearing.O.rating_life_l10``, ``parts.pin.B.peak_shear_stress``, ``parts.link.rod.fatigue_safety_
    factor_goodman``, ``parts.utilisation.max``), each (N,), and ``valid`` (N,): False where a design's forces
    are not finite (it does not assemble) or a check is not defined for it (a rolling bearing that does not turn,
    a link broken in its first cycle), the results of such a design NaN.

    The formulas are those of :func:`machdyn.drivetrain.parts.size_parts`; the names are checked as it does.
    """
    kin, mech = forces.kinematics, forces.mechanism
    phi = np.asarray(kin.crank_angle, dtype=float).ravel()
    joint_forces = {name: forces.joint(name) for name, *_ in _model.joints(mech)}
    fx0 = _rows(next(iter(joint_forces.values())).fx)
    n, k = fx0.shape[0], phi.size
    shape = (n, k)
    speed = np.abs(np.broadcast_to(np.asarray(kin.speed, dtype=float), shape))
    step = np.abs(np.gradient(np.unwrap(phi))) if k > 1 else np.array([2 * np.pi])
    with np.errstate(divide="ignore", invalid="ignore"):
        dt = step / speed
    period = dt.sum(axis=1)
    valid = np.all(speed > 0, axis=1)
    joints = {name: (kind, b1, b2) for name, kind, b1, b2 in _model.joints(mech)}
    out: dict[str, np.ndarray] = {}
    utilisation = np.zeros(n)

    def put(part: str, quantity: str, value: np.ndarray, use: np.ndarray, figure: str) -> None:
        nonlocal utilisation
        out[check_key(part, quantity, figure)] = value
        utilisation = np.maximum(utilisation, use)

    def joint(name: str, where: str) -> tuple[np.ndarray, np.ndarray]:
        if name not in joints:
            raise InputError(f"{where}: no joint '{name}'; joints: {', '.join(joints)}.")
        r = joint_forces[name]
        return (np.broadcast_to(np.asarray(r.fx, dtype=float), shape),
                np.broadcast_to(np.asarray(r.fy, dtype=float), shape))

    def omega(body: str) -> np.ndarray:
        if body == _model.GROUND:
            return np.zeros(shape)
        return np.broadcast_to(np.asarray(kin.body(body).omega, dtype=float), shape)

    for b in bearings:
        fx, fy = joint(b.joint, f"bearing at {b.joint}")
        kind, b1, b2 = joints[b.joint]
        if kind != "R":
            raise InputError(f"A bearing sits at a revolute joint; '{b.joint}' is prismatic.")
        load = np.hypot(fx, fy)
        w_rel = np.abs(omega(b2) - omega(b1))
        valid &= np.all(np.isfinite(load), axis=1)
        if b.kind in ("ball", "roller"):
            life, _fm, ok = rolling_bearing_life(load, w_rel * dt, period, b.capacity, b.kind, b.reliability)
            valid &= ok
            if b.life is not None:
                put(f"bearing {b.joint}", f"rating life L{100 - b.reliability:g} (p = {life_exponent(b.kind):.3g})",
                    life, b.life / life, "rating_life")
            else:
                put(f"bearing {b.joint}", "rating life (no requirement)", life, np.zeros(n), "rating_life")
        else:
            p_max, mean_pv = plain_bearing(load, w_rel, dt, period, b.diameter, b.length)
            if b.max_pressure is not None:
                put(f"bearing {b.joint}", "peak pressure p", p_max, p_max / b.max_pressure, "peak_pressure")
            if b.max_pv is not None:
                put(f"bearing {b.joint}", "mean p·v over the cycle", mean_pv, mean_pv / b.max_pv, "mean_pv")
    for pin in pins:
        fx, fy = joint(pin.joint, f"pin at {pin.joint}")
        tau, p = pin_peaks(np.hypot(fx, fy), pin.diameter, pin.length, pin.shear_planes)
        if pin.allowable_shear is not None:
            put(f"pin {pin.joint}", "peak shear stress", tau, tau / pin.allowable_shear, "peak_shear_stress")
        if pin.allowable_pressure is not None:
            put(f"pin {pin.joint}", "peak bearing pressure", p, p / pin.allowable_pressure,
                "peak_bearing_pressure")
    for link in links:
        ends = [(nm, b1, b2) for nm, (kd, b1, b2) in joints.items() if kd == "R" and link.body in (b1, b2)]
        if len(ends) != 2:
            raise InputError(f"A link is a body with exactly two revolute joints; '{link.body}' has {len(ends)}.")
        (name_a, a1, _a2), (name_b, _b1, _b2) = ends
        point_a, point_b = name_a.split(":")[0], name_b.split(":")[0]
        body = mech.body(link.body)
        state_a, state_b = kin.point(f"{link.body}.{point_a}"), kin.point(f"{link.body}.{point_b}")
        fx, fy = joint(name_a, f"link {link.body}")
        on_link = (fx, fy) if a1 != link.body else (-fx, -fy)
        mass = np.reshape(np.asarray(body.mass, dtype=float), (-1, 1))
        axial, moment = link_section_loads(state_a, state_b, on_link, mass)
        sigma_axial, sigma_bend = axial / link.area, np.abs(moment) / link.section_modulus
        found = link_fatigue(link, sigma_axial + sigma_bend, sigma_axial - sigma_bend)
        name = f"link {link.body}"
        valid &= ~found.broken
        put(name, f"fatigue safety factor ({CRITERION_NAMES[link.criterion]})", found.fatigue,
            np.where(np.isfinite(found.fatigue), link.min_safety / found.fatigue, 0.0), "fatigue_safety")
        if link.yield_strength is not None:
            put(name, "yield safety factor (Langer)", found.yielding,
                np.where(np.isfinite(found.yielding), link.min_safety / found.yielding, 0.0), "yield_safety")
        if link.required_cycles is not None:
            put(name, "fatigue damage over the required cycles", found.damage, found.damage, "fatigue_damage")
    out["parts.utilisation.max"] = utilisation
    return {key: np.where(valid, np.asarray(v, dtype=float), np.nan) for key, v in out.items()} | {"valid": valid}
