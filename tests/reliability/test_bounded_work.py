"""Bounded work: what a problem file or the command line may ask for is limited (and the limit named) before
the work starts; connections and integrations that would wait or run for minutes are stopped in seconds."""

from __future__ import annotations

import os
import socket
import threading

import pytest
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.studies.exploration.execution import worker_limit, workers_error

from .conftest import FOUR_BAR, ROOT, machdyn, sweep_text


@pytest.fixture
def silent_server():
    """A TCP service that accepts connections and never says a word (not a Dask scheduler)."""
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen(8)
    held = []

    def accept():
        while True:
            try:
                held.append(server.accept()[0])
            except OSError:
                return

    threading.Thread(target=accept, daemon=True).start()
    yield f"tcp://127.0.0.1:{server.getsockname()[1]}"
    server.close()
    for c in held:
        c.close()


def test_a_scheduler_address_that_is_not_dask_exits_1_in_seconds(write, silent_server):
    path = write(sweep_text(samples=64))
    code, _, err, seconds = machdyn("run", str(path), "--out", str(path.parent / "out"), "--scheduler",
                                    silent_server, timeout=120)
    assert code == 1, err
    assert "no Dask scheduler answered at" in err and "Traceback" not in err
    assert len(err.strip().splitlines()) == 1
    assert seconds < 60  # 10 s to connect and shake hands, plus the interpreter and the plan


def test_a_scheduler_nobody_listens_on_exits_1(write):
    with socket.socket() as s:  # a free port, closed again: nothing listens there
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    path = write(sweep_text(samples=64))
    code, _, err, _ = machdyn("run", str(path), "--out", str(path.parent / "out"), "--scheduler",
                              f"tcp://127.0.0.1:{port}", timeout=120)
    assert code == 1 and "Dask scheduler" in err and f"tcp://127.0.0.1:{port}" in err and "internal error" not in err
    assert len(err.strip().splitlines()) == 1


@pytest.mark.parametrize("address", ["tcp://host", "http://host:8786", "tcp://host:99999", "host:8786", "tcp://a b:1"])
def test_bad_scheduler_addresses_are_refused_by_check_and_by_run(tmp_path, address):
    path = tmp_path / "p.toml"
    path.write_text(sweep_text(samples=64, extra=f'scheduler = "{address}"\n'))
    checked = CliRunner().invoke(app, ["check", str(path)])
    assert checked.exit_code == 2 and "sweep.scheduler" in checked.output
    plain = tmp_path / "q.toml"
    plain.write_text(sweep_text(samples=64))
    ran = CliRunner().invoke(app, ["run", str(plain), "--out", str(tmp_path / "o"), "--scheduler", address])
    assert ran.exit_code == 2 and "--scheduler" in ran.output


def test_workers_beyond_the_machine_are_refused_naming_the_field(tmp_path, monkeypatch):
    monkeypatch.delenv("MACHDYN_MAX_WORKERS", raising=False)
    limit = worker_limit()
    assert limit == max(1, os.cpu_count() or 1)
    path = tmp_path / "p.toml"
    path.write_text(sweep_text(samples=64))
    ran = CliRunner().invoke(app, ["run", str(path), "--out", str(tmp_path / "o"), "--workers", "512"])
    assert ran.exit_code == 2 and "--workers must be at most" in ran.output and "MACHDYN_MAX_WORKERS" in ran.output
    assert not (tmp_path / "o").exists()  # refused before anything starts
    path.write_text(sweep_text(samples=64, extra="workers = 512\n"))
    checked = CliRunner().invoke(app, ["check", str(path)])
    assert checked.exit_code == 2 and "sweep.workers" in checked.output
    monkeypatch.setenv("MACHDYN_MAX_WORKERS", "600")
    assert workers_error(512) is None  # the documented override


@pytest.mark.parametrize(("table", "field"), [
    ("[sweep]\nparameter = \"mechanism.crank.length\"\nstart = \"30 mm\"\nstop = \"50 mm\"\ncount = 1000000\n",
     "sweep.count"),
    ("[[optimise.objectives]]\nresult = \"max_driving_torque\"\n[[optimise.variables]]\n"
     "parameter = \"mechanism.crank.length\"\nlower = \"30 mm\"\nupper = \"45 mm\"\n[optimise]\npopulation = 100000\n",
     "optimise.population"),
])
def test_designs_times_positions_held_in_memory_are_refused_naming_the_field(write, table, field):
    path = write(FOUR_BAR.replace("positions = 36", "positions = 100000") + table)
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 2, result.output
    assert f"{field}:" in result.output and "held in memory at once" in result.output


