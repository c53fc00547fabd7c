"""The checks a cam designer makes: pressure angle against a limit, radius of curvature against the roller
(undercutting, a pointed cam), a flat face's width, and the smallest base circle meeting the limits.

Limits (defaults):

* pressure angle: 30 deg for a translating roller follower, 35 deg for an oscillating one. Norton, *Design of
  Machinery*, 5th ed., §8.6: "keep the pressure angle between about +/-30 deg" for a translating follower (the
  side load jams its guide); an oscillating follower has no sliding guide and tolerates more, Rothbart, *Cam
  Design Handbook*, ch. 6, up to 45 deg; 35 deg is the lower, conservative end of the 35-45 deg range;
* radius of curvature: the convex radius of the pitch curve must exceed the roller radius (else the cam is
  undercut, the follower does not follow the program), and Norton §8.6 recommends |rho_min| >= 2 to 3 r_r;
  a flat face needs rho = R_b + s + a > 0 everywhere (else the cam has a cusp: Uicker, Pennock & Shigley, *Theory
  of Machines and Mechanisms*, 4th ed., eq 6.28);
* face width of a flat follower: the contact point runs over v_min <= x <= v_max (Norton eq 8.38); the face must
  span that range plus a margin on each side.

The smallest base circle meeting a pressure-angle limit is found directly for a translating roller follower:
tan phi = (v - e)/(d + s) <= tan phi_max at every angle needs d >= max(|v - e|/tan phi_max - s), and
R_b = sqrt(d^2 + e^2) - r_r (from Norton eq 8.31). For a flat face, rho >= rho_min needs
R_b >= max(rho_min - s - a) (from Uicker eq 6.28). An oscillating follower's limit is met by bisection on R_b.

Every check is judged on the exact extremes of each segment (:mod:`machdyn.cams.exact`), never on the sampled
profile alone: the cam's ``positions`` set the drawing, the CSV and the DXF, not what passes. The smallest base
circles are found over angles that sample every segment's own interval (:func:`~machdyn.cams.exact.segment_angles`).
A segment shorter than the spacing of the drawn profile is named in a warning: the drawn profile and the DXF
step over it.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..errors import InputError
from .exact import extremes, segment_angles
from .followers import MAX_CAM_SIZE, Follower
from .profile import Profile, profile
from .program import Program

#: Rim speed [m/s] above which a steel cam disc on its shaft bursts: the hoop stress at the bore of a rotating
#: disc with a small bore, (3 + nu)/4 rho v^2 (Budynas & Nisbett, *Shigley's Mechanical Engineering Design*, 8th
#: ed., §3-15, rotating rings, eq 3-55 with r_i -> 0; Timoshenko & Goodier, *Theory of Elasticity*, §32), reaches
#: 2 GPa, the strength of the strongest through-hardened cam steels, with rho = 7850 kg/m^3 and nu = 0.3.
BURST_RIM_SPEED = float(np.sqrt(4.0 * 2.0e9 / ((3.0 + 0.3) * 7850.0)))


def rim_speed_failure(outer_radius: float, speed: float) -> str | None:
    """The failed check of a cam whose rim, ``outer_radius`` [m] at ``speed`` [rad/s], runs faster than
    :data:`BURST_RIM_SPEED` (a speed or a size no steel cam survives), else None."""
    rim = outer_radius * speed
    if rim <= BURST_RIM_SPEED:
        return None
    return (f"the cam's rim runs at {rim:.4g} m/s (outer radius {outer_radius * 1e3:.4g} mm at "
            f"{speed * 30 / np.pi:.4g} rpm): a steel cam on its shaft bursts above about {BURST_RIM_SPEED:.0f} m/s "
            "(hoop stress (3 + nu)/4 rho v^2 at the bore reaching 2 GPa); the speed or the size is not physical")


def default_pressure_limit(follower: Follower) -> float:
    """The default pressure-angle limit [rad]: 30 deg translating, 35 deg oscillating (see the module)."""
    return float(np.radians(30.0 if follower.motion == "translating" else 35.0))


@dataclass(frozen=True)
class CamChecks:
    """Results of the checks (SI): the largest |pressure angle| and where, the smallest convex radius of
    curvature of the pitch curve and of the cam surface and where, the flat face's contact range, the smallest
    base circles meeting the limits, and the failed checks and warnings as sentences."""

    max_pressure_angle: float
    max_pressure_angle_at: float
    pressure_angle_limit: float
    min_pitch_radius: float
    min_surface_radius: float
    min_radius_at: float
    face_min: float
    face_max: float
    face_width: float
    min_base_radius_pressure: float
    min_base_radius_curvature: float
    failed: tuple[str, ...]
    warnings: tuple[str, ...]


def min_base_radius_pressure(prog: Program, follower: Follower, limit: float, theta) -> float:
    """The smallest base-circle radius R_b [m] for which |phi| <= limit [rad] at every cam angle theta [rad].

    Translating roller or knife edge: direct (module docstring); flat face: 0 (phi = 0); oscillating: bisection
    between the smallest assembling base circle and one where the limit is met.
    """
    if not 0 < limit < np.pi / 2:
        raise InputError(f"cam.checks.pressure_angle_limit must lie between 0 and 90 deg; got "
                         f"{np.degrees(limit):g} deg.")
    m = prog.svaj(theta)
    if follower.contact == "flat":
        return 0.0
    r = follower.roller_radius
    if follower.motion == "translating":
        e = follower.offset
        d = float(np.max(np.abs(m.v - e) / np.tan(limit) - m.s))
        d = max(d, 0.0)
        return max(float(np.hypot(d, e)) - r, 0.0)

    def worst(rb: float) -> float:
        f = replace(follower, base_radius=rb)
        return float(np.max(np.abs(profile(prog, f, theta).pressure_angle)))

    lo_rp = abs(follower.pivot_distance - follower.arm_length)
    hi_rp = follower.pivot_distance + follower.arm_length
    lo = max(lo_rp - r, 0.0) * (1 + 1e-9) + 1e-12
    hi = hi_rp - r - 1e-9 * hi_rp
    grid = np.linspace(lo, hi, 64)
    ok = [rb for rb in grid if rb > 0 and worst(rb) <= limit]
    if not ok:
        return float("nan")
    upper = ok[0]
    k = int(np.searchsorted(grid, upper))
    lower = grid[k - 1] if k > 0 else lo
    for _ in range(60):
        mid = 0.5 * (lower + upper)
        if mid > 0 and worst(mid) <= limit:
            upper = mid
        else:
            lower = mid
    return float(upper)


def min_base_radius_curvature(prog: Program, follower: Follower, theta, factor: float = 1.0) -> float:
    """The smallest base-circle radius R_b [m] for which the convex radius of curvature of the pitch curve is at
    least ``factor`` x the roller radius (roller) or the cam's is > 0 (flat face, direct; knife edge > 0)."""
    m = prog.svaj(theta)
    if follower.contact == "flat":
        return max(float(np.max(-(m.s + m.a))), 0.0)
    need = factor * follower.roller_radius

    def ok(rb: float) -> bool:
        p = profile(prog, replace(follower, base_radius=rb), theta)
        rho = p.pitch_curvature_radius
        return bool(np.all((rho <= 0) | (rho > need)))

    lo = 1e-6 * max(prog.stroke, 1e-3)
    hi = max(follower.base_radius, lo * 2)
    if follower.motion == "translating":
        lo = max(lo, abs(follower.offset) - follower.roller_radius + 1e-9)
        hi = max(hi, lo * 2)
    else:
        lo = max(lo, abs(follower.pivot_distance - follower.arm_length) - follower.roller_radius + 1e-9)
        hi = min(follower.pivot_distance + follower.arm_length - follower.roller_radius - 1e-9, max(hi, 2 * lo))
    grow = 0
    while not ok(hi):
        hi *= 2.0
        grow += 1
        if grow > 40 or (follower.motion == "oscillating") or hi + follower.roller_radius > MAX_CAM_SIZE:
            return float("nan")  # none within the plausible sizes of a cam
    if ok(lo):
        return float(lo)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if ok(mid):
            hi = mid
        else:
            lo = mid
    return float(hi)


