"""The kernels import only math, numpy, numba, typing and each other (STYLE: kernels vs API)."""

import ast
from pathlib import Path

import pytest

KERNELS = Path(__file__).parents[1] / "src" / "jointwear" / "kernels"
ALLOWED = {"math", "numpy", "numba", "typing", "enum"}


@pytest.mark.parametrize("path", sorted(KERNELS.glob("*.py")), ids=lambda p: p.name)
def test_kernel_imports(path):
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
        assert roots <= ALLOWED, f"{path.name} imports {roots - ALLOWED}"
