"""Peer benchmark: machdyn's four-bar analysis against pylinkage, mechanism and a NumPy closed form.

One crank-rocker four-bar (crank 40, coupler 120, rocker 80, ground 100 mm, crank speed 10 rad/s) is
analysed over 3600 crank angles by every implementation. Each result is checked against the closed form
written below (rocker angle within 1e-9 rad), every implementation is timed (best of several repeats after a
warm-up call), then a sweep of 10,000 four-bar designs x 360 positions measures machdyn's throughput and
peak memory. The script prints a table and, as its very last line, one JSON object.

Nothing is installed here: the peers come from the ``bench`` extra (``make bench`` installs it). A peer that
cannot be imported is reported as such and its numbers are null.

Usage: ``python bench/peers.py [--quick] [--strict]``; see bench/README.md.
"""

from __future__ import annotations

import argparse
import gc
import json
import math
import os
import platform
import resource
import subprocess
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from importlib import metadata
from pathlib import Path
from typing import Any

import numpy as np

ROOT = Path(__file__).resolve().parent.parent

# --- the benchmark case (SI units) -------------------------------------------------------------------------
CRANK, COUPLER, ROCKER, GROUND = 0.040, 0.120, 0.080, 0.100  # m
OMEGA = 10.0  # rad/s, constant crank speed
N_ANGLES = 3600
ANGLE_TOL = 1e-9  # rad, rocker angle agreement required of every implementation
DERIV_RTOL = 1e-8  # relative to the peak value: angular velocity / acceleration agreement (machdyn)
TORQUE_RTOL = 1e-8  # relative to the peak torque: kinetostatics against the energy balance
LINEAR_DENSITY = 1.0  # kg/m, machdyn's default bar mass per length
GRAVITY = (0.0, -9.80665)  # m/s^2, machdyn's default

SWEEP_DESIGNS = 10_000
SWEEP_POSITIONS = 360
SWEEP_SEED = 20240611
SWEEP_SPREAD = 0.10  # +-10 % on every link length
SWEEP_TORQUE_RTOL = 1e-6  # spot check of the sweep's RMS driving torque against the energy balance

# --- targets -----------------------------------------------------------------------------------------------
TARGET_VS_PYLINKAGE = 100.0  # kinematics at least this many times faster than pure-Python pylinkage
TARGET_VS_NUMPY = 2.0  # kinematics within this factor of the NumPy reference
TARGET_KINETOSTATICS_VS_NUMPY = 5.0  # full kinetostatics within this factor of the NumPy kinematics
TARGET_SWEEP_POSITIONS_PER_S = 2.0e6
TARGET_SWEEP_PEAK_MB = 2048.0
TARGET_FUSED_SWEEP_POSITIONS_PER_S = 12.0e6  # fused sweep with full kinetostatics
TARGET_FUSED_KIN_VS_NUMPY = 1.0  # fused kinematics of one cycle at most as long as the NumPy reference
TARGET_FUSED_KINETOSTATICS_VS_NUMPY = 2.0  # fused full kinetostatics within 2x the NumPy kinematics reference
TARGET_ANALYSE_MS = 1.0  # analyse of one design at 360 positions
ANALYSE_POSITIONS = 360
RATIO_REPEATS = 15  # interleaved repeats for the ratio statistics

INSTALL_HINT = "install the bench extra: make bench, or pip install -e '.[bench]'"


def crank_angles(n: int) -> np.ndarray:
    """n crank angles evenly spaced over one revolution, starting at 0."""
    return np.arange(n) * (2.0 * math.pi / n)


# --- NumPy closed-form reference -------------------------------------------------------------------------


def fourbar_reference(
    crank: Any, coupler: Any, rocker: Any, ground: Any, phi: np.ndarray, omega: float, alpha: float = 0.0
) -> dict[str, np.ndarray]:
    """Closed-form kinematics of the four-bar O-A-B-D (O at the origin, D on the x axis at ``ground``).

    Open branch: B lies to the left of the line A -> D. Returns the crank pin A, the joint B, the coupler
    angle theta3 (A -> B), the rocker angle theta4 (D -> B) and their angular velocities and accelerations
    for the crank angle phi turning at ``omega`` with angular acceleration ``alpha``. Link lengths broadcast
    against phi, e.g. shape (designs, 1) against (positions,).
    """
    a, b, c, g = crank, coupler, rocker, ground
    c2, s2 = np.cos(phi), np.sin(phi)
    ax, ay = a * c2, a * s2
    dx, dy = g - ax, -ay  # A -> D
    l2 = dx * dx + dy * dy
    ln = np.sqrt(l2)
    p = (b * b - c * c + l2) / (2.0 * ln)  # along A -> D, from A to the foot of B
    q = np.sqrt(b * b - p * p)  # to the left of A -> D
    ux, uy = dx / ln, dy / ln
    bx = ax + p * ux - q * uy
    by = ay + p * uy + q * ux
    c3, s3 = (bx - ax) / b, (by - ay) / b
    c4, s4 = (bx - g) / c, by / c
    s34 = s3 * c4 - c3 * s4  # sin(theta3 - theta4)
    s42 = s4 * c2 - c4 * s2  # sin(theta4 - theta2)
    s23 = s2 * c3 - c2 * s3  # sin(theta2 - theta3)
    w3 = a * omega * s42 / (b * s34)
    w4 = -a * omega * s23 / (c * s34)
    # a e^{i t2} + b e^{i t3} = g + c e^{i t4}, differentiated twice: b al3 e^{i t3} - c al4 e^{i t4} = -i R
    rx = a * omega * omega * c2 + b * w3 * w3 * c3 - c * w4 * w4 * c4 + a * alpha * s2
    ry = a * omega * omega * s2 + b * w3 * w3 * s3 - c * w4 * w4 * s4 - a * alpha * c2
    al3 = -(rx * c4 + ry * s4) / (b * s34)
    al4 = -(rx * c3 + ry * s3) / (c * s34)
    return {
        "ax": ax, "ay": ay, "bx": bx, "by": by,
        "theta3": np.arctan2(s3, c3), "theta4": np.arctan2(s4, c4),
        "omega3": w3, "omega4": w4, "alpha3": al3, "alpha4": al4,
    }  # fmt: skip


