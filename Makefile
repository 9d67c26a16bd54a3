# jointwear: `make run` sets up .venv and runs the paper's four-bar; `make test` runs the tests.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
OUT ?= results/flores2009_fourbar

.PHONY: install run test lint docs clean clean-cache

install: $(VENV)/.installed

# compileall does for this editable install what pip does for an installed package, so that
# no run compiles the modules again (where PYTHONDONTWRITEBYTECODE is set, none would save
# them): about 0.3 s of every command. A short run of the paper's four-bar then fills numba's
# cache with the kernels it uses (and its all-ideal twin's), so that `make run` does not
# compile; a model with other laws or integrators compiles its own on its first run.
$(VENV)/.installed: pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/pip install --quiet --upgrade pip
	$(BIN)/pip install --quiet -e '.[dev]'
	$(BIN)/python -m compileall -q src
	@echo "compiling the kernels for the paper's four-bar (once, about a minute)"
	$(BIN)/jointwear run examples/flores2009_fourbar.toml --t-end 0.001 --no-figures \
		--out $(VENV)/kernel-warm-up > $(VENV)/kernel-warm-up.log 2>&1 \
		|| { cat $(VENV)/kernel-warm-up.log; exit 1; }
	touch $@

run: install
	$(BIN)/jointwear run examples/flores2009_fourbar.toml --out $(OUT)

test: install
	$(BIN)/pytest -q

lint: install
	$(BIN)/ruff check .

# The documentation site (mkdocs.yml): docs/*.md and the API from the docstrings, into site/.
docs: $(VENV)/.docs-installed
	$(BIN)/mkdocs build --strict --site-dir site

$(VENV)/.docs-installed: $(VENV)/.installed pyproject.toml
	$(BIN)/pip install --quiet -e '.[dev,docs]'
	touch $@

clean:
	rm -rf $(VENV) results .pytest_cache site

# Drops the compiled cache. Not needed after edits: any kernel edit invalidates all of it.
clean-cache:
	find src -name '*.nbi' -delete -o -name '*.nbc' -delete
