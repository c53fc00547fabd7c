"""The registry of problem kinds and capabilities: adding a capability is one package and one registry line.

The capability below is the worked example of ``docs/architecture.md``; registering it by one line makes it
reachable from problem files, the check, the run, the summary, results.json and the exit code.
"""

from __future__ import annotations

import re
import sys
import types

import numpy as np
import pytest
from pydantic import Field
from typer.testing import CliRunner

from machdyn import kinds
from machdyn.cli import EXIT_BAD_INPUT, EXIT_CHECKS_FAILED, EXIT_OK, app
from machdyn.pipeline import Capability, Outcome, StageContext
from machdyn.problem.fields import Torque
from machdyn.problem.schema import Spec
from machdyn.reading import load_problem
from machdyn.results.labels import Label
from machdyn.runner import run_problem

FILE = """
[mechanism]
type = "four_bar"
crank = {length = "40 mm", mass = "0.2 kg"}
coupler = {length = "120 mm", mass = "0.5 kg"}
rocker = {length = "80 mm", mass = "0.4 kg"}
ground = {length = "100 mm"}
[drive]
speed = "300 rpm"
positions = 72
"""


class LimitTable(Spec):
    limit: Torque
    margin: float = Field(0.1, ge=0.0, lt=1.0)


def _run(ctx: StageContext) -> Outcome:
    peak = float(np.max(np.abs(ctx.analysis.forces.driving_torque)))
    allowed = ctx.table.limit * (1.0 - ctx.table.margin)
    failed = (f"peak driving torque {peak:.4g} N*m > {allowed:.4g} N*m",) if peak > allowed else ()
    return Outcome(results=peak, scalars={"torque_limit.utilisation": peak / allowed},
                   summary=("torque_limit.utilisation",), failed_checks=failed)


CAPABILITY = Capability(
    table="torque_limit", schema=LimitTable, run=_run, step="torque limit",
    labels={"torque_limit.utilisation": Label("Peak driving torque / allowed", "", over="scalar", better="lower")},
    result_type=float,
)


@pytest.fixture
def registered(monkeypatch):
    """Register the example capability by one registry line, as a user's package would."""
    module = types.ModuleType("example_torque_limit")
    module.CAPABILITY = CAPABILITY
    monkeypatch.setitem(sys.modules, "example_torque_limit", module)
    monkeypatch.setitem(kinds.CAPABILITIES, "torque_limit", "example_torque_limit:CAPABILITY")
    for cached in (kinds.capabilities_for, kinds.problem_model, kinds.capability):
        cached.cache_clear()
    yield
    monkeypatch.delitem(kinds.CAPABILITIES, "torque_limit")
    for cached in (kinds.capabilities_for, kinds.problem_model, kinds.capability):
        cached.cache_clear()


def test_a_registered_capability_runs_from_a_problem_file(registered):
    problem = load_problem(FILE + '[torque_limit]\nlimit = "50 N*m"\n')
    assert problem.torque_limit.limit == 50.0
    result = run_problem(problem)
    assert result.failed_checks == []
    row = next(r for r in result.summary.rows if r.key == "torque_limit.utilisation")
    peak = float(np.max(np.abs(result.analysis.forces.driving_torque)))
    assert row.label == "Peak driving torque / allowed" and row.value == pytest.approx(peak / 45.0, rel=1e-12)
    assert result.results_json()["scalars"]["torque_limit.utilisation"]["unit"] == ""


def test_a_failed_check_of_a_capability_exits_with_3(registered, tmp_path):
    path = tmp_path / "limited.toml"
    path.write_text(FILE + '[torque_limit]\nlimit = "1e-6 N*m"\n', encoding="utf-8")
    result = CliRunner().invoke(app, ["run", str(path), "--out", str(tmp_path / "out"), "--quiet"])
    assert result.exit_code == EXIT_CHECKS_FAILED, result.output
    assert "design check failed: peak driving torque" in result.stderr
    assert (tmp_path / "out" / "results.json").exists(), "the outputs of a failed design are still written"


