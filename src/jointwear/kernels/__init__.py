"""Compiled kernels: plain SI numbers and arrays, no names, units or I/O.

Everything here is ``@njit(cache=True)`` and imports only ``math``, ``numpy``, ``numba``
and sibling kernel modules (``cache`` also ``hashlib``, ``os`` and ``typing``, to stamp the
cache).

- ``laws/``: normal-force, friction and wear laws, each family with its registry table;
- ``elements/``: contact elements (``journal``: the revolute clearance joint);
- ``integrate/``: integrators behind one interface (Runge-Kutta tableaus, Adams);
- ``kinematics``, ``functions``, ``constraints``, ``forces``, ``linalg``, ``dynamics``: the
  constrained mechanism and its right-hand side;
- ``loop``: ``advance``, the step loop; ``outputs``: one row of the time series.
"""

from . import cache

cache.install()
