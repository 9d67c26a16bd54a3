"""The compiled cache's stamp covers every kernel source, so an edit anywhere recompiles all."""

import shutil

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
