"""Sizing the parts that carry a linkage's joint forces over its cycle: rolling and plain bearings at revolute
joints, pins, and two-pin links in fatigue. Each part is a check with its value, its limit and its utilisation
(value / limit for a load, limit / value for a life or a safety factor), like the conveyor's checks.

The loads are the engine's joint reactions at every crank position; the time each position lasts is dφ/ω, so a
run at a fluctuating speed (``[flywheel]``) weights the cycle correctly.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..errors import InputError
from ..linkage import model as _model
from ..notebook import ShownInNotebook
from .bearings import life_exponent, plain_bearing_pv
from .fatigue import amplitude_and_mean, fatigue_safety, reversed_equivalent, sn_line
from .population import rolling_bearing_life
from .strength import link_section_loads, pin_stresses

HOUR = 3600.0


@dataclass(frozen=True)
class PartCheck:
    """One check of a part: what, its value and limit (SI), the utilisation (1 = at the limit) and the unit."""

    part: str
    quantity: str
    value: float
    limit: float
    utilisation: float
    unit: str
    #: the last part of the result's key, ``parts.<part kind>.<name>.<figure>`` (``rating_life``, ``mean_pv``)
    figure: str = ""

    @property
    def passed(self) -> bool:
        return bool(self.utilisation <= 1.0)


@dataclass(frozen=True)
class BearingSpec:
    """A bearing at a revolute joint: rolling ("ball", "roller": rating C [N], required life [s], reliability
    [%]) or "plain" (bore d, length l [m], allowable pressure [Pa] and pv [Pa·m/s])."""

    joint: str
    kind: str
    capacity: float | None = None
    life: float | None = None
    reliability: float = 90.0
    diameter: float | None = None
    length: float | None = None
    max_pressure: float | None = None
    max_pv: float | None = None


@dataclass(frozen=True)
class PinSpec:
    """A pin at a joint: diameter, length in the eye [m], shear planes, allowable shear and pressure [Pa]."""

    joint: str
    diameter: float
    length: float
    shear_planes: int = 2
    allowable_shear: float | None = None
    allowable_pressure: float | None = None


@dataclass(frozen=True)
class LinkSpec:
    """A two-pin link: its cross-section area [m²], section modulus [m³], corrected endurance limit Se and
    ultimate strength Sut [Pa], the smallest fatigue safety factor accepted, the fatigue criterion, the yield
    strength Sy [Pa] (for Soderberg, ASME-elliptic and Langer's yield check), the fatigue notch factor Kf applied
    to the stresses, and the life [cycles] required of a link stressed above its endurance limit (with Shigley's
    fraction f, None: his fit)."""

    body: str
    area: float
    section_modulus: float
    endurance_limit: float
    ultimate_strength: float
    min_safety: float = 1.5
    criterion: str = "goodman"
    yield_strength: float | None = None
    notch_factor: float = 1.0
    required_cycles: float | None = None
    fraction: float | None = None


def check_key(part: str, quantity: str, figure: str = "") -> str:
    """The result key of a check: ``parts.<kind>.<name>.<figure>`` (``parts.pin.B.peak_shear_stress``); a check
    with no figure of the grammar (see docs/results.md) is named by its quantity in lower-case words joined by
    ``_``."""
    return "parts." + part.replace(" ", ".") + "." + (figure or re.sub(r"[^a-z0-9]+", "_", quantity.lower()).strip("_"))


#: The names of the fatigue criteria in the checks (the Goodman one keeps its historical key).
CRITERION_NAMES = {"goodman": "modified Goodman", "soderberg": "Soderberg", "gerber": "Gerber",
                   "asme_elliptic": "ASME elliptic"}


@dataclass(frozen=True)
class PartsResult(ShownInNotebook):
    """Every check, and the per-position series the report draws (crank angle [rad], loads, stresses)."""

    checks: tuple[PartCheck, ...]
    crank_angle: np.ndarray
    bearing_loads: dict = field(default_factory=dict)   # joint -> (|F| [N], equal-life load [N] or None)
    link_stress: dict = field(default_factory=dict)     # body -> (σ_max fibre [Pa], σ_min fibre [Pa])
    link_fatigue: dict = field(default_factory=dict)    # body -> LinkFatigue

    @property
    def failed(self) -> tuple[PartCheck, ...]:
        return tuple(c for c in self.checks if not c.passed)


@dataclass(frozen=True)
class LinkFatigue:
    """A link's fatigue point (σ_a, σ_m [Pa], the notch factor applied) and its strengths S_e, S_ut, S_y [Pa]
    (S_y None if not given), with the criterion used: what the report's Haigh diagram draws."""

    amplitude: float
    mean: float
    endurance: float
    ultimate: float
    yield_strength: float | None
    criterion: str


def link_fatigue_checks(link: LinkSpec, top: np.ndarray, bottom: np.ndarray) -> tuple[list[PartCheck], LinkFatigue]:
    """The fatigue checks of a link from the stress histories of its extreme fibres: the safety factor by its
    criterion, Langer's yield factor (with S_y), the peak stress against S_ut, and, with required cycles, the
    damage n/N of those cycles (Palmgren–Miner) with N from the S–N line and the Goodman-equivalent reversed
    stress (0 below the endurance limit). The worse fibre (the larger |σ|) governs."""
    worst = top if np.max(np.abs(top)) >= np.max(np.abs(bottom)) else bottom
    amp, mean = amplitude_and_mean(link.notch_factor * worst, link.notch_factor * worst)
    name = f"link {link.body}"
    point = LinkFatigue(amp, mean, link.endurance_limit, link.ultimate_strength, link.yield_strength,
                        link.criterion)
    peak = amp + abs(mean)
    if peak >= link.ultimate_strength:  # broken in the first cycle: no fatigue factor to give
        return [PartCheck(name, "peak stress", peak, link.ultimate_strength, peak / link.ultimate_strength,
                          "Pa", "peak_stress")], point
    safety = fatigue_safety(amp, mean, link.endurance_limit, link.ultimate_strength, link.yield_strength,
                            link.criterion)  # type: ignore[arg-type]
    checks = [PartCheck(name, f"fatigue safety factor ({CRITERION_NAMES[link.criterion]})", float(safety.fatigue),
                        link.min_safety, link.min_safety / safety.fatigue if np.isfinite(safety.fatigue) else 0.0,
                        "", "fatigue_safety")]
    if link.yield_strength is not None:
        checks.append(PartCheck(name, "yield safety factor (Langer)", float(safety.yielding), link.min_safety,
                                link.min_safety / safety.yielding if np.isfinite(safety.yielding) else 0.0, "",
                                "yield_safety"))
    if link.required_cycles is not None:
        line = sn_line(link.ultimate_strength, link.endurance_limit, link.fraction)
        cycles = line.cycles(reversed_equivalent(amp, mean, link.ultimate_strength))
        damage = link.required_cycles / cycles if np.isfinite(cycles) else 0.0  # 0: below the endurance limit
        checks.append(PartCheck(name, "fatigue damage over the required cycles", damage, 1.0, damage, "",
                                "fatigue_damage"))
    return checks, point


def _cycle_weights(kin: Any) -> tuple[np.ndarray, float]:
    """Duration [s] of each crank position (trapezoid over the periodic grid) and the cycle's period [s]."""
    phi = np.asarray(kin.crank_angle, dtype=float).ravel()
    speed = np.abs(np.broadcast_to(np.asarray(kin.speed, dtype=float), phi.shape))
    if np.any(speed <= 0):
        raise InputError("Parts are sized over a turning crank: the crank speed must be > 0 at every position.")
    step = np.gradient(np.unwrap(phi)) if phi.size > 1 else np.array([2 * np.pi])
    dt = np.abs(step) / speed
    return dt, float(dt.sum())


def _joints(mech: Any) -> dict[str, tuple[str, str, str]]:
    return {name: (kind, b1, b2) for name, kind, b1, b2 in _model.joints(mech)}


def _omega(kin: Any, body: str, size: int) -> np.ndarray:
    if body == _model.GROUND:
        return np.zeros(size)
    return np.broadcast_to(np.asarray(kin.body(body).omega, dtype=float), (size,))


def size_parts(forces: Any, *, bearings: tuple[BearingSpec, ...] = (), pins: tuple[PinSpec, ...] = (),
               links: tuple[LinkSpec, ...] = ()) -> PartsResult:
    """Check every part named against the joint forces of one design over its cycle.

    Parameters
    ----------
    forces : the kinetostatic result (:func:`machdyn.linkage.kinetostatics`) of a single design over a whole
        cycle of crank positions (at constant or varying speed).
    bearings, pins, links : the parts.

    Returns
    -------
    PartsResult
    """
    kin = forces.kinematics
    mech = forces.mechanism
    phi = np.asarray(kin.crank_angle, dtype=float).ravel()
    size = phi.size
    joints = _joints(mech)
    dt, period = _cycle_weights(kin)
    checks: list[PartCheck] = []
    bearing_loads: dict = {}
    link_stress: dict = {}
    link_fatigue: dict = {}

    def joint(name: str, where: str) -> tuple[np.ndarray, np.ndarray, tuple[str, str, str]]:
        if name not in joints:
            raise InputError(f"{where}: no joint '{name}'; joints: {', '.join(joints)}.")
        r = forces.joint(name)
        fx = np.broadcast_to(np.asarray(r.fx, dtype=float), (size,))
        fy = np.broadcast_to(np.asarray(r.fy, dtype=float), (size,))
        return fx, fy, joints[name]

    for b in bearings:
        fx, fy, (kind, b1, b2) = joint(b.joint, f"bearing at {b.joint}")
        if kind != "R":
            raise InputError(f"A bearing sits at a revolute joint; '{b.joint}' is prismatic.")
        load = np.hypot(fx, fy)
        w_rel = np.abs(_omega(kin, b2, size) - _omega(kin, b1, size))
        turned = w_rel * dt  # [rad] of relative rotation made at each position
        if b.kind in ("ball", "roller"):
            if turned.sum() <= 0:
                raise InputError(f"The rolling bearing at {b.joint} does not turn over the cycle; give it as a "
                                 "plain bearing or bushing.")
            # the population's formula, for one design (one formula for both)
            lives, equivalents, _ok = rolling_bearing_life(load, turned, period, b.capacity, b.kind, b.reliability)
            life, equivalent = float(lives[0]), float(equivalents[0])  # [s], [N]
            bearing_loads[b.joint] = (load, equivalent)
            if b.life is not None:
                checks.append(PartCheck(f"bearing {b.joint}", f"rating life L{100 - b.reliability:g} "
                                        f"(p = {life_exponent(b.kind):.3g})", life, b.life, b.life / life, "s",
                                        "rating_life"))
            else:
                checks.append(PartCheck(f"bearing {b.joint}", "rating life (no requirement)", life, 0.0, 0.0, "s",
                                        "rating_life"))
        else:
            assert b.diameter is not None and b.length is not None
            p, pv = plain_bearing_pv(load, b.diameter, b.length, w_rel * b.diameter / 2.0)
            bearing_loads[b.joint] = (load, None)  # a plain bearing has no equal-life load
            if b.max_pressure is not None:
                checks.append(PartCheck(f"bearing {b.joint}", "peak pressure p", float(p.max()), b.max_pressure,
                                        float(p.max()) / b.max_pressure, "Pa", "peak_pressure"))
            mean_pv = float(np.sum(pv * dt) / period)
            if b.max_pv is not None:
                checks.append(PartCheck(f"bearing {b.joint}", "mean p·v over the cycle", mean_pv, b.max_pv,
                                        mean_pv / b.max_pv, "Pa*m/s", "mean_pv"))
    for pin in pins:
        fx, fy, _j = joint(pin.joint, f"pin at {pin.joint}")
        tau, p = pin_stresses(np.hypot(fx, fy), pin.diameter, pin.length, pin.shear_planes)
        if pin.allowable_shear is not None:
            checks.append(PartCheck(f"pin {pin.joint}", "peak shear stress", float(tau.max()), pin.allowable_shear,
                                    float(tau.max()) / pin.allowable_shear, "Pa", "peak_shear_stress"))
        if pin.allowable_pressure is not None:
            checks.append(PartCheck(f"pin {pin.joint}", "peak bearing pressure", float(p.max()),
                                    pin.allowable_pressure, float(p.max()) / pin.allowable_pressure, "Pa",
                                    "peak_bearing_pressure"))
    for link in links:
        ends = [(n, b1, b2) for n, (k, b1, b2) in joints.items() if k == "R" and link.body in (b1, b2)]
        if len(ends) != 2:
            raise InputError(f"A link is a body with exactly two revolute joints; '{link.body}' has {len(ends)}.")
        (name_a, a1, _a2), (name_b, _b1, _b2) = ends
        point_a, point_b = name_a.split(":")[0], name_b.split(":")[0]
        body = mech.body(link.body)
        if point_a not in body.points or point_b not in body.points:
            raise InputError(f"The link '{link.body}' has no points named after its joints ({point_a}, {point_b}).")
        state_a, state_b = kin.point(f"{link.body}.{point_a}"), kin.point(f"{link.body}.{point_b}")
        fx, fy, _j = joint(name_a, f"link {link.body}")
        if a1 != link.body:  # the reaction is on the later body: on the link when the link comes later
            on_link = (fx, fy)
        else:
            on_link = (-fx, -fy)
        axial, moment = link_section_loads(state_a, state_b, on_link, float(np.ravel(body.mass)[0]))
        sigma_axial = axial / link.area
        sigma_bend = np.abs(moment) / link.section_modulus
        top, bottom = sigma_axial + sigma_bend, sigma_axial - sigma_bend
        link_stress[link.body] = (top, bottom)
        found, link_fatigue[link.body] = link_fatigue_checks(link, top, bottom)
        checks += found
    return PartsResult(tuple(checks), phi, bearing_loads, link_stress, link_fatigue)
