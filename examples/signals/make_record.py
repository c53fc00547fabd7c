"""Make the test records ``tamper_before.csv`` and ``tamper_after.csv`` beside this script.

They stand in for accelerometer records on the screed frame of ``examples/tamper_on_tyres.toml``: the vertical
acceleration machdyn predicts at the points ``centre``, ``front`` and ``rear`` (before and after balancing),
plus what a real record also holds and the standards' 10-1000 Hz band must remove or tolerate — a 1.5 Hz sway of
the paver (outside the band), a 0.2 m/s^2 offset (sensor bias) and broad-band noise of 0.03 m/s^2 RMS from a
seeded generator. The result is deterministic: running the script again writes the same files.

Run it from the repository root:  python examples/signals/make_record.py
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent
sys.path.insert(0, str(ROOT / "src"))

from machdyn.kinds import kind  # noqa: E402
from machdyn.pipeline import no_step  # noqa: E402
from machdyn.reading import read_problem  # noqa: E402
from machdyn.vibration.study import study_frame  # noqa: E402

SAMPLING_RATE = 2560.0  # Hz: more than twice the band's top of 1000 Hz
DURATION = 2.0  # s: 40 revolutions of the 20 Hz shaft, 20 periods of the band's 10 Hz lower edge
SEED = 20160605


def predicted_study(problem_file: Path):
    """The frame study of the problem file (its [signals] records are not read: they are what this makes)."""
    loaded = read_problem(problem_file)
    outcome = kind(loaded.kind).analyse(loaded.spec, loaded.model, no_step)
    return study_frame(loaded.spec.frame, outcome.mechanism, outcome.analysis)


def record(response, points, direction, rng) -> np.ndarray:
    t = np.arange(round(SAMPLING_RATE * DURATION)) / SAMPLING_RATE
    d = np.array([np.cos(direction), np.sin(direction)])
    columns = [t]
    for p in points.values():
        amplitudes = response.acceleration(p) @ d  # complex amplitude per order
        signal = (np.exp(1j * np.outer(t, response.angular_frequencies)) @ amplitudes).real
        sway = 0.05 * np.sin(2 * np.pi * 1.5 * t)
        columns.append(signal + sway + 0.2 + 0.03 * rng.standard_normal(t.size))
    return np.column_stack(columns)


def write(path: Path, names, rows: np.ndarray, note: str) -> None:
    header = "time [s]," + ",".join(f"{n} [m/s^2]" for n in names)
    lines = [f"# {note}", "# made by examples/signals/make_record.py (deterministic)", header]
    lines += [f"{row[0]:.9f}," + ",".join(f"{v:.6f}" for v in row[1:]) for row in rows]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")


def main() -> None:
    study = predicted_study(ROOT / "examples" / "tamper_on_tyres.toml")
    rng = np.random.default_rng(SEED)
    direction = study.direction if study.direction is not None else np.pi / 2
    for tag, response in (("before", study.before), ("after", study.after)):
        rows = record(response, study.points, direction, rng)
        write(HERE / f"tamper_{tag}.csv", list(study.points), rows,
              f"screed frame, vertical acceleration, {tag} balancing (synthetic test record)")
        print(f"wrote {HERE / f'tamper_{tag}.csv'}: {rows.shape[0]} samples x {rows.shape[1] - 1} channels")


if __name__ == "__main__":
    main()
