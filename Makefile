# EyeSim: `make demo` runs the simulator on the bundled scene; `make test` runs every test.
# Both set up everything they need on first use: a virtual environment in .venv with EyeSim
# installed into it (which builds the C library), and for the tests the Debian packages of the
# headless browser when run as root.

PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
SOURCES := $(shell find eyesim robios protocol -type f -not -path '*/__pycache__/*' 2>/dev/null) pyproject.toml
INSTALLED := $(VENV)/.installed

.PHONY: demo test install viewer protocol bench clean

demo: $(INSTALLED) build/demo
	$(BIN)/eyesim run --program 1=build/demo --open

test: $(INSTALLED) browser-packages
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

build/demo: examples/programs/demo.c $(INSTALLED)
	mkdir -p build
	$(BIN)/eyesim cc -O2 -Wall -Wextra examples/programs/demo.c -o $@

# Headless Chromium for the browser tests, from Debian's packages (needs root; skipped otherwise
# when already present).
.PHONY: browser-packages
browser-packages:
	@if ! command -v chromium >/dev/null 2>&1; then \
		if [ "$$(id -u)" = 0 ]; then \
			apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium >/dev/null; \
		else \
			echo "make test: Chromium is missing; install the Debian package 'chromium' (as root) for the browser tests" >&2; exit 1; \
		fi; \
	fi

# Rebuild the browser bundle committed in eyesim/web/static (needs Node.js and npm).
viewer:
	cd web && npm ci --no-audit --no-fund && npm run build

# Regenerate the protocol tables from protocol/protocol.json.
protocol:
	$(PYTHON) protocol/generate.py

bench: $(INSTALLED)
	$(BIN)/python bench/bench_roundtrip.py
	$(BIN)/python bench/bench_stalled_client.py

clean:
	rm -rf $(VENV) build
