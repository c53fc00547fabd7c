"""Benchmark: cam analysis of 360 positions, machdyn against pylinkage's cam module and the ``mechanism`` package's
``Cam`` on the same cam, and designs per second for a population of cams.

The cam: a cycloidal rise of 20 mm over 120 deg, a dwell to 180 deg, a cycloidal fall to 300 deg and a dwell, on a
40 mm base circle with a radial knife edge (pylinkage's profile is the knife-edge radius R_b + s; its pressure angle
is that of the cam surface r(theta)). Both compute the follower displacement and the pressure angle at 360 cam
angles; agreement is the largest difference of each. ``mechanism``'s ``Cam`` (PyPI ``mechanism``) computes S, V, A
and J of its three laws at once at a constant speed (here 1 rev/s) and the knife-edge profile (R_b + s) e^(i theta);
agreement is the largest difference of S, V, A and of the profile's radius. machdyn computes the profile, both radii
of curvature and the checks besides. The population: N cams with random base radius, lift and rise angle, each
analysed in full (profile, pressure angle, curvature, smallest base circles), one after the other; and N cams of one
program shape with random base radius, roller, offset and lift analysed at once as arrays
(``machdyn.cams.population``: pressure angle, curvature, smallest base circle).

Usage: ``python bench/cams.py [--quick] [--repeats N]``. The last line printed is one JSON object.
"""

from __future__ import annotations

import argparse
import json
import math
import statistics
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src"))

BASE, LIFT = 0.040, 0.020
RISE, DWELL_END, FALL_END = math.radians(120), math.radians(180), math.radians(300)


def _machdyn(theta):
    from machdyn.cams.followers import Follower
    from machdyn.cams.profile import profile
    from machdyn.cams.program import Segment, program

    prog = program([Segment("rise", RISE, LIFT, "cycloidal"), Segment("dwell", DWELL_END - RISE),
                    Segment("return", FALL_END - DWELL_END, LIFT, "cycloidal"),
                    Segment("dwell", 2 * math.pi - FALL_END)])
    return profile(prog, Follower("translating", "knife", BASE), theta)


def _pylinkage(theta):
    from pylinkage.cam import CycloidalMotionLaw, FunctionProfile

    cam = FunctionProfile(motion_law=CycloidalMotionLaw(), base_radius=BASE, total_lift=LIFT, rise_start=0.0,
                          rise_end=RISE, dwell_high_end=DWELL_END, fall_end=FALL_END)
    s = np.array([cam.evaluate(float(t)) - BASE for t in theta])
    phi = np.array([cam.pressure_angle(float(t)) for t in theta])
    return s, phi


def _mechanism(theta):
    from mechanism import Cam

    motion = [("rise", LIFT, math.degrees(RISE)), ("dwell", math.degrees(DWELL_END - RISE)),
              ("fall", LIFT, math.degrees(FALL_END - DWELL_END)), ("dwell", math.degrees(2 * math.pi - FALL_END))]
    cam = Cam(motion=motion, degrees=True, omega=2 * math.pi, h=theta[1] - theta[0])
    motion = cam.cycloidal
    x, y = motion.get_profile(BASE, cam.thetas_r)
    n = theta.size  # np.arange(0, 2 pi, h) may hold one sample more than theta
    return motion.S[:n], motion.V[:n], motion.A[:n], np.hypot(x, y)[:n]


def _time(fn, repeats):
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return out, times


def _population(n, rng):
    from machdyn.cams.checks import check_cam
    from machdyn.cams.followers import Follower
    from machdyn.cams.profile import cam_angles, profile
    from machdyn.cams.program import Segment, program

    th = cam_angles(360)
    bases = rng.uniform(0.03, 0.08, n)
    lifts = rng.uniform(0.005, 0.03, n)
    rises = rng.uniform(60, 150, n)
    worst = []
    for rb, h, rise in zip(bases, lifts, rises, strict=True):
        prog = program([Segment("rise", math.radians(rise), h, "cycloidal"), Segment("dwell", math.radians(30)),
                        Segment("return", math.radians(rise), h, "poly345"),
                        Segment("dwell", math.radians(330 - 2 * rise))])
        prof = profile(prog, Follower("translating", "roller", rb, 0.01), th)
        worst.append(check_cam(prof, prog).max_pressure_angle)
    return np.array(worst)


def _vectorised(n, rng, theta):
    """N cams of one program shape with random base radius, roller, offset and lift, as arrays (no loop)."""
    from machdyn.cams.population import analyse_population
    from machdyn.cams.program import Segment, program

    prog = program([Segment("rise", RISE, LIFT, "cycloidal"), Segment("dwell", DWELL_END - RISE),
                    Segment("return", FALL_END - DWELL_END, LIFT, "cycloidal"),
                    Segment("dwell", 2 * math.pi - FALL_END)])
    return analyse_population(prog, theta, rng.uniform(0.03, 0.08, n), rng.uniform(0.005, 0.015, n),
                              rng.uniform(-0.01, 0.01, n), rng.uniform(0.5, 1.5, n))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--repeats", type=int, default=None)
    args = ap.parse_args()
    repeats = args.repeats or (3 if args.quick else 7)
    theta = np.arange(360) * (2 * math.pi / 360)
    ours, t_ours = _time(lambda: _machdyn(theta), repeats)
    result = {"positions": 360, "machdyn_s": statistics.median(t_ours)}
    try:
        (s_peer, phi_peer), t_peer = _time(lambda: _pylinkage(theta), repeats)
        result |= {"pylinkage_s": statistics.median(t_peer),
                   "speed_ratio": statistics.median(t_peer) / statistics.median(t_ours),
                   "displacement_agreement_m": float(np.max(np.abs(s_peer - ours.svaj.s))),
                   "pressure_angle_agreement_deg": float(np.degrees(np.max(np.abs(np.abs(phi_peer)
                                                                             - np.abs(ours.pressure_angle)))))}
    except ImportError:
        result["pylinkage"] = "not installed"
    try:
        (s_m, v_m, a_m, r_m), t_m = _time(lambda: _mechanism(theta), repeats)
        v_ours, a_ours, _ = ours.svaj.per_second(2 * math.pi)
        result |= {"mechanism_s": statistics.median(t_m),
                   "mechanism_speed_ratio": statistics.median(t_m) / statistics.median(t_ours),
                   "mechanism_displacement_agreement_m": float(np.max(np.abs(s_m - ours.svaj.s))),
                   "mechanism_velocity_agreement_m_s": float(np.max(np.abs(v_m - v_ours))),
                   "mechanism_acceleration_agreement_m_s2": float(np.max(np.abs(a_m - a_ours))),
                   "mechanism_profile_radius_agreement_m": float(np.max(np.abs(
                       r_m - np.hypot(ours.surface[0], ours.surface[1]))))}
    except ImportError:
        result["mechanism"] = "not installed"
    n = 50 if args.quick else 400
    rng = np.random.default_rng(1)
    t0 = time.perf_counter()
    _population(n, rng)
    result |= {"population": n, "designs_per_second": n / (time.perf_counter() - t0)}
    nv = 2_000 if args.quick else 20_000
    _, t_vec = _time(lambda: _vectorised(nv, rng, theta), repeats)
    result |= {"vectorised_population": nv, "vectorised_designs_per_second": nv / statistics.median(t_vec)}
    for k, v in result.items():
        print(f"{k:32s} {v:.6g}" if isinstance(v, float) else f"{k:32s} {v}")  # noqa: T201
    print(json.dumps(result))  # noqa: T201


if __name__ == "__main__":
    main()
