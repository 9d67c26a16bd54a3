"""Compiled kernels: plain SI numbers and arrays, no names, units or I/O.

Everything here is ``@njit(cache=True)`` and imports only ``math``, ``numpy``, ``numba``
and sibling kernel modules (``cache`` also ``hashlib``, ``os``, ``pickle``, ``contextlib`` and
``sys``, to stamp the cache; this file ``os``, for the switch below).

- ``laws/``: normal-force, friction and wear laws, each family with its registry table;
- ``elements/``: contact elements (``journal``: the revolute clearance joint);
- ``integrate/``: integrators behind one interface (Runge-Kutta tableaus, Adams);
- ``kinematics``, ``functions``, ``constraints``, ``forces``, ``linalg``, ``dynamics``: the
  constrained mechanism and its right-hand side;
- ``loop``: ``advance``, the step loop; ``outputs``: one row of the time series.

``JOINTWEAR_PLAIN_NUMBA=1`` (any value but empty or 0) keeps numba's plain behaviour where the
kernels rely on its internals, in case a numba release breaks them: no stamped cache
(``cache``) and named tuples instead of structs (``structs``). Slower to compile and to load,
and numba's own cache can go stale after a kernel edit.
"""

import os

PLAIN_NUMBA = os.environ.get("JOINTWEAR_PLAIN_NUMBA", "") not in ("", "0")

if not PLAIN_NUMBA:
    from . import cache

    cache.install()
