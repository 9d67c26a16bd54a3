"""The kernels import only math, numpy, numba, typing and each other (STYLE: kernels vs API)."""

import ast
from pathlib import Path

import pytest

KERNELS = Path(__file__).parents[1] / "src" / "jointwear" / "kernels"
ALLOWED = {"math", "numpy", "numba", "typing", "enum"}
CACHE_STAMP = {"hashlib", "os"}  # cache.py hashes the kernel sources
CACHE_HOOK = {"sys"}  # the package's __init__.py installs the cache when a kernel loads


@pytest.mark.parametrize(
    "path", sorted(KERNELS.rglob("*.py")), ids=lambda p: str(p.relative_to(KERNELS))
)
def test_kernel_imports(path):
    allowed = ALLOWED | CACHE_STAMP if path.name == "cache.py" else ALLOWED
    allowed = allowed | CACHE_HOOK if path == KERNELS / "__init__.py" else allowed
    tree = ast.parse(path.read_text())
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            roots = {alias.name.split(".")[0] for alias in node.names}
        elif isinstance(node, ast.ImportFrom):
            if node.level > 0 or (node.module or "").startswith("jointwear.kernels"):
                continue  # a sibling kernel
            roots = {(node.module or "").split(".")[0]}
        else:
            continue
        assert roots <= allowed, f"{path.name} imports {roots - allowed}"
