"""Compiled kernels: plain SI numbers and arrays, no names, units or I/O.

Everything here is ``@njit(cache=True)`` and imports only ``math``, ``numpy``, ``numba``
and sibling kernel modules.
"""
