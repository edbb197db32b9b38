# make test    set up what is missing, then run every test (notebooks included)
# make report  set up what is missing, then build the example's calc report
# make bench   set up what is missing, then print the benchmark
SHELL := /bin/bash
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
STAMP := $(VENV)/.installed-$(shell sha256sum environment.txt | cut -c1-12)
EXAMPLE := cases/indexing-table.toml

.PHONY: setup test report bench notebooks clean

setup: $(STAMP)

$(STAMP): environment.txt
	@test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --disable-pip-version-check -r environment.txt
	$(PY) -m pip install --quiet --disable-pip-version-check --no-deps -e .
	$(PY) -m ipykernel install --sys-prefix --name python3 >/dev/null
	@rm -f $(VENV)/.installed-* && touch $@

test: setup
	$(PY) -m pytest

report: setup
	@mkdir -p reports
	$(PY) -m calc evaluate $(EXAMPLE) > reports/indexing-table.txt
	@cat reports/indexing-table.txt
	@echo "written: reports/indexing-table.txt"

# Re-execute every notebook in place (after a change to calc/), so nbval has true outputs to compare.
notebooks: setup
	for nb in notebooks/*.ipynb; do \
	  $(PY) -m jupyter nbconvert --to notebook --execute --inplace "$$nb" || exit 1; done

clean:
	rm -rf $(VENV) .pytest_cache .hypothesis
