"""Start-up: what ``import jointwear``, ``jointwear --help`` and ``jointwear check`` load."""

import subprocess
import sys
from pathlib import Path

HEAVY = ("pandas", "matplotlib", "numba", "scipy", "pint", "pydantic", "dask", "pyarrow")
FOURBAR = Path(__file__).parents[1] / "examples" / "flores2009_fourbar.toml"


def loaded(code: str) -> set[str]:
    """The heavy packages a fresh interpreter has imported after running ``code``."""
    report = f"import sys; print('LOADED', *(m for m in {HEAVY!r} if m in sys.modules))"
    script = f"try:\n    {code}\nexcept SystemExit:\n    pass\n{report}"
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    line = next(line for line in done.stdout.splitlines() if line.startswith("LOADED"))
    return set(line.split()[1:])


def test_import_loads_nothing_heavy():
    assert loaded("import jointwear") == set()


def test_help_loads_typer_and_rich_only():
    assert loaded("from jointwear.cli import app; app(['--help'])") == set()


def test_check_loads_no_pandas_nor_matplotlib():
    # the schema needs pydantic and pint, the assembly a compiled kernel (numba); pint and
    # numba import dask and scipy themselves
    code = f"from jointwear.cli import app; app(['check', {str(FOURBAR)!r}])"
    assert not loaded(code) & {"pandas", "matplotlib", "pyarrow"}


def test_validating_every_example_loads_no_numba():
    # validation reads the law records (model.laws), never the compiled kernels
    examples = sorted(str(p) for p in FOURBAR.parent.glob("*.toml"))
    code = f"import jointwear\n    for path in {examples!r}:\n        jointwear.load_model(path)"
    assert "numba" not in loaded(code)
