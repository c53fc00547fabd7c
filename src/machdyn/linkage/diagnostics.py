"""Diagnostics of a linkage over a crank revolution: where it assembles, the Grashof type of four-bars, dead
(toggle) positions, limit positions and strokes of the outputs, time ratio and transmission-angle extremes.

Sources: Grashof's rule and the transmission angle, Norton, *Design of Machinery*, 5th ed., §2.12 and
§4.10; limit positions and time ratio (quick-return ratio), Uicker, Pennock & Shigley, 5th ed., §1.9.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError
from .grashof import grashof_type
from .kinematics import kinematics
from .model import Mechanism, output_bodies
from .motion import Kinematics, angle_ranges, crank_angles, format_ranges, is_full_turn, singular
from .reductions import worst_of

#: Below this transmission angle [deg] force transmission is poor (Norton, §4.10: keep mu >= 40 deg).
MIN_GOOD_TRANSMISSION_DEG = 40.0


@dataclass(frozen=True)
class LimitPosition:
    """An output at rest: body, crank angle [rad], the output's value there (angle [rad] or travel [m])."""

    body: str
    crank_angle: float
    value: float


@dataclass(frozen=True)
class Diagnostics:
    """What a designer checks first about a linkage (one design; see :func:`diagnose`)."""

    grashof: str | None
    assembly_ranges: list
    non_assembly_ranges: list
    dead_positions: list
    limit_positions: list
    strokes: dict
    time_ratio: float | None
    transmission_angle_min: float
    transmission_angle_max: float
    warnings: list = field(default_factory=list)
    #: (start, stop) [rad] of the crank range described, or None for the full turn.
    crank_range: tuple[float, float] | None = None
    #: Per output of each dyad (body name): its time ratio (None without a full turn and two limit positions).
    time_ratios: dict = field(default_factory=dict)
    #: Per output of each dyad (body name): (min, max) transmission angle [rad] of the dyad that drives it.
    transmission_angles: dict = field(default_factory=dict)


def _zero_crossings(phi, values, valid):
    """(index, crank angle [rad]) where ``values`` changes sign between neighbouring valid samples (linear
    interpolation) or is zero, including the wrap from the last sample to the first over a full cycle."""
    n = len(phi)
    i = np.arange(n)
    j = (i + 1) % n
    pair = valid & valid[j]
    if n and not np.isclose((phi[0] - phi[-1]) % (2 * np.pi), 2 * np.pi / n):
        pair[-1] = False  # not a full cycle: no wrap
    a, b = values, values[j]
    with np.errstate(invalid="ignore"):
        zero = pair & (a == 0.0)
        cross = pair & ~zero & (a * b < 0.0)
    idx = np.flatnonzero(zero | cross)
    step = (phi[j[idx]] - phi[idx]) % (2 * np.pi)
    ai, bi = a[idx], b[idx]
    with np.errstate(invalid="ignore", divide="ignore"):
        interpolated = (phi[idx] + step * ai / (ai - bi)) % (2 * np.pi)
    angles = np.where(zero[idx], phi[idx], interpolated)
    return [(int(k), float(x)) for k, x in zip(idx, angles, strict=True)]


def diagnose(mech: Mechanism, samples: int = 3600, *, kinematics_result: Kinematics | None = None,
             crank_range: tuple[float, float] | None = None) -> Diagnostics:
    """Assembly ranges, Grashof type, dead and limit positions, strokes, time ratio and transmission-angle
    extremes of one design over a full crank revolution sampled at ``samples`` evenly spaced angles
    (accuracy of located angles about 360/samples deg before interpolation).

    With ``kinematics_result`` (one design over a full revolution sampled evenly, as
    :func:`~machdyn.linkage.kinematics.crank_angles` makes it, at a crank speed that does not vanish) the
    diagnostics are sized to that request: no kinematics is computed again. The result is kept with the
    (immutable) mechanism, so asking again costs nothing.

    With ``crank_range = (start, stop)`` [rad] (a partial turn; the crank turns from ``start`` to ``stop``)
    everything is said of that range only: dead and limit positions inside it, strokes and transmission-angle
    extremes over it, no time ratio (it needs a full turn; ``time_ratio`` is None and a note says so).
    """
    if mech.design_count is not None:
        raise InputError(
            f"diagnose works on one design at a time; mechanism '{mech.name}' has {mech.design_count} "
            "variants (use mech.take_designs(i))."
        )
    window = _window(crank_range)
    if kinematics_result is not None:
        return _diagnose(mech, _revolution(kinematics_result), window)
    key = ("diagnostics", int(samples), window)
    if key not in mech._derived:
        full = ("diagnostics", int(samples), None)
        if full in mech._derived and window is not None:
            kin = mech._derived[("diagnostics.kinematics", int(samples))]
        else:
            kin = kinematics(mech, crank_angles(samples), 1.0, 0.0, on_fail="mask")
            mech._derived[("diagnostics.kinematics", int(samples))] = kin
        mech._derived[key] = _diagnose(mech, kin, window)
    return mech._derived[key]