def test_a_capability_table_is_validated_with_the_rest_of_the_file(registered, tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text(FILE.replace('"300 rpm"', '"-1 m"') + '[torque_limit]\nlimit = "5 m"\nmargni = 0.2\n',
                    encoding="utf-8")
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == EXIT_BAD_INPUT
    for fragment in ("drive.speed", "torque_limit.limit", "torque_limit.margni", "did you mean 'margin'"):
        assert fragment in result.stderr, fragment


def test_unregistered_tables_are_refused_with_a_hint(tmp_path):
    path = tmp_path / "typo.toml"
    path.write_text(FILE + '[swep]\nparameter = "mechanism.crank.length"\nvalues = ["40 mm"]\n', encoding="utf-8")
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == EXIT_BAD_INPUT and "did you mean 'sweep'" in result.stderr


def test_every_registered_entry_imports_and_names_its_table():
    for name in kinds.KINDS:
        assert kinds.kind(name).name == name
    for table in kinds.CAPABILITIES:
        cap = kinds.capability(table)
        assert cap.table == table and cap.kinds, table
        assert all(k in kinds.KINDS for k in cap.kinds)


def test_every_capability_declares_the_type_of_its_result_and_names_the_tables_it_reads():
    """The typed contracts between capabilities: every stage declares what its ``Outcome.results`` is, and a
    stage that reads another's result (``ctx.result_of``) lists that table in ``after``."""
    import inspect

    for table in kinds.CAPABILITIES:
        cap = kinds.capability(table)
        assert cap.result_type is not None, table
        read = set(re.findall(r'result_of\("(\w+)"', inspect.getsource(cap.run)))
        read -= set(kinds.KINDS)  # the kind's own result is always there first
        assert read <= set(cap.after) | {cap.table}, (table, read, cap.after)


def test_result_of_gives_the_typed_result_none_when_absent_and_refuses_another_type():
    from machdyn.balancing.frame import BalanceRun

    run = BalanceRun("crank", None, None, None, "")
    ctx = StageContext(None, None, None, None, {"balance": Outcome(results=run), "flywheel": Outcome()})
    assert ctx.result_of("balance", BalanceRun) is run
    assert ctx.result_of("flywheel", BalanceRun) is None  # a stage that produced no result object
    assert ctx.result_of("frame", BalanceRun) is None  # no such table in the file
    with pytest.raises(TypeError, match="BalanceRun"):
        StageContext(None, None, None, None, {"balance": Outcome(results=1.0)}).result_of("balance", BalanceRun)


def test_the_runner_refuses_a_result_of_another_type_than_declared(registered, monkeypatch, tmp_path):
    from dataclasses import replace

    wrong = types.ModuleType("example_wrong_type")
    wrong.CAPABILITY = replace(CAPABILITY, result_type=str)
    monkeypatch.setitem(sys.modules, "example_wrong_type", wrong)
    monkeypatch.setitem(kinds.CAPABILITIES, "torque_limit", "example_wrong_type:CAPABILITY")
    for cached in (kinds.capabilities_for, kinds.problem_model, kinds.capability):
        cached.cache_clear()
    with pytest.raises(TypeError, match="torque_limit"):
        run_problem(FILE + '[torque_limit]\nlimit = "500 N*m"\n')


def test_every_balancing_method_of_the_schema_has_one_entry():
    from typing import get_args

    from machdyn.balancing.methods import METHODS
    from machdyn.balancing.stage import BalanceSpec

    assert set(get_args(BalanceSpec.model_fields["method"].annotation)) == set(METHODS)


def test_the_cli_knows_no_kind_by_name():
    from pathlib import Path

    import machdyn.cli

    text = Path(machdyn.cli.__file__).read_text(encoding="utf-8")
    for name in [*kinds.KINDS, *kinds.CAPABILITIES]:
        assert f'"{name}"' not in text, name


def test_plain_run_succeeds(tmp_path):
    path = tmp_path / "plain.toml"
    path.write_text(FILE, encoding="utf-8")
    result = CliRunner().invoke(app, ["run", str(path), "--out", str(tmp_path / "out"), "--quiet"])
    assert result.exit_code == EXIT_OK, result.output


def test_the_registry_entries_the_architecture_page_names_exist():
    """Every ``"machdyn.<module>:<OBJECT>"`` of docs/architecture.md but those of its two worked examples (the
    torque-limit capability and the press kind, which the page writes) imports."""
    import re
    from pathlib import Path

    from machdyn.pipeline import import_object

    text = (Path(__file__).resolve().parents[2] / "docs" / "architecture.md").read_text(encoding="utf-8")
    examples = ("machdyn.mypackage.", "machdyn.press.", "machdyn.report.torque_limit", "machdyn.report.press")
    entries = [e for e in re.findall(r'"(machdyn\.[\w.]+:\w+)"', text) if not e.startswith(examples)]
    assert entries
    for entry in entries:
        assert import_object(entry) is not None, entry