def reference_kinematics() -> tuple[np.ndarray, ...]:
    """The timed NumPy reference: coupler and rocker angles, angular velocities and accelerations."""
    r = fourbar_reference(CRANK, COUPLER, ROCKER, GROUND, crank_angles(N_ANGLES), OMEGA)
    return r["theta3"], r["omega3"], r["alpha3"], r["theta4"], r["omega4"], r["alpha4"]


def reference_driving_torque(
    crank: Any, coupler: Any, rocker: Any, ground: Any, phi: np.ndarray, omega: float
) -> np.ndarray:
    """Driving torque at constant crank speed from the power balance T*omega = dE_kin/dt - P_gravity.

    Bars of LINEAR_DENSITY kg/m with the centre of mass at mid-length and inertia m L^2/12, gravity GRAVITY,
    no external loads: machdyn's defaults for ``four_bar``. Independent of any joint-force computation.
    """
    r = fourbar_reference(crank, coupler, rocker, ground, phi, omega)
    gx, gy = GRAVITY
    c2, s2 = np.cos(phi), np.sin(phi)
    # crank pin A and joint B (rocker turns about D)
    vax, vay = -crank * omega * s2, crank * omega * c2
    aax, aay = -crank * omega * omega * c2, -crank * omega * omega * s2
    c4, s4 = np.cos(r["theta4"]), np.sin(r["theta4"])
    w4, al4 = r["omega4"], r["alpha4"]
    vbx, vby = -rocker * w4 * s4, rocker * w4 * c4
    abx = -rocker * al4 * s4 - rocker * w4 * w4 * c4
    aby = rocker * al4 * c4 - rocker * w4 * w4 * s4
    power = np.zeros(np.broadcast_shapes(np.shape(crank), np.shape(phi)))
    # (mass, com velocity, com acceleration, inertia, omega, alpha) of crank, coupler, rocker
    bodies = (
        (crank, 0.5 * vax, 0.5 * vay, 0.5 * aax, 0.5 * aay, omega, 0.0),
        (coupler, 0.5 * (vax + vbx), 0.5 * (vay + vby), 0.5 * (aax + abx), 0.5 * (aay + aby),
         r["omega3"], r["alpha3"]),
        (rocker, 0.5 * vbx, 0.5 * vby, 0.5 * abx, 0.5 * aby, w4, al4),
    )  # fmt: skip
    for length, vx, vy, ax, ay, w, al in bodies:
        m = LINEAR_DENSITY * length
        inertia = m * length * length / 12.0
        power = power + m * (vx * ax + vy * ay) + inertia * w * al - m * (gx * vx + gy * vy)
    return power / omega


# --- helpers -----------------------------------------------------------------------------------------------


def wrapped_max_diff(x: Any, y: Any) -> float:
    """Largest |x - y| with each difference wrapped into (-pi, pi]."""
    d = np.asarray(x, dtype=float) - np.asarray(y, dtype=float)
    d = np.pi - np.mod(np.pi - d, 2.0 * np.pi)
    return float(np.max(np.abs(d)))


def max_diff(x: Any, y: Any) -> float:
    return float(np.max(np.abs(np.asarray(x, dtype=float) - np.asarray(y, dtype=float))))


def rel_diff(x: Any, y: Any) -> float:
    """Largest |x - y| relative to the peak |y|."""
    y = np.asarray(y, dtype=float)
    return max_diff(x, y) / float(np.max(np.abs(y)))


def best_time_ms(
    fn: Callable[[], Any], *, repeats: int = 7, warmup: int = 1, min_batch_s: float = 0.05
) -> tuple[float, Any]:
    """Best time of one call [ms] over ``repeats`` batches, after ``warmup`` calls; returns it and a result.

    Calls are batched so that each batch lasts at least ``min_batch_s`` (timeit's autorange idea); the
    garbage collector is paused while timing, as timeit does.
    """
    result = None
    for _ in range(warmup):
        result = fn()
    number = 1
    best = math.inf
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        runs = 0
        while runs < repeats:
            start = time.perf_counter()
            for _ in range(number):
                result = fn()
            elapsed = time.perf_counter() - start
            if elapsed < min_batch_s and runs == 0 and number < 1_000_000:
                number *= max(2, min(10, int(min_batch_s / max(elapsed, 1e-9)) + 1))
                continue  # still calibrating the batch size
            best = min(best, elapsed / number)
            runs += 1
    finally:
        if was_enabled:
            gc.enable()
    return best * 1e3, result


def batch_size(fn: Callable[[], Any], min_batch_s: float = 0.02) -> int:
    """Calls per batch so that a batch of ``fn`` lasts at least ``min_batch_s``."""
    fn()
    number = 1
    while True:
        start = time.perf_counter()
        for _ in range(number):
            fn()
        if time.perf_counter() - start >= min_batch_s or number >= 1_000_000:
            return number
        number *= 2


def interleaved_times(fns: dict[str, Callable[[], Any]], repeats: int) -> dict[str, list[float]]:
    """Per repeat, the time of one call [ms] of every function, the functions timed one after the other in
    each repeat (so that a change of machine load affects all of them alike); garbage collector paused."""
    numbers = {k: batch_size(f) for k, f in fns.items()}
    out: dict[str, list[float]] = {k: [] for k in fns}
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        for _ in range(repeats):
            for k, f in fns.items():
                start = time.perf_counter()
                for _ in range(numbers[k]):
                    f()
                out[k].append((time.perf_counter() - start) / numbers[k] * 1e3)
    finally:
        if was_enabled:
            gc.enable()
    return out


def stats(values: list[float]) -> dict[str, float]:
    """min, median and max of ``values``."""
    arr = np.asarray(values, dtype=float)
    return {"min": float(arr.min()), "median": float(np.median(arr)), "max": float(arr.max())}


def ratio_stats(num: list[float], den: list[float]) -> dict[str, float]:
    """min/median/max over repeats of the per-repeat ratio num/den."""
    return stats([a / b for a, b in zip(num, den, strict=True)])


def version_of(dist: str) -> str | None:
    try:
        return metadata.version(dist)
    except metadata.PackageNotFoundError:
        return None