def check_cam(prof: Profile, prog: Program, *, pressure_limit: float | None = None, curvature_factor: float = 1.0,
              face_margin: float = 0.0, face_width: float | None = None) -> CamChecks:
    """Every check on a computed profile. ``pressure_limit`` [rad] (default :func:`default_pressure_limit`),
    ``curvature_factor`` [-] the required rho_min / r_r (1: no undercut; Norton recommends 2-3), ``face_margin``
    [m] added on each side of a flat face's contact range, ``face_width`` [m] the face's actual width to check
    (centred on the follower's path)."""
    f = prof.follower
    th = prof.svaj.theta
    limit = default_pressure_limit(f) if pressure_limit is None else float(pressure_limit)
    failed: list[str] = []
    warnings: list[str] = []
    ext = extremes(prog, f)
    phi, phi_at = ext.max_pressure_angle, ext.max_pressure_angle_at
    if phi > limit:
        failed.append(f"pressure angle {np.degrees(phi):.4g} deg at cam angle {np.degrees(phi_at):.4g} deg exceeds "
                      f"the limit {np.degrees(limit):.4g} deg (a larger base circle, a longer rise or an offset "
                      "lowers it)")
    rho_p, at = ext.min_convex_radius, ext.max_convex_curvature_at
    rho_s = rho_p - f.roller_radius if np.isfinite(rho_p) else rho_p
    if f.contact == "flat":
        rho_p = rho_s = ext.min_flat_radius
        at = ext.min_flat_radius_at
        if rho_s <= 0:
            failed.append(f"the cam has a cusp: its radius of curvature R_b + s + a is {rho_s * 1e3:.4g} mm at cam "
                          f"angle {np.degrees(at):.4g} deg (increase the base circle)")
    elif f.contact == "roller":
        if rho_p <= f.roller_radius * curvature_factor:
            what = ("undercut: the roller" if rho_p <= f.roller_radius else
                    f"the roller's radius x {curvature_factor:g} exceeds")
            failed.append(f"{what} radius {f.roller_radius * 1e3:.4g} mm vs the smallest convex radius of "
                          f"curvature of the pitch curve {rho_p * 1e3:.4g} mm at cam angle {np.degrees(at):.4g} deg")
        elif rho_p < 2.0 * f.roller_radius:
            warnings.append(f"the smallest convex radius of curvature of the pitch curve, {rho_p * 1e3:.4g} mm, is "
                            f"less than twice the roller radius {f.roller_radius * 1e3:.4g} mm (Norton recommends "
                            "2-3 x)")
    spacing = 2.0 * np.pi / max(th.size, 1)
    for k, seg in enumerate(prog.segments):
        if seg.motion != "dwell" and seg.duration < 2.0 * spacing:
            warnings.append(f"segment {k + 1} ({seg.motion} over {np.degrees(seg.duration):.4g} deg) is shorter than "
                            f"two steps of the drawn profile ({np.degrees(spacing):.4g} deg): the profile, its CSV "
                            "and DXF step over it (raise cam.positions); the checks judge it exactly")
    lo, hi = ext.contact_min, ext.contact_max
    width = (hi - lo) + 2.0 * face_margin if f.contact == "flat" else 0.0
    if f.contact == "flat" and face_width is not None:
        half = face_width / 2.0
        need = max(abs(hi - f.offset), abs(lo - f.offset)) + face_margin
        if half < need:
            failed.append(f"the flat face, {face_width * 1e3:.4g} mm wide, is too narrow: the contact point runs "
                          f"{need * 1e3:.4g} mm from the follower's axis (face at least {2 * need * 1e3:.4g} mm)")
    grid = segment_angles(prog)
    return CamChecks(
        max_pressure_angle=float(phi), max_pressure_angle_at=float(phi_at), pressure_angle_limit=limit,
        min_pitch_radius=rho_p, min_surface_radius=rho_s, min_radius_at=at, face_min=lo, face_max=hi,
        face_width=width,
        min_base_radius_pressure=min_base_radius_pressure(prog, f, limit, grid),
        min_base_radius_curvature=min_base_radius_curvature(prog, f, grid, curvature_factor),
        failed=tuple(failed), warnings=tuple(warnings),
    )
