"""What the runtime loads: scipy only when a model has a table or a run is exported; Dask only
for clusters."""

import ast
import sys
from pathlib import Path

from typer.testing import CliRunner

from jointwear.cli import app

ROOT = Path(__file__).parents[1]
SOURCE = ROOT / "src" / "jointwear"
FOURBAR = ROOT / "examples" / "flores2009_fourbar.toml"
FRICTION = "joints.coupler_follower.clearance.friction_coefficient"


def _imports(tree: ast.AST) -> list[tuple[str, ast.AST]]:
    """(module, node) of every import statement in a tree."""
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found += [(alias.name, node) for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            found.append((node.module, node))
    return found


def _top_level(tree: ast.Module) -> set[ast.AST]:
    """The import statements run when the module is imported (not inside a function)."""
    inside = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
            inside.update(ast.walk(node))
    return {node for _, node in _imports(tree) if node not in inside}


SCIPY_USERS = {  # the .mat writer, table functions' interpolants, sampled studies, films, and
    # the sparse set-up of large mechanisms
    SOURCE / "results" / "export.py",
    SOURCE / "film" / "reynolds.py",
    SOURCE / "mechanism" / "functions.py",
    SOURCE / "mechanism" / "jacobian.py",
    SOURCE / "mechanism" / "least_norm.py",
    *(SOURCE / "studies" / "sample" / f"{name}.py"
      for name in ("distributions", "design", "statistics", "sensitivity")),
}  # fmt: skip


def test_the_package_imports_scipy_and_dask_only_inside_the_functions_that_need_them():
    for path in sorted(SOURCE.rglob("*.py")):
        tree = ast.parse(path.read_text(), filename=str(path))
        top = _top_level(tree)
        for module, node in _imports(tree):
            root = module.split(".")[0]
            if root == "scipy":
                assert path in SCIPY_USERS, f"{path} imports scipy"
            if root in ("dask", "distributed", "scipy", "xarray", "h5netcdf"):
                assert node not in top, f"{path.relative_to(ROOT)} imports {module} at load"


def test_a_cluster_sweep_without_dask_says_how_to_install_it(tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "dask.distributed", None)  # import fails as if absent
    result = CliRunner().invoke(
        app,
        [
            "sweep", str(FOURBAR), "--out", str(tmp_path / "sweep"), "--vary",
            f"{FRICTION}=0.05,0.1", "--set", "solver.t_end=0.001", "--no-figures",
            "--scheduler", "tcp://127.0.0.1:8786",
        ],
    )  # fmt: skip
    assert result.exit_code == 2, result.output
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    assert "pip install 'jointwear[dask]'" in lines[0]
    assert "--scheduler tcp://127.0.0.1:8786" in lines[0]
    assert not (tmp_path / "sweep" / "cases").exists()  # no case ran
