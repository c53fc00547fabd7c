"""Fuzzing the problem files: every shipped example mutated in many ways, each mutant checked and run.

For every mutant: no traceback; `check` and `run` agree on validity (both exit 2, or neither does); an invalid
file's message names a field of the table that was mutated (or, for a file that is not TOML at all, says so);
a refused file leaves no output folder behind; and no valid file ends in an internal error (exit 4).

The mutants are drawn with a fixed seed, so the run is deterministic; the number of full runs (with the report)
is capped, and the other valid mutants are analysed without writing, to keep the suite's time bounded.
"""

from __future__ import annotations

import copy
import datetime
import json
import math
import random
import tomllib
from pathlib import Path
from typing import Any

import pytest
from typer.testing import CliRunner

from machdyn.cli import EXIT_BAD_INPUT, EXIT_INTERNAL, app
from machdyn.errors import MachdynError
from machdyn.runner import run_problem
from problem_texts import circular_arc_cam, table_cam
from reproductions import example as example_text
from reproductions import replaced

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))
SEED = 20261123
CASES = 400  # spread evenly over the shipped examples (8 a file; the seed set and the table fuzz add theirs)
FULL_RUNS = 40

# ------------------------------------------------------------------------------------ a minimal TOML writer


def _value(v: Any) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, datetime.date):
        return v.isoformat()
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)
    if isinstance(v, list):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{json.dumps(k)} = {_value(x)}" for k, x in v.items()) + "}"
    raise TypeError(type(v))


def to_toml(data: dict[str, Any]) -> str:
    """TOML text of parsed data: top-level scalars, then a [table] per dict, a [[table]] per list of dicts."""
    lines: list[str] = []

    def table(prefix: str, body: dict[str, Any]) -> None:
        plain = {k: v for k, v in body.items() if not _is_table(v)}
        for k, v in plain.items():
            lines.append(f"{json.dumps(k)} = {_value(v)}")
        for k, v in body.items():
            name = f"{prefix}.{json.dumps(k)}" if prefix else json.dumps(k)
            if isinstance(v, dict):
                lines.append(f"\n[{name}]")
                table(name, v)
            elif _is_table(v):
                for item in v:
                    lines.append(f"\n[[{name}]]")
                    table(name, item)

    table("", data)
    return "\n".join(lines) + "\n"


def _is_table(v: Any) -> bool:
    return isinstance(v, dict) or (isinstance(v, list) and bool(v) and all(isinstance(x, dict) for x in v))


# ------------------------------------------------------------------------------------------------ mutants


def _leaves(data: Any, path: tuple = ()) -> list[tuple]:
    out = []
    if isinstance(data, dict):
        for k, v in data.items():
            out.append((*path, k))
            out += _leaves(v, (*path, k))
    elif isinstance(data, list):
        for i, v in enumerate(data):
            if isinstance(v, dict | list):
                out += _leaves(v, (*path, i))
    return out


def _get(data: Any, path: tuple) -> Any:
    for k in path:
        data = data[k]
    return data


def _set(data: Any, path: tuple, value: Any) -> None:
    _get(data, path[:-1])[path[-1]] = value


def _delete(data: Any, path: tuple) -> None:
    del _get(data, path[:-1])[path[-1]]


NUMBERS = ["0", "-1", "1e300", "-1e300", "nan", "inf", "1e-300", "-0"]
UNITS = ["kg", "mm", "rpm", "N", "deg", "s", "Hz", "m^3", "furlong", ""]
TEXT = ["abc", "", "\u202e45 mm", "45\u200b mm", "四十五 mm", "🙂", "1 mm" * 60, "[[[", "{x = 1}", "null"]
NON_STRINGS: list[Any] = [datetime.date(2026, 11, 23), True, -1, 1e308, [], {}, [1, 2, 3], {"a": {"b": 1}}]


