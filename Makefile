# Denavit: install · run · test · bench
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
HOST   ?= 127.0.0.1
PORT   ?= 8000
STAMP  := $(VENV)/.installed

LOCK     := requirements-dev.lock
RT_LOCK  := requirements.lock
IMAGE    ?= denavit

.PHONY: install install-run run test lint browser viewer-vendor bench bench-env rtb-fixtures lock-bench openapi lock image container-check compose-check clean clients typescript openapi-lint-tools openapi-lint examples

install: $(STAMP)

# Exactly the locked packages (hash-checked, no resolution), then the project itself,
# editable, built with the locked setuptools. Re-installs when the lock changes.
$(STAMP): pyproject.toml $(LOCK) clients/python/pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --no-deps --require-hashes -r $(LOCK)
	$(BIN)/python -m pip install --quiet --no-deps --no-build-isolation -e .
	$(BIN)/python -m pip install --quiet --no-deps --no-build-isolation \
		--config-settings editable_mode=compat -e ./clients/python
	touch $(STAMP)

# Re-resolve every transitive dependency from pyproject.toml (its == pins, the build
# backend, [tool.uv] overrides) into the two hash-locked files; the runtime lock is
# constrained to the development one, so both hold the same versions.
BUILD_REQUIRES = $(BIN)/python -c 'import tomllib; \
	print(*tomllib.load(open("pyproject.toml", "rb"))["build-system"]["requires"], sep="\n")'
UV_COMPILE = $(BIN)/uv pip compile --quiet --universal --python-version 3.11 --generate-hashes \
	--annotation-style line
# The runtime lock omits what [tool.denavit.runtime-lock] names (never imported: see there).
RT_OMIT = $(BIN)/python -c 'import tomllib; \
	t = tomllib.load(open("pyproject.toml", "rb"))["tool"]["denavit"]["runtime-lock"]; \
	print(*(f"--no-emit-package={p}" for p in t["cut"] + t["with-cut"]))'
lock: install
	$(BUILD_REQUIRES) | $(UV_COMPILE) pyproject.toml - --extra test -o $(LOCK)
	$(BUILD_REQUIRES) | $(UV_COMPILE) pyproject.toml - -c $(LOCK) $$($(RT_OMIT)) -o $(RT_LOCK)

# The production image: docker when its engine answers, else podman.
image:
	if docker info >/dev/null 2>&1; then docker build -t $(IMAGE) .; \
	else podman build --format docker -t $(IMAGE) .; fi

# Build the image with podman, run it for real and check it (root on Debian: see the
# script's header).
container-check:
	bash .ci/container-check.sh

# compose.yaml with podman-compose on the image container-check built (deploy/compose-check.sh).
compose-check: install
	PATH=$(CURDIR)/$(BIN):$$PATH bash deploy/compose-check.sh

# The serving venv: exactly the runtime lock (what the Docker image installs), no test or
# lint tools; its own directory and stamp, so `make run` and `make test` work in either
# order in one checkout. Re-installs when the lock changes.
RUN_VENV  := .venv-run
RUN_STAMP := $(RUN_VENV)/.installed
install-run: $(RUN_STAMP)
$(RUN_STAMP): pyproject.toml $(RT_LOCK)
	test -x $(RUN_VENV)/bin/python || $(PYTHON) -m venv $(RUN_VENV)
	$(RUN_VENV)/bin/python -m pip install --quiet --no-deps --require-hashes -r $(RT_LOCK)
	$(RUN_VENV)/bin/python -m pip install --quiet --no-deps --no-build-isolation -e .
	touch $(RUN_STAMP)

# The same entry as the Docker image: settings from DENAVIT_* (HOST and PORT override).
run: install-run
	DENAVIT_HOST=$(HOST) DENAVIT_PORT=$(PORT) $(RUN_VENV)/bin/python -m app

lint: install
	$(BIN)/ruff check app dh2urdf robots tests bench deploy scripts clients
	$(BIN)/ruff format --check app dh2urdf robots tests bench deploy scripts clients
	$(BIN)/hadolint Dockerfile

test: install lint browser openapi-lint-tools typescript
	$(BIN)/python -m pytest -n 2 tests

# The browser tests (tests/browser) drive Debian's chromium through Playwright; Playwright's
# own browser download does not work here. Installed when missing (root, apt), else the
# target fails and says how: the browser tests never skip.
CHROMIUM ?= /usr/bin/chromium
browser:
	@test -x $(CHROMIUM) || { \
	  if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null; then \
	    DEBIAN_FRONTEND=noninteractive apt-get install -y chromium \
	      || { apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y \
	           chromium; }; \
	  else echo "no $(CHROMIUM): install Debian's chromium (sudo apt-get install chromium)"; \
	    exit 1; fi; }