def run_worker(name: str, quick: bool, timeout_s: float = 600.0) -> dict[str, Any]:
    """Run this script as ``--worker name`` in a fresh interpreter; returns its last-line JSON."""
    cmd = [sys.executable, str(Path(__file__).resolve()), "--worker", name] + (["--quick"] if quick else [])
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout_s, check=False)
    except subprocess.TimeoutExpired:
        return {"error": f"timed out after {timeout_s:.0f} s"}
    lines = proc.stdout.strip().splitlines()
    if proc.returncode != 0 or not lines:
        tail = (proc.stderr.strip().splitlines() or ["no output"])[-1]
        return {"error": f"exit status {proc.returncode}: {tail}"}
    return json.loads(lines[-1])


def import_machdyn() -> tuple[Any, str | None]:
    """The machdyn.linkage module, from the installed package or this checkout's src/."""
    try:
        import machdyn.linkage as linkage
    except ImportError:
        src = str(ROOT / "src")
        if src not in sys.path:
            sys.path.insert(0, src)
        sys.modules.pop("machdyn", None)
        try:
            import machdyn.linkage as linkage
        except ImportError as exc:
            return None, f"machdyn.linkage cannot be imported ({exc})"
    missing = [n for n in ("four_bar", "kinematics", "kinetostatics", "sweep") if not hasattr(linkage, n)]
    if missing:
        return None, f"machdyn.linkage does not provide {', '.join(missing)}"
    return linkage, None


# --- results -----------------------------------------------------------------------------------------------


@dataclass
class Row:
    """One timed implementation of the 3600-angle cycle."""

    key: str  # JSON key prefix
    label: str
    call: str  # the API call timed
    ms: float | None = None
    angle_diff: float | None = None  # max |rocker angle - reference| [rad]
    note: str = ""  # short remark shown in the table
    problem: str = ""  # why it was not measured, or what disagrees
    extra: dict[str, Any] = field(default_factory=dict)

    @property
    def angle_ok(self) -> bool | None:
        return None if self.angle_diff is None else self.angle_diff <= ANGLE_TOL


# --- peers -------------------------------------------------------------------------------------------------


def pylinkage_fourbar() -> tuple[Any, Any]:
    """The benchmark four-bar in pylinkage: (linkage, crank). Components: O, D, crank pin A, joint B.

    The crank turns 2 pi / N_ANGLES per step and starts one step back, so the N_ANGLES yielded steps are at
    crank_angles(N_ANGLES). B starts near the open configuration; pylinkage keeps the branch nearest to it.
    """
    from pylinkage.actuators import Crank
    from pylinkage.components import Ground
    from pylinkage.dyads import RRRDyad
    from pylinkage.simulation import Linkage

    step = 2.0 * math.pi / N_ANGLES
    o = Ground(0.0, 0.0, name="O")
    d = Ground(GROUND, 0.0, name="D")
    crank = Crank(anchor=o, radius=CRANK, angular_velocity=step, initial_angle=-step, name="crank")
    bx, by = GROUND + 0.3 * ROCKER, ROCKER  # initial guess for B, above the ground line
    b = RRRDyad(crank.output, d, distance1=COUPLER, distance2=ROCKER, x=bx, y=by, name="B")
    linkage = Linkage([o, d, crank, b], name="crank-rocker")
    linkage.set_input_velocity(crank, omega=OMEGA)
    return linkage, crank


def rocker_motion(b_pos: np.ndarray, b_vel: np.ndarray, b_acc: np.ndarray) -> tuple[np.ndarray, ...]:
    """Rocker angle, angular velocity and acceleration from the position, velocity, acceleration of B."""
    rx, ry = b_pos[:, 0] - GROUND, b_pos[:, 1]
    r2 = rx * rx + ry * ry
    return (
        np.arctan2(ry, rx),
        (rx * b_vel[:, 1] - ry * b_vel[:, 0]) / r2,
        (rx * b_acc[:, 1] - ry * b_acc[:, 0]) / r2,
    )


def time_pylinkage_step(repeats: int) -> tuple[float, dict[str, float]]:
    """Time ``step_with_derivatives`` over one cycle; returns ms and the rocker's max differences."""
    linkage, _ = pylinkage_fourbar()
    start = linkage.get_coords()

    def cycle() -> list[tuple[Any, Any, Any]]:
        linkage.set_coords(start)
        return [(p[3], v[3], a[3]) for p, v, a in linkage.step_with_derivatives(iterations=N_ANGLES)]

    ms, out = best_time_ms(cycle, repeats=repeats, min_batch_s=0.0)
    pos = np.array([o[0] for o in out], dtype=float)
    vel = np.array([o[1] for o in out], dtype=float)
    acc = np.array([o[2] for o in out], dtype=float)
    return ms, compare_rocker(*rocker_motion(pos, vel, acc))


def time_pylinkage_fast(repeats: int) -> tuple[float, dict[str, float]]:
    """Time the numba path ``step_fast_with_kinematics`` (compiled by the warm-up call)."""
    linkage, _ = pylinkage_fourbar()
    start = linkage.get_coords()

    def cycle() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        linkage.set_coords(start)
        return linkage.step_fast_with_kinematics(iterations=N_ANGLES)

    ms, (pos, vel, acc) = best_time_ms(cycle, repeats=repeats)
    return ms, compare_rocker(*rocker_motion(pos[:, 3], vel[:, 3], acc[:, 3]))


def compare_rocker(theta4: Any, omega4: Any, alpha4: Any) -> dict[str, float]:
    ref = fourbar_reference(CRANK, COUPLER, ROCKER, GROUND, crank_angles(N_ANGLES), OMEGA)
    return {
        "angle": wrapped_max_diff(theta4, ref["theta4"]),
        "omega_rel": rel_diff(omega4, ref["omega4"]),
        "alpha_rel": rel_diff(alpha4, ref["alpha4"]),
    }


