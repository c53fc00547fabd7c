"""Dimensional synthesis against pylinkage on the same tasks, and the time to rank a population by dynamics.

Tasks: Freudenstein three-point function generation, three-pose motion generation and five-pose Burmester
points. For each: solutions per second of machdyn and of pylinkage, and their quality judged the same way (the
largest error at the precision positions; for motion, the share free of defects by machdyn's defect check).
Then: 10,000 quick-return crank-rockers checked, run through the engine and ranked by peak driving torque.

Run: ``python bench/synthesis.py`` (``--quick`` for a smoke test). Prints a table and one JSON line.
"""

from __future__ import annotations

import json
import sys
import time

import numpy as np


def _timed(fn, repeats: int) -> tuple[float, object]:
    best, out = np.inf, None
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def function_generation(n: int) -> dict:
    from pylinkage.synthesis.function_generation import coefficients_to_link_lengths, solve_freudenstein_3_positions

    from machdyn.synthesis.function import freudenstein, output_error

    rng = np.random.default_rng(0)
    tasks = []
    for _ in range(n):
        t2 = np.sort(rng.uniform(0.2, 2.0, 3))
        t4 = np.sort(rng.uniform(2.0, 3.5, 3))
        tasks.append((t2, t4))

    def ours():
        out = []
        for t2, t4 in tasks:
            try:
                out.append(freudenstein(t2, t4, 1.0))
            except ValueError:
                out.append(None)
        return out

    def theirs():
        out = []
        for t2, t4 in tasks:
            try:
                out.append(coefficients_to_link_lengths(*solve_freudenstein_3_positions(list(zip(t2, t4,
                                                                                                   strict=True)))))
            except Exception:  # noqa: BLE001 - pylinkage refuses negative lengths (a link turned by pi)
                out.append(None)
        return out

    t_ours, mine = _timed(ours, 3)
    t_theirs, other = _timed(theirs, 3)
    exact = sum(float(np.max(np.abs(output_error(c, t2, t4)))) < 1e-9 for c, (t2, t4) in zip(mine, tasks, strict=True)
                if c is not None)
    return {"task": "Freudenstein, 3 points", "ours_per_s": n / t_ours, "theirs_per_s": n / t_theirs,
            "ours_solved": sum(c is not None for c in mine), "theirs_solved": sum(c is not None for c in other),
            "tasks": n, "ours_exact_on_one_branch": exact}


def _poses(k: int):
    from machdyn.synthesis.candidate import Candidate

    true = Candidate(kind="four_bar", origin=0j, crank=0.04, coupler=0.12, rocker=0.1, ground=0.13,
                     coupler_point=(0.06, 0.025), branch=1)
    phi = np.radians([10, 60, 110, 170, 240])[:k]
    return true.point(phi), true.coupler_angle(phi)


def motion(n: int) -> dict:
    from pylinkage.synthesis import Pose
    from pylinkage.synthesis.motion_generation import motion_generation

    from machdyn.synthesis.candidate import four_bar_from_points
    from machdyn.synthesis.defects import Targets, check
    from machdyn.synthesis.motion import motion_candidates

    p, t = _poses(3)
    targets = Targets(points=p, coupler_angles=t, scale=0.05)
    t_ours, mine = _timed(lambda: motion_candidates(p, t, count=n), 2)
    poses = [Pose(float(q.real), float(q.imag), float(a)) for q, a in zip(p, t, strict=True)]
    t_theirs, res = _timed(lambda: motion_generation(poses, max_solutions=n, require_grashof=False), 2)
    theirs = []
    for s in res.raw_solutions:
        a0, d0 = complex(*s.ground_pivot_a), complex(*s.ground_pivot_d)
        b1, c1 = complex(*s.crank_pivot_b), complex(*s.coupler_pivot_c)
        theirs.append(four_bar_from_points(a0, b1, c1, d0, p[0], np.zeros(3),
                                           coupler_offset=float(t[0] - np.angle(c1 - b1))))
    ok_ours = sum(check(c, targets).ok for c in mine)
    # pylinkage gives no crank angles: machdyn's closure finds the crank angle of each position
    from dataclasses import replace

    from scipy.optimize import minimize_scalar

    ok_theirs = 0
    phi = np.linspace(0, 2 * np.pi, 720, endpoint=False)
    for c in theirs:
        curve = c.point(phi)
        near = [phi[int(np.nanargmin(np.abs(curve - q)))] for q in p]
        found = [minimize_scalar(lambda x, q=q, c=c: float(np.nan_to_num(abs(c.point(np.array([x]))[0] - q), nan=1.0)),
                                 bounds=(f - 0.01, f + 0.01), method="bounded", options={"xatol": 1e-13}).x
                 for f, q in zip(near, p, strict=True)]
        ok_theirs += check(replace(c, angles=np.array(found)), targets, tolerance=1e-7).ok
    return {"task": "motion, 3 poses", "ours_per_s": len(mine) / t_ours, "theirs_per_s": len(theirs) / t_theirs,
            "ours_solved": len(mine), "theirs_solved": len(theirs), "ours_defect_free": ok_ours,
            "theirs_defect_free": ok_theirs}


