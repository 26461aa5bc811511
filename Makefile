# `make demo` and `make test` work on a fresh machine with only Python 3.11.
PYTHON ?= python3
VENV := .venv
PLUGINS := $(sort $(dir $(wildcard plugins/*/pyproject.toml)))
RUN_STAMP := $(VENV)/.installed-run
STAMP := $(VENV)/.installed

.PHONY: demo test fuzz bench corpus dist clean

# What a run needs: the core and every plugin, editable. The build backend is installed once and
# shared (--no-build-isolation): an isolated build environment per distribution costs a minute.
$(RUN_STAMP): pyproject.toml $(wildcard plugins/*/pyproject.toml)
	$(PYTHON) -m venv $(VENV)
	$(VENV)/bin/pip install -q --upgrade pip 'setuptools>=77'
	$(VENV)/bin/pip install -q --no-build-isolation -e . $(foreach p,$(PLUGINS),-e '$(p)')
	touch $(RUN_STAMP)

# The tests add MPI, the bench's plotting and the test extras (OVITO, MDAnalysis, freud...).
$(STAMP): $(RUN_STAMP)
	$(VENV)/bin/pip install -q --no-build-isolation -e '.[mpi,bench,test]' \
		$(foreach p,$(PLUGINS),-e '$(p)[test]') pytest
	touch $(STAMP)

demo: $(RUN_STAMP)
	cd examples && ../$(VENV)/bin/pdps run water.in

test: $(STAMP)
	$(VENV)/bin/python -m pytest -m "not slow"

# The fuzz suite (tests/fuzz) at 100,000 cases instead of make test's 2,800 (progress lines on the way),
# 200 of their errors again on 2 ranks, and 100 kill -9 trials instead of 10; the counts per class
# and every distinct failure with its reproducer are appended to FUZZ_REPORT.
FUZZ_CASES ?= 100000
FUZZ_REPORT ?= build/fuzz-report.md
fuzz: $(STAMP)
	mkdir -p $(dir $(FUZZ_REPORT))
	PDPS_FUZZ_CASES=$(FUZZ_CASES) PDPS_FUZZ_MPI=200 PDPS_FUZZ_KILLS=100 PDPS_FUZZ_REPORT=$(FUZZ_REPORT) \
		$(VENV)/bin/python -m pytest tests/fuzz/test_fuzz.py tests/fuzz/test_kill.py -p no:cacheprovider

# pdps beside LAMMPS (../shared/bench/lmp, or $$PDPS_LAMMPS_BENCH/lmp) on LAMMPS's own scenes, back to
# back, median of three runs: throughput, time per stage, peak and anonymous memory, start-up; the
# table goes into docs/performance.md. Only this target needs LAMMPS; test and the CI do not.
bench: $(STAMP)
	$(VENV)/bin/python benchmarks/bench.py

# Scripts nobody here wrote, beside the programs they were written for: LIGGGHTS 3.8.0's tutorials
# (Debian's liggghts-doc, unpacked into build/corpus/ when missing) in pdps and in LIGGGHTS
# (../shared/bench/liggghts, or $$PDPS_LAMMPS_BENCH/liggghts); the table goes into docs/liggghts.md.
# About an hour; not part of test or the CI.
corpus: $(RUN_STAMP)
	$(VENV)/bin/python benchmarks/corpus.py
	$(VENV)/bin/python benchmarks/liggghts_manual.py
	$(VENV)/bin/python benchmarks/corpus_lammps.py

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
