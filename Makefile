# Two commands do everything on a fresh machine (each creates .venv and installs on first use):
#   make example   runs the main job on a bundled example scene
#   make test      runs the test suite
PY ?= python3
VENV := .venv
BIN := $(VENV)/bin

$(BIN)/thermobear: pyproject.toml
	$(PY) -m venv $(VENV)
	$(BIN)/pip install --upgrade pip
	$(BIN)/pip install -e ".[test]"
	touch $@

.PHONY: example test validate clean
example: $(BIN)/thermobear
	$(BIN)/thermobear run examples/seed004_oil_jet_7210.toml

test: $(BIN)/thermobear
	$(BIN)/python -m pytest

validate: $(BIN)/thermobear
	$(BIN)/python validation/run_all.py

clean:
	rm -rf $(VENV) .pytest_cache
