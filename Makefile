# HexBot toolchain: every set-up step, idempotent, for a fresh Debian machine.
#
#   make run    set up, then open the console on the embedded simulated cluster
#   make test   set up, then lint, check firmware budgets and run the test suite:
#               on every core with pytest-xdist (tests share no ports or files),
#               then the few tests marked `wallclock` alone (they pace a simulator
#               by the wall clock and failed under load). PYTEST_ARGS goes to both.
#
# Sub-steps: deps (Debian packages), venv (.venv + pip install -e .[dev]; dev
# brings the test tools and the plot extra, so the drawing tests run),
# firmware (avr-gcc images).

SHELL := /bin/bash
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMPS := .stamps

# Debian packages the project needs: AVR toolchain, simavr library and headers
# (our ATmega162 core links against it), avrdude, and what builds the Python
# extension.
APT_PACKAGES := gcc-avr avr-libc binutils-avr simavr libsimavr-dev libelf-dev \
	avrdude pkg-config gcc make python3-venv python3-dev openssl
PYTEST_ARGS ?=
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: setup deps venv firmware run test lint clean

setup: deps venv firmware

deps:
	@missing=$$(for p in $(APT_PACKAGES); do \
		dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q 'ok installed' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
		echo "installing Debian packages:" $$missing; \
		$(SUDO) apt-get update -qq && \
		$(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing; \
	else echo "Debian packages: all present"; fi

# Reinstall when the packaging or the C sources (simulator core, crossing search) change.
PY_BUILD_INPUTS := pyproject.toml setup.py $(wildcard hil_sim/core/*.c hil_sim/core/*.h planning/*.c) firmware/include/hexbot_codes.h

venv: $(STAMPS)/venv

$(STAMPS)/venv: $(PY_BUILD_INPUTS)
	@test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install -q --upgrade pip
	$(BIN)/python -m pip install -q -e '.[dev]'
	@mkdir -p $(STAMPS) && touch $@

firmware: deps
	@if [ -f firmware/Makefile ]; then $(MAKE) --no-print-directory -C firmware all; fi

run: setup
	$(BIN)/hexbot console

lint: venv
	$(BIN)/ruff check .

test: setup lint
	@if [ -f firmware/Makefile ]; then $(MAKE) --no-print-directory -C firmware check-size; fi
	$(BIN)/python -m pytest -n auto -m "not wallclock" $(PYTEST_ARGS) || [ $$? -eq 5 ]
	$(BIN)/python -m pytest -m wallclock $(PYTEST_ARGS) || [ $$? -eq 5 ]

clean:
	rm -rf $(STAMPS) build *.egg-info
	@if [ -f firmware/Makefile ]; then $(MAKE) --no-print-directory -C firmware clean; fi
