"""Sparse symmetric positive-definite solves in envelope (skyline) storage, allocation-free.

Row i of a matrix in envelope storage holds its columns first[i] .. i (the lower triangle from
the row's first non-zero to the diagonal) at a[ptr[i] : ptr[i] + i - first[i] + 1]. Cholesky
factorisation fills nothing outside the envelope, so with the rows ordered for a narrow
envelope (``pattern.py``) the cost is about size x width^2: linear in the size of a chain
or a tree of bodies. George and Liu (1981), "Computer Solution of Large Sparse Positive
Definite Systems", ch. 4. For the few-by-few systems of small mechanisms these hand-written
loops also beat a LAPACK call, whose overhead dominates at those sizes.
"""

import math

from numba import njit

PIVOT_TOLERANCE = 1e-13  # a pivot below this fraction of the diagonal is singular


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def envelope_factor(first, ptr, a, per_row):
    """Overwrite the envelope a with its Cholesky factor L (a = L L^T).

    Returns False if a pivot is not positive relative to the largest diagonal entry, or with
    ``per_row`` to its own row's diagonal entry (a singular matrix: redundant constraints or a
    dead-centre position), True otherwise. Per row, rows of very different scales pass (a
    light wheel beside a heavy frame in M + Phi_q^T W Phi_q, positive definite by
    construction); against the largest, a Schur complement near a dead centre is caught.
    """
    size = first.shape[0]
    largest = 0.0
    for i in range(size):
        largest = max(largest, abs(a[ptr[i] + i - first[i]]))
    for i in range(size):
        fi = first[i]
        row_i = ptr[i] - fi  # a[row_i + j] is entry (i, j)
        for j in range(fi, i):
            fj = first[j]
            row_j = ptr[j] - fj
            s = a[row_i + j]
            for k in range(max(fi, fj), j):
                s -= a[row_i + k] * a[row_j + k]
            a[row_i + j] = s / a[row_j + j]
        d = a[row_i + i]
        tiny = PIVOT_TOLERANCE * (abs(d) if per_row else largest)
        for k in range(fi, i):
            d -= a[row_i + k] * a[row_i + k]
        if not d > tiny:
            return False
        a[row_i + i] = math.sqrt(d)
    return True


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def envelope_solve(first, ptr, factor, x):
    """Solve L L^T x = b in place (x holds b on entry), L from ``envelope_factor``."""
    size = first.shape[0]
    for i in range(size):  # forward: L z = b
        row_i = ptr[i] - first[i]
        s = x[i]
        for k in range(first[i], i):
            s -= factor[row_i + k] * x[k]
        x[i] = s / factor[row_i + i]
    for i in range(size - 1, -1, -1):  # backward: L^T x = z, a column of L^T at a time
        row_i = ptr[i] - first[i]
        x[i] /= factor[row_i + i]
        xi = x[i]
        for k in range(first[i], i):
            x[k] -= factor[row_i + k] * xi
