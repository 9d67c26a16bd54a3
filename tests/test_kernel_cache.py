"""The compiled cache's stamp covers every kernel source, so an edit anywhere recompiles all."""

import os
import shutil
import subprocess
import sys
import textwrap

import numpy as np
import pytest
from numba.core import caching
from runs import EXAMPLES

import jointwear as jw
from jointwear.engine.prepare import prepare
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


def _run(script: str, env: dict | None = None) -> subprocess.CompletedProcess:
    done = subprocess.run(
        [sys.executable, "-c", textwrap.dedent(script)],
        capture_output=True,
        text=True,
        env=env,
        timeout=900,
    )
    assert done.returncode == 0, done.stderr
    return done


def _python(script: str, env: dict | None = None) -> str:
    return _run(script, env).stdout


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


def test_a_set_locator_variable_is_warned_about_once(tmp_path):
    # numba then uses the locators it names for the kernels too: numba's own, unstamped.
    script = """
        from numba import njit
        from jointwear.kernels.laws.normal import hertz, hunt_crossley
        hertz(1e-6, 1e10, 1.5), hunt_crossley(0.8)
        print(type(hertz._cache._impl.locator).__name__)
    """
    env = {**os.environ, "NUMBA_CACHE_DIR": str(tmp_path)}
    warned = {**env, "NUMBA_CACHE_LOCATOR_CLASSES": "UserProvidedCacheLocator"}
    done = _run(script, warned)
    assert done.stdout.split() == ["UserProvidedCacheLocator"]
    assert done.stderr.count("NUMBA_CACHE_LOCATOR_CLASSES") == 1
    assert done.stderr.startswith(cache.LOCATORS_SET)  # what to do: unset it, or delete
    done = _run(script, env)
    assert done.stdout.split() == ["KernelTreeUserProvidedCacheLocator"]
    assert "NUMBA_CACHE_LOCATOR_CLASSES" not in done.stderr


def test_an_index_naming_a_moved_type_is_a_miss(tmp_path):
    # A kernel cached for a named tuple of a module outside the kernels; the module then goes
    # (its class moved elsewhere), which the stamp does not see. numba unpickles the whole
    # index before it looks up a signature: the kernel must compile, not raise ImportError.
    env = {
        **os.environ,
        "NUMBA_CACHE_DIR": str(tmp_path / "cache"),
        "PYTHONPATH": os.pathsep.join([str(tmp_path), os.environ.get("PYTHONPATH", "")]),
    }
    record = "from typing import NamedTuple\n\nclass Record(NamedTuple):\n    x: float\n"
    (tmp_path / "old_home.py").write_text(record)
    script = """
        from jointwear.kernels.structs import to_struct
        from {module} import Record
        to_struct(Record(1.5))
        print(to_struct.stats.cache_hits.get(to_struct.signatures[0], 0))
    """
    assert _python(script.format(module="old_home"), env).split() == ["0"]  # compiled
    (index,) = (tmp_path / "cache").rglob("struct_ref.to_struct-*.nbi")
    assert b"old_home" in index.read_bytes()
    (tmp_path / "old_home.py").rename(tmp_path / "new_home.py")
    assert _python(script.format(module="new_home"), env).split() == ["0"]  # compiled again
    assert b"old_home" not in index.read_bytes()  # the stale index replaced
    assert _python(script.format(module="new_home"), env).split() == ["1"]  # and loaded


def test_plain_numba_prepares_as_the_stamped_kernels_do(tmp_path):
    # JOINTWEAR_PLAIN_NUMBA=1: numba's own locators and loading, named tuples for structs, and
    # neither cache.py nor struct_ref.py imported. A run's preparation (arrays, assembly with
    # its kernels, the lock-up check of a driven four-bar) compiles into an empty cache and
    # gives the same start, bit for bit. (A whole run compiles the step loop without the
    # cache, over a minute of CI; its time series was compared once, and equal exactly.)
    env = {**os.environ, "JOINTWEAR_PLAIN_NUMBA": "1", "NUMBA_CACHE_DIR": str(tmp_path / "c")}
    fourbar = EXAMPLES / "flores2009_fourbar.toml"
    out = tmp_path / "plain.npy"
    script = f"""
        import sys
        import numpy as np
        import jointwear as jw
        from jointwear.engine.prepare import prepare
        from jointwear.kernels import constraints, structs
        ready = prepare(jw.load_model({str(fourbar)!r}))
        np.save({str(out)!r}, ready.assembly.y0)
        locator = constraints.evaluate_constraints._cache._impl.locator
        print(ready.lock is None, type(locator).__name__)
        print(structs.StructProxy is tuple, "jointwear.kernels.cache" in sys.modules)
        print("jointwear.kernels.struct_ref" in sys.modules)
    """
    assert _python(script, env).split() == [
        *("True", "UserProvidedCacheLocator"),
        *("True", "False", "False"),
    ]
    assert any((tmp_path / "c").rglob("constraints.evaluate_constraints-*.nbi"))  # numba's own
    start = prepare(jw.load_model(fourbar)).assembly.y0
    np.testing.assert_array_equal(np.load(out), start)
