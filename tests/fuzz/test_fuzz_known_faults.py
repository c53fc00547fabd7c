"""The fuzz's seed set: every fault an adversarial pass found, run through ``machdyn check`` and ``machdyn run``
before the generated files (this module sorts, and so runs, before test_fuzz_problem_files.py).

Each seed is a reproduction of :mod:`reproductions` (the same text its own regression test checks in words), with
the folder it runs in where that is part of the fault (a planted list of outputs, a folder that looks like an
exploration's store, a private file named as a record). The property, for every seed: no traceback and no internal
error; ``check`` and ``run`` agree — both refuse the file as bad input (exit 2), or ``check`` accepts it and the run
ends in a result (0), a failed design check (3) or an operational refusal (1, only where the folder is the fault);
each seed ends in the class its fault was fixed to; and no file of the user's is changed or echoed.
"""

from __future__ import annotations

import json
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import pytest
from typer.testing import CliRunner

from machdyn.cli import EXIT_BAD_INPUT, EXIT_INTERNAL, app
from machdyn.outputs import MANIFEST
from problem_texts import four_bar
from reproductions import (
    SECRET,
    compactor_derived,
    empty_speed_fractions,
    fast_cam,
    huge_base_radius,
    parts_column,
    parts_objective,
    press_with_brake,
    private_record,
    shaft_column,
    shaft_objective,
    stalling_compactor,
    steep_rise,
    swapped_strengths,
    synthesis,
    tiny_cam_segments,
    tiny_trial,
    vibration_reference,
)

#: The user's own files of a project folder (what a planted list of outputs named to be deleted).
OWN = {"README.md": "# my project\n", "setup.py": "print('setup')\n"}


def _planted_manifest(folder: Path) -> dict[str, str]:
    """The user's files beside the problem file, and a list of outputs that names them and the problem file."""
    for name, text in OWN.items():
        (folder / name).write_text(text)
    (folder / MANIFEST).write_text(json.dumps([*OWN, "problem.toml"]))
    return dict(OWN)


def _look_alike_store(folder: Path) -> dict[str, str]:
    """A folder named as the exploration's store that holds someone's data, not an exploration's."""
    store = folder / "out" / "sweep.parquet"
    store.mkdir(parents=True)
    (store / "part-000000.parquet").write_text("someone's data, not an exploration's")
    return {"out/sweep.parquet/part-000000.parquet": "someone's data, not an exploration's"}


def _private_file(folder: Path) -> dict[str, str]:
    (folder / ".env").write_text(f"{SECRET}\nSECOND=line\n")
    return {".env": f"{SECRET}\nSECOND=line\n"}


EXPLORATION = four_bar("seed", positions=36) + '''
[sweep]
method = "sobol"
samples = 8
seed = 3
partition = 8

[[sweep.quantities]]
parameter = "mechanism.crank.length"
start = "30 mm"
stop = "50 mm"

[[sweep.quantities]]
parameter = "drive.speed"
start = "5 rad/s"
stop = "15 rad/s"
'''


@dataclass(frozen=True)
class Seed:
    """A reproduction: its problem text, the folder it needs (the files it plants, returned by name and text to be
    found unchanged), the output folder (relative to the problem's) and the exit codes of check and run."""

    name: str
    text: Callable[[], str]
    codes: tuple[int, int]
    prepare: Callable[[Path], dict[str, str]] | None = None
    out: str = "out"


SEEDS = [
    Seed("planted_list_of_outputs", lambda: four_bar("rotor"), (0, 0), _planted_manifest, out="."),
    Seed("folder_that_looks_like_a_store", lambda: EXPLORATION, (0, 1), _look_alike_store),
    Seed("private_file_named_as_a_field_record", private_record, (2, 2), _private_file),
    Seed("vibration_channel_as_the_phase_reference", vibration_reference, (2, 2)),
    Seed("near_singular_influence_matrix", tiny_trial, (2, 2)),
    Seed("rise_of_30_mm_over_0.3_deg", steep_rise, (0, 3)),
    Seed("base_radius_of_1e9_m", huge_base_radius, (2, 2)),
    Seed("cam_at_1e9_rpm", fast_cam, (0, 3)),
    Seed("ultimate_strength_below_the_endurance_limit", swapped_strengths, (2, 2)),
    Seed("brake_that_cannot_stop_the_load", lambda: press_with_brake("2000 N*m"), (2, 2)),
    Seed("motor_that_stalls_against_a_damper", stalling_compactor, (0, 3)),
    Seed("empty_conveyor_speed_fractions", empty_speed_fractions, (2, 2)),
    Seed("derived_formula_that_overflows", lambda: compactor_derived("*".join(["1e12"] * 30) + " * l"), (2, 2)),
    Seed("derived_formula_that_divides_by_zero", lambda: compactor_derived("2000 * 0.1 / (l - l)"), (2, 2)),
    Seed("cam_segment_of_1e-300_deg", tiny_cam_segments, (2, 2)),
    Seed("synthesis_of_a_reciprocal_across_zero", lambda: synthesis("reciprocal", "[-1.0, 2.0]"), (2, 2)),
    Seed("synthesis_over_a_nan_range", lambda: synthesis("log10", "[nan, 2.0]"), (2, 2)),
    Seed("shaft_bearing_typo_in_a_sweep_column", lambda: shaft_column("shaft.bearing.frnt.peak"), (2, 2)),
    Seed("shaft_frame_point_typo_in_a_sweep_column",
         lambda: shaft_column("shaft.frame.point.nowhere.rms_velocity"), (2, 2)),
    Seed("shaft_bearing_typo_in_an_objective", lambda: shaft_objective("shaft.bearing.frnt.peak"), (2, 2)),
    Seed("undeclared_bearing_in_a_sweep_column", lambda: parts_column("parts.bearing.Q.rating_life"), (2, 2)),
    Seed("undeclared_pin_in_an_objective", lambda: parts_objective("parts.pin.D.peak_shear_stress"), (2, 2)),
]


@pytest.mark.parametrize("seed", SEEDS, ids=[s.name for s in SEEDS])
def test_the_seed_set_check_agrees_with_run(tmp_path, seed):
    folder = tmp_path / "project"
    folder.mkdir()
    kept = seed.prepare(folder) if seed.prepare is not None else {}
    problem = folder / "problem.toml"
    text = seed.text()
    problem.write_text(text, encoding="utf-8")
    runner = CliRunner()
    checked = runner.invoke(app, ["check", str(problem)])
    ran = runner.invoke(app, ["run", str(problem), "--out", str(folder / seed.out), "-q"])
    said = checked.output + ran.output
    assert "Traceback" not in said and EXIT_INTERNAL not in (checked.exit_code, ran.exit_code), said[-600:]
    assert (checked.exit_code == EXIT_BAD_INPUT) == (ran.exit_code == EXIT_BAD_INPUT), said[-600:]
    assert (checked.exit_code, ran.exit_code) == seed.codes, said[-600:]
    assert problem.read_text(encoding="utf-8") == text
    assert {name: (folder / name).read_text() for name in kept} == kept
    assert SECRET not in said