def bench_pylinkage(quick: bool) -> list[Row]:
    pure = Row("pylinkage", "pylinkage, pure Python", "step_with_derivatives", note="numba hidden")
    step_nb = Row("pylinkage_numba_step", "pylinkage + numba", "step_with_derivatives")
    fast = Row("pylinkage_numba", "pylinkage + numba, fast path", "step_fast_with_kinematics")
    rows = [pure, step_nb, fast]
    version = version_of("pylinkage")
    try:
        import pylinkage  # noqa: F401
        from pylinkage._numba_compat import HAS_NUMBA
    except ImportError as exc:
        for row in rows:
            row.problem = f"pylinkage cannot be imported ({exc}); {INSTALL_HINT}"
        return rows
    for row in rows:
        row.extra["version"] = version

    # pure Python: a fresh interpreter where numba cannot be imported, pylinkage's own fallback
    res = run_worker("pylinkage-pure", quick)
    if "error" in res:
        pure.problem = f"pure-Python run failed: {res['error']}"
    else:
        pure.ms, pure.angle_diff = res["ms"], res["diff"]["angle"]
        pure.extra.update(omega_rel_diff=res["diff"]["omega_rel"], alpha_rel_diff=res["diff"]["alpha_rel"])

    if not HAS_NUMBA:
        for row in (step_nb, fast):
            row.problem = f"numba cannot be imported; {INSTALL_HINT}"
        return rows
    for row, timer, reps in (
        (step_nb, time_pylinkage_step, 3 if quick else 5),
        (fast, time_pylinkage_fast, 7),
    ):
        try:
            row.ms, diff = timer(reps)
        except Exception as exc:  # a peer's failure is reported, not fatal
            row.problem = f"failed: {type(exc).__name__}: {exc}"
            continue
        row.angle_diff = diff["angle"]
        row.extra.update(omega_rel_diff=diff["omega_rel"], alpha_rel_diff=diff["alpha_rel"])
    fast.note = "compiled in warm-up"
    return rows


def bench_mechanism(quick: bool) -> Row:
    row = Row("mechanism", "mechanism", "Mechanism.iterate", note="fsolve per angle")
    os.environ.setdefault("MPLBACKEND", "Agg")
    try:
        from mechanism import Mechanism, Vector, get_joints
    except ImportError as exc:
        row.problem = f"mechanism cannot be imported ({exc}); {INSTALL_HINT}"
        return row
    row.extra["version"] = version_of("mechanism")
    phi = crank_angles(N_ANGLES)
    ref = fourbar_reference(CRANK, COUPLER, ROCKER, GROUND, phi[:1], OMEGA)

    def cycle() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        # the vector loop O->A->B = O->D->B, as in the package's four-bar example
        o, a_, b_, d_ = get_joints("O A B D")
        crank = Vector((o, a_), r=CRANK)
        coupler = Vector((a_, b_), r=COUPLER)
        ground = Vector((o, d_), r=GROUND, theta=0.0, style="ground")
        rocker = Vector((d_, b_), r=ROCKER)

        def loop(x: np.ndarray, i: float) -> np.ndarray:
            return crank(i) + coupler(x[0]) - ground() - rocker(x[1])

        guess = (
            np.array([ref["theta3"][0], ref["theta4"][0]]) + 0.05,  # near the open branch
            np.array([1.0, 1.0]),
            np.array([1.0, 1.0]),
        )
        mech = Mechanism(
            vectors=(crank, coupler, ground, rocker),
            origin=o,
            loops=loop,
            pos=phi,
            vel=np.full(N_ANGLES, OMEGA),
            acc=np.zeros(N_ANGLES),
            guess=guess,
        )
        mech.iterate()
        return rocker.pos.thetas.copy(), rocker.vel.omegas.copy(), rocker.acc.alphas.copy()

    try:
        reps, warm = (1, 0) if quick else (2, 1)
        row.ms, out = best_time_ms(cycle, repeats=reps, warmup=warm, min_batch_s=0.0)
    except Exception as exc:
        row.problem = f"failed: {type(exc).__name__}: {exc}"
        return row
    diff = compare_rocker(*out)
    row.angle_diff = diff["angle"]
    row.extra.update(omega_rel_diff=diff["omega_rel"], alpha_rel_diff=diff["alpha_rel"])
    return row


# --- machdyn -----------------------------------------------------------------------------------------------


def bench_machdyn(linkage: Any, quick: bool) -> tuple[Row, Row, dict[str, Any]]:
    kin_row = Row("kin", "machdyn", "kinematics")
    kst_row = Row("kinetostatics", "machdyn", "kinetostatics", note="+ all joint forces")
    info: dict[str, Any] = {}
    phi = crank_angles(N_ANGLES)
    ref = fourbar_reference(CRANK, COUPLER, ROCKER, GROUND, phi, OMEGA)

    t0 = time.perf_counter()
    mech = linkage.four_bar(CRANK, COUPLER, ROCKER, GROUND)
    info["four_bar_build_ms"] = (time.perf_counter() - t0) * 1e3

    def kin() -> tuple[np.ndarray, ...]:
        k = linkage.kinematics(mech, phi, speed=OMEGA)
        cpl, rck = k.body("coupler"), k.body("rocker")
        return cpl.angle, cpl.omega, cpl.alpha, rck.angle, rck.omega, rck.alpha

    kin_row.ms, out = best_time_ms(kin, repeats=5 if quick else 15)
    kin_row.angle_diff = wrapped_max_diff(out[3], ref["theta4"])
    checks = {
        "coupler_angle_diff_rad": wrapped_max_diff(out[0], ref["theta3"]),
        "coupler_omega_rel_diff": rel_diff(out[1], ref["omega3"]),
        "coupler_alpha_rel_diff": rel_diff(out[2], ref["alpha3"]),
        "rocker_omega_rel_diff": rel_diff(out[4], ref["omega4"]),
        "rocker_alpha_rel_diff": rel_diff(out[5], ref["alpha4"]),
    }
    kin_row.extra.update(checks)
    info["derivatives_ok"] = bool(
        checks["coupler_angle_diff_rad"] <= ANGLE_TOL
        and all(v <= DERIV_RTOL for k, v in checks.items() if k.endswith("rel_diff"))
    )

    def kst() -> Any:
        f = linkage.kinetostatics(mech, phi, speed=OMEGA)
        torque = f.driving_torque
        reactions = [f.joint(j.name if hasattr(j, "name") else j[0]) for j in f.joints]
        return torque, reactions, f

    kst_row.ms, (torque, _, forces) = best_time_ms(kst, repeats=5 if quick else 11)
    kst_row.angle_diff = wrapped_max_diff(forces.kinematics.body("rocker").angle, ref["theta4"])
    torque_ref = reference_driving_torque(CRANK, COUPLER, ROCKER, GROUND, phi, OMEGA)
    info["torque_max_abs_diff_nm"] = max_diff(torque, torque_ref)
    info["torque_rel_diff"] = rel_diff(torque, torque_ref)
    info["torque_ok"] = bool(info["torque_rel_diff"] <= TORQUE_RTOL)
    kst_row.extra["torque_rel_diff"] = info["torque_rel_diff"]
    if not info["derivatives_ok"]:
        kin_row.problem = "coupler angle or angular velocities/accelerations disagree with the reference"
    if not info["torque_ok"]:
        kst_row.problem = "driving torque disagrees with the energy balance"
    return kin_row, kst_row, info