def test_a_custom_mechanism_of_thousands_of_dyads_is_refused_by_the_schema(write):
    dyads = "".join(f'[[mechanism.dyads]]\ntype = "RRR"\nname = "d{i}"\n' for i in range(3000))
    path = write(FOUR_BAR.replace('type = "four_bar"', 'type = "custom"') + dyads)
    code, _, err, seconds = machdyn("check", str(path), timeout=120)
    assert code == 2 and "mechanism" in err and "at most 64" in err
    assert seconds < 60


def _weak_motor(example: str, rated_power: str) -> str:
    text = (ROOT / "examples" / example).read_text()
    text = text.replace('kind = "select"', 'kind = "induction"\nrated_power = "' + rated_power + '"\n'
                        'rated_speed = "1440 rpm"', 1)
    return text.replace('rated_power = "4 kW"', f'rated_power = "{rated_power}"')


@pytest.mark.parametrize("example", ["compactor_flywheel.toml", "crank_press.toml", "rotary_screen_drive.toml"])
def test_a_1_watt_motor_with_a_crank_damper_is_decided_in_seconds(write, example):
    path = write(_weak_motor(example, "1 W"))
    code, _, err, seconds = machdyn("run", str(path), "--out", str(path.parent / "out"), "-q", timeout=300)
    assert code in (2, 3), err  # refused (the drive cannot carry the machine) or its design checks fail
    assert "Traceback" not in err and seconds < 120


def test_an_integration_that_creeps_towards_a_stall_is_stopped_by_its_budget(monkeypatch):
    import importlib

    from machdyn.dynamics.motion import start_up
    from machdyn.dynamics.simulate import NotSettledError
    from machdyn.runner import run_problem

    done = run_problem(ROOT / "examples" / "crank_press.toml").outcomes["flywheel"].results
    motion = importlib.import_module("machdyn.dynamics.motion")
    monkeypatch.setattr(motion, "MAX_START_UP_EVALUATIONS", 50)  # far fewer than a start-up needs
    with pytest.raises(NotSettledError, match="start-up was stopped after 50 steps"):
        start_up(done.machine, done.drive, done.flywheel, steady=done.steady)
    simulate = importlib.import_module("machdyn.dynamics.simulate")
    monkeypatch.setattr(simulate, "MAX_EVALUATIONS_PER_CYCLE", 50)  # far fewer than one cycle needs
    # a machine that nearly stalls is a design that fails its check (exit 3), the same verdict as a stall
    failed = run_problem(ROOT / "examples" / "crank_press.toml").failed_checks
    assert any("nearly stalls: one cycle of its motion needed more than 50 steps" in f for f in failed), failed


def test_max_time_stops_a_run_with_exit_1_and_keeps_the_finished_partitions(write):
    text = sweep_text(samples=65536, partition=256).replace("positions = 36", "positions = 360")
    path = write(text)
    out = path.parent / "out"
    code, _, err, seconds = machdyn("run", str(path), "--out", str(out), "--max-time", "6", timeout=300)
    assert code == 1, err
    assert "stopped: the run took longer than --max-time 6 s" in err and "Traceback" not in err
    assert seconds < 60
    assert not (out / "results.json").exists()
    assert not [p for p in out.iterdir() if p.name.startswith(".machdyn-partial-")]


def test_a_long_exploration_prints_an_estimate_before_it_starts(write):
    text = sweep_text(samples=1048576, partition=4096).replace("positions = 36", "positions = 360")
    path = write(text)
    # the estimate comes before any design is computed: --max-time ends the run soon after (exit 1), or a fast
    # machine finishes it (exit 0); either way the note was printed first
    code, _, err, _ = machdyn("run", str(path), "--out", str(path.parent / "out"), "--max-time", "5", timeout=300)
    assert code in (0, 1), err
    assert "note: 1,048,576 designs x 360 crank positions on 1 process(es): about" in err and "MB per process" in err
