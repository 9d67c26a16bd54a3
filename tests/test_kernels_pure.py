"""The kernels import only math, numpy, numba, typing, enum and each other (STYLE: kernels vs API).

Relative imports are resolved against the importing module's package, so ``from ...model
import X`` in ``kernels/elements/`` is caught as the import of ``jointwear.model`` it is.
"""

import ast
from pathlib import Path

import pytest

KERNELS = Path(__file__).parents[1] / "src" / "jointwear" / "kernels"
PACKAGE = "jointwear.kernels"
ALLOWED = {"math", "numpy", "numba", "typing", "enum"}
# Standard modules some files need beside them, by path under kernels/.
EXTRA = {
    "__init__.py": {"os", "sys"},  # JOINTWEAR_PLAIN_NUMBA, the cache-installing finder
    "cache.py": {"hashlib", "os", "pickle", "contextlib", "sys"},  # stamp, index, warning
    "laws/dispatch.py": {"collections"},  # collections.abc, for type hints
    "laws/lawset.py": {"collections"},
}


def _module_name(path: Path) -> str:
    """Dotted name of a kernel source file, e.g. ``jointwear.kernels.elements.journal``."""
    parts = path.relative_to(KERNELS).with_suffix("").parts
    if parts[-1] == "__init__":
        parts = parts[:-1]
    return ".".join((PACKAGE, *parts))


def _inside(name: str) -> bool:
    return name == PACKAGE or name.startswith(PACKAGE + ".")


def outside_imports(source: str, module: str, is_package: bool, allowed: set[str]) -> list[str]:
    """What ``source`` (the module ``module``) imports from outside the kernels and ``allowed``.

    Relative imports are resolved from the module's package (the module itself for an
    ``__init__``); a call of ``__import__`` is reported as such.
    """
    package = module if is_package else module.rpartition(".")[0]
    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Import):
            targets = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parts = package.split(".")
                if node.level - 1 >= len(parts):
                    found.append(f"{'.' * node.level}{base} (beyond the top-level package)")
                    continue
                base = ".".join(filter(None, [*parts[: len(parts) - node.level + 1], base]))
            names = [alias.name for alias in node.names]
            targets = [base] if _inside(base) else [f"{base}.{name}" for name in names]
        elif isinstance(node, ast.Name) and node.id == "__import__":
            found.append("__import__(...)")
            continue
        else:
            continue
        found += [t for t in targets if not _inside(t) and t.split(".")[0] not in allowed]
    return found


@pytest.mark.parametrize(
    "path", sorted(KERNELS.rglob("*.py")), ids=lambda p: str(p.relative_to(KERNELS))
)
def test_kernel_imports(path):
    allowed = ALLOWED | EXTRA.get(str(path.relative_to(KERNELS)), set())
    found = outside_imports(
        path.read_text(), _module_name(path), path.name == "__init__.py", allowed
    )
    assert not found, f"{path.relative_to(KERNELS)} imports {found}"


DEEP = "jointwear.kernels.elements.journal"  # a module two levels down


@pytest.mark.parametrize(
    "line",
    [
        "from ...model import Model",  # jointwear.model
        "from ... import model",
        "from ...results.tribology import COLUMNS",
        "from .... import x",  # beyond the top-level package
        "import jointwear.model",
        "from jointwear import model",
        "import scipy.linalg",
        "import os",  # a standard module not allowed to this file
        "mod = __import__('jointwear.model')",
        "def f():\n    from ...model import Model",  # inside a function
    ],
)
def test_the_check_catches_an_import_from_outside(line):
    assert outside_imports(line, DEEP, False, ALLOWED)


@pytest.mark.parametrize(
    "line",
    [
        "from ..laws.normal import damped",
        "from . import journal_geometry",
        "from .. import structs",
        "from jointwear.kernels.laws import wear",
        "import numpy as np\nfrom numba.core import types\nfrom math import pi",
    ],
)
def test_the_check_lets_imports_from_inside_through(line):
    assert outside_imports(line, DEEP, False, ALLOWED) == []


def test_a_packages_relative_imports_resolve_from_the_package_itself():
    # In kernels/elements/__init__.py "." is kernels/elements, ".." kernels, "..." jointwear.
    package = "jointwear.kernels.elements"
    assert outside_imports("from .journal import evaluate", package, True, ALLOWED) == []
    assert outside_imports("from ..loop import advance", package, True, ALLOWED) == []
    assert outside_imports("from ...units import Q", package, True, ALLOWED) == [
        "jointwear.units.Q"
    ]