def bench_engines(linkage: Any, quick: bool) -> tuple[list[Row], dict[str, Any]]:
    """The fused engine against the NumPy engine and the NumPy reference: kinematics and full kinetostatics of
    the cycle, and analyse at 360 positions, timed interleaved over repeats (ratios min/median/max)."""
    phi = crank_angles(N_ANGLES)
    ref = fourbar_reference(CRANK, COUPLER, ROCKER, GROUND, phi, OMEGA)
    mech = linkage.four_bar(CRANK, COUPLER, ROCKER, GROUND)
    kin_row = Row("kin_fused", "machdyn, fused", "kinematics(engine='fused')", note="compiled, cached")
    kst_row = Row("kinetostatics_fused", "machdyn, fused", "kinetostatics(engine='fused')",
                  note="+ all joint forces")
    info: dict[str, Any] = {}
    t0 = time.perf_counter()
    try:
        linkage.kinematics(mech, phi, speed=OMEGA, engine="fused")
        linkage.kinetostatics(mech, phi, speed=OMEGA, engine="fused")
    except Exception as exc:  # numba missing or the engine failing: reported, not fatal
        for row in (kin_row, kst_row):
            row.problem = f"fused engine failed: {type(exc).__name__}: {exc}"
        return [kin_row, kst_row], info
    info["first_call_s"] = time.perf_counter() - t0  # compilation, or loading the compiled kernels

    def kin(engine: str) -> Callable[[], tuple[np.ndarray, ...]]:
        def call() -> tuple[np.ndarray, ...]:
            k = linkage.kinematics(mech, phi, speed=OMEGA, engine=engine)
            cpl, rck = k.body("coupler"), k.body("rocker")
            return cpl.angle, cpl.omega, cpl.alpha, rck.angle, rck.omega, rck.alpha
        return call

    def kst(engine: str) -> Callable[[], Any]:
        def call() -> Any:
            f = linkage.kinetostatics(mech, phi, speed=OMEGA, engine=engine)
            return f.driving_torque, [f.joint(j.name) for j in f.joints], f
        return call

    phi_a = linkage.crank_angles(ANALYSE_POSITIONS)

    def analyse_only() -> Any:
        return linkage.analyse(mech, phi_a, OMEGA)

    def analyse_sized() -> Any:
        a = linkage.analyse(mech, phi_a, OMEGA)
        return linkage.diagnose(mech, kinematics_result=a.kinematics)

    def analyse_fresh() -> Any:  # a new mechanism each call: its diagnostics (3600 samples) computed anew
        m = linkage.four_bar(CRANK, COUPLER, ROCKER, GROUND)
        return linkage.analyse(m, phi_a, OMEGA).diagnostics

    fns = {"numpy_ref": reference_kinematics, "kin_numpy": kin("numpy"), "kin_fused": kin("fused"),
           "kst_numpy": kst("numpy"), "kst_fused": kst("fused"), "analyse": analyse_only,
           "analyse_sized": analyse_sized, "analyse_fresh": analyse_fresh}
    times = interleaved_times(fns, 5 if quick else RATIO_REPEATS)
    info["times_ms"] = {k: stats(v) for k, v in times.items()}
    info["ratios"] = {
        "kin_fused_over_numpy_ref": ratio_stats(times["kin_fused"], times["numpy_ref"]),
        "kinetostatics_fused_over_numpy_ref": ratio_stats(times["kst_fused"], times["numpy_ref"]),
        "kin_numpy_over_numpy_ref": ratio_stats(times["kin_numpy"], times["numpy_ref"]),
        "kinetostatics_numpy_over_numpy_ref": ratio_stats(times["kst_numpy"], times["numpy_ref"]),
        "kin_fused_over_kin_numpy": ratio_stats(times["kin_fused"], times["kin_numpy"]),
        "kinetostatics_fused_over_kinetostatics_numpy": ratio_stats(times["kst_fused"], times["kst_numpy"]),
    }
    out = kin("fused")()
    kin_row.ms = info["times_ms"]["kin_fused"]["min"]
    kin_row.angle_diff = wrapped_max_diff(out[3], ref["theta4"])
    kin_row.extra.update(
        coupler_angle_diff_rad=wrapped_max_diff(out[0], ref["theta3"]),
        rocker_omega_rel_diff=rel_diff(out[4], ref["omega4"]),
        rocker_alpha_rel_diff=rel_diff(out[5], ref["alpha4"]),
    )
    torque = kst("fused")()[0]
    torque_ref = reference_driving_torque(CRANK, COUPLER, ROCKER, GROUND, phi, OMEGA)
    kst_row.ms = info["times_ms"]["kst_fused"]["min"]
    kst_row.angle_diff = kin_row.angle_diff
    kst_row.extra["torque_rel_diff"] = rel_diff(torque, torque_ref)
    numpy_torque = linkage.kinetostatics(mech, phi, speed=OMEGA).driving_torque
    info["fused_vs_numpy_torque_rel_diff"] = rel_diff(torque, numpy_torque)
    info["ok"] = bool(kst_row.extra["torque_rel_diff"] <= TORQUE_RTOL
                      and info["fused_vs_numpy_torque_rel_diff"] <= 1e-12
                      and kin_row.extra["rocker_omega_rel_diff"] <= DERIV_RTOL)
    if not info["ok"]:
        kst_row.problem = "the fused engine disagrees with the reference or with the NumPy engine"
    return [kin_row, kst_row], info


def sweep_designs(n: int, seed: int = SWEEP_SEED) -> tuple[np.ndarray, ...]:
    """n four-bar designs, each link +-SWEEP_SPREAD around the benchmark's, all Grashof crank-rockers."""
    rng = np.random.default_rng(seed)
    nominal = np.array([CRANK, COUPLER, ROCKER, GROUND])
    kept: list[np.ndarray] = []
    count = 0
    while count < n:
        links = nominal * rng.uniform(1.0 - SWEEP_SPREAD, 1.0 + SWEEP_SPREAD, size=(2 * n, 4))
        s, longest = links.min(axis=1), links.max(axis=1)
        grashof = s + longest < links.sum(axis=1) - s - longest  # strict: no change-point designs
        crank_shortest = links[:, 0] == s
        good = links[grashof & crank_shortest]
        kept.append(good)
        count += len(good)
    links = np.concatenate(kept)[:n]
    return links[:, 0], links[:, 1], links[:, 2], links[:, 3]