def burmester_five() -> dict:
    from pylinkage.synthesis import Pose
    from pylinkage.synthesis.burmester import compute_circle_point_curve

    from machdyn.synthesis.burmester import points_five

    p, t = _poses(5)
    t_ours, mine = _timed(lambda: points_five(p, t), 3)
    poses = [Pose(float(q.real), float(q.imag), float(a)) for q, a in zip(p, t, strict=True)]
    t_theirs, res = _timed(lambda: compute_circle_point_curve(poses), 3)

    def spread(circle, centre):
        moving = p + (circle - p[0]) * np.exp(1j * (t - t[0]))
        r = np.abs(moving - centre)
        return float(np.ptp(r) / r.mean())

    ours_err = max(spread(d.moving_pivot, d.ground_pivot) for d in mine)
    theirs_err = max((spread(complex(c), complex(m)) for c, m in zip(res.circle_curve, res.center_curve,
                                                                      strict=True)), default=float("nan"))
    return {"task": "Burmester, 5 poses", "ours_per_s": len(mine) / t_ours,
            "theirs_per_s": len(res.center_curve) / t_theirs, "ours_solved": len(mine),
            "theirs_solved": len(res.center_curve), "ours_worst_spread": ours_err, "theirs_worst_spread": theirs_err}


def rank(n: int) -> dict:
    from machdyn.synthesis.defects import Targets, check
    from machdyn.synthesis.quick_return import crank_rocker
    from machdyn.synthesis.rank import Drive, evaluate, order

    grid = (np.arange(n // 2) + 0.5) / (n // 2)
    t0 = time.perf_counter()
    cands = [crank_rocker(np.radians(40), 1.3, 0.25, position=float(g), side=s) for s in (1, -1) for g in grid]
    t1 = time.perf_counter()
    psi = np.pi / 2 - np.radians(20)
    targets = Targets(outputs=np.array([psi, psi + np.radians(40)]), scale=0.25)
    reports = [check(c, targets) for c in cands]
    t2 = time.perf_counter()
    values = evaluate(cands, reports, Drive(speed=12.6, linear_density=6.0, load=-60.0, positions=121))
    best = order(values, reports, "peak_torque")[0]
    t3 = time.perf_counter()
    return {"task": f"rank {len(cands)} crank-rockers", "synthesis_s": t1 - t0, "defects_s": t2 - t1,
            "dynamics_and_rank_s": t3 - t2, "total_s": t3 - t0, "best_peak_torque": float(values["peak_torque"][best])}


def main() -> None:
    quick = "--quick" in sys.argv
    rows = [function_generation(200 if quick else 2000), motion(50 if quick else 200), burmester_five(),
            rank(1000 if quick else 10_000)]
    for r in rows[:3]:
        print(f"{r['task']:<24} machdyn {r['ours_per_s']:10.0f} /s ({r['ours_solved']} solutions)   "
              f"pylinkage {r['theirs_per_s']:10.0f} /s ({r['theirs_solved']} solutions)")
    r = rows[3]
    print(f"{r['task']:<24} synthesis {r['synthesis_s']:.2f} s, defects {r['defects_s']:.2f} s, dynamics and "
          f"rank {r['dynamics_and_rank_s']:.2f} s, total {r['total_s']:.2f} s")
    print(json.dumps({"synthesis": rows}, default=float))


if __name__ == "__main__":
    main()
