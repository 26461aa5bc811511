# `make demo` and `make test` work on a fresh machine with only Python 3.11.
PYTHON ?= python3
VENV := .venv
PLUGINS := $(sort $(dir $(wildcard plugins/*/pyproject.toml)))
STAMP := $(VENV)/.installed

.PHONY: demo test dist clean

$(STAMP): pyproject.toml $(wildcard plugins/*/pyproject.toml)
	$(PYTHON) -m venv $(VENV)
	$(VENV)/bin/pip install -q --upgrade pip
	$(VENV)/bin/pip install -q -e '.[mpi,bench]' $(foreach p,$(PLUGINS),-e '$(p)[test]') pytest \
		'setuptools>=70.1'
	touch $(STAMP)

demo: $(STAMP)
	cd examples && ../$(VENV)/bin/pdps run water.in

test: $(STAMP)
	$(VENV)/bin/python -m pytest -m "not slow"

# Wheels as users install them: the core, every distribution under plugins/ and the pdps
# meta-distribution (packaging/pdps). All are built in .venv with its setuptools (an isolated build
# environment per wheel takes a minute instead of seconds). Old build/ folders go first: setuptools
# packs whatever a previous build left there, modules since moved or deleted included.
DIST ?= dist
DISTRIBUTIONS := ./ $(PLUGINS) packaging/pdps/
dist: $(STAMP)
	rm -rf $(addsuffix build,$(DISTRIBUTIONS))
	rm -f $(DIST)/*.whl
	$(VENV)/bin/pip wheel -q --no-deps --no-build-isolation --wheel-dir $(DIST) $(DISTRIBUTIONS)

clean:
	rm -rf $(VENV)
