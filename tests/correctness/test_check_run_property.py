"""The property ``check`` ≡ ``run`` over generated problem files: every file that ``machdyn check`` accepts runs
to exit 0 or fails a design check with exit 3 — never 1 (the analysis failed) or 2 (bad input found late) — and
``check`` itself never crashes. The files are the shipped examples of every kind and capability (kept small),
with one to three quantities scaled by a factor from zero, a sign flip, 1e-6 ... 1e6."""

from __future__ import annotations

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from .generated import BASES, FACTORS, base, quantity_paths, scaled, to_toml
from .helpers import EXAMPLES, invoke


@st.composite
def problem_files(draw):
    name = draw(st.sampled_from(sorted(BASES)))
    data = base(name)
    changes = []
    for _ in range(draw(st.integers(1, 3))):
        path = draw(st.sampled_from(quantity_paths(data)))
        factor = draw(st.sampled_from(FACTORS))
        data = scaled(data, path, factor)
        changes.append(f"{'.'.join(map(str, path))} x {factor:g}")
    return name, to_toml(data), changes


@settings(max_examples=20, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(problem_files())
def test_every_file_check_accepts_runs_to_exit_0_or_3(tmp_path_factory, generated):
    name, text, changes = generated
    folder = tmp_path_factory.mktemp(name)
    path = folder / "problem.toml"
    path.write_text(text, encoding="utf-8")
    for csv in (EXAMPLES / "signals").glob("*.csv"):  # records named relative to the file
        (folder / "signals").mkdir(exist_ok=True)
        (folder / "signals" / csv.name).write_bytes(csv.read_bytes())
    check = invoke(["check", str(path)])
    assert check.code in (0, 2), (name, changes, check)
    if check.code == 0:
        run = invoke(["run", str(path), "--out", str(folder / "out"), "-q"])
        assert run.code in (0, 3), (name, changes, run.code, run.stderr[-600:])
