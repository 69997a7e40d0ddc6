# Denavit: install · run · test · bench
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
HOST   ?= 127.0.0.1
PORT   ?= 8000
STAMP  := $(VENV)/.installed

.PHONY: install run test lint bench openapi clean

install: $(STAMP)

# Re-install only when the project's dependency list changes.
$(STAMP): pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[test]'
	touch $(STAMP)

# The same entry as the Docker image: settings from DENAVIT_* (HOST and PORT override).
run: install
	DENAVIT_HOST=$(HOST) DENAVIT_PORT=$(PORT) $(BIN)/python -m app

lint: install
	$(BIN)/ruff check app dh2urdf robots tests bench
	$(BIN)/ruff format --check app dh2urdf robots tests bench
	$(BIN)/hadolint Dockerfile

test: install lint
	$(BIN)/python -m pytest -n 2 tests

bench: install
	$(BIN)/python -m bench

# Regenerate the committed OpenAPI schema from the app (tests/test_openapi.py compares).
openapi: install
	$(BIN)/python -m app openapi docs/openapi.json

clean:
	rm -rf $(VENV) .pytest_cache .ruff_cache