def sweep_worker(quick: bool, engine: str = "numpy") -> dict[str, Any]:
    """Runs in its own process so that its peak resident memory is the sweep's alone."""
    linkage, error = import_machdyn()
    if error:
        return {"error": error}
    n = 1_000 if quick else SWEEP_DESIGNS
    crank, coupler, rocker, ground = sweep_designs(n)
    phi = crank_angles(SWEEP_POSITIONS)
    mech = linkage.four_bar(crank, coupler, rocker, ground)
    warm = linkage.four_bar(crank[:50], coupler[:50], rocker[:50], ground[:50])
    t0 = time.perf_counter()
    linkage.sweep(warm, phi, speed=OMEGA, engine=engine)  # for "fused": compiles or loads the kernel
    warm_s = time.perf_counter() - t0
    rss_before_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    runs: list[float] = []
    result = None
    for _ in range(1 if quick else (2 if engine == "numpy" else 5)):
        result = None
        gc.collect()
        t0 = time.perf_counter()
        result = linkage.sweep(mech, phi, speed=OMEGA, engine=engine)
        runs.append(time.perf_counter() - t0)
    best = min(runs)
    peak_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0  # Linux: KiB
    assembled = np.asarray(result.assembled)
    # spot check: RMS driving torque of a few designs against the energy balance in NumPy
    idx = np.linspace(0, n - 1, 20).astype(int)
    t_ref = reference_driving_torque(
        crank[idx, None], coupler[idx, None], rocker[idx, None], ground[idx, None], phi, OMEGA
    )
    rms_ref = np.sqrt(np.mean(t_ref * t_ref, axis=1))
    rms = np.asarray(result.rms_driving_torque)[idx]
    return {
        "engine": engine,
        "warmup_s": warm_s,
        "runs_s": runs,
        "designs": n,
        "positions": SWEEP_POSITIONS,
        "seconds": best,
        "positions_per_s": n * SWEEP_POSITIONS / best,
        "peak_mb": peak_mb,
        "rss_before_mb": rss_before_mb,
        "all_assembled": bool(assembled.all()),
        "rms_torque_rel_diff": float(np.max(np.abs(rms - rms_ref) / np.abs(rms_ref))),
    }


def pylinkage_pure_worker(quick: bool) -> dict[str, Any]:
    """pylinkage with numba made unimportable: its pure-Python fallback, as without numba installed."""
    sys.modules["numba"] = None  # type: ignore[assignment]  # any 'import numba' now raises ImportError
    from pylinkage._numba_compat import HAS_NUMBA

    if HAS_NUMBA:
        return {"error": "numba could not be hidden from pylinkage"}
    ms, diff = time_pylinkage_step(repeats=2 if quick else 5)
    return {"ms": ms, "diff": diff}


# --- report ------------------------------------------------------------------------------------------------


def ratio(num: float | None, den: float | None) -> float | None:
    return None if num is None or den is None or den == 0 else num / den


def fmt(x: float | None, spec: str) -> str:
    return "—" if x is None else format(x, spec)


