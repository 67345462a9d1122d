# Two entry points for a fresh clone (see README):
#   make book   set up .venv, execute every notebook afresh, build the HTML book in _build/html
#   make test   set up .venv, run the whole test suite (library, notebooks, book, lint)
# and two live routes:
#   make explore   serve the explorers as a Voila app on http://127.0.0.1:$(PORT)/
#   make lab       open JupyterLab on the chapters (notebooks/) and the explorers (explore/)
SHELL := /bin/bash
PYTHON ?= $(shell command -v python3.11 || command -v python3)
VENV := .venv
PY := $(VENV)/bin/python
STAMP := $(VENV)/.installed

.PHONY: setup book test benchmarks clean explore lab

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

# Voila runs explore/explore.ipynb in a kernel and shows only its outputs; 127.0.0.1 only.
PORT ?= 8866
explore: setup
	@echo "vbi explorers: http://127.0.0.1:$(PORT)/ (Ctrl-C stops the app)"
	$(VENV)/bin/voila explore/explore.ipynb --no-browser --Voila.ip=127.0.0.1 \
		--port=$(PORT) --Voila.port_retries=0

# JupyterLab on 127.0.0.1 (it prints its URL with a token); LAB_OPTIONS adds options.
# As root (a container) JupyterLab needs --allow-root.
LAB_PORT ?= 8888
lab: setup
	$(VENV)/bin/jupyter lab --ServerApp.ip=127.0.0.1 --ServerApp.port=$(LAB_PORT) \
		--ServerApp.port_retries=0 --ServerApp.root_dir="$(CURDIR)" \
		--LabApp.default_url=/lab/tree/notebooks \
		$(if $(filter 0,$(shell id -u)),--allow-root) $(LAB_OPTIONS)

benchmarks: setup
	$(PY) benchmarks/run_all.py

clean:
	rm -rf _build
