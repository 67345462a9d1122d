# Two entry points for a fresh clone (see README):
#   make book   set up .venv, execute every notebook afresh, build the HTML book in _build/html
#   make test   set up .venv, run the whole test suite (library, notebooks, book, lint)
SHELL := /bin/bash
PYTHON ?= $(shell command -v python3.11 || command -v python3)
VENV := .venv
PY := $(VENV)/bin/python
STAMP := $(VENV)/.installed

.PHONY: setup book test benchmarks clean

$(STAMP): requirements.txt pyproject.toml
	@$(PYTHON) -c 'import sys; assert sys.version_info[:2] == (3, 11), "vbi needs Python 3.11, found " + sys.version.split()[0]'
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -r requirements.txt
	$(PY) -m pip install --quiet --no-deps -e .
	touch $(STAMP)

setup: $(STAMP)

book: setup
	rm -rf _build/html _build/.jupyter_cache _build/jupyter_execute
	$(VENV)/bin/jupyter-book build . -W --keep-going
	@echo "Open _build/html/index.html in a browser."

test: setup
	$(PY) -m pytest

benchmarks: setup
	$(PY) benchmarks/run_all.py

clean:
	rm -rf _build
