"""Products with the sparse constraint Jacobian, stored by row.

Row r of Phi_q holds ENTRIES values, cq[r, e], in the columns mech.row_coord[r, e]: the x, y,
phi of the row's first body, then of its second (-1 for the ground; ``pattern.py``).
"""

import math

from numba import njit

ENTRIES = 6  # Jacobian entries per row: x, y, phi of its first body, then of its second


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def row_dot(mech, cq, r, v):
    """Phi_q,r . v for a coordinate vector v."""
    row_coord = mech.row_coord
    total = 0.0
    for e in range(ENTRIES):
        col = row_coord[r, e]
        if col >= 0:
            total += cq[r, e] * v[col]
    return total


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def add_transpose_product(mech, cq, coef, out):
    """Out += Phi_q^T coef for a row vector coef."""
    row_coord = mech.row_coord
    for r in range(coef.shape[0]):
        for e in range(ENTRIES):
            col = row_coord[r, e]
            if col >= 0:
                out[col] += cq[r, e] * coef[r]


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def norm(v):
    """2-norm of a vector."""
    total = 0.0
    for i in range(v.shape[0]):
        total += v[i] * v[i]
    return math.sqrt(total)
