"""Brakes from their geometry: block (shoe) brakes on a lever, simple and differential band brakes, band-and-block
brakes, internal expanding shoes and disc brakes — the braking torque from the force at the lever, whether the
brake is self-energising and whether it would lock itself; and the temperature rise of the drum or disc per stop
and over repeated stops.

Every function takes and returns SI floats (m, N, Pa, rad, N·m, J, kg, K). A brake that would lock itself (the
friction alone holds the lever on, so a zero lever force already brakes) is refused with an error naming the
dimension that causes it: a self-locking service brake grabs and cannot be released by the operator.

Sources
-------
- R. S. Khurmi, J. K. Gupta, *Theory of Machines*, 14th ed., S. Chand/Eurasia 2005, ch. 19 "Brakes and
  dynamometers": single block brake (the three cases of the pivot's offset from the friction line, the
  self-energising and self-locking conditions), long shoe equivalent μ' = 4 μ sin θ / (2θ + sin 2θ), double
  block brake, simple and differential band brakes (T1/T2 = e^{μθ}; self-locking when b2 <= b1 e^{μθ}) and the
  band-and-block brake (T1/T2 = ((1 + μ tan θ)/(1 − μ tan θ))^n).
- R. G. Budynas, J. K. Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed., McGraw-Hill 2015, §16-2
  "Internal expanding rim clutches and brakes" (p = p_a sin θ / sin θ_a; M_f, M_N and F = (M_N ∓ M_f)/c;
  T = f p_a b r² (cos θ1 − cos θ2)/sin θ_a; self-locking when M_f >= M_N), §16-5/16-6 (disc brakes with
  annular pads, uniform wear), §16-12 "Energy considerations" and "Temperature rise" (ΔT = E/(C W); Newton
  cooling with the lumped coefficient β = ħ_CR A/(W C); the temperature after many stops at intervals t1,
  T_max = T∞ + ΔT/(1 − e^{−β t1})).
- Each closed form is checked in the tests against a second method (the numerical integral of the shoe's
  pressure, the band's differential equation, a stop-by-stop simulation of heating and cooling).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import InputError
from .clutches import Law, plate_clutch_torque


@dataclass(frozen=True)
class BrakeTorque:
    """A brake from its geometry: the braking torque [N·m] for the force at the lever [N], the same brake's
    torque with the drum turning the other way [N·m], whether the friction helps the lever (self-energising),
    and the largest lining pressure [Pa] where the geometry defines it (else NaN-free 0.0)."""

    torque: float
    lever_force: float
    torque_reverse: float
    self_energising: bool
    max_pressure: float = 0.0


def _positive(name: str, value: float, *, allow_zero: bool = False) -> None:
    ok = math.isfinite(value) and (value >= 0 if allow_zero else value > 0)
    if not ok:
        raise InputError(f"The brake's {name} must be {'>= 0' if allow_zero else '> 0'}; got {value!r}.")


def equivalent_friction(friction: float, contact_angle: float) -> float:
    """The equivalent coefficient of friction of a long block (shoe) pressed on the drum over the angle 2θ
    (Khurmi & Gupta, *Theory of Machines*, 14th ed., ch. 19, "Single block or shoe brake", long shoe; the
    pressure ∝ cos of the angle from the shoe's centre):

    μ' = 4 μ sin θ / (2θ + sin 2θ)

    Parameters
    ----------
    friction : μ [-] > 0.
    contact_angle : 2θ [rad], 0 <= 2θ < π (0: a short block, μ' = μ).

    Returns
    -------
    float
        μ' [-] >= μ.

    Examples
    --------
    A 90° shoe: μ' = 4·0.3·sin 45° / (π/2 + 1) = 0.330:

    >>> round(equivalent_friction(0.3, math.pi / 2), 4)
    0.33
    """
    _positive("coefficient of friction", friction)
    if not (math.isfinite(contact_angle) and 0.0 <= contact_angle < math.pi):
        raise InputError(f"A block's contact angle must be >= 0 and < 180°; got {math.degrees(contact_angle):g}°.")
    theta = 0.5 * contact_angle
    if theta < 1e-9:
        return friction
    return 4.0 * friction * math.sin(theta) / (2.0 * theta + math.sin(2.0 * theta))


def _block_normal(force: float, lever: float, block: float, offset: float, friction: float) -> float:
    """N from the moments about the lever's pivot, F l + μ N a = N x (a > 0: the friction helps the lever)."""
    arm = block - friction * offset
    if arm <= 0:
        raise InputError(f"The block brake locks itself: the friction's moment about the pivot, μ·a = "
                         f"{friction:g}·{offset:g} m, is at least the normal force's arm x = {block:g} m "
                         f"(needs x > μ·a; move the pivot towards the friction line or lengthen x).")
    return force * lever / arm


def block_brake(friction: float, force: float, drum_radius: float, lever: float, block: float,
                offset: float = 0.0, contact_angle: float = 0.0) -> BrakeTorque:
    """A single block (shoe) brake on a pivoted lever (Khurmi & Gupta, *Theory of Machines*, 14th ed., ch. 19,
    "Single block or shoe brake").

    Moments about the pivot: F l + μ N a = N x, so N = F l / (x − μ a);  T = μ' N r.

    Parameters
    ----------
    friction : μ [-] > 0 of the lining.
    force : F [N] >= 0, the force at the end of the lever.
    drum_radius : r [m] > 0.
    lever : l [m] > 0, from the pivot to the line of the force F.
    block : x [m] > 0, from the pivot to the line of the block's normal force (through the drum's centre).
    offset : a [m], the distance of the pivot from the line of the friction force (the tangent at the block),
        signed: > 0 when the friction's moment about the pivot adds to the force's (self-energising for this
        direction of rotation), < 0 when it opposes it, 0 when the pivot lies on the friction line.
    contact_angle : 2θ [rad] of the block; > 0 uses the long-shoe equivalent μ' (:func:`equivalent_friction`).

    Returns
    -------
    BrakeTorque
        torque_reverse: the drum turning the other way (the offset's sign changed).

    Raises
    ------
    InputError
        if the brake locks itself (x <= μ a).

    Examples
    --------
    Drum 320 mm, μ = 0.3, F = 100 N at 1 m, block at 0.3 m, pivot 40 mm off the friction line, self-energising:
    N = 100/(0.3 − 0.012) = 347.2 N, T = 0.3·347.2·0.16 = 16.67 N·m:

    >>> b = block_brake(0.3, 100.0, 0.16, 1.0, 0.3, 0.04)
    >>> round(b.torque, 2), round(b.torque_reverse, 2), b.self_energising
    (16.67, 15.38, True)
    """
    for name, value in (("drum radius", drum_radius), ("lever length", lever), ("block distance", block)):
        _positive(name, value)
    _positive("lever force", force, allow_zero=True)
    if not math.isfinite(offset):
        raise InputError(f"The brake's friction-line offset must be finite; got {offset!r}.")
    mu = equivalent_friction(friction, contact_angle)
    forward = mu * _block_normal(force, lever, block, offset, mu) * drum_radius
    backward = mu * _block_normal(force, lever, block, -offset, mu) * drum_radius
    return BrakeTorque(forward, force, backward, offset > 0)


def double_block_brake(friction: float, force: float, drum_radius: float, lever: float, block: float,
                       offset: float = 0.0, contact_angle: float = 0.0) -> BrakeTorque:
    """A double block brake: two levers mirrored about the drum, each pressed by the force F (a spring between
    them). For a given rotation one block is self-energising and the other is not (Khurmi & Gupta, *Theory of
    Machines*, 14th ed., ch. 19, "Double block or shoe brake").

    T = μ' r (N1 + N2),  N1 = F l / (x − μ' a),  N2 = F l / (x + μ' a)

    Parameters
    ----------
    As :func:`block_brake`; ``offset`` is that of either block (its sign does not matter: the pair is symmetric).

    Returns
    -------
    BrakeTorque
        the same torque either way.

    Examples
    --------
    With the pivots on the friction lines (a = 0) the torque is twice one block's:

    >>> round(double_block_brake(0.3, 100.0, 0.16, 1.0, 0.3).torque, 3)
    32.0
    """
    one = block_brake(friction, force, drum_radius, lever, block, abs(offset), contact_angle)
    total = one.torque + one.torque_reverse
    return BrakeTorque(total, force, total, False)


def band_ratio(friction: float, wrap_angle: float, blocks: int = 0, block_angle: float = 0.0) -> float:
    """The tension ratio T1/T2 of a band brake (Euler–Eytelwein, T1/T2 = e^{μθ}) or of a band-and-block brake of
    n blocks each subtending 2θ, T1/T2 = ((1 + μ tan θ)/(1 − μ tan θ))^n (Khurmi & Gupta, *Theory of Machines*,
    14th ed., ch. 19, "Band and block brake").

    Parameters
    ----------
    friction : μ [-] > 0.
    wrap_angle : θ [rad] > 0, the band's angle of contact (band brake; ignored with blocks).
    blocks : n >= 0; 0 for a plain band.
    block_angle : 2θ [rad] of each block, with μ tan θ < 1.

    Returns
    -------
    float
        T1/T2 [-] > 1.

    Examples
    --------
    >>> round(band_ratio(0.3, math.radians(270)), 4), round(band_ratio(0.3, 0, 12, math.radians(15)), 3)
    (4.1112, 2.582)
    """
    _positive("coefficient of friction", friction)
    if blocks:
        if int(blocks) != blocks or blocks < 1:
            raise InputError(f"A band-and-block brake has a whole number >= 1 of blocks; got {blocks!r}.")
        half = 0.5 * block_angle
        if not (math.isfinite(half) and 0.0 < half < 0.5 * math.pi) or friction * math.tan(half) >= 1.0:
            raise InputError(f"A block's angle 2θ = {math.degrees(block_angle):g}° must be > 0 with μ·tan θ < 1.")
        return float(((1.0 + friction * math.tan(half)) / (1.0 - friction * math.tan(half))) ** blocks)
    if not (math.isfinite(wrap_angle) and wrap_angle > 0):
        raise InputError(f"A band's angle of contact must be > 0; got {wrap_angle!r} rad.")
    return math.exp(friction * wrap_angle)


def band_brake(friction: float, force: float, drum_radius: float, lever: float, arm: float, wrap_angle: float,
               *, lever_on: str = "slack", blocks: int = 0, block_angle: float = 0.0) -> BrakeTorque:
    """A simple band brake (or band-and-block brake): one end of the band at the lever's pivot, the other at the
    distance b from it (Khurmi & Gupta, *Theory of Machines*, 14th ed., ch. 19, "Simple band brake").

    lever on the slack end: F l = T2 b;  lever on the tight end: F l = T1 b;  T = (T1 − T2) r, T1 = T2 · (T1/T2).

    Parameters
    ----------
    friction : μ [-]; force : F [N] >= 0 at the lever's end; drum_radius : r [m] (to the band's centre line for
        a thick band); lever : l [m] > 0; arm : b [m] > 0, from the pivot to the band's end on the lever;
    wrap_angle : θ [rad] of contact.
    lever_on : "slack" (the drum pulls the other, tight end against the pivot: the stronger way) or "tight".
    blocks, block_angle : n blocks of 2θ each for a band-and-block brake (:func:`band_ratio`).

    Returns
    -------
    BrakeTorque
        torque_reverse: the drum turning the other way (the lever then on the other end's role).

    Examples
    --------
    A 500 mm drum, 270° of wrap, μ = 0.3, F = 300 N at 0.5 m, slack end 50 mm from the pivot: T2 = 3000 N,
    T1 = 12334 N, T = 2333 N·m:

    >>> round(band_brake(0.3, 300.0, 0.25, 0.5, 0.05, math.radians(270)).torque)
    2333
    """
    for name, value in (("drum radius", drum_radius), ("lever length", lever), ("band's arm", arm)):
        _positive(name, value)
    _positive("lever force", force, allow_zero=True)
    if lever_on not in ("slack", "tight"):
        raise InputError(f"The lever holds the 'slack' or the 'tight' end of the band; got {lever_on!r}.")
    ratio = band_ratio(friction, wrap_angle, blocks, block_angle)
    pull = force * lever / arm
    slack_torque = pull * (ratio - 1.0) * drum_radius        # the lever's end is the slack one
    tight_torque = pull * (1.0 - 1.0 / ratio) * drum_radius  # the lever's end is the tight one
    if lever_on == "slack":
        return BrakeTorque(slack_torque, force, tight_torque, False, 0.0)
    return BrakeTorque(tight_torque, force, slack_torque, False, 0.0)


def differential_band_brake(friction: float, force: float, drum_radius: float, lever: float, slack_arm: float,
                            tight_arm: float, wrap_angle: float, *, blocks: int = 0,
                            block_angle: float = 0.0) -> BrakeTorque:
    """A differential band brake: both ends of the band on the lever, on either side of the pivot, so that the
    tight end's pull helps the force (Khurmi & Gupta, *Theory of Machines*, 14th ed., ch. 19, "Differential band
    brake").

    F l = T2 b2 − T1 b1 = T2 (b2 − b1 T1/T2);  T = (T1 − T2) r;  self-locking when b2 <= b1 · T1/T2.

    Parameters
    ----------
    friction, force, drum_radius, lever, wrap_angle, blocks, block_angle : as :func:`band_brake`.
    slack_arm : b2 [m] > 0, from the pivot to the slack end.
    tight_arm : b1 [m] >= 0, from the pivot to the tight end, on the other side.

    Returns
    -------
    BrakeTorque
        torque_reverse: the drum turning the other way, the ends' roles exchanged (refused if that direction locks
        too: then the brake is self-locking for both).

    Raises
    ------
    InputError
        if the brake locks itself (b2 <= b1 e^{μθ}).

    Examples
    --------
    Drum 250 mm radius, 270°, μ = 0.3, F = 100 N at 0.5 m, b2 = 100 mm, b1 = 20 mm: T2 = 50/(0.1 − 0.0822) =
    2814 N, T = 2814·3.1112·0.25 = 2188 N·m:

    >>> b = differential_band_brake(0.3, 100.0, 0.25, 0.5, 0.1, 0.02, math.radians(270))
    >>> round(b.torque), b.self_energising
    (2188, True)
    """
    for name, value in (("drum radius", drum_radius), ("lever length", lever), ("slack end's arm", slack_arm)):
        _positive(name, value)
    _positive("tight end's arm", tight_arm, allow_zero=True)
    _positive("lever force", force, allow_zero=True)
    ratio = band_ratio(friction, wrap_angle, blocks, block_angle)
    net = slack_arm - tight_arm * ratio
    if net <= 0:
        raise InputError(f"The differential band brake locks itself: the slack end's arm b2 = {slack_arm:g} m is "
                         f"not larger than the tight end's arm times the tension ratio, b1·T1/T2 = {tight_arm:g}·"
                         f"{ratio:.4g} = {tight_arm * ratio:.4g} m (needs b2 > b1·e^(μθ)).")
    slack = force * lever / net
    torque = slack * (ratio - 1.0) * drum_radius
    # the other way the tight end sits at b2 and opposes the lever: F l = T2' (b2 ratio - b1)
    reverse = force * lever / (slack_arm * ratio - tight_arm) * (ratio - 1.0) * drum_radius
    return BrakeTorque(torque, force, reverse, tight_arm > 0)


@dataclass(frozen=True)
class ShoeMoments:
    """The moments about the shoe's hinge per unit largest pressure: of the friction forces M_f/p_a and of the
    normal forces M_N/p_a [N·m/Pa], and the torque on the drum T/p_a [N·m/Pa]."""

    friction: float
    normal: float
    torque: float


def shoe_moments(friction: float, drum_radius: float, width: float, start: float, end: float,
                 hinge: float) -> ShoeMoments:
    """Moments of an internal (or external) shoe hinged at the distance a from the drum's centre, the lining from
    θ1 to θ2 measured from the line through the hinge, the pressure p = p_a sin θ / sin θ_a (Shigley's MED, 10th
    ed., §16-2, eqs. for M_f, M_N and T):

    M_f = f p_a b r / sin θ_a ∫ sin θ (r − a cos θ) dθ,   M_N = p_a b r a / sin θ_a ∫ sin² θ dθ,
    T = f p_a b r² (cos θ1 − cos θ2) / sin θ_a,   θ_a = θ2 if θ2 < 90° else 90°.

    Parameters
    ----------
    friction : f [-] > 0; drum_radius : r [m] > 0; width : b [m] > 0, the face width;
    start, end : θ1, θ2 [rad], 0 <= θ1 < θ2 <= π; hinge : a [m] > 0, the hinge's distance from the centre.

    Returns
    -------
    ShoeMoments
        per pascal of p_a.

    Examples
    --------
    >>> m = shoe_moments(0.32, 0.15, 0.032, 0.0, math.radians(126), 0.123)
    >>> round(m.friction * 1e6, 1), round(m.normal * 1e6, 1), round(m.torque * 1e6, 1)
    (304.0, 789.6, 365.8)
    """
    for name, value in (("drum radius", drum_radius), ("face width", width), ("hinge distance", hinge)):
        _positive(name, value)
    _positive("coefficient of friction", friction)
    if not (0.0 <= start < end <= math.pi):
        raise InputError(f"A shoe's lining runs from θ1 to θ2 with 0 <= θ1 < θ2 <= 180°; got "
                         f"{math.degrees(start):g}° to {math.degrees(end):g}°.")
    peak = math.sin(end) if end < 0.5 * math.pi else 1.0
    r, a = drum_radius, hinge
    friction_integral = (r * (math.cos(start) - math.cos(end))
                         - 0.5 * a * (math.sin(end) ** 2 - math.sin(start) ** 2))
    normal_integral = 0.5 * (end - start) - 0.25 * (math.sin(2 * end) - math.sin(2 * start))
    return ShoeMoments(friction * width * r / peak * friction_integral, width * r * a / peak * normal_integral,
                       friction * width * r * r * (math.cos(start) - math.cos(end)) / peak)


def internal_shoe_brake(friction: float, force: float, drum_radius: float, width: float, start: float, end: float,
                        hinge: float, force_arm: float, shoes: int = 2) -> BrakeTorque:
    """An internal expanding brake of one or two identical shoes pushed by the same force F at the arm c from
    their hinges; with two, one shoe is self-energising and the other is not (Shigley's MED, 10th ed., §16-2).

    energising shoe:   F c = M_N − M_f  →  p_a = F c / (M_N/p_a − M_f/p_a)   (locks itself if M_f >= M_N)
    other shoe:        F c = M_N + M_f  →  p_a' = F c / (M_N/p_a + M_f/p_a)
    T = (p_a + p_a') · T/p_a

    Parameters
    ----------
    friction, drum_radius, width, start, end, hinge : as :func:`shoe_moments`.
    force : F [N] >= 0 on each shoe.
    force_arm : c [m] > 0, from the hinge to the line of F.
    shoes : 1 (the energising shoe alone) or 2.

    Returns
    -------
    BrakeTorque
        max_pressure: the energising shoe's p_a; torque_reverse: the drum turning the other way.

    Raises
    ------
    InputError
        if the energising shoe locks itself.

    Examples
    --------
    Shigley's Example 16-2 geometry at F = (M_N − M_f)/c = 4856 N: p_a = 1 MPa on the energising shoe and
    T = 528 N·m from both shoes:

    >>> b = internal_shoe_brake(0.32, 4856.0, 0.15, 0.032, 0.0, math.radians(126), 0.123, 0.1)
    >>> round(b.max_pressure / 1e3), round(b.torque)
    (1000, 528)
    """
    _positive("actuating force", force, allow_zero=True)
    _positive("force arm", force_arm)
    if shoes not in (1, 2):
        raise InputError(f"An internal shoe brake has 1 or 2 shoes; got {shoes!r}.")
    m = shoe_moments(friction, drum_radius, width, start, end, hinge)
    if m.friction >= m.normal:
        raise InputError(f"The shoe locks itself: the friction's moment about the hinge M_f = "
                         f"{m.friction:.4g} N·m/Pa is not smaller than the normal forces' M_N = {m.normal:.4g} "
                         f"N·m/Pa (move the hinge farther from the centre or shorten the lining).")
    energised = force * force_arm / (m.normal - m.friction)
    other = force * force_arm / (m.normal + m.friction)
    torque = (energised + (other if shoes == 2 else 0.0)) * m.torque
    reverse = (other + (energised if shoes == 2 else 0.0)) * m.torque
    return BrakeTorque(torque, force, reverse, True, energised)


def disc_brake(friction: float, force: float, inner: float, outer: float, faces: int = 2,
               law: Law = "uniform_wear") -> BrakeTorque:
    """A caliper disc brake: pads of annular shape pressed on ``faces`` faces of the disc by the force F each,
    T = n μ F R_f (Shigley's MED, 10th ed., §16-5/16-6; the same mean friction radius as a plate clutch,
    :func:`~machdyn.drivetrain.clutches.friction_radius`; the pads' angular extent does not change it).

    Parameters
    ----------
    friction : μ [-]; force : F [N] >= 0, the clamping force on each face; inner, outer : r_i < r_o [m] of the
        pads; faces : n, 2 for a caliper gripping both faces; law : "uniform_wear" or "uniform_pressure".

    Returns
    -------
    BrakeTorque

    Examples
    --------
    >>> round(disc_brake(0.35, 5000.0, 0.08, 0.13).torque, 1)
    367.5
    """
    torque = plate_clutch_torque(friction, force, inner, outer, faces, law)
    return BrakeTorque(torque, force, torque, False)


@dataclass(frozen=True)
class Heating:
    """The temperature of a drum or disc: the rise per stop [K], the largest rise above the surroundings after
    many stops at the interval asked for [K] (the rise per stop where no cooling is given), the rise left when
    the next stop begins [K], the cooling rate constant β [1/s] and the interval between stops [s] (inf: one
    stop)."""

    rise_per_stop: float
    steady_peak_rise: float
    steady_base_rise: float
    decay_rate: float
    interval: float = math.inf

    def history(self, stops: int, points: int = 40) -> tuple[list[float], list[float]]:
        """The rise above the surroundings over the first ``stops`` stops (time [s], rise [K]): each stop adds
        ΔT at once, then the part cools exponentially until the next."""
        t: list[float] = []
        rise: list[float] = []
        level = 0.0
        span = self.interval if math.isfinite(self.interval) else 5.0 / max(self.decay_rate, 1e-12)
        for k in range(stops):
            level += self.rise_per_stop
            for i in range(points + 1):
                dt = span * i / points
                t.append(k * span + dt)
                rise.append(level * math.exp(-self.decay_rate * dt))
            level *= math.exp(-self.decay_rate * span)
        return t, rise


def temperature_rise(energy: float, mass: float, specific_heat: float, *, cooling: float = 0.0,
                     interval: float = math.inf) -> Heating:
    """The temperature rise of a brake drum or disc (Shigley's MED, 10th ed., §16-12 "Energy considerations",
    "Temperature rise"): the energy of a stop heats the part's mass, ΔT = E/(m c); between stops the part cools
    by Newton's law, dT/dt = −β (T − T∞) with β = ħA/(m c). After many stops at the interval t1 the temperature
    cycles between

    T_max − T∞ = ΔT / (1 − e^{−β t1})   and   T_min − T∞ = ΔT e^{−β t1} / (1 − e^{−β t1})

    (the geometric series of the rises left from the stops before).

    Parameters
    ----------
    energy : E [J] >= 0 turned into heat per stop.
    mass : m [kg] > 0 of the drum or disc that takes the heat (the lining's share neglected).
    specific_heat : c [J/(kg·K)] > 0 (cast iron 500, steel 460).
    cooling : ħA [W/K] >= 0, the lumped heat-transfer coefficient times the area that sheds heat (Shigley
        §16-12, Fig. 16-24 for ħ of a drum or disc); 0: no cooling.
    interval : t1 [s] > 0 between the starts of successive stops (inf: one stop).

    Returns
    -------
    Heating
        With no cooling and repeated stops the temperature grows without bound: refused.

    Examples
    --------
    A 20 kg cast-iron drum taking 100 kJ a stop, once a minute, ħA = 40 W/K: ΔT = 10 K, β = 0.004 /s,
    T_max − T∞ = 10/(1 − e^{−0.24}) = 46.9 K:

    >>> h = temperature_rise(100e3, 20.0, 500.0, cooling=40.0, interval=60.0)
    >>> round(h.rise_per_stop, 2), round(h.steady_peak_rise, 2)
    (10.0, 46.87)
    """
    _positive("energy per stop", energy, allow_zero=True)
    _positive("mass", mass)
    _positive("specific heat", specific_heat)
    _positive("cooling coefficient", cooling, allow_zero=True)
    if not interval > 0:
        raise InputError(f"The interval between stops must be > 0 s; got {interval!r}.")
    rise = energy / (mass * specific_heat)
    beta = cooling / (mass * specific_heat)
    if math.isinf(interval):
        return Heating(rise, rise, 0.0, beta, interval)
    if beta <= 0:
        raise InputError("Repeated stops with no cooling heat the brake without bound: give its cooling "
                         "coefficient ħA > 0 W/K.")
    left = math.exp(-beta * interval)
    peak = rise / (1.0 - left)
    return Heating(rise, peak, peak * left, beta, interval)
