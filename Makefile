# Two entry points for a fresh clone (see README):
#   make book   set up .venv and the book's browser assets, execute every notebook afresh,
#               build the HTML book in _build/html
#   make test   the same set-up, then run the whole test suite (library, notebooks, book, lint)
# and two live routes:
#   make explore   serve the explorers as a Voila app on http://127.0.0.1:$(PORT)/
#   make lab       open JupyterLab on the chapters (notebooks/) and the explorers (explore/)
SHELL := /bin/bash
PYTHON ?= $(shell command -v python3.11 || command -v python3)
VENV := .venv
PY := $(VENV)/bin/python
STAMP := $(VENV)/.installed

# MathJax, RequireJS, the ipywidgets HTML manager and uPlot (the static explorers' plots),
# installed from the npm registry at the
# versions locked in book/assets/package-lock.json and copied into book/assets/static/vendor,
# which Sphinx copies into the book's _static folder: the pages load nothing from a CDN.
ASSETS_DIR := book/assets
NODE_MODULES := $(ASSETS_DIR)/node_modules
VENDOR := $(ASSETS_DIR)/static/vendor
ASSETS := $(ASSETS_DIR)/static/.installed

.PHONY: setup assets book test benchmarks clean explore lab

$(STAMP): requirements.txt pyproject.toml
	@$(PYTHON) -c 'import sys; assert sys.version_info[:2] == (3, 11), "vbi needs Python 3.11, found " + sys.version.split()[0]'
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -r requirements.txt
	$(PY) -m pip install --quiet --no-deps -e .
	touch $(STAMP)

setup: $(STAMP)

$(ASSETS): $(ASSETS_DIR)/package.json $(ASSETS_DIR)/package-lock.json
	@command -v npm >/dev/null || { echo "make: the book's browser assets need npm (Node.js 18 or newer); install it, e.g. apt-get install -y npm"; exit 1; }
	npm ci --prefix $(ASSETS_DIR) --ignore-scripts --no-audit --no-fund --loglevel=error
	rm -rf $(ASSETS_DIR)/static
	mkdir -p $(VENDOR)/mathjax/output $(VENDOR)/html-manager $(VENDOR)/uplot
	cp -r $(NODE_MODULES)/mathjax/es5/tex-mml-chtml.js $(NODE_MODULES)/mathjax/es5/input \
	    $(NODE_MODULES)/mathjax/es5/ui $(NODE_MODULES)/mathjax/es5/a11y \
	    $(NODE_MODULES)/mathjax/es5/sre $(NODE_MODULES)/mathjax/es5/adaptors $(VENDOR)/mathjax/
	cp -r $(NODE_MODULES)/mathjax/es5/output/chtml $(VENDOR)/mathjax/output/
	cp $(NODE_MODULES)/mathjax/LICENSE $(VENDOR)/mathjax/
	cp $(NODE_MODULES)/requirejs/require.js $(VENDOR)/
	cp $(NODE_MODULES)/@jupyter-widgets/html-manager/dist/embed-amd.js \
	    $(NODE_MODULES)/@jupyter-widgets/html-manager/dist/*.{woff,woff2,ttf,eot,svg} \
	    $(NODE_MODULES)/@jupyter-widgets/html-manager/dist/embed.js.LICENSE.txt \
	    $(VENDOR)/html-manager/
	cp $(NODE_MODULES)/uplot/dist/uPlot.iife.min.js $(NODE_MODULES)/uplot/dist/uPlot.min.css \
	    $(NODE_MODULES)/uplot/LICENSE $(VENDOR)/uplot/
	touch $(ASSETS)

assets: $(ASSETS)

book: setup assets
	rm -rf _build/html _build/.jupyter_cache _build/jupyter_execute
	$(VENV)/bin/jupyter-book build . -W --keep-going
	@echo "Open _build/html/index.html in a browser."

test: setup assets
	$(PY) -m pytest

# Voila runs explore/explore.ipynb in a kernel and shows only its outputs; 127.0.0.1 only.
# Every page load starts a kernel (some 450 MB) that Voila cannot shut down when the tab
# closes (its shutdown request is refused, voila#1458), so kernels idle for EXPLORE_IDLE
# seconds with no page connected are culled, checked every EXPLORE_CULL seconds; a page that
# stays open keeps its kernel.  EXPLORE_OPTIONS passes more Voila options (they come last).
# The vbi template (explore/share/jupyter/voila/templates/vbi) is Voila's lab template
# without its links to a CDN: every asset is served by Voila itself.
PORT ?= 8866
EXPLORE_IDLE ?= 120
EXPLORE_CULL ?= 30
EXPLORE_OPTIONS ?=
explore: setup
	@echo "vbi explorers: http://127.0.0.1:$(PORT)/ (Ctrl-C stops the app)"
	JUPYTER_PATH="$(CURDIR)/explore/share/jupyter$${JUPYTER_PATH:+:$$JUPYTER_PATH}" \
	$(VENV)/bin/voila explore/explore.ipynb --no-browser --Voila.ip=127.0.0.1 \
		--port=$(PORT) --Voila.port_retries=0 --template=vbi \
		--MappingKernelManager.cull_idle_timeout=$(EXPLORE_IDLE) \
		--MappingKernelManager.cull_interval=$(EXPLORE_CULL) \
		--MappingKernelManager.cull_connected=False $(EXPLORE_OPTIONS)

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
