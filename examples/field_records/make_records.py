"""Make the test records ``original.csv``, ``trial_1.csv`` and ``trial_2.csv`` beside this script.

They stand in for a two-plane field balancing of a fan: a rigid rotor (35 kg, transverse inertia 2.4 kg m^2 about
its centre of mass at z = 0.45 m) on two spring-damper bearings at z = 0 and 0.9 m, running at 1485 rpm, with an
unknown unbalance of 24 g at 160 mm in plane 1 (z = 0.1 m) and 15 g in plane 2 (z = 0.8 m). Each record holds a
once-per-revolution pulse (a 5 V keyphasor, 3 % of a revolution wide) and the velocity at both bearings [mm/s]
with a 0.3 mm/s offset, a small 2x component and seeded broad-band noise. Trial runs: 20 g at 0 deg in plane 1,
then 25 g at 90 deg in plane 2 (angles from the mark against rotation). The result is deterministic.

Run it from the repository root:  python examples/field_records/make_records.py
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
SPEED = 1485 * np.pi / 30  # rad/s
RATE, SECONDS, SEED = 2048.0, 1.0, 20261124
PLANES, BEARINGS, RADIUS = (0.1, 0.8), (0.0, 0.9), 0.16
UNBALANCE = (0.024 * np.exp(1j * np.radians(250.0)), 0.015 * np.exp(1j * np.radians(40.0)))  # kg, against rotation


def response(masses) -> np.ndarray:
    """Complex velocity amplitudes [m/s] at the bearings of the rigid rotor for masses [kg] at RADIUS in PLANES."""
    k, c, m, j, zg = np.array([3.0e6, 2.2e6]), np.array([1500.0, 1100.0]), 35.0, 2.4, 0.45
    zb = np.array(BEARINGS) - zg
    kk = np.array([[k.sum(), (k * zb).sum()], [(k * zb).sum(), (k * zb**2).sum()]])
    cc = np.array([[c.sum(), (c * zb).sum()], [(c * zb).sum(), (c * zb**2).sum()]])
    mm = np.diag([m, j])
    u = [w * RADIUS for w in masses]
    f = SPEED**2 * np.array([sum(u), sum(ui * (z - zg) for ui, z in zip(u, PLANES, strict=True))])
    q = np.linalg.solve(kk + 1j * SPEED * cc - SPEED**2 * mm, f)
    return 1j * SPEED * (q[0] + q[1] * zb)


def write(name: str, masses, rng) -> None:
    t = np.arange(int(RATE * SECONDS)) / RATE
    angle = SPEED * t + 0.7  # the mark passes the keyphasor at angle 0 (mod 2 pi)
    key = np.where(np.mod(angle, 2 * np.pi) < 0.03 * 2 * np.pi, 5.0, 0.0)
    v = response(masses) * 1e3  # mm/s
    # a mass at angle a against rotation passes the sensor when the shaft angle is a: phase lag a, cos(angle - a)
    cols = [np.abs(vi) * np.cos(angle - np.angle(vi)) + 0.3 + 0.2 * np.cos(2 * angle + i)
            + rng.normal(0.0, 0.05, t.size) for i, vi in enumerate(v)]
    lines = ["# two-plane field balancing of a fan: synthetic test record made by make_records.py (deterministic)",
             "time [s],key [V],drive_end [mm/s],free_end [mm/s]"]
    lines += [f"{ti:.6f},{ki:.1f},{a:.5f},{b:.5f}" for ti, ki, a, b in zip(t, key, *cols, strict=True)]
    (HERE / name).write_text("\n".join(lines) + "\n", encoding="utf-8")


def main() -> None:
    rng = np.random.default_rng(SEED)
    write("original.csv", UNBALANCE, rng)
    write("trial_1.csv", (UNBALANCE[0] + 0.020, UNBALANCE[1]), rng)
    write("trial_2.csv", (UNBALANCE[0], UNBALANCE[1] + 0.025j), rng)


if __name__ == "__main__":
    main()