def _window(crank_range) -> tuple[float, float] | None:
    """(start, span) [rad] of a partial crank range, span in (0, 2*pi); None for a full turn or more."""
    if crank_range is None:
        return None
    start, stop = (float(x) for x in crank_range)
    if not (np.isfinite(start) and np.isfinite(stop)):
        raise InputError(f"crank_range must be two finite angles [rad]; got {crank_range!r}.")
    lo, span = min(start, stop), abs(stop - start)
    if span >= 2 * np.pi * (1.0 - 1e-9):
        return None
    return (float(lo % (2 * np.pi)), float(span))


def in_window(angles, window: tuple[float, float] | None) -> np.ndarray:
    """True where crank ``angles`` [rad] lie in ``window`` = (start, span) (all True for None)."""
    a = np.asarray(angles, dtype=float)
    if window is None:
        return np.ones(a.shape, dtype=bool)
    start, span = window
    tol = 1e-9
    return ((a - start) % (2 * np.pi) <= span + tol) | ((a - start) % (2 * np.pi) >= 2 * np.pi - tol)


def _revolution(kin: Kinematics) -> Kinematics:
    phi = np.asarray(kin.crank_angle, dtype=float)
    n = phi.size
    if (kin.mechanism.design_count is not None or phi.ndim != 1 or n < 4 or np.ndim(kin.assembled) != 1
            or not is_full_turn(phi)):
        raise InputError(
            "Diagnostics from a kinematics result need one design over a full revolution sampled evenly "
            f"(crank_angles(n)); got crank angles of shape {phi.shape} and results of shape {kin.shape}."
        )
    if not np.all(np.asarray(kin.speed) != 0.0):
        raise InputError("Diagnostics from a kinematics result need a crank speed that does not vanish.")
    return kin


