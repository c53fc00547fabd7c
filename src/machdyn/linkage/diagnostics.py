"""Diagnostics of a linkage over a crank revolution: where it assembles, the Grashof type of four-bars, dead
(toggle) positions, limit positions and strokes of the outputs, time ratio and transmission-angle extremes.

Sources: Grashof's rule and the transmission angle, Norton, *Design of Machinery*, 5th ed., §2.12 and
§4.10; limit positions and time ratio (quick-return ratio), Uicker, Pennock & Shigley, 5th ed., §1.9.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError
from .kinematics import angle_ranges, crank_angles, format_ranges, kinematics
from .model import GROUND, RPR, RRP, RRR, Mechanism, split_ref

#: Below this transmission angle [deg] force transmission is poor (Norton, §4.10: keep mu >= 40 deg).
MIN_GOOD_TRANSMISSION_DEG = 40.0


def _four_bar_lengths(mech: Mechanism):
    """Crank, coupler, rocker and ground lengths [m] if ``mech`` is a four-bar (one RRR from the crank to the
    ground), else None."""
    if len(mech.dyads) != 1 or not isinstance(mech.dyads[0], RRR):
        return None
    d = mech.dyads[0]
    body_a, pin_a = split_ref(d.pin_a)
    body_b, pin_b = split_ref(d.pin_b)
    if body_a != mech.crank.body or body_b != GROUND:
        return None
    pivot = split_ref(mech.crank.pivot)[1]

    def dist(p, q):
        return np.hypot(np.asarray(p[0]) - q[0], np.asarray(p[1]) - q[1])

    crank = mech.body(mech.crank.body).points
    a, b = mech.body(d.a).points, mech.body(d.b).points
    return (
        dist(crank[pin_a], crank[pivot]),
        dist(a[pin_a], a[d.inner]),
        dist(b[pin_b], b[d.inner]),
        dist(mech.ground[pin_b], mech.ground[pivot]),
    )


def grashof_type(mech: Mechanism):
    """Grashof type of a four-bar: 'crank-rocker', 'double-crank', 'rocker-crank', 'Grashof double-rocker',
    'change-point' or 'non-Grashof triple-rocker' (Norton, §2.12: s + l vs p + q, and which link is shortest).
    None if ``mech`` is not a four-bar; an array of names for design variants."""
    lengths = _four_bar_lengths(mech)
    if lengths is None:
        return None
    links = np.broadcast_arrays(*[np.asarray(v, dtype=float) for v in lengths])
    stack = np.stack(links, axis=-1)
    s, l_ = stack.min(axis=-1), stack.max(axis=-1)
    total = stack.sum(axis=-1)
    pq = total - s - l_
    shortest = stack.argmin(axis=-1)
    names = np.array(["crank-rocker", "rocker-crank", "Grashof double-rocker", "double-crank"])
    # shortest index: 0 crank, 1 coupler, 2 rocker, 3 ground
    grashof = names[np.choose(shortest, [0, 2, 1, 3])]
    tol = 1e-12 * total
    kind = np.where(np.abs(s + l_ - pq) <= tol, "change-point",
                    np.where(s + l_ < pq, grashof, "non-Grashof triple-rocker"))
    return str(kind) if kind.ndim == 0 else kind


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


def _zero_crossings(phi, values, valid):
    """Crank angles [rad] where ``values`` changes sign between neighbouring valid samples (linear
    interpolation), including the wrap from the last sample to the first over a full cycle."""
    out = []
    n = len(phi)
    for i in range(n):
        j = (i + 1) % n
        if j == 0 and not np.isclose((phi[0] - phi[-1]) % (2 * np.pi), 2 * np.pi / n):
            continue
        if not (valid[i] and valid[j]):
            continue
        a, b = values[i], values[j]
        if a == 0.0:
            out.append((i, float(phi[i])))
        elif a * b < 0.0:
            step = (phi[j] - phi[i]) % (2 * np.pi)
            out.append((i, float((phi[i] + step * a / (a - b)) % (2 * np.pi))))
    return out


def diagnose(mech: Mechanism, samples: int = 3600) -> Diagnostics:
    """Assembly ranges, Grashof type, dead and limit positions, strokes, time ratio and transmission-angle
    extremes of one design over a full crank revolution sampled at ``samples`` evenly spaced angles
    (accuracy of located angles about 360/samples deg before interpolation)."""
    if mech.design_count is not None:
        raise InputError(
            f"diagnose works on one design at a time; mechanism '{mech.name}' has {mech.design_count} "
            "variants (use mech.take_designs(i))."
        )
    phi = crank_angles(samples)
    kin = kinematics(mech, phi, 1.0, 0.0, on_fail="mask")
    ok = np.asarray(kin.assembled)
    warnings = []
    ranges = angle_ranges(phi, ok)
    gaps = angle_ranges(phi, ~ok)
    kind = grashof_type(mech)
    if gaps:
        text = format_ranges(gaps)
        warnings.append(f"The linkage cannot assemble for crank angles {text}" + (f" ({kind})." if kind else "."))
    dead = []
    t_min, t_max = np.inf, -np.inf
    for rep in kin.dyad_reports:
        for _, angle in _zero_crossings(phi, rep.det, ok):
            dead.append(angle)
        mu = rep.transmission[ok]
        if mu.size:
            t_min, t_max = min(t_min, float(mu.min())), max(t_max, float(mu.max()))
    limits, strokes = [], {}
    for body, values, rates in _outputs(mech, kin):
        for i, angle in _zero_crossings(phi, rates, ok):
            limits.append(LimitPosition(body, angle, float(values[i])))
        v = values[ok]
        if v.size:
            strokes[body] = float(v.max() - v.min())
    time_ratio = _time_ratio(limits, bool(ok.all()))
    if np.isfinite(t_min) and min(np.degrees(t_min), 180.0 - np.degrees(t_max)) < MIN_GOOD_TRANSMISSION_DEG:
        warnings.append(
            f"The transmission angle ranges {np.degrees(t_min):.1f}°–{np.degrees(t_max):.1f}°; below "
            f"{MIN_GOOD_TRANSMISSION_DEG:.0f}° (or above {180 - MIN_GOOD_TRANSMISSION_DEG:.0f}°) force "
            "transmission is poor."
        )
    if dead:
        warnings.append(
            "Dead (toggle) positions at crank angles "
            + ", ".join(f"{np.degrees(a):.1f}°" for a in sorted(dead))
            + "; forces are unbounded there."
        )
    return Diagnostics(kind, ranges, gaps, sorted(dead), limits, strokes, time_ratio,
                       float(t_min), float(t_max), warnings)


def _outputs(mech: Mechanism, kin):
    """The outputs whose limit positions matter: sliders (travel) and rockers pinned to the ground (angle)."""
    for d in mech.dyads:
        if isinstance(d, RRP) and d.guide.body == GROUND:
            sm = kin.slide(d.b)
            yield d.b, np.asarray(sm.s), np.asarray(sm.v)
        if isinstance(d, RRR | RPR) and split_ref(d.pin_b)[0] == GROUND:
            b = kin.body(d.b)
            yield d.b, np.unwrap(np.asarray(b.angle)), np.asarray(b.omega)


def _time_ratio(limits: list, full_rotation: bool) -> float | None:
    """Quick-return ratio: the longer over the shorter crank interval between the two limit positions of the
    first output (None unless the crank turns fully and the output has exactly two limit positions)."""
    if not full_rotation or not limits:
        return None
    first = [p for p in limits if p.body == limits[0].body]
    if len(first) != 2:
        return None
    forward = (first[1].crank_angle - first[0].crank_angle) % (2 * np.pi)
    back = 2 * np.pi - forward
    return float(max(forward, back) / min(forward, back))