def print_report(rows: list[Row], kin_ms: float | None, sweep: dict[str, Any], targets: list[tuple],
                 engines: dict[str, Any], fused_sweep: dict[str, Any]) -> None:
    from rich.console import Console
    from rich.markup import escape
    from rich.table import Table

    console = Console(width=132)
    yes_no = {None: "—", True: "yes", False: "NO"}
    cycle = Table(
        title=f"Four-bar 40/120/80/100 mm, {N_ANGLES} crank angles, ω = {OMEGA:g} rad/s: "
        "best time per cycle after a warm-up call",
        title_justify="left",
    )
    cycle.add_column("implementation", no_wrap=True)
    cycle.add_column("call", no_wrap=True)
    cycle.add_column("ms / cycle", justify="right")
    cycle.add_column("time ÷ machdyn kin", justify="right")
    cycle.add_column("max |Δθ4| rad", justify="right")
    cycle.add_column(f"≤ {ANGLE_TOL:g}", justify="center")
    cycle.add_column("note", no_wrap=True)
    for r in rows:
        cycle.add_row(
            r.label,
            r.call,
            fmt(r.ms, ".3f"),
            fmt(ratio(r.ms, kin_ms), ".2f") + ("×" if r.ms is not None and kin_ms else ""),
            fmt(r.angle_diff, ".1e"),
            yes_no[r.angle_ok],
            r.note if not r.problem else "see below",
        )
    console.print(cycle)

    sw = Table(
        title=f"machdyn sweep with full kinetostatics: links ±{SWEEP_SPREAD:.0%}, Grashof crank-rockers",
        title_justify="left",
    )
    for col in ("designs", "positions", "best time s", "positions / s", "peak RSS MB", "all assembled"):
        sw.add_column(col, justify="right")
    sw.add_column("engine")
    for run in (sweep, fused_sweep):
        if "error" not in run:
            sw.add_row(
                f"{run['designs']:,}",
                str(run["positions"]),
                f"{run['seconds']:.3f}",
                f"{run['positions_per_s']:,.0f}",
                f"{run['peak_mb']:.0f}",
                yes_no[run["all_assembled"]],
                run.get("engine", ""),
            )
        else:
            sw.add_row("—", "—", "—", "—", "—", "—", "—")
    console.print(sw)

    if engines.get("ratios"):
        et = Table(title="Engines: time ratios per interleaved repeat (min / median / max)", title_justify="left")
        et.add_column("ratio")
        for col in ("min", "median", "max"):
            et.add_column(col, justify="right")
        for key, st in engines["ratios"].items():
            et.add_row(key, *(f"{st[c]:.2f}" for c in ("min", "median", "max")))
        for key, st in engines["times_ms"].items():
            et.add_row(f"{key} [ms]", *(f"{st[c]:.3f}" for c in ("min", "median", "max")))
        console.print(et)

    tt = Table(title="Targets", title_justify="left")
    tt.add_column("target")
    tt.add_column("measured", justify="right")
    tt.add_column("required", justify="right")
    tt.add_column("met", justify="center")
    for name, measured, required, met in targets:
        tt.add_row(name, measured, required, {None: "n/a", True: "yes", False: "NO"}[met])
    console.print(tt)

    problems = [f"{r.label} {r.call}: {r.problem}" for r in rows if r.problem]
    if "error" in sweep:
        problems.append(f"machdyn sweep: {sweep['error']}")
    if "error" in fused_sweep:
        problems.append(f"machdyn fused sweep: {fused_sweep['error']}")
    for line in problems:
        console.print(f"[bold red]not measured or failed[/]: {escape(line)}", highlight=False)
    console.file.flush()


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    quick_help = "fewer repeats and a 1,000-design sweep (smoke test)"
    parser.add_argument("--quick", action="store_true", help=quick_help)
    parser.add_argument("--strict", action="store_true", help="exit non-zero when a target is missed")
    parser.add_argument("--worker", choices=("pylinkage-pure", "sweep", "sweep-fused"), help=argparse.SUPPRESS)
    args = parser.parse_args(argv)

    if args.worker:
        if args.worker == "pylinkage-pure":
            out = pylinkage_pure_worker(args.quick)
        else:
            out = sweep_worker(args.quick, "fused" if args.worker == "sweep-fused" else "numpy")
        print(json.dumps(out))
        return 0

    t_start = time.perf_counter()
    ref_row = Row("numpy_ref", "NumPy closed form", "in this script", note="reference")
    ref_row.ms, _ = best_time_ms(reference_kinematics, repeats=5 if args.quick else 15)
    ref_row.angle_diff = 0.0
    numpy_ms = ref_row.ms

    linkage, machdyn_error = import_machdyn()
    info: dict[str, Any] = {}
    if linkage is None:
        kin_row = Row("kin", "machdyn", "kinematics", problem=str(machdyn_error))
        kst_row = Row("kinetostatics", "machdyn", "kinetostatics", problem=str(machdyn_error))
        sweep: dict[str, Any] = {"error": str(machdyn_error)}
        fused_sweep: dict[str, Any] = {"error": str(machdyn_error)}
        engine_rows, engines = [], {}
    else:
        kin_row, kst_row, info = bench_machdyn(linkage, args.quick)
        engine_rows, engines = bench_engines(linkage, args.quick)
        sweep = run_worker("sweep", args.quick)
        fused_sweep = run_worker("sweep-fused", args.quick)

    peer_rows = bench_pylinkage(args.quick)
    mech_row = bench_mechanism(args.quick)
    rows = [ref_row, kin_row, kst_row, *engine_rows, *peer_rows, mech_row]

    by_key = {r.key: r for r in rows}
    kin_ms, kst_ms = kin_row.ms, kst_row.ms
    pl_ms = by_key["pylinkage"].ms
    nb_fast_ms, nb_step_ms = by_key["pylinkage_numba"].ms, by_key["pylinkage_numba_step"].ms
    nb_best = min((x for x in (nb_fast_ms, nb_step_ms) if x is not None), default=None)
    sweep_ok = "error" not in sweep

    def check(value: float | None, ok: Callable[[float], bool]) -> bool | None:
        return None if value is None else bool(ok(value))

    r_pl, r_nb = ratio(pl_ms, kin_ms), ratio(nb_best, kin_ms)
    r_np, r_kst = ratio(kin_ms, numpy_ms), ratio(kst_ms, numpy_ms)
    pps = sweep.get("positions_per_s")
    peak = sweep.get("peak_mb")
    met = {
        "kin_vs_pylinkage": check(r_pl, lambda r: r >= TARGET_VS_PYLINKAGE),
        "kin_vs_pylinkage_numba": check(r_nb, lambda r: r > 1.0),
        "kin_vs_numpy_ref": check(r_np, lambda r: r <= TARGET_VS_NUMPY),
        "kinetostatics_vs_numpy_ref": check(r_kst, lambda r: r <= TARGET_KINETOSTATICS_VS_NUMPY),
        "sweep_throughput": check(pps, lambda v: v >= TARGET_SWEEP_POSITIONS_PER_S),
        "sweep_memory": check(peak, lambda v: v < TARGET_SWEEP_PEAK_MB),
    }
    ratios = engines.get("ratios", {})
    times_ms = engines.get("times_ms", {})
    fused_pps = fused_sweep.get("positions_per_s")
    r_fk = ratios.get("kin_fused_over_numpy_ref", {}).get("median")
    r_fks = ratios.get("kinetostatics_fused_over_numpy_ref", {}).get("median")
    analyse_ms = times_ms.get("analyse", {}).get("median")
    met.update({
        "fused_sweep_throughput": check(fused_pps, lambda v: v >= TARGET_FUSED_SWEEP_POSITIONS_PER_S),
        "fused_kin_vs_numpy_ref": check(r_fk, lambda r: r <= TARGET_FUSED_KIN_VS_NUMPY),
        "fused_kinetostatics_vs_numpy_ref": check(r_fks, lambda r: r <= TARGET_FUSED_KINETOSTATICS_VS_NUMPY),
        "analyse_360_ms": check(analyse_ms, lambda v: v < TARGET_ANALYSE_MS),
    })
    targets = [
        (
            "kinematics vs pure-Python pylinkage",
            f"{fmt(r_pl, '.0f')}× faster",
            f"≥ {TARGET_VS_PYLINKAGE:.0f}×",
            met["kin_vs_pylinkage"],
        ),
        (
            "kinematics vs pylinkage with numba (faster of its two)",
            f"{fmt(r_nb, '.2f')}× faster",
            "> 1×",
            met["kin_vs_pylinkage_numba"],
        ),
        (
            "kinematics / NumPy reference",
            f"{fmt(r_np, '.2f')}×",
            f"≤ {TARGET_VS_NUMPY:g}×",
            met["kin_vs_numpy_ref"],
        ),
        (
            "kinetostatics / NumPy kinematics reference",
            f"{fmt(r_kst, '.2f')}×",
            f"≤ {TARGET_KINETOSTATICS_VS_NUMPY:g}×",
            met["kinetostatics_vs_numpy_ref"],
        ),
        (
            f"sweep {sweep.get('designs', SWEEP_DESIGNS):,} designs × {SWEEP_POSITIONS} positions",
            f"{fmt(pps, ',.0f')} pos/s",
            f"≥ {TARGET_SWEEP_POSITIONS_PER_S:,.0f} pos/s",
            met["sweep_throughput"],
        ),
        (
            "sweep peak memory (RSS of its process)",
            f"{fmt(peak, '.0f')} MB",
            f"< {TARGET_SWEEP_PEAK_MB:.0f} MB",
            met["sweep_memory"],
        ),
        (
            f"fused sweep {fused_sweep.get('designs', SWEEP_DESIGNS):,} designs × {SWEEP_POSITIONS} positions",
            f"{fmt(fused_pps, ',.0f')} pos/s",
            f"≥ {TARGET_FUSED_SWEEP_POSITIONS_PER_S:,.0f} pos/s",
            met["fused_sweep_throughput"],
        ),
        (
            "fused kinematics / NumPy reference (median)",
            f"{fmt(r_fk, '.2f')}×",
            f"≤ {TARGET_FUSED_KIN_VS_NUMPY:g}×",
            met["fused_kin_vs_numpy_ref"],
        ),
        (
            "fused kinetostatics / NumPy kinematics reference (median)",
            f"{fmt(r_fks, '.2f')}×",
            f"≤ {TARGET_FUSED_KINETOSTATICS_VS_NUMPY:g}×",
            met["fused_kinetostatics_vs_numpy_ref"],
        ),
        (
            f"analyse at {ANALYSE_POSITIONS} positions (median; diagnostics not read)",
            f"{fmt(analyse_ms, '.3f')} ms",
            f"< {TARGET_ANALYSE_MS:g} ms",
            met["analyse_360_ms"],
        ),
    ]

    accuracy = {r.key: r.angle_ok for r in rows}
    accuracy_ok = all(v is not False for v in accuracy.values())
    sweep_torque_ok = sweep_ok and sweep["rms_torque_rel_diff"] <= SWEEP_TORQUE_RTOL
    machdyn_checks_ok = linkage is not None and info.get("derivatives_ok") and info.get("torque_ok")
    sweep_checks_ok = sweep_ok and sweep["all_assembled"] and sweep_torque_ok
    fused_ok = "error" not in fused_sweep and fused_sweep["all_assembled"] and (
        fused_sweep["rms_torque_rel_diff"] <= SWEEP_TORQUE_RTOL) and engines.get("ok", False)
    sweep_checks_ok = bool(sweep_checks_ok and fused_ok)
    machdyn_checks_ok = bool(machdyn_checks_ok and sweep_checks_ok)

    sweep_runs = {k: stats(v["runs_s"]) for k, v in (("numpy", sweep), ("fused", fused_sweep)) if "runs_s" in v}
    engines["sweep_runs_s"] = sweep_runs
    if "numpy" in sweep_runs and "fused" in sweep_runs:  # throughput ratio over every pair of runs
        engines["ratios"]["sweep_numpy_time_over_fused_time"] = stats(
            [a / b for a in sweep["runs_s"] for b in fused_sweep["runs_s"]])
    print_report(rows, kin_ms, sweep, targets, engines, fused_sweep)

    sweep_headline = ("seconds", "positions_per_s", "peak_mb")  # top-level keys already
    result: dict[str, Any] = {
        "kin_ms": kin_ms,
        "kinetostatics_ms": kst_ms,
        "pylinkage_ms": pl_ms,
        "pylinkage_numba_ms": nb_fast_ms,
        "pylinkage_numba_step_ms": nb_step_ms,
        "mechanism_ms": mech_row.ms,
        "numpy_ref_ms": numpy_ms,
        "sweep_positions_per_s": pps,
        "sweep_seconds": sweep.get("seconds"),
        "sweep_peak_mb": peak,
        "sweep_designs": sweep.get("designs"),
        "sweep_positions": SWEEP_POSITIONS,
        "max_abs_diff_rad": kin_row.angle_diff,
        "kinetostatics_max_abs_diff_rad": kst_row.angle_diff,
        "pylinkage_max_abs_diff_rad": by_key["pylinkage"].angle_diff,
        "pylinkage_numba_max_abs_diff_rad": by_key["pylinkage_numba"].angle_diff,
        "pylinkage_numba_step_max_abs_diff_rad": by_key["pylinkage_numba_step"].angle_diff,
        "mechanism_max_abs_diff_rad": mech_row.angle_diff,
        "angle_tol_rad": ANGLE_TOL,
        "ratio_pylinkage_over_kin": r_pl,
        "ratio_pylinkage_numba_over_kin": r_nb,
        "ratio_kin_over_numpy_ref": r_np,
        "ratio_kinetostatics_over_numpy_ref": r_kst,
        "fused_sweep_positions_per_s": fused_pps,
        "fused_sweep_seconds": fused_sweep.get("seconds"),
        "fused_sweep_peak_mb": fused_sweep.get("peak_mb"),
        "engines": engines,
        "targets_met": met,
        "all_targets_met": all(v is True for v in met.values()),
        "accuracy_ok": accuracy_ok,
        "machdyn_checks_ok": machdyn_checks_ok,
        "checks": {
            **{f"{r.key}_{k}": v for r in rows for k, v in r.extra.items() if k != "version"},
            **{f"machdyn_{k}": v for k, v in info.items()},
            **{f"sweep_{k}": v for k, v in sweep.items() if k not in sweep_headline},
            **{f"fused_sweep_{k}": v for k, v in fused_sweep.items() if k not in sweep_headline},
        },
        "problems": {
            **{r.key: r.problem for r in rows if r.problem},
            **({"sweep": sweep["error"]} if not sweep_ok else {}),
            **({"fused_sweep": fused_sweep["error"]} if "error" in fused_sweep else {}),
        },
        "versions": {
            "python": platform.python_version(),
            "numpy": np.__version__,
            "machdyn": version_of("machdyn"),
            "pylinkage": version_of("pylinkage"),
            "numba": version_of("numba"),
            "mechanism": version_of("mechanism"),
        },
        "cpus": os.cpu_count(),
        "quick": args.quick,
        "runtime_s": round(time.perf_counter() - t_start, 1),
    }
    sys.stdout.flush()
    print(json.dumps(result))
    if not accuracy_ok or not machdyn_checks_ok:
        return 1
    if args.strict and not result["all_targets_met"]:
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