def _diagnose(mech: Mechanism, kin: Kinematics, window: tuple[float, float] | None = None) -> Diagnostics:
    phi = np.asarray(kin.crank_angle, dtype=float)
    samples = phi.size
    assembled = np.asarray(kin.assembled)
    inside = in_window(phi, window)
    ok_full = assembled & ~singular(kin.dyad_reports, kin.shape)
    ok = ok_full & inside
    warnings = []
    ranges = angle_ranges(phi, assembled & inside)
    gaps = angle_ranges(phi, ~assembled & inside)
    kind = grashof_type(mech)
    if gaps:
        text = format_ranges(gaps)
        warnings.append(f"The linkage cannot assemble for crank angles {text}" + (f" ({kind})." if kind else "."))
    # Dead positions are located over the whole turn (a range may end right at one) and kept if inside.
    full_ranges = angle_ranges(phi, assembled)
    dead = _dead_positions(phi, kin.dyad_reports, assembled, ok_full,
                           full_ranges if angle_ranges(phi, ~assembled) else [])
    dead = [d for d in dead if bool(in_window(d, window))]
    t_min, t_max = np.inf, -np.inf
    per_dyad: list[tuple[float, float] | None] = []
    closest = (np.inf, 0.0)  # (angle to a dead position: min(mu, 180 deg - mu) [rad], crank angle [rad])
    for rep in kin.dyad_reports:
        mu_all = np.asarray(rep.transmission, dtype=float)
        if mu_all.shape == phi.shape:
            margin = np.where(ok & np.isfinite(mu_all), worst_of(mu_all, mu_all), np.inf)
            if margin.size and np.isfinite(margin.min()) and margin.min() < closest[0]:
                closest = (float(margin.min()), float(phi[int(np.argmin(margin))]))
        mu = np.asarray(rep.transmission)[ok]
        mu = mu[np.isfinite(mu)]
        per_dyad.append((float(mu.min()), float(mu.max())) if mu.size else None)
        if mu.size:
            t_min, t_max = min(t_min, float(mu.min())), max(t_max, float(mu.max()))
    transmission_angles = {}
    for d, extremes in zip(mech.dyads, per_dyad, strict=False):
        for out in d.outputs():
            if extremes is not None:
                transmission_angles[out.body] = extremes
    step = 2 * np.pi / samples
    limits, strokes = [], {}
    for body, values, rates in _outputs(mech, kin):
        for i, angle in _zero_crossings(phi, rates, ok):
            # A sign change of the rate right at a dead position is a branch change, not a limit position.
            if all(abs(_angle_between(angle, d)) > 2.5 * step for d in dead):
                limits.append(LimitPosition(body, angle, float(values[i])))
        v = values[ok & np.isfinite(values)]
        if v.size:
            rotating = body not in {b for b, kind in output_bodies(mech) if kind == "slide"}
            strokes[body] = float(full_turn_stroke(v.max() - v.min(), step)) if rotating else float(v.max() - v.min())
    full_turn = window is None and bool(ok.all())
    # A sign change of the rate right at a dead position is a branch change, not a limit position.
    clear = ok & np.array([all(abs(_angle_between(a, d)) > 2.5 * step for d in dead) for a in phi], dtype=bool)
    time_ratios = {}
    for body, _values, rates in _outputs(mech, kin):
        if body in strokes:
            ratio = float(time_ratio(phi, rates, clear, full_turn)[0])
            time_ratios[body] = ratio if np.isfinite(ratio) else None
    first = time_ratios.get(limits[0].body) if limits else None  # the first output with a limit position
    if window is not None:
        warnings.append(
            f"The diagnostics describe the crank range {np.degrees(window[0]):.1f}°–"
            f"{np.degrees(window[0] + window[1]):.1f}° only; the strokes are the travel over that range and "
            "no time ratio is given (it needs a full turn)."
        )
    if np.isfinite(t_min) and min(np.degrees(t_min), 180.0 - np.degrees(t_max)) < MIN_GOOD_TRANSMISSION_DEG:
        warnings.append(
            f"The transmission angle ranges {np.degrees(t_min):.1f}°–{np.degrees(t_max):.1f}°; below "
            f"{MIN_GOOD_TRANSMISSION_DEG:.0f}° (or above {180 - MIN_GOOD_TRANSMISSION_DEG:.0f}°) force "
            "transmission is poor"
            + (f"; nearest a dead position (0° or 180°) at crank angle {np.degrees(closest[1]) % 360:.1f}°, "
               f"{np.degrees(closest[0]):.1f}° away: the joint forces grow as 1/sin of that angle."
               if np.isfinite(closest[0]) else ".")
        )
    if dead:
        warnings.append(
            "Dead (toggle) positions at crank angles "
            + ", ".join(f"{np.degrees(a):.1f}°" for a in sorted(dead))
            + "; forces are unbounded there."
        )
    return Diagnostics(kind, ranges, gaps, sorted(dead), limits, strokes, first,
                       float(t_min), float(t_max), warnings, window, time_ratios, transmission_angles)


