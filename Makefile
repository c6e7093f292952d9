# Two entry points: `make demo` and `make test`. Both set up a virtual
# environment in .venv from scratch when it is missing or outdated.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed

.PHONY: demo test lint clean

$(STAMP): pyproject.toml hatch_build.py $(shell find cantools_od templates schemas -type f -not -name '*.pyc' 2>/dev/null)
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet ".[test]"
	touch $(STAMP)

demo: $(STAMP)
	$(BIN)/cantools-od lint eds/cia402_drive.eds
	$(BIN)/cantools-od pdo eds/cia402_drive.eds --node-id 5
	$(BIN)/cantools-od gen eds/cia402_drive.eds -t c -t rust -t python -t markdown -t html -o build/demo --name drive
	$(BIN)/cantools-od pdo eds/cia402_drive.eds --format svg -o build/demo/pdo
	$(BIN)/cantools-od network examples/network/bus.yml --load --svg build/demo/bus.svg
	@echo "generated:" && ls build/demo

# One worker per core (pytest-xdist); a module whose tests share one expensive fixture (a built crate,
# a venv, the peer matrix) is kept on one worker by its xdist_group mark, so the fixture is made once.
test: $(STAMP)
	cd tests && ../$(BIN)/python -m pytest -q -p no:cacheprovider -n auto --dist loadgroup ../tests

lint: $(STAMP)
	$(BIN)/ruff check cantools_od tests bench
	$(BIN)/ruff format --check cantools_od tests bench
	$(BIN)/mypy cantools_od

clean:
	rm -rf $(VENV) build dist
