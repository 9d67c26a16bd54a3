"""A compiled-kernel cache that cannot go stale.

numba stamps each cached function with a hash of its own source file only, so editing a
kernel that others call (a law, the kinematics) left its callers' cached machine code in
place. Every kernel here is stamped instead with one hash of all the kernel sources and of
numba's version: any edit under ``kernels/`` recompiles all of them on the next run.

The stamp rides on numba's cache locators (``numba.core.caching``), which numba lets a
project replace (``NUMBA_CACHE_LOCATOR_CLASSES``); the numba range in ``pyproject.toml``
is the one this was written and tested against.

Loading a kernel from this cache also skips numba's refresh of its whole target context
(``load_kernel``): up to half a second of every process that runs a kernel (0.55 s for the
four-bar; less where a kernel's environment imports some of numba's modules back).

An index that no longer unpickles (it names a type of the kernels' arguments in a module
that has moved since, outside ``kernels/``, so the stamp did not change) is a miss: it is
removed, and the kernel compiles and is saved again.

With ``NUMBA_CACHE_LOCATOR_CLASSES`` set (in the environment or numba's config file), numba
uses the locators it names for every function, these included, and the stamp is lost: a
kernel loaded from the cache may then be older than a kernel it calls. That is warned about,
once per process on stderr, not refused: the setting may be there for other code.

With ``JOINTWEAR_PLAIN_NUMBA=1`` this module is not imported (``kernels/__init__.py``):
numba caches and loads the kernels as it does any function, the way out if a numba release
breaks the internals used here (``caching``'s locator classes, ``Cache._load_overload`` and
``_guard_against_spurious_io_errors``, ``rtsys``). Then numba's own cache can go stale:
delete it after changing a kernel.
"""

import contextlib
import hashlib
import os
import pickle
import sys
from typing import Any

import numba
from numba.core import caching
from numba.core.runtime import rtsys

KERNELS = os.path.dirname(os.path.abspath(__file__))
LOCATORS_SET = (
    "jointwear: NUMBA_CACHE_LOCATOR_CLASSES is set, so numba's cache of jointwear's kernels "
    "is not stamped with their sources and can go stale when a kernel changes: unset it, or "
    "delete the cache after changing jointwear (__pycache__ under jointwear/kernels/, or "
    "NUMBA_CACHE_DIR).\n"
)


def _sources_digest() -> str:
    """sha256 of every kernel source (path and content) and of numba's version."""
    digest = hashlib.sha256(numba.__version__.encode())
    for folder, _, files in sorted(os.walk(KERNELS)):
        for name in sorted(files):
            if name.endswith(".py"):
                path = os.path.join(folder, name)
                digest.update(os.path.relpath(path, KERNELS).encode())
                with open(path, "rb") as source:
                    digest.update(source.read())
    return digest.hexdigest()


STAMP = _sources_digest()


def _tree_stamped(base: type) -> type:
    """``base`` (a numba locator) for kernel files only, stamped with ``STAMP``."""

    class Locator(base):
        def get_source_stamp(self) -> str:
            return STAMP

        def get_disambiguator(self) -> str:
            # In the file names too: numba unpickles an index before it compares stamps, and
            # an index of older sources can name a class that no longer exists.
            return f"{super().get_disambiguator()}-{STAMP[:12]}"

        @classmethod
        def from_function(cls, py_func, py_file):
            if not os.path.abspath(py_file).startswith(KERNELS + os.sep):
                return None
            return super().from_function(py_func, py_file)

    Locator.__name__ = Locator.__qualname__ = f"KernelTree{base.__name__}"
    return Locator


LOCATORS = [
    _tree_stamped(caching.UserProvidedCacheLocator),  # NUMBA_CACHE_DIR, when set
    _tree_stamped(caching.InTreeCacheLocator),  # __pycache__ beside the sources
    _tree_stamped(caching.UserWideCacheLocator),  # the user's cache folder (read-only install)
]


_numba_load = caching.Cache.load_overload


def load_kernel(cache: caching.Cache, signature: Any, target_context: Any) -> Any:
    """Load as numba's ``Cache.load_overload`` does, without its refresh for a kernel's cache.

    Before it looks in any cache, numba refreshes the target context: it imports what it
    needs to compile every Python and NumPy feature it knows, 0.5-0.6 s. Machine code read
    from a cache needs only numba's runtime (``rtsys``), and a miss is compiled by
    ``numba.core.compiler.compile_extra``, which refreshes the context itself. Caches of
    functions outside the kernels load as numba loads them.
    """
    if not isinstance(cache._impl.locator, tuple(LOCATORS)):
        return _numba_load(cache, signature, target_context)
    rtsys.initialize(target_context)
    with cache._guard_against_spurious_io_errors():
        try:
            return cache._load_overload(signature, target_context)
        except STALE_INDEX:
            with contextlib.suppress(OSError):
                os.remove(cache._cache_file._index_path)
            return None


STALE_INDEX = (ImportError, AttributeError, pickle.UnpicklingError, EOFError)


def install() -> None:
    """Put the kernel-tree locators first in numba's list and load kernels with ``load_kernel``.

    Once; before any kernel is defined. Warns on stderr where ``NUMBA_CACHE_LOCATOR_CLASSES``
    overrides the locators.
    """
    if getattr(numba.config, "CACHE_LOCATOR_CLASSES", ""):
        sys.stderr.write(LOCATORS_SET)
    classes = caching.CacheImpl._locator_classes
    if classes[0] is not LOCATORS[0]:
        classes[:0] = LOCATORS
    caching.Cache.load_overload = load_kernel