# Refresh the browser libraries vendored in app/static/vendor (three.js, urdf-loader,
# Swagger UI, ReDoc) from the npm registry, at the versions pinned in scripts/vendor_web.py.
# Only for changing them: `make run` serves the committed files and needs no Node.
viewer-vendor: install
	$(BIN)/python scripts/vendor_web.py

# The bench-only venv: the Robotics Toolbox (ik_LM, side by side in bench_ik), which needs
# another NumPy than the service: never in .venv or its locks; `make test`/CI do not need it.
# Exactly the hash-locked packages of requirements-bench.lock (`make lock-bench`).
BENCH_VENV  := .venv-bench
BENCH_LOCK  := requirements-bench.lock
BENCH_STAMP := $(BENCH_VENV)/.installed
bench-env: $(BENCH_STAMP)
$(BENCH_STAMP): $(BENCH_LOCK)
	test -x $(BENCH_VENV)/bin/python || $(PYTHON) -m venv $(BENCH_VENV)
	$(BENCH_VENV)/bin/python -m pip install --quiet --no-deps --require-hashes -r $(BENCH_LOCK)
	touch $(BENCH_STAMP)

# The Robotics Toolbox's dynamics of its DH Puma 560 and UR5 (rne, gravload, inertia,
# coriolis at fixed-seed states) as the fixture tests/kinematics/test_dynamics_rtb.py
# compares the service with (bench/rtb_dynamics.py, run by the bench venv's python).
rtb-fixtures: bench-env
	$(BENCH_VENV)/bin/python bench/rtb_dynamics.py tests/kinematics/data/rtb_dynamics.json

lock-bench: install
	$(BIN)/uv pip compile --quiet --python-version 3.11 --python-platform x86_64-manylinux_2_28 \
		--generate-hashes --annotation-style line requirements-bench.in -o $(BENCH_LOCK)

# Without the bench venv (no network, say) the ik_LM rows say so; the rest still runs.
bench: install
	$(MAKE) bench-env || echo "bench: $(BENCH_VENV) could not be built; ik_LM rows skipped"
	DENAVIT_BENCH_PYTHON=$(CURDIR)/$(BENCH_VENV)/bin/python $(BIN)/python -m bench

# The TypeScript client's tools (openapi-typescript, openapi-fetch, tsc): exactly
# clients/typescript/package-lock.json, by npm ci (Node from Debian: apt-get install nodejs npm).
# tests/clients compiles its lab script with tsc --strict and checks its types for drift.
TS_DIR   := clients/typescript
TS_STAMP := $(TS_DIR)/node_modules/.installed
typescript: $(TS_STAMP)
$(TS_STAMP): $(TS_DIR)/package.json $(TS_DIR)/package-lock.json
	cd $(TS_DIR) && npm ci --no-audit --no-fund --loglevel=error
	touch $(TS_STAMP)

# Regenerate the clients from the committed OpenAPI document (run after `make openapi`):
# clients/python (clients/generate.py) and clients/typescript/src/schema.d.ts.
clients: install typescript
	$(BIN)/python clients/generate.py
	cd $(TS_DIR) && node generate.mjs

# Regenerate the committed OpenAPI schema from the app (tests/test_openapi.py compares).
openapi: install
	$(BIN)/python -m app openapi docs/openapi.json

# Record the document's examples again (after a model change; then `make openapi`):
# scripts/record_examples.py runs the requests of tests/openapi_examples.py.
examples: install
	$(BIN)/python scripts/record_examples.py

# The OpenAPI linters (@redocly/cli, @stoplight/spectral-cli) exactly as
# tools/lint/package-lock.json pins them (no install scripts); tests/test_openapi_lint.py
# runs them on docs/openapi.json offline, so `make test` fails on any lint error.
LINT_DIR   := tools/lint
LINT_STAMP := $(LINT_DIR)/node_modules/.installed
openapi-lint-tools: $(LINT_STAMP)
$(LINT_STAMP): $(LINT_DIR)/package.json $(LINT_DIR)/package-lock.json
	cd $(LINT_DIR) && npm ci --ignore-scripts --no-audit --no-fund --prefer-offline
	touch $(LINT_STAMP)

openapi-lint: install openapi-lint-tools
	$(BIN)/python -m pytest -o addopts= -q tests/test_openapi_lint.py

clean:
	rm -rf $(VENV) $(RUN_VENV) $(BENCH_VENV) .pytest_cache .ruff_cache .mypy_cache \
		$(TS_DIR)/node_modules $(TS_DIR)/dist $(LINT_DIR)/node_modules
