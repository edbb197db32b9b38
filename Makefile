# make test    set up what is missing, then run every test (notebooks included)
# make report  set up what is missing, then build the example's calc report
# make bench   set up what is missing, then print the benchmark
# make review  set up what is missing, then serve the design review on http://localhost:8866/
# make book    set up what is missing, then build the course as a static website in build/book/
# make student   what students receive (build/student/): the workbook without the answers, the book, each
#                student's brief and checkpoint notebook (ROSTER=course/roster.csv SEED=2026)
# make lecturer  what the lecturer keeps (build/lecturer/): the book with the answers, the autograder, the keys
SHELL := /bin/bash
# Python keeps what it compiled (__pycache__/, ignored by git) even where the environment says not to
# (PYTHONDONTWRITEBYTECODE, set in some containers): else every test process, notebook kernel and page
# kernel compiles the package's source again, some 0.12 s of CPU each, and pytest rewrites every test
# file again in each worker.
unexport PYTHONDONTWRITEBYTECODE
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
STAMP := $(VENV)/.installed-$(shell cat environment.txt pyproject.toml | sha256sum | cut -c1-12)
EXAMPLE := cases/indexing-table.toml

.PHONY: setup tex browser test report bench review notebooks book student lecturer clean

setup: $(STAMP)

$(STAMP): environment.txt pyproject.toml
	@test -x $(PY) || $(PYTHON) -m venv $(VENV)
	# --no-deps: environment.txt pins the whole set (tests/test_dependencies.py), so nothing is resolved again;
	# basyx-python-sdk declares python-dateutil<3 and runs (its tests pass) with the pinned 4.0.0.
	$(PY) -m pip install --quiet --disable-pip-version-check --no-deps -r environment.txt
	$(PY) -m pip install --quiet --disable-pip-version-check --no-deps -e .
	$(PY) -m ipykernel install --sys-prefix --name python3 >/dev/null
	@rm -f $(VENV)/.installed-* && touch $@

# The PDF reports need XeLaTeX, pandoc (nbconvert), the DejaVu fonts (Greek, ≤ ≥ · ° µ in text and
# math) and poppler (pdftotext, pdftoppm: the report tests read and render the PDF). On Debian they
# are installed here when missing (as root); elsewhere this says what to install.
TEX_DEBS := texlive-xetex texlive-fonts-recommended texlive-plain-generic lmodern pandoc poppler-utils \
            fonts-dejavu-core fonts-dejavu-extra fontconfig
tex:
	@missing=""; \
	for tool in xelatex pandoc pdftotext pdftoppm; do command -v $$tool >/dev/null || missing="$$missing $$tool"; done; \
	command -v fc-list >/dev/null && fc-list : family | grep -q "DejaVu Math TeX Gyre" || missing="$$missing DejaVu-fonts"; \
	test -z "$$missing" && exit 0; \
	if command -v apt-get >/dev/null && [ "$$(id -u)" = 0 ]; then \
	  echo "installing the TeX tools for the PDF reports (missing:$$missing)"; \
	  export DEBIAN_FRONTEND=noninteractive; \
	  apt-get update -qq && apt-get install -y -qq --no-install-recommends $(TEX_DEBS) >/dev/null || exit 1; \
	else \
	  echo "The PDF reports need:$$missing." >&2; \
	  echo "  Debian/Ubuntu (as root): apt-get install --no-install-recommends $(TEX_DEBS)" >&2; \
	  echo "  Fedora: dnf install texlive-xetex texlive-collection-latexextra pandoc poppler-utils dejavu-fonts-all" >&2; \
	  echo "  macOS (Homebrew): brew install --cask mactex-no-gui; brew install pandoc poppler; brew install --cask font-dejavu" >&2; \
	  echo "  Windows: MiKTeX (or TeX Live), pandoc, poppler and the DejaVu fonts" >&2; \
	  exit 1; \
	fi

# The browser test of the served design review drives headless Chromium (Debian's package, by
# Playwright). On Debian it is installed here when missing (as root); elsewhere this says what to install.
browser:
	@test -x /usr/bin/chromium && exit 0; \
	if command -v apt-get >/dev/null && [ "$$(id -u)" = 0 ]; then \
	  echo "installing Chromium for the browser test of the design review"; \
	  export DEBIAN_FRONTEND=noninteractive; \
	  apt-get update -qq && apt-get install -y -qq --no-install-recommends chromium >/dev/null || exit 1; \
	else \
	  echo "The browser test of the design review needs Chromium at /usr/bin/chromium." >&2; \
	  echo "  Debian/Ubuntu (as root): apt-get install --no-install-recommends chromium" >&2; \
	  exit 1; \
	fi

# On every core (pytest-xdist), one worker more than cores: the browser tests spend much of their time waiting
# for a kernel or a page (one waits a minute for a closed page's kernel to go), which another worker fills.
# The tests that share a costly fixture, and each notebook's cells, stay on one worker (--dist loadgroup), the
# long ones handed out first (--no-loadscope-reorder keeps that order), both set in tests/conftest.py.
# `pytest` alone runs in one process.
WORKERS := $(shell $(PYTHON) -c "import os; print((os.cpu_count() or 1) + 1)")
test: setup tex browser
	$(PY) -m pytest -n $(WORKERS) --dist loadgroup --no-loadscope-reorder

report: setup tex
	$(PY) -m calc report $(EXAMPLE) -o reports/indexing-table.pdf

# One line per measurement, `name: value unit`, with its target (bench/bench.py says what each is).
bench: setup tex browser
	$(PY) bench/bench.py

# The design-review panel alone as a web page (Voilà), on this machine only; docs/user-guide.md, "Design review",
# says how to serve it on a network.
review: setup
	$(PY) -m calc.review.serve

# The course as a static website from the notebooks as stored (nothing is executed, nothing fetched):
# open build/book/index.html in a browser.
book: setup
	$(PY) -m sphinx -q -W --keep-going -c book . build/book
	@echo "the book: build/book/index.html"

# The course handed out and kept apart: each student's brief is drawn from the roster's name and the
# course's seed, which the lecturer's autograder draws again (docs/course.md, "Handing out the course").
ROSTER ?= course/roster.csv
SEED ?= 2026
student: setup
	$(PY) -m calc.course student --roster $(ROSTER) --seed $(SEED) -o build/student

lecturer: setup
	$(PY) -m calc.course lecturer --roster $(ROSTER) --seed $(SEED) -o build/lecturer

# Re-execute every notebook in place (after a change to calc/), so nbval has true outputs to compare.
# No execution times are recorded, so a re-run changes only what the calculation changed; no widget
# state is stored either (notebook 12's panel: some 170 KB of it, new on every run, and a live kernel
# rebuilds it anyway).
notebooks: setup
	for nb in notebooks/*.ipynb notebooks/instructor/*.ipynb; do \
	  $(PY) -m jupyter nbconvert --to notebook --execute --inplace --ExecutePreprocessor.record_timing=False \
	    --ExecutePreprocessor.store_widget_state=False "$$nb" || exit 1; done

clean:
	rm -rf $(VENV) .pytest_cache .hypothesis
