"""Compiled kernels: plain SI numbers and arrays, no names, units or I/O.

Everything here is ``@njit(cache=True, no_cfunc_wrapper=True)`` (no kernel is called as a C
function, and that wrapper was a tenth of the compile time). The core (the step loop, the
integrators, the formulations, constraints, forces, functions, kinematics, linear algebra and
outputs) also has ``error_model="numpy"``: a division by zero gives inf or NaN, which the
loop reports as ``non_finite``, instead of a test and a raise at every division; that made
the paper's four-bar's step loop about 1.4 times faster. Contact elements and laws keep the
Python error model, so that a model's values at float's edges stop the run naming the
``ZeroDivisionError`` where they meet. Everything imports only ``math``,
``numpy``, ``numba`` and sibling kernel modules (``cache`` also ``hashlib``, ``os``,
``pickle``, ``contextlib`` and ``sys``, to stamp the cache; this file ``os`` and ``sys``, for
the switch and the finder below; ``laws.dispatch`` and ``laws.lawset`` ``collections.abc``,
for type hints).

- ``laws/``: normal-force, damping, friction, wear and film laws, dispatched by code and
  compiled for the codes a model uses (``laws.dispatch``; their records, names and keys are
  in ``model.laws``);
- ``elements/``: contact elements (``journal``: the revolute clearance joint);
- ``integrate/``: integrators behind one interface (Runge-Kutta tableaus, Adams);
- ``kinematics``, ``functions``, ``constraints``, ``forces``, ``linalg``, ``dynamics``: the
  constrained mechanism and its right-hand side;
- ``loop``: ``advance``, the step loop; ``outputs``: one row of the time series.

The package imports no numba itself: ``codes``, plain integer codes that the model schema
reads, loads without it, and the cache (``cache.install``) is installed just before the
first module that needs numba loads, so that reading a model never loads numba.

``JOINTWEAR_PLAIN_NUMBA=1`` (any value but empty or 0) keeps numba's plain behaviour where the
kernels rely on its internals, in case a numba release breaks them: no stamped cache
(``cache``) and named tuples instead of structs (``structs``). Slower to compile and to load,
and numba's own cache can go stale after a kernel edit.
"""

import os
import sys

PLAIN_NUMBA = os.environ.get("JOINTWEAR_PLAIN_NUMBA", "") not in ("", "0")
_WITHOUT_NUMBA = (f"{__name__}.codes", f"{__name__}.cache")


class _InstallCache:
    """A finder that installs the kernel cache when a module of the package first needs it."""

    def find_spec(self, name: str, path: object = None, target: object = None) -> None:
        if name.startswith(f"{__name__}.") and name not in _WITHOUT_NUMBA:
            sys.meta_path.remove(self)
            from . import cache

            cache.install()
        return None  # the module itself is found by the usual finders


if not PLAIN_NUMBA:
    sys.meta_path.insert(0, _InstallCache())