def mutants(data: dict[str, Any], text: str, rng: random.Random, count: int,
            within: tuple = ()) -> list[tuple[str, Any, tuple]]:
    """(kind, content, mutated paths) tuples; content is a dict (written as TOML), text or bytes. With ``within``
    (a table's path, e.g. ``("flywheel", "motor")``) only the keys inside that table are mutated."""
    leaves = [p for p in _leaves(data) if p[: len(within)] == within and len(p) > len(within)]
    out: list[tuple[str, Any, tuple]] = []
    for path in leaves:  # every key deleted once
        d = copy.deepcopy(data)
        _delete(d, path)
        out.append(("delete", d, (path,)))
    kinds = ["swap", "unit", "number", "string", "type", "unicode", "nest", "truncate", "binary", "unknown"]
    if within:  # a third of the mutants delete a key of the table, the rest change one
        kinds = [k for k in kinds if k not in ("truncate", "binary")]
        rng.shuffle(out)
        del out[max(1, count // 3):]
    while len(out) < count:
        kind = rng.choice(kinds)
        d = copy.deepcopy(data)
        path = rng.choice(leaves)
        value = _get(d, path)
        if kind == "swap":
            other = rng.choice(leaves)
            if other[: len(path)] == path or path[: len(other)] == other:
                continue
            a, b = copy.deepcopy(_get(d, path)), copy.deepcopy(_get(d, other))
            _set(d, path, b)
            _set(d, other, a)
            out.append(("swap", d, (path, other)))
            continue
        elif kind == "unit" and isinstance(value, str) and " " in value:
            _set(d, path, value.split(" ", 1)[0] + " " + rng.choice(UNITS))
        elif kind == "number" and isinstance(value, str) and " " in value:
            _set(d, path, rng.choice(NUMBERS) + " " + value.split(" ", 1)[1])
        elif kind == "number" and isinstance(value, int | float) and not isinstance(value, bool):
            _set(d, path, rng.choice([0, -1, 10**18, float("nan"), float("inf"), -1e300, 0.5]))
        elif kind == "string":
            _set(d, path, rng.choice(TEXT))
        elif kind == "type":
            _set(d, path, copy.deepcopy(rng.choice(NON_STRINGS)))
        elif kind == "unicode" and isinstance(value, str):
            at = rng.randrange(len(value) + 1)
            _set(d, path, value[:at] + rng.choice(["\u202e", "\u0301", "\x00", "\ufeff", "é", "\u2028"]) + value[at:])
        elif kind == "nest":
            nested: Any = value
            for _ in range(rng.choice([3, 20, 40])):
                nested = [nested]
            _set(d, path, nested)
        elif kind == "truncate":
            out.append(("truncate", text[: rng.randrange(len(text))], ()))
            continue
        elif kind == "binary":
            raw = bytearray(text.encode())
            for _ in range(rng.randint(1, 8)):
                raw.insert(rng.randrange(len(raw)), rng.randrange(256))
            out.append(("binary", bytes(raw), ()))
            continue
        elif kind == "unknown":
            _get(d, path[:-1])[str(path[-1]) + "x"] = value
        else:
            continue
        out.append((kind, d, (path,)))
    return out[:count] if len(out) > count else out


# ------------------------------------------------------------------------------------------------- the test


def _cases() -> list[tuple[str, str, Any, tuple]]:
    rng = random.Random(SEED)
    cases = []
    for example in EXAMPLES:
        text = example.read_text(encoding="utf-8")
        data = tomllib.loads(text)
        for kind, content, path in mutants(data, text, rng, math.ceil(CASES / len(EXAMPLES))):
            cases.append((example.stem, kind, content, path))
    return cases


def _write(tmp: Path, content: Any) -> Path:
    path = tmp / "mutant.toml"
    if isinstance(content, bytes):
        path.write_bytes(content)
    elif isinstance(content, str):
        path.write_text(content, encoding="utf-8")
    else:
        path.write_text(to_toml(content), encoding="utf-8")
    return path


#: The mutants are checked in this many shards (every SHARDS-th mutant each), so that the test runners share them.
SHARDS = 4


def test_at_least_400_mutants_are_drawn_per_run():
    assert len(_cases()) >= CASES


@pytest.mark.parametrize("shard", range(SHARDS))
def test_fuzzed_problem_files(tmp_path, shard):
    cases = list(enumerate(_cases()))[shard::SHARDS]
    runner = CliRunner()
    counts = {"cases": 0, "invalid": 0, "valid": 0, "full runs": 0}
    failures: list[str] = []
    for i, (example, kind, content, path) in cases:
        folder = tmp_path / f"case{i}"
        folder.mkdir()
        file = _write(folder, content)
        out = folder / "out"
        where = f"{example} {kind} {' <-> '.join('.'.join(map(str, p)) for p in path)}"
        checked = runner.invoke(app, ["check", str(file)])
        counts["cases"] += 1
        for res in (checked,):
            if "Traceback" in res.output or res.exit_code == EXIT_INTERNAL:
                failures.append(f"{where}: check crashed: {res.output[-400:]}")
        if checked.exit_code == EXIT_BAD_INPUT:
            counts["invalid"] += 1
            ran = runner.invoke(app, ["run", str(file), "--out", str(out), "--quiet"])
            if ran.exit_code != EXIT_BAD_INPUT:
                failures.append(f"{where}: check refused it but run exited {ran.exit_code}: {ran.output[-300:]}")
            if out.exists():
                failures.append(f"{where}: a refused file left {sorted(p.name for p in out.iterdir())}")
            if "Traceback" in ran.output:
                failures.append(f"{where}: run printed a traceback")
            message = checked.stderr
            if path and kind not in ("nest",):
                roots = {str(p[0]) for p in path}
                if not any(r in message for r in roots) and "TOML" not in message:
                    failures.append(f"{where}: the message does not name {sorted(roots)}: {message[-300:]}")
            elif not path and not any(w in message for w in ("TOML", "UTF-8", "nested", "main table", "problem")):
                failures.append(f"{where}: the message does not say what is wrong: {message[-300:]}")
        elif checked.exit_code == 0:
            counts["valid"] += 1
            if counts["full runs"] < FULL_RUNS // SHARDS:
                counts["full runs"] += 1
                ran = runner.invoke(app, ["run", str(file), "--out", str(out), "--quiet"])
                code = ran.exit_code
                if "Traceback" in ran.output:
                    failures.append(f"{where}: run printed a traceback")
            else:
                try:
                    run_problem(file)
                    code = 0
                except MachdynError as exc:
                    code = EXIT_BAD_INPUT if isinstance(exc, ValueError) else 1
            if code in (EXIT_BAD_INPUT, EXIT_INTERNAL):
                failures.append(f"{where}: check accepted it but run exited {code}")
        else:
            failures.append(f"{where}: check exited {checked.exit_code}: {checked.output[-300:]}")
    print(f"fuzz, shard {shard}: {counts}")  # noqa: T201 - the counts are part of the suite's output
    assert not failures, f"{len(failures)} of {counts['cases']} mutants failed:\n" + "\n".join(failures[:25])


@pytest.mark.parametrize("text", ["x = " + "[" * 500 + "]" * 500, "x = " + "{a = " * 300 + "1" + "}" * 300])
def test_deep_nesting_is_refused_without_a_traceback(tmp_path, text):
    file = tmp_path / "deep.toml"
    file.write_text(text)
    result = CliRunner().invoke(app, ["check", str(file)])
    assert result.exit_code == EXIT_BAD_INPUT and "nested" in result.stderr and "Traceback" not in result.output


# ------------------------------------------------------------------------ the capability tables, one by one

#: table -> the shipped example whose table is mutated (made cheap to run: fewer positions, a short search)
TABLE_BASES: dict[tuple, str] = {
    ("flywheel",): "rotary_screen_drive",
    ("flywheel", "motor"): "compactor_flywheel",
    ("balance",): "slider_crank_balance",
    ("frame",): "tamper_on_tyres",
    ("signals",): "vibration_record",
    ("optimise",): "compactor_optimise",
    ("sweep",): "four_bar_sweep",
}
TABLE_CASES = 14  # mutants per table


def _cheap(data: dict[str, Any]) -> dict[str, Any]:
    data["drive"]["positions"] = min(int(data["drive"].get("positions", 360)), 90)
    if "flywheel" in data:
        data["flywheel"].update(positions=90, start_up=False)
        if data["flywheel"].get("motor", {}).get("kind") == "select":
            data["flywheel"]["motor"].update(kind="induction", rated_power="0.55 kW", rated_speed="1440 rpm")
    if "optimise" in data:
        data["optimise"].update(generations=2, population=6, positions=36)
    if "sweep" in data:
        data["sweep"]["count"] = 4
    return data


def test_fuzzed_capability_tables_check_agrees_with_run(tmp_path):
    """Mutants of each capability table ([flywheel], [flywheel.motor], [balance], [frame], [signals], [optimise],
    [sweep]): a file check refuses is refused by run (exit 2), and a file check accepts runs to 0 or 3, never 1,
    2 or 4."""
    rng = random.Random(SEED + 1)
    runner = CliRunner()
    counts = {"mutants": 0, "refused by both": 0, "accepted by both": 0, "disagreements": 0}
    failures: list[str] = []
    for within, example in TABLE_BASES.items():
        data = _cheap(tomllib.loads((ROOT / "examples" / f"{example}.toml").read_text(encoding="utf-8")))
        for i, (kind, content, path) in enumerate(mutants(data, to_toml(data), rng, TABLE_CASES, within)):
            folder = tmp_path / f"{'_'.join(within)}{i}"
            folder.mkdir()
            file = _write(folder, content)
            where = f"[{'.'.join(within)}] {kind} {' <-> '.join('.'.join(map(str, p)) for p in path)}"
            checked = runner.invoke(app, ["check", str(file)])
            ran = runner.invoke(app, ["run", str(file), "--out", str(folder / "out"), "--quiet"])
            counts["mutants"] += 1
            if checked.exit_code == EXIT_BAD_INPUT and ran.exit_code == EXIT_BAD_INPUT:
                counts["refused by both"] += 1
            elif checked.exit_code == 0 and ran.exit_code in (0, 3):
                counts["accepted by both"] += 1
            else:
                counts["disagreements"] += 1
                failures.append(f"{where}: check {checked.exit_code}, run {ran.exit_code}: {ran.output[-300:]}")
            if "Traceback" in checked.output + ran.output:
                failures.append(f"{where}: a traceback")
    print(f"fuzz of the capability tables: {counts}")  # noqa: T201 - the counts are part of the suite's output
    assert counts["mutants"] >= len(TABLE_BASES) * TABLE_CASES
    assert not failures, f"{len(failures)} of {counts['mutants']} mutants failed:\n" + "\n".join(failures[:25])


# ------------------------------------------------------------------------------ the newer tables, one by one


def _light_press() -> str:
    """The press with its clutch and brake from their geometry, its gear's teeth and its pinion shaft, without the
    flywheel, the single stroke and the parts (whose runs take seconds), at 90 positions."""
    text = example_text("press_brake_clutch")
    text = text[: text.index("[drivetrain.single_stroke]")]
    text = text[: text.index("[flywheel]")] + text[text.index("[drivetrain]"):]
    return replaced(text, "positions = 360", "positions = 90")


#: table -> the problem text whose table is mutated: the tables added since the capability tables above
NEWER_TABLES: dict[tuple, Any] = {
    ("transient",): lambda: example_text("rotary_screen_start_stop"),
    ("hoist",): lambda: example_text("hoist_mine_cage"),
    ("drivetrain", "clutch", "geometry"): _light_press,
    ("drivetrain", "brake", "geometry"): _light_press,
    ("drivetrain", "shafts", 0): _light_press,
    ("drivetrain", "stages", 1, "teeth"): _light_press,
    ("synthesis",): lambda: example_text("synthesis_shaper_slotted_lever"),
    ("cam", "segments", 0): lambda: table_cam("points = [[0.2, 0.06], [0.45, 0.4], [0.7, 0.85]]"),
    ("cam", "segments", 1): lambda: circular_arc_cam().replace("positions = 3600", "positions = 720"),
}
NEWER_CASES = 3  # mutants per table: one key deleted, two changed


def _analysed(file: Path) -> tuple[int, str]:
    """The exit code ``machdyn run`` gives ``file`` (2 bad input, 1 a failed analysis, 4 an internal error), from
    a run that writes nothing; and what it said."""
    try:
        run_problem(file)
    except MachdynError as exc:
        return (EXIT_BAD_INPUT if isinstance(exc, ValueError) else 1), str(exc)
    except Exception as exc:  # noqa: BLE001 - any other exception is the internal error the fuzz looks for
        return EXIT_INTERNAL, f"{type(exc).__name__}: {exc}"
    return 0, ""


def test_fuzzed_newer_tables_check_agrees_with_run(tmp_path):
    """Mutants of the tables added since ([transient], [hoist], a clutch's and a brake's geometry, a shaft's design
    check, a gear stage's teeth, a slotted-lever synthesis, a table cam's and a contour cam's segment): check and
    run refuse the same files (exit 2), a file check accepts never ends in bad input or an internal error, and
    neither prints a traceback."""
    rng = random.Random(SEED + 2)
    runner = CliRunner()
    counts = {"mutants": 0, "refused by both": 0, "accepted by both": 0}
    failures: list[str] = []
    for within, make in NEWER_TABLES.items():
        data = tomllib.loads(make())
        for i, (kind, content, path) in enumerate(mutants(data, to_toml(data), rng, NEWER_CASES, within)):
            folder = tmp_path / f"{'_'.join(map(str, within))}{i}"
            folder.mkdir()
            file = _write(folder, content)
            where = f"[{'.'.join(map(str, within))}] {kind} {' <-> '.join('.'.join(map(str, p)) for p in path)}"
            checked = runner.invoke(app, ["check", str(file)])
            counts["mutants"] += 1
            if checked.exit_code == 0:  # analysed without writing the report, as most valid mutants above
                code, said = _analysed(file)
            else:
                ran = runner.invoke(app, ["run", str(file), "--out", str(folder / "out"), "--quiet"])
                code, said = ran.exit_code, ran.output
            if checked.exit_code == EXIT_BAD_INPUT and code == EXIT_BAD_INPUT:
                counts["refused by both"] += 1
            elif checked.exit_code == 0 and code not in (EXIT_BAD_INPUT, EXIT_INTERNAL):
                counts["accepted by both"] += 1
            else:
                failures.append(f"{where}: check {checked.exit_code}, run {code}: {said[-300:]}")
            if "Traceback" in checked.output + said:
                failures.append(f"{where}: a traceback")
    print(f"fuzz of the newer tables: {counts}")  # noqa: T201 - the counts are part of the suite's output
    assert counts["mutants"] == len(NEWER_TABLES) * NEWER_CASES
    assert not failures, f"{len(failures)} of {counts['mutants']} mutants failed:\n" + "\n".join(failures[:25])
