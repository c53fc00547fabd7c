# Two commands set everything up on a fresh machine with Python 3.11: `make run` and `make test`.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
BENCH_STAMP := $(VENV)/.installed-bench
OUT ?= out

.PHONY: run test bench lint clean

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e ".[test]"
	touch $(STAMP)

$(BENCH_STAMP): $(STAMP)
	$(BIN)/python -m pip install --quiet -e ".[test,bench]"
	touch $(BENCH_STAMP)

run: $(STAMP)
	$(BIN)/machdyn run examples/rotary_screen.toml --out $(OUT)

test: $(STAMP)
	$(BIN)/ruff check src tests bench
	$(BIN)/mypy
	$(BIN)/python -m pytest -n auto

bench: $(BENCH_STAMP)
	$(BIN)/python bench/peers.py
	$(BIN)/python bench/dynamics.py
	$(BIN)/python bench/explore.py throughput
	$(BIN)/python bench/optimise.py
	$(BIN)/python bench/synthesis.py
	$(BIN)/python bench/transient.py
	$(BIN)/python bench/cli.py
	$(BIN)/python bench/cams.py
	$(BIN)/python bench/walk.py
	$(BIN)/python bench/capabilities.py
	$(BIN)/python bench/time_to_optimum.py

lint: $(STAMP)
	$(BIN)/ruff check src tests bench

clean:
	rm -rf $(VENV) $(OUT) build .pytest_cache .hypothesis
