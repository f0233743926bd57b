# camtrain: set-up, demo, tests, benchmarks, lint.
# Every target bootstraps its own virtual environment, so a fresh clone needs only Python 3.11+.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed

.PHONY: demo test test-all test-reverse test-folders test-oldest fuzz bench lint docs clean venv

venv: $(STAMP)

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[test]'
	touch $(STAMP)

# The warm-up compiles every numba kernel once (numba's disk cache), so that no deck's first run
# pays for it (docs/performance.md, "First run").
demo: $(STAMP)
	$(BIN)/camtrain warmup
	$(BIN)/camtrain run decks/harrison_flat.toml --out out/harrison_flat

# `make test` leaves out the tests marked slow (each a minute or more of marching on two cores)
# so that it stays under ten minutes; `make test-all` runs every test.
test: $(STAMP)
	$(BIN)/python -m pytest -m "not slow"

test-all: $(STAMP)
	$(BIN)/python -m pytest

# Order-dependence checks: the whole suite last test first, and each test folder on its own.
test-reverse: $(STAMP)
	$(BIN)/python -m pytest --reverse -p no:cacheprovider

test-folders: $(STAMP)
	set -e; for d in tests/*/ tests/test_*.py; do case $$d in *__pycache__*|*fuzz/*|*repro/*) continue;; esac; \
		echo "== $$d"; $(BIN)/python -m pytest $$d -p no:cacheprovider; done

# The declared minimum version of every dependency (and test extra), in a venv of its own.
OLDEST := .venv-oldest
$(OLDEST)/.installed: pyproject.toml scripts/oldest_pins.py
	$(PYTHON) -m venv $(OLDEST)
	$(OLDEST)/bin/python -m pip install --quiet --upgrade pip
	$(PYTHON) scripts/oldest_pins.py > $(OLDEST)/constraints.txt
	$(OLDEST)/bin/python -m pip install --quiet -c $(OLDEST)/constraints.txt -e '.[test]'
	touch $@

test-oldest: $(OLDEST)/.installed
	$(OLDEST)/bin/python -m pip list --format=freeze | grep -i -E '^(numpy|scipy|numba|matplotlib|click|rich|tomli.w|pillow|pandas)=='
	CAMTRAIN_GOLDEN_RTOL=1e-8 $(OLDEST)/bin/python -m pytest -p no:cacheprovider

# Thousands of fuzzed decks of every kind through `camtrain run` (make test runs the first 200
# cases); each case is time-boxed (FUZZ_BOX s); the cases per kind and exit code are written to
# out/fuzz_report.txt and printed.
FUZZ_CASES ?= 3000
FUZZ_BOX ?= 180
fuzz: $(STAMP)
	CAMTRAIN_FUZZ_START=200 CAMTRAIN_FUZZ_CASES=$(FUZZ_CASES) CAMTRAIN_FUZZ_BOX=$(FUZZ_BOX) \
		CAMTRAIN_FUZZ_REPORT=out/fuzz_report.txt $(BIN)/python -m pytest \
		tests/test_fuzz_decks.py -k mutated_deck -p no:cacheprovider; \
		status=$$?; cat out/fuzz_report.txt; exit $$status

bench: $(STAMP)
	$(BIN)/python -m pytest benchmarks --benchmark-enable --benchmark-only -p no:cacheprovider

# The documentation site: the gallery (every shipped deck run, its sheets and key results) is
# generated, then docs/ is built into site/ by MkDocs; any warning fails the build.
DOCS_STAMP := $(VENV)/.docs-installed
$(DOCS_STAMP): $(STAMP) pyproject.toml
	$(BIN)/python -m pip install --quiet -e '.[docs]'
	touch $@

docs: $(DOCS_STAMP)
	$(BIN)/python docs/make_gallery.py
	NO_MKDOCS_2_WARNING=1 $(BIN)/python -m mkdocs build --strict

lint: $(STAMP)
	$(BIN)/ruff check camtrain tests benchmarks

clean:
	rm -rf $(VENV) $(OLDEST) out build site docs/gallery docs/gallery.md *.egg-info
