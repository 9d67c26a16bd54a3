"""The compiled cache's stamp covers every kernel source, so an edit anywhere recompiles all."""

import os
import shutil
import subprocess
import sys
import textwrap

import pytest
from numba.core import caching

from jointwear.kernels import cache


def test_stamp_changes_with_any_kernel_source(tmp_path, monkeypatch):
    tree = tmp_path / "kernels"
    shutil.copytree(cache.KERNELS, tree, ignore=shutil.ignore_patterns("__pycache__"))
    monkeypatch.setattr(cache, "KERNELS", str(tree))
    before = cache._sources_digest()
    assert cache._sources_digest() == before  # deterministic
    law = tree / "laws" / "normal.py"
    law.write_text(law.read_text() + "\n# an edit in a law that the loop calls\n")
    assert cache._sources_digest() != before
    # a new kernel module counts too
    law.write_text(law.read_text().replace("\n# an edit in a law that the loop calls\n", ""))
    assert cache._sources_digest() == before
    (tree / "elements" / "new_kind.py").write_text("X = 1\n")
    assert cache._sources_digest() != before


def test_kernels_use_the_stamped_locators_first():
    from jointwear.kernels import loop

    impl = loop.advance._cache._impl
    assert type(impl.locator) in cache.LOCATORS
    assert impl.locator.get_source_stamp() == cache.STAMP
    assert caching.CacheImpl._locator_classes[: len(cache.LOCATORS)] == cache.LOCATORS


def test_functions_outside_the_kernels_keep_numba_locators(tmp_path):
    outside = tmp_path / "script.py"
    outside.write_text("def f():\n    return 1\n")
    for locator in cache.LOCATORS:
        assert locator.from_function(lambda: 1, str(outside)) is None


def _python(script: str, env: dict | None = None) -> str:
    done = subprocess.run(
        [sys.executable, "-c", textwrap.dedent(script)],
        capture_output=True,
        text=True,
        env=env,
        timeout=600,
    )
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_a_kernel_loads_from_the_cache_without_numbas_compile_time_modules():
    # The first process fills the cache if needed; the second loads the kernel from it.
    script = """
        import sys
        from jointwear.kernels.laws.normal import lankarani_nikravesh
        print(lankarani_nikravesh(0.6))
        print("numba.np.arraymath" in sys.modules)
    """
    _python(script)
    value, compile_modules = _python(script).split()
    assert float(value) == pytest.approx(0.75 * (1.0 - 0.36), rel=1e-15)  # 3 (1 - c_e^2) / 4
    assert compile_modules == "False"


def test_compiling_after_a_kernel_loaded_from_the_cache_still_works():
    # numba's compiler loads what compiling needs itself: a new function using NumPy compiles.
    out = _python("""
        import numpy as np
        from numba import njit
        from jointwear.kernels.laws.normal import hertz
        print(hertz(1e-4, 1e10, 1.5))
        print(njit(lambda a: np.sum(np.sort(a)[1:]))(np.array([3.0, 1.0, 2.0])))
    """)
    force, total = map(float, out.split())
    assert force == pytest.approx(1e4, rel=1e-12)  # K delta^1.5 = 1e10 * (1e-4)^1.5
    assert total == 5.0


def test_functions_outside_the_kernels_load_from_their_cache_as_numba_loads_them(tmp_path):
    (tmp_path / "outside.py").write_text(
        "from numba import njit\n\n@njit(cache=True)\ndef twice(x):\n    return 2.0 * x\n"
    )
    env = {**os.environ, "PYTHONPATH": str(tmp_path), "NUMBA_CACHE_DIR": str(tmp_path / "c")}
    script = """
        import sys
        import jointwear.kernels
        from outside import twice
        print(twice(1.5), twice.stats.cache_hits.get(twice.signatures[0], 0))
        print("numba.np.arraymath" in sys.modules)
    """
    _python(script, env)
    value, hits, compile_modules = _python(script, env).split()
    assert (float(value), int(hits)) == (3.0, 1)
    assert compile_modules == "True"  # numba's own load refreshed its context