def time_ratio(phi, rates, ok, full_cycle: bool) -> np.ndarray:
    """Quick-return ratio of an output for each design: the longer over the shorter crank interval between the
    output's two limit positions (where its rate changes sign), located by linear interpolation between
    neighbouring crank angles (Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed., §1.9).
    The one implementation: the diagnostics of a run and the population evaluator both call it.

    Parameters
    ----------
    phi : array_like
        Crank angles [rad], M of them, evenly spaced for a full cycle.
    rates : array_like
        The output's velocity (designs x M) [m/s or rad/s]; a 1-D array is one design.
    ok : array_like of bool
        Where each design is regular (designs x M); a limit position needs both neighbours regular.
    full_cycle : bool
        True when ``phi`` covers one full turn without its end point (the last angle neighbours the first).

    Returns
    -------
    numpy.ndarray
        The ratio [-] per design, >= 1; NaN unless the crank turns fully and the output has exactly two
        limit positions.

    Examples
    --------
    >>> import numpy as np
    >>> phi = np.arange(360) * np.pi / 180
    >>> rates = np.cos(phi - 0.3)                  # limit positions 180 deg apart: no quick return
    >>> float(time_ratio(phi, rates, np.ones(360, bool), True)[0])
    1.0
    """
    phi = np.asarray(phi, dtype=float)
    rates = np.atleast_2d(np.asarray(rates, dtype=float))
    ok = np.broadcast_to(np.atleast_2d(ok), rates.shape)
    nxt = np.roll(rates, -1, axis=1)
    ok_pair = ok & np.roll(ok, -1, axis=1)
    if not full_cycle:
        ok_pair[:, -1] = False
    with np.errstate(invalid="ignore"):
        cross = ok_pair & ((rates == 0.0) | (rates * nxt < 0.0))
    count = cross.sum(axis=1)
    step = np.mod(np.roll(phi, -1) - phi, 2 * np.pi)
    with np.errstate(all="ignore"):
        frac = np.where(rates == 0.0, 0.0, rates / (rates - nxt))
    where = np.broadcast_to(phi, rates.shape) + np.broadcast_to(step, rates.shape) * frac
    i1 = np.argmax(cross, axis=1)
    rest = cross.copy()
    rest[np.arange(len(i1)), i1] = False
    i2 = np.argmax(rest, axis=1)
    rows = np.arange(len(i1))
    forward = np.mod(where[rows, i2] - where[rows, i1], 2 * np.pi)
    back = 2 * np.pi - forward
    with np.errstate(all="ignore"):
        ratio = np.maximum(forward, back) / np.minimum(forward, back)
    return np.where((count == 2) & full_cycle, ratio, np.nan)


def _angle_between(a: float, b: float) -> float:
    return float((a - b + np.pi) % (2 * np.pi) - np.pi)


def _dead_positions(phi, reports, assembled, ok, assembly_ranges) -> list[float]:
    """Crank angles [rad] of dead (toggle) positions: where a dyad determinant changes sign (PRP), where it
    touches zero without changing sign (a change-point linkage; a local minimum of |det| within ten sampling
    steps of zero), and the ends of the assembly ranges, where the dyad that cannot close is in line."""
    step = 2 * np.pi / len(phi)
    found: list[float] = []
    for rep in reports:
        det = np.broadcast_to(rep.det, np.shape(phi))
        found += [angle for _, angle in _zero_crossings(phi, det, ok)]
        mag = np.abs(np.where(assembled, det, np.inf))
        left, right = np.roll(mag, 1), np.roll(mag, -1)
        touching = assembled & (mag <= left) & (mag <= right) & (mag < 10 * step)
        found += [float(a) for a in phi[touching]]
    for start, end in assembly_ranges:
        found += [start, end]
    unique: list[float] = []
    for angle in sorted(a % (2 * np.pi) for a in found):
        if all(abs(_angle_between(angle, u)) > 2.5 * step for u in unique):
            unique.append(angle)
    return unique


def full_turn_stroke(stroke, step: float):
    """The angular stroke [rad] of an output over the sampled crank angles, with an output that turns fully given
    its full turn, 2 pi: sampled every ``step`` [rad] of the crank, a lever that turns once per turn of the crank
    spans only 2 pi less about one step between its first and last sample (359.8 deg at 1 deg steps), so a span
    within 2.5 steps of 2 pi is a full turn, not a stroke just short of it."""
    stroke = np.asarray(stroke, dtype=float)
    return np.where(stroke >= 2 * np.pi - 2.5 * step, 2 * np.pi, stroke)


def _outputs(mech: Mechanism, kin):
    """The outputs whose limit positions matter with their values and rates: sliders (travel [m]) and rockers
    pinned to the ground (angle [rad])."""
    for body, kind in output_bodies(mech):
        if kind == "slide":
            sm = kin.slide(body)
            yield body, np.asarray(sm.s), np.asarray(sm.v)
        else:
            b = kin.body(body)
            angle = np.asarray(b.angle)
            good = np.isfinite(angle)
            unwrapped = np.full(angle.shape, np.nan)
            unwrapped[good] = np.unwrap(angle[good])  # NaN (not assembled) would spread through unwrap
            yield body, unwrapped, np.asarray(b.omega)
