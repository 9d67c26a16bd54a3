"""The data path's arrows: which folders a folder's modules may import at module level.

``model -> mechanism -> engine -> results -> figures`` (and ``studies``, ``cli`` on top): a
folder that imports one further down the path makes a circle, or makes the cheap part load the
heavy one. Imports inside functions (loaded when used) are not arrows of the layout.
"""

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).parents[1] / "src" / "jointwear"
FORBIDDEN = {  # folder: what its modules must not import at module level
    "model": ("jointwear.mechanism", "jointwear.engine", "jointwear.results",
              "jointwear.figures", "jointwear.studies", "jointwear.cli"),
    "results": ("jointwear.figures", "jointwear.studies", "jointwear.cli"),
    "engine": ("jointwear.figures", "jointwear.studies", "jointwear.cli"),
    "figures": ("jointwear.studies", "jointwear.cli"),  # figures take tables, not studies
    "mechanism": ("jointwear.engine", "jointwear.results", "jointwear.figures",
                  "jointwear.studies", "jointwear.cli"),
}  # fmt: skip


def module_imports(path: Path) -> set[str]:
    """Absolute names a module imports at its top level (relative imports resolved)."""
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    package = parts[:-1]  # of a module, and of a package's __init__ alike
    names = set()
    for node in ast.parse(path.read_text()).body:
        if isinstance(node, ast.Import):
            names |= {alias.name for alias in node.names}
        elif isinstance(node, ast.ImportFrom):
            base = list(package[: len(package) - node.level + 1]) if node.level else []
            module = ".".join([*base, *([node.module] if node.module else [])])
            names |= {f"{module}.{alias.name}" for alias in node.names} | {module}
    return names


@pytest.mark.parametrize("folder", sorted(FORBIDDEN))
def test_no_folder_imports_one_further_down_the_path(folder):
    found = {
        str(path.relative_to(PACKAGE)): sorted(
            name for name in module_imports(path) if name.startswith(FORBIDDEN[folder])
        )
        for path in sorted((PACKAGE / folder).rglob("*.py"))
    }
    assert {path: names for path, names in found.items() if names} == {}


def test_the_check_sees_relative_imports(tmp_path, monkeypatch):
    source = PACKAGE / "results" / "example.py"
    monkeypatch.setattr(Path, "read_text", lambda self: "from ..figures.run import x\n")
    assert "jointwear.figures.run.x" in module_imports(source)
